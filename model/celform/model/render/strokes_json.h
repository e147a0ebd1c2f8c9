// The strokes of a frame as JSON (issue 28, "Vector lines": `celform render --strokes F.json`):
// per eye, per stroke its kind, points, widths and depths, as the SVG draws them (svg_lines.h).
#pragma once

#include "celform/model/render/vector_lines.h"

#include <QByteArray>
#include <QString>

namespace celform::model {

/// {"format": "celform-strokes", "version": 1, "frame": F, "width": W, "height": H,
///  "eyes": [{"eye": "mono", "strokes": [{"kind": "silhouette", "kinds": ["silhouette"],
///  "closed": false, "points": [[x, y], ...], "widths": [...], "depths": [...]}, ...]}]}
/// Points in the eye's pixels (x right, y down), widths in pixels, depths the camera-space
/// distance along the view axis. Numbers with three decimals (depths with six significant
/// digits); deterministic.
QByteArray strokesJson(const VectorLines& lines);

/// Writes strokesJson(lines) to path whole or not at all (output_file.h). Throws IoError naming path.
void writeStrokesJson(const VectorLines& lines, const QString& path);

} // namespace celform::model
