// Fit Shape to Drawing (fit_shape.h): contour generator, matches along projected normals, and an
// as-rigid-as-possible solve, round after round.
#include "celform/algorithms/fit_shape.h"

#include "celform/algorithms/arap.h"
#include "celform/algorithms/lines.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace celform::algo {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The fields of one round at full resolution.
struct RoundImages {
    int width = 0;
    int height = 0;
    std::vector<float> silhouette; ///< signed distance to the current silhouette's boundary
    const std::vector<float>* outline = nullptr; ///< signed distance to the outline's boundary
};

/// Where a silhouette vertex at x with outward normal n meets the outline: the signed offset s
/// along n of the zero crossing of the outline's distance field nearest to x within radius, or
/// NaN when there is none or the match is rejected (path through another part of the silhouette,
/// or an outline facing away: a fold).
double matchAlongNormal(
    const RoundImages& images, const Eigen::Vector2d& x, const Eigen::Vector2d& n, double radius, double minCosine)
{
    const int w = images.width, h = images.height;
    auto outline = [&](double s) {
        const Eigen::Vector2d p = x + s * n;
        return sampleBilinear(*images.outline, w, h, p.x(), p.y());
    };
    const double f0 = outline(0.0);
    double found = std::numeric_limits<double>::quiet_NaN();
    if (std::abs(f0) < 0.25) {
        found = -f0; // already on the outline (to first order the field is the distance)
    } else {
        const double step = 0.5;
        double previousOut = f0, previousIn = f0;
        // Both directions at once, nearest first; on a tie the side the field points to wins
        // (outside the outline: inwards).
        for (double s = step; s <= radius + 1e-9 && std::isnan(found); s += step) {
            const double out = outline(s), in = outline(-s);
            const bool crossOut = (previousOut > 0.0) != (out > 0.0);
            const bool crossIn = (previousIn > 0.0) != (in > 0.0);
            auto crossing = [&](double fa, double fb, double sa, double sb) { return sa + (sb - sa) * fa / (fa - fb); };
            if (crossOut && crossIn)
                found = f0 > 0.0 ? crossing(previousIn, in, -(s - step), -s) : crossing(previousOut, out, s - step, s);
            else if (crossOut)
                found = crossing(previousOut, out, s - step, s);
            else if (crossIn)
                found = crossing(previousIn, in, -(s - step), -s);
            previousOut = out;
            previousIn = in;
        }
    }
    if (std::isnan(found))
        return found;
    // The path must stay outside the current silhouette when moving out, inside when moving in:
    // otherwise the match belongs to another part (a leg behind a leg, the gap under the trunk).
    const double direction = found > 0.0 ? 1.0 : -1.0;
    for (double s = 1.5; s < std::abs(found) - 0.5; s += 1.0) {
        const Eigen::Vector2d p = x + direction * s * n;
        const double f = sampleBilinear(images.silhouette, w, h, p.x(), p.y());
        if ((direction > 0.0 && f < -0.25) || (direction < 0.0 && f > 0.25))
            return std::numeric_limits<double>::quiet_NaN();
    }
    // The outline at the target must face the same way as the silhouette at the vertex.
    Eigen::Vector2d gradient;
    const Eigen::Vector2d target = x + found * n;
    sampleBilinear(*images.outline, w, h, target.x(), target.y(), &gradient);
    if (gradient.norm() > 1e-9 && gradient.normalized().dot(n) < minCosine)
        return std::numeric_limits<double>::quiet_NaN();
    return found;
}

Eigen::Vector3d reflect(const Eigen::Vector3d& d, const Eigen::Vector3d& normal)
{
    return d - 2.0 * d.dot(normal) * normal;
}

} // namespace

FitShapeResult fitShape(const Positions& shape, const Faces& faces, const EdgeTopology& topology,
    const RasterCamera& cameraIn, const Outline& outline, const FitShapeOptions& options, Progress* progress)
{
    FitShapeResult result;
    result.displacements.resize(0, 3);
    if (!outline.ok()) {
        result.error = outlineErrorMessage(outline.error);
        return result;
    }
    const Eigen::Index n = shape.rows();
    if (n == 0 || faces.rows() == 0) {
        result.error = "The model has no triangles.";
        return result;
    }
    RasterCamera camera = cameraIn;
    camera.width = outline.width;
    camera.height = outline.height;
    const ProjectionFrame frame(camera);
    FitScratch scratch;
    result.before = measureFit(shape, faces, camera, outline, {}, &scratch);
    if (!result.before.valid) {
        result.error = "The model is not in view of the drawing's camera.";
        return result;
    }

    // Which vertices may move: the region's (or all), less the pins.
    std::vector<std::uint8_t> free(std::size_t(n), options.regionFaces.empty() ? 1 : 0);
    for (std::int32_t f : options.regionFaces)
        if (f >= 0 && f < faces.rows())
            for (int k = 0; k < 3; ++k)
                if (faces(f, k) >= 0 && faces(f, k) < n)
                    free[std::size_t(faces(f, k))] = 1;
    for (std::int32_t v : options.pinnedVertices)
        if (v >= 0 && v < n)
            free[std::size_t(v)] = 0;
    const bool mirrored = options.mirror.size() == std::size_t(n) && options.mirrorNormal.norm() > 0.0;
    const Eigen::Vector3d mirrorNormal = mirrored ? options.mirrorNormal.normalized() : Eigen::Vector3d::UnitX();

    ArapSolver solver(shape, faces, free);
    if (solver.freeCount() == 0) {
        result.error = "No vertex of the model may move (the region is empty or pinned).";
        return result;
    }

    RoundImages images;
    images.width = outline.width;
    images.height = outline.height;
    std::vector<float> outlineField;
    signedDistanceField(outline.mask.data(), outline.width, outline.height, outlineField, &scratch);
    images.outline = &outlineField;
    double radius = options.searchRadiusPx;
    if (!(radius > 0.0)) {
        Eigen::AlignedBox2d box;
        for (const auto& contour : outline.contours)
            for (const auto& p : contour)
                box.extend(p);
        radius = std::max(6.0, 0.08 * box.diagonal().norm());
    }
    const double minCosine = std::cos(options.maxNormalAngleDegrees * kPi / 180.0);

    const Eigen::MatrixXd rest = shape.cast<double>();
    Eigen::MatrixXd current = rest, best = rest;
    FitMetrics bestMetrics = result.before;
    FeatureEdges features;
    LineSettings settings;
    settings.creases = false;
    settings.materialBoundaries = false;
    std::vector<std::uint8_t> mask;
    const int rounds = std::max(options.maxRounds, 1);
    for (int round = 0; round < rounds; ++round) {
        if (cancelRequested(progress)) {
            result.cancelled = true;
            return result;
        }
        report(progress, round, rounds);
        const Positions positions = current.cast<float>();
        Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> projected = projectVertices(positions, camera);
        coverageMask(projected, faces, images.width, images.height, mask);
        if (outline.holesFilled)
            fillMaskHoles(mask, images.width, images.height, scratch.reached, scratch.stack);
        signedDistanceField(mask.data(), images.width, images.height, images.silhouette, &scratch);

        // 1. The contour generator of the current shape, chained.
        LineView view;
        view.orthographic = camera.orthographic;
        view.eye = camera.eye.cast<float>();
        view.direction = frame.forward.cast<float>();
        extractFeatureEdges(positions, faces, topology, {}, view, settings, features);
        const std::vector<Stroke> strokes = chainStrokes(topology, features);

        // 2. Matches along the projected normals.
        std::vector<std::int32_t> handleOf(std::size_t(n), -1);
        std::vector<Eigen::Vector3d> displacement;
        std::vector<double> stiffness;
        std::vector<std::int32_t> handleVertex;
        for (const Stroke& stroke : strokes) {
            const std::size_t m = stroke.vertices.size();
            for (std::size_t i = 0; i < m; ++i) {
                const std::int32_t v = stroke.vertices[i];
                if (!free[std::size_t(v)] || handleOf[std::size_t(v)] >= 0 || !(projected(v, 2) > 0.0))
                    continue;
                const Eigen::Vector2d x = projected.row(v).head<2>().transpose();
                if (x.x() < 0 || x.y() < 0 || x.x() >= images.width || x.y() >= images.height)
                    continue;
                Eigen::Vector2d gradient;
                const double onSilhouette
                    = sampleBilinear(images.silhouette, images.width, images.height, x.x(), x.y(), &gradient);
                if (std::abs(onSilhouette) > 1.5)
                    continue; // an inner contour (an ear over the head) or a hidden one
                const bool hasPrev = i > 0 || stroke.closed, hasNext = i + 1 < m || stroke.closed;
                const std::int32_t a = hasPrev ? stroke.vertices[(i + m - 1) % m] : v;
                const std::int32_t b = hasNext ? stroke.vertices[(i + 1) % m] : v;
                const Eigen::Vector2d t = (projected.row(b) - projected.row(a)).head<2>().transpose();
                Eigen::Vector2d normal = t.norm() > 1e-9 ? Eigen::Vector2d(t.y(), -t.x()).normalized()
                                                         : Eigen::Vector2d(gradient.normalized());
                if (!normal.allFinite())
                    continue;
                if (normal.dot(gradient) < 0.0)
                    normal = -normal; // outward: where the silhouette's distance grows
                const double s = matchAlongNormal(images, x, normal, radius, minCosine);
                if (std::isnan(s))
                    continue;
                // Tukey's weight of the distance moved (twice the search radius as its scale):
                // long moves are trusted less than the vertices that already match.
                const double u = s / (2.0 * radius);
                const double weight = (1.0 - u * u) * (1.0 - u * u);
                const Eigen::Vector2d target = x + s * normal;
                const Eigen::Vector3d goal = frame.unproject(target.x(), target.y(), projected(v, 2));
                handleOf[std::size_t(v)] = std::int32_t(handleVertex.size());
                handleVertex.push_back(v);
                displacement.push_back(goal - current.row(v).transpose());
                stiffness.push_back(options.handleStiffness * weight);
            }
        }
        const std::size_t matched = handleVertex.size();
        if (matched == 0)
            break;

        // 3. Handles (with their mirrored twins), then the rest as rigidly as possible.
        std::vector<ArapHandle> handles;
        handles.reserve(2 * matched);
        for (std::size_t k = 0; k < matched; ++k) {
            const std::int32_t v = handleVertex[k];
            Eigen::Vector3d d = displacement[k];
            if (mirrored) {
                const std::int32_t twin = options.mirror[std::size_t(v)];
                if (twin >= 0 && twin != v && handleOf[std::size_t(twin)] >= 0)
                    d = 0.5 * (d + reflect(displacement[std::size_t(handleOf[std::size_t(twin)])], mirrorNormal));
            }
            handles.push_back({v, current.row(v).transpose() + d, stiffness[k]});
        }
        if (mirrored)
            for (std::size_t k = 0; k < matched; ++k) {
                const std::int32_t twin = options.mirror[std::size_t(handleVertex[k])];
                if (twin < 0 || twin >= n || handleOf[std::size_t(twin)] >= 0 || !free[std::size_t(twin)])
                    continue;
                const Eigen::Vector3d d = reflect(displacement[k], mirrorNormal);
                handles.push_back({twin, current.row(twin).transpose() + d, stiffness[k]});
            }
        if (!solver.setHandles(handles)) {
            result.error = "The deformation could not be solved.";
            return result;
        }
        Eigen::MatrixXd next = current;
        if (!solver.solve(next, options.arapIterations, progress)) {
            result.cancelled = true;
            return result;
        }
        if (mirrored) {
            // The mirror keeps the shape's symmetry exactly: each offset averaged with its twin's.
            const Eigen::MatrixXd offsets = next - rest;
            for (Eigen::Index v = 0; v < n; ++v) {
                const std::int32_t twin = options.mirror[std::size_t(v)];
                if (twin >= 0 && twin < n && free[std::size_t(v)] && free[std::size_t(twin)])
                    next.row(v) = rest.row(v)
                        + 0.5 * (offsets.row(v) + reflect(offsets.row(twin).transpose(), mirrorNormal).transpose());
            }
        }
        const FitMetrics metrics = measureFit(next.cast<float>(), faces, camera, outline, {}, &scratch);
        if (!metrics.valid || metrics.chamferPx >= bestMetrics.chamferPx)
            break; // this round made it worse: keep the last one
        const bool enough = metrics.chamferPx > bestMetrics.chamferPx * (1.0 - options.minImprovement);
        current = next;
        best = next;
        bestMetrics = metrics;
        result.rounds = round + 1;
        result.matchedVertices = std::int64_t(matched);
        if (enough)
            break;
    }
    report(progress, rounds, rounds);

    const double strength = std::clamp(options.strength, 0.0, 1.0);
    const Eigen::MatrixXd offsets = strength * (best - rest);
    const double size = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
    const double tiny = 1e-7 * std::max(size, 1e-30);
    for (Eigen::Index v = 0; v < n; ++v)
        if (offsets.row(v).norm() > tiny)
            result.indices.push_back(std::uint32_t(v));
    result.displacements.resize(Eigen::Index(result.indices.size()), 3);
    for (std::size_t k = 0; k < result.indices.size(); ++k)
        result.displacements.row(Eigen::Index(k)) = offsets.row(Eigen::Index(result.indices[k])).cast<float>();
    if (strength == 1.0) {
        result.after = bestMetrics;
    } else {
        Positions moved = shape;
        for (std::size_t k = 0; k < result.indices.size(); ++k)
            moved.row(Eigen::Index(result.indices[k])) += result.displacements.row(Eigen::Index(k));
        result.after = measureFit(moved, faces, camera, outline, {}, &scratch);
    }
    result.ok = true;
    return result;
}

} // namespace celform::algo
