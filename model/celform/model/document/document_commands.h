// The generic undo commands behind the Document's edits: a property set by id, an item inserted or
// removed, the id counter. They hold ids and before/after values, never pointers into the data,
// so an undo after other edits still finds its target.
#pragma once

#include "celform/model/document/document_command.h"

#include <functional>
#include <optional>
#include <utility>

namespace celform::model {

/// Sets one value found by a locator (by id) from `before` to `after`. A value spread over
/// several members (a drawing's camera and its "aligned" flag) goes through a getter and a setter.
template <typename T> class PropertyCommand : public DocumentCommand {
public:
    using Locator = std::function<T*(ProjectData&)>;
    /// Reads the value (none when the target is gone); given the data the setter writes, so that
    /// a locator serves both.
    using Getter = std::function<std::optional<T>(ProjectData&)>;
    using Setter = std::function<void(ProjectData&, const T&)>;

    PropertyCommand(Document* doc, const QString& text, EditTarget target, Locator locate, T after, ChangeSet change,
        GestureId gesture, QUndoCommand* parent = nullptr)
        : PropertyCommand(
            doc, text, target,
            [locate](ProjectData& d) -> std::optional<T> {
                if (T* v = locate(d))
                    return *v;
                return std::nullopt;
            },
            [locate](ProjectData& d, const T& value) {
                if (T* v = locate(d))
                    *v = value;
            },
            std::move(after), std::move(change), gesture, parent)
    { }

    PropertyCommand(Document* doc, const QString& text, EditTarget target, Getter get, Setter set, T after,
        ChangeSet change, GestureId gesture, QUndoCommand* parent = nullptr)
        : DocumentCommand(doc, text, parent)
        , m_target(target)
        , m_get(std::move(get))
        , m_set(std::move(set))
        , m_after(std::move(after))
        , m_change(std::move(change))
        , m_gesture(gesture)
    {
        if (const std::optional<T> v = m_get(mutableData()))
            m_before = *v;
    }

    int id() const override { return m_gesture ? kPropertyMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* o = dynamic_cast<const PropertyCommand*>(other);
        if (!o || o->m_target != m_target || o->m_gesture != m_gesture)
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
        if (!m_get(mutableData()))
            return; // the target is gone
        m_set(mutableData(), forward ? m_after : m_before);
        noteChange(m_change);
    }

private:
    EditTarget m_target;
    Getter m_get;
    Setter m_set;
    T m_before{};
    T m_after;
    ChangeSet m_change;
    GestureId m_gesture;
};

/// A change of a part's structure (items added, removed or renamed).
inline ChangeSet structuralChange(Part part, ObjectId id = 0)
{
    ChangeSet c = ChangeSet::of(part, id);
    c.structure = true;
    return c;
}

/// The object of a kind with an id (for fieldOf).
template <typename Object> Object* objectById(ProjectData& data, ObjectId id);
template <> inline Drawing* objectById<Drawing>(ProjectData& data, ObjectId id)
{
    return data.drawing(id);
}
template <> inline KeyViewpoint* objectById<KeyViewpoint>(ProjectData& data, ObjectId id)
{
    return data.key(id);
}
template <> inline HighlightTrack* objectById<HighlightTrack>(ProjectData& data, ObjectId id)
{
    return data.highlight(id);
}

/// Locates a member of the object with an id (a drawing, key or highlight layer); null when the
/// object is gone.
template <typename T, typename Object> std::function<T*(ProjectData&)> fieldOf(ObjectId id, T Object::*member)
{
    return [id, member](ProjectData& d) -> T* {
        Object* x = objectById<Object>(d, id);
        return x ? &(x->*member) : nullptr;
    };
}

/// Locates a member of a part the document holds once (the look, the blend settings).
template <typename T, typename Part> std::function<T*(ProjectData&)> fieldOf(Part ProjectData::*part, T Part::*member)
{
    return [part, member](ProjectData& d) { return &((d.*part).*member); };
}

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
        noteChange(change);
    }
    void put()
    {
        auto& items = m_container(mutableData());
        items.insert(items.begin() + std::ptrdiff_t(std::min(m_index, items.size())), m_item);
        note();
    }
    void take()
    {
        auto& items = m_container(mutableData());
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
    void apply(bool forward) override { mutableData().nextId = forward ? m_after : m_before; }

private:
    ObjectId m_before;
    ObjectId m_after;
};

/// The command that stores a drawing's aligned camera (camera and "aligned" flag as one value),
/// for the edits that align a drawing alone or together with its key.
QUndoCommand* newDrawingCameraCommand(Document* doc, const QString& text, ObjectId id, const Camera& camera,
    GestureId gesture, QUndoCommand* parent = nullptr);

} // namespace celform::model
