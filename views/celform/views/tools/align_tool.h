// Aligning the model to a reference drawing (paper 1, section 3.1.1): while the tool is on, the
// navigation moves a camera that is stored with the drawing once it settles (one undo step per
// gesture), and with point matching on, clicks place model and drawing points for the camera solve.
#pragma once

#include "celform/views/tools/viewport_tool.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <Eigen/Core>

#include <optional>
#include <vector>

class QWidget;

namespace celform::views {

class AlignTool : public QObject, public ViewportTool {
    Q_OBJECT
public:
    explicit AlignTool(Viewport* viewport);
    ~AlignTool() override;

    void activate() override;
    void deactivate() override;
    bool press(const ToolEvent& event) override;
    void cameraChanged() override;
    [[nodiscard]] Qt::CursorShape cursor() const override { return Qt::ArrowCursor; }

    void setMatching(bool on);
    [[nodiscard]] bool isMatching() const { return m_matching; }
    [[nodiscard]] const std::vector<Eigen::Vector3d>& modelPoints() const { return m_modelPoints; }
    [[nodiscard]] const std::vector<Eigen::Vector2d>& drawingPoints() const { return m_drawingPoints; }
    void clearPoints();
    void removeLastPoint();
    /// See Viewport::solveFromMatchedPoints.
    std::optional<double> solve(QString* error);
    /// The viewport changed size: the markers follow.
    void resized();

private:
    /// Stores the camera with the drawing now, if a commit is pending.
    void commitNow();
    void markersChanged();

    QTimer m_commit; ///< stores the aligned camera once navigation settles
    bool m_matching = false;
    std::vector<Eigen::Vector3d> m_modelPoints;
    std::vector<Eigen::Vector2d> m_drawingPoints;
    QWidget* m_markers; ///< transparent child of the viewport painting the matched points
};

} // namespace celform::views
