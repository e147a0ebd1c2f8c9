// Mouse motion to brush steps; the document does the deformation (Document::applyBrushStroke).
#include "celform/views/tools/brush_tool.h"

#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/viewport.h"
#include "celform/views/viewport_keys.h"

#include <QCoreApplication>
#include <QTimer>

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

BrushTool::BrushTool(Viewport* viewport)
    : ViewportTool(viewport)
    , m_circle(new BrushCursor(viewport))
    , m_hoverTimer(new QTimer(viewport))
{
    m_hoverTimer->setSingleShot(true);
    m_hoverTimer->setInterval(16);
    QObject::connect(m_hoverTimer, &QTimer::timeout, viewport, [this] { updateCircle(); });
}

BrushTool::~BrushTool() = default; // the circle and the timer belong to the viewport

double BrushTool::radiusPixels(double unitsPerPixel) const
{
    if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
        return m_viewport->brushPixelRadius();
    return unitsPerPixel > 0.0 ? m_viewport->brushRadius() / unitsPerPixel : 0.0;
}

void BrushTool::updateCircle()
{
    if (m_resizing)
        return;
    const auto hit = m_viewport->pickSurface(m_hoverPos);
    if (!hit) {
        m_hoverUnitsPerPixel = 0.0;
        m_circle->hide();
        return;
    }
    m_hoverUnitsPerPixel = m_viewport->worldUnitsPerPixel(hit->second);
    m_circle->showCircle(m_hoverPos, radiusPixels(m_hoverUnitsPerPixel), m_viewport->brushProfile().falloff);
}

void BrushTool::hover(const QPointF& position)
{
    m_hoverPos = position;
    if (m_resizing) {
        // The radius is the cursor's distance from the circle's centre.
        const QPointF d = position - m_resizeCentre;
        const double pixels = std::max(std::sqrt(QPointF::dotProduct(d, d)), 2.0);
        if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
            m_viewport->setBrushPixelRadius(pixels);
        else if (m_hoverUnitsPerPixel > 0.0)
            m_viewport->setBrushRadius(pixels * m_hoverUnitsPerPixel);
        m_circle->showCircle(m_resizeCentre, pixels, m_viewport->brushProfile().falloff, true);
        return;
    }
    if (!m_hoverTimer->isActive())
        m_hoverTimer->start();
}

void BrushTool::leave()
{
    m_hoverTimer->stop();
    if (!m_resizing && !m_stroke.active())
        m_circle->hide();
}

void BrushTool::cameraChanged()
{
    // The surface under the cursor moved: its scale (world units per pixel) changed.
    if (m_circle->isVisible() && !m_resizing && !m_stroke.active())
        hover(m_hoverPos);
}

bool BrushTool::wantsKey(int key, Qt::KeyboardModifiers modifiers) const
{
    if (modifiers & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize)) // F, listed in Help > Keyboard Shortcuts
        return !m_stroke.active();
    return m_resizing && (key == Qt::Key_Escape || key == Qt::Key_Return || key == Qt::Key_Enter);
}

bool BrushTool::keyPress(int key, Qt::KeyboardModifiers modifiers)
{
    if (!wantsKey(key, modifiers))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize) && !m_resizing) {
        if (m_hoverUnitsPerPixel <= 0.0 && m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::World) {
            emit m_viewport->message(Brush::tr("Hold the cursor over the model to resize the brush there."));
            return true;
        }
        m_resizing = true;
        m_radiusBeforeResize = m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels
            ? m_viewport->brushPixelRadius()
            : m_viewport->brushRadius();
        // The circle stays where it is; moving the cursor away from its centre sizes it.
        const double pixels = radiusPixels(m_hoverUnitsPerPixel);
        m_resizeCentre = m_hoverPos - QPointF(pixels, 0.0);
        m_circle->showCircle(m_resizeCentre, pixels, m_viewport->brushProfile().falloff, true);
        emit m_viewport->message(
            Brush::tr("Move the mouse to resize the brush; click or Enter to keep, Esc to cancel."));
        return true;
    }
    endResize(key != Qt::Key_Escape);
    return true;
}

void BrushTool::endResize(bool keep)
{
    if (!m_resizing)
        return;
    m_resizing = false;
    if (!keep) {
        if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
            m_viewport->setBrushPixelRadius(m_radiusBeforeResize);
        else
            m_viewport->setBrushRadius(m_radiusBeforeResize);
    }
    updateCircle();
}

bool BrushTool::press(const ToolEvent& event)
{
    if (m_resizing) {
        endResize(true); // Blender: a click keeps the new size
        return false;
    }
    model::Document* document = m_viewport->document();
    const model::ObjectId key = m_viewport->displayedKey();
    if (!document || !document->data().key(key)) {
        emit m_viewport->message(Brush::tr("Choose a key to deform first (Scene panel, then Edit Key)."));
        return true;
    }
    const std::int64_t picked = m_viewport->pickVertex(event.position);
    if (picked < 0) {
        m_viewport->showBrushSelection(nullptr, nullptr);
        return true;
    }
    const Eigen::Vector3d pickedPoint = m_viewport->displayedShape().row(picked).cast<double>().transpose();
    const double unitsPerPixel = m_viewport->worldUnitsPerPixel(pickedPoint);
    // A radius in pixels is the world radius that many pixels span at the picked point.
    const double radius = m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels
        ? m_viewport->brushPixelRadius() * unitsPerPixel
        : m_viewport->brushRadius();
    try {
        m_stroke = document->beginBrushStroke(key, document->currentFrame(), std::uint32_t(picked), radius,
            m_viewport->camera(), m_viewport->brushMirrorX(), m_viewport->brushProfile());
    } catch (const model::EditRefused& e) {
        emit m_viewport->message(e.message());
        return true;
    }
    m_unitsPerPixel = unitsPerPixel;
    m_viewport->showBrushSelection(&m_stroke.selection, &m_stroke.mirrorSelection);
    m_hoverTimer->stop();
    m_circle->showCircle(event.position, radius / std::max(unitsPerPixel, 1e-12), m_viewport->brushProfile().falloff);
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
    if (m_viewport->brushMode() == Viewport::BrushMode::Smooth)
        step = {model::BrushMotion::Smooth, kSmoothStrength, 0.0};
    else if (m_viewport->brushMode() == Viewport::BrushMode::Relax)
        step = {model::BrushMotion::Relax, kSmoothStrength, 0.0};
    else if (ctrl && shift)
        step = {model::BrushMotion::Scale, std::exp(kScalePerPixel * d.x()), 0.0};
    else if (shift)
        step = {model::BrushMotion::Rotate, -kRadiansPerPixel * d.x(), 0.0};
    else if (ctrl)
        step = {model::BrushMotion::Push, -d.y() * m_unitsPerPixel, 0.0};
    else
        step = {model::BrushMotion::Drag, d.x() * m_unitsPerPixel, -d.y() * m_unitsPerPixel};
    document->applyBrushStroke(m_stroke, step);
    // The circle follows the cursor with the stroke's radius.
    m_circle->showCircle(event.position, m_circle->radiusPixels(), m_viewport->brushProfile().falloff);
}

void BrushTool::finish()
{
    if (model::Document* document = m_viewport->document())
        document->endBrushStroke(m_stroke);
}

void BrushTool::release(const ToolEvent& event)
{
    finish();
    // The selection is shown during the stroke only: afterwards (and after an undo) the model
    // shows its look again.
    m_viewport->showBrushSelection(nullptr, nullptr);
    m_hoverPos = event.position;
    updateCircle();
}

void BrushTool::cancel()
{
    finish();
    m_viewport->showBrushSelection(nullptr, nullptr);
}

void BrushTool::deactivate()
{
    m_resizing = false;
    m_hoverTimer->stop();
    m_circle->hide();
    finish();
    m_stroke = {};
    m_viewport->showBrushSelection(nullptr, nullptr);
}

} // namespace celform::views
