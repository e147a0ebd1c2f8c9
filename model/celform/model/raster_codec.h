// Raster image reading and writing through OpenImageIO, in a module loaded on first use.
// OpenImageIO maps about 260 shared libraries (FFmpeg, GDAL, OpenCV, GStreamer, ...), which cost
// 0.25 s and 130 MB at the start of every program linking it; behind this module, only programs
// that read or write a raster image pay it, and only then (`celform info` or `set` never do).
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

#include <string>
#include <vector>

namespace celform::model {

/// The module's functions. They report problems as text, so no exception crosses the module.
struct RasterCodec {
    /// Decodes raster bytes of a format (lower-case suffix: png, jpg, tif, exr, psd, ...) to 8-bit
    /// straight-alpha RGBA, float pixels sRGB-encoded. A null image on failure, with the problem
    /// in *problem; fileLabel names the file in the messages.
    QImage (*decode)(const QByteArray& data, const QString& format, const QString& fileLabel, QString* problem);
    /// Writes width by height pixels of the named channels, interleaved, to file (its suffix picks
    /// the format): floats when isFloat (EXR, zip-compressed), else bytes. Returns the problem,
    /// empty on success.
    QString (*write)(const QString& file, int width, int height, const std::vector<std::string>& channels, bool isFloat,
        const void* pixels);
};

/// The entry the module exports: returns its functions.
using RasterCodecEntry = const RasterCodec* (*)();
constexpr const char* kRasterCodecEntry = "celform_raster_codec";

/// Loads the module on first use (beside the program or the library holding this code, in
/// ../lib/celform from there, or in the build tree) and returns its functions. Thread-safe.
/// Throws IoError naming fileLabel when the module cannot be loaded.
const RasterCodec& rasterCodec(const QString& fileLabel);

} // namespace celform::model
