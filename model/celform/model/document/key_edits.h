// The key viewpoints' edits (doc.keys()): adding, re-aligning and linking keys, their
// deformations per frame (paper 1, sections 3.1.2 and 4.2) and the falloff brush that edits them.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/brush_stroke.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/gesture.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace celform::model {

struct MeshImport;

class KeyEdits : public DocumentFacade {
public:
    /// Adds a key as given, but for links to drawings the project does not hold. Throws
    /// EditRefused when its direction is within algo::ViewSphere::kDuplicateAngleDegrees of
    /// another key's.
    ObjectId addKey(KeyViewpoint key);
    /// A key seen from camera: its direction runs from the base centroid towards the eye
    /// (DESIGN.md); it starts as a copy of the base model unless a deformation is given (at
    /// frame). Throws EditRefused (no base model, eye at the centroid, duplicate direction).
    ObjectId createKey(const QString& name, const Camera& camera, std::vector<ObjectId> drawingIds = {},
        SparseOffsets deformation = {}, int frame = 0);
    /// "Create key from this drawing": the drawing's aligned camera, linked to the drawing.
    ObjectId createKeyFromDrawing(ObjectId drawingId);
    /// Re-aligns a key: new camera and direction. Throws EditRefused for a duplicate direction.
    void setKeyCamera(ObjectId id, const Camera& camera);
    /// Fit Camera to Drawing's result, one undo step: the drawing's aligned camera and, with a key
    /// (keyId not 0), the key's camera and direction with it, as aligning by hand and re-aligning
    /// the key would. Throws EditRefused as setKeyCamera.
    void applyFittedCamera(ObjectId drawingId, ObjectId keyId, const Camera& camera);
    /// Links a key to one drawing (0 unlinks every drawing).
    void linkKeyDrawing(ObjectId keyId, ObjectId drawingId);
    void removeKey(ObjectId id);
    void renameKey(ObjectId id, const QString& name);
    void setKeyEnabled(ObjectId id, bool enabled);
    /// Makes a name unique among keys by appending " 2", " 3", ...
    [[nodiscard]] QString uniqueKeyName(const QString& wanted) const;

    // --- deformations --------------------------------------------------------------------------
    /// Replaces a key's deformation at a frame (one undo step).
    void setKeyDeformation(ObjectId id, int frame, SparseOffsets deformation, const QString& undoText);
    /// Makes the difference of a mesh with the base model's vertex count and order from the base
    /// at frame (the animated base there, not its rest pose) the key's deformation at frame,
    /// replacing any stored there (one undo step; `key add --mesh`, `key set`, the editor's Import
    /// Key Deformation). The mesh is read before, outside the
    /// document (model::importMesh; the editor reads it as a job); meshPath names it in errors.
    /// Throws IoError (vertex count mismatch). Returns warnings.
    QStringList importKeyDeformation(ObjectId id, const MeshImport& imported, const QString& meshPath, int frame = 0);
    /// Adds displacements (#indices by 3, indices ascending) to a key's deformation at a frame.
    /// At a frame without a stored deformation the stored one starts from the interpolated one
    /// there (what the artist sees), so the edit adds to it. Steps given one gesture on the same
    /// key and frame are one undo step.
    void displaceKeyVertices(ObjectId id, int frame, const std::vector<std::uint32_t>& indices,
        const algo::Positions& displacements, const QString& undoText, GestureId gesture = {});

    /// Fit Shape to Drawing's result, one undo step: displacements added to the key's deformation
    /// at frame (as displaceKeyVertices).
    void applyFittedShape(
        ObjectId id, int frame, const std::vector<std::uint32_t>& indices, const algo::Positions& displacements);

    // --- the falloff brush (paper 1, section 3.1.2): the editor's tool and `celform brush` -----
    /// Sets the plane the brushes mirror across (ProjectData::mirrorPlane), one undo step.
    void setMirrorPlane(MirrorPlane plane);
    /// Starts a stroke on key `id` at `frame`: selects the vertices of the key's shape there
    /// within radius of vertex picked, and with a mirror plane the same neighbourhood around the
    /// picked vertex's mirror image (the base vertex nearest to its reflection, so approximate
    /// symmetry works; BrushStroke::twinMissing when there is none); the stroke holds its own
    /// gesture. The camera gives the image plane; the profile the falloff curve and strength.
    /// Throws EditRefused (no such key or vertex, no base model).
    [[nodiscard]] BrushStroke beginBrushStroke(ObjectId id, int frame, std::uint32_t picked, double radius,
        const Camera& camera, MirrorPlane mirror = MirrorPlane::Off, const algo::BrushProfile& profile = {});
    /// One step of the stroke: displaces the selection (see BrushStep) and stores it; all steps of
    /// a stroke are one undo step.
    void applyBrushStroke(BrushStroke& stroke, const BrushStep& step);
    /// Ends the stroke's gesture.
    void endBrushStroke(BrushStroke& stroke);

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
    void refuseDuplicateDirection(const Eigen::Vector3d& direction, ObjectId ignoredKey) const;
    /// The direction of key id seen from camera; throws EditRefused (eye at the centre, duplicate).
    [[nodiscard]] Eigen::Vector3d keyDirection(ObjectId id, const Camera& camera) const;
    void addKeyCameraCommands(
        ObjectId id, const Camera& camera, const Eigen::Vector3d& direction, QUndoCommand* parent) const;
};

} // namespace celform::model
