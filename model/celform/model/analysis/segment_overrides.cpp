// The segment brush's edits (segment_overrides.h).
#include "celform/model/analysis/segment_overrides.h"

#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>

#include <algorithm>
#include <limits>
#include <set>

namespace celform::model {
namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("celform::model::Document", text);
}

std::vector<std::int32_t> startingOverrides(const ProjectData& data)
{
    const std::size_t faces = data.baseMesh ? std::size_t(data.baseMesh->faceCount()) : 0;
    if (data.segmentOverrides.size() == faces)
        return data.segmentOverrides;
    return std::vector<std::int32_t>(faces, kNoSegmentOverride);
}

void refuseSegment(const SegmentPicture& picture, int segment)
{
    if (segment < 0 || std::size_t(segment) >= picture.segments.sizes.size())
        throw EditRefused(
            tr("There is no segment %1 in this picture (it has %2).").arg(segment).arg(picture.segments.sizes.size()));
}

/// Per face whether it belongs to one of the segments: by the vote, or through an override label
/// one of its voted faces carries (so the faces of an override group hidden in this view follow).
std::vector<char> groupOf(
    const SegmentPicture& picture, const std::vector<std::int32_t>& overrides, const std::vector<int>& segments)
{
    std::vector<char> in(overrides.size(), 0);
    std::set<std::int32_t> labels;
    for (std::size_t f = 0; f < overrides.size() && f < picture.owner.size(); ++f)
        if (std::find(segments.begin(), segments.end(), picture.owner[f]) != segments.end()) {
            in[f] = 1;
            if (overrides[f] != kNoSegmentOverride)
                labels.insert(overrides[f]);
        }
    for (std::size_t f = 0; f < overrides.size(); ++f)
        if (overrides[f] != kNoSegmentOverride && labels.count(overrides[f]))
            in[f] = 1;
    return in;
}

std::int32_t nextLabel(const std::vector<std::int32_t>& overrides)
{
    std::int32_t next = 0;
    for (const std::int32_t l : overrides)
        next = std::max(next, l + 1);
    return next;
}

} // namespace

void voteSegmentFaces(SegmentPicture& picture, std::int32_t faceCount)
{
    const bool sized = picture.faces.size() == picture.segments.labels.size();
    algo::faceSegmentVote(picture.segments, sized ? picture.faces.data() : nullptr, faceCount, picture.owner);
}

std::vector<std::int32_t> mergedSegmentOverrides(
    const ProjectData& data, const SegmentPicture& picture, const std::vector<int>& segments)
{
    for (const int s : segments)
        refuseSegment(picture, s);
    if (std::set<int>(segments.begin(), segments.end()).size() < 2)
        throw EditRefused(tr("A merge needs two different segments."));
    std::vector<std::int32_t> overrides = startingOverrides(data);
    const std::vector<char> in = groupOf(picture, overrides, segments);
    const std::int32_t label = nextLabel(overrides);
    for (std::size_t f = 0; f < overrides.size(); ++f)
        if (in[f])
            overrides[f] = label;
    compactSegmentOverrides(overrides);
    return overrides;
}

std::vector<std::int32_t> splitSegmentOverrides(const ProjectData& data, const SegmentPicture& picture, int segment,
    const std::vector<Eigen::Vector2d>& stroke, const algo::Positions& shape, const algo::RasterCamera& camera)
{
    refuseSegment(picture, segment);
    if (stroke.size() < 2)
        throw EditRefused(tr("A split needs a stroke of at least two points."));
    std::vector<std::int32_t> overrides = startingOverrides(data);
    const std::vector<char> in = groupOf(picture, overrides, {segment});
    const algo::TriMesh& mesh = *data.baseMesh;
    const std::int32_t left = nextLabel(overrides), right = left + 1;
    std::int64_t counts[2] = {0, 0};
    for (std::size_t f = 0; f < overrides.size(); ++f) {
        if (!in[f] || Eigen::Index(f) >= mesh.faceCount())
            continue;
        const Eigen::Index i = Eigen::Index(f);
        const Eigen::Vector3d centroid
            = (shape.row(mesh.faces(i, 0)) + shape.row(mesh.faces(i, 1)) + shape.row(mesh.faces(i, 2)))
                  .transpose()
                  .cast<double>()
            / 3.0;
        const Eigen::Vector2d p = camera.project(centroid).head<2>();
        // The side of the nearest piece of the stroke (its sign of the cross product).
        double nearest = std::numeric_limits<double>::infinity();
        double side = 0.0;
        for (std::size_t k = 0; k + 1 < stroke.size(); ++k) {
            const Eigen::Vector2d a = stroke[k], d = stroke[k + 1] - stroke[k];
            const double length2 = d.squaredNorm();
            const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
            const double distance = (a + t * d - p).squaredNorm();
            if (length2 > 0.0 && distance < nearest) {
                nearest = distance;
                side = d.x() * (p - a).y() - d.y() * (p - a).x();
            }
        }
        const bool onLeft = side < 0.0;
        overrides[f] = onLeft ? left : right;
        ++counts[onLeft ? 0 : 1];
    }
    if (counts[0] == 0 || counts[1] == 0)
        throw EditRefused(tr("The stroke does not cross segment %1: its faces all lie on one side.").arg(segment));
    compactSegmentOverrides(overrides);
    return overrides;
}

std::vector<std::int32_t> releasedSegmentOverrides(
    const ProjectData& data, const SegmentPicture& picture, const std::vector<int>& segments)
{
    for (const int s : segments)
        refuseSegment(picture, s);
    std::vector<std::int32_t> overrides = startingOverrides(data);
    const std::vector<char> in = groupOf(picture, overrides, segments);
    for (std::size_t f = 0; f < overrides.size(); ++f)
        if (in[f])
            overrides[f] = kNoSegmentOverride;
    compactSegmentOverrides(overrides);
    return overrides;
}

void compactSegmentOverrides(std::vector<std::int32_t>& overrides)
{
    std::vector<std::int32_t> number;
    std::int32_t next = 0;
    bool any = false;
    for (std::int32_t& l : overrides) {
        if (l < 0) {
            l = kNoSegmentOverride;
            continue;
        }
        if (std::size_t(l) >= number.size())
            number.resize(std::size_t(l) + 1, -1);
        if (number[std::size_t(l)] < 0)
            number[std::size_t(l)] = next++;
        l = number[std::size_t(l)];
        any = true;
    }
    if (!any)
        overrides.clear();
}

std::vector<std::int64_t> segmentOverrideSizes(const std::vector<std::int32_t>& overrides)
{
    std::vector<std::int64_t> sizes;
    for (const std::int32_t l : overrides)
        if (l >= 0) {
            if (std::size_t(l) >= sizes.size())
                sizes.resize(std::size_t(l) + 1, 0);
            ++sizes[std::size_t(l)];
        }
    return sizes;
}

} // namespace celform::model
