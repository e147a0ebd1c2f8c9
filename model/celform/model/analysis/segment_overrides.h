// The segment brush (paper 3, 6.2: "a brush tool can be provided that allows artists to manually
// select segments"; issue 26): merges of segments and splits along a stroke, as per-face override
// labels (ProjectData::segmentOverrides) that the depth analysis regroups its segments by
// (algo::applySegmentOverrides). The edits are computed here from an analysed picture, off the
// document; FaceSetEdits::setSegmentOverrides stores them as one undo step.
#pragma once

#include "celform/algorithms/raster.h"
#include "celform/algorithms/segments.h"
#include "celform/model/data/project_data.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace celform::model {

/// What the edits read of one analysed picture: its segments, the base model's face at each pixel
/// (-1 off the model), and the face vote over them (algo::faceSegmentVote).
struct SegmentPicture {
    algo::SegmentLabels segments;
    std::vector<std::int32_t> faces; ///< per pixel
    std::vector<std::int32_t> owner; ///< per base face: its segment, or -1
};

/// Fills picture.owner from its segments and faces for a base model of faceCount faces.
void voteSegmentFaces(SegmentPicture& picture, std::int32_t faceCount);

/// The overrides with the segments given (numbers of the picture, two or more) made one: their
/// faces by the vote, and every face sharing an override label with one of them, take one new
/// label. Throws EditRefused for a number the picture does not have or fewer than two segments.
[[nodiscard]] std::vector<std::int32_t> mergedSegmentOverrides(
    const ProjectData& data, const SegmentPicture& picture, const std::vector<int>& segments);

/// The overrides with the segment given split along a stroke (a polyline in the picture's pixels,
/// two or more points): its faces by the vote, and every face sharing an override label with them,
/// take one new label on each side of the stroke (each face by its centroid in shape, projected
/// through camera; the side of the nearest piece of the stroke). Throws EditRefused for a number
/// the picture does not have, a stroke of fewer than two points, or one with faces on one side only.
[[nodiscard]] std::vector<std::int32_t> splitSegmentOverrides(const ProjectData& data, const SegmentPicture& picture,
    int segment, const std::vector<Eigen::Vector2d>& stroke, const algo::Positions& shape,
    const algo::RasterCamera& camera);

/// The overrides with the faces of the segments given (by the vote, and those sharing their labels)
/// back to the analysis's own segmentation. Throws EditRefused for a number the picture lacks.
[[nodiscard]] std::vector<std::int32_t> releasedSegmentOverrides(
    const ProjectData& data, const SegmentPicture& picture, const std::vector<int>& segments);

/// Labels renumbered 0, 1, ... in the order of their first face (the file's and the undo
/// step's values stay small); all kNoSegmentOverride becomes empty.
void compactSegmentOverrides(std::vector<std::int32_t>& overrides);

/// Override groups: per label in use, its faces.
[[nodiscard]] std::vector<std::int64_t> segmentOverrideSizes(const std::vector<std::int32_t>& overrides);

} // namespace celform::model
