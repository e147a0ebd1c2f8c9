// The document's animation edits (doc.animation(); paper 1, section 4 and figures 10-12): the
// scene's time, the camera path and turntable, and the animated base model. Each is one undo step.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/gesture.h"

#include <QString>

#include <memory>

namespace celform::model {

struct AnimatedImport;

class AnimationEdits : public DocumentFacade {
public:
    /// Frames per second and the frame range. Throws EditRefused (sceneTimeProblem).
    void setSceneTime(const SceneTime& time, GestureId gesture = {});
    /// Replaces the camera path (one undo step named undoText). Throws EditRefused
    /// (cameraPathProblem).
    void setCameraPath(const CameraPath& path, const QString& undoText);
    /// Keys the render camera at a frame (replacing a key there).
    void setCameraKey(int frame, const Camera& camera);
    /// Removes the camera key at a frame (nothing when there is none).
    void removeCameraKey(int frame);
    /// Clears the camera path (the render camera applies again).
    void clearCameraPath();
    /// A turntable path around the base model's centre at the start frame, at the distance that
    /// frames the whole model for an image of the given aspect ratio, through the render camera's
    /// lens; the frame range becomes the revolution's frames. One undo step. Throws EditRefused.
    void makeTurntable(const Turntable& turntable, double aspect = 16.0 / 9.0);
    /// Replaces the base model by an animated one (one undo step): the rest mesh, its animation
    /// (null: a still base) and the scene's frames per second and range taken from it. Throws
    /// IoError naming sourceName when the keys' deformations do not fit, EditRefused for an
    /// inconsistent animation.
    void setAnimatedBase(std::shared_ptr<const algo::TriMesh> mesh,
        std::shared_ptr<const algo::BaseAnimation> animation, double fps, const QString& sourceName);
    /// The same from what readAnimatedBase read (animation_io.h); an empty animation is a still base.
    void setAnimatedBase(AnimatedImport&& imported, const QString& sourceName);
    /// Imports an animated base (glTF/GLB with skins or morph targets, or an OBJ/PLY sequence)
    /// sampled at fps in place of the base model (setAnimatedBase). Throws IoError.
    void importAnimatedBase(const QString& path, double fps = 24.0);

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
};

} // namespace celform::model
