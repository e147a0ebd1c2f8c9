// The lines of a frame as SVG (issue 28, "Vector lines"; docs/lines.md, "Vector lines"): one
// filled <path> per stroke, outlining its varying width, grouped by kind, in the image's pixels,
// with the tone regions as optional filled layers under them and a group per eye in stereo.
#pragma once

#include "celform/model/render/vector_lines.h"

#include <QByteArray>
#include <QString>

namespace celform::model {

/// The SVG document of lines (see the file comment). Deterministic: the same lines give the
/// same bytes. Coordinates with two decimals.
QByteArray linesSvg(const VectorLines& lines);

/// Writes linesSvg(lines) to path whole or not at all (output_file.h). Throws IoError naming path.
void writeLinesSvg(const VectorLines& lines, const QString& path);

} // namespace celform::model
