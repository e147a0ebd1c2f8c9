// Stable segment numbers along a shot (issue 26, "stable segments"): a segment keeps its number
// from frame to frame as long as it covers the same part of the model. Segments are identified
// through the mesh faces they cover (the per-face vote the automatic offsets use, thesis 4.3),
// not by the scan order labelSegments numbers them in.
#pragma once

#include "celform/algorithms/segments.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace celform::model {

class SegmentTracker {
public:
    /// The stable number of each segment of the next frame: labels as labelSegments gives them,
    /// faces the face id of each pixel (the G-buffer's, -1 off the model). A segment takes the
    /// number of the previous frame's segment that most of its pixels' faces belonged to, when
    /// that covers at least a quarter of its pixels and no larger segment took it first; else a
    /// new number.
    const std::vector<int>& track(const algo::SegmentLabels& labels, const std::vector<std::int32_t>& faces);
    /// Of this frame's segment pixels whose face was in a segment in the previous frame, the share
    /// whose segment has that segment's number (1 for the first frame): the stability,
    /// averaged over segments weighted by pixels.
    [[nodiscard]] double stability() const { return m_stability; }
    /// The pixels the last stability() counted (0 for the first frame).
    [[nodiscard]] std::int64_t comparedPixels() const { return m_compared; }

private:
    std::unordered_map<std::int32_t, int> m_owner; ///< face -> its segment's number in the previous frame
    std::vector<int> m_ids;
    int m_next = 0;
    double m_stability = 1.0;
    std::int64_t m_compared = 0;
};

} // namespace celform::model
