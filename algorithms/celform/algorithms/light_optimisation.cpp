// The light optimisation of paper 3 (light_optimisation.h).
#include "celform/algorithms/light_optimisation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

namespace celform::algo {
namespace {

template <typename T> void resizeTo(std::vector<T>& v, std::size_t n)
{
    if (v.size() != n)
        v.resize(n);
}

/// A uniform double in [-1, 1) from the generator's raw bits: std::uniform_real_distribution is
/// not specified bit for bit, the engine is, so runs repeat on every platform.
double symmetricUnit(std::mt19937_64& rng)
{
    return double(rng() >> 11) * 0x1.0p-52 - 1.0;
}

Eigen::Vector3d randomInCube(std::mt19937_64& rng)
{
    const double x = symmetricUnit(rng);
    const double y = symmetricUnit(rng);
    const double z = symmetricUnit(rng);
    return {x, y, z};
}

/// Thesis 5.0.3's weight (figure 5.9) times the segment's importance: thesis 6.2 leaves "all
/// segments are equally important" open and proposes focal points an artist specifies.
double segmentWeight(const ShadingSamples& samples, int s, double totalPixels, SegmentWeight weight)
{
    const double importance = std::size_t(s) < samples.importance.size() ? samples.importance[std::size_t(s)] : 1.0;
    return importance * (weight == SegmentWeight::Area ? double(samples.pixels(s)) / totalPixels : 1.0);
}

/// How far a ratio is outside the window (0 inside).
double windowDistance(double ratio, const RatioWindow& window)
{
    return std::max({0.0, double(window.low) - ratio, ratio - double(window.high)});
}

/// A light is usable when finite and, for a direction, not zero.
bool normalise(LightPose& light)
{
    if (!light.vector.allFinite())
        return false;
    if (light.point)
        return true;
    const double n = light.vector.norm();
    if (!(n > 1e-12))
        return false;
    light.vector /= n;
    return true;
}

std::vector<float> ratios(const ShadingSamples& samples, const LightEvaluation& e)
{
    std::vector<float> out(std::size_t(samples.segmentCount()), 0.f);
    for (int s = 0; s < samples.segmentCount(); ++s)
        if (samples.pixels(s) > 0)
            out[std::size_t(s)] = float(e.bright[std::size_t(s)]) / float(samples.pixels(s));
    return out;
}

/// Listing 4.3 as the text of 4.1.2-4.1.3 means it (the listing as printed loops while the error
/// is *below* the margin, never resets its sum, and takes position - light where eq. 4.2 needs
/// the vector from the surface to the light): per segment outside the window, its summed
/// gradient normalised, pointing towards brighter when the segment is too dark and away when
/// too bright, weighted by its size class and figure 5.8's fall-off; the sum's direction.
Eigen::Vector3d descentDirection(
    const ShadingSamples& samples, const LightEvaluation& e, const LightOptimisationSettings& settings)
{
    const double total = double(samples.segmentStart.empty() ? 0 : samples.segmentStart.back());
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    for (int s = 0; s < samples.segmentCount(); ++s) {
        const std::int32_t pixels = samples.pixels(s);
        if (pixels == 0)
            continue;
        const double ratio = double(e.bright[std::size_t(s)]) / double(pixels);
        const double distance = windowDistance(ratio, settings.window);
        const double norm = e.gradient[std::size_t(s)].norm();
        if (distance <= 0.0 || !(norm > 0.0))
            continue;
        const double falloff = settings.falloff > 0.0 ? std::min(1.0, distance / settings.falloff) : 1.0;
        const double sign = ratio < double(settings.window.low) ? 1.0 : -1.0;
        direction
            += (sign * falloff * segmentWeight(samples, s, total, settings.weight) / norm) * e.gradient[std::size_t(s)];
    }
    return direction;
}

/// The light moved by step along the unit direction: a direction turns (and stays unit), a
/// position moves by step model radii.
LightPose moved(const LightPose& light, const Eigen::Vector3d& direction, double step, double scale)
{
    LightPose next = light;
    next.vector += (light.point ? step * scale : step) * direction;
    return next;
}

} // namespace

void gatherShadingSamples(const GBuffer& g, const std::vector<Eigen::Vector3f>& normals, const SegmentLabels& segments,
    const Faces& faces, const std::vector<float>* offsets, float toonThreshold, ShadingSamples& out)
{
    const std::size_t count = std::size_t(g.width) * std::size_t(g.height);
    const int segmentCount = int(segments.sizes.size());
    const bool sized = segments.labels.size() == count && normals.size() == count && g.faceId.size() == count
        && g.position.size() == count && g.barycentric.size() == count;
    resizeTo(out.segmentStart, std::size_t(segmentCount) + 1);
    resizeTo(out.normalSum, std::size_t(segmentCount));
    out.importance.assign(std::size_t(segmentCount), 1.0);
    std::fill(out.normalSum.begin(), out.normalSum.end(), Eigen::Vector3d::Zero());
    // Counting sort of the segment pixels by segment, in scan order within each.
    std::fill(out.segmentStart.begin(), out.segmentStart.end(), 0);
    if (sized)
        for (std::size_t i = 0; i < count; ++i)
            if (segments.labels[i] >= 0 && segments.labels[i] < segmentCount)
                ++out.segmentStart[std::size_t(segments.labels[i]) + 1];
    for (int s = 0; s < segmentCount; ++s)
        out.segmentStart[std::size_t(s) + 1] += out.segmentStart[std::size_t(s)];
    const std::size_t total = std::size_t(out.segmentStart.back());
    for (std::vector<float>* v : {&out.nx, &out.ny, &out.nz, &out.px, &out.py, &out.pz, &out.threshold})
        resizeTo(*v, total);
    if (!sized)
        return;
    std::vector<std::int32_t>& cursor = out.cursor;
    cursor.assign(out.segmentStart.begin(), out.segmentStart.end() - 1);
    auto vertexOffset = [offsets](std::int32_t v) {
        return offsets && std::size_t(v) < offsets->size() ? (*offsets)[std::size_t(v)] : 0.f;
    };
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t s = segments.labels[i];
        const std::int32_t f = g.faceId[i];
        if (s < 0 || s >= segmentCount)
            continue;
        const std::size_t k = std::size_t(cursor[std::size_t(s)]++);
        const Eigen::Vector3f& n = normals[i];
        out.nx[k] = n.x();
        out.ny[k] = n.y();
        out.nz[k] = n.z();
        out.px[k] = g.position[i].x();
        out.py[k] = g.position[i].y();
        out.pz[k] = g.position[i].z();
        float offset = 0.f;
        if (offsets && f >= 0 && f < faces.rows()) {
            // The same sum, in the same order, as algo::analyseDepth's.
            const Eigen::Vector3f b = g.barycentric[i];
            offset = b.x() * vertexOffset(faces(f, 0)) + b.y() * vertexOffset(faces(f, 1))
                + b.z() * vertexOffset(faces(f, 2));
        }
        out.threshold[k] = toonThreshold - offset;
        out.normalSum[std::size_t(s)] += n.cast<double>();
    }
}

void evaluateLight(const ShadingSamples& samples, const LightPose& light, const LightOptimisationSettings& settings,
    bool gradients, LightEvaluation& out)
{
    const int segmentCount = samples.segmentCount();
    resizeTo(out.bright, std::size_t(segmentCount));
    resizeTo(out.gradient, std::size_t(segmentCount));
    const float* nx = samples.nx.data();
    const float* ny = samples.ny.data();
    const float* nz = samples.nz.data();
    const float* t = samples.threshold.data();
    double total = 0.0;
    for (int s = 0; s < segmentCount; ++s)
        total += double(samples.pixels(s));
    out.objective = 0.0;
    for (int s = 0; s < segmentCount; ++s) {
        const std::int32_t begin = samples.segmentStart[std::size_t(s)];
        const std::int32_t end = samples.segmentStart[std::size_t(s) + 1];
        std::int32_t bright = 0;
        Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
        if (!light.point) {
            // N.L with a unit L is the same for the whole light; eq. 4.2 with |l| = 1 summed over
            // the segment is (sum n) - (l . sum n) l.
            const Eigen::Vector3d l = light.vector.normalized();
            const float lx = float(l.x()), ly = float(l.y()), lz = float(l.z());
            for (std::int32_t i = begin; i < end; ++i)
                bright += (nx[i] * lx + ny[i] * ly + nz[i] * lz >= t[i]) ? 1 : 0;
            if (gradients) {
                const Eigen::Vector3d& n = samples.normalSum[std::size_t(s)];
                gradient = n - l.dot(n) * l;
            }
        } else {
            const float lx = float(light.vector.x()), ly = float(light.vector.y()), lz = float(light.vector.z());
            const float* px = samples.px.data();
            const float* py = samples.py.data();
            const float* pz = samples.pz.data();
            float gx = 0.f, gy = 0.f, gz = 0.f;
            for (std::int32_t i = begin; i < end; ++i) {
                // l runs from the surface point to the light (eq. 4.2, listing 4.5).
                const float dx = lx - px[i], dy = ly - py[i], dz = lz - pz[i];
                const float nl = nx[i] * dx + ny[i] * dy + nz[i] * dz;
                const float ll = dx * dx + dy * dy + dz * dz;
                const float len = std::sqrt(ll);
                // N.L >= t with L = l / |l|, multiplied out (|l| > 0 unless the light sits on
                // the surface, where nothing is bright).
                bright += (len > 0.f && nl >= t[i] * len) ? 1 : 0;
                if (gradients && ll > 0.f) {
                    const float a = nl / ll, inv = 1.f / len;
                    gx += (nx[i] - a * dx) * inv;
                    gy += (ny[i] - a * dy) * inv;
                    gz += (nz[i] - a * dz) * inv;
                }
            }
            gradient = {double(gx), double(gy), double(gz)};
        }
        out.bright[std::size_t(s)] = bright;
        out.gradient[std::size_t(s)] = gradient;
        const std::int32_t pixels = end - begin;
        if (pixels > 0)
            out.objective += segmentWeight(samples, s, total, settings.weight)
                * windowDistance(double(bright) / double(pixels), settings.window);
    }
}

LightOptimisationResult optimiseLight(const ShadingSamples& samples, const LightPose& start,
    const LightOptimisationSettings& settings, LightOptimisationWorkspace& work, Progress* progress)
{
    LightOptimisationResult result;
    LightPose light = start;
    result.before = start;
    if (!normalise(light)) {
        result.after = start;
        return result;
    }
    const bool gradients = settings.method == LightMethod::Gradient;
    evaluateLight(samples, light, settings, gradients, work.current);
    result.objectiveBefore = work.current.objective;
    result.ratioBefore = ratios(samples, work.current);
    LightPose best = light;
    work.best.bright = work.current.bright;
    work.best.objective = work.current.objective;
    const int iterations = std::max(0, settings.iterations);
    result.iterations.reserve(std::size_t(iterations));

    std::mt19937_64 rng(settings.seed);
    // Gradient: 5.0.2's schedule. Annealing: listing 4.2 starts at 1 and shrinks by 0.95; the text
    // ("reduce the offset size in every iteration") shrinks every iteration, the listing only
    // after accepted ones and compares against an error it never updates: the text is followed.
    double step = gradients ? settings.initialStep : 1.0;
    const double factor = gradients ? settings.stepFactor : 0.95;
    for (int it = 0; it < iterations && work.best.objective > 0.0; ++it) {
        LightIteration record;
        LightPose candidate = light;
        bool usable = false;
        switch (settings.method) {
        case LightMethod::Gradient: {
            const Eigen::Vector3d direction = descentDirection(samples, work.current, settings);
            const double norm = direction.norm();
            if (!(norm > 0.0))
                break;
            candidate = moved(light, direction / norm, step, settings.scale);
            usable = normalise(candidate);
            record.step = step;
            break;
        }
        case LightMethod::Annealing:
            candidate = moved(light, randomInCube(rng), step, settings.scale);
            usable = normalise(candidate);
            record.step = step;
            break;
        case LightMethod::Random:
            // Listing 4.1 draws positions in the unit cube of a model of radius 1: here a
            // direction uniform on the sphere, or a position up to two radii from the centre
            // and outside the model's bounding sphere (a light inside the model lights nothing
            // the camera sees).
            for (int tries = 0; tries < 64 && !usable; ++tries) {
                const Eigen::Vector3d u = randomInCube(rng);
                const double n = u.norm();
                if (!candidate.point) {
                    candidate.vector = u;
                    usable = n <= 1.0 && normalise(candidate);
                } else {
                    candidate.vector = settings.centre + 2.0 * settings.scale * u;
                    usable = n >= 0.5;
                }
            }
            break;
        }
        if (usable) {
            evaluateLight(samples, candidate, settings, gradients, work.candidate);
            record.tried = work.candidate.objective;
            record.ratios = ratios(samples, work.candidate);
            // Gradient: the thesis moves the light every iteration until it settles at a fixed point
            // (4.1.3, 5.0.2); a segment whose ratio sits at 0 or 1 pulls before its ratio can
            // answer, so single steps may make the sum worse on the way. Annealing (listing 4.2)
            // keeps only positions that are not worse; random keeps only better ones.
            const bool move = settings.method == LightMethod::Gradient
                || (settings.method == LightMethod::Annealing && work.candidate.objective <= work.current.objective)
                || (settings.method == LightMethod::Random && work.candidate.objective < work.current.objective);
            if (move) {
                light = candidate;
                std::swap(work.current, work.candidate);
            }
            // The answer is the best light met: its objective never rises from one accepted
            // iteration to the next.
            if (work.current.objective < work.best.objective || (move && settings.method == LightMethod::Annealing)) {
                best = light;
                work.best.bright = work.current.bright;
                work.best.objective = work.current.objective;
                record.accepted = true;
            }
        }
        record.objective = work.best.objective;
        record.light = best.vector;
        result.iterations.push_back(record);
        step *= factor;
        report(progress, it + 1, iterations);
        if (cancelRequested(progress)) {
            result.cancelled = true;
            result.after = start;
            result.ratioAfter = result.ratioBefore;
            result.objectiveAfter = result.objectiveBefore;
            return result;
        }
        if (settings.method == LightMethod::Gradient && !usable)
            break; // no segment outside the window has a gradient: nothing moves the light
    }
    result.after = best;
    result.objectiveAfter = work.best.objective;
    result.ratioAfter = ratios(samples, work.best);
    return result;
}

} // namespace celform::algo
