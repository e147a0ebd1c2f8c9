// Shading offsets: neighbourhoods, bleeding and the automatic per-segment solve (shading_offsets.h).
#include "celform/algorithms/shading_offsets.h"

#include <algorithm>
#include <cmath>

namespace celform::algo {
namespace {

/// The field interpolated at a pixel, summed in the order the depth analysis sums it
/// (depth_analysis.cpp), so that the ratios predicted here are the ones it will measure.
inline float interpolated(const Faces& faces, std::int32_t f, const Eigen::Vector3f& b, const std::vector<float>& field)
{
    const std::int32_t a = faces(f, 0), c1 = faces(f, 1), c2 = faces(f, 2);
    return b.x() * field[std::size_t(a)] + b.y() * field[std::size_t(c1)] + b.z() * field[std::size_t(c2)];
}

bool validInput(const SegmentOffsetInput& in, std::size_t vertexCount)
{
    if (in.width < 0 || in.height < 0 || !in.faces || !in.neighbours || in.segmentCount < 0)
        return false;
    if (std::size_t(in.neighbours->vertexCount()) != vertexCount)
        return false;
    const std::size_t count = std::size_t(in.width) * std::size_t(in.height);
    if (count > 0 && (!in.faceId || !in.barycentric || !in.baseline || !in.labels))
        return false;
    const Faces& faces = *in.faces;
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int c = 0; c < 3; ++c)
            if (faces(f, c) < 0 || std::size_t(faces(f, c)) >= vertexCount)
                return false;
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t s = in.labels[i];
        if (s < 0)
            continue;
        const std::int32_t f = in.faceId[i];
        if (s >= in.segmentCount || f < 0 || f >= faces.rows() || !std::isfinite(in.baseline[i])
            || !in.barycentric[i].allFinite())
            return false;
    }
    return true;
}

} // namespace

VertexNeighbours buildVertexNeighbours(const Faces& faces, std::int32_t vertexCount)
{
    VertexNeighbours out;
    const std::size_t n = std::size_t(std::max(vertexCount, 0));
    out.start.assign(n + 1, 0);
    auto inRange = [n](std::int32_t v) { return v >= 0 && std::size_t(v) < n; };
    // Each face gives each corner its two other corners; repeats are removed per row afterwards.
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int c = 0; c < 3; ++c) {
            const std::int32_t v = faces(f, c);
            if (!inRange(v))
                continue;
            for (int d = 1; d < 3; ++d)
                if (inRange(faces(f, (c + d) % 3)))
                    ++out.start[std::size_t(v) + 1];
        }
    for (std::size_t v = 0; v < n; ++v)
        out.start[v + 1] += out.start[v];
    std::vector<std::int32_t> all(std::size_t(out.start[n]));
    std::vector<std::int32_t> fill(out.start.begin(), out.start.end() - 1);
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int c = 0; c < 3; ++c) {
            const std::int32_t v = faces(f, c);
            if (!inRange(v))
                continue;
            for (int d = 1; d < 3; ++d) {
                const std::int32_t w = faces(f, (c + d) % 3);
                if (inRange(w))
                    all[std::size_t(fill[std::size_t(v)]++)] = w;
            }
        }
    out.neighbours.reserve(all.size() / 2 + 1);
    std::int32_t written = 0;
    for (std::size_t v = 0; v < n; ++v) {
        const auto begin = all.begin() + out.start[v], end = all.begin() + out.start[v + 1];
        std::sort(begin, end);
        const auto last = std::unique(begin, end);
        out.start[v] = written;
        for (auto it = begin; it != last; ++it)
            if (*it != std::int32_t(v))
                out.neighbours.push_back(*it);
        written = std::int32_t(out.neighbours.size());
    }
    out.start[n] = written;
    return out;
}

void smoothVertexValues(const VertexNeighbours& nb, int rounds, const std::uint8_t* free, std::vector<float>& values,
    std::vector<float>& scratch)
{
    const std::size_t n = values.size();
    if (rounds <= 0 || std::size_t(nb.vertexCount()) != n)
        return;
    scratch.resize(n);
    for (int r = 0; r < rounds; ++r) {
        for (std::size_t v = 0; v < n; ++v) {
            const std::int32_t b = nb.start[v], e = nb.start[v + 1];
            if ((free && !free[v]) || b == e) {
                scratch[v] = values[v];
                continue;
            }
            float sum = 0.f;
            for (std::int32_t k = b; k < e; ++k)
                sum += values[std::size_t(nb.neighbours[std::size_t(k)])];
            scratch[v] = 0.5f * (values[v] + sum / float(e - b));
        }
        values.swap(scratch);
    }
}

void segmentRatios(
    const SegmentOffsetInput& in, const std::vector<float>& field, float threshold, std::vector<float>& ratios)
{
    ratios.assign(std::size_t(std::max(in.segmentCount, 0)), 0.f);
    std::vector<std::int32_t> pixels(ratios.size(), 0);
    const std::size_t count = std::size_t(in.width) * std::size_t(in.height);
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t s = in.labels[i];
        if (s < 0 || s >= in.segmentCount)
            continue;
        ++pixels[std::size_t(s)];
        const float value = in.baseline[i] + interpolated(*in.faces, in.faceId[i], in.barycentric[i], field);
        if (value >= threshold)
            ratios[std::size_t(s)] += 1.f;
    }
    for (std::size_t s = 0; s < ratios.size(); ++s)
        ratios[s] = pixels[s] > 0 ? ratios[s] / float(pixels[s]) : 0.f;
}

bool solveSegmentOffsets(const SegmentOffsetInput& in, const SegmentOffsetSettings& st, std::vector<float>& field,
    SegmentOffsetScratch& sc, SegmentOffsetReport* report)
{
    const std::size_t nv = field.size();
    const bool settingsOk = std::isfinite(st.threshold) && st.percentile >= 0.f && st.percentile <= 1.f
        && st.aggressiveness >= 0.f && st.aggressiveness <= 1.f && st.bleedRounds >= 0 && st.maxIterations >= 0
        && st.limit > 0.f && std::isfinite(st.limit);
    if (!settingsOk || !validInput(in, nv))
        return false;
    for (float v : field)
        if (!std::isfinite(v))
            return false;
    const Faces& faces = *in.faces;
    const std::size_t count = std::size_t(in.width) * std::size_t(in.height);
    const std::size_t ns = std::size_t(in.segmentCount);

    // Vertex to segment: a vote of the pixels of the faces around each vertex, weighted by the
    // pixels' barycentric coordinates (the thesis projects each vertex onto the label image;
    // voting also reaches vertices that fall between pixel centres or just behind a silhouette).
    // Every vote is kept (no fixed number of slots per vertex): the corners' votes are grouped
    // by vertex (counting sort), then each vertex's are summed per segment in place.
    const auto chosen = [&in](std::int32_t s) { return !in.solve || in.solve[s] != 0; };
    sc.voteStart.assign(nv + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
        if (in.labels[i] >= 0)
            for (int c = 0; c < 3; ++c)
                ++sc.voteStart[std::size_t(faces(in.faceId[i], c)) + 1];
    for (std::size_t v = 0; v < nv; ++v)
        sc.voteStart[v + 1] += sc.voteStart[v];
    sc.votes.resize(std::size_t(sc.voteStart[nv]));
    sc.voteCursor.assign(sc.voteStart.begin(), sc.voteStart.end() - 1);
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t s = in.labels[i];
        if (s < 0)
            continue;
        const std::int32_t f = in.faceId[i];
        for (int c = 0; c < 3; ++c) {
            const std::size_t v = std::size_t(faces(f, c));
            sc.votes[std::size_t(sc.voteCursor[v]++)] = {s, std::max(in.barycentric[i][c], 0.f) + 1e-6f};
        }
    }
    std::vector<std::int32_t> localSegment;
    std::vector<std::int32_t>& vertexSegment = report ? report->vertexSegment : localSegment;
    vertexSegment.assign(nv, -1);
    sc.free.assign(nv, 0);
    sc.hasVertices.assign(ns, 0);
    for (std::size_t v = 0; v < nv; ++v) {
        // Sum the vertex's votes per segment at the front of its range (few segments meet at a
        // vertex, so the linear search is short); the first segment to reach the best sum wins.
        auto* begin = sc.votes.data() + sc.voteStart[v];
        auto* const end = sc.votes.data() + sc.voteStart[v + 1];
        auto* distinct = begin;
        for (auto* vote = begin; vote != end; ++vote) {
            auto* same = std::find_if(begin, distinct, [vote](const auto& d) { return d.first == vote->first; });
            if (same == distinct)
                *distinct++ = *vote;
            else
                same->second += vote->second;
        }
        float best = 0.f;
        for (auto* d = begin; d != distinct; ++d)
            if (d->second > best) {
                best = d->second;
                vertexSegment[v] = d->first;
            }
        // A vertex of a segment left alone (not chosen) keeps its value, so that segment's
        // ratio stays as it is.
        if (vertexSegment[v] >= 0 && !chosen(vertexSegment[v]))
            vertexSegment[v] = -1;
        if (vertexSegment[v] >= 0) {
            sc.free[v] = 1;
            sc.hasVertices[std::size_t(vertexSegment[v])] = 1;
        }
    }

    // The pixels of each segment, grouped (counting sort).
    sc.segmentStart.assign(ns + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
        if (in.labels[i] >= 0)
            ++sc.segmentStart[std::size_t(in.labels[i]) + 1];
    for (std::size_t s = 0; s < ns; ++s)
        sc.segmentStart[s + 1] += sc.segmentStart[s];
    sc.segmentPixels.resize(std::size_t(sc.segmentStart[ns]));
    sc.cursor.assign(sc.segmentStart.begin(), sc.segmentStart.end() - 1);
    for (std::size_t i = 0; i < count; ++i)
        if (in.labels[i] >= 0)
            sc.segmentPixels[std::size_t(sc.cursor[std::size_t(in.labels[i])]++)] = std::int32_t(i);
    sc.values.resize(sc.segmentPixels.size());

    // The field as it will be: the kept values, each segment's constant on its vertices, bled.
    auto build = [&]() {
        sc.solved = field;
        for (std::size_t v = 0; v < nv; ++v)
            if (vertexSegment[v] >= 0)
                sc.solved[v] = sc.constants[std::size_t(vertexSegment[v])];
        smoothVertexValues(*in.neighbours, st.bleedRounds, sc.free.data(), sc.solved, sc.smoothing);
    };
    // For segment s: its values under the current field, the cut between dark and bright, and
    // whether the bright count is the wanted one.
    auto cutOf = [&](std::size_t s, float& cut, bool& exact) {
        const std::int32_t b = sc.segmentStart[s], e = sc.segmentStart[s + 1];
        const std::int32_t n = e - b;
        float* values = sc.values.data() + b;
        std::int32_t bright = 0;
        for (std::int32_t k = 0; k < n; ++k) {
            const std::size_t i = std::size_t(sc.segmentPixels[std::size_t(b + k)]);
            values[k] = in.baseline[i] + interpolated(faces, in.faceId[i], in.barycentric[i], sc.solved);
            bright += values[k] >= st.threshold ? 1 : 0;
        }
        const auto dark = std::int32_t(std::lround(double(st.percentile) * double(n)));
        exact = bright == n - dark;
        // The cut lies halfway between the darkest bright pixel and the brightest dark one, so
        // rounding in the analysis's own sums cannot move a pixel across it.
        if (dark <= 0) {
            cut = *std::min_element(values, values + n) - 1e-3f;
        } else if (dark >= n) {
            cut = *std::max_element(values, values + n) + 1e-3f;
        } else {
            std::nth_element(values, values + dark, values + n);
            const float above = values[dark];
            const float below = *std::max_element(values, values + dark);
            cut = 0.5f * (below + above);
        }
    };

    // Start from the thesis's one-shot answer (threshold - quantile of N.L), then iterate.
    sc.constants.assign(ns, 0.f);
    sc.steps.assign(ns, 1.f);
    sc.lastError.assign(ns, 0.f);
    build();
    int iterations = 0;
    bool converged = false;
    for (;;) {
        bool allExact = true;
        float cut = 0.f;
        bool exact = false;
        for (std::size_t s = 0; s < ns; ++s) {
            if (!sc.hasVertices[s] || sc.segmentStart[s + 1] == sc.segmentStart[s])
                continue;
            cutOf(s, cut, exact);
            allExact = allExact && exact;
            if (exact)
                continue;
            const float error = st.threshold - cut;
            // Neighbouring segments pull on each other through the bleeding: halve a step that
            // overshoots, so the coupled iteration settles instead of swinging.
            if (error * sc.lastError[s] < 0.f)
                sc.steps[s] *= 0.5f;
            sc.lastError[s] = error;
            sc.constants[s] = std::clamp(sc.constants[s] + sc.steps[s] * error, -st.limit, st.limit);
        }
        if (allExact) {
            converged = true;
            break;
        }
        if (iterations >= st.maxIterations)
            break;
        ++iterations;
        build();
    }

    if (report) {
        report->constants = sc.constants;
        report->covered = sc.hasVertices;
        report->iterations = iterations;
        report->converged = converged;
        segmentRatios(in, sc.solved, st.threshold, report->ratio);
    }
    // Aggressiveness (figure 4.16): part of the way from the kept values to the solved field.
    const float a = st.aggressiveness;
    for (std::size_t v = 0; v < nv; ++v)
        if (vertexSegment[v] >= 0 || sc.solved[v] != field[v])
            field[v] = a == 1.f ? sc.solved[v] : field[v] + a * (sc.solved[v] - field[v]);
    return true;
}

} // namespace celform::algo
