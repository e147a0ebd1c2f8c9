// Per-vertex shading offsets O_v (paper 3, section 4.3, eq. 4.3: I_d = k_d i_d (L.N + O_v)): the
// vertex neighbourhoods they are smoothed ("bled") over, the painting falloff, and the automatic
// per-segment offsets that give each segment of the depth analysis a chosen bright/dark ratio.
#pragma once

#include "celform/algorithms/mesh_types.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace celform::algo {

/// The distinct neighbours of each vertex over the faces' edges, in compressed rows: the
/// neighbours of v are neighbours[start[v]] .. neighbours[start[v + 1] - 1], ascending.
struct VertexNeighbours {
    std::vector<std::int32_t> start;
    std::vector<std::int32_t> neighbours;
    [[nodiscard]] std::int32_t vertexCount() const { return start.empty() ? 0 : std::int32_t(start.size() - 1); }
};

/// Builds the neighbourhoods of faces (#F by 3) over vertexCount vertices; corners out of range
/// are skipped.
VertexNeighbours buildVertexNeighbours(const Faces& faces, std::int32_t vertexCount);

/// rounds of Laplacian smoothing of per-vertex values (#V): each round every free vertex takes
/// the mean of itself and the mean of its neighbours, v <- (v + mean(n)) / 2 (Jacobi: every vertex
/// reads the previous round). free (#V, may be null: all free) marks the vertices that may change;
/// the others keep their values and still pull on their neighbours. scratch: caller's memory.
void smoothVertexValues(const VertexNeighbours& neighbours, int rounds, const std::uint8_t* free,
    std::vector<float>& values, std::vector<float>& scratch);

/// What automatic per-segment offsets are asked for (paper 3, section 4.3).
struct SegmentOffsetSettings {
    float threshold = 0.5f; ///< the toon threshold the ratio is taken at (N.L + O at or above: bright)
    /// Q in [0, 1]: the fraction of each segment's pixels left dark; the offset moves the Q-quantile
    /// of the segment's N.L onto the threshold (0.5: the median, a 50/50 ratio).
    float percentile = 0.5f;
    /// A in [0, 1]: the result is keep + A (solved - keep) per vertex; with offsets starting at zero
    /// this is the thesis's multiplication of the offset by A (figure 4.16).
    float aggressiveness = 1.f;
    int bleedRounds = 2; ///< rounds of smoothing over the mesh after each solve (figure 4.15)
    int maxIterations = 40; ///< rounds of the constants' fixed-point iteration
    float limit = 2.5f; ///< |constant| bound: N.L + O spans [-1, 1] + threshold well inside it
};

/// One analysed picture, borrowed: pixels row-major, width * height each.
struct SegmentOffsetInput {
    int width = 0;
    int height = 0;
    const std::int32_t* faceId = nullptr; ///< G-buffer face per pixel, < 0 off the model
    const Eigen::Vector3f* barycentric = nullptr; ///< of the face's corners per pixel
    /// N.L per pixel plus whatever offsets are not being solved for (other layers), finite on labelled pixels.
    const float* baseline = nullptr;
    const std::int32_t* labels = nullptr; ///< segment per pixel, < 0 for none
    std::int32_t segmentCount = 0;
    const Faces* faces = nullptr;
    const VertexNeighbours* neighbours = nullptr; ///< of faces, over the field's vertices
    /// Per segment, 1 for the segments to solve (null: all). The others get no vertices and are
    /// left alone, as uncovered ones: thesis 4.3 offsets only the segments the light left with an
    /// undesirable ratio (model::solveAutoOffsets chooses those outside the window by default).
    const std::uint8_t* solve = nullptr;
};

/// Working memory kept between solves so that repeated solves do not allocate.
struct SegmentOffsetScratch {
    std::vector<std::pair<std::int32_t, float>> votes; ///< (segment, weight), grouped by vertex
    std::vector<std::int32_t> voteStart, voteCursor;
    std::vector<std::int32_t> segmentStart, segmentPixels, cursor;
    std::vector<float> values, solved, smoothing, constants, steps, lastError;
    std::vector<std::uint8_t> free, hasVertices;
};

/// What a solve found, for reports and tests.
struct SegmentOffsetReport {
    std::vector<std::int32_t> vertexSegment; ///< per vertex, -1 for none
    std::vector<float> constants; ///< per segment: the solved constant c_s before bleeding
    std::vector<float> ratio; ///< per segment: predicted bright fraction with the solved field (A = 1)
    std::vector<std::uint8_t> covered; ///< per segment: 1 when some vertex belongs to it
    int iterations = 0;
    bool converged = false; ///< every covered segment within one pixel of 1 - Q
};

/// Automatic per-segment offsets (paper 3, section 4.3). Each vertex belongs to the segment whose
/// pixels, over the faces around it, vote for it most (each pixel votes for its face's three
/// corners with their barycentric weights), so vertices hidden between pixel centres count too;
/// vertices no labelled pixel sees belong to none and keep their value. Every segment's votes
/// count, however many segments meet at a vertex. Every segment s gets a
/// constant c_s on its vertices; the field is bled over the mesh (smoothVertexValues, segment
/// vertices free); and since bleeding and the per-pixel interpolation change what each pixel
/// gets, the constants are iterated: c_s += threshold - cut_s, cut_s being the value halfway
/// between the k-th and (k+1)-th smallest N.L + interpolated field over the segment's pixels,
/// k = round(Q * pixels), until every segment has exactly pixels - k bright pixels (a step halves
/// when its error changes sign). A segment no vertex belongs to is left alone (the thesis: "unless
/// the segment is not covered by vertices").
/// field (#V) holds the current values on entry (kept where no segment reaches) and the result
/// keep + A (solved - keep) on return. Returns false, field untouched, when sizes disagree,
/// values are not finite or a setting is out of range.
bool solveSegmentOffsets(const SegmentOffsetInput& input, const SegmentOffsetSettings& settings,
    std::vector<float>& field, SegmentOffsetScratch& scratch, SegmentOffsetReport* report = nullptr);

/// The bright fraction of each segment for a field: N.L + O at or above threshold, O interpolated
/// as the depth analysis interpolates it. ratios gets segmentCount entries (0 for empty segments).
void segmentRatios(
    const SegmentOffsetInput& input, const std::vector<float>& field, float threshold, std::vector<float>& ratios);

} // namespace celform::algo
