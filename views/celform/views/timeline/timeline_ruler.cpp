// The Timeline dock's ruler (timeline_ruler.h).
#include "celform/views/timeline/timeline_ruler.h"

#include "celform/model/document/document.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

constexpr double kMargin = 10.0;
constexpr double kLabelHeight = 14.0;
constexpr double kRowHeight = 12.0;
constexpr double kMarkRadius = 4.5;
/// Frame steps between ticks and between labels, smallest first.
constexpr int kSteps[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000, 100000, 1000000};

/// The kinds in the order of their rows, top to bottom.
constexpr TimelineMarkKind kKinds[]
    = {TimelineMarkKind::Camera, TimelineMarkKind::Light, TimelineMarkKind::Deformation, TimelineMarkKind::Highlight};

/// A mark's outline: camera keys are triangles pointing down (a lens), key deformations diamonds
/// (the usual key mark), highlight keys circles (a highlight spot), light keys squares.
QPainterPath markShape(TimelineMarkKind kind, QPointF c, double r)
{
    QPainterPath path;
    switch (kind) {
    case TimelineMarkKind::Camera:
        path.moveTo(c.x() - r, c.y() - r * 0.8);
        path.lineTo(c.x() + r, c.y() - r * 0.8);
        path.lineTo(c.x(), c.y() + r);
        path.closeSubpath();
        break;
    case TimelineMarkKind::Deformation:
        path.moveTo(c.x(), c.y() - r);
        path.lineTo(c.x() + r, c.y());
        path.lineTo(c.x(), c.y() + r);
        path.lineTo(c.x() - r, c.y());
        path.closeSubpath();
        break;
    case TimelineMarkKind::Highlight:
        path.addEllipse(c, r * 0.85, r * 0.85);
        break;
    case TimelineMarkKind::Light:
        path.addRect(QRectF(c.x() - r * 0.75, c.y() - r * 0.75, r * 1.5, r * 1.5));
        break;
    }
    return path;
}

} // namespace

std::vector<TimelineMark> timelineMarks(const model::ProjectData& data)
{
    std::vector<TimelineMark> marks;
    for (const model::KeyViewpoint& key : data.keys)
        for (const auto& [frame, offsets] : key.offsetsByFrame)
            marks.push_back({frame, TimelineMarkKind::Deformation});
    for (const model::HighlightTrack& track : data.look.highlights)
        for (const algo::HighlightKey& key : track.keys)
            marks.push_back({int(std::lround(key.frame)), TimelineMarkKind::Highlight});
    for (const model::CameraKey& key : data.look.cameraPath.keys)
        marks.push_back({key.frame, TimelineMarkKind::Camera});
    for (const model::LightKey& key : data.look.lightTrack.keys)
        marks.push_back({key.frame, TimelineMarkKind::Light});
    std::sort(marks.begin(), marks.end());
    marks.erase(std::unique(marks.begin(), marks.end()), marks.end());
    return marks;
}

std::vector<int> markFrames(const std::vector<TimelineMark>& marks)
{
    std::vector<int> frames;
    frames.reserve(marks.size());
    for (const TimelineMark& mark : marks)
        frames.push_back(mark.frame);
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

QColor markColor(TimelineMarkKind kind)
{
    switch (kind) {
    case TimelineMarkKind::Camera:
        return QColor(70, 150, 235);
    case TimelineMarkKind::Deformation:
        return QColor(235, 140, 40);
    case TimelineMarkKind::Highlight:
        return QColor(225, 200, 40);
    case TimelineMarkKind::Light:
        return QColor(170, 110, 230);
    }
    return Qt::gray;
}

QString markName(TimelineMarkKind kind)
{
    switch (kind) {
    case TimelineMarkKind::Camera:
        return TimelineRuler::tr("camera key");
    case TimelineMarkKind::Deformation:
        return TimelineRuler::tr("key deformation");
    case TimelineMarkKind::Highlight:
        return TimelineRuler::tr("highlight key");
    case TimelineMarkKind::Light:
        return TimelineRuler::tr("light key");
    }
    return {};
}

TimelineRuler::TimelineRuler(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    setObjectName(QStringLiteral("timelineRuler"));
    // paintEvent fills every pixel: the playhead's repaint on each played frame need not repaint
    // the panel, the dock and the window beneath.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setFixedHeight(sizeHint().height());
    setMouseTracking(false);
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        if (change.reset || change.has(model::Part::Playhead))
            update();
    });
}

void TimelineRuler::setRange(int first, int last)
{
    if (first == m_first && std::max(first, last) == m_last)
        return;
    m_first = first;
    m_last = std::max(first, last);
    update();
}

void TimelineRuler::setMarks(std::vector<TimelineMark> marks)
{
    if (marks == m_marks)
        return;
    m_marks = std::move(marks);
    update();
}

double TimelineRuler::xForFrame(int frame) const
{
    // Frames are cells: a range of one frame still has room for its mark.
    const double cells = double(m_last - m_first + 1);
    const double cell = (width() - 2.0 * kMargin) / cells;
    return kMargin + cell * (double(frame - m_first) + 0.5);
}

double TimelineRuler::yForKind(TimelineMarkKind kind) const
{
    const auto row = std::find(std::begin(kKinds), std::end(kKinds), kind) - std::begin(kKinds);
    return kLabelHeight + kRowHeight * (double(row) + 0.5);
}

int TimelineRuler::frameAt(double x) const
{
    const double cells = double(m_last - m_first + 1);
    const double cell = std::max(1e-9, (width() - 2.0 * kMargin) / cells);
    const int frame = m_first + int(std::floor((x - kMargin) / cell));
    return std::clamp(frame, m_first, m_last);
}

void TimelineRuler::scrubTo(double x)
{
    const int frame = frameAt(x);
    if (frame != m_document->currentFrame())
        m_document->setCurrentFrame(frame);
}

void TimelineRuler::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        scrubTo(event->position().x());
}

void TimelineRuler::mouseMoveEvent(QMouseEvent* event)
{
    if (event->buttons() & Qt::LeftButton)
        scrubTo(event->position().x());
}

bool TimelineRuler::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        // The frame under the cursor and what is keyed there, then the legend.
        const auto* help = static_cast<QHelpEvent*>(event);
        const int frame = frameAt(help->pos().x());
        QStringList keyed;
        for (const TimelineMark& mark : m_marks)
            if (mark.frame == frame)
                keyed << markName(mark.kind);
        QString text = keyed.isEmpty() ? tr("Frame %1").arg(frame)
                                       : tr("Frame %1: %2").arg(frame).arg(keyed.join(QStringLiteral(", ")));
        text += QStringLiteral("\n") + tr("▼ camera keys · ■ light keys · ◆ key deformations · ● highlight keys");
        text += QStringLiteral("\n") + tr("Click or drag to move the current frame");
        QToolTip::showText(help->globalPos(), text, this);
        return true;
    }
    return QWidget::event(event);
}

void TimelineRuler::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Base));
    const double bottom = height() - 4.0;
    const double left = xForFrame(m_first), right = xForFrame(m_last);
    // Alternate shading of the mark rows, so each kind reads as its own track.
    for (int row = 0; row < int(std::size(kKinds)); ++row)
        if (row % 2 == 1)
            p.fillRect(QRectF(kMargin, kLabelHeight + row * kRowHeight, width() - 2.0 * kMargin, kRowHeight),
                pal.color(QPalette::AlternateBase));
    p.setPen(pal.color(QPalette::Mid));
    p.drawLine(QPointF(left, bottom), QPointF(right, bottom));

    // Ticks on every frame when there is room, else every 5th or 10th...; labels where they fit.
    const double cell = (width() - 2.0 * kMargin) / double(m_last - m_first + 1);
    QFont font = p.font();
    font.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.75));
    p.setFont(font);
    const QFontMetrics metrics(font);
    const int labelWidth = metrics.horizontalAdvance(QString::number(m_last)) + 8;
    auto stepFor = [cell](double room) {
        for (int step : kSteps)
            if (cell * step >= room)
                return step;
        return kSteps[std::size(kSteps) - 1];
    };
    const int tickStep = stepFor(5.0);
    const int labelStep = std::max(tickStep, stepFor(labelWidth));
    const int start = int(std::ceil(double(m_first) / tickStep)) * tickStep;
    for (int f = start; f <= m_last; f += tickStep) {
        const double x = xForFrame(f);
        const bool labelled = f % labelStep == 0;
        p.setPen(pal.color(QPalette::Mid));
        p.drawLine(QPointF(x, bottom), QPointF(x, bottom - (labelled ? 6.0 : 3.0)));
        if (labelled) {
            p.setPen(pal.color(QPalette::Text));
            p.drawText(
                QRectF(x - labelWidth / 2.0, 0.0, labelWidth, kLabelHeight), Qt::AlignCenter, QString::number(f));
        }
    }

    for (const TimelineMark& mark : m_marks) {
        if (mark.frame < m_first || mark.frame > m_last)
            continue;
        const QColor color = markColor(mark.kind);
        p.setPen(QPen(color.darker(160), 1.0));
        p.setBrush(color);
        p.drawPath(markShape(mark.kind, QPointF(xForFrame(mark.frame), yForKind(mark.kind)), kMarkRadius));
    }

    // The playhead: a line across the rows and its frame number boxed over the labels.
    const int current = m_document->currentFrame();
    if (current >= m_first && current <= m_last) {
        const double x = xForFrame(current);
        const QColor accent = pal.color(QPalette::Highlight);
        p.setPen(QPen(accent, 2.0));
        p.drawLine(QPointF(x, kLabelHeight), QPointF(x, bottom));
        const QString text = QString::number(current);
        const double w = metrics.horizontalAdvance(text) + 8.0;
        const QRectF box(std::clamp(x - w / 2.0, 0.0, width() - w), 0.0, w, kLabelHeight);
        p.setPen(Qt::NoPen);
        p.setBrush(accent);
        p.drawRoundedRect(box, 3.0, 3.0);
        p.setPen(pal.color(QPalette::HighlightedText));
        p.drawText(box, Qt::AlignCenter, text);
    }
}

} // namespace celform::views
