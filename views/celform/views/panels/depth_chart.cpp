// The Depth tab's chart over the shot (depth_chart.h).
#include "celform/views/panels/depth_chart.h"

#include "celform/model/document/document.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

constexpr double kMargin = 8.0;
constexpr double kTop = 16.0; ///< room for the legend

} // namespace

DepthChart::DepthChart(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    setObjectName(QStringLiteral("depthChart"));
    setToolTip(tr("Depth error (MSE) and the share of segments inside the window over the shot; click to go to "
                  "a frame"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setFixedHeight(sizeHint().height());
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        if (change.reset || change.has(model::Part::Playhead))
            update();
    });
}

void DepthChart::setSamples(std::vector<ShotDepthSample> samples)
{
    m_samples = std::move(samples);
    m_stale = false;
    update();
}

void DepthChart::setStale(bool stale)
{
    if (stale == m_stale)
        return;
    m_stale = stale;
    update();
}

void DepthChart::setRange(int first, int last)
{
    m_first = first;
    m_last = std::max(first, last);
    update();
}

double DepthChart::xForFrame(int frame) const
{
    const double span = std::max(1, m_last - m_first);
    return kMargin + (width() - 2.0 * kMargin) * double(frame - m_first) / span;
}

int DepthChart::frameAt(double x) const
{
    const double span = std::max(1, m_last - m_first);
    const double t = (x - kMargin) / std::max(1e-9, width() - 2.0 * kMargin);
    return std::clamp(m_first + int(std::lround(t * span)), m_first, m_last);
}

void DepthChart::scrubTo(double x)
{
    const int frame = frameAt(x);
    if (frame != m_document->currentFrame())
        m_document->setCurrentFrame(frame);
}

void DepthChart::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        scrubTo(event->position().x());
}

void DepthChart::mouseMoveEvent(QMouseEvent* event)
{
    if (event->buttons() & Qt::LeftButton)
        scrubTo(event->position().x());
}

void DepthChart::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Base));
    const QRectF plot(kMargin, kTop, width() - 2.0 * kMargin, height() - kTop - kMargin);
    p.setPen(pal.color(QPalette::Mid));
    p.drawRect(plot);

    const QColor mseColor = m_stale ? pal.color(QPalette::Mid) : QColor(220, 70, 60);
    const QColor windowColor = m_stale ? pal.color(QPalette::Mid) : QColor(60, 140, 220);
    QFont font = p.font();
    font.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.8));
    p.setFont(font);
    if (m_samples.empty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(plot, Qt::AlignCenter, tr("Chart Shot analyses every frame of the scene"));
    } else {
        double largest = 0.0;
        for (const ShotDepthSample& s : m_samples)
            largest = std::max(largest, s.mse);
        largest = largest > 0.0 ? largest : 1.0;
        QPainterPath mse, window;
        for (std::size_t i = 0; i < m_samples.size(); ++i) {
            const double x = xForFrame(m_samples[i].frame);
            const QPointF a(x, plot.bottom() - plot.height() * m_samples[i].mse / largest);
            const QPointF b(x, plot.bottom() - plot.height() * m_samples[i].inWindow);
            if (i == 0) {
                mse.moveTo(a);
                window.moveTo(b);
            } else {
                mse.lineTo(a);
                window.lineTo(b);
            }
        }
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(windowColor, 1.5));
        p.drawPath(window);
        p.setPen(QPen(mseColor, 2.0));
        p.drawPath(mse);
        p.setPen(mseColor);
        p.drawText(QRectF(kMargin, 0.0, plot.width() / 2.0, kTop), Qt::AlignLeft | Qt::AlignVCenter,
            tr("MSE (max %1)").arg(largest, 0, 'g', 3));
        p.setPen(windowColor);
        p.drawText(QRectF(kMargin + plot.width() / 2.0, 0.0, plot.width() / 2.0, kTop),
            Qt::AlignRight | Qt::AlignVCenter, tr("inside the window (0-100 %)"));
    }
    // The current frame.
    const int current = m_document->currentFrame();
    if (current >= m_first && current <= m_last) {
        const double x = xForFrame(current);
        p.setPen(QPen(pal.color(QPalette::Highlight), 2.0));
        p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    }
}

} // namespace celform::views
