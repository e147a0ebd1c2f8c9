// Docks to tools and back (tool_panels.h).
#include "editor/actions/tool_panels.h"

#include "celform/model/document/document.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/panels/highlight_panel.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/tools/align_tool.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/tools/highlight_tool.h"
#include "celform/views/tools/offset_brush_tool.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/viewport.h"

namespace celform::app {

void connectToolPanels(views::Viewport& viewport, views::PropertiesPanel& properties, views::HighlightPanel& highlights,
    views::DepthPanel& depth)
{
    using views::PropertiesPanel;
    views::BrushTool& brush = viewport.tool<views::BrushTool>();
    views::BrushSize& size = brush.size();
    QObject::connect(&properties, &PropertiesPanel::brushRadiusEdited, &size, &views::BrushSize::setRadius);
    QObject::connect(&properties, &PropertiesPanel::brushPixelRadiusEdited, &size, &views::BrushSize::setPixelRadius);
    QObject::connect(&properties, &PropertiesPanel::brushRadiusInPixelsEdited, &size, [&size](bool pixels) {
        size.setUnit(pixels ? views::BrushSize::Unit::Pixels : views::BrushSize::Unit::World);
    });
    QObject::connect(&properties, &PropertiesPanel::brushProfileEdited, &brush,
        [&brush](const algo::BrushProfile& profile) { brush.settings().profile = profile; });
    QObject::connect(&properties, &PropertiesPanel::brushModeEdited, &brush,
        [&brush](int mode) { brush.settings().mode = views::BrushMode(mode); });
    QObject::connect(
        &properties, &PropertiesPanel::brushMirrorEdited, &brush, [&brush](bool on) { brush.settings().mirror = on; });
    auto showRadius = [&properties, &size] { properties.showBrushRadius(size.radius(), size.pixelRadius()); };
    QObject::connect(&size, &views::BrushSize::radiusChanged, &properties, showRadius);
    QObject::connect(&size, &views::BrushSize::pixelRadiusChanged, &properties, showRadius);
    if (const double radius = properties.defaultBrushRadius(); radius > 0.0)
        size.setRadius(radius);
    showRadius();

    views::AlignTool& align = viewport.tool<views::AlignTool>();
    auto showMatching = [&properties, &align] {
        properties.showMatching(
            int(align.matchedModelPoints().size()), int(align.matchedDrawingPoints().size()), align.isPointMatching());
    };
    QObject::connect(&align, &views::AlignTool::matchedPointsChanged, &properties, showMatching);
    QObject::connect(&properties, &PropertiesPanel::pointMatchingToggled, &align, [&align, showMatching](bool on) {
        align.setPointMatching(on);
        showMatching();
    });
    // Leaving the align tool ends matching (the tool's deactivate): the button follows.
    QObject::connect(&viewport, &views::Viewport::toolChanged, &properties, showMatching);
    QObject::connect(
        &properties, &PropertiesPanel::clearMatchedPointsRequested, &align, [&align] { align.clearMatchedPoints(); });
    QObject::connect(&properties, &PropertiesPanel::solveCameraRequested, &align, [&align, &properties] {
        QString error;
        const auto rms = align.solveFromMatchedPoints(&error);
        properties.showSolveResult(rms, error);
    });

    QObject::connect(&highlights, &views::HighlightPanel::highlightTargetChosen, &viewport,
        [&viewport](model::ObjectId layer) { viewport.tool<views::HighlightTool>().setTarget(layer); });
    QObject::connect(
        &highlights, &views::HighlightPanel::patchTargetChosen, &viewport, [&viewport](const QString& faceSet) {
            viewport.tool<views::PatchTool>().setTarget(faceSet);
            viewport.tool<views::PatchTool>().setMode(views::PatchTool::Mode::Patch);
        });
    QObject::connect(&highlights, &views::HighlightPanel::patchMirrorToggled, &viewport,
        [&viewport](bool on) { viewport.tool<views::PatchTool>().setMirror(on); });

    auto* offsets = &viewport.tool<views::OffsetBrushTool>();
    auto showTarget = [&depth, offsets] { depth.showOffsetTarget(offsets->targetText()); };
    QObject::connect(&viewport, &views::Viewport::toolChanged, &depth, showTarget);
    if (model::Document* document = viewport.document())
        QObject::connect(document, &model::Document::changed, &depth, showTarget);
    showTarget();
}

} // namespace celform::app
