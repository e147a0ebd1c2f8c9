// The strokes of a frame as JSON (strokes_json.h). Written by hand rather than through
// QJsonDocument, to fix the numbers' precision and keep big frames one line per stroke.
#include "celform/model/render/strokes_json.h"

#include "celform/model/io/output_file.h"

#include <cmath>

namespace celform::model {
namespace {

QByteArray fixed(double v)
{
    return decimalText(v, 3);
}

QByteArray significant(double v)
{
    return std::isfinite(v) ? QByteArray::number(v, 'g', 6) : QByteArray("null");
}

} // namespace

QByteArray strokesJson(const VectorLines& lines)
{
    QByteArray out = "{\"format\": \"celform-strokes\", \"version\": 1, \"frame\": " + QByteArray::number(lines.frame)
        + ", \"width\": " + QByteArray::number(lines.width) + ", \"height\": " + QByteArray::number(lines.height)
        + ",\n \"eyes\": [";
    for (std::size_t e = 0; e < lines.eyes.size(); ++e) {
        const VectorLinesEye& eye = lines.eyes[e];
        out += QByteArray(e ? ",\n  " : "\n  ") + "{\"eye\": \"" + eye.name.toUtf8() + "\", \"strokes\": [";
        for (std::size_t s = 0; s < eye.strokes.size(); ++s) {
            const algo::StyledStroke& stroke = eye.strokes[s];
            QByteArray kinds;
            for (const std::uint8_t k : lineKindOrder())
                if (stroke.kinds & k)
                    kinds += QByteArray(kinds.isEmpty() ? "" : ", ") + '"' + lineKindName(k).toUtf8() + '"';
            QByteArray points, widths, depths;
            for (std::size_t k = 0; k < stroke.points.size(); ++k) {
                const char* comma = k ? ", " : "";
                points += comma + ('[' + fixed(stroke.points[k].x()) + ", " + fixed(stroke.points[k].y()) + ']');
                widths += comma + fixed(stroke.widths[k]);
                depths += comma + significant(stroke.depths[k]);
            }
            out += QByteArray(s ? ",\n   " : "\n   ") + "{\"kind\": \""
                + lineKindName(primaryLineKind(stroke.kinds)).toUtf8() + "\", \"kinds\": [" + kinds
                + "], \"closed\": " + (stroke.closed ? "true" : "false") + ", \"points\": [" + points
                + "], \"widths\": [" + widths + "], \"depths\": [" + depths + "]}";
        }
        out += "]}";
    }
    out += "]}\n";
    return out;
}

void writeStrokesJson(const VectorLines& lines, const QString& path)
{
    writeWholeFile(path, strokesJson(lines));
}

} // namespace celform::model
