// A small timeline bound to the document's playhead: frames 0..N with key marks and a cursor at the
// current frame; clicking or dragging moves the playhead (DESIGN.md: one playhead that every view
// follows). The key marks are the owner's (the Highlights dock shows the selected layer's keys).
#pragma once

#include <QWidget>

#include <vector>

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class FrameTimeline : public QWidget {
    Q_OBJECT
public:
    explicit FrameTimeline(model::Document* document, QWidget* parent = nullptr);

    void setLastFrame(int last); ///< the last frame N shown
    [[nodiscard]] int lastFrame() const { return m_last; }
    void setKeys(std::vector<double> frames);
    /// Horizontal widget coordinate of a frame's centre (tests, hit testing).
    [[nodiscard]] int xForFrame(int frame) const;
    [[nodiscard]] QSize sizeHint() const override { return {240, 40}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {80, 36}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    [[nodiscard]] int frameAt(double x) const;
    void scrubTo(double x);

    model::Document* m_document;
    int m_last = 48;
    std::vector<double> m_keys;
};

} // namespace celform::views
