// model_sheet: the reference drawings of the bundled sample (scripts/make-model-sheet.sh). Renders
// the CGAL elephant's silhouette from the side and from the front in the model's own pose, warps
// it smoothly in 2D the way a model sheet exaggerates (bigger ears, a longer trunk; sheet_warp.h),
// inks it with a varying line width (sheet_ink.h), writes RGBA PNGs and prints each drawing's
// camera. It then reads every PNG back, extracts its outline as the Fit commands do
// (algo::extractOutline) and prints the IoU and chamfer distance against the unwarped silhouette.
//
// Usage: model_sheet MESH OUT_DIR [--long-side PIXELS] [--plain]
// (--plain inks the model's own silhouette, without the exaggeration, for comparison.)
//
// The anchors are this mesh's: vertex indices of cgal_elephant.off (2,775 vertices) chosen by
// looking at it, which is acceptable because this program is the sample's recipe, not a feature.
#include "sheet_ink.h"
#include "sheet_warp.h"

#include "celform/algorithms/fit_metrics.h"
#include "celform/algorithms/outline.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"

#include <QDir>
#include <QImage>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace {

using celform::algo::Positions;
using celform::algo::RasterCamera;
using celform::algo::TriMesh;

// --- this mesh's anchors (cgal_elephant.off) -----------------------------------------------------
/// The tip of the raised trunk (the vertex scripts/make-sample.sh brushes too).
constexpr int kTrunkTip = 691;
/// Geodesic length of the trunk from its tip to where it widens into the head, model units.
constexpr double kTrunkLength = 0.5;
/// Vertices at the middle of the two ears (+z, the near ear from the side view, and -z).
constexpr int kEars[] = {456, 2603};
/// Radius of an ear about its middle, model units (the highlight sample's ear patch is 0.12).
constexpr double kEarRadius = 0.11;

// --- the exaggeration ----------------------------------------------------------------------------
/// Ear field gain: the rim at about one sigma moves out by 0.61 gain of its radius (20 %).
constexpr double kEarGain = 0.33;
/// The trunk grows by this fraction of its length beyond its tip.
constexpr double kTrunkStretch = 0.13;
/// Sigma of the trunk's Gaussians, model units: wide enough that the displacement fades over
/// more than its own size beyond the tip (the warp folds nowhere), narrow enough to spare the head.
constexpr double kTrunkSigma = 0.07;
/// The fraction of the image height the figure fills.
constexpr double kFill = 0.8;
constexpr int kSupersample = 3;

void printVector(const char* label, const Eigen::Vector3d& v)
{
    std::printf("%s%.6f,%.6f,%.6f", label, v.x(), v.y(), v.z());
}

/// Geodesic distances along edges from one vertex (Dijkstra).
std::vector<double> geodesicFrom(const TriMesh& mesh, int source)
{
    std::vector<std::vector<int>> neighbours(std::size_t(mesh.vertexCount()));
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
        for (int c = 0; c < 3; ++c) {
            neighbours[std::size_t(mesh.faces(f, c))].push_back(mesh.faces(f, (c + 1) % 3));
            neighbours[std::size_t(mesh.faces(f, (c + 1) % 3))].push_back(mesh.faces(f, c));
        }
    std::vector<double> distance(std::size_t(mesh.vertexCount()), 1e300);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    distance[std::size_t(source)] = 0.0;
    queue.push({0.0, source});
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > distance[std::size_t(v)])
            continue;
        for (const int n : neighbours[std::size_t(v)]) {
            const double next = d + (mesh.vertices.row(v) - mesh.vertices.row(n)).cast<double>().norm();
            if (next < distance[std::size_t(n)]) {
                distance[std::size_t(n)] = next;
                queue.push({next, n});
            }
        }
    }
    return distance;
}

/// The trunk's centreline in model space, tip first: the centroids of rings of equal geodesic
/// distance from the tip, every 0.03 model units up to kTrunkLength.
std::vector<Eigen::Vector3d> trunkCentreline(const TriMesh& mesh)
{
    const std::vector<double> distance = geodesicFrom(mesh, kTrunkTip);
    const double band = 0.03;
    const int rings = int(std::lround(kTrunkLength / band));
    std::vector<Eigen::Vector3d> sums(std::size_t(rings), Eigen::Vector3d::Zero());
    std::vector<int> counts(std::size_t(rings), 0);
    for (Eigen::Index v = 0; v < mesh.vertexCount(); ++v) {
        const int ring = int(distance[std::size_t(v)] / band);
        if (ring < rings) {
            sums[std::size_t(ring)] += mesh.vertices.row(v).cast<double>().transpose();
            ++counts[std::size_t(ring)];
        }
    }
    std::vector<Eigen::Vector3d> line;
    for (int r = 0; r < rings; ++r)
        if (counts[std::size_t(r)] > 0)
            line.push_back(sums[std::size_t(r)] / counts[std::size_t(r)]);
    return line;
}

/// The middle of an ear: the centroid of the vertices within kEarRadius of its anchor vertex.
Eigen::Vector3d earCentre(const TriMesh& mesh, int anchor)
{
    const Eigen::Vector3d a = mesh.vertices.row(anchor).cast<double>().transpose();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (Eigen::Index v = 0; v < mesh.vertexCount(); ++v) {
        const Eigen::Vector3d p = mesh.vertices.row(v).cast<double>().transpose();
        if ((p - a).norm() < kEarRadius) {
            sum += p;
            ++count;
        }
    }
    return sum / count;
}

/// The horizontal axis the elephant faces: the larger horizontal component of the way from the
/// centroid to the trunk's base (the head), with its sign.
Eigen::Vector3d facingDirection(const Eigen::Vector3d& centroid, const Eigen::Vector3d& trunkBase)
{
    const Eigen::Vector3d head = trunkBase - centroid;
    return std::abs(head.x()) >= std::abs(head.z()) ? Eigen::Vector3d(head.x() > 0 ? 1 : -1, 0, 0)
                                                    : Eigen::Vector3d(0, 0, head.z() > 0 ? 1 : -1);
}

/// A 30-degree perspective camera looking along -view, up +y, whose figure fills kFill of the
/// image height, centred both ways: the target is the centroid moved across the view (never
/// along it) until the projected bounding box is centred, and the distance is scaled until its
/// height is kFill of the field of view. The image is longSide pixels high, and as wide as the
/// figure plus the same margins (or longSide wide and less high when the figure is wider).
RasterCamera frameCamera(const Positions& vertices, const Eigen::Vector3d& view, int longSide)
{
    RasterCamera camera;
    camera.fovYDegrees = 30.0;
    camera.up = Eigen::Vector3d(0, 1, 0);
    const Eigen::Vector3d centroid = celform::algo::centroid(vertices);
    const Eigen::Vector3d direction = view.normalized();
    camera.target = centroid;
    double distance = 3.0;
    const double tanHalf = std::tan(camera.fovYDegrees * M_PI / 360.0);
    double spanX = 1.0;
    double spanY = 1.0;
    for (int iteration = 0; iteration < 30; ++iteration) {
        camera.eye = camera.target + direction * distance;
        const Eigen::Vector3d forward = camera.forward();
        const Eigen::Vector3d right = camera.right();
        const Eigen::Vector3d up = camera.trueUp();
        double lowX = 1e300, highX = -1e300, lowY = 1e300, highY = -1e300;
        for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
            const Eigen::Vector3d p = vertices.row(v).cast<double>().transpose() - camera.eye;
            const double depth = p.dot(forward);
            lowX = std::min(lowX, p.dot(right) / depth);
            highX = std::max(highX, p.dot(right) / depth);
            lowY = std::min(lowY, p.dot(up) / depth);
            highY = std::max(highY, p.dot(up) / depth);
        }
        spanX = highX - lowX;
        spanY = highY - lowY;
        camera.target += distance * (0.5 * (lowX + highX) * right + 0.5 * (lowY + highY) * up);
        distance *= spanY / (kFill * 2.0 * tanHalf);
    }
    // Rounded to the printed digits, so that the printed camera is the one the drawing was made with.
    const auto rounded = [](const Eigen::Vector3d& v) { return Eigen::Vector3d((v * 1e6).array().round() / 1e6); };
    camera.target = rounded(camera.target);
    camera.eye = rounded(camera.target + direction * distance);
    // Margins of (1 - kFill) / 2 of the height on every side.
    const double aspect = (spanX / spanY * kFill + (1.0 - kFill)) / 1.0;
    camera.height = longSide;
    camera.width = 2 * int(std::lround(0.5 * longSide * aspect));
    if (camera.width > longSide) {
        camera.width = longSide;
        camera.height = 2 * int(std::lround(0.5 * longSide / aspect));
    }
    return camera;
}

/// Depth discontinuities of a G-buffer: covered pixels with a covered pixel one or two steps away
/// along a row or column farther by more than jump, the inner occluding contours (an ear over the
/// body, a leg over a leg), two pixels wide so that the warp's nearest sampling keeps them whole.
std::vector<std::uint8_t> depthEdges(const celform::algo::GBuffer& g, double jump)
{
    std::vector<std::uint8_t> edges(g.depth.size(), 0);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(g.width) + std::size_t(x);
            if (g.faceId[p] < 0)
                continue;
            for (const int step : {1, 2})
                for (const auto& [dx, dy] :
                    {std::pair{-step, 0}, std::pair{step, 0}, std::pair{0, -step}, std::pair{0, step}}) {
                    const int nx = x + dx;
                    const int ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height)
                        continue;
                    const std::size_t n = std::size_t(ny) * std::size_t(g.width) + std::size_t(nx);
                    if (g.faceId[n] >= 0 && g.depth[n] > g.depth[p] + jump)
                        edges[p] = 1;
                }
        }
    return edges;
}

struct SheetView {
    std::string name;
    Eigen::Vector3d view;
};

celform::algo::DrawingImage readBack(const QString& file)
{
    const QImage image = QImage(file).convertToFormat(QImage::Format_RGBA8888);
    celform::algo::DrawingImage drawing;
    drawing.width = image.width();
    drawing.height = image.height();
    drawing.channels = 4;
    drawing.pixels.resize(std::size_t(image.width()) * std::size_t(image.height()) * 4);
    for (int y = 0; y < image.height(); ++y)
        std::copy_n(image.constScanLine(y), std::size_t(image.width()) * 4,
            drawing.pixels.data() + std::size_t(y) * std::size_t(image.width()) * 4);
    return drawing;
}

/// Extracts the drawing's outline (by alpha, or by luminance on white) and measures the model's
/// unwarped silhouette against it, as the Fit commands would before fitting.
void check(const TriMesh& mesh, const RasterCamera& camera, const QString& file)
{
    const celform::algo::DrawingImage drawing = readBack(file);
    for (const bool alpha : {true, false}) {
        celform::algo::OutlineSettings settings;
        settings.useAlpha = alpha;
        const celform::algo::Outline outline = celform::algo::extractOutline(drawing, settings);
        if (!outline.ok()) {
            std::printf("  outline (%s): %s\n", alpha ? "alpha" : "luminance",
                celform::algo::outlineErrorMessage(outline.error).c_str());
            continue;
        }
        const celform::algo::FitMetrics m = celform::algo::measureFit(mesh.vertices, mesh.faces, camera, outline);
        std::printf("  outline (%s): IoU %.3f against the unwarped silhouette, chamfer %.2f px\n",
            alpha ? "alpha" : "luminance", m.iou, m.chamferPx);
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: model_sheet MESH OUT_DIR [--long-side PIXELS] [--plain]\n");
        return 2;
    }
    int longSide = 1024;
    bool plain = false;
    for (int i = 3; i < argc; ++i) {
        if (std::string(argv[i]) == "--long-side" && i + 1 < argc)
            longSide = std::max(64, std::atoi(argv[++i]));
        else if (std::string(argv[i]) == "--plain")
            plain = true;
    }
    TriMesh mesh;
    try {
        mesh = celform::model::importMesh(QString::fromLocal8Bit(argv[1]), celform::model::ImportIsolation::ThisProcess)
                   .mesh;
    } catch (const celform::model::IoError& e) {
        std::fprintf(stderr, "model_sheet: %s\n", e.what());
        return 3;
    }
    if (mesh.vertexCount() <= *std::max_element(std::begin(kEars), std::end(kEars))
        || mesh.vertexCount() <= kTrunkTip) {
        std::fprintf(stderr, "model_sheet: the anchors are cgal_elephant.off's; this mesh has too few vertices\n");
        return 3;
    }
    const QString outDir = QString::fromLocal8Bit(argv[2]);
    QDir().mkpath(outDir);

    const Eigen::Vector3d centroid = celform::algo::centroid(mesh.vertices);
    const std::vector<Eigen::Vector3d> trunk = trunkCentreline(mesh);
    std::vector<Eigen::Vector3d> ears;
    for (const int anchor : kEars)
        ears.push_back(earCentre(mesh, anchor));
    const Eigen::Vector3d facing = facingDirection(centroid, trunk.back());
    printVector("centroid ", centroid);
    printVector("\ntrunk tip (vertex 691) ", mesh.vertices.row(kTrunkTip).cast<double>().transpose());
    printVector(", trunk base ", trunk.back());
    std::printf(" (%zu centreline points)", trunk.size());
    printVector("\nfacing ", facing);
    for (std::size_t e = 0; e < ears.size(); ++e) {
        std::printf("\near %zu (vertex %d) ", e, kEars[e]);
        printVector("centre ", ears[e]);
    }
    std::printf("\n");

    const std::vector<SheetView> views = {{"side", {0, 0, 1}}, {"front", facing}};
    for (const SheetView& view : views) {
        const RasterCamera camera = frameCamera(mesh.vertices, view.view, longSide);
        const QString file = QDir(outDir).filePath(QString::fromStdString("elephant-sheet-" + view.name + ".png"));
        std::printf("%s: %s %dx%d\n", view.name.c_str(), qPrintable(file), camera.width, camera.height);
        printVector("  camera --eye ", camera.eye);
        printVector(" --target ", camera.target);
        printVector(" --up ", camera.up);
        std::printf(" fovY %.1f (perspective)\n", camera.fovYDegrees);

        // The exaggeration in sheet pixels.
        const celform::algo::ProjectionFrame frame(camera);
        const auto pixel = [&](const Eigen::Vector3d& p, double* perUnit = nullptr) {
            const Eigen::Vector3d x = frame.project(p);
            if (perUnit)
                *perUnit = frame.scale / x.z();
            return Eigen::Vector2d(x.x(), x.y());
        };
        sheet::Exaggeration field;
        for (std::size_t e = 0; e < ears.size(); ++e) {
            double perUnit = 1.0;
            const Eigen::Vector2d centre = pixel(ears[e], &perUnit);
            field.ears.push_back({centre, kEarRadius * perUnit, kEarGain});
            std::printf("  ear %zu at (%.1f, %.1f) px, sigma %.1f px: %.0f %% larger at one sigma\n", e, centre.x(),
                centre.y(), kEarRadius * perUnit, plain ? 0.0 : 100.0 * kEarGain * std::exp(-0.5));
        }
        sheet::TrunkField trunkField;
        double perUnit = 1.0;
        for (const Eigen::Vector3d& p : trunk)
            trunkField.centreline.push_back(pixel(p, &perUnit));
        trunkField.sigma = kTrunkSigma * perUnit;
        trunkField.stretch = kTrunkStretch;
        field.trunks.push_back(trunkField);
        if (plain)
            field = {};
        const Eigen::Vector2d tip = trunkField.centreline.front();
        const Eigen::Vector2d tipMoved = tip + field.displacement(tip);
        const Eigen::Vector2d base = trunkField.centreline.back();
        std::printf(
            "  trunk tip (%.1f, %.1f) -> (%.1f, %.1f) px, base (%.1f, %.1f) px: %.0f %% farther from the base\n",
            tip.x(), tip.y(), tipMoved.x(), tipMoved.y(), base.x(), base.y(),
            100.0 * ((tipMoved - base).norm() / (tip - base).norm() - 1.0));
        std::printf("  smallest Jacobian determinant of the warp %.3f (positive: no fold)\n",
            sheet::minJacobian(field, camera.width, camera.height, 4));

        // The model's silhouette and inner contours, supersampled, warped by the inverse map.
        RasterCamera big = camera;
        big.width *= kSupersample;
        big.height *= kSupersample;
        celform::algo::GBuffer gbuffer;
        celform::algo::rasterise(mesh.vertices, mesh.faces, Positions(), big, gbuffer);
        const std::vector<std::uint8_t> edges = depthEdges(gbuffer, 0.03);
        const sheet::InverseMap inverse(field, big.width, big.height, kSupersample, 4);
        std::vector<std::uint8_t> figure(gbuffer.faceId.size(), 0);
        std::vector<std::uint8_t> lines(gbuffer.faceId.size(), 0);
        for (int y = 0; y < big.height; ++y)
            for (int x = 0; x < big.width; ++x) {
                const Eigen::Vector2d q = inverse.at(x, y);
                const int sx = int(std::floor(q.x()));
                const int sy = int(std::floor(q.y()));
                if (sx < 0 || sy < 0 || sx >= big.width || sy >= big.height)
                    continue;
                const std::size_t from = std::size_t(sy) * std::size_t(big.width) + std::size_t(sx);
                const std::size_t to = std::size_t(y) * std::size_t(big.width) + std::size_t(x);
                figure[to] = gbuffer.faceId[from] >= 0 ? 1 : 0;
                lines[to] = edges[from];
            }
        sheet::InkSettings ink;
        ink.supersample = kSupersample;
        const celform::algo::DrawingImage drawing = sheet::inkFigure(figure, lines, camera.width, camera.height, ink);
        const QImage image(
            drawing.pixels.data(), drawing.width, drawing.height, drawing.width * 4, QImage::Format_RGBA8888);
        if (!image.save(file, "PNG")) {
            std::fprintf(stderr, "model_sheet: cannot write %s\n", qPrintable(file));
            return 3;
        }
        check(mesh, camera, file);
    }
    return 0;
}
