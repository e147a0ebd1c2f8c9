// Aligning the model to a reference drawing (paper 1, section 3.1.1): an explicit mode bound to the
// drawing it was started on, shown by a banner over the viewport. While it is on, the navigation
// moves a camera stored with that drawing (one undo step per navigation gesture); with point
// matching on, clicks place model and drawing points for the camera solve.
#pragma once

#include "celform/views/tools/viewport_tool.h"

#include "celform/model/data/camera.h"
#include "celform/model/data/object_id.h"
#include "celform/model/document/change_set.h"

#include <QString>

#include <Eigen/Core>

#include <optional>
#include <vector>

class QLabel;
class QWidget;

namespace celform::views {

class AlignTool : public ViewportTool {
    Q_OBJECT
public:
    explicit AlignTool(Viewport* viewport);
    ~AlignTool() override;

    void activate() override;
    void deactivate() override;
    bool press(const ToolEvent& event) override;
    void cameraChanged() override;
    void navigationStarted() override;
    void navigationEnded() override;
    /// The view is the drawing's camera while the mode is on.
    [[nodiscard]] bool holdsCamera() const override { return m_drawing != 0; }
    [[nodiscard]] Qt::CursorShape cursor() const override { return Qt::ArrowCursor; }
    /// The drawing being aligned (0 while the tool is off).
    [[nodiscard]] model::ObjectId drawing() const { return m_drawing; }

    // --- semi-automatic alignment: model points matched to drawing points ---------------------
    /// A click on the model adds a model point and Shift+click adds a drawing point; the i-th of
    /// each form a pair. The points outlive the tool until cleared (or another drawing shows).
    void setPointMatching(bool on);
    [[nodiscard]] bool isPointMatching() const { return m_matching; }
    [[nodiscard]] const std::vector<Eigen::Vector3d>& matchedModelPoints() const { return m_modelPoints; }
    /// Drawing pixels (x right, y down from the top-left corner).
    [[nodiscard]] const std::vector<Eigen::Vector2d>& matchedDrawingPoints() const { return m_drawingPoints; }
    void clearMatchedPoints();
    void removeLastMatchedPoint();
    /// Solves the camera from at least six pairs (DLT, then Levenberg-Marquardt) and stores it
    /// with the drawing as one undo step. Returns the RMS reprojection error in drawing pixels,
    /// or nothing with a message.
    std::optional<double> solveFromMatchedPoints(QString* error);
    /// The viewport changed size: the markers follow.
    void resized();

signals:
    void matchedPointsChanged();

private:
    /// Stores the viewport's camera with the drawing when it differs from the last one stored.
    void commit();
    /// Follows the drawing's camera when the document changes it (undo, redo).
    void documentChanged(const model::ChangeSet& change);
    void markersChanged();
    void placeBanner();

    model::ObjectId m_drawing = 0; ///< bound at activation: another drawing ends the mode
    model::Camera m_stored; ///< the camera last stored (or found) with the drawing
    bool m_matching = false;
    bool m_following = false; ///< the view takes the drawing's camera from the document
    std::vector<Eigen::Vector3d> m_modelPoints;
    std::vector<Eigen::Vector2d> m_drawingPoints;
    QWidget* m_markers; ///< transparent child of the viewport painting the matched points
    QLabel* m_banner; ///< says the mode is on, what it edits, and the way out
};

} // namespace celform::views
