// Key deformations: offsets per frame (paper 1, sections 3.1.2 and 4.2), the brush strokes that
// edit them, and the undo command that stores them sparsely.
#include "celform/model/document/document.h"

#include "celform/algorithms/sorted_merge.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

/// Whether indices are strictly ascending and below limit, and the rows are finite.
bool validStep(const std::vector<std::uint32_t>& indices, const algo::Positions& displacements, std::uint32_t limit)
{
    if (displacements.rows() != Eigen::Index(indices.size()) || !displacements.allFinite())
        return false;
    for (std::size_t k = 0; k < indices.size(); ++k)
        if (indices[k] >= limit || (k > 0 && indices[k] <= indices[k - 1]))
            return false;
    return true;
}

} // namespace

// --- KeyOffsetsCommand ------------------------------------------------------------------------

KeyOffsetsCommand::KeyOffsetsCommand(
    Document* doc, const QString& text, ObjectId key, int frame, Change change, int gesture)
    : DocumentCommand(doc, text)
    , m_key(key)
    , m_frame(frame)
    , m_change(std::move(change))
    , m_gesture(gesture)
{
    const KeyViewpoint* k = doc->data().key(key);
    m_frameExisted = k && k->offsetsByFrame.count(frame) > 0;
    m_note.parts = std::uint32_t(Part::Keys);
    m_note.offsetsOnly = true;
    m_note.ids = {key};
    m_note.frames = {frame};
}

void KeyOffsetsCommand::note(bool frameAddedOrRemoved)
{
    m_note.structure = frameAddedOrRemoved;
    m_doc->noteChange(m_note);
}

void KeyOffsetsCommand::apply(bool forward)
{
    KeyViewpoint* key = m_doc->mutableData().key(m_key);
    if (!key)
        return;
    const bool existed = key->offsetsByFrame.count(m_frame) > 0;
    SparseOffsets& offsets = key->offsetsByFrame[m_frame];
    offsets.assign(m_change.indices, forward ? m_change.after : m_change.before,
        forward ? m_change.afterPresent : m_change.beforePresent);
    if (!forward && !m_frameExisted && offsets.indices.empty())
        key->offsetsByFrame.erase(m_frame); // undo leaves the key exactly as it was
    m_note.vertices.assign(m_change.indices.begin(), m_change.indices.end());
    note(existed != (key->offsetsByFrame.count(m_frame) > 0));
}

bool KeyOffsetsCommand::absorb(const std::vector<std::uint32_t>& indices, const algo::Positions& displacements)
{
    KeyViewpoint* key = m_doc->mutableData().key(m_key);
    if (!key || indices.empty())
        return false;
    const auto stored = key->offsetsByFrame.find(m_frame);
    if (stored == key->offsetsByFrame.end())
        return false;
    // Every step index must be one of ours and already stored. All three lists ascend, so one
    // forward walk finds each index's slot in the command and in the stored offsets; nothing is
    // written before every index is found.
    SparseOffsets& offsets = stored->second;
    m_slots.resize(indices.size());
    std::size_t slot = 0;
    auto at = offsets.indices.begin();
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const std::uint32_t v = indices[k];
        while (slot < m_change.indices.size() && m_change.indices[slot] < v)
            ++slot;
        if (slot == m_change.indices.size() || m_change.indices[slot] != v || !m_change.afterPresent[slot])
            return false;
        at = std::lower_bound(at, offsets.indices.end(), v);
        if (at == offsets.indices.end() || *at != v)
            return false;
        m_slots[k] = {slot, std::size_t(at - offsets.indices.begin())};
    }
    for (std::size_t k = 0; k < indices.size(); ++k) {
        Eigen::Vector3f& after = m_change.after[m_slots[k].first];
        after += displacements.row(Eigen::Index(k)).transpose();
        offsets.deltas[m_slots[k].second] = after;
    }
    m_note.vertices.assign(indices.begin(), indices.end());
    const Document::Batch batch(m_doc);
    note(false);
    return true;
}

bool KeyOffsetsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const KeyOffsetsCommand*>(other);
    if (!o || o->m_gesture != m_gesture || o->m_key != m_key || o->m_frame != m_frame)
        return false;
    const Change& b = o->m_change;
    if (b.indices == m_change.indices) {
        // The same vertices again (a stroke's steps): take their "after" in place.
        m_change.after = b.after;
        m_change.afterPresent = b.afterPresent;
        return true;
    }
    // Union of the two vertex sets: our "before" where we have one, their "after" where they do.
    Change merged;
    const Change& a = m_change;
    auto add = [&merged](const Change& first, std::size_t i, const Change& last, std::size_t j) {
        merged.indices.push_back(first.indices[i]);
        merged.before.push_back(first.before[i]);
        merged.beforePresent.push_back(first.beforePresent[i]);
        merged.after.push_back(last.after[j]);
        merged.afterPresent.push_back(last.afterPresent[j]);
    };
    algo::mergeAscending(
        a.indices, b.indices, [&](std::size_t i) { add(a, i, a, i); }, [&](std::size_t j) { add(b, j, b, j); },
        [&](std::size_t i, std::size_t j) { add(a, i, b, j); });
    m_change = std::move(merged);
    return true;
}

// --- offsets ---------------------------------------------------------------------------------------

void Document::setKeyOffsets(ObjectId id, int frame, SparseOffsets offsets, const QString& undoText)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key)
        return;
    // Express the replacement as a sparse change of the union of old and new vertices.
    const SparseOffsets* old = nullptr;
    if (auto it = key->offsetsByFrame.find(frame); it != key->offsetsByFrame.end())
        old = &it->second;
    KeyOffsetsCommand::Change change;
    const SparseOffsets none;
    const SparseOffsets& before = old ? *old : none;
    auto add = [&change](std::uint32_t v, const Eigen::Vector3f* was, const Eigen::Vector3f* becomes) {
        change.indices.push_back(v);
        change.before.push_back(was ? *was : Eigen::Vector3f::Zero());
        change.beforePresent.push_back(was != nullptr);
        change.after.push_back(becomes ? *becomes : Eigen::Vector3f::Zero());
        change.afterPresent.push_back(becomes != nullptr);
    };
    algo::mergeAscending(
        before.indices, offsets.indices, [&](std::size_t i) { add(before.indices[i], &before.deltas[i], nullptr); },
        [&](std::size_t j) { add(offsets.indices[j], nullptr, &offsets.deltas[j]); },
        [&](std::size_t i, std::size_t j) { add(before.indices[i], &before.deltas[i], &offsets.deltas[j]); });
    push(new KeyOffsetsCommand(this, undoText, id, frame, std::move(change), 0));
}

QStringList Document::importKeyDeformation(ObjectId id, const QString& meshPath, int frame)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || !m_data.baseMesh)
        return {};
    MeshImport imported = importMesh(meshPath);
    const auto& base = *m_data.baseMesh;
    if (imported.mesh.vertexCount() != base.vertexCount())
        throw IoError(meshPath,
            tr("has %1 vertices, but the base model has %2: a key deformation needs the base "
               "model's vertex count and order")
                .arg(imported.mesh.vertexCount())
                .arg(base.vertexCount()));
    QStringList warnings;
    if (imported.mesh.faces.rows() != base.faces.rows() || imported.mesh.faces != base.faces)
        warnings << tr("its triangles differ from the base model's; only the vertex positions are used");
    setKeyOffsets(id, frame, SparseOffsets::difference(imported.mesh.vertices, base.vertices),
        tr("Import Deformation into “%1”").arg(key->name));
    return warnings;
}

void Document::displaceKeyVertices(ObjectId id, int frame, const std::vector<std::uint32_t>& indices,
    const algo::Positions& displacements, const QString& undoText)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || indices.empty() || !m_data.baseMesh)
        return;
    if (!validStep(indices, displacements, std::uint32_t(m_data.baseMesh->vertexCount())))
        return; // out of range, out of order or NaN: never written into the document
    // A stroke's later steps: the command on top of the stack takes them in place. Not at the
    // clean index (a save during the stroke): the saved state must stay one undo step away, as
    // QUndoStack keeps it by never merging into the clean command.
    const bool onTop = m_openOffsets && m_undo->index() == m_undo->count() && m_undo->index() > 0
        && m_undo->cleanIndex() != m_undo->index() && m_undo->command(m_undo->index() - 1) == m_openOffsets;
    if (onTop && m_openOffsets->key() == id && m_openOffsets->frame() == frame && m_openOffsets->gesture() == m_gesture
        && m_gesture != 0 && m_openOffsets->absorb(indices, displacements))
        return;

    // The offsets the artist sees at this frame: the stored ones, or where the frame has none,
    // the interpolated ones (paper 1, section 4.2), which the new frame then stores in full so
    // that adding a keyed frame does not change the shape shown there.
    const auto stored = key->offsetsByFrame.find(frame);
    const bool isKeyed = stored != key->offsetsByFrame.end();
    ProjectData::FrameOffsets seen;
    if (!isKeyed)
        seen = ProjectData::offsetsAt(*key, frame, m_data.blend.time);
    const SparseOffsets empty;
    const SparseOffsets& current = isKeyed ? stored->second : seen.get() ? *seen.get() : empty;

    KeyOffsetsCommand::Change change;
    const std::size_t reserve = isKeyed ? indices.size() : indices.size() + current.indices.size();
    change.indices.reserve(reserve);
    change.before.reserve(reserve);
    change.after.reserve(reserve);
    change.beforePresent.reserve(reserve);
    change.afterPresent.reserve(reserve);
    auto add = [&change](std::uint32_t v, const Eigen::Vector3f& before, bool present, const Eigen::Vector3f& after) {
        change.indices.push_back(v);
        change.before.push_back(before);
        change.beforePresent.push_back(present);
        change.after.push_back(after);
        change.afterPresent.push_back(1);
    };
    const Eigen::Vector3f zero = Eigen::Vector3f::Zero();
    auto moved = [&](std::size_t k, const Eigen::Vector3f* shown) {
        const Eigen::Vector3f now = shown ? *shown : zero;
        add(indices[k], isKeyed ? now : zero, isKeyed && shown, now + displacements.row(Eigen::Index(k)).transpose());
    };
    algo::mergeAscending(
        current.indices, indices,
        [&](std::size_t i) {
            // A new frame stores the interpolated offsets of the vertices the step does not touch.
            if (!isKeyed)
                add(current.indices[i], zero, false, current.deltas[i]);
        },
        [&](std::size_t k) { moved(k, nullptr); }, [&](std::size_t i, std::size_t k) { moved(k, &current.deltas[i]); });

    push(new KeyOffsetsCommand(this, undoText, id, frame, std::move(change), m_gesture));
    if (m_gesture != 0 && m_undo->index() > 0) {
        // The command on top now (ours, or the one it merged into) takes the gesture's next steps.
        auto* top = dynamic_cast<KeyOffsetsCommand*>(const_cast<QUndoCommand*>(m_undo->command(m_undo->index() - 1)));
        m_openOffsets = top && top->gesture() == m_gesture ? top : nullptr;
    }
}

// --- brush strokes ------------------------------------------------------------------------------------

BrushStroke Document::beginBrushStroke(ObjectId id, int frame, std::uint32_t picked, double radius,
    const Camera& camera, bool mirrorX, const algo::BrushProfile& profile)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key)
        throw EditRefused(tr("Choose a key to deform first (Scene panel, then Edit Key)."));
    if (!m_data.baseMesh || picked >= std::uint32_t(m_data.baseMesh->vertexCount()))
        throw EditRefused(tr("The base model has no vertex %1.").arg(picked));
    if (!(radius >= 0.0) || !std::isfinite(radius))
        throw EditRefused(tr("The brush radius must be a positive number."));
    if (!camera.isValid())
        throw EditRefused(tr("The brush needs a valid camera (eye, target and up must differ)."));
    BrushStroke stroke;
    stroke.key = id;
    stroke.frame = frame;
    stroke.imageFrame = {camera.right(), camera.trueUp(), camera.forward()};
    stroke.shape = m_data.keyShape(*key, frame);
    // Paper 1, section 3.1.2: every vertex within r of the picked one, on the shape as it is now.
    const algo::VertexGrid grid(stroke.shape);
    stroke.selection = algo::selectForBrush(stroke.shape, grid, picked, radius, profile);
    if (mirrorX) {
        const std::int32_t twin = m_data.baseMesh->xMirror()[picked];
        if (twin >= 0 && std::uint32_t(twin) != picked)
            stroke.mirrorSelection = algo::selectForBrush(stroke.shape, grid, std::uint32_t(twin), radius, profile);
    }
    // The union of both selections, ascending; where both hold a vertex the first one moves it.
    const auto& a = stroke.selection.indices;
    const auto& b = stroke.mirrorSelection.indices;
    stroke.indices.reserve(a.size() + b.size());
    stroke.sources.reserve(a.size() + b.size());
    auto fromSelection = [&stroke, &a](std::size_t i) {
        stroke.sources.push_back(std::int32_t(i));
        stroke.indices.push_back(a[i]);
    };
    algo::mergeAscending(
        a, b, fromSelection,
        [&stroke, &b](std::size_t j) {
            stroke.sources.push_back(-1 - std::int32_t(j));
            stroke.indices.push_back(b[j]);
        },
        [&fromSelection](std::size_t i, std::size_t) { fromSelection(i); });
    stroke.moves.resize(Eigen::Index(a.size()), 3);
    stroke.twinMoves.resize(Eigen::Index(b.size()), 3);
    stroke.steps.resize(Eigen::Index(stroke.indices.size()), 3);
    stroke.undoText = tr("Brush “%1”").arg(key->name);
    stroke.gesture = beginGesture();
    return stroke;
}

void Document::applyBrushStroke(BrushStroke& stroke, const BrushStep& step)
{
    const KeyViewpoint* key = m_data.key(stroke.key);
    if (!stroke.active() || !key || !m_data.baseMesh || stroke.shape.rows() != m_data.baseMesh->vertexCount())
        return;
    const algo::ImageFrame& frame = stroke.imageFrame;
    // The mirror image of the frame: the twin selection moves as the reflection of the first.
    const Eigen::Vector3d flip(-1.0, 1.0, 1.0);
    const algo::ImageFrame mirrored{
        -frame.right.cwiseProduct(flip), frame.up.cwiseProduct(flip), frame.forward.cwiseProduct(flip)};
    const algo::TriMesh& mesh = *m_data.baseMesh;
    auto displace = [&](const algo::BrushSelection& selection, const algo::ImageFrame& f, algo::Positions& out) {
        switch (step.motion) {
        case BrushMotion::Drag:
            algo::brushDrag(selection, f, step.a, step.b, out);
            break;
        case BrushMotion::Push:
            algo::brushPush(selection, f, step.a, out);
            break;
        case BrushMotion::Rotate:
            algo::brushRotate(selection, stroke.shape, f, step.a, out);
            break;
        case BrushMotion::Scale:
            algo::brushScale(selection, stroke.shape, f, step.a, out);
            break;
        case BrushMotion::Smooth:
        case BrushMotion::Relax:
            algo::brushSmooth(selection, stroke.shape, mesh.faces, mesh.vertexFaces(), std::clamp(step.a, 0.0, 1.0),
                out, stroke.scratch, step.motion == BrushMotion::Relax);
            break;
        }
    };
    displace(stroke.selection, frame, stroke.moves);
    if (!stroke.mirrorSelection.indices.empty())
        displace(stroke.mirrorSelection, mirrored, stroke.twinMoves);
    for (std::size_t k = 0; k < stroke.indices.size(); ++k) {
        const std::int32_t s = stroke.sources[k];
        stroke.steps.row(Eigen::Index(k))
            = s >= 0 ? stroke.moves.row(Eigen::Index(s)) : stroke.twinMoves.row(Eigen::Index(-1 - s));
    }
    if (!stroke.steps.allFinite())
        return;
    for (std::size_t k = 0; k < stroke.indices.size(); ++k)
        stroke.shape.row(stroke.indices[k]) += stroke.steps.row(Eigen::Index(k));
    const int gesture = m_gesture;
    m_gesture = stroke.gesture; // the stroke's steps merge whatever else opened a gesture since
    displaceKeyVertices(stroke.key, stroke.frame, stroke.indices, stroke.steps, stroke.undoText);
    m_gesture = gesture;
}

void Document::endBrushStroke(BrushStroke& stroke)
{
    if (stroke.gesture != 0 && m_gesture == stroke.gesture)
        endGesture();
    stroke.gesture = 0;
}

} // namespace celform::model
