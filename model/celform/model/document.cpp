// Document edits: each builds an undo command and pushes it; the command does the change.
#include "celform/model/document.h"

#include "celform/model/document_commands.h"
#include "celform/model/image_io.h"
#include "celform/model/io_error.h"
#include "celform/model/mesh_io.h"
#include "celform/model/project_file.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <QCoreApplication>
#include <QFileInfo>

namespace celform::model {
namespace {

using MeshPtr = std::shared_ptr<const algo::TriMesh>;

/// Highest vertex index any key offset refers to, or -1.
std::int64_t maxOffsetIndex(const ProjectData& data)
{
    std::int64_t m = -1;
    for (const auto& key : data.keys)
        for (const auto& [frame, offsets] : key.offsetsByFrame)
            if (!offsets.indices.empty())
                m = std::max<std::int64_t>(m, offsets.indices.back());
    return m;
}

/// A command that records the id counter, so undoing an addition leaves the data as it was.
class NextIdCommand : public QUndoCommand {
public:
    NextIdCommand(Document* doc, ObjectId after, QUndoCommand* parent)
        : QUndoCommand(parent)
        , m_doc(doc)
        , m_before(doc->data().nextId)
        , m_after(after)
    { }
    void redo() override { m_doc->mutableData().nextId = m_after; }
    void undo() override { m_doc->mutableData().nextId = m_before; }

private:
    Document* m_doc;
    ObjectId m_before;
    ObjectId m_after;
};

QString uniqueName(const QString& wanted, const std::function<bool(const QString&)>& taken)
{
    const QString base = wanted.trimmed().isEmpty() ? Document::tr("Untitled") : wanted.trimmed();
    if (!taken(base))
        return base;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(base).arg(n);
        if (!taken(candidate))
            return candidate;
    }
}

/// The look with its highlight layers on patch `from` (on any patch when from is empty) moved to
/// patch `to` (empty: all faces); nothing when no layer is on it.
std::optional<Look> lookWithLayersMoved(const Look& look, const QString& from, const QString& to)
{
    Look moved = look;
    bool changed = false;
    for (auto& track : moved.highlights)
        if (!track.patch.isEmpty() && (from.isEmpty() || track.patch == from)) {
            track.patch = to;
            changed = true;
        }
    return changed ? std::optional<Look>(std::move(moved)) : std::nullopt;
}

} // namespace

Document::Document(QObject* parent)
    : QObject(parent)
    , m_undo(new QUndoStack(this))
{ }

Document::~Document() = default;

void Document::notifyChanged(Part part)
{
    switch (part) {
    case Part::Mesh:
        emit meshChanged();
        break;
    case Part::Drawings:
        emit drawingsChanged();
        break;
    case Part::Keys:
        emit keysChanged();
        break;
    case Part::Blend:
        emit blendChanged();
        break;
    case Part::Look:
        emit lookChanged();
        break;
    case Part::FaceSets:
        emit faceSetsChanged();
        break;
    }
}

// --- files ------------------------------------------------------------------------------------

void Document::reset(ProjectData data, const QString& filePath)
{
    m_data = std::move(data);
    m_undo->clear();
    m_undo->setClean();
    if (m_filePath != filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    emit documentReset();
}

void Document::open(const QString& path)
{
    ProjectData loaded = loadProject(path); // throws before anything here changes
    reset(std::move(loaded), QFileInfo(path).absoluteFilePath());
}

void Document::saveAs(const QString& path)
{
    saveProject(m_data, path);
    m_undo->setClean();
    const QString abs = QFileInfo(path).absoluteFilePath();
    if (m_filePath != abs) {
        m_filePath = abs;
        emit filePathChanged(m_filePath);
    }
}

void Document::saveCopy(const QString& path) const
{
    saveProject(m_data, path, /*keepBackup=*/false);
}

QStringList Document::newFromMesh(const QString& meshPath)
{
    MeshImport imported = importMesh(meshPath);
    reset(newProject(std::make_shared<const algo::TriMesh>(std::move(imported.mesh)), QFileInfo(meshPath).fileName()));
    return imported.warnings;
}

// --- edits ------------------------------------------------------------------------------------

void Document::setBaseMesh(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName)
{
    Q_ASSERT(mesh);
    const std::int64_t needed = maxOffsetIndex(m_data);
    if (needed >= mesh->vertexCount())
        throw IoError(meshName,
            tr("has %1 vertices, but the key deformations use vertex %2; "
               "a replacement base model needs the same vertex count and order")
                .arg(mesh->vertexCount())
                .arg(needed));
    const bool dropFaceSets
        = !m_data.faceSets.empty() && m_data.baseMesh && m_data.baseMesh->faceCount() != mesh->faceCount();
    auto* cmd = new QUndoCommand(tr("Replace Base Model"));
    new AssignCommand<MeshPtr>(
        this, {}, [](ProjectData& d) { return &d.baseMesh; }, std::move(mesh), Part::Mesh, -1, 0, cmd);
    new AssignCommand<QString>(
        this, {}, [](ProjectData& d) { return &d.baseMeshName; }, meshName, Part::Mesh, -1, 0, cmd);
    if (dropFaceSets) {
        // Face indices mean nothing on other faces: the patches go, their layers cover all faces.
        new AssignCommand<std::vector<algo::FaceSet>>(
            this, {}, [](ProjectData& d) { return &d.faceSets; }, {}, Part::FaceSets, -1, 0, cmd);
        if (auto look = lookWithLayersMoved(m_data.look, {}, {}))
            new AssignCommand<Look>(
                this, {}, [](ProjectData& d) { return &d.look; }, std::move(*look), Part::Look, -1, 0, cmd);
    }
    m_undo->push(cmd);
}

QStringList Document::importBaseMesh(const QString& path)
{
    MeshImport imported = importMesh(path);
    setBaseMesh(std::make_shared<const algo::TriMesh>(std::move(imported.mesh)), QFileInfo(path).fileName());
    return imported.warnings;
}

ObjectId Document::addDrawing(Drawing drawing)
{
    drawing.id = m_data.nextId;
    drawing.name = uniqueDrawingName(drawing.name);
    const ObjectId id = drawing.id;
    auto* cmd = new QUndoCommand(tr("Add Drawing “%1”").arg(drawing.name));
    new NextIdCommand(this, id + 1, cmd);
    new InsertRemoveCommand<Drawing>(
        this, {}, [](ProjectData& d) -> std::vector<Drawing>& { return d.drawings; }, std::move(drawing),
        m_data.drawings.size(), false, Part::Drawings, cmd);
    m_undo->push(cmd);
    return id;
}

ObjectId Document::importDrawing(const QString& path)
{
    return addDrawing(model::importDrawing(path));
}

void Document::removeDrawing(ObjectId id)
{
    const Drawing* drawing = m_data.drawing(id);
    if (!drawing)
        return;
    auto* cmd = new QUndoCommand(tr("Remove Drawing “%1”").arg(drawing->name));
    // Unlink the drawing from keys first, so undo relinks them after the drawing is back.
    for (const auto& key : m_data.keys) {
        std::vector<ObjectId> ids = key.drawingIds;
        const auto newEnd = std::remove(ids.begin(), ids.end(), id);
        if (newEnd == ids.end())
            continue;
        ids.erase(newEnd, ids.end());
        const ObjectId keyId = key.id;
        new AssignCommand<std::vector<ObjectId>>(
            this, {},
            [keyId](ProjectData& d) {
                auto* k = d.key(keyId);
                return k ? &k->drawingIds : nullptr;
            },
            std::move(ids), Part::Keys, -1, 0, cmd);
    }
    const auto index = std::size_t(drawing - m_data.drawings.data());
    new InsertRemoveCommand<Drawing>(
        this, {}, [](ProjectData& d) -> std::vector<Drawing>& { return d.drawings; }, *drawing, index, true,
        Part::Drawings, cmd);
    m_undo->push(cmd);
}

void Document::renameDrawing(ObjectId id, const QString& name)
{
    const Drawing* drawing = m_data.drawing(id);
    if (!drawing || drawing->name == name.trimmed() || name.trimmed().isEmpty())
        return;
    const QString unique = uniqueDrawingName(name);
    m_undo->push(new AssignCommand<QString>(
        this, tr("Rename Drawing to “%1”").arg(unique),
        [id](ProjectData& d) {
            auto* x = d.drawing(id);
            return x ? &x->name : nullptr;
        },
        unique, Part::Drawings));
}

void Document::setDrawingOpacity(ObjectId id, double opacity)
{
    const Drawing* drawing = m_data.drawing(id);
    opacity = std::clamp(opacity, 0.0, 1.0);
    if (!drawing || drawing->opacity == opacity)
        return;
    m_undo->push(new AssignCommand<double>(
        this, tr("Set Drawing Opacity"),
        [id](ProjectData& d) {
            auto* x = d.drawing(id);
            return x ? &x->opacity : nullptr;
        },
        opacity, Part::Drawings, kDrawingOpacityId, id));
}

void Document::setDrawingCamera(ObjectId id, const Camera& camera)
{
    const Drawing* drawing = m_data.drawing(id);
    if (!drawing || !camera.isValid() || (drawing->aligned && drawing->camera == camera))
        return;
    auto* cmd = new QUndoCommand(tr("Align Drawing “%1”").arg(drawing->name));
    new AssignCommand<Camera>(
        this, {},
        [id](ProjectData& d) {
            auto* x = d.drawing(id);
            return x ? &x->camera : nullptr;
        },
        camera, Part::Drawings, -1, 0, cmd);
    new AssignCommand<bool>(
        this, {},
        [id](ProjectData& d) {
            auto* x = d.drawing(id);
            return x ? &x->aligned : nullptr;
        },
        true, Part::Drawings, -1, 0, cmd);
    m_undo->push(cmd);
}

void Document::refuseDuplicateDirection(const Eigen::Vector3d& direction, ObjectId ignoredKey) const
{
    const double limit = std::cos(algo::ViewSphere::kDuplicateAngleDegrees * M_PI / 180.0);
    for (const auto& other : m_data.keys) {
        if (other.id != ignoredKey && other.direction.dot(direction) > limit)
            throw EditRefused(tr("Key “%1” already has this view direction; a second key needs a different "
                                 "direction (at least %2° apart).")
                                  .arg(other.name)
                                  .arg(algo::ViewSphere::kDuplicateAngleDegrees));
    }
}

ObjectId Document::addKey(KeyViewpoint key)
{
    if (!key.direction.allFinite() || key.direction.norm() == 0.0)
        throw EditRefused(tr("A key needs a view direction."));
    key.direction.normalize();
    refuseDuplicateDirection(key.direction, 0);
    key.id = m_data.nextId;
    key.name = uniqueKeyName(key.name);
    const ObjectId id = key.id;
    auto* cmd = new QUndoCommand(tr("Add Key “%1”").arg(key.name));
    new NextIdCommand(this, id + 1, cmd);
    new InsertRemoveCommand<KeyViewpoint>(
        this, {}, [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; }, std::move(key),
        m_data.keys.size(), false, Part::Keys, cmd);
    m_undo->push(cmd);
    return id;
}

ObjectId Document::createKey(
    const QString& name, const Camera& camera, std::vector<ObjectId> drawingIds, SparseOffsets offsets, int frame)
{
    if (!m_data.baseMesh)
        throw EditRefused(tr("Import a base model before making keys."));
    if (!camera.isValid())
        throw EditRefused(tr("The key's camera is not valid (eye, target and up must differ)."));
    KeyViewpoint key;
    key.name = name;
    key.camera = camera;
    key.direction = m_blender.viewDirection(m_data, camera.eye);
    if (key.direction.norm() == 0.0)
        throw EditRefused(tr("The key's camera sits at the centre of the model; move it away first."));
    key.drawingIds = std::move(drawingIds);
    key.offsetsByFrame[frame] = std::move(offsets);
    return addKey(std::move(key));
}

ObjectId Document::createKeyFromDrawing(ObjectId drawingId)
{
    const Drawing* drawing = m_data.drawing(drawingId);
    if (!drawing)
        throw EditRefused(tr("The drawing no longer exists."));
    if (!drawing->aligned)
        throw EditRefused(
            tr("Align the drawing “%1” first: its camera gives the key's view direction.").arg(drawing->name));
    return createKey(drawing->name, drawing->camera, {drawingId});
}

void Document::setKeyCamera(ObjectId id, const Camera& camera)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || !camera.isValid() || key->camera == camera)
        return;
    const Eigen::Vector3d direction = m_blender.viewDirection(m_data, camera.eye);
    if (direction.norm() == 0.0)
        throw EditRefused(tr("The key's camera sits at the centre of the model; move it away first."));
    refuseDuplicateDirection(direction, id);
    auto* cmd = new QUndoCommand(tr("Re-align Key “%1”").arg(key->name));
    new AssignCommand<Camera>(
        this, {},
        [id](ProjectData& d) {
            auto* k = d.key(id);
            return k ? &k->camera : nullptr;
        },
        camera, Part::Keys, -1, 0, cmd);
    new AssignCommand<Eigen::Vector3d>(
        this, {},
        [id](ProjectData& d) {
            auto* k = d.key(id);
            return k ? &k->direction : nullptr;
        },
        direction, Part::Keys, -1, 0, cmd);
    m_undo->push(cmd);
}

void Document::linkKeyDrawing(ObjectId keyId, ObjectId drawingId)
{
    const KeyViewpoint* key = m_data.key(keyId);
    if (!key)
        return;
    std::vector<ObjectId> ids;
    if (drawingId != 0 && m_data.drawing(drawingId))
        ids.push_back(drawingId);
    if (ids == key->drawingIds)
        return;
    m_undo->push(new AssignCommand<std::vector<ObjectId>>(
        this, ids.empty() ? tr("Unlink Key “%1”").arg(key->name) : tr("Link Key “%1” to a Drawing").arg(key->name),
        [keyId](ProjectData& d) {
            auto* k = d.key(keyId);
            return k ? &k->drawingIds : nullptr;
        },
        ids, Part::Keys));
}

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
    std::size_t i = 0, j = 0;
    const std::size_t n = old ? old->indices.size() : 0;
    while (i < n || j < offsets.indices.size()) {
        const bool takeOld = j == offsets.indices.size() || (i < n && old->indices[i] <= offsets.indices[j]);
        const bool takeNew = i == n || (j < offsets.indices.size() && offsets.indices[j] <= old->indices[i]);
        change.indices.push_back(takeOld ? old->indices[i] : offsets.indices[j]);
        change.before.push_back(takeOld ? old->deltas[i] : Eigen::Vector3f::Zero());
        change.beforePresent.push_back(takeOld);
        change.after.push_back(takeNew ? offsets.deltas[j] : Eigen::Vector3f::Zero());
        change.afterPresent.push_back(takeNew);
        i += takeOld;
        j += takeNew;
    }
    m_undo->push(new KeyOffsetsCommand(this, undoText, id, frame, std::move(change), 0));
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
    const algo::Positions& displacements, int strokeId, const QString& undoText)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || indices.empty() || !m_data.baseMesh)
        return;
    Q_ASSERT(displacements.rows() == Eigen::Index(indices.size()));
    const auto nv = std::uint32_t(m_data.baseMesh->vertexCount());
    const SparseOffsets* current = nullptr;
    if (auto it = key->offsetsByFrame.find(frame); it != key->offsetsByFrame.end())
        current = &it->second;
    KeyOffsetsCommand::Change change;
    change.indices.reserve(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const std::uint32_t v = indices[k];
        if (v >= nv || (k > 0 && v <= indices[k - 1]) || !displacements.row(Eigen::Index(k)).allFinite())
            continue; // out of range, out of order or NaN: never written into the document
        const Eigen::Vector3f before = current ? current->at(v) : Eigen::Vector3f::Zero();
        bool present = false;
        if (current) {
            const auto it = std::lower_bound(current->indices.begin(), current->indices.end(), v);
            present = it != current->indices.end() && *it == v;
        }
        change.indices.push_back(v);
        change.before.push_back(before);
        change.beforePresent.push_back(present);
        change.after.push_back(before + displacements.row(Eigen::Index(k)).transpose());
        change.afterPresent.push_back(1);
    }
    if (change.indices.empty())
        return;
    m_undo->push(new KeyOffsetsCommand(this, undoText, id, frame, std::move(change), strokeId));
}

BlendEvaluator& Document::blender()
{
    m_blender.update(m_data);
    return m_blender;
}

// --- KeyOffsetsCommand ------------------------------------------------------------------------

KeyOffsetsCommand::KeyOffsetsCommand(
    Document* doc, const QString& text, ObjectId key, int frame, Change change, int strokeId)
    : QUndoCommand(text)
    , m_doc(doc)
    , m_key(key)
    , m_frame(frame)
    , m_change(std::move(change))
    , m_strokeId(strokeId)
{
    const KeyViewpoint* k = doc->data().key(key);
    m_frameExisted = k && k->offsetsByFrame.count(frame) > 0;
}

void KeyOffsetsCommand::apply(bool forward)
{
    KeyViewpoint* key = m_doc->mutableData().key(m_key);
    if (!key)
        return;
    SparseOffsets& offsets = key->offsetsByFrame[m_frame];
    offsets.assign(m_change.indices, forward ? m_change.after : m_change.before,
        forward ? m_change.afterPresent : m_change.beforePresent);
    if (!forward && !m_frameExisted && offsets.indices.empty())
        key->offsetsByFrame.erase(m_frame); // undo leaves the key exactly as it was
    m_doc->notifyChanged(Document::Part::Keys);
}

bool KeyOffsetsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const KeyOffsetsCommand*>(other);
    if (!o || o->m_strokeId != m_strokeId || o->m_key != m_key || o->m_frame != m_frame)
        return false;
    // Union of two ascending index lists: keep our "before", take their "after".
    Change merged;
    const Change& a = m_change;
    const Change& b = o->m_change;
    std::size_t i = 0, j = 0;
    while (i < a.indices.size() || j < b.indices.size()) {
        const bool fromA = j == b.indices.size() || (i < a.indices.size() && a.indices[i] <= b.indices[j]);
        const bool fromB = i == a.indices.size() || (j < b.indices.size() && b.indices[j] <= a.indices[i]);
        merged.indices.push_back(fromA ? a.indices[i] : b.indices[j]);
        merged.before.push_back(fromA ? a.before[i] : b.before[j]);
        merged.beforePresent.push_back(fromA ? a.beforePresent[i] : b.beforePresent[j]);
        merged.after.push_back(fromB ? b.after[j] : a.after[i]);
        merged.afterPresent.push_back(fromB ? b.afterPresent[j] : a.afterPresent[i]);
        i += fromA;
        j += fromB;
    }
    m_change = std::move(merged);
    return true;
}

void Document::removeKey(ObjectId id)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key)
        return;
    const auto index = std::size_t(key - m_data.keys.data());
    m_undo->push(new InsertRemoveCommand<KeyViewpoint>(
        this, tr("Remove Key “%1”").arg(key->name), [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; },
        *key, index, true, Part::Keys));
}

void Document::renameKey(ObjectId id, const QString& name)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || key->name == name.trimmed() || name.trimmed().isEmpty())
        return;
    const QString unique = uniqueKeyName(name);
    m_undo->push(new AssignCommand<QString>(
        this, tr("Rename Key to “%1”").arg(unique),
        [id](ProjectData& d) {
            auto* x = d.key(id);
            return x ? &x->name : nullptr;
        },
        unique, Part::Keys));
}

void Document::setKeyEnabled(ObjectId id, bool enabled)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || key->enabled == enabled)
        return;
    m_undo->push(new AssignCommand<bool>(
        this, enabled ? tr("Enable Key “%1”").arg(key->name) : tr("Disable Key “%1”").arg(key->name),
        [id](ProjectData& d) {
            auto* x = d.key(id);
            return x ? &x->enabled : nullptr;
        },
        enabled, Part::Keys));
}

void Document::setBlendSettings(const BlendSettings& settings)
{
    if (settings == m_data.blend)
        return;
    m_undo->push(new AssignCommand<BlendSettings>(
        this, tr("Change Blend Settings"), [](ProjectData& d) { return &d.blend; }, settings, Part::Blend, kBlendId));
}

void Document::setLook(const Look& look)
{
    if (look == m_data.look)
        return;
    m_undo->push(new AssignCommand<Look>(
        this, tr("Change Look"), [](ProjectData& d) { return &d.look; }, look, Part::Look, kLookId));
}

void Document::setFaceSet(const QString& name, std::vector<std::int32_t> faces, const QString& undoText, int strokeId)
{
    if (!m_data.baseMesh)
        throw EditRefused(tr("There is no base model to make a patch on."));
    if (name.trimmed().isEmpty())
        throw EditRefused(tr("A patch needs a name."));
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    if (!faces.empty() && (faces.front() < 0 || faces.back() >= m_data.baseMesh->faceCount()))
        throw EditRefused(tr("Patch “%1” names a face the base model does not have.").arg(name));
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    const std::string wanted = name.toStdString();
    auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end()) {
        sets.push_back({wanted, std::move(faces)});
    } else {
        if (it->faces == faces && strokeId == 0)
            return;
        it->faces = std::move(faces);
    }
    m_undo->push(new AssignCommand<std::vector<algo::FaceSet>>(
        this, undoText, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), Part::FaceSets,
        strokeId != 0 ? kFaceSetsId : -1, ObjectId(strokeId)));
}

void Document::removeFaceSet(const QString& name)
{
    const std::string wanted = name.toStdString();
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end())
        return;
    sets.erase(it);
    auto* cmd = new QUndoCommand(tr("Delete Patch “%1”").arg(name));
    if (auto look = lookWithLayersMoved(m_data.look, name, {}))
        new AssignCommand<Look>(
            this, {}, [](ProjectData& d) { return &d.look; }, std::move(*look), Part::Look, -1, 0, cmd);
    new AssignCommand<std::vector<algo::FaceSet>>(
        this, {}, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), Part::FaceSets, -1, 0, cmd);
    m_undo->push(cmd);
}

void Document::renameFaceSet(const QString& name, const QString& newName)
{
    const QString trimmed = newName.trimmed();
    if (trimmed == name)
        return;
    if (trimmed.isEmpty())
        throw EditRefused(tr("A patch needs a name."));
    if (m_data.faceSet(trimmed))
        throw EditRefused(tr("There is already a patch named “%1”.").arg(trimmed));
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    const std::string wanted = name.toStdString();
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end())
        return;
    it->name = trimmed.toStdString();
    auto* cmd = new QUndoCommand(tr("Rename Patch “%1”").arg(name));
    new AssignCommand<std::vector<algo::FaceSet>>(
        this, {}, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), Part::FaceSets, -1, 0, cmd);
    if (auto look = lookWithLayersMoved(m_data.look, name, trimmed))
        new AssignCommand<Look>(
            this, {}, [](ProjectData& d) { return &d.look; }, std::move(*look), Part::Look, -1, 0, cmd);
    m_undo->push(cmd);
}

QString Document::uniqueFaceSetName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.faceSet(n) != nullptr; });
}

QString Document::uniqueDrawingName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.drawingByName(n) != nullptr; });
}

QString Document::uniqueKeyName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.keyByName(n) != nullptr; });
}

} // namespace celform::model
