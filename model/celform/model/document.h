// The Celform document: the project data, the undo stack, and the edit methods that views and
// the command line call. Every edit is a QUndoCommand; nothing changes the data behind its back.
#pragma once

#include "celform/model/project_data.h"
#include "celform/model/view_blend.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <memory>

namespace celform::model {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    [[nodiscard]] const ProjectData& data() const { return m_data; }
    [[nodiscard]] QUndoStack* undoStack() const { return m_undo; }
    [[nodiscard]] bool hasMesh() const { return m_data.baseMesh != nullptr; }

    // --- files -----------------------------------------------------------------------------
    /// The project's file, empty until saved or opened.
    [[nodiscard]] QString filePath() const { return m_filePath; }
    [[nodiscard]] bool isModified() const { return !m_undo->isClean(); }
    /// Replaces the document by a project file. Throws IoError and leaves the document untouched
    /// when the file cannot be read.
    void open(const QString& path);
    /// Saves to path (atomic, backup kept) and marks the document clean. Throws IoError.
    void saveAs(const QString& path);
    /// Writes a copy (autosave, recovery) without touching the file path or clean state.
    void saveCopy(const QString& path) const;
    /// Starts a new project on a mesh file. Throws IoError and leaves the document untouched.
    /// Returns the import warnings.
    QStringList newFromMesh(const QString& meshPath);
    /// Replaces everything, clears undo history; for open and tests.
    void reset(ProjectData data, const QString& filePath = {});

    // --- edits (each pushes one undo command) --------------------------------------------------
    /// Replaces the base model. Keys whose offsets do not fit the new vertex count are refused:
    /// throws IoError naming meshName in that case, and the document is unchanged.
    void setBaseMesh(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName);
    /// Imports a mesh file as the base model; returns the import warnings. Throws IoError.
    QStringList importBaseMesh(const QString& path);

    ObjectId addDrawing(Drawing drawing);
    /// Imports an image file as a drawing; returns its id. Throws IoError.
    ObjectId importDrawing(const QString& path);
    void removeDrawing(ObjectId id);
    void renameDrawing(ObjectId id, const QString& name);
    /// Mergeable: a slider drag is one undo step.
    void setDrawingOpacity(ObjectId id, double opacity);
    void setDrawingCamera(ObjectId id, const Camera& camera);

    /// Adds a key as given. Throws EditRefused when its direction is within
    /// algo::ViewSphere::kDuplicateAngleDegrees of another key's.
    ObjectId addKey(KeyViewpoint key);
    /// A key seen from camera: its direction runs from the base centroid towards the eye
    /// (DESIGN.md); it starts as a copy of the base model unless offsets are given (at frame).
    /// Throws EditRefused (no base model, eye at the centroid, duplicate direction).
    ObjectId createKey(const QString& name, const Camera& camera, std::vector<ObjectId> drawingIds = {},
        SparseOffsets offsets = {}, int frame = 0);
    /// "Create key from this drawing": the drawing's aligned camera, linked to the drawing.
    ObjectId createKeyFromDrawing(ObjectId drawingId);
    /// Re-aligns a key: new camera and direction. Throws EditRefused for a duplicate direction.
    void setKeyCamera(ObjectId id, const Camera& camera);
    /// Links a key to one drawing (0 unlinks every drawing).
    void linkKeyDrawing(ObjectId keyId, ObjectId drawingId);
    /// Replaces a key's offsets at a frame (one undo step).
    void setKeyOffsets(ObjectId id, int frame, SparseOffsets offsets, const QString& undoText);
    /// Reads a mesh with the base model's vertex count and order and makes its difference from
    /// the base the key's deformation at frame. Throws IoError (unreadable, vertex count
    /// mismatch). Returns import warnings.
    QStringList importKeyDeformation(ObjectId id, const QString& meshPath, int frame = 0);
    /// Adds displacements (#indices by 3) to a key's vertices at a frame: one brush step. Steps
    /// with the same non-zero strokeId merge into one undo step (one drag = one undo).
    void displaceKeyVertices(ObjectId id, int frame, const std::vector<std::uint32_t>& indices,
        const algo::Positions& displacements, int strokeId, const QString& undoText);
    /// A fresh id for displaceKeyVertices strokes.
    int newStrokeId() { return ++m_lastStrokeId; }

    /// The view-dependent blend of the current keys, up to date.
    BlendEvaluator& blender();
    void removeKey(ObjectId id);
    void renameKey(ObjectId id, const QString& name);
    void setKeyEnabled(ObjectId id, bool enabled);

    // --- face sets: the highlight patches (paper 2, "Highlight operations": each operation acts on
    // one patch) ---------------------------------------------------------------------------
    /// Creates or replaces a face set; faces are sorted and repeats dropped. Steps with the same
    /// non-zero strokeId merge into one undo step (one paint drag = one undo). Throws
    /// EditRefused without a base model, for an empty name or a face out of range.
    void setFaceSet(const QString& name, std::vector<std::int32_t> faces, const QString& undoText, int strokeId = 0);
    /// Removes a face set; highlight layers on it go back to all faces in the same undo step.
    void removeFaceSet(const QString& name);
    /// Renames a face set and the highlight layers' references to it (one undo step). Throws
    /// EditRefused for an empty name or one already taken.
    void renameFaceSet(const QString& name, const QString& newName);
    [[nodiscard]] QString uniqueFaceSetName(const QString& wanted) const;

    void setBlendSettings(const BlendSettings& settings);
    void setLook(const Look& look);

    /// Makes a name unique among drawings or keys by appending " 2", " 3", ...
    [[nodiscard]] QString uniqueDrawingName(const QString& wanted) const;
    [[nodiscard]] QString uniqueKeyName(const QString& wanted) const;

    /// Low-level access for undo commands only.
    ProjectData& mutableData() { return m_data; }

    enum class Part { Mesh, Drawings, Keys, Blend, Look, FaceSets };
    /// Called by commands after they changed a part.
    void notifyChanged(Part part);

signals:
    void meshChanged();
    void drawingsChanged();
    void keysChanged();
    void blendChanged();
    void lookChanged();
    /// Face sets were added, changed, renamed or removed.
    void faceSetsChanged();
    /// The whole document was replaced (open, new).
    void documentReset();
    void filePathChanged(const QString& path);

private:
    void refuseDuplicateDirection(const Eigen::Vector3d& direction, ObjectId ignoredKey) const;

    ProjectData m_data;
    QUndoStack* m_undo;
    BlendEvaluator m_blender;
    int m_lastStrokeId = 0;
    QString m_filePath;
};

} // namespace celform::model
