// Document edits: each builds an undo command and pushes it; the command does the change.
#include "celform/model/document.h"

#include "celform/model/document_commands.h"
#include "celform/model/image_io.h"
#include "celform/model/io_error.h"
#include "celform/model/mesh_io.h"
#include "celform/model/project_file.h"

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
    ProjectData data;
    data.baseMesh = std::make_shared<const algo::TriMesh>(std::move(imported.mesh));
    data.baseMeshName = QFileInfo(meshPath).fileName();
    reset(std::move(data));
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
    auto* cmd = new QUndoCommand(tr("Replace Base Model"));
    new AssignCommand<MeshPtr>(
        this, {}, [](ProjectData& d) { return &d.baseMesh; }, std::move(mesh), Part::Mesh, -1, 0, cmd);
    new AssignCommand<QString>(
        this, {}, [](ProjectData& d) { return &d.baseMeshName; }, meshName, Part::Mesh, -1, 0, cmd);
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

ObjectId Document::addKey(KeyViewpoint key)
{
    key.id = m_data.nextId;
    key.name = uniqueKeyName(key.name);
    if (key.direction.norm() > 0)
        key.direction.normalize();
    const ObjectId id = key.id;
    auto* cmd = new QUndoCommand(tr("Add Key “%1”").arg(key.name));
    new NextIdCommand(this, id + 1, cmd);
    new InsertRemoveCommand<KeyViewpoint>(
        this, {}, [](ProjectData& d) -> std::vector<KeyViewpoint>& { return d.keys; }, std::move(key),
        m_data.keys.size(), false, Part::Keys, cmd);
    m_undo->push(cmd);
    return id;
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

QString Document::uniqueDrawingName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.drawingByName(n) != nullptr; });
}

QString Document::uniqueKeyName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return m_data.keyByName(n) != nullptr; });
}

} // namespace celform::model
