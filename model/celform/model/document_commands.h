// The undo commands behind every Document edit. They hold ids and before/after values, never
// pointers into the data, so an undo after other edits still finds its target.
#pragma once

#include "celform/model/document.h"

#include <QUndoCommand>

#include <functional>
#include <utility>

namespace celform::model {

/// Merge ids of commands that a single gesture repeats (slider drags).
enum CommandId { kDrawingOpacityId = 1001, kBlendId = 1002, kLookId = 1003, kKeyOffsetsId = 1004, kFaceSetsId = 1005 };

/// Sets one value found by a locator (by id) from `before` to `after`. With a merge id, repeated
/// pushes for the same target fold into one undo step keeping the first "before".
template <typename T> class AssignCommand : public QUndoCommand {
public:
    using Locator = std::function<T*(ProjectData&)>;

    AssignCommand(Document* doc, const QString& text, Locator locate, T after, Document::Part part, int mergeId = -1,
        ObjectId mergeTarget = 0, QUndoCommand* parent = nullptr)
        : QUndoCommand(text, parent)
        , m_doc(doc)
        , m_locate(std::move(locate))
        , m_after(std::move(after))
        , m_part(part)
        , m_mergeId(mergeId)
        , m_target(mergeTarget)
    {
        if (T* v = m_locate(m_doc->mutableData()))
            m_before = *v;
    }

    void redo() override { assign(m_after); }
    void undo() override { assign(m_before); }
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override
    {
        auto* o = dynamic_cast<const AssignCommand*>(other);
        if (!o || o->m_target != m_target)
            return false;
        m_after = o->m_after;
        return true;
    }

private:
    void assign(const T& value)
    {
        if (T* v = m_locate(m_doc->mutableData())) {
            *v = value;
            m_doc->notifyChanged(m_part);
        }
    }

    Document* m_doc;
    Locator m_locate;
    T m_before{};
    T m_after;
    Document::Part m_part;
    int m_mergeId;
    ObjectId m_target;
};

/// Inserts an item (drawing or key) at an index, or removes it when constructed with remove=true.
template <typename Item> class InsertRemoveCommand : public QUndoCommand {
public:
    using Container = std::function<std::vector<Item>&(ProjectData&)>;

    InsertRemoveCommand(Document* doc, const QString& text, Container container, Item item, std::size_t index,
        bool remove, Document::Part part, QUndoCommand* parent = nullptr)
        : QUndoCommand(text, parent)
        , m_doc(doc)
        , m_container(std::move(container))
        , m_item(std::move(item))
        , m_index(index)
        , m_remove(remove)
        , m_part(part)
    { }

    void redo() override { m_remove ? take() : put(); }
    void undo() override { m_remove ? put() : take(); }

private:
    void put()
    {
        auto& items = m_container(m_doc->mutableData());
        items.insert(items.begin() + std::ptrdiff_t(std::min(m_index, items.size())), m_item);
        m_doc->notifyChanged(m_part);
    }
    void take()
    {
        auto& items = m_container(m_doc->mutableData());
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (items[i].id == m_item.id) {
                m_item = items[i]; // keep the latest state for a later re-insert
                m_index = i;
                items.erase(items.begin() + std::ptrdiff_t(i));
                m_doc->notifyChanged(m_part);
                return;
            }
        }
    }

    Document* m_doc;
    Container m_container;
    Item m_item;
    std::size_t m_index;
    bool m_remove;
    Document::Part m_part;
};

/// Changes some of a key's offsets at one frame, storing before and after values of just those
/// vertices (sparse). Steps of one brush stroke merge: the union of the vertices, the first
/// "before" and the last "after" of each.
class KeyOffsetsCommand : public QUndoCommand {
public:
    struct Change {
        std::vector<std::uint32_t> indices; ///< ascending
        std::vector<Eigen::Vector3f> before, after;
        std::vector<char> beforePresent, afterPresent;
    };

    KeyOffsetsCommand(Document* doc, const QString& text, ObjectId key, int frame, Change change, int strokeId);

    void redo() override { apply(true); }
    void undo() override { apply(false); }
    int id() const override { return m_strokeId != 0 ? kKeyOffsetsId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(bool forward);

    Document* m_doc;
    ObjectId m_key;
    int m_frame;
    Change m_change;
    int m_strokeId;
    bool m_frameExisted; ///< whether the key had offsets at m_frame before the first step
};

} // namespace celform::model
