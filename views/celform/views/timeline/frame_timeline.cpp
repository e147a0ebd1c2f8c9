// Painting and scrubbing of the playhead timeline.
#include "celform/views/timeline/frame_timeline.h"

#include "celform/model/document/document.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

constexpr double kMargin = 8.0;

} // namespace

FrameTimeline::FrameTimeline(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    setToolTip(tr("Frames of the animation: diamonds are the selected layer's keys; click or drag to move the "
                  "current frame"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setFixedHeight(40);
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        if (change.reset || change.has(model::Part::Playhead))
            update();
    });
}

void FrameTimeline::setLastFrame(int last)
{
    m_last = std::max(1, last);
    update();
}

void FrameTimeline::setKeys(std::vector<double> frames)
{
    if (frames == m_keys)
        return;
    m_keys = std::move(frames);
    update();
}

int FrameTimeline::xForFrame(int frame) const
{
    return int(std::lround(kMargin + (width() - 2.0 * kMargin) * double(frame) / double(m_last)));
}

int FrameTimeline::frameAt(double x) const
{
    const double t = (x - kMargin) / std::max(1.0, width() - 2.0 * kMargin);
    return std::clamp(int(std::lround(t * m_last)), 0, m_last);
}

void FrameTimeline::scrubTo(double x)
{
    const int frame = frameAt(x);
    if (frame != m_document->currentFrame())
        m_document->setCurrentFrame(frame);
}

void FrameTimeline::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Base));
    const int axisY = height() - 12;
    p.setPen(pal.color(QPalette::Mid));
    p.drawLine(xForFrame(0), axisY, xForFrame(m_last), axisY);
    // Ticks: every frame when there is room, else every 6th; labels every 12th (half a second).
    const double perFrame = (width() - 2.0 * kMargin) / double(m_last);
    const int tickStep = perFrame >= 4.0 ? 1 : 6;
    QFont font = p.font();
    font.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.75));
    p.setFont(font);
    for (int f = 0; f <= m_last; f += tickStep) {
        const int x = xForFrame(f);
        const bool major = f % 12 == 0;
        p.setPen(pal.color(major ? QPalette::Text : QPalette::Mid));
        p.drawLine(x, axisY, x, axisY - (major ? 6 : 3));
        if (major && perFrame * 12 >= 18)
            p.drawText(QRect(x - 15, axisY + 1, 30, 11), Qt::AlignCenter, QString::number(f));
    }
    // Key marks.
    p.setPen(QPen(pal.color(QPalette::Text), 1));
    for (double k : m_keys) {
        const double x = kMargin + (width() - 2.0 * kMargin) * k / double(m_last);
        QPainterPath diamond;
        diamond.moveTo(x, 6);
        diamond.lineTo(x + 5, 12);
        diamond.lineTo(x, 18);
        diamond.lineTo(x - 5, 12);
        diamond.closeSubpath();
        p.fillPath(diamond, QColor(240, 190, 40));
        p.drawPath(diamond);
    }
    // The playhead.
    const int cx = xForFrame(m_document->currentFrame());
    p.setPen(QPen(QColor(220, 50, 40), 2));
    p.drawLine(cx, 2, cx, axisY);
    p.fillRect(QRect(cx - 4, 0, 9, 4), QColor(220, 50, 40));
}

void FrameTimeline::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        scrubTo(event->position().x());
}

void FrameTimeline::mouseMoveEvent(QMouseEvent* event)
{
    if (event->buttons() & Qt::LeftButton)
        scrubTo(event->position().x());
}

} // namespace celform::views
