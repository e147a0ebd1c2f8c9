// The undo commands behind every Document edit. They hold ids and before/after values, never
// pointers into the data, so an undo after other edits still finds its target. A command merges
// only with the next command of the same property on the same target in the same gesture
// (DESIGN.md, "The document"; Qt's undo framework and Krita do the same).
#pragma once

#include "celform/model/document/document.h"

#include <QUndoCommand>

#include <functional>
#include <optional>
#include <utility>

namespace celform::model {

/// The properties a PropertyCommand can set; with the target they decide what merges.
enum class Property {
    BaseMesh,
    DrawingName,
    DrawingOpacity,
    DrawingCamera,
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
};

/// QUndoCommand::id() of the commands that may merge (within a gesture).
enum CommandId { kPropertyMergeId = 1001, kKeyOffsetsMergeId = 1002, kShadingOffsetsMergeId = 1003 };

/// Base of every document command: its redo and undo run inside one Document::Batch, so the
/// document emits one changed() for the command and all its children.
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
    Document* m_doc;
};

/// A step made of child commands only.
using CompositeCommand = DocumentCommand;

/// Sets one value found by a locator (by id) from `before` to `after`. A value spread over
/// several members (a drawing's camera and its "aligned" flag) goes through a getter and a setter.
template <typename T> class PropertyCommand : public DocumentCommand {
public:
    using Locator = std::function<T*(ProjectData&)>;
    using Getter = std::function<std::optional<T>(const ProjectData&)>;
    using Setter = std::function<void(ProjectData&, const T&)>;

    PropertyCommand(Document* doc, const QString& text, Property property, QString target, Locator locate, T after,
        ChangeSet change, int gesture, QUndoCommand* parent = nullptr)
        : PropertyCommand(
            doc, text, property, std::move(target),
            [locate](const ProjectData& d) -> std::optional<T> {
                if (T* v = locate(const_cast<ProjectData&>(d)))
                    return *v;
                return std::nullopt;
            },
            [locate](ProjectData& d, const T& value) {
                if (T* v = locate(d))
                    *v = value;
            },
            std::move(after), std::move(change), gesture, parent)
    { }

    PropertyCommand(Document* doc, const QString& text, Property property, QString target, Getter get, Setter set,
        T after, ChangeSet change, int gesture, QUndoCommand* parent = nullptr)
        : DocumentCommand(doc, text, parent)
        , m_property(property)
        , m_target(std::move(target))
        , m_get(std::move(get))
        , m_set(std::move(set))
        , m_after(std::move(after))
        , m_change(std::move(change))
        , m_gesture(gesture)
    {
        if (const std::optional<T> v = m_get(m_doc->data()))
            m_before = *v;
    }

    int id() const override { return m_gesture != 0 ? kPropertyMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* o = dynamic_cast<const PropertyCommand*>(other);
        if (!o || o->m_property != m_property || o->m_target != m_target || o->m_gesture != m_gesture)
            return false;
        m_after = o->m_after;
        m_change.merge(o->m_change);
        // A gesture that ends where it began leaves no step behind (Qt drops obsolete commands).
        setObsolete(m_before == m_after);
        return true;
    }

protected:
    void apply(bool forward) override
    {
        if (!m_get(m_doc->data()))
            return; // the target is gone
        m_set(m_doc->mutableData(), forward ? m_after : m_before);
        m_doc->noteChange(m_change);
    }

private:
    Property m_property;
    QString m_target;
    Getter m_get;
    Setter m_set;
    T m_before{};
    T m_after;
    ChangeSet m_change;
    int m_gesture;
};

/// Inserts an item (drawing, key, highlight layer) at an index, or removes it when constructed
/// with remove=true.
template <typename Item> class InsertRemoveCommand : public DocumentCommand {
public:
    using Container = std::function<std::vector<Item>&(ProjectData&)>;

    InsertRemoveCommand(Document* doc, const QString& text, Container container, Item item, std::size_t index,
        bool remove, Part part, QUndoCommand* parent = nullptr)
        : DocumentCommand(doc, text, parent)
        , m_container(std::move(container))
        , m_item(std::move(item))
        , m_index(index)
        , m_remove(remove)
        , m_part(part)
    { }

protected:
    void apply(bool forward) override { forward != m_remove ? put() : take(); }

private:
    void note()
    {
        ChangeSet change = ChangeSet::of(m_part, m_item.id);
        change.structure = true;
        m_doc->noteChange(change);
    }
    void put()
    {
        auto& items = m_container(m_doc->mutableData());
        items.insert(items.begin() + std::ptrdiff_t(std::min(m_index, items.size())), m_item);
        note();
    }
    void take()
    {
        auto& items = m_container(m_doc->mutableData());
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (items[i].id == m_item.id) {
                m_item = items[i]; // keep the latest state for a later re-insert
                m_index = i;
                items.erase(items.begin() + std::ptrdiff_t(i));
                note();
                return;
            }
        }
    }

    Container m_container;
    Item m_item;
    std::size_t m_index;
    bool m_remove;
    Part m_part;
};

/// Records the id counter, so undoing an addition leaves the data as it was.
class NextIdCommand : public DocumentCommand {
public:
    NextIdCommand(Document* doc, ObjectId after, QUndoCommand* parent)
        : DocumentCommand(doc, {}, parent)
        , m_before(doc->data().nextId)
        , m_after(after)
    { }

protected:
    void apply(bool forward) override { m_doc->mutableData().nextId = forward ? m_after : m_before; }

private:
    ObjectId m_before;
    ObjectId m_after;
};

/// Changes some of a key's offsets at one frame, storing before and after values of just those
/// vertices (sparse). Steps of one gesture on the same key and frame merge: the union of the
/// vertices, the first "before" and the last "after" of each.
class KeyOffsetsCommand : public DocumentCommand {
public:
    struct Change {
        std::vector<std::uint32_t> indices; ///< ascending
        std::vector<Eigen::Vector3f> before, after;
        std::vector<char> beforePresent, afterPresent;
    };

    KeyOffsetsCommand(Document* doc, const QString& text, ObjectId key, int frame, Change change, int gesture);

    int id() const override { return m_gesture != 0 ? kKeyOffsetsMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

    [[nodiscard]] ObjectId key() const { return m_key; }
    [[nodiscard]] int frame() const { return m_frame; }
    [[nodiscard]] int gesture() const { return m_gesture; }
    /// A brush step on the vertices this command already holds (indices ascending, a subset of
    /// the command's): adds the displacements to their "after" values and applies them in place,
    /// without a new command or any allocation. False (nothing done) when an index is not held.
    bool absorb(const std::vector<std::uint32_t>& indices, const algo::Positions& displacements);

protected:
    void apply(bool forward) override;

private:
    void note(bool frameAddedOrRemoved);

    ObjectId m_key;
    int m_frame;
    Change m_change;
    int m_gesture;
    bool m_frameExisted; ///< whether the key had offsets at m_frame before the first step
    ChangeSet m_note; ///< reused for every notification
    /// absorb()'s working memory: each step index's slot in m_change and in the stored offsets.
    std::vector<std::pair<std::size_t, std::size_t>> m_slots;
};

/// Changes some values of a layer of shading offsets (the base, or a key's at a frame), storing
/// before and after values of just those vertices (sparse), and whether the layer existed before
/// and exists after (a layer made here is stored whole: the command then holds every vertex).
/// Steps of one gesture on the same target merge: the union of the vertices, the first "before"
/// and the last "after" of each.
class ShadingOffsetsCommand : public DocumentCommand {
public:
    struct Change {
        std::vector<std::uint32_t> indices; ///< ascending
        std::vector<float> before, after;
        bool existedBefore = false;
        bool existsAfter = true;
    };
    ShadingOffsetsCommand(Document* doc, const QString& text, ShadingTarget target, Change change, int gesture,
        QUndoCommand* parent = nullptr);

    int id() const override { return m_gesture != 0 ? kShadingOffsetsMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(bool forward) override;

private:
    ShadingTarget m_target;
    Change m_change;
    int m_gesture;
};

} // namespace celform::model
