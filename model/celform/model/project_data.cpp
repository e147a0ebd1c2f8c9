// Look-ups and comparison of the project data.
#include "celform/model/project_data.h"

#include <algorithm>

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

bool ProjectData::operator==(const ProjectData& o) const
{
    const bool meshEqual = (!baseMesh && !o.baseMesh) || (baseMesh && o.baseMesh && *baseMesh == *o.baseMesh);
    return meshEqual && baseMeshName == o.baseMeshName && drawings == o.drawings && keys == o.keys && blend == o.blend
        && look == o.look && nextId == o.nextId;
}

} // namespace celform::model
