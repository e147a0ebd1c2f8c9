// The Timeline dock's ruler: the scene's frame range with ticks, the key marks of every
// kind (key deformations, highlight keys, camera keys, light keys) in their own shapes and colours, and the
// playhead. Clicking or dragging scrubs the document's playhead within the range.
#pragma once

#include <QColor>
#include <QString>
#include <QWidget>

#include <vector>

namespace celform::model {
class Document;
struct ProjectData;
} // namespace celform::model

namespace celform::views {

/// What a mark on the ruler stands for.
enum class TimelineMarkKind { Deformation, Highlight, Camera, Light };

struct TimelineMark {
    int frame = 0;
    TimelineMarkKind kind = TimelineMarkKind::Deformation;
    bool operator==(const TimelineMark& o) const { return frame == o.frame && kind == o.kind; }
    bool operator<(const TimelineMark& o) const { return frame != o.frame ? frame < o.frame : int(kind) < int(o.kind); }
};

/// Every keyed frame of the project: each key viewpoint's deformation frames, each highlight
/// layer's key frames (rounded to whole frames), the camera path's keys and the light track's keys. Sorted, no repeats.
[[nodiscard]] std::vector<TimelineMark> timelineMarks(const model::ProjectData& data);
/// The distinct frames of marks, ascending.
[[nodiscard]] std::vector<int> markFrames(const std::vector<TimelineMark>& marks);

/// The colour and name a kind of mark is drawn and explained with (legend and tooltips).
[[nodiscard]] QColor markColor(TimelineMarkKind kind);
[[nodiscard]] QString markName(TimelineMarkKind kind);

class TimelineRuler : public QWidget {
    Q_OBJECT
public:
    explicit TimelineRuler(model::Document* document, QWidget* parent = nullptr);

    /// The frames shown, first to last (inclusive).
    void setRange(int first, int last);
    [[nodiscard]] int firstFrame() const { return m_first; }
    [[nodiscard]] int lastFrame() const { return m_last; }
    void setMarks(std::vector<TimelineMark> marks);
    [[nodiscard]] const std::vector<TimelineMark>& marks() const { return m_marks; }
    /// Horizontal widget coordinate of a frame's centre (tests, hit testing).
    [[nodiscard]] double xForFrame(int frame) const;
    /// The vertical centre of a kind's row of marks.
    [[nodiscard]] double yForKind(TimelineMarkKind kind) const;
    [[nodiscard]] QSize sizeHint() const override { return {480, 70}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {120, 70}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override;

private:
    [[nodiscard]] int frameAt(double x) const;
    void scrubTo(double x);

    model::Document* m_document;
    int m_first = 0;
    int m_last = 47;
    std::vector<TimelineMark> m_marks;
};

} // namespace celform::views
