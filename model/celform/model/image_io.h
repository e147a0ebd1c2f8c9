// Reference drawing import: raster formats through OpenImageIO, SVG through Qt Svg.
#pragma once

#include "celform/model/project_data.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>

namespace celform::model {

/// Reads an image file into a Drawing (bytes embedded, decoded image filled, name from the file
/// name, id 0). Throws IoError for a missing, empty, truncated or unreadable file.
Drawing importDrawing(const QString& path);

/// Decodes embedded image bytes of the given format (suffix). SVG is rendered at 1024 px high
/// on transparent. HDR images are tone-clamped to 8 bits per channel for display. Throws
/// IoError with fileLabel as the file name.
QImage decodeImage(const QByteArray& data, const QString& format, const QString& fileLabel);

/// The size decodeImage() gives, read from the header for PNG, JPEG and BMP (Qt's readers) and
/// from the view box for SVG, decoding only the other formats: for readers that show sizes, like
/// `celform info`, without paying for the pixels or for loading OpenImageIO. Throws IoError.
QSize decodedImageSize(const QByteArray& data, const QString& format, const QString& fileLabel);

/// Suffixes importDrawing() understands, lower case without the dot.
QStringList imageSuffixes();
/// A file dialog filter for drawings, translated.
QString imageFileFilter();

} // namespace celform::model
