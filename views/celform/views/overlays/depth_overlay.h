// The depth analysis drawn over a viewport (paper 3, figures 4.5, 4.17 and 5.1-5.7): the segments,
// the Gaussian curvature or the depth error of the newest analysis, with a legend. A child widget
// that covers the viewport and lets every mouse event through.
#pragma once

#include <QPointer>
#include <QWidget>

namespace celform::views {

class DepthAnalysisRunner;
class Viewport;

class DepthOverlay : public QWidget {
    Q_OBJECT
public:
    enum class Kind { None, Segments, Curvature, DepthError };

    DepthOverlay(Viewport* viewport, DepthAnalysisRunner* runner);

    /// None hides the overlay (the analysis may still run for the panel's figures).
    void setKind(Kind kind);
    [[nodiscard]] Kind kind() const { return m_kind; }
    /// 0..1, how much of the analysis covers the model (0.8 by default).
    void setOpacity(double opacity);
    [[nodiscard]] double opacity() const { return m_opacity; }

protected:
    void paintEvent(QPaintEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void drawLegend(QPainter& painter, const QString& positive, const QString& negative, const QColor& positiveColor,
        const QColor& negativeColor, float scale);

    QPointer<Viewport> m_viewport;
    DepthAnalysisRunner* m_runner;
    Kind m_kind = Kind::None;
    double m_opacity = 0.8;
};

} // namespace celform::views
