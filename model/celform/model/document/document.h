// The Celform document: the project data, the undo stack, the playhead, gestures, and the edit
// operations that panels, viewport tools and the command line all call (DESIGN.md, "The
// document"), grouped by domain into facades (doc.keys(), doc.look(), ...). Every edit is a
// QUndoCommand; nothing changes the data behind its back. One changed(ChangeSet) signal says what
// each push, undo or redo touched.
#pragma once

#include "celform/model/data/blend_evaluator.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/animation_edits.h"
#include "celform/model/document/change_set.h"
#include "celform/model/document/drawing_edits.h"
#include "celform/model/document/face_set_edits.h"
#include "celform/model/document/gesture.h"
#include "celform/model/document/highlight_edits.h"
#include "celform/model/document/key_edits.h"
#include "celform/model/document/look_edits.h"
#include "celform/model/document/shading_edits.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <memory>
#include <optional>

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
    /// An animated glTF/GLB, a `#` pattern (walk_####.obj) or, with sequence, a numbered file
    /// and its numbered siblings start an animated base (animation_io.h) sampled at fps, which
    /// sets the scene's frame rate and range.
    QStringList newFromMesh(const QString& meshPath, double fps = 24.0, bool sequence = false);
    /// Replaces everything, clears undo history; for open and tests.
    void reset(ProjectData data, const QString& filePath = {});

    // --- the playhead (DESIGN.md: not undoable, saved with the project) ---------------------
    [[nodiscard]] int currentFrame() const { return m_data.currentFrame; }
    /// Moves the playhead; every view follows it. Does not mark the document modified.
    void setCurrentFrame(int frame);

    // --- gestures: one drag, slider press-to-release or run of key repeats is one undo step ----
    /// Opens a gesture (gesture.h): edits given it merge with the previous edit of the same
    /// property on the same target in it; it ends when the token is destroyed or ended. Edits
    /// given no gesture are one undo step each.
    [[nodiscard]] Gesture beginGesture();

    // --- base model --------------------------------------------------------------------------
    /// Replaces the base model. Keys whose deformations do not fit the new vertex count are
    /// refused: throws IoError naming meshName in that case, and the document is unchanged.
    void setBaseMesh(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName);
    /// Imports a mesh file as the base model; returns the import warnings. Throws IoError.
    QStringList importBaseMesh(const QString& path);

    /// The view-dependent blend of the current keys, up to date.
    BlendEvaluator& blender();

    // --- the edits, by domain ------------------------------------------------------------------
    /// Key viewpoints, their deformations and the falloff brush.
    [[nodiscard]] KeyEdits& keys() { return m_keys; }
    /// Reference drawings and their aligned cameras.
    [[nodiscard]] DrawingEdits& drawings() { return m_drawings; }
    /// Blend settings and the look: shading style, light, toon, lines, stereo, render camera.
    [[nodiscard]] LookEdits& look() { return m_look; }
    /// Stylized highlight layers, their keys and operations.
    [[nodiscard]] HighlightEdits& highlights() { return m_highlights; }
    /// Named face sets: the highlight patches.
    [[nodiscard]] FaceSetEdits& faceSets() { return m_faceSets; }
    /// Shading offsets: set, clear, smooth, the automatic solve's result, the offset brush.
    [[nodiscard]] ShadingEdits& shading() { return m_shading; }
    /// Scene time, camera path, turntable, animated base.
    [[nodiscard]] AnimationEdits& animation() { return m_animation; }

    /// Commands running inside one Batch emit one changed() at the end.
    class Batch {
    public:
        explicit Batch(Document* doc);
        ~Batch();
        Batch(const Batch&) = delete;
        Batch& operator=(const Batch&) = delete;

    private:
        Document* m_doc;
    };

signals:
    /// What one push, undo, redo, reset or playhead move changed. Delivered synchronously; the
    /// set is valid only during the call.
    void changed(const celform::model::ChangeSet& change);
    void filePathChanged(const QString& path);

private:
    // Only commands write the data and report what they changed; the facades push commands.
    friend class DocumentCommand;
    friend class DocumentFacade;
    ProjectData& mutableData() { return m_data; }
    /// Records what a command changed; emitted once when the outermost command finishes.
    void noteChange(const ChangeSet& change);
    void push(QUndoCommand* command);

    ProjectData m_data;
    QUndoStack* m_undo;
    BlendEvaluator m_blender;
    QString m_filePath;
    int m_lastGesture = 0;
    int m_batchDepth = 0;
    ChangeSet m_pending;
    KeyEdits m_keys{*this};
    DrawingEdits m_drawings{*this};
    LookEdits m_look{*this};
    HighlightEdits m_highlights{*this};
    FaceSetEdits m_faceSets{*this};
    ShadingEdits m_shading{*this};
    AnimationEdits m_animation{*this};
};

} // namespace celform::model
