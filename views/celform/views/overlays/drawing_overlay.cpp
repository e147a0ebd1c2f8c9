// The reference drawing's placement over the viewport (drawing_overlay.h).
#include "celform/views/overlays/drawing_overlay.h"

#include "celform/model/analysis/drawing_fit.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/drawing_outline.h"
#include "celform/views/overlays/outline_cache.h"

#include <QEvent>
#include <QLabel>
#include <QWidget>

#include <algorithm>

namespace celform::views {

DrawingOverlay::DrawingOverlay(model::Document* document, QWidget* view)
    : QObject(view)
    , m_document(document)
    , m_view(view)
    , m_outlines(std::make_shared<OutlineCache>())
    , m_banner(new QLabel(view))
{
    m_banner->setObjectName(QStringLiteral("outlineProblemBanner"));
    m_banner->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_banner->setWordWrap(true);
    m_banner->setStyleSheet(QStringLiteral("QLabel { background: rgba(190, 90, 20, 215); color: white; "
                                           "border-radius: 5px; padding: 4px 10px; }"));
    m_banner->hide();
    view->installEventFilter(this);
}

void DrawingOverlay::setDrawing(model::ObjectId drawing)
{
    if (drawing == m_drawing)
        return;
    emit drawingAboutToChange();
    m_drawing = drawing;
    emit drawingChanged();
    emit changed();
}

void DrawingOverlay::toggleShown(model::ObjectId drawing)
{
    if (drawing == 0)
        return;
    const bool shown = drawing == m_drawing;
    m_asked = shown ? 0 : drawing;
    setDrawing(shown ? 0 : drawing);
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

void DrawingOverlay::setProblem(const QString& problem)
{
    if (problem == m_problem)
        return;
    m_problem = problem;
    m_banner->setText(problem);
    m_banner->setVisible(!problem.isEmpty());
    if (!problem.isEmpty()) {
        placeBanner();
        m_banner->raise();
    }
    emit outlineProblemChanged(problem);
}

void DrawingOverlay::placeBanner()
{
    // At the bottom: the align tool's banner holds the top.
    m_banner->setMaximumWidth(std::max(m_view->width() - 40, 100));
    m_banner->adjustSize();
    m_banner->move((m_view->width() - m_banner->width()) / 2, m_view->height() - m_banner->height() - 8);
}

bool DrawingOverlay::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_view && event->type() == QEvent::Resize && m_banner->isVisible())
        placeBanner();
    return false;
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
    if (!drawing || !m_outline) {
        setProblem({});
        return drawing ? &drawing->image : nullptr;
    }
    // The outline Fit to Drawing aims at, so the artist sees and corrects it (its settings are
    // the drawing's, in the Properties panel); the cache extracts it once per settings.
    const std::shared_ptr<const algo::Outline> outline = m_outlines->outline(*drawing);
    setProblem(model::outlineProblem(*drawing, *outline));
    if (outline->ok()) {
        if (m_outlineSource != outline || m_outlineImage.isNull()) {
            // About two screen pixels wide once the drawing is scaled to the viewport.
            const double pen = std::max(2.0, 2.0 * drawing->image.height() / std::max(1, m_view->height()));
            m_outlineImage = model::outlineImage(*outline, QColor(255, 0, 170), pen);
            m_outlineSource = outline;
            m_edgesSource = 0;
        }
    } else if (m_edgesSource != drawing->image.cacheKey() || m_outlineImage.isNull()) {
        // No outline to aim at: the drawing's lines, in orange, to see what went wrong.
        m_outlineImage = drawingEdges(drawing->image, QColor(255, 140, 0));
        m_edgesSource = drawing->image.cacheKey();
        m_outlineSource.reset();
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
