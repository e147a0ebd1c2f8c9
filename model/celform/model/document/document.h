// The Celform document: the project data, the undo stack, the playhead, and the edit operations
// that panels, viewport tools and the command line all call (DESIGN.md, "The document"). Every
// edit is a QUndoCommand; nothing changes the data behind its back. One changed(ChangeSet) signal
// says what each push, undo or redo touched.
#pragma once

#include "celform/model/document/brush_stroke.h"
#include "celform/model/document/change_set.h"
#include "celform/model/document/highlight_presets.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/offset_stroke.h"
#include "celform/model/data/blend_evaluator.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <memory>
#include <optional>

namespace celform::model {

class KeyOffsetsCommand;
struct AnimatedImport;

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
    /// Opens a gesture: until endGesture(), edits of the same property on the same target merge
    /// into one undo step. Edits outside a gesture are one step each. Returns the gesture's id.
    int beginGesture();
    void endGesture();
    [[nodiscard]] int currentGesture() const { return m_gesture; }

    // --- base model --------------------------------------------------------------------------
    /// Replaces the base model. Keys whose offsets do not fit the new vertex count are refused:
    /// throws IoError naming meshName in that case, and the document is unchanged.
    void setBaseMesh(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName);
    /// Imports a mesh file as the base model; returns the import warnings. Throws IoError.
    QStringList importBaseMesh(const QString& path);
    /// Imports an animated base (glTF/GLB with skins or morph targets, or an OBJ/PLY sequence)
    /// sampled at fps in place of the base model (setAnimatedBase). Throws IoError.
    void importAnimatedBase(const QString& path, double fps = 24.0);

    // --- drawings ----------------------------------------------------------------------------
    ObjectId addDrawing(Drawing drawing);
    /// Imports an image file as a drawing; returns its id. Throws IoError.
    ObjectId importDrawing(const QString& path);
    void removeDrawing(ObjectId id);
    void renameDrawing(ObjectId id, const QString& name);
    void setDrawingOpacity(ObjectId id, double opacity);
    /// Stores the camera aligned to a drawing (and marks it aligned).
    void setDrawingCamera(ObjectId id, const Camera& camera);

    // --- key viewpoints ------------------------------------------------------------------------
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
    void removeKey(ObjectId id);
    void renameKey(ObjectId id, const QString& name);
    void setKeyEnabled(ObjectId id, bool enabled);
    /// Replaces a key's offsets at a frame (one undo step).
    void setKeyOffsets(ObjectId id, int frame, SparseOffsets offsets, const QString& undoText);
    /// Reads a mesh with the base model's vertex count and order and makes its difference from
    /// the base the key's deformation at frame. Throws IoError (unreadable, vertex count
    /// mismatch). Returns import warnings.
    QStringList importKeyDeformation(ObjectId id, const QString& meshPath, int frame = 0);
    /// Adds displacements (#indices by 3, indices ascending) to a key's offsets at a frame. At a
    /// frame without stored offsets the stored offsets start from the interpolated ones there
    /// (what the artist sees), so the edit adds to them. Steps in one gesture on the same key and
    /// frame are one undo step.
    void displaceKeyVertices(ObjectId id, int frame, const std::vector<std::uint32_t>& indices,
        const algo::Positions& displacements, const QString& undoText);

    // --- the falloff brush (paper 1, section 3.1.2): the editor's tool and `celform brush` -----
    /// Starts a stroke on key `id` at `frame`: selects the vertices of the key's shape there
    /// within radius of vertex picked, and with mirrorX their mirror images across x = 0, and
    /// opens a gesture. The camera gives the image plane; the profile the falloff curve and
    /// strength. Throws EditRefused (no such key or vertex, no base model).
    BrushStroke beginBrushStroke(ObjectId id, int frame, std::uint32_t picked, double radius, const Camera& camera,
        bool mirrorX = false, const algo::BrushProfile& profile = {});
    /// One step of the stroke: displaces the selection (see BrushStep) and stores it; all steps of
    /// a stroke are one undo step. After the first step nothing is allocated.
    void applyBrushStroke(BrushStroke& stroke, const BrushStep& step);
    /// Ends the stroke's gesture.
    void endBrushStroke(BrushStroke& stroke);

    /// The view-dependent blend of the current keys, up to date.
    BlendEvaluator& blender();

    // --- shading offsets (paper 3, section 4.3): the base layer, or a key's layer at a frame ---
    /// Replaces a target's values (#V, finite) in one undo step. Throws EditRefused (no base
    /// model, no such key, wrong count, a value not finite) and changes nothing then.
    void setShadingOffsets(const ShadingTarget& target, const std::vector<float>& values, const QString& undoText = {});
    /// Removes a target's layer: the base layer, or the key's layer at target.frame (allFrames:
    /// at every frame). One undo step; nothing when there is nothing to clear.
    void clearShadingOffsets(const ShadingTarget& target, bool allFrames = false);
    /// rounds (1 .. kMaxOffsetRounds) of Laplacian smoothing over the mesh's vertex neighbours of
    /// a target's values as seen at its frame. One undo step. Throws EditRefused.
    void smoothShadingOffsets(const ShadingTarget& target, int rounds);
    /// Stores the values model::solveAutoOffsets found for a target (analysis/auto_offsets.h) as
    /// one undo step, "Automatic Shading Offsets (name)". Throws EditRefused as setShadingOffsets.
    void applyAutoOffsets(const ShadingTarget& target, const std::vector<float>& values);
    /// Starts painting a target on shape (the shape shown, #V by 3) and opens a gesture; all dabs
    /// of the stroke are one undo step. Throws EditRefused (no base model or key, bad brush).
    OffsetStroke beginOffsetStroke(const ShadingTarget& target, const OffsetBrush& brush, const algo::Positions& shape);
    /// One dab centred at a point of the shape (model space), with the falloff (1 - d/r)^2 and,
    /// with mirrorX, at its mirror image too. Returns the vertices changed (0: none in reach).
    std::size_t applyOffsetStroke(OffsetStroke& stroke, const Eigen::Vector3d& centre);
    void endOffsetStroke(OffsetStroke& stroke);

    // --- blend settings (paper 1, sections 3.2-3.3 and 4.2) -----------------------------------
    void setSharpness(double alpha);
    void setUnspecifiedMode(UnspecifiedMode mode);
    void setTimeInterpolation(TimeInterpolation time);

    // --- the look, property by property ---------------------------------------------------------
    /// The style of every material (material < 0: clears per-material styles) or of one.
    void setShadingStyle(ShadingStyle style, int material = -1);
    /// The key light; a change of vector is "Move Light", of type "Change Light Type".
    void setLight(const Light& light);
    /// Optimise Light for Stereo (paper 3, 4.1): stores the light a finished run of
    /// model::optimiseLight found (found) as one undo step; nothing when it kept the light. Throws
    /// EditRefused when the light is no longer the one the run started from (startedFrom).
    void applyOptimisedLight(const Light& startedFrom, const Light& found);
    void setBackgroundColor(const Eigen::Vector3f& color);
    /// Refused (no change) when the ramp is not valid.
    void setToonRamp(const algo::ToonRamp& ramp);
    void setToonEvaluation(algo::ToonEvaluation evaluation);
    void setGooch(const algo::GoochParams& gooch);
    void setHatch(const algo::HatchParams& hatch);
    void setShowLines(bool show);
    void setLineSettings(const algo::LineSettings& settings);
    void setLineStyle(const algo::LineStyle& style);
    void setStereo(const StereoLook& stereo);
    /// The shot's camera (none: a framed default view). Refuses an invalid camera.
    void setRenderCamera(const std::optional<Camera>& camera);
    /// Replaces the whole look but its highlight layers in one step ("Apply Look", presets);
    /// never merges.
    void setLook(const Look& look);

    // --- animation (issue 13; paper 1, section 4 and figures 10-12): document_animation.cpp -----
    /// Frames per second and the frame range. Throws EditRefused (sceneTimeProblem).
    void setSceneTime(const SceneTime& time);
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
    /// IoError naming sourceName when the keys' offsets do not fit, EditRefused for an
    /// inconsistent animation.
    void setAnimatedBase(std::shared_ptr<const algo::TriMesh> mesh,
        std::shared_ptr<const algo::BaseAnimation> animation, double fps, const QString& sourceName);
    /// The same from what readAnimatedBase read (animation_io.h); an empty animation is a still base.
    void setAnimatedBase(AnimatedImport&& imported, const QString& sourceName);

    // --- stylized highlights (Anjyo & Hiramitsu 2003), by layer id ----------------------------
    /// Adds layers in one undo step (undoText), after the others; gives each a new id. Names must
    /// be unique and the tracks valid (highlightTracksProblem), else EditRefused and no change.
    std::vector<ObjectId> addHighlightLayers(std::vector<HighlightTrack> tracks, const QString& undoText);
    /// Adds one layer named name (made unique) with a plain key at frame. Returns its id.
    ObjectId addHighlightLayer(const QString& name, int frame);
    /// Adds a preset's layers (highlight_presets.h) at frame, on the patch, guide and smoothing of
    /// base (0: all faces) with names made unique; one undo step. Returns the ids, the visible
    /// layer last.
    std::vector<ObjectId> addHighlightPreset(HighlightPreset preset, ObjectId base, int frame);
    /// Removes a layer and its use in other layers' combinations (one undo step).
    void removeHighlightLayer(ObjectId id);
    /// Renames a layer, other layers' combinations following. Throws EditRefused for an empty or
    /// taken name.
    void renameHighlightLayer(ObjectId id, const QString& name);
    /// Sets (replaces or inserts) the key at frame. The undo text names what changed (size,
    /// colour, cut, operations). Throws EditRefused for parameters out of the paper's range.
    void setHighlightKey(ObjectId id, double frame, const algo::HighlightLayer& layer);
    /// Replaces all keys at once (structure edits of the operations, which every key follows).
    void setHighlightKeys(ObjectId id, std::vector<algo::HighlightKey> keys, const QString& undoText);
    /// Operations are the same list in every key (so that keys interpolate): these change the list
    /// of every key at once. Add appends a neutral operation of the type; move shifts one by delta
    /// places; remove drops one.
    void addHighlightOperation(ObjectId id, algo::HighlightOperationType type);
    void moveHighlightOperation(ObjectId id, int index, int delta);
    void removeHighlightOperation(ObjectId id, int index);
    /// Removes the key at frame; a layer keeps at least one key (no change then).
    void removeHighlightKey(ObjectId id, double frame);
    /// Direct manipulation of a highlight at frame: Translation moves it by (a, b) along the
    /// layer's du and dv as they are before its operations (rotations earlier in the list turn
    /// the frame; they are undone here), Rotation turns it by a degrees, DirectionalScaling adds a
    /// to delta (clamped to [0, 1]). A layer without an operation of that type gets one in every
    /// key first (translation and rotation at the front, scaling at the end), so its keys keep
    /// interpolating. Steps in one gesture are one undo step.
    void nudgeHighlight(ObjectId id, double frame, algo::HighlightOperationType type, double a, double b = 0.0);
    /// Moves a highlight at frame so that its translation along the unturned du and dv is
    /// (alpha, beta) (HighlightTrack::translationAt); the "Move Highlight" step of a drag.
    void setHighlightTranslation(ObjectId id, double frame, double alpha, double beta);
    void setHighlightPatch(ObjectId id, const QString& patch);
    void setHighlightGuide(ObjectId id, const Eigen::Vector3f& guide);
    void setHighlightSmoothing(ObjectId id, int rounds);
    void setHighlightVisible(ObjectId id, bool visible);
    void setHighlightCombinations(ObjectId id, std::vector<std::pair<algo::HighlightBoolean, QString>> combinations);
    [[nodiscard]] QString uniqueHighlightName(const QString& wanted) const;

    // --- face sets: the highlight patches (paper 2, "Highlight operations") --------------------
    /// Creates or replaces a face set; faces are sorted and repeats dropped. Steps in one gesture
    /// are one undo step (one paint drag). Throws EditRefused without a base model, for an
    /// empty name or a face out of range.
    void setFaceSet(const QString& name, std::vector<std::int32_t> faces, const QString& undoText);
    /// Adds faces to (subtract: takes them from) a face set, creating it when missing.
    void paintFaceSet(const QString& name, const std::vector<std::int32_t>& faces, bool subtract);
    /// Removes a face set; highlight layers on it go back to all faces in the same undo step.
    void removeFaceSet(const QString& name);
    /// Renames a face set and the highlight layers' references to it (one undo step). Throws
    /// EditRefused for an empty name or one already taken.
    void renameFaceSet(const QString& name, const QString& newName);
    /// A new empty face set for a layer, and the layer moved onto it (one undo step).
    QString newFaceSetForLayer(ObjectId layer, const QString& wanted);
    [[nodiscard]] QString uniqueFaceSetName(const QString& wanted) const;

    /// Makes a name unique among drawings or keys by appending " 2", " 3", ...
    [[nodiscard]] QString uniqueDrawingName(const QString& wanted) const;
    [[nodiscard]] QString uniqueKeyName(const QString& wanted) const;

    // --- for the undo commands only ---------------------------------------------------------------
    ProjectData& mutableData() { return m_data; }
    /// Records what a command changed; emitted once when the outermost command finishes.
    void noteChange(const ChangeSet& change);
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
    friend class KeyOffsetsCommand;
    void refuseDuplicateDirection(const Eigen::Vector3d& direction, ObjectId ignoredKey) const;
    /// Pushes a command, or when the open brush-stroke command is on top, lets it absorb the step.
    void push(QUndoCommand* command);
    [[nodiscard]] const HighlightTrack& highlightOrThrow(ObjectId id) const;
    /// Checks the tracks as they would be after an edit; throws EditRefused with the problem.
    void refuseInvalidTracks(const std::vector<HighlightTrack>& tracks) const;

    ProjectData m_data;
    QUndoStack* m_undo;
    BlendEvaluator m_blender;
    QString m_filePath;
    int m_gesture = 0;
    int m_lastGesture = 0;
    int m_batchDepth = 0;
    ChangeSet m_pending;
    /// The brush-stroke command on top of the stack while its gesture is open (see push()).
    KeyOffsetsCommand* m_openOffsets = nullptr;
};

} // namespace celform::model
