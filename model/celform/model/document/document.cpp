// Document core: files, the playhead, gestures, change notification, the base model, and the
// facades' base. The edits by domain have files of their own (key_edits.cpp, look_edits.cpp, ...).
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

/// Highest vertex index any key deformation refers to, or -1.
std::int64_t maxDeformedIndex(const ProjectData& data)
{
    std::int64_t m = -1;
    for (const auto& key : data.keys)
        for (const auto& [frame, offsets] : key.offsetsByFrame)
            if (!offsets.indices.empty())
                m = std::max<std::int64_t>(m, offsets.indices.back());
    return m;
}

} // namespace

Document::Document(QObject* parent)
    : QObject(parent)
    , m_undo(new QUndoStack(this))
{ }

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

// --- the facades' base ---------------------------------------------------------------------------

const ProjectData& DocumentFacade::data() const
{
    return m_doc->data();
}

void DocumentFacade::push(QUndoCommand* command) const
{
    m_doc->push(command);
}

QString DocumentFacade::uniqueName(const QString& wanted, const std::function<bool(const QString&)>& taken)
{
    const QString base = wanted.trimmed().isEmpty() ? tr("Untitled") : wanted.trimmed();
    if (!taken(base))
        return base;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(base).arg(n);
        if (!taken(candidate))
            return candidate;
    }
}

// --- files ------------------------------------------------------------------------------------

void Document::reset(ProjectData data, const QString& filePath)
{
    m_data = std::move(data);
    // Layers from files of before highlight ids, or made by hand, get theirs now.
    for (HighlightTrack& track : m_data.look.highlights)
        if (track.id == 0)
            track.id = m_data.nextId++;
    m_undo->clear();
    m_undo->setClean();
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
        AnimatedImport animated = readAnimatedBase(meshPath, fps);
        QStringList warnings = std::move(animated.warnings);
        reset(newAnimatedProject(std::move(animated), QFileInfo(meshPath).fileName()));
        return warnings;
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

Gesture Document::beginGesture()
{
    return Gesture(++m_lastGesture);
}

// --- base model --------------------------------------------------------------------------------

void Document::setBaseMesh(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName)
{
    Q_ASSERT(mesh);
    const std::int64_t needed = maxDeformedIndex(m_data);
    if (needed >= mesh->vertexCount())
        throw IoError(meshName,
            tr("has %1 vertices, but the key deformations use vertex %2; "
               "a replacement base model needs the same vertex count and order")
                .arg(mesh->vertexCount())
                .arg(needed));
    const Eigen::Index meshFaces = mesh->faceCount();
    const bool dropFaceSets
        = !m_data.faceSets.empty() && m_data.baseMesh && m_data.baseMesh->faceCount() != mesh->faceCount();
    auto* cmd = new CompositeCommand(this, tr("Replace Base Model"));
    const ChangeSet meshChange = structuralChange(Part::Mesh);
    new PropertyCommand<MeshPtr>(
        this, {}, {Property::BaseMesh}, [](ProjectData& d) { return &d.baseMesh; }, std::move(mesh), meshChange, {},
        cmd);
    new PropertyCommand<QString>(
        this, {}, {Property::BaseMesh}, [](ProjectData& d) { return &d.baseMeshName; }, meshName, meshChange, {}, cmd);
    if (dropFaceSets) {
        // Face indices mean nothing on other faces: the patches go, their layers cover all faces.
        new PropertyCommand<std::vector<algo::FaceSet>>(
            this, {}, {Property::FaceSets}, [](ProjectData& d) { return &d.faceSets; }, {},
            structuralChange(Part::FaceSets), {}, cmd);
        for (const HighlightTrack& track : m_data.look.highlights)
            if (!track.patch.isEmpty()) {
                const ObjectId id = track.id;
                new PropertyCommand<QString>(this, {}, {Property::HighlightPatch, id},
                    fieldOf(id, &HighlightTrack::patch), QString(), ChangeSet::of(Part::Highlights, id), {}, cmd);
            }
    }
    // The depth analysis's per-face say (importance, segment overrides) goes with other faces too.
    if (m_data.baseMesh && m_data.baseMesh->faceCount() != meshFaces) {
        if (!m_data.faceImportance.empty())
            new PropertyCommand<std::vector<float>>(
                this, {}, {Property::FaceValues}, [](ProjectData& d) { return &d.faceImportance; }, {},
                ChangeSet::of(Part::FaceValues), {}, cmd);
        if (!m_data.segmentOverrides.empty())
            new PropertyCommand<std::vector<std::int32_t>>(
                this, {}, {Property::FaceValues}, [](ProjectData& d) { return &d.segmentOverrides; }, {},
                ChangeSet::of(Part::FaceValues), {}, cmd);
    }
    push(cmd);
}

QStringList Document::importBaseMesh(const QString& path)
{
    MeshImport imported = importMesh(path);
    setBaseMesh(std::make_shared<const algo::TriMesh>(std::move(imported.mesh)), QFileInfo(path).fileName());
    return imported.warnings;
}

BlendEvaluator& Document::blender()
{
    m_blender.update(m_data);
    return m_blender;
}

} // namespace celform::model
