// The reference drawing's placement over the viewport (drawing_overlay.h).
#include "celform/views/overlays/drawing_overlay.h"

#include "celform/model/document/document.h"
#include "celform/views/overlays/drawing_outline.h"

#include <QWidget>

#include <algorithm>

namespace celform::views {

DrawingOverlay::DrawingOverlay(model::Document* document, QWidget* view)
    : QObject(view)
    , m_document(document)
    , m_view(view)
{ }

void DrawingOverlay::setDrawing(model::ObjectId drawing)
{
    if (drawing == m_drawing)
        return;
    emit drawingAboutToChange();
    m_drawing = drawing;
    emit drawingChanged();
    emit changed();
}

void DrawingOverlay::setOnTop(bool onTop)
{
    if (onTop == m_onTop)
        return;
    m_onTop = onTop;
    emit changed();
}

void DrawingOverlay::setOutline(bool on)
{
    if (on == m_outline)
        return;
    m_outline = on;
    emit changed();
}

const model::Drawing* DrawingOverlay::current() const
{
    return (m_document && m_drawing) ? m_document->data().drawing(m_drawing) : nullptr;
}

const model::Drawing* DrawingOverlay::resolve()
{
    const model::Drawing* drawing = current();
    if (!drawing)
        m_drawing = 0;
    return drawing;
}

const QImage* DrawingOverlay::image()
{
    const model::Drawing* drawing = current();
    if (!drawing)
        return nullptr;
    if (!m_outline)
        return &drawing->image;
    if (m_outlineSource != drawing->image.cacheKey() || m_outlineImage.isNull()) {
        m_outlineImage = drawingOutline(drawing->image);
        m_outlineSource = drawing->image.cacheKey();
    }
    return &m_outlineImage;
}

double DrawingOverlay::opacity() const
{
    const model::Drawing* drawing = current();
    return drawing && !m_outline ? drawing->opacity : 1.0;
}

double DrawingOverlay::frameScale() const
{
    const model::Drawing* drawing = current();
    const int width = m_view->width(), height = m_view->height();
    if (!drawing || drawing->image.isNull() || width <= 0 || height <= 0)
        return 1.0;
    // The drawing fits inside the viewport; the camera's frame is the drawing's frame.
    const double fit = std::min(double(width) / drawing->image.width(), double(height) / drawing->image.height());
    return std::max(1.0, double(height) / (fit * drawing->image.height()));
}

std::optional<Eigen::Vector2d> DrawingOverlay::widgetToDrawing(const QPointF& position) const
{
    const model::Drawing* drawing = current();
    if (!drawing || drawing->image.isNull())
        return std::nullopt;
    const double w = drawing->image.width(), h = drawing->image.height();
    const double width = m_view->width(), height = m_view->height();
    const double fit = std::min(width / w, height / h);
    const double x = (position.x() - 0.5 * (width - fit * w)) / fit;
    const double y = (position.y() - 0.5 * (height - fit * h)) / fit;
    if (x < 0 || y < 0 || x > w || y > h)
        return std::nullopt;
    return Eigen::Vector2d(x, y);
}

QPointF DrawingOverlay::drawingToWidget(const Eigen::Vector2d& pixel) const
{
    const model::Drawing* drawing = current();
    if (!drawing || drawing->image.isNull())
        return {};
    const double w = drawing->image.width(), h = drawing->image.height();
    const double width = m_view->width(), height = m_view->height();
    const double fit = std::min(width / w, height / h);
    return {0.5 * (width - fit * w) + fit * pixel.x(), 0.5 * (height - fit * h) + fit * pixel.y()};
}

} // namespace celform::views
