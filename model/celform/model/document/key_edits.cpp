// The key viewpoints' edits: keys, their deformations per frame (paper 1, sections 3.1.2 and
// 4.2) and the falloff brush strokes that edit them.
#include "celform/model/document/key_edits.h"

#include "celform/algorithms/sorted_merge.h"
#include "celform/model/data/io_error.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/document/key_deformation_command.h"
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

void KeyEdits::refuseDuplicateDirection(const Eigen::Vector3d& direction, ObjectId ignoredKey) const
{
    const double limit = std::cos(algo::ViewSphere::kDuplicateAngleDegrees * M_PI / 180.0);
    for (const auto& other : data().keys) {
        if (other.id != ignoredKey && other.direction.dot(direction) > limit)
            throw EditRefused(tr("Key “%1” already has this view direction; a second key needs a different "
                                 "direction (at least %2° apart).")
                                  .arg(other.name)
                                  .arg(algo::ViewSphere::kDuplicateAngleDegrees));
    }
}

ObjectId KeyEdits::addKey(KeyViewpoint key)
{
    if (!key.direction.allFinite() || key.direction.norm() == 0.0)
        throw EditRefused(tr("A key needs a view direction."));
    key.direction.normalize();
    refuseDuplicateDirection(key.direction, 0);
    key.id = data().nextId;
    key.name = uniqueKeyName(key.name);
    // Links only to drawings the project holds (as linkKeyDrawing): a project file never names a
    // drawing that is not in it.
    key.drawingIds.erase(std::remove_if(key.drawingIds.begin(), key.drawingIds.end(),
                             [this](ObjectId drawing) { return data().drawing(drawing) == nullptr; }),
        key.drawingIds.end());
    const ObjectId id = key.id;
    auto* cmd = new CompositeCommand(m_doc, tr("Add Key “%1”").arg(key.name));
    new NextIdCommand(m_doc, id + 1, cmd);
    new InsertRemoveCommand<KeyViewpoint>(
        m_doc, {}, [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; }, std::move(key),
        data().keys.size(), false, Part::Keys, cmd);
    push(cmd);
    return id;
}

ObjectId KeyEdits::createKey(
    const QString& name, const Camera& camera, std::vector<ObjectId> drawingIds, SparseOffsets deformation, int frame)
{
    if (!data().baseMesh)
        throw EditRefused(tr("Import a base model before making keys."));
    if (!camera.isValid())
        throw EditRefused(tr("The key's camera is not valid (eye, target and up must differ)."));
    KeyViewpoint key;
    key.name = name;
    key.camera = camera;
    key.direction = BlendEvaluator::viewDirection(data(), camera.eye, frame);
    if (key.direction.norm() == 0.0)
        throw EditRefused(tr("The key's camera sits at the centre of the model; move it away first."));
    key.drawingIds = std::move(drawingIds);
    key.offsetsByFrame[frame] = std::move(deformation);
    return addKey(std::move(key));
}

ObjectId KeyEdits::createKeyFromDrawing(ObjectId drawingId)
{
    const Drawing* drawing = data().drawing(drawingId);
    if (!drawing)
        throw EditRefused(tr("The drawing no longer exists."));
    if (!drawing->aligned)
        throw EditRefused(
            tr("Align the drawing “%1” first: its camera gives the key's view direction.").arg(drawing->name));
    return createKey(drawing->name, drawing->camera, {drawingId});
}

void KeyEdits::setKeyCamera(ObjectId id, const Camera& camera)
{
    const KeyViewpoint* key = data().key(id);
    if (!key || !camera.isValid() || key->camera == camera)
        return;
    const Eigen::Vector3d direction = keyDirection(id, camera);
    auto* cmd = new CompositeCommand(m_doc, tr("Re-align Key “%1”").arg(key->name));
    addKeyCameraCommands(id, camera, direction, cmd);
    push(cmd);
}

Eigen::Vector3d KeyEdits::keyDirection(ObjectId id, const Camera& camera) const
{
    const Eigen::Vector3d direction = BlendEvaluator::viewDirection(data(), camera.eye, data().currentFrame);
    if (direction.norm() == 0.0)
        throw EditRefused(tr("The key's camera sits at the centre of the model; move it away first."));
    refuseDuplicateDirection(direction, id);
    return direction;
}

void KeyEdits::addKeyCameraCommands(
    ObjectId id, const Camera& camera, const Eigen::Vector3d& direction, QUndoCommand* parent) const
{
    const ChangeSet change = ChangeSet::of(Part::Keys, id);
    new PropertyCommand<Camera>(
        m_doc, {}, {Property::KeyCamera, id}, fieldOf(id, &KeyViewpoint::camera), camera, change, {}, parent);
    new PropertyCommand<Eigen::Vector3d>(
        m_doc, {}, {Property::KeyCamera, id}, fieldOf(id, &KeyViewpoint::direction), direction, change, {}, parent);
}

void KeyEdits::applyFittedCamera(ObjectId drawingId, ObjectId keyId, const Camera& camera)
{
    const Drawing* drawing = data().drawing(drawingId);
    const KeyViewpoint* key = keyId ? data().key(keyId) : nullptr;
    if (!drawing || !camera.isValid() || (keyId && !key))
        return;
    const bool moveKey = key && key->camera != camera;
    const Eigen::Vector3d direction = moveKey ? keyDirection(keyId, camera) : Eigen::Vector3d::Zero();
    auto* cmd = new CompositeCommand(m_doc, tr("Fit Camera to Drawing"));
    newDrawingCameraCommand(m_doc, {}, drawingId, camera, {}, cmd);
    if (moveKey)
        addKeyCameraCommands(keyId, camera, direction, cmd);
    push(cmd);
}

void KeyEdits::linkKeyDrawing(ObjectId keyId, ObjectId drawingId)
{
    const KeyViewpoint* key = data().key(keyId);
    if (!key)
        return;
    std::vector<ObjectId> ids;
    if (drawingId != 0 && data().drawing(drawingId))
        ids.push_back(drawingId);
    if (ids == key->drawingIds)
        return;
    push(new PropertyCommand<std::vector<ObjectId>>(m_doc,
        ids.empty() ? tr("Unlink Key “%1”").arg(key->name) : tr("Link Key “%1” to a Drawing").arg(key->name),
        {Property::KeyDrawings, keyId}, fieldOf(keyId, &KeyViewpoint::drawingIds), ids,
        structuralChange(Part::Keys, keyId), {}));
}

void KeyEdits::removeKey(ObjectId id)
{
    const KeyViewpoint* key = data().key(id);
    if (!key)
        return;
    const auto index = std::size_t(key - data().keys.data());
    push(new InsertRemoveCommand<KeyViewpoint>(
        m_doc, tr("Remove Key “%1”").arg(key->name),
        [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; }, *key, index, true, Part::Keys));
}

void KeyEdits::renameKey(ObjectId id, const QString& name)
{
    const KeyViewpoint* key = data().key(id);
    if (!key || key->name == name.trimmed() || name.trimmed().isEmpty())
        return;
    const QString unique = uniqueKeyName(name);
    push(new PropertyCommand<QString>(m_doc, tr("Rename Key to “%1”").arg(unique), {Property::KeyName, id},
        fieldOf(id, &KeyViewpoint::name), unique, structuralChange(Part::Keys, id), {}));
}

void KeyEdits::setKeyEnabled(ObjectId id, bool enabled)
{
    const KeyViewpoint* key = data().key(id);
    if (!key || key->enabled == enabled)
        return;
    push(new PropertyCommand<bool>(m_doc,
        enabled ? tr("Enable Key “%1”").arg(key->name) : tr("Disable Key “%1”").arg(key->name),
        {Property::KeyEnabled, id}, fieldOf(id, &KeyViewpoint::enabled), enabled, structuralChange(Part::Keys, id),
        {}));
}

QString KeyEdits::uniqueKeyName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return data().keyByName(n) != nullptr; });
}

// --- deformations -----------------------------------------------------------------------------------

void KeyEdits::setKeyDeformation(ObjectId id, int frame, SparseOffsets deformation, const QString& undoText)
{
    const KeyViewpoint* key = data().key(id);
    if (!key)
        return;
    // Express the replacement as a sparse change of the union of old and new vertices.
    const SparseOffsets* old = nullptr;
    if (auto it = key->offsetsByFrame.find(frame); it != key->offsetsByFrame.end())
        old = &it->second;
    KeyDeformationCommand::Change change;
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
        before.indices, deformation.indices, [&](std::size_t i) { add(before.indices[i], &before.deltas[i], nullptr); },
        [&](std::size_t j) { add(deformation.indices[j], nullptr, &deformation.deltas[j]); },
        [&](std::size_t i, std::size_t j) { add(before.indices[i], &before.deltas[i], &deformation.deltas[j]); });
    push(new KeyDeformationCommand(m_doc, undoText, id, frame, std::move(change), {}));
}

QStringList KeyEdits::importKeyDeformation(ObjectId id, const MeshImport& imported, const QString& meshPath, int frame)
{
    const KeyViewpoint* key = data().key(id);
    if (!key || !data().baseMesh)
        return {};
    const auto& base = *data().baseMesh;
    if (imported.mesh.vertexCount() != base.vertexCount())
        throw IoError(meshPath,
            tr("has %1 vertices, but the base model has %2: a key deformation needs the base "
               "model's vertex count and order")
                .arg(imported.mesh.vertexCount())
                .arg(base.vertexCount()));
    QStringList warnings;
    if (imported.mesh.faces.rows() != base.faces.rows() || imported.mesh.faces != base.faces)
        warnings << tr("its triangles differ from the base model's; only the vertex positions are used");
    // The mesh is the shape at the frame, so the deformation is taken from the base as it stands
    // there (paper 1, section 4: offsets ride on the animated base), not from the rest pose, or
    // the shape at frame would carry the base's motion twice.
    algo::Positions scratch;
    setKeyDeformation(id, frame,
        SparseOffsets::difference(imported.mesh.vertices, data().basePositions(frame, scratch)),
        tr("Import Deformation into “%1”").arg(key->name));
    return warnings;
}

void KeyEdits::applyFittedShape(
    ObjectId id, int frame, const std::vector<std::uint32_t>& indices, const algo::Positions& displacements)
{
    displaceKeyVertices(id, frame, indices, displacements, tr("Fit Shape to Drawing"));
}

void KeyEdits::displaceKeyVertices(ObjectId id, int frame, const std::vector<std::uint32_t>& indices,
    const algo::Positions& displacements, const QString& undoText, GestureId gesture)
{
    const KeyViewpoint* key = data().key(id);
    if (!key || indices.empty() || !data().baseMesh)
        return;
    if (!validStep(indices, displacements, std::uint32_t(data().baseMesh->vertexCount())))
        return; // out of range, out of order or NaN: never written into the document
    // The deformation the artist sees at this frame: the stored ones, or where the frame has none,
    // the interpolated ones (paper 1, section 4.2), which the new frame then stores in full so
    // that adding a keyed frame does not change the shape shown there.
    const auto stored = key->offsetsByFrame.find(frame);
    const bool isKeyed = stored != key->offsetsByFrame.end();
    ProjectData::FrameOffsets seen;
    if (!isKeyed)
        seen = ProjectData::offsetsAt(*key, frame, data().blend.time);
    const SparseOffsets empty;
    const SparseOffsets& current = isKeyed ? stored->second : seen.get() ? *seen.get() : empty;

    KeyDeformationCommand::Change change;
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
    if (isKeyed) {
        // A keyed frame (a stroke's later steps): look each vertex up from where the last one was
        // found, so a step costs what the brush touches, not the key's whole deformation.
        auto from = current.indices.begin();
        for (std::size_t k = 0; k < indices.size(); ++k) {
            from = std::lower_bound(from, current.indices.end(), indices[k]);
            const bool held = from != current.indices.end() && *from == indices[k];
            moved(k, held ? &current.deltas[std::size_t(from - current.indices.begin())] : nullptr);
        }
    } else {
        algo::mergeAscending(
            current.indices, indices,
            [&](std::size_t i) {
                // A new frame stores the interpolated deformation of the vertices the step does not
                // touch.
                add(current.indices[i], zero, false, current.deltas[i]);
            },
            [&](std::size_t k) { moved(k, nullptr); },
            [&](std::size_t i, std::size_t k) { moved(k, &current.deltas[i]); });
    }

    push(new KeyDeformationCommand(m_doc, undoText, id, frame, std::move(change), gesture));
}

// --- brush strokes ------------------------------------------------------------------------------------

void KeyEdits::setMirrorPlane(MirrorPlane plane)
{
    if (data().mirrorPlane == plane)
        return;
    push(new PropertyCommand<MirrorPlane>(m_doc, tr("Set Mirror Plane"), {Property::MirrorPlane},
        [](ProjectData& d) { return &d.mirrorPlane; }, plane, ChangeSet::of(Part::Keys), {}));
}

BrushStroke KeyEdits::beginBrushStroke(ObjectId id, int frame, std::uint32_t picked, double radius,
    const Camera& camera, MirrorPlane mirror, const algo::BrushProfile& profile)
{
    const KeyViewpoint* key = data().key(id);
    if (!key)
        throw EditRefused(tr("Choose a key to deform first (Scene panel, then Edit Key)."));
    if (!data().baseMesh || picked >= std::uint32_t(data().baseMesh->vertexCount()))
        throw EditRefused(tr("The base model has no vertex %1.").arg(picked));
    if (!(radius >= 0.0) || !std::isfinite(radius))
        throw EditRefused(tr("The brush radius must be a positive number."));
    if (!camera.isValid())
        throw EditRefused(tr("The brush needs a valid camera (eye, target and up must differ)."));
    BrushStroke stroke;
    stroke.key = id;
    stroke.frame = frame;
    stroke.imageFrame = {camera.right(), camera.trueUp(), camera.forward()};
    stroke.shape = data().keyShape(*key, frame);
    // Paper 1, section 3.1.2: every vertex within r of the picked one, on the shape as it is now.
    const algo::VertexGrid grid(stroke.shape);
    stroke.selection = algo::selectForBrush(stroke.shape, grid, picked, radius, profile);
    stroke.mirrorAxis = mirrorAxis(mirror);
    if (stroke.mirrorAxis >= 0) {
        // The twin is found on the base model, where the symmetry is: the vertex nearest to the
        // picked one's reflection (an exact twin on a symmetric model). Its neighbourhood on the
        // shape gets the same falloff.
        const std::int32_t twin = data().baseMesh->mirrorTwins(stroke.mirrorAxis)[picked];
        stroke.twinMissing = twin < 0;
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
    stroke.gesture = m_doc->beginGesture();
    return stroke;
}

void KeyEdits::applyBrushStroke(BrushStroke& stroke, const BrushStep& step)
{
    const KeyViewpoint* key = data().key(stroke.key);
    if (!stroke.active() || !key || !data().baseMesh || stroke.shape.rows() != data().baseMesh->vertexCount())
        return;
    const algo::ImageFrame& frame = stroke.imageFrame;
    // The mirror image of the frame: the twin selection moves as the reflection of the first.
    Eigen::Vector3d flip(1.0, 1.0, 1.0);
    if (stroke.mirrorAxis >= 0)
        flip[stroke.mirrorAxis] = -1.0;
    const algo::ImageFrame mirrored{
        -frame.right.cwiseProduct(flip), frame.up.cwiseProduct(flip), frame.forward.cwiseProduct(flip)};
    const algo::TriMesh& mesh = *data().baseMesh;
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
    displaceKeyVertices(stroke.key, stroke.frame, stroke.indices, stroke.steps, stroke.undoText, stroke.gesture);
}

void KeyEdits::endBrushStroke(BrushStroke& stroke)
{
    stroke.gesture.end();
}

} // namespace celform::model
