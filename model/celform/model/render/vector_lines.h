// A frame's lines as geometry (issue 28, "Vector lines"): the strokes the lines pass draws, cut to
// their visible parts, per eye, with the tone regions as polygons; what the SVG and stroke JSON
// writers write (svg_lines.h, strokes_json.h).
#pragma once

#include "celform/algorithms/render.h"
#include "celform/algorithms/stereo.h"
#include "celform/model/data/project_data.h"

#include <Eigen/Core>

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <vector>

namespace celform::model {

/// One tone of the picture: the pixels of the model whose tone pass is nearest this level of the
/// look's toon ramp, outlined (algo::traceRegionOutlines), and their mean colour.
struct VectorTone {
    float level = 0.f; ///< the ramp's intensity
    algo::Color color = algo::Color::Zero(); ///< linear, the beauty's mean away from the lines
    std::vector<std::vector<Eigen::Vector2i>> outlines; ///< pixel corners, holes reversed
};

/// The lines of one picture: the mono one, or one eye of a stereo pair.
struct VectorLinesEye {
    QString name; ///< "mono", "left" or "right"
    std::vector<algo::StyledStroke> strokes; ///< visible parts, in this eye's pixels
    std::vector<VectorTone> tones; ///< empty unless asked for
};

struct VectorLines {
    int width = 0, height = 0; ///< of each eye's picture
    int frame = 0;
    algo::StereoOutput stereo = algo::StereoOutput::Off;
    algo::Color lineColor = algo::Color::Zero(); ///< linear
    std::vector<VectorLinesEye> eyes; ///< one in mono, left then right in stereo
};

/// The vector lines of rendered eyes (renderEyes without the centre: one in mono, left and right
/// in stereo): the strokes of each cut to what its lines pass shows (algo::visibleStrokeParts
/// against its depth and ids), and with tones the tone regions of the look's toon ramp.
VectorLines vectorLinesOf(
    const std::vector<algo::RenderPasses>& eyes, algo::StereoOutput stereo, const Look& look, bool tones, int frame);

/// The kind a stroke is filed under: the first of silhouette, border, crease, material, ridge it has.
std::uint8_t primaryLineKind(std::uint8_t kinds);
/// The writers' names of line kinds: "silhouette", "crease", "border", "material", "ridge".
QString lineKindName(std::uint8_t kind);
/// v with at most `decimals` decimals and no trailing zeros ("-0" is "0"; non-finite: "null"),
/// the writers' numbers: the same value always gives the same text.
QByteArray decimalText(double v, int decimals);

/// The kinds in the order the writers group them: silhouette, border, crease, material, ridge.
const std::vector<std::uint8_t>& lineKindOrder();

} // namespace celform::model
