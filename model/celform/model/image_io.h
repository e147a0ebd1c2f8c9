// Reference drawing import: raster formats through OpenImageIO, SVG through Qt Svg.
#pragma once

#include "celform/model/project_data.h"

#include <QImage>
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

/// Suffixes importDrawing() understands, lower case without the dot.
QStringList imageSuffixes();
/// A file dialog filter for drawings, translated.
QString imageFileFilter();

} // namespace celform::model
