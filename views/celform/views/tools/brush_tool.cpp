// Mouse motion to brush steps; the document does the deformation (Document::applyBrushStroke).
#include "celform/views/tools/brush_tool.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/viewport/viewport.h"

#include <QCoreApplication>

#include <cmath>

namespace celform::views {
namespace {

struct Brush {
    Q_DECLARE_TR_FUNCTIONS(celform::views::BrushTool)
};

constexpr double kRadiansPerPixel = 0.5 * 3.14159265358979323846 / 180.0; // half a degree
constexpr double kScalePerPixel = 0.005; // exp(kScalePerPixel * pixels)
constexpr double kSmoothStrength = 0.25;

} // namespace

BrushTool::BrushTool(Viewport* viewport, BrushSize& size)
    : BrushHover(viewport, size)
{ }

BrushTool::~BrushTool() = default;

bool BrushTool::press(const ToolEvent& event)
{
    if (isResizing()) {
        endResize(true); // Blender: a click keeps the new size
        return false;
    }
    model::Document* document = m_viewport->document();
    const model::ObjectId key = m_viewport->displayedKey();
    if (!document || !document->data().key(key)) {
        emit message(Brush::tr("Choose a key to deform first (Scene panel, then Edit Key)."));
        return true;
    }
    const std::int64_t picked = m_viewport->pickVertex(event.position);
    if (picked < 0) {
        emit selectionChanged(nullptr, nullptr);
        return true;
    }
    const Eigen::Vector3d pickedPoint = m_viewport->displayedShape().row(picked).cast<double>().transpose();
    const double unitsPerPixel = m_viewport->worldUnitsPerPixel(pickedPoint);
    const double radius = size().worldRadius(unitsPerPixel);
    try {
        m_stroke = document->keys().beginBrushStroke(key, document->currentFrame(), std::uint32_t(picked), radius,
            m_viewport->camera(), m_settings.mirror ? document->data().mirrorPlane : model::MirrorPlane::Off,
            m_settings.profile);
    } catch (const model::EditRefused& e) {
        emit message(e.message());
        return true;
    }
    m_unitsPerPixel = unitsPerPixel;
    if (m_stroke.twinMissing)
        emit message(Brush::tr("The mirror finds no twin of this vertex across the %1 plane: only this side moves.")
                         .arg(model::mirrorPlaneName(document->data().mirrorPlane).toUpper()));
    emit selectionChanged(&m_stroke.selection, &m_stroke.mirrorSelection);
    showAt(event.position, radius / std::max(unitsPerPixel, 1e-12));
    return true;
}

void BrushTool::move(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !m_stroke.active())
        return;
    const QPointF d = event.delta;
    model::BrushStep step;
    const bool ctrl = event.modifiers & Qt::ControlModifier, shift = event.modifiers & Qt::ShiftModifier;
    if (m_settings.mode == BrushMode::Smooth)
        step = {model::BrushMotion::Smooth, kSmoothStrength, 0.0};
    else if (m_settings.mode == BrushMode::Relax)
        step = {model::BrushMotion::Relax, kSmoothStrength, 0.0};
    else if (ctrl && shift)
        step = {model::BrushMotion::Scale, std::exp(kScalePerPixel * d.x()), 0.0};
    else if (shift)
        step = {model::BrushMotion::Rotate, -kRadiansPerPixel * d.x(), 0.0};
    else if (ctrl)
        step = {model::BrushMotion::Push, -d.y() * m_unitsPerPixel, 0.0};
    else
        step = {model::BrushMotion::Drag, d.x() * m_unitsPerPixel, -d.y() * m_unitsPerPixel};
    document->keys().applyBrushStroke(m_stroke, step);
    // The circle follows the cursor with the stroke's radius.
    showAt(event.position, circlePixels());
}

void BrushTool::finish()
{
    if (model::Document* document = m_viewport->document())
        document->keys().endBrushStroke(m_stroke);
    m_stroke = {};
}

void BrushTool::release(const ToolEvent& event)
{
    finish();
    // The selection is shown during the stroke only: afterwards (and after an undo) the model
    // shows its look again.
    emit selectionChanged(nullptr, nullptr);
    hover(event.position);
    updateCircle();
}

void BrushTool::cancel()
{
    finish();
    emit selectionChanged(nullptr, nullptr);
}

bool BrushTool::holdsCamera() const
{
    return m_viewport->displayedKey() != 0;
}

void BrushTool::deactivate()
{
    stopHover();
    finish();
    emit selectionChanged(nullptr, nullptr);
}

} // namespace celform::views
