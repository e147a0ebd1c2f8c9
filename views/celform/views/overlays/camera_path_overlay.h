// The Observer's picture of the shot (paper 1, figures 10-12): the camera path as a polyline
// through its keys' eyes and the main camera as a small pyramid at its eye pointing at its
// target, drawn in the Observer viewport's 3D scene beside the view-dependent model it shows.
#pragma once

#include "celform/model/data/camera.h"

#include <QObject>
#include <QPointer>

#include <memory>

class vtkPolyData;

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class Viewport;

class CameraPathOverlay : public QObject {
    Q_OBJECT
public:
    /// Draws into observer's scene the path of observer's document and driver's camera. Owned by
    /// observer (its child).
    CameraPathOverlay(Viewport* observer, Viewport* driver);
    ~CameraPathOverlay() override;

    void setVisible(bool on);
    [[nodiscard]] bool isVisible() const { return m_visible; }
    /// The path polyline's points (one per camera key) and the glyph's apex (the camera eye).
    [[nodiscard]] vtkPolyData* pathPolyData() const;
    [[nodiscard]] vtkPolyData* cameraGlyph() const;
    /// The camera the glyph shows now.
    [[nodiscard]] const model::Camera& glyphCamera() const { return m_camera; }

private:
    void documentChanged(const model::ChangeSet& change);
    void rebuildPath();
    void updateGlyph();
    /// The base model's bounding-box diagonal: the glyph's scale.
    void measureModel();

    QPointer<Viewport> m_observer;
    QPointer<Viewport> m_driver;
    model::Document* m_document;
    struct Props; ///< the VTK data and actors (VTK stays out of this header)
    std::unique_ptr<Props> m_props;
    model::Camera m_camera;
    double m_modelSize = 1.0;
    bool m_visible = true;
};

} // namespace celform::views
