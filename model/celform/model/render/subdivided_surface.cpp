// The subdivided surface of a project's base model (subdivided_surface.h).
#include "celform/model/render/subdivided_surface.h"

#include "celform/model/render/render_job.h"

#include <QCoreApplication>

#include <list>
#include <mutex>
#include <numeric>

namespace celform::model {
namespace {

/// Bytes per subdivided vertex (stencil rows of about 8 position and 2 x 6 tangent weights with
/// their reach, positions, normals, the renderer's per-vertex arrays) and per face (corners,
/// parent, edges, the renderer's per-face data): measured on the elephant and the dragon with
/// margin.
constexpr qint64 kBytesPerVertex = 400;
constexpr qint64 kBytesPerFace = 100;

/// The number of surfaces kept: a render uses one, an editor session switches between a few.
constexpr std::size_t kCachedSurfaces = 3;

struct CacheEntry {
    std::weak_ptr<const algo::TriMesh> mesh;
    int level = 0;
    std::vector<algo::FaceSet> faceSets;
    std::vector<float> shadingOffsets;
    std::vector<float> faceImportance;
    std::vector<std::int32_t> segmentOverrides;
    std::shared_ptr<const SubdividedSurface> surface;
};

std::shared_ptr<const SubdividedSurface> build(
    const ProjectData& data, int level, std::shared_ptr<const algo::SubdivisionStencil> stencil)
{
    auto s = std::make_shared<SubdividedSurface>();
    const algo::TriMesh& control = *data.baseMesh;
    s->level = level;
    s->stencil = stencil ? std::move(stencil)
                         : std::make_shared<const algo::SubdivisionStencil>(
                             algo::buildSubdivisionStencil(control.faces, std::int32_t(control.vertexCount()), level));
    const algo::SubdivisionStencil& st = *s->stencil;
    auto mesh = std::make_shared<algo::TriMesh>();
    algo::applySubdivision(st, control.vertices, mesh->vertices);
    mesh->faces = st.faces;
    mesh->materials = control.materials;
    if (!control.faceMaterials.empty()) {
        mesh->faceMaterials.resize(st.parentFace.size());
        for (std::size_t f = 0; f < mesh->faceMaterials.size(); ++f)
            mesh->faceMaterials[f] = control.faceMaterials[std::size_t(st.parentFace[f])];
    }
    if (control.hasUvs()) {
        mesh->uvs = algo::subdividedCornerUvs(st, control.uvs, control.uvFaces);
        mesh->uvFaces.resize(mesh->faces.rows(), 3);
        std::iota(mesh->uvFaces.data(), mesh->uvFaces.data() + mesh->uvFaces.size(), 0);
    }
    s->display.baseMesh = std::move(mesh);
    s->display.baseMeshName = data.baseMeshName;
    s->display.look = data.look;
    s->display.mirrorPlane = data.mirrorPlane;
    for (const algo::FaceSet& set : data.faceSets)
        s->display.faceSets.push_back({set.name, algo::subdividedFaceSet(st, set.faces)});
    s->apply(data.shadingOffsets, s->display.shadingOffsets);
    // The depth analysis's per-face say (issue 26): children take their control face's.
    auto perChild = [&st, &control](const auto& values, auto& out) {
        out.clear();
        if (values.size() != std::size_t(control.faceCount()))
            return;
        out.resize(st.parentFace.size());
        for (std::size_t f = 0; f < out.size(); ++f)
            out[f] = values[std::size_t(st.parentFace[f])];
    };
    perChild(data.faceImportance, s->display.faceImportance);
    perChild(data.segmentOverrides, s->display.segmentOverrides);
    return s;
}

} // namespace

void SubdividedSurface::apply(const algo::Positions& shape, algo::Positions& out) const
{
    algo::applySubdivision(*stencil, shape, out);
}

void SubdividedSurface::apply(const std::vector<float>& offsets, std::vector<float>& out) const
{
    if (offsets.empty()) {
        out.clear();
        return;
    }
    algo::applySubdivision(*stencil, offsets, out);
}

qint64 subdivisionBytesNeeded(const algo::TriMesh& mesh, int level)
{
    return algo::subdividedVertexBound(mesh.vertexCount(), mesh.faceCount(), level) * kBytesPerVertex
        + algo::subdividedFaceCount(mesh.faceCount(), level) * kBytesPerFace;
}

QString subdivisionMemoryProblem(const algo::TriMesh& mesh, int level, qint64 extraBytes)
{
    if (level <= 0)
        return {};
    const qint64 needed = subdivisionBytesNeeded(mesh, level);
    const qint64 available = availableRenderMemory() - extraBytes;
    if (needed <= available)
        return {};
    const double gb = 1024.0 * 1024.0 * 1024.0;
    return QCoreApplication::translate("celform::model::RenderJob",
        "subdivision level %1 turns %2 triangles into %3 and needs about %4 GB, more than the %5 GB "
        "available; choose a lower level")
        .arg(level)
        .arg(mesh.faceCount())
        .arg(algo::subdividedFaceCount(mesh.faceCount(), level))
        .arg(double(needed) / gb, 0, 'f', 1)
        .arg(std::max(0.0, double(available) / gb), 0, 'f', 1);
}

std::shared_ptr<const SubdividedSurface> subdividedSurface(const ProjectData& data, int level)
{
    if (level <= 0 || !data.baseMesh)
        return nullptr;
    level = std::min(level, algo::kMaxSubdivisionLevel);
    static std::mutex mutex;
    static std::list<CacheEntry> cache; // most recently used first
    const std::lock_guard<std::mutex> lock(mutex);
    for (auto it = cache.begin(); it != cache.end(); ++it) {
        if (it->mesh.lock() != data.baseMesh || it->level != level)
            continue;
        cache.splice(cache.begin(), cache, it);
        CacheEntry& entry = cache.front();
        if (entry.faceSets != data.faceSets || entry.shadingOffsets != data.shadingOffsets
            || entry.faceImportance != data.faceImportance || entry.segmentOverrides != data.segmentOverrides) {
            entry.surface = build(data, level, entry.surface->stencil);
            entry.faceSets = data.faceSets;
            entry.shadingOffsets = data.shadingOffsets;
            entry.faceImportance = data.faceImportance;
            entry.segmentOverrides = data.segmentOverrides;
        }
        return entry.surface;
    }
    cache.push_front({data.baseMesh, level, data.faceSets, data.shadingOffsets, data.faceImportance,
        data.segmentOverrides, build(data, level, nullptr)});
    while (cache.size() > kCachedSurfaces)
        cache.pop_back();
    return cache.front().surface;
}

} // namespace celform::model
