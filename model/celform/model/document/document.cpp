// Document core: files, the playhead, gestures, change notification, and the edits of the base
// model, drawings and key viewpoints. The look, highlights and key offsets have files of their own
// (document_look.cpp, document_highlights.cpp, document_offsets.cpp).
#include "celform/model/document/document.h"

#include "celform/model/io/animation_io.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/io/image_io.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

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

QString idTarget(ObjectId id)
{
    return QString::number(id);
}

ChangeSet structural(Part part, ObjectId id = 0)
{
    ChangeSet c = ChangeSet::of(part, id);
    c.structure = true;
    return c;
}

/// Locates a drawing's member by id.
template <typename T> std::function<T*(ProjectData&)> drawingField(ObjectId id, T Drawing::*member)
{
    return [id, member](ProjectData& d) -> T* {
        Drawing* x = d.drawing(id);
        return x ? &(x->*member) : nullptr;
    };
}

/// Locates a key's member by id.
template <typename T> std::function<T*(ProjectData&)> keyField(ObjectId id, T KeyViewpoint::*member)
{
    return [id, member](ProjectData& d) -> T* {
        KeyViewpoint* x = d.key(id);
        return x ? &(x->*member) : nullptr;
    };
}

} // namespace

Document::Document(QObject* parent)
    : QObject(parent)
    , m_undo(new QUndoStack(this))
{
    // Anything that changes the stack's top ends the brush stroke's in-place updates.
    connect(m_undo, &QUndoStack::indexChanged, this, [this] {
        if (m_openOffsets && (m_undo->count() == 0 || m_undo->command(m_undo->index() - 1) != m_openOffsets))
            m_openOffsets = nullptr;
    });
}

Document::~Document() = default;

// --- change notification ------------------------------------------------------------------------

Document::Batch::Batch(Document* doc)
    : m_doc(doc)
{
    ++m_doc->m_batchDepth;
}

Document::Batch::~Batch()
{
    if (--m_doc->m_batchDepth > 0 || m_doc->m_pending.empty())
        return;
    // Listeners may push edits of their own: hand them a settled set and start a fresh one.
    ChangeSet change;
    std::swap(change, m_doc->m_pending);
    emit m_doc->changed(change);
    change.clear();
    if (m_doc->m_pending.empty())
        std::swap(change, m_doc->m_pending); // keep the vectors' memory for the next step
}

void Document::noteChange(const ChangeSet& change)
{
    m_pending.merge(change);
    if (m_batchDepth == 0) {
        const Batch flush(this);
    }
}

void Document::push(QUndoCommand* command)
{
    m_undo->push(command);
}

// --- files ------------------------------------------------------------------------------------

void Document::reset(ProjectData data, const QString& filePath)
{
    m_openOffsets = nullptr;
    m_data = std::move(data);
    // Layers from files of before highlight ids, or made by hand, get theirs now.
    for (HighlightTrack& track : m_data.look.highlights)
        if (track.id == 0)
            track.id = m_data.nextId++;
    m_undo->clear();
    m_undo->setClean();
    m_gesture = 0;
    if (m_filePath != filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    ChangeSet change;
    change.reset = true;
    change.structure = true;
    noteChange(change);
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

QStringList Document::newFromMesh(const QString& meshPath, double fps, bool sequence)
{
    if (sequence || opensAsAnimatedBase(meshPath)) {
        reset(newAnimatedProject(readAnimatedBase(meshPath, fps), QFileInfo(meshPath).fileName()));
        return {};
    }
    MeshImport imported = importMesh(meshPath);
    reset(newProject(std::make_shared<const algo::TriMesh>(std::move(imported.mesh)), QFileInfo(meshPath).fileName()));
    return imported.warnings;
}

// --- playhead and gestures ---------------------------------------------------------------------------

void Document::setCurrentFrame(int frame)
{
    if (frame == m_data.currentFrame)
        return;
    m_data.currentFrame = frame;
    ChangeSet change = ChangeSet::of(Part::Playhead);
    change.frames.push_back(frame);
    noteChange(change);
}

int Document::beginGesture()
{
    m_gesture = ++m_lastGesture;
    return m_gesture;
}

void Document::endGesture()
{
    m_gesture = 0;
    m_openOffsets = nullptr;
}

// --- base model --------------------------------------------------------------------------------

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
    auto* cmd = new CompositeCommand(this, tr("Replace Base Model"));
    const ChangeSet meshChange = structural(Part::Mesh);
    new PropertyCommand<MeshPtr>(
        this, {}, Property::BaseMesh, {}, [](ProjectData& d) { return &d.baseMesh; }, std::move(mesh), meshChange, 0,
        cmd);
    new PropertyCommand<QString>(
        this, {}, Property::BaseMesh, {}, [](ProjectData& d) { return &d.baseMeshName; }, meshName, meshChange, 0, cmd);
    if (dropFaceSets) {
        // Face indices mean nothing on other faces: the patches go, their layers cover all faces.
        new PropertyCommand<std::vector<algo::FaceSet>>(
            this, {}, Property::FaceSets, {}, [](ProjectData& d) { return &d.faceSets; }, {},
            structural(Part::FaceSets), 0, cmd);
        for (const HighlightTrack& track : m_data.look.highlights)
            if (!track.patch.isEmpty()) {
                const ObjectId id = track.id;
                new PropertyCommand<QString>(
                    this, {}, Property::HighlightPatch, idTarget(id),
                    [id](ProjectData& d) {
                        HighlightTrack* t = d.highlight(id);
                        return t ? &t->patch : nullptr;
                    },
                    QString(), ChangeSet::of(Part::Highlights, id), 0, cmd);
            }
    }
    push(cmd);
}

QStringList Document::importBaseMesh(const QString& path)
{
    MeshImport imported = importMesh(path);
    setBaseMesh(std::make_shared<const algo::TriMesh>(std::move(imported.mesh)), QFileInfo(path).fileName());
    return imported.warnings;
}

void Document::importAnimatedBase(const QString& path, double fps)
{
    setAnimatedBase(readAnimatedBase(path, fps), QFileInfo(path).fileName());
}

// --- drawings ------------------------------------------------------------------------------------

ObjectId Document::addDrawing(Drawing drawing)
{
    drawing.id = m_data.nextId;
    drawing.name = uniqueDrawingName(drawing.name);
    const ObjectId id = drawing.id;
    auto* cmd = new CompositeCommand(this, tr("Add Drawing “%1”").arg(drawing.name));
    new NextIdCommand(this, id + 1, cmd);
    new InsertRemoveCommand<Drawing>(
        this, {}, [](ProjectData& d) -> std::vector<Drawing>& { return d.drawings; }, std::move(drawing),
        m_data.drawings.size(), false, Part::Drawings, cmd);
    push(cmd);
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
    auto* cmd = new CompositeCommand(this, tr("Remove Drawing “%1”").arg(drawing->name));
    // Unlink the drawing from keys first, so undo relinks them after the drawing is back.
    for (const auto& key : m_data.keys) {
        std::vector<ObjectId> ids = key.drawingIds;
        const auto newEnd = std::remove(ids.begin(), ids.end(), id);
        if (newEnd == ids.end())
            continue;
        ids.erase(newEnd, ids.end());
        new PropertyCommand<std::vector<ObjectId>>(this, {}, Property::KeyDrawings, idTarget(key.id),
            keyField(key.id, &KeyViewpoint::drawingIds), std::move(ids), structural(Part::Keys, key.id), 0, cmd);
    }
    const auto index = std::size_t(drawing - m_data.drawings.data());
    new InsertRemoveCommand<Drawing>(
        this, {}, [](ProjectData& d) -> std::vector<Drawing>& { return d.drawings; }, *drawing, index, true,
        Part::Drawings, cmd);
    push(cmd);
}

void Document::renameDrawing(ObjectId id, const QString& name)
{
    const Drawing* drawing = m_data.drawing(id);
    if (!drawing || drawing->name == name.trimmed() || name.trimmed().isEmpty())
        return;
    const QString unique = uniqueDrawingName(name);
    push(new PropertyCommand<QString>(this, tr("Rename Drawing to “%1”").arg(unique), Property::DrawingName,
        idTarget(id), drawingField(id, &Drawing::name), unique, structural(Part::Drawings, id), 0));
}

void Document::setDrawingOpacity(ObjectId id, double opacity)
{
    const Drawing* drawing = m_data.drawing(id);
    opacity = std::clamp(opacity, 0.0, 1.0);
    if (!drawing || drawing->opacity == opacity || !std::isfinite(opacity))
        return;
    push(new PropertyCommand<double>(this, tr("Set Drawing Opacity"), Property::DrawingOpacity, idTarget(id),
        drawingField(id, &Drawing::opacity), opacity, ChangeSet::of(Part::Drawings, id), m_gesture));
}

void Document::setDrawingCamera(ObjectId id, const Camera& camera)
{
    const Drawing* drawing = m_data.drawing(id);
    if (!drawing || !camera.isValid() || (drawing->aligned && drawing->camera == camera))
        return;
    // The camera and the "aligned" flag are one value: a navigation gesture is one step, and its
    // undo gives back an unaligned drawing where there was one.
    using Aligned = std::pair<Camera, bool>;
    push(new PropertyCommand<Aligned>(
        this, tr("Align Drawing “%1”").arg(drawing->name), Property::DrawingCamera, idTarget(id),
        [id](const ProjectData& d) -> std::optional<Aligned> {
            const Drawing* x = d.drawing(id);
            return x ? std::optional<Aligned>(Aligned{x->camera, x->aligned}) : std::nullopt;
        },
        [id](ProjectData& d, const Aligned& value) {
            if (Drawing* x = d.drawing(id)) {
                x->camera = value.first;
                x->aligned = value.second;
            }
        },
        Aligned{camera, true}, ChangeSet::of(Part::Drawings, id), m_gesture));
}

// --- key viewpoints ---------------------------------------------------------------------------------

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
    auto* cmd = new CompositeCommand(this, tr("Add Key “%1”").arg(key.name));
    new NextIdCommand(this, id + 1, cmd);
    new InsertRemoveCommand<KeyViewpoint>(
        this, {}, [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; }, std::move(key),
        m_data.keys.size(), false, Part::Keys, cmd);
    push(cmd);
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
    key.direction = m_blender.viewDirection(m_data, camera.eye, frame);
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
    const Eigen::Vector3d direction = m_blender.viewDirection(m_data, camera.eye, m_data.currentFrame);
    if (direction.norm() == 0.0)
        throw EditRefused(tr("The key's camera sits at the centre of the model; move it away first."));
    refuseDuplicateDirection(direction, id);
    auto* cmd = new CompositeCommand(this, tr("Re-align Key “%1”").arg(key->name));
    const ChangeSet change = ChangeSet::of(Part::Keys, id);
    new PropertyCommand<Camera>(
        this, {}, Property::KeyCamera, idTarget(id), keyField(id, &KeyViewpoint::camera), camera, change, 0, cmd);
    new PropertyCommand<Eigen::Vector3d>(
        this, {}, Property::KeyCamera, idTarget(id), keyField(id, &KeyViewpoint::direction), direction, change, 0, cmd);
    push(cmd);
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
    push(new PropertyCommand<std::vector<ObjectId>>(this,
        ids.empty() ? tr("Unlink Key “%1”").arg(key->name) : tr("Link Key “%1” to a Drawing").arg(key->name),
        Property::KeyDrawings, idTarget(keyId), keyField(keyId, &KeyViewpoint::drawingIds), ids,
        structural(Part::Keys, keyId), 0));
}

void Document::removeKey(ObjectId id)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key)
        return;
    const auto index = std::size_t(key - m_data.keys.data());
    push(new InsertRemoveCommand<KeyViewpoint>(
        this, tr("Remove Key “%1”").arg(key->name), [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; },
        *key, index, true, Part::Keys));
}

void Document::renameKey(ObjectId id, const QString& name)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || key->name == name.trimmed() || name.trimmed().isEmpty())
        return;
    const QString unique = uniqueKeyName(name);
    push(new PropertyCommand<QString>(this, tr("Rename Key to “%1”").arg(unique), Property::KeyName, idTarget(id),
        keyField(id, &KeyViewpoint::name), unique, structural(Part::Keys, id), 0));
}

void Document::setKeyEnabled(ObjectId id, bool enabled)
{
    const KeyViewpoint* key = m_data.key(id);
    if (!key || key->enabled == enabled)
        return;
    push(new PropertyCommand<bool>(this,
        enabled ? tr("Enable Key “%1”").arg(key->name) : tr("Disable Key “%1”").arg(key->name), Property::KeyEnabled,
        idTarget(id), keyField(id, &KeyViewpoint::enabled), enabled, structural(Part::Keys, id), 0));
}

BlendEvaluator& Document::blender()
{
    m_blender.update(m_data);
    return m_blender;
}

QString Document::uniqueDrawingName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.drawingByName(n) != nullptr; });
}

QString Document::uniqueKeyName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.keyByName(n) != nullptr; });
}

QString Document::uniqueFaceSetName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.faceSet(n) != nullptr; });
}

QString Document::uniqueHighlightName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.highlightByName(n) != nullptr; });
}

} // namespace celform::model
