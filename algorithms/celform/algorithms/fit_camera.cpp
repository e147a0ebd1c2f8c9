// Fit Camera to Drawing (fit_camera.h): Levenberg-Marquardt on robust chamfer residuals, coarse to
// fine, from a few starts.
//
// The residuals at a camera C (DESIGN.md, "Drawings and cameras": the symmetric chamfer distance):
//  - silhouette to outline: points sampled on the mesh's silhouette edges (the contour generator,
//    lines.h) where they lie on the outer boundary of the projected silhouette, projected by C and
//    looked up in the outline's signed distance field with bilinear interpolation (smooth through
//    zero, so the residual is differentiable in C);
//  - outline to silhouette: points sampled on the outline, each paired with its nearest silhouette
//    sample, the residual being that sample's distance to the
//    outline's tangent line at the point (point-to-line, as in ICP).
// The samples, pairs and robust weights (iteratively reweighted) are refreshed at every iteration;
// within one the residuals are smooth functions of the seven camera parameters, differentiated by
// central differences.
#include "celform/algorithms/fit_camera.h"

#include "celform/algorithms/distance_transform.h"
#include "celform/algorithms/lines.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace celform::algo {

namespace {

constexpr double kPi = 3.14159265358979323846;
using Projected = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
constexpr int kParameters = 7; // orbit (3), pan (2), dolly, zoom

/// The camera's zoom on the parameters' scale: log tan(fov / 2), or log of the orthographic height.
double logZoom(const RasterCamera& c)
{
    return c.orthographic ? std::log(c.orthoHeight) : std::log(std::tan(0.5 * c.fovYDegrees * kPi / 180.0));
}

/// The camera for a parameter vector relative to a base camera: an orbit (rotation vector) about
/// the pivot on the view axis at the model's depth, a pan of the camera across its image plane (in
/// units of the pivot distance, so about radians), a dolly (log of the pivot distance) and a zoom
/// (log of tan(fov / 2), or of the orthographic height). Orbit and pan separate the view direction
/// from the image position better than a rotation about the eye would.
struct CameraParameters {
    RasterCamera base;
    double pivotDistance = 1.0;
    double targetDistance = 1.0;
    /// Bounds of the zoom (logZoom) over the whole fit: FitCameraOptions::maxZoomFactor about the
    /// start's.
    double zoomLow = -1e300;
    double zoomHigh = 1e300;

    [[nodiscard]] RasterCamera apply(const Eigen::Matrix<double, kParameters, 1>& x) const
    {
        const Eigen::Vector3d forward = base.forward(), right = base.right(), up = base.trueUp();
        const Eigen::Vector3d pivot = base.eye + pivotDistance * forward;
        const Eigen::Vector3d omega = x.head<3>();
        const double angle = omega.norm();
        const Eigen::Matrix3d r
            = angle > 0.0 ? Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
        const Eigen::Vector3d f = r * forward, u = r * up, rt = r * right;
        const Eigen::Vector3d newPivot = pivot + pivotDistance * (x(3) * rt + x(4) * u);
        const double distance = base.orthographic ? pivotDistance : pivotDistance * std::exp(x(5));
        RasterCamera c = base;
        c.eye = newPivot - distance * f;
        c.target = c.eye + targetDistance * f;
        c.up = u;
        const double zoom = std::clamp(logZoom(base) + x(6), zoomLow, zoomHigh);
        if (base.orthographic) {
            c.orthoHeight = std::exp(zoom);
        } else {
            const double t = std::exp(zoom);
            c.fovYDegrees = std::clamp(2.0 * std::atan(t) * 180.0 / kPi, FitCameraOptions::kMinFieldOfViewDegrees,
                FitCameraOptions::kMaxFieldOfViewDegrees);
        }
        return c;
    }
};

/// A point on a silhouette edge: corners v0, v1 of the edge and the parameter along it.
struct EdgeSample {
    std::int32_t v0 = 0;
    std::int32_t v1 = 0;
    double t = 0.5;
};

/// One pyramid level of the drawing: its outline's signed distance field and samples.
struct Level {
    int factor = 1; ///< full-resolution pixels per level pixel
    bool holesFilled = true; ///< the outline's: the silhouette's holes are filled likewise
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> outlineMask;
    std::vector<float> outlineField;
    std::vector<Eigen::Vector2d> points; ///< outline samples, level pixels
    std::vector<Eigen::Vector2d> normals; ///< outward unit normals
};

Level makeLevel(const Outline& outline, int factor, int maxSamples, FitScratch& scratch)
{
    Level level;
    level.factor = factor;
    level.holesFilled = outline.holesFilled;
    level.outlineMask = downsampleMask(outline.mask, outline.width, outline.height, factor, level.width, level.height);
    signedDistanceField(level.outlineMask.data(), level.width, level.height, level.outlineField, &scratch);
    double length = 0.0;
    for (const auto& contour : outline.contours)
        for (std::size_t i = 0; i < contour.size(); ++i)
            length += (contour[(i + 1) % contour.size()] - contour[i]).norm();
    const double spacing = std::max(1.0 * factor, length / std::max(maxSamples, 1));
    for (const auto& contour : outline.contours) {
        const std::vector<Eigen::Vector2d> samples = resampleClosed(contour, spacing);
        const std::size_t m = samples.size();
        for (std::size_t i = 0; i < m; ++i) {
            const Eigen::Vector2d t = samples[(i + 1) % m] - samples[(i + m - 1) % m];
            const Eigen::Vector2d n(t.y(), -t.x()); // outward for a positive-area contour
            if (n.norm() <= 0.0)
                continue;
            level.points.push_back(samples[i] / double(factor));
            level.normals.push_back(n.normalized());
        }
    }
    return level;
}

/// The residuals of one iteration: samples, pairs and weights fixed, the camera varying.
struct Linearisation {
    const Positions* shape = nullptr;
    const Level* level = nullptr;
    std::vector<EdgeSample> silhouette;
    std::vector<double> silhouetteWeight; ///< sqrt(robust weight / count)
    std::vector<std::int32_t> pair; ///< per outline point: its silhouette sample, or -1
    std::vector<double> pairWeight;

    [[nodiscard]] Eigen::Vector2d projectSample(const ProjectionFrame& frame, const EdgeSample& s) const
    {
        const Eigen::Vector3d a = shape->row(s.v0).transpose().cast<double>();
        const Eigen::Vector3d b = shape->row(s.v1).transpose().cast<double>();
        const Eigen::Vector3d p = frame.project(a + s.t * (b - a));
        return p.head<2>() / double(level->factor);
    }

    void residuals(const RasterCamera& camera, Eigen::VectorXd& r) const
    {
        const ProjectionFrame frame(camera);
        r.resize(Eigen::Index(silhouette.size() + pair.size()));
        std::vector<Eigen::Vector2d> projected(silhouette.size());
        for (std::size_t k = 0; k < silhouette.size(); ++k) {
            projected[k] = projectSample(frame, silhouette[k]);
            const double d
                = sampleBilinear(level->outlineField, level->width, level->height, projected[k].x(), projected[k].y());
            r(Eigen::Index(k)) = silhouetteWeight[k] * d;
        }
        for (std::size_t j = 0; j < pair.size(); ++j) {
            double d = 0.0;
            if (pair[j] >= 0)
                d = level->normals[j].dot(projected[std::size_t(pair[j])] - level->points[j]);
            r(Eigen::Index(silhouette.size() + j)) = pairWeight[j] * d;
        }
    }
};

/// A uniform grid over 2D points for nearest-point queries: rings of cells are searched outwards
/// until the ring is farther than the best point found.
class PointGrid {
public:
    PointGrid(const std::vector<Eigen::Vector2d>& points, double cell)
        : m_points(points)
        , m_cell(cell)
    {
        for (const auto& p : points)
            m_box.extend(p);
        if (points.empty())
            return;
        m_columns = int(std::floor((m_box.max().x() - m_box.min().x()) / cell)) + 1;
        m_rows = int(std::floor((m_box.max().y() - m_box.min().y()) / cell)) + 1;
        m_start.assign(std::size_t(m_columns) * std::size_t(m_rows) + 1, 0);
        for (const auto& p : points)
            ++m_start[cellOf(p) + 1];
        for (std::size_t c = 0; c + 1 < m_start.size(); ++c)
            m_start[c + 1] += m_start[c];
        m_items.resize(points.size());
        std::vector<std::int32_t> fill(m_start.begin(), m_start.end() - 1);
        for (std::size_t k = 0; k < points.size(); ++k)
            m_items[std::size_t(fill[cellOf(points[k])]++)] = std::int32_t(k);
    }

    /// The nearest point's index, -1 when there are none.
    [[nodiscard]] std::int32_t nearest(const Eigen::Vector2d& q) const
    {
        if (m_points.empty())
            return -1;
        const int cx = std::clamp(int(std::floor((q.x() - m_box.min().x()) / m_cell)), 0, m_columns - 1);
        const int cy = std::clamp(int(std::floor((q.y() - m_box.min().y()) / m_cell)), 0, m_rows - 1);
        std::int32_t best = -1;
        double bestSquared = std::numeric_limits<double>::infinity();
        const int rings = std::max(m_columns, m_rows);
        for (int r = 0; r <= rings; ++r) {
            // Every point in ring r is at least (r - 1) cells away from q (q may lie outside the box).
            const double reach = std::max(0.0, (r - 1) * m_cell - m_box.exteriorDistance(q));
            if (best >= 0 && reach * reach > bestSquared)
                break;
            for (int y = cy - r; y <= cy + r; ++y) {
                if (y < 0 || y >= m_rows)
                    continue;
                const bool edgeRow = y == cy - r || y == cy + r;
                for (int x = cx - r; x <= cx + r; x += edgeRow ? 1 : 2 * std::max(r, 1)) {
                    if (x < 0 || x >= m_columns)
                        continue;
                    const std::size_t c = std::size_t(y) * std::size_t(m_columns) + std::size_t(x);
                    for (std::int32_t i = m_start[c]; i < m_start[c + 1]; ++i) {
                        const std::int32_t k = m_items[std::size_t(i)];
                        const double d = (m_points[std::size_t(k)] - q).squaredNorm();
                        if (d < bestSquared) {
                            bestSquared = d;
                            best = k;
                        }
                    }
                }
            }
        }
        return best;
    }

private:
    [[nodiscard]] std::size_t cellOf(const Eigen::Vector2d& p) const
    {
        const int x = std::clamp(int(std::floor((p.x() - m_box.min().x()) / m_cell)), 0, m_columns - 1);
        const int y = std::clamp(int(std::floor((p.y() - m_box.min().y()) / m_cell)), 0, m_rows - 1);
        return std::size_t(y) * std::size_t(m_columns) + std::size_t(x);
    }

    const std::vector<Eigen::Vector2d>& m_points;
    double m_cell = 1.0;
    Eigen::AlignedBox2d m_box;
    int m_columns = 0;
    int m_rows = 0;
    std::vector<std::int32_t> m_start;
    std::vector<std::int32_t> m_items;
};

/// Samples, pairs and weights at camera (level coordinates). False when the model's silhouette is
/// not in the image.
bool linearise(const Positions& shape, const Faces& faces, const EdgeTopology& topology, const RasterCamera& camera,
    const Level& level, const FitCameraOptions& options, Linearisation& lin, FeatureEdges& features,
    const RobustKernel& levelKernel, FitScratch& scratch)
{
    lin.shape = &shape;
    lin.level = &level;
    const ProjectionFrame frame(camera);
    Projected projected = projectVertices(shape, camera);
    projected.leftCols<2>() /= double(level.factor);
    std::vector<std::uint8_t>& mask = scratch.mask;
    coverageMask(projected, faces, level.width, level.height, mask);
    if (level.holesFilled)
        fillMaskHoles(mask, level.width, level.height, scratch.reached, scratch.stack);
    // A sample lies on the outer boundary when the filled silhouette is empty a pixel and a half to
    // one side of its edge; contour generators inside the silhouette (an ear over the body, hidden
    // folds) have the silhouette on both sides, do not meet the outline and are left out.
    auto inside = [&](const Eigen::Vector2d& p) {
        const int x = int(std::floor(p.x())), y = int(std::floor(p.y()));
        if (x < 0 || y < 0 || x >= level.width || y >= level.height)
            return false;
        return mask[std::size_t(y) * std::size_t(level.width) + std::size_t(x)] != 0;
    };

    LineView view;
    view.orthographic = camera.orthographic;
    view.eye = camera.eye.cast<float>();
    view.direction = frame.forward.cast<float>();
    LineSettings settings;
    settings.creases = false;
    settings.materialBoundaries = false;
    extractFeatureEdges(shape, faces, topology, {}, view, settings, features);

    std::vector<EdgeSample> samples;
    std::vector<Eigen::Vector2d> where;
    for (std::size_t e = 0; e < features.edges.size(); ++e) {
        const std::int32_t v0 = topology.edges(features.edges[e], 0), v1 = topology.edges(features.edges[e], 1);
        const Eigen::Vector3d a = projected.row(v0).transpose(), b = projected.row(v1).transpose();
        if (!(a.z() > 0.0 && b.z() > 0.0))
            continue;
        const Eigen::Vector2d along = b.head<2>() - a.head<2>();
        const double length = along.norm();
        if (!(length > 1e-6))
            continue;
        const Eigen::Vector2d side = 1.5 / length * Eigen::Vector2d(along.y(), -along.x());
        const int m = std::clamp(int(std::ceil(length)), 1, 64);
        for (int i = 0; i < m; ++i) {
            const double t = (i + 0.5) / m;
            const Eigen::Vector2d p = a.head<2>() + t * (b.head<2>() - a.head<2>());
            if (p.x() < 0 || p.y() < 0 || p.x() >= level.width || p.y() >= level.height)
                continue;
            if (inside(p + side) && inside(p - side))
                continue;
            samples.push_back({v0, v1, t});
            where.push_back(p);
        }
    }
    if (samples.empty())
        return false;
    const std::size_t stride = (samples.size() + std::size_t(options.maxSamples) - 1) / std::size_t(options.maxSamples);
    lin.silhouette.clear();
    std::vector<Eigen::Vector2d> kept;
    for (std::size_t k = 0; k < samples.size(); k += std::max<std::size_t>(stride, 1)) {
        lin.silhouette.push_back(samples[k]);
        kept.push_back(where[k]);
    }

    // Pairs: the nearest silhouette sample of every outline point, through a uniform grid of the
    // samples (a few thousand points: cheaper than a transform of the whole level).
    const PointGrid grid(kept, 8.0);
    const RobustKernel& kernel = levelKernel;
    const double na = double(lin.silhouette.size()), nb = double(std::max<std::size_t>(level.points.size(), 1));
    lin.silhouetteWeight.resize(lin.silhouette.size());
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const double d = sampleBilinear(level.outlineField, level.width, level.height, kept[k].x(), kept[k].y());
        lin.silhouetteWeight[k] = std::sqrt(kernel.weight(d) / na);
    }
    lin.pair.assign(level.points.size(), -1);
    lin.pairWeight.assign(level.points.size(), 0.0);
    for (std::size_t j = 0; j < level.points.size(); ++j) {
        const Eigen::Vector2d& q = level.points[j];
        const std::int32_t k = grid.nearest(q);
        if (k < 0)
            continue;
        lin.pair[j] = k;
        // The weight follows the full distance to the pair, the residual its normal part.
        const double d = (kept[std::size_t(k)] - q).norm();
        lin.pairWeight[j] = std::sqrt(kernel.weight(d) / nb);
    }
    return true;
}

/// Levenberg-Marquardt at one level from camera; returns the refined camera and counts iterations.
/// False on cancel.
bool solveLevel(const Positions& shape, const Faces& faces, const EdgeTopology& topology, RasterCamera& camera,
    double startZoom, const Eigen::Vector3d& centroid, const Level& level, const FitCameraOptions& options,
    const RobustKernel& kernel, Progress* progress, std::int64_t& done, std::int64_t total, int& iterations,
    FitScratch& scratch)
{
    FeatureEdges features;
    RobustKernel levelKernel = kernel;
    levelKernel.scale = std::max(kernel.scale / level.factor, 1.5);
    double lambda = 1e-3;
    int quiet = 0;
    for (int it = 0; it < options.iterationsPerLevel; ++it) {
        if (cancelRequested(progress))
            return false;
        report(progress, ++done, total);
        ++iterations;
        Linearisation lin;
        if (!linearise(shape, faces, topology, camera, level, options, lin, features, levelKernel, scratch))
            return true;
        CameraParameters parameters;
        parameters.base = camera;
        parameters.pivotDistance = std::max((centroid - camera.eye).dot(camera.forward()), 1e-6);
        parameters.targetDistance = (camera.target - camera.eye).norm();
        parameters.zoomLow = startZoom - std::log(options.maxZoomFactor);
        parameters.zoomHigh = startZoom + std::log(options.maxZoomFactor);
        using Vector7 = Eigen::Matrix<double, kParameters, 1>;
        Eigen::VectorXd r0;
        lin.residuals(camera, r0);
        const double cost0 = r0.squaredNorm();
        Eigen::MatrixXd jacobian(r0.size(), kParameters);
        Eigen::VectorXd plus, minus;
        const double h = 1e-4;
        for (int p = 0; p < kParameters; ++p) {
            Vector7 x = Vector7::Zero();
            x(p) = h;
            lin.residuals(parameters.apply(x), plus);
            x(p) = -h;
            lin.residuals(parameters.apply(x), minus);
            jacobian.col(p) = (plus - minus) / (2.0 * h);
        }
        std::vector<bool> active(kParameters, true);
        if (camera.orthographic)
            active[5] = false; // a dolly does not change an orthographic image
        if (!options.fitFieldOfView)
            active[6] = false;
        Eigen::Matrix<double, kParameters, kParameters> jtj = jacobian.transpose() * jacobian;
        Vector7 jtr = jacobian.transpose() * r0;
        for (int p = 0; p < kParameters; ++p)
            if (!active[std::size_t(p)]) {
                jtj.row(p).setZero();
                jtj.col(p).setZero();
                jtj(p, p) = 1.0;
                jtr(p) = 0.0;
            }
        bool accepted = false;
        double decrease = 0.0;
        Vector7 step = Vector7::Zero();
        for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
            Eigen::Matrix<double, kParameters, kParameters> a = jtj;
            for (int p = 0; p < kParameters; ++p)
                a(p, p) += lambda * std::max(jtj(p, p), 1e-9) + 1e-12;
            step = a.ldlt().solve(-jtr);
            // Trust region: a tenth of a radian per iteration at most.
            const double norm = step.norm();
            if (norm > 0.1)
                step *= 0.1 / norm;
            Eigen::VectorXd r1;
            const RasterCamera trial = parameters.apply(step);
            lin.residuals(trial, r1);
            if (r1.allFinite() && r1.squaredNorm() < cost0) {
                camera = trial;
                decrease = (cost0 - r1.squaredNorm()) / std::max(cost0, 1e-300);
                lambda = std::max(lambda / 3.0, 1e-7);
                accepted = true;
            } else {
                lambda *= 4.0;
            }
        }
        // Converged when steps stop helping: rejected, tiny, or lowering the cost by under 0.1 %.
        if (!accepted || step.norm() < 1e-6 || decrease < 1e-3)
            ++quiet;
        else
            quiet = 0;
        if (quiet >= 2)
            break;
    }
    return true;
}

/// The level's robust chamfer cost of a camera (masks at the level's size), for choosing a start.
double levelCost(const Positions& shape, const Faces& faces, const RasterCamera& camera, const Level& level,
    const RobustKernel& kernel, FitScratch& scratch)
{
    Projected projected = projectVertices(shape, camera);
    projected.leftCols<2>() /= double(level.factor);
    std::vector<std::uint8_t> mask;
    coverageMask(projected, faces, level.width, level.height, mask);
    if (level.holesFilled)
        fillMaskHoles(mask, level.width, level.height, scratch.reached, scratch.stack);
    RobustKernel levelKernel = kernel;
    levelKernel.scale = std::max(kernel.scale / level.factor, 1.5);
    const FitMetrics m
        = compareMasks(mask.data(), level.outlineMask.data(), level.width, level.height, levelKernel, &scratch);
    return m.valid ? m.robustCost : std::numeric_limits<double>::infinity();
}

} // namespace

RasterCamera orbitCamera(
    const RasterCamera& camera, const Eigen::Vector3d& pivot, double yawDegrees, double pitchDegrees)
{
    const Eigen::Vector3d up = camera.trueUp(), right = camera.right();
    const Eigen::Matrix3d r
        = (Eigen::AngleAxisd(pitchDegrees * kPi / 180.0, right) * Eigen::AngleAxisd(yawDegrees * kPi / 180.0, up))
              .toRotationMatrix();
    RasterCamera c = camera;
    c.eye = pivot + r * (camera.eye - pivot);
    c.target = pivot + r * (camera.target - pivot);
    c.up = r * up;
    return c;
}

Eigen::Vector3d viewDirection(const RasterCamera& camera, const Eigen::Vector3d& centroid)
{
    return (camera.eye - centroid).normalized();
}

FitCameraResult fitCamera(const Positions& shape, const Faces& faces, const EdgeTopology& topology,
    const RasterCamera& start, const Outline& outline, const FitCameraOptions& options, Progress* progress)
{
    FitCameraResult result;
    result.camera = start;
    result.camera.width = outline.width;
    result.camera.height = outline.height;
    if (!outline.ok()) {
        result.error = outlineErrorMessage(outline.error);
        return result;
    }
    if (shape.rows() == 0 || faces.rows() == 0) {
        result.error = "The model has no triangles.";
        return result;
    }
    // One working memory for the whole fit: a megapixel's transforms touch tens of megabytes.
    FitScratch scratch;
    result.before = measureFit(shape, faces, result.camera, outline, options.kernel, &scratch);
    if (!result.before.valid) {
        result.error = "The model is not in view of the drawing's camera.";
        return result;
    }
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Eigen::Index v = 0; v < shape.rows(); ++v)
        centroid += shape.row(v).transpose().cast<double>();
    centroid /= double(shape.rows());

    // The pyramid: factors of two from the coarsest level to the finest used.
    const int longSide = std::max(outline.width, outline.height);
    int finest = 1;
    while (longSide / (finest * 2) >= std::max(options.finestSize, 16))
        finest *= 2;
    int coarsest = finest;
    while (longSide / (coarsest * 2) >= std::max(options.coarsestSize, 16))
        coarsest *= 2;
    std::vector<Level> levels;
    for (int f = coarsest; f >= finest; f /= 2)
        levels.push_back(makeLevel(outline, f, options.maxSamples, scratch));

    // Starts: the camera and orbits of +/- spread in yaw and pitch about the centroid, each solved
    // on the coarsest level; the best few continue through the middle levels with the same loss,
    // and the best of those is refined on the finest level with the redescending loss, which
    // ignores the parts of the drawing the model does not have (an exaggerated ear, a pulled trunk).
    const double startZoom = logZoom(result.camera);
    std::vector<RasterCamera> starts = {result.camera};
    if (options.startSpreadDegrees > 0.0) {
        const double s = options.startSpreadDegrees;
        for (const auto& [yaw, pitch] : {std::pair{s, 0.0}, {-s, 0.0}, {0.0, s}, {0.0, -s}})
            starts.push_back(orbitCamera(result.camera, centroid, yaw, pitch));
    }
    const std::size_t kept = std::clamp<std::size_t>(std::size_t(std::max(options.keptStarts, 1)), 1, starts.size());
    const std::size_t middle = levels.size() >= 2 ? levels.size() - 2 : 0;
    const std::int64_t total
        = std::int64_t(options.iterationsPerLevel) * std::int64_t(starts.size() + kept * middle + 1);
    std::int64_t done = 0;
    auto cancelled = [&] {
        result.cancelled = true;
        result.camera = start;
        result.camera.width = outline.width;
        result.camera.height = outline.height;
        return result;
    };
    auto bestFirst = [&](std::vector<RasterCamera>& cameras, const Level& level) {
        std::vector<std::pair<double, std::size_t>> costs;
        for (std::size_t s = 0; s < cameras.size(); ++s)
            costs.emplace_back(levelCost(shape, faces, cameras[s], level, options.kernel, scratch), s);
        std::stable_sort(costs.begin(), costs.end());
        std::vector<RasterCamera> sorted;
        for (const auto& c : costs)
            sorted.push_back(cameras[c.second]);
        cameras = std::move(sorted);
    };
    for (RasterCamera& s : starts)
        if (!solveLevel(shape, faces, topology, s, startZoom, centroid, levels.front(), options, options.kernel,
                progress, done, total, result.iterations, scratch))
            return cancelled();
    bestFirst(starts, levels.front());
    starts.resize(kept);
    for (std::size_t l = 1; l + 1 < levels.size(); ++l) {
        for (RasterCamera& s : starts)
            if (!solveLevel(shape, faces, topology, s, startZoom, centroid, levels[l], options, options.kernel,
                    progress, done, total, result.iterations, scratch))
                return cancelled();
        bestFirst(starts, levels[l]);
    }
    RasterCamera camera = starts.front();
    if (!solveLevel(shape, faces, topology, camera, startZoom, centroid, levels.back(), options, options.refineKernel,
            progress, done, total, result.iterations, scratch))
        return cancelled();
    report(progress, total, total);

    const FitMetrics after = measureFit(shape, faces, camera, outline, options.kernel, &scratch);
    if (after.valid && after.robustCost <= result.before.robustCost) {
        result.camera = camera;
        result.after = after;
    } else {
        result.after = result.before;
    }
    result.ok = true;
    return result;
}

} // namespace celform::algo
