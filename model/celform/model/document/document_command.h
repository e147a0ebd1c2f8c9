// The base of the undo commands behind every Document edit, and what decides which of them merge:
// a command merges only with the next command of the same property on the same target in the
// same gesture (DESIGN.md, "The document"; Qt's undo framework and Krita do the same), through
// QUndoCommand::id() and mergeWith() alone.
#pragma once

#include "celform/model/document/document.h"

#include <QUndoCommand>

namespace celform::model {

/// The properties a PropertyCommand can set; with the target they decide what merges.
enum class Property {
    BaseMesh,
    DrawingName,
    DrawingOpacity,
    DrawingCamera,
    DrawingOutline,
    KeyName,
    KeyEnabled,
    KeyCamera,
    KeyDrawings,
    Sharpness,
    UnspecifiedMode,
    TimeInterpolation,
    ShadingStyle,
    MaterialStyles,
    Light,
    Background,
    ToonRamp,
    ToonEvaluation,
    Gooch,
    Hatch,
    ShowLines,
    LineSettings,
    LineStyle,
    Stereo,
    RenderCamera,
    CameraPath,
    SceneTime,
    BaseAnimation,
    WholeLook,
    HighlightName,
    HighlightKeys,
    HighlightPatch,
    HighlightGuide,
    HighlightSmoothing,
    HighlightVisible,
    HighlightCombinations,
    FaceSets,
    MirrorPlane,
    Subdivision,
    LightTrack,
    FaceValues,
};

/// What a command edits, for merging: a property of one object (id 0: of the document itself)
/// at an index (a material; 0 for properties without one). Two edits merge only when their
/// targets are equal and they were made in the same gesture.
struct EditTarget {
    Property property;
    ObjectId id = 0;
    int index = 0;

    friend bool operator==(const EditTarget& a, const EditTarget& b)
    {
        return a.property == b.property && a.id == b.id && a.index == b.index;
    }
    friend bool operator!=(const EditTarget& a, const EditTarget& b) { return !(a == b); }
};

/// QUndoCommand::id() of the commands that may merge (within a gesture).
enum CommandId {
    kPropertyMergeId = 1001,
    kKeyDeformationMergeId = 1002,
    kShadingOffsetsMergeId = 1003,
    kFaceSetMergeId = 1004,
    kFaceValuesMergeId = 1005,
};

/// Base of every document command: its redo and undo run inside one Document::Batch, so the
/// document emits one changed() for the command and all its children. Commands are the only
/// code that writes the document's data (mutableData()) and reports the change (noteChange()).
class DocumentCommand : public QUndoCommand {
public:
    DocumentCommand(Document* doc, const QString& text, QUndoCommand* parent = nullptr)
        : QUndoCommand(text, parent)
        , m_doc(doc)
    { }
    void redo() final
    {
        const Document::Batch batch(m_doc);
        QUndoCommand::redo(); // children first, in order
        apply(true);
    }
    void undo() final
    {
        const Document::Batch batch(m_doc);
        apply(false);
        QUndoCommand::undo(); // children in reverse order
    }

protected:
    /// Does (forward) or undoes this command's own change and reports it with noteChange().
    virtual void apply(bool /*forward*/) { }
    [[nodiscard]] ProjectData& mutableData() const { return m_doc->mutableData(); }
    void noteChange(const ChangeSet& change) const { m_doc->noteChange(change); }
    Document* m_doc;
};

/// A step made of child commands only.
using CompositeCommand = DocumentCommand;

} // namespace celform::model
