// Raster image reading and writing through OpenImageIO, in a module loaded on first use.
// OpenImageIO maps about 260 shared libraries (FFmpeg, GDAL, OpenCV, GStreamer, ...), which cost
// 0.25 s and 130 MB at the start of every program linking it; behind this module, only programs
// that read or write a raster image pay it, and only then (`celform info` or `set` never do).
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QImage>
#include <QString>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace celform::model {

/// The widest and tallest drawing read, in pixels.
constexpr std::int64_t kMaxImageSide = 32768;
/// The most pixels a drawing may have: larger than any drawing an artist scans, small enough that
/// the decoder's float buffer stays below 2 GB.
constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 27;
/// Any file may decode to this many pixels (64 MB as 8-bit RGBA)...
constexpr std::int64_t kAlwaysPlausiblePixels = std::int64_t(4096) * 4096;
/// ...and beyond that to at most this many per byte of the file. Deflate (PNG, EXR, TIFF) gains at
/// most 1032:1, so even a blank 1-bit PNG stays below 8,300 pixels per byte (3,300 from zlib), a
/// JPEG near 250; a 69-byte PNG stating 11585 x 11585 pixels (134 million) is damaged or a bomb.
/// Only bilevel fax-coded TIFFs of blank pages can beat it, and they are no drawings.
constexpr std::int64_t kMaxPixelsPerFileByte = 16384;

/// Why width x height pixels, as an image's header states them, are not read from a file of
/// fileBytes bytes; empty when they may be. Checked before any pixel is decoded, by the header
/// readers of image_io.cpp and by the OpenImageIO module for every other format.
inline QString imageSizeProblem(std::int64_t width, std::int64_t height, std::int64_t fileBytes)
{
    if (width <= 0 || height <= 0)
        return QCoreApplication::translate("celform::model::ImageIo", "the image has no pixels");
    if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
        return QCoreApplication::translate("celform::model::ImageIo",
            "the image is too large (%1 x %2 pixels; drawings may have up to %3 pixels a side and %4 million in all)")
            .arg(width)
            .arg(height)
            .arg(kMaxImageSide)
            .arg(kMaxImagePixels / 1000000);
    if (width * height > std::max(kAlwaysPlausiblePixels, fileBytes * kMaxPixelsPerFileByte))
        return QCoreApplication::translate("celform::model::ImageIo",
            "the image is too large for its file (%1 x %2 pixels from %3 bytes): the file is damaged")
            .arg(width)
            .arg(height)
            .arg(fileBytes);
    return {};
}

/// The module's functions. They report problems as text, so no exception crosses the module.
struct RasterCodec {
    /// Decodes raster bytes of a format (lower-case suffix: png, jpg, tif, exr, psd, ...) to 8-bit
    /// straight-alpha RGBA, float pixels sRGB-encoded. A null image on failure, with the problem
    /// in *problem; fileLabel names the file in the messages.
    QImage (*decode)(const QByteArray& data, const QString& format, const QString& fileLabel, QString* problem);
    /// Encodes width by height 8-bit pixels of the named channels, interleaved, as a file of the
    /// format (lower-case suffix: png, jpg, tif) into *encoded, in memory. The caller writes the
    /// bytes (output_file.h), so no encoder ever meets a full disk (libjpeg ended the process on
    /// one). EXR files are made by exr_encoder.h. Returns the problem, empty on success.
    QString (*encode)(const QString& format, int width, int height, const std::vector<std::string>& channels,
        const unsigned char* pixels, std::vector<unsigned char>* encoded);
};

/// The entry the module exports: returns its functions.
using RasterCodecEntry = const RasterCodec* (*)();
constexpr const char* kRasterCodecEntry = "celform_raster_codec";

/// Loads the module on first use (beside the program or the library holding this code, in
/// ../lib/celform from there, or in the build tree) and returns its functions. Thread-safe.
/// Throws IoError naming fileLabel when the module cannot be loaded.
const RasterCodec& rasterCodec(const QString& fileLabel);

} // namespace celform::model
