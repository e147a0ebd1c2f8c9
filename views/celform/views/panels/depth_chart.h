// The Depth tab's chart over the shot (issue 26): the depth error (MSE, thesis 4.4) and the share
// of segments inside the window per analysed frame, with the current frame marked. Clicking or
// dragging moves the playhead to the frame under the cursor.
#pragma once

#include "celform/views/overlays/shot_depth_runner.h"

#include <QWidget>

#include <vector>

namespace celform::model {
class Document;
}

namespace celform::views {

class DepthChart : public QWidget {
    Q_OBJECT
public:
    explicit DepthChart(model::Document* document, QWidget* parent = nullptr);

    void setSamples(std::vector<ShotDepthSample> samples);
    [[nodiscard]] const std::vector<ShotDepthSample>& samples() const { return m_samples; }
    /// Greys the curves: they describe the document before its last change.
    void setStale(bool stale);
    /// The frames along the horizontal axis (the scene's range).
    void setRange(int first, int last);
    /// Horizontal widget coordinate of a frame (tests, hit testing).
    [[nodiscard]] double xForFrame(int frame) const;
    [[nodiscard]] int frameAt(double x) const;
    [[nodiscard]] QSize sizeHint() const override { return {300, 120}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {120, 90}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    void scrubTo(double x);

    model::Document* m_document;
    std::vector<ShotDepthSample> m_samples;
    int m_first = 0;
    int m_last = 47;
    bool m_stale = false;
};

} // namespace celform::views
