// The preset layers. Their values were tuned on the sample elephant seen from the front
// (resources/samples/elephant-highlights.celform): its ear is nearly flat like the paper's car
// window, where the plain highlight covers everything (Figure 5a); smoothed normals give clean
// outlines on its coarse mesh.
#include "celform/model/document/highlight_presets.h"

#include <QCoreApplication>

namespace celform::model {
namespace {

/// The names keep the Highlights dock's translation context, where they were first shown.
struct Text {
    Q_DECLARE_TR_FUNCTIONS(celform::views::HighlightPanel)
};

} // namespace

std::vector<HighlightTrack> highlightPresetLayers(HighlightPreset preset, const HighlightTrack& base, int frame)
{
    HighlightTrack start;
    start.patch = base.patch;
    start.guide = base.guide;
    start.smoothing = base.smoothing > 0 ? base.smoothing : 8;
    using Op = algo::HighlightOperation;
    if (preset == HighlightPreset::Window) {
        // Figure 5b: rotation, directional scaling and split turn the window-filling highlight
        // into a long streak and a short one.
        HighlightTrack window = start;
        window.name = Text::tr("Window");
        algo::HighlightLayer layer;
        layer.shape.epsilon = 0.03f;
        layer.shape.operations = {Op::rotation(30.f), Op::directionalScaling(0.6f), Op::split(0.25f, 0.f)};
        window.setKey(frame, layer);
        return {window};
    }
    // Figure 6: G minus H, H the same area moved along du and dv.
    HighlightTrack cut = start;
    cut.name = Text::tr("Crescent cut");
    cut.visible = false;
    algo::HighlightLayer cutLayer;
    cutLayer.shape.epsilon = 0.04f;
    cutLayer.shape.operations = {Op::translation(0.1f, 0.1f)};
    cut.setKey(frame, cutLayer);
    HighlightTrack crescent = start;
    crescent.name = Text::tr("Crescent");
    algo::HighlightLayer layer;
    layer.shape.epsilon = 0.04f;
    crescent.setKey(frame, layer);
    crescent.combineWith.emplace_back(algo::HighlightBoolean::Subtraction, cut.name);
    return {cut, crescent};
}

algo::HighlightOperation neutralHighlightOperation(algo::HighlightOperationType type)
{
    using T = algo::HighlightOperationType;
    switch (type) {
    case T::Translation:
        return algo::HighlightOperation::translation(0.f, 0.f);
    case T::Rotation:
        return algo::HighlightOperation::rotation(0.f);
    case T::DirectionalScaling:
        return algo::HighlightOperation::directionalScaling(0.f);
    case T::Split:
        return algo::HighlightOperation::split(0.f, 0.f);
    case T::Squaring:
        return algo::HighlightOperation::squaring(0.2f, 2.f);
    }
    return {};
}

} // namespace celform::model
