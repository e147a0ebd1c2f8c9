// The Depth dock (paper 3, chapter 4): where toon shading hides depth. Overlays of the segments,
// the Gaussian curvature and the depth error over the viewport, the segments' bright/dark ratios
// against the window, and the depth error's mean squared error as one live number. The analysis
// runs off the GUI thread (DepthAnalysisRunner) while the dock is shown or an overlay is on.
#pragma once

#include "celform/algorithms/light_optimisation.h"
#include "celform/views/overlays/depth_overlay.h"

#include <QWidget>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTableWidget;
class QToolButton;
class QAction;

namespace celform::model {
class Document;
}

namespace celform::views {

class DepthAnalysisRunner;
class DepthChart;
class ShotDepthRunner;
class Viewport;

class DepthPanel : public QWidget {
    Q_OBJECT
public:
    DepthPanel(model::Document* document, Viewport* viewport, QWidget* parent = nullptr);

    [[nodiscard]] DepthAnalysisRunner* runner() const { return m_runner; }
    [[nodiscard]] DepthOverlay* overlay() const { return m_overlay; }
    /// Shows one overlay (None hides it) and ticks its button.
    void setOverlayKind(DepthOverlay::Kind kind);
    [[nodiscard]] QTableWidget* segmentTable() const { return m_table; }
    [[nodiscard]] QLabel* errorLabel() const { return m_mse; }
    /// The chart of the depth error over the shot, and what fills it.
    [[nodiscard]] DepthChart* chart() const { return m_chart; }
    [[nodiscard]] ShotDepthRunner* shotRunner() const { return m_shotRunner; }
    /// Analyses the scene's frame range for the chart (the Chart Shot button).
    void chartShot();
    /// The button of the Optimise Light for Stereo action (the window owns the action).
    void setOptimiseLightAction(QAction* action);
    /// The method and weight chosen in the panel (the window, the scale and the centre come from
    /// the analysis settings and the shape: model::optimiseLight fills them in).
    [[nodiscard]] algo::LightOptimisationSettings lightSettings() const;

    /// Where the offset brush and the automatic offsets write, as the offset brush names it (the
    /// editor window keeps it up to date: panels do not know tools).
    void showOffsetTarget(const QString& target);

signals:
    void overlayKindChanged(celform::views::DepthOverlay::Kind kind);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void updateActivity();
    void applySettings();
    void showResult();
    void showBusy(bool busy);

    model::Document* m_document;
    DepthAnalysisRunner* m_runner;
    DepthOverlay* m_overlay;
    bool m_shown = false;
    QButtonGroup* m_kinds;
    QSlider* m_opacity;
    QComboBox* m_window;
    QDoubleSpinBox* m_low;
    QDoubleSpinBox* m_high;
    QDoubleSpinBox* m_depthThreshold;
    QSpinBox* m_minPixels;
    QLabel* m_mse;
    QLabel* m_details;
    QLabel* m_status;
    QLabel* m_offsetTarget; ///< the shading-offset layer edits go into
    QTableWidget* m_table;
    QComboBox* m_method;
    QComboBox* m_weight;
    QToolButton* m_optimise;
    DepthChart* m_chart;
    ShotDepthRunner* m_shotRunner;
    QToolButton* m_chartButton;
    QToolButton* m_chartCancel;
    QLabel* m_chartStatus;
};

} // namespace celform::views
