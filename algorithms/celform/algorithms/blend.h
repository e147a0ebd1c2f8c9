// Shape blending (paper 1, section 3.2.3): shape = base + sum of w'_i * offset_i, with sparse
// per-key offsets.
#pragma once

#include "celform/algorithms/tri_mesh.h"

#include <cstdint>
#include <vector>

namespace celform::algo {

/// A key's offsets as views into its storage: count strictly increasing vertex indices and as
/// many float xyz offsets. Dense offsets have count == #V and indices 0..#V-1 (indices may then
/// be null).
struct OffsetsView {
    const std::uint32_t* indices = nullptr;
    const float* offsets = nullptr; ///< 3 * count floats
    std::size_t count = 0;
    bool dense = false;
};

struct WeightedOffsets {
    OffsetsView offsets;
    float weight = 0.f;
};

/// out = base + sum weight_i * offsets_i. out is resized to base's size; base and out must not
/// alias. Memory-bound: runs within about 2x of a memcpy of the same bytes.
void blendShape(const Positions& base, const std::vector<WeightedOffsets>& keys, Positions& out);

} // namespace celform::algo
