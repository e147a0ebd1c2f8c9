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

/// Paper 1, section 4.2: key deformations given at some frames are interpolated per vertex with
/// cubic splines. The spline through (knots_i, y_i) is linear in the y_i, so it is the weighted sum
/// S(t) = sum_i w_i y_i; this returns those weights (one per knot) for time t, so that every
/// vertex's offsets share one set of weights. knots strictly increasing (empty: no weights).
/// - natural (periodic false): S'' = 0 at both ends; t before the first knot or after the last
///   holds that knot's value.
/// - periodic (looping cycles): the cycle runs from the first knot to the last, whose value is
///   taken to be the first's (the last key closes the loop and gets weight 0); t wraps modulo
///   knots.back() - knots.front(). With fewer than three knots the first value holds.
/// At a knot the weights are exactly that knot's unit vector (for periodic, the last knot's is
/// the first's).
std::vector<double> splineWeights(const std::vector<double>& knots, double t, bool periodic);

/// out = base + sum weight_i * offsets_i. out is resized to base's size; base and out must not
/// alias. Memory-bound: runs within about 2x of a memcpy of the same bytes.
void blendShape(const Positions& base, const std::vector<WeightedOffsets>& keys, Positions& out);

} // namespace celform::algo
