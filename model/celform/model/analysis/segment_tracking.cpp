// Stable segment numbers along a shot (segment_tracking.h).
#include "celform/model/analysis/segment_tracking.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace celform::model {

const std::vector<int>& SegmentTracker::track(const algo::SegmentLabels& labels, const std::vector<std::int32_t>& faces)
{
    const std::size_t segments = labels.sizes.size();
    const std::size_t pixels = std::min(labels.labels.size(), faces.size());
    // Per segment, the votes of its pixels for the previous frame's numbers (through their faces),
    // and per face, its pixels in each segment of this frame.
    std::vector<std::map<int, std::int64_t>> votes(segments);
    std::unordered_map<std::int32_t, std::map<int, std::int64_t>> byFace;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::int32_t label = labels.labels[i], face = faces[i];
        if (label < 0 || face < 0)
            continue;
        ++byFace[face][label];
        if (const auto it = m_owner.find(face); it != m_owner.end())
            ++votes[std::size_t(label)][it->second];
    }
    // Greedy matching, the largest votes first: each previous number goes to one segment.
    std::vector<std::tuple<std::int64_t, int, int>> candidates; // votes, segment, previous number
    for (std::size_t s = 0; s < segments; ++s)
        for (const auto& [number, count] : votes[s])
            if (4 * count >= std::int64_t(labels.sizes[s]))
                candidates.emplace_back(count, int(s), number);
    std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a > b; });
    m_ids.assign(segments, -1);
    std::vector<int> taken;
    for (const auto& [count, segment, number] : candidates) {
        if (m_ids[std::size_t(segment)] >= 0 || std::find(taken.begin(), taken.end(), number) != taken.end())
            continue;
        m_ids[std::size_t(segment)] = number;
        taken.push_back(number);
    }
    for (int& id : m_ids)
        if (id < 0)
            id = m_next++;

    // Stability: pixels whose face's number in the previous frame is their segment's number now.
    std::int64_t same = 0;
    m_compared = 0;
    for (std::size_t s = 0; s < segments; ++s)
        for (const auto& [number, count] : votes[s]) {
            m_compared += count;
            if (number == m_ids[s])
                same += count;
        }
    m_stability = m_compared > 0 ? double(same) / double(m_compared) : 1.0;

    // Each face belongs to the segment most of its pixels are in, for the next frame.
    m_owner.clear();
    for (const auto& [face, counts] : byFace) {
        const auto best = std::max_element(
            counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
        m_owner[face] = m_ids[std::size_t(best->first)];
    }
    return m_ids;
}

} // namespace celform::model
