// Look-ups and comparison of the project data.
#include "celform/model/project_data.h"

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {
template <typename Vec> auto* findById(Vec& items, ObjectId id)
{
    auto it = std::find_if(items.begin(), items.end(), [id](const auto& x) { return x.id == id; });
    return it == items.end() ? nullptr : &*it;
}
template <typename Vec> auto* findByName(Vec& items, const QString& name)
{
    auto it = std::find_if(items.begin(), items.end(), [&name](const auto& x) { return x.name == name; });
    return it == items.end() ? nullptr : &*it;
}
} // namespace

const Drawing* ProjectData::drawing(ObjectId id) const
{
    return findById(drawings, id);
}
Drawing* ProjectData::drawing(ObjectId id)
{
    return findById(drawings, id);
}
const KeyViewpoint* ProjectData::key(ObjectId id) const
{
    return findById(keys, id);
}
KeyViewpoint* ProjectData::key(ObjectId id)
{
    return findById(keys, id);
}
const KeyViewpoint* ProjectData::keyByName(const QString& name) const
{
    return findByName(keys, name);
}
const Drawing* ProjectData::drawingByName(const QString& name) const
{
    return findByName(drawings, name);
}

Eigen::Vector3f SparseOffsets::at(std::uint32_t index) const
{
    const auto it = std::lower_bound(indices.begin(), indices.end(), index);
    if (it == indices.end() || *it != index)
        return Eigen::Vector3f::Zero();
    return deltas[std::size_t(it - indices.begin())];
}

void SparseOffsets::assign(const std::vector<std::uint32_t>& changed, const std::vector<Eigen::Vector3f>& values,
    const std::vector<char>& present)
{
    // One merge pass of two ascending lists: O(n + m), no per-vertex insertion into the middle.
    std::vector<std::uint32_t> mergedIndices;
    std::vector<Eigen::Vector3f> mergedDeltas;
    mergedIndices.reserve(indices.size() + changed.size());
    mergedDeltas.reserve(indices.size() + changed.size());
    std::size_t i = 0, j = 0;
    while (i < indices.size() || j < changed.size()) {
        if (j == changed.size() || (i < indices.size() && indices[i] < changed[j])) {
            mergedIndices.push_back(indices[i]);
            mergedDeltas.push_back(deltas[i]);
            ++i;
            continue;
        }
        if (i < indices.size() && indices[i] == changed[j])
            ++i; // replaced (or removed) by the change
        if (present[j]) {
            mergedIndices.push_back(changed[j]);
            mergedDeltas.push_back(values[j]);
        }
        ++j;
    }
    indices = std::move(mergedIndices);
    deltas = std::move(mergedDeltas);
}

SparseOffsets SparseOffsets::difference(const algo::Positions& shape, const algo::Positions& base)
{
    SparseOffsets result;
    for (Eigen::Index v = 0; v < std::min(shape.rows(), base.rows()); ++v) {
        const Eigen::Vector3f d = shape.row(v) - base.row(v);
        if (d != Eigen::Vector3f::Zero()) {
            result.indices.push_back(std::uint32_t(v));
            result.deltas.push_back(d);
        }
    }
    return result;
}

const SparseOffsets* ProjectData::offsetsAt(const KeyViewpoint& key, int frame)
{
    if (key.offsetsByFrame.empty())
        return nullptr;
    auto it = key.offsetsByFrame.upper_bound(frame);
    if (it == key.offsetsByFrame.begin())
        return &it->second;
    return &std::prev(it)->second;
}

algo::Positions ProjectData::keyShape(const KeyViewpoint& key, int frame) const
{
    Q_ASSERT(baseMesh);
    algo::Positions shape = baseMesh->vertices;
    if (const SparseOffsets* offsets = offsetsAt(key, frame))
        for (std::size_t i = 0; i < offsets->indices.size(); ++i)
            shape.row(offsets->indices[i]) += offsets->deltas[i].transpose();
    return shape;
}

ProjectData newProject(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName)
{
    ProjectData data;
    if (mesh) {
        // Strokes about 1.5% of the model apart read as hatching at any model scale.
        const double diagonal = algo::boundingBox(mesh->vertices).diagonal().norm();
        if (diagonal > 0 && std::isfinite(diagonal))
            data.look.hatch.spacing = float(0.015 * diagonal);
    }
    data.baseMesh = std::move(mesh);
    data.baseMeshName = meshName;
    return data;
}

bool ProjectData::operator==(const ProjectData& o) const
{
    const bool meshEqual = (!baseMesh && !o.baseMesh) || (baseMesh && o.baseMesh && *baseMesh == *o.baseMesh);
    return meshEqual && baseMeshName == o.baseMeshName && drawings == o.drawings && keys == o.keys && blend == o.blend
        && look == o.look && nextId == o.nextId;
}

} // namespace celform::model
