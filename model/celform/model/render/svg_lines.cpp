// The lines of a frame as SVG (svg_lines.h).
//
// A stroke is drawn by the renderer as a chain of capsules whose width varies linearly along
// each segment (raster.h, drawStrokes). Its SVG outline is the same shape as one closed contour:
// the left offsets forward, a round cap, the right offsets backward, a round cap, offsets at
// each point by half its width along the segment's normal. At a bend the outer side is joined by
// an arc about the point, and the inner side passes through the point itself (the "pivot" inner
// join of stroking renderers, as Skia's SkStroke), so the non-zero fill rule covers the
// overlapping corners and no fish-tail is left out. Closed strokes are a band between two loops
// of opposite direction.
#include "celform/model/render/svg_lines.h"

#include "celform/model/io/output_file.h"

#include "celform/algorithms/image.h"

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

/// The file's coordinates: two decimals.
QByteArray num(double v)
{
    return decimalText(v, 2);
}

QByteArray point(const Eigen::Vector2f& p)
{
    return num(p.x()) + ' ' + num(p.y());
}

/// An sRGB hex colour of a linear colour.
QByteArray hexColor(const algo::Color& c)
{
    QByteArray s = "#";
    for (int i = 0; i < 3; ++i) {
        const int v = int(std::lround(std::clamp(algo::linearToSrgb(std::clamp(c[i], 0.f, 1.f)), 0.f, 1.f) * 255.f));
        s += QByteArray::number(v, 16).rightJustified(2, '0');
    }
    return s;
}

float cross(const Eigen::Vector2f& a, const Eigen::Vector2f& b)
{
    return a.x() * b.y() - a.y() * b.x();
}

/// The stroke's points without repeats (a closed stroke's repeated last point dropped) and
/// their half widths.
struct Centreline {
    std::vector<Eigen::Vector2f> p;
    std::vector<float> r;
    bool closed = false;
};

Centreline centreline(const algo::StyledStroke& s)
{
    Centreline c;
    for (std::size_t k = 0; k < s.points.size(); ++k) {
        if (!s.points[k].allFinite())
            continue;
        if (!c.p.empty() && (s.points[k] - c.p.back()).norm() < 1e-3f)
            continue;
        c.p.push_back(s.points[k]);
        c.r.push_back(std::max(0.f, 0.5f * s.widths[k]));
    }
    if (s.closed && c.p.size() >= 4 && (c.p.front() - c.p.back()).norm() < 1e-2f) {
        c.p.pop_back();
        c.r.pop_back();
        c.closed = true;
    } else if (s.closed && c.p.size() >= 3) {
        c.closed = true;
    }
    return c;
}

/// From p + n0 r (already reached) to p + n1 r on one side: an arc about p when that side is the
/// outer one of the bend, else through p.
void join(QByteArray& d, const Eigen::Vector2f& p, float r, const Eigen::Vector2f& n1, bool outer)
{
    const Eigen::Vector2f to = p + r * n1;
    if (outer)
        d += " A" + num(r) + ' ' + num(r) + " 0 0 1 " + point(to);
    else
        d += " L" + point(p) + " L" + point(to);
}

/// The outline of a stroke as path data (see the file comment).
QByteArray outline(const algo::StyledStroke& stroke)
{
    const Centreline c = centreline(stroke);
    const std::size_t m = c.p.size();
    QByteArray d;
    if (m == 0)
        return d;
    if (m == 1) {
        const float r = c.r[0];
        const Eigen::Vector2f a = c.p[0] - Eigen::Vector2f(r, 0.f), b = c.p[0] + Eigen::Vector2f(r, 0.f);
        d += "M" + point(a) + " A" + num(r) + ' ' + num(r) + " 0 1 1 " + point(b) + " A" + num(r) + ' ' + num(r)
            + " 0 1 1 " + point(a) + " Z";
        return d;
    }
    const std::size_t segments = c.closed ? m : m - 1;
    std::vector<Eigen::Vector2f> dir(segments), n(segments);
    for (std::size_t k = 0; k < segments; ++k) {
        dir[k] = (c.p[(k + 1) % m] - c.p[k]).normalized();
        n[k] = Eigen::Vector2f(dir[k].y(), -dir[k].x()); // the left on screen (y down)
    }
    // Left side forward: segment k from p[k] to p[k + 1], then the bend at p[k + 1].
    d += "M" + point(c.p[0] + c.r[0] * n[0]);
    for (std::size_t k = 0; k < segments; ++k) {
        const std::size_t v = (k + 1) % m;
        d += " L" + point(c.p[v] + c.r[v] * n[k]);
        if (c.closed || k + 1 < segments) {
            const std::size_t next = (k + 1) % segments;
            join(d, c.p[v], c.r[v], n[next], cross(dir[k], dir[next]) > 0.f);
        }
    }
    const auto cap = [&](std::size_t v, const Eigen::Vector2f& normal) {
        d += " A" + num(c.r[v]) + ' ' + num(c.r[v]) + " 0 0 1 " + point(c.p[v] - c.r[v] * normal);
    };
    if (c.closed) {
        d += " Z M" + point(c.p[0] - c.r[0] * n[segments - 1]);
    } else {
        cap(m - 1, n[segments - 1]);
    }
    // Right side backward: segment k from p[k + 1] to p[k], then the bend at p[k].
    for (std::size_t s = segments; s-- > 0;) {
        d += " L" + point(c.p[s] - c.r[s] * n[s]);
        if (c.closed || s > 0) {
            const std::size_t previous = (s + segments - 1) % segments;
            join(d, c.p[s], c.r[s], -n[previous], cross(dir[previous], dir[s]) < 0.f);
        }
    }
    if (!c.closed)
        cap(0, -n[0]);
    d += " Z";
    return d;
}

/// An eye's colour in an anaglyph (paper 3, section 4.5.2: red from the left eye, green and blue
/// from the right): the other eye's channels white, so eyes multiplied over each other compose.
algo::Color eyeColor(const algo::Color& c, algo::StereoOutput stereo, const QString& eye)
{
    if (stereo != algo::StereoOutput::Anaglyph)
        return c;
    return eye == QLatin1String("left") ? algo::Color(c.x(), 1.f, 1.f) : algo::Color(1.f, c.y(), c.z());
}

void writeEye(QByteArray& svg, const VectorLines& lines, const VectorLinesEye& eye)
{
    const bool stereo = lines.eyes.size() > 1;
    const QByteArray prefix = stereo ? eye.name.toUtf8() + '-' : QByteArray();
    const QByteArray indent = stereo ? "    " : "  ";
    if (stereo) {
        QByteArray transform;
        if (eye.name == QLatin1String("right") && lines.stereo == algo::StereoOutput::SideBySide)
            transform = " transform=\"translate(" + QByteArray::number(lines.width) + " 0)\"";
        else if (eye.name == QLatin1String("right") && lines.stereo == algo::StereoOutput::TopBottom)
            transform = " transform=\"translate(0 " + QByteArray::number(lines.height) + ")\"";
        const QByteArray blend
            = lines.stereo == algo::StereoOutput::Anaglyph ? " style=\"mix-blend-mode:multiply\"" : QByteArray();
        svg += "  <g id=\"" + eye.name.toUtf8() + "\" class=\"eye\" inkscape:groupmode=\"layer\" inkscape:label=\""
            + eye.name.toUtf8() + "\"" + transform + blend + ">\n";
    }
    if (!eye.tones.empty()) {
        svg += indent + "<g id=\"" + prefix + "tones\" class=\"tones\" inkscape:groupmode=\"layer\" "
            + "inkscape:label=\"tones\" stroke=\"none\">\n";
        for (const VectorTone& tone : eye.tones) {
            QByteArray d;
            for (const std::vector<Eigen::Vector2i>& loop : tone.outlines) {
                for (std::size_t k = 0; k < loop.size(); ++k)
                    d += QByteArray(k == 0 ? "M" : " L") + QByteArray::number(loop[k].x()) + ' '
                        + QByteArray::number(loop[k].y());
                d += " Z ";
            }
            svg += indent + "  <path class=\"tone\" data-tone=\"" + num(tone.level) + "\" fill=\""
                + hexColor(eyeColor(tone.color, lines.stereo, eye.name)) + "\" d=\"" + d.trimmed() + "\"/>\n";
        }
        svg += indent + "</g>\n";
    }
    const QByteArray ink = hexColor(eyeColor(lines.lineColor, lines.stereo, eye.name));
    for (const std::uint8_t kind : lineKindOrder()) {
        const QByteArray name = lineKindName(kind).toUtf8();
        QByteArray paths;
        for (const algo::StyledStroke& stroke : eye.strokes) {
            if (primaryLineKind(stroke.kinds) != kind)
                continue;
            const QByteArray d = outline(stroke);
            if (d.isEmpty())
                continue;
            QByteArray classes = "stroke";
            for (const std::uint8_t k : lineKindOrder())
                if (stroke.kinds & k)
                    classes += ' ' + lineKindName(k).toUtf8();
            const float width
                = stroke.widths.empty() ? 0.f : *std::max_element(stroke.widths.begin(), stroke.widths.end());
            paths += indent + "  <path class=\"" + classes + "\" data-kind=\"" + name + "\" data-width=\"" + num(width)
                + "\" d=\"" + d + "\"/>\n";
        }
        if (paths.isEmpty())
            continue;
        svg += indent + "<g id=\"" + prefix + name + "\" class=\"lines " + name + "\" inkscape:groupmode=\"layer\" "
            + "inkscape:label=\"" + name + "\" fill=\"" + ink + "\" fill-rule=\"nonzero\" stroke=\"none\">\n" + paths
            + indent + "</g>\n";
    }
    if (stereo)
        svg += "  </g>\n";
}

} // namespace

QByteArray linesSvg(const VectorLines& lines)
{
    int width = lines.width, height = lines.height;
    if (lines.eyes.size() > 1 && lines.stereo == algo::StereoOutput::SideBySide)
        width *= 2;
    if (lines.eyes.size() > 1 && lines.stereo == algo::StereoOutput::TopBottom)
        height *= 2;
    const QByteArray w = QByteArray::number(width), h = QByteArray::number(height);
    QByteArray svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                     "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" width=\""
        + w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + ' ' + h + "\" data-frame=\""
        + QByteArray::number(lines.frame) + "\">\n";
    for (const VectorLinesEye& eye : lines.eyes)
        writeEye(svg, lines, eye);
    svg += "</svg>\n";
    return svg;
}

void writeLinesSvg(const VectorLines& lines, const QString& path)
{
    writeWholeFile(path, linesSvg(lines));
}

} // namespace celform::model
