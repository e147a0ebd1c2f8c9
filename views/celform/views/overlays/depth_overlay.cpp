// The depth analysis over the viewport (depth_overlay.h).
#include "celform/views/overlays/depth_overlay.h"

#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/viewport/viewport.h"

#include <QEvent>
#include <QPainter>

namespace celform::views {

DepthOverlay::DepthOverlay(Viewport* viewport, DepthAnalysisRunner* runner)
    : QWidget(viewport)
    , m_viewport(viewport)
    , m_runner(runner)
{
    setObjectName(QStringLiteral("depthOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setGeometry(viewport->rect());
    viewport->installEventFilter(this);
    connect(runner, &DepthAnalysisRunner::analysed, this, qOverload<>(&QWidget::update));
    connect(viewport, &Viewport::cameraChanged, this, qOverload<>(&QWidget::update));
    hide();
}

void DepthOverlay::setKind(Kind kind)
{
    m_kind = kind;
    setVisible(kind != Kind::None);
    if (kind != Kind::None)
        raise();
    update();
}

void DepthOverlay::setOpacity(double opacity)
{
    m_opacity = std::clamp(opacity, 0.0, 1.0);
    update();
}

bool DepthOverlay::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_viewport && event->type() == QEvent::Resize)
        setGeometry(m_viewport->rect());
    return QWidget::eventFilter(watched, event);
}

void DepthOverlay::drawLegend(QPainter& painter, const QString& positive, const QString& negative,
    const QColor& positiveColor, const QColor& negativeColor, float scale)
{
    const QFontMetrics metrics(painter.font());
    const int line = metrics.height();
    const QString range = tr("saturates at ±%1").arg(double(scale), 0, 'g', 3);
    const int textWidth = std::max(
        {metrics.horizontalAdvance(positive), metrics.horizontalAdvance(negative), metrics.horizontalAdvance(range)});
    // Bottom right: the axis triad has the bottom left, hints the bottom centre.
    const QSize size(textWidth + line + 22, 3 * line + 12);
    const QRect box(QPoint(width() - 8 - size.width(), height() - 8 - size.height()), size);
    painter.setOpacity(1.0);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRoundedRect(box, 4, 4);
    const int x = box.left() + 8;
    int y = box.top() + 6;
    for (const auto& [text, colour] : {std::pair{positive, positiveColor}, std::pair{negative, negativeColor}}) {
        painter.setBrush(colour);
        painter.setPen(QColor(60, 60, 60));
        painter.drawRect(QRect(x, y + 2, line - 4, line - 4));
        painter.drawText(QPoint(x + line + 2, y + metrics.ascent()), text);
        y += line;
    }
    painter.drawText(QPoint(x, y + metrics.ascent()), range);
}

void DepthOverlay::paintEvent(QPaintEvent*)
{
    const auto result = m_runner->result();
    if (m_kind == Kind::None || !result)
        return;
    QPainter painter(this);
    if (!result->error.isEmpty()) {
        painter.setPen(QColor(160, 30, 30));
        painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignBottom | Qt::AlignLeft, result->error);
        return;
    }
    const QImage& image = m_kind == Kind::Segments ? result->segments
        : m_kind == Kind::Curvature                ? result->curvature
                                                   : result->depthError;
    // A result made through another camera is drawn faded until the new one arrives.
    painter.setOpacity(m_runner->isCurrent() ? m_opacity : m_opacity * 0.4);
    painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
    painter.drawImage(rect(), image);

    painter.setOpacity(1.0);
    const QColor orange(245, 128, 13), blue(26, 89, 242);
    if (m_kind == Kind::Curvature) {
        drawLegend(painter, tr("K > 0 (dome)"), tr("K < 0 (saddle)"), orange, blue, result->curvatureScale);
    } else if (m_kind == Kind::DepthError) {
        drawLegend(painter, tr("seen farther than it is"), tr("seen nearer than it is"), blue, orange,
            result->depthErrorScale);
    } else {
        // Segment numbers at their centres, as in the Depth panel's table.
        painter.setPen(Qt::black);
        const double sx = double(width()) / std::max(1, result->width);
        const double sy = double(height()) / std::max(1, result->height);
        for (std::size_t i = 0; i < result->segmentStats.size(); ++i) {
            const algo::SegmentStats& s = result->segmentStats[i];
            if (s.pixels < 400)
                continue;
            const QPointF at(s.centroid.x() * sx, s.centroid.y() * sy);
            const QString label = QString::number(i);
            QRectF box(at - QPointF(14, 9), QSizeF(28, 18));
            painter.setBrush(QColor(255, 255, 255, 200));
            painter.setPen(Qt::NoPen);
            painter.drawRoundedRect(box, 4, 4);
            painter.setPen(Qt::black);
            painter.drawText(box, Qt::AlignCenter, label);
        }
    }
}

} // namespace celform::views
