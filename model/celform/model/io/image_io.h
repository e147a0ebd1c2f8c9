// Reference drawing import: raster formats through OpenImageIO, SVG through Qt Svg. Every raster
// format but PNG and JPEG is decoded in a child process (import_process.h).
#pragma once

#include "celform/model/io/import_process.h"
#include "celform/model/data/project_data.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>

#include <vector>

namespace celform::model {

/// Reads an image file into a Drawing (bytes embedded, decoded image filled, name from the file
/// name, id 0). Throws IoError for a missing, empty, truncated or unreadable file.
Drawing importDrawing(const QString& path);

/// Decodes embedded image bytes of the given format (suffix). SVG is rendered at 1024 px high
/// on transparent. HDR images are tone-clamped to 8 bits per channel for display. Throws
/// IoError with fileLabel as the file name. PSD, TIFF, EXR and the other formats OpenImageIO reads
/// besides PNG and JPEG are decoded in a child process unless isolation says otherwise: a crash,
/// hang or huge allocation inside OpenImageIO is then an IoError too.
QImage decodeImage(const QByteArray& data, const QString& format, const QString& fileLabel,
    ImportIsolation isolation = ImportIsolation::ChildProcess);

/// One image for decodeImages(): its bytes, its format (suffix) and the label naming it in messages.
struct EncodedImage {
    QByteArray data;
    QString format;
    QString label;
};

/// decodeImage() for several images: those decoded in a child process share one, which loads
/// OpenImageIO once (half a second of processor time) rather than once an image. Throws IoError
/// naming an image that cannot be decoded.
std::vector<QImage> decodeImages(const std::vector<EncodedImage>& images);

/// The child's half of decodeImages() (`celform import-image IN OUT`): decodes every image file in
/// the folder inFolder (the suffix gives the format) in this process and writes each one's pixels
/// to a file of the same base name in outFolder. Throws IoError naming inFolder.
void decodeImagesForParent(const QString& inFolder, const QString& outFolder);

/// The size decodeImage() gives, read from the header for PNG, JPEG, BMP and PSD and
/// from the view box for SVG, decoding only the other formats: for readers that show sizes, like
/// `celform info`, without paying for the pixels or for loading OpenImageIO. Throws IoError.
QSize decodedImageSize(const QByteArray& data, const QString& format, const QString& fileLabel);

/// Suffixes importDrawing() understands, lower case without the dot.
QStringList imageSuffixes();
/// A file dialog filter for drawings, translated.
QString imageFileFilter();

} // namespace celform::model
