// Stylized highlights (Anjyo & Hiramitsu 2003, "the paper"): the highlight vector field and its
// operations, tangent frames, post operations, keyframe interpolation. See highlights.h.
#include "celform/algorithms/highlights.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace celform::algo {

namespace {

using Eigen::Vector3f;

constexpr float kDegToRad = 0.0174532925f;
/// Squared lengths below this count as zero (unit vectors in float).
constexpr float kTiny = 1e-12f;

Vector3f safeNormalized(const Vector3f& v)
{
    const float n2 = v.squaredNorm();
    return n2 > kTiny ? Vector3f(v / std::sqrt(n2)) : Vector3f::Zero();
}

/// The paper's signature function for split: sgn[0] = 1, x / |x| otherwise.
float paperSign(float x)
{
    return x >= 0.0f ? 1.0f : -1.0f;
}

Vector3f leastAlignedAxis(const Vector3f& n)
{
    const Vector3f a = n.cwiseAbs();
    if (a.x() <= a.y() && a.x() <= a.z())
        return Vector3f::UnitX();
    return a.y() <= a.z() ? Vector3f::UnitY() : Vector3f::UnitZ();
}

Vector3f towardsLight(const Vector3f& position, const HighlightLight& light)
{
    return safeNormalized(light.point ? Vector3f(light.vector - position) : light.vector);
}

float lerp(float a, float b, float t)
{
    return a + (b - a) * t;
}

/// Everything the mask needs at one sample of the footprint.
struct Sample {
    Vector3f normal;
    HighlightFrame frame;
    Vector3f halfway;
    float lambert; // (N, L), for the off-specular cut
};

Sample makeSample(const Vector3f& position, const Vector3f& normal, const HighlightFrame& frame,
    const HighlightLight& light, const Vector3f& eye)
{
    Sample s;
    s.normal = safeNormalized(normal);
    s.frame = makeTangentFrame(s.normal, frame.du, frame.dv);
    s.halfway = halfwayVector(position, light, eye);
    s.lambert = s.normal.dot(towardsLight(position, light));
    return s;
}

/// Coverage of "value > threshold": a step without footprint; with one, the step box-filtered
/// over the change of the value across the pixel (fwidth in GLSL).
float edgeCoverage(float value, float valueX, float valueY, float threshold, bool filtered)
{
    const float margin = value - threshold;
    const float width = filtered ? std::abs(valueX - value) + std::abs(valueY - value) : 0.0f;
    if (!(width > 0.0f))
        return margin > 0.0f ? 1.0f : 0.0f;
    return std::clamp(margin / width + 0.5f, 0.0f, 1.0f);
}

float shapeCoverage(const HighlightShape& shape, const Sample& s0, const Sample& sx, const Sample& sy, bool filtered)
{
    const float threshold = 1.0f - shape.epsilon; // eq. 3
    const float phi = highlightFunction(s0.halfway, s0.normal, s0.frame, shape);
    if (!filtered)
        return edgeCoverage(phi, phi, phi, threshold, false);
    return edgeCoverage(phi, highlightFunction(sx.halfway, sx.normal, sx.frame, shape),
        highlightFunction(sy.halfway, sy.normal, sy.frame, shape), threshold, true);
}

void lerpShape(HighlightShape& out, const HighlightShape& a, const HighlightShape& b, float t)
{
    out.epsilon = lerp(a.epsilon, b.epsilon, t);
    for (size_t i = 0; i < out.operations.size(); ++i) {
        out.operations[i].a = lerp(a.operations[i].a, b.operations[i].a, t);
        out.operations[i].b = lerp(a.operations[i].b, b.operations[i].b, t);
    }
}

bool sameOperationTypes(const HighlightShape& a, const HighlightShape& b)
{
    if (a.operations.size() != b.operations.size())
        return false;
    for (size_t i = 0; i < a.operations.size(); ++i)
        if (a.operations[i].type != b.operations[i].type)
            return false;
    return true;
}

} // namespace

HighlightFrame makeTangentFrame(const Vector3f& normal, const Vector3f& du, const Vector3f& dv)
{
    const Vector3f n = safeNormalized(normal);
    Vector3f u = du - du.dot(n) * n;
    if (u.squaredNorm() <= kTiny) {
        // For a right-handed frame dv = n x du, so du = dv x n.
        const Vector3f w = dv - dv.dot(n) * n;
        u = w.squaredNorm() > kTiny ? Vector3f(w.cross(n)) : Vector3f::Zero();
    }
    if (u.squaredNorm() <= kTiny) {
        const Vector3f axis = leastAlignedAxis(n);
        u = axis - axis.dot(n) * n;
    }
    u.normalize();
    const Vector3f c = n.cross(u);
    return {u, c.dot(dv) < 0.0f ? Vector3f(-c) : c};
}

HighlightFrame guideTangentFrame(const Vector3f& normal, const Vector3f& guide)
{
    return makeTangentFrame(normal, guide, normal.cross(guide));
}

namespace {

/// dP/du and dP/dv of face f from its corner UVs (the usual tangent-space solve); false where
/// the UV triangle is degenerate.
bool faceUvDerivatives(const TriMesh& mesh, Eigen::Index f, Vector3f& tu, Vector3f& tv)
{
    const Vector3f p0 = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Vector3f e1 = mesh.vertices.row(mesh.faces(f, 1)).transpose() - p0;
    const Vector3f e2 = mesh.vertices.row(mesh.faces(f, 2)).transpose() - p0;
    const Eigen::Vector2f t0 = mesh.uvs.row(mesh.uvFaces(f, 0)).transpose();
    const Eigen::Vector2f a = mesh.uvs.row(mesh.uvFaces(f, 1)).transpose() - t0;
    const Eigen::Vector2f b = mesh.uvs.row(mesh.uvFaces(f, 2)).transpose() - t0;
    const float det = a.x() * b.y() - b.x() * a.y();
    if (!(std::abs(det) > 1e-20f))
        return false;
    tu = (e1 * b.y() - e2 * a.y()) / det;
    tv = (e2 * a.x() - e1 * b.x()) / det;
    return true;
}

Vector3f faceNormal(const TriMesh& mesh, Eigen::Index f)
{
    const Vector3f p0 = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Vector3f e1 = mesh.vertices.row(mesh.faces(f, 1)).transpose() - p0;
    const Vector3f e2 = mesh.vertices.row(mesh.faces(f, 2)).transpose() - p0;
    const Vector3f n = safeNormalized(e1.cross(e2));
    return n.squaredNorm() > 0.0f ? n : Vector3f::UnitZ();
}

} // namespace

bool faceTangentFrames(const TriMesh& mesh, Positions& du, Positions& dv)
{
    if (!mesh.hasUvs())
        return false;
    const Eigen::Index nf = mesh.faceCount();
    du.resize(nf, 3);
    dv.resize(nf, 3);
    for (Eigen::Index f = 0; f < nf; ++f) {
        const Vector3f n = faceNormal(mesh, f);
        Vector3f tu, tv;
        const HighlightFrame frame = faceUvDerivatives(mesh, f, tu, tv) ? makeTangentFrame(n, tu, tv)
                                                                        : guideTangentFrame(n, Vector3f::UnitX());
        du.row(f) = frame.du.transpose();
        dv.row(f) = frame.dv.transpose();
    }
    return true;
}

bool vertexTangentFramesFromUvs(const TriMesh& mesh, const Positions& normals, Positions& du, Positions& dv)
{
    if (!mesh.hasUvs() || normals.rows() != mesh.vertexCount())
        return false;
    const Eigen::Index nv = mesh.vertexCount();
    Positions su = Positions::Zero(nv, 3);
    Positions sv = Positions::Zero(nv, 3);
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
        Vector3f tu, tv;
        if (!faceUvDerivatives(mesh, f, tu, tv))
            continue;
        const Vector3f p0 = mesh.vertices.row(mesh.faces(f, 0)).transpose();
        const float area = 0.5f
            * (mesh.vertices.row(mesh.faces(f, 1)).transpose() - p0)
                  .cross(mesh.vertices.row(mesh.faces(f, 2)).transpose() - p0)
                  .norm();
        // Directions only, weighted by area: UV scale differs from chart to chart.
        const Vector3f wu = safeNormalized(tu) * area;
        const Vector3f wv = safeNormalized(tv) * area;
        for (int c = 0; c < 3; ++c) {
            su.row(mesh.faces(f, c)) += wu.transpose();
            sv.row(mesh.faces(f, c)) += wv.transpose();
        }
    }
    du.resize(nv, 3);
    dv.resize(nv, 3);
    for (Eigen::Index i = 0; i < nv; ++i) {
        const HighlightFrame frame
            = makeTangentFrame(normals.row(i).transpose(), su.row(i).transpose(), sv.row(i).transpose());
        du.row(i) = frame.du.transpose();
        dv.row(i) = frame.dv.transpose();
    }
    return true;
}

namespace {

/// A face patch as a graph: the vertices of its faces and their neighbours along its edges.
struct PatchGraph {
    std::vector<std::vector<std::int32_t>> neighbours; ///< per vertex, empty outside the patch
    std::vector<char> inPatch; ///< per vertex
};

/// The graph of patchFaces (all faces when empty); false for a face or vertex out of range.
bool buildPatchGraph(
    const Faces& faces, Eigen::Index vertexCount, const std::vector<std::int32_t>& patchFaces, PatchGraph& graph)
{
    std::vector<std::int32_t> patch = patchFaces;
    if (patch.empty()) {
        patch.resize(static_cast<size_t>(faces.rows()));
        for (size_t f = 0; f < patch.size(); ++f)
            patch[f] = static_cast<std::int32_t>(f);
    }
    // Each edge seen from both faces: duplicates only add weight to interior edges, which is
    // harmless for a smoothing step.
    graph.neighbours.assign(static_cast<size_t>(vertexCount), {});
    graph.inPatch.assign(static_cast<size_t>(vertexCount), 0);
    for (const std::int32_t f : patch) {
        if (f < 0 || f >= faces.rows())
            return false;
        for (int c = 0; c < 3; ++c) {
            const std::int32_t a = faces(f, c);
            const std::int32_t b = faces(f, (c + 1) % 3);
            if (a < 0 || a >= vertexCount || b < 0 || b >= vertexCount)
                return false;
            graph.inPatch[static_cast<size_t>(a)] = 1;
            graph.neighbours[static_cast<size_t>(a)].push_back(b);
            graph.neighbours[static_cast<size_t>(b)].push_back(a);
        }
    }
    return true;
}

/// Uniform mean of row i of d and its neighbours' rows.
Vector3f ringMean(const Positions& d, Eigen::Index i, const std::vector<std::int32_t>& ring)
{
    Vector3f sum = d.row(i).transpose();
    for (const std::int32_t j : ring)
        sum += d.row(j).transpose();
    return sum / static_cast<float>(ring.size() + 1);
}

/// `iterations` rounds of moving each patch vertex's row to the mean of its ring (itself and its
/// patch neighbours); settle(i, mean) adjusts the mean in place and returns false to keep the
/// old row.
template <typename Settle> void smoothOverPatch(Positions& d, const PatchGraph& graph, int iterations, Settle settle)
{
    for (int it = 0; it < iterations; ++it) {
        Positions next = d;
        for (Eigen::Index i = 0; i < d.rows(); ++i) {
            const auto& ring = graph.neighbours[static_cast<size_t>(i)];
            if (ring.empty())
                continue;
            Vector3f mean = ringMean(d, i, ring);
            if (settle(i, mean))
                next.row(i) = mean.transpose();
        }
        d.swap(next);
    }
}

} // namespace

bool guideVertexFrames(const Positions& vertices, const Faces& faces, const Positions& normals,
    const std::vector<std::int32_t>& patchFaces, const Vector3f& guide, int iterations, Positions& du, Positions& dv)
{
    const Eigen::Index nv = vertices.rows();
    PatchGraph graph;
    if (normals.rows() != nv || !(guide.squaredNorm() > kTiny) || !buildPatchGraph(faces, nv, patchFaces, graph))
        return false;
    const Vector3f g = guide.normalized();
    // Unnormalised projections: their length (sin of the angle to the normal) is the weight.
    Positions d = Positions::Zero(nv, 3);
    for (Eigen::Index i = 0; i < nv; ++i)
        if (graph.inPatch[static_cast<size_t>(i)]) {
            const Vector3f n = normals.row(i).transpose();
            d.row(i) = (g - g.dot(n) * n).transpose();
        }
    smoothOverPatch(d, graph, iterations, [&](Eigen::Index i, Vector3f& mean) {
        const Vector3f n = normals.row(i).transpose();
        mean -= mean.dot(n) * n;
        return true;
    });
    du = Positions::Zero(nv, 3);
    dv = Positions::Zero(nv, 3);
    for (Eigen::Index i = 0; i < nv; ++i)
        if (graph.inPatch[static_cast<size_t>(i)]) {
            const HighlightFrame frame = guideTangentFrame(normals.row(i).transpose(), d.row(i).transpose());
            du.row(i) = frame.du.transpose();
            dv.row(i) = frame.dv.transpose();
        }
    return true;
}

bool smoothPatchNormals(const Positions& vertices, const Faces& faces, const Positions& normals,
    const std::vector<std::int32_t>& patchFaces, int iterations, Positions& smoothed)
{
    const Eigen::Index nv = vertices.rows();
    PatchGraph graph;
    if (normals.rows() != nv || !buildPatchGraph(faces, nv, patchFaces, graph))
        return false;
    Positions d = Positions::Zero(nv, 3);
    for (Eigen::Index i = 0; i < nv; ++i)
        if (graph.inPatch[static_cast<size_t>(i)])
            d.row(i) = safeNormalized(normals.row(i).transpose()).transpose();
    smoothOverPatch(d, graph, iterations, [](Eigen::Index, Vector3f& mean) {
        // Where the neighbourhood's normals cancel (a fold), the vertex keeps its own.
        mean = safeNormalized(mean);
        return mean.squaredNorm() > 0.0f;
    });
    smoothed.swap(d);
    return true;
}

Vector3f halfwayVector(const Vector3f& position, const HighlightLight& light, const Vector3f& eye)
{
    // Paper eq. 3 with Figure 3: H = (L + V) / |L + V|, L and V unit vectors from the point.
    const Vector3f l = towardsLight(position, light);
    const Vector3f v = safeNormalized(eye - position);
    return safeNormalized(l + v);
}

Vector3f applyHighlightOperations(
    const Vector3f& halfway, const HighlightFrame& frame, const std::vector<HighlightOperation>& operations)
{
    Vector3f h = halfway;
    Vector3f du = frame.du;
    Vector3f dv = frame.dv;
    for (const HighlightOperation& op : operations) {
        switch (op.type) {
        case HighlightOperationType::Translation:
            // Paper, "Translation": H' = H + alpha du + beta dv, t(H) = H' / |H'|. The area moves
            // towards +du for alpha > 0: (N, H') = (N, H), and |H'| is smallest where H leans
            // towards -du, i.e. where the normal has turned towards +du.
            h = safeNormalized(h + op.a * du + op.b * dv);
            break;
        case HighlightOperationType::Rotation: {
            // Paper, "Rotation": the 2D rotation of the (u, v) coordinate system. H itself does not
            // change (rotating H about N as well would leave every later (N, H) as it was: all
            // operations read H in frame coordinates), so alone it leaves the area untouched; it
            // turns the directions the following operations act along.
            const float c = std::cos(op.a * kDegToRad);
            const float s = std::sin(op.a * kDegToRad);
            const Vector3f u = c * du + s * dv;
            dv = c * dv - s * du;
            du = u;
            break;
        }
        case HighlightOperationType::DirectionalScaling:
            // Paper eq. 4: H'' = H - delta (H, du) du, s(H) = H'' / |H''|. (N, H'') = (N, H) and
            // |H''| <= 1, so the new area contains the original one and stretches along du.
            h = safeNormalized(h - op.a * h.dot(du) * du);
            break;
        case HighlightOperationType::Split:
            // Paper, "Split": H = H - gamma1 sgn[(H, du)] du - gamma2 sgn[(H, dv)] dv, sgn[0] = 1.
            // Our reading: on each side of the curve (H, du) = 0 through the highlight's centre
            // the field is translated by gamma1 away from it, so each half holds a copy of the
            // area moved outwards (centred where (H, du) = +-gamma1). Where the halves meet the
            // tangential part is at least gamma1, so the pieces separate once
            // 1 / sqrt(1 + gamma^2) <= 1 - epsilon, i.e. gamma >= sqrt(1 / (1 - epsilon)^2 - 1)
            // (0.33 for epsilon = 0.05); a smaller gamma only pinches the area in the middle.
            h = safeNormalized(h - op.a * paperSign(h.dot(du)) * du - op.b * paperSign(h.dot(dv)) * dv);
            break;
        case HighlightOperationType::Squaring: {
            // Paper, "Squaring", as printed: theta = min(acos(H, du), acos(H, dv)),
            // sqrnorm = sin(2 theta)^n, H^ = H - sigma sqrnorm ((H, du) du + (H, dv) dv).
            // Read literally, theta is the angle of the whole 3D H to du, about 90 degrees near
            // any highlight (H is close to N there), so sqrnorm ~ 0 and nothing happens. The
            // stated intent (square along du and dv, sharper for larger n, sigma the magnitude)
            // follows when theta is the angle of H's tangential part (H, du) du + (H, dv) dv to
            // the du and dv axes: then sqrnorm is 0 along the axes and 1 on the diagonals, and
            //   |sin 2 theta| = 2 |(H, du)(H, dv)| / ((H, du)^2 + (H, dv)^2)
            // for every quadrant (the absolute value also covers the third quadrant, where the
            // printed min() gives theta = 135 degrees and a negative sin). Shrinking the tangential
            // part by the factor 1 - sigma sqrnorm lets the area reach further along the
            // diagonals: in tangential terms its radius becomes r / (1 - sigma |sin 2 theta|^n), a
            // rounded square with corners on the diagonals; larger n concentrates the push on the
            // diagonals (sharper corners), sigma sets how far the corners go.
            const float hu = h.dot(du);
            const float hv = h.dot(dv);
            const float t2 = hu * hu + hv * hv;
            const float sin2 = t2 > kTiny ? 2.0f * std::abs(hu * hv) / t2 : 0.0f;
            const float sqrnorm = std::pow(sin2, std::max(op.b, 1.0f));
            h = safeNormalized(h - op.a * sqrnorm * (hu * du + hv * dv));
            break;
        }
        }
    }
    return h;
}

float highlightFunction(
    const Vector3f& halfway, const Vector3f& normal, const HighlightFrame& frame, const HighlightShape& shape)
{
    // Paper eq. 2: Phi(p, N, H) = (N(p), H(p)).
    return normal.dot(applyHighlightOperations(halfway, frame, shape.operations));
}

float layerCoverage(const HighlightSurfacePoint& point, const HighlightLight& light, const Vector3f& eye,
    const HighlightLayer& layer, const HighlightFootprint* footprint)
{
    const bool filtered = footprint != nullptr;
    const Sample s0 = makeSample(point.position, point.normal, point.frame, light, eye);
    Sample sx = s0;
    Sample sy = s0;
    if (filtered) {
        // The frame follows the neighbouring normal; its own change across a pixel is ignored.
        sx = makeSample(point.position + footprint->dPdx, point.normal + footprint->dNdx, s0.frame, light, eye);
        sy = makeSample(point.position + footprint->dPdy, point.normal + footprint->dNdy, s0.frame, light, eye);
    }
    float coverage = shapeCoverage(layer.shape, s0, sx, sy, filtered);
    // Paper, "Post operations": sum and subtraction of areas, each with its own epsilon. On 0/1
    // masks max / min(a, 1 - b) are exactly union and subtraction; on filtered edges they are the
    // usual fuzzy-set versions.
    for (const HighlightCombination& combination : layer.combinations) {
        const float other = shapeCoverage(combination.shape, s0, sx, sy, filtered);
        coverage = combination.mode == HighlightBoolean::Union ? std::max(coverage, other)
                                                               : std::min(coverage, 1.0f - other);
    }
    if (layer.offSpecularCut > -1.0f)
        coverage = std::min(coverage, edgeCoverage(s0.lambert, sx.lambert, sy.lambert, layer.offSpecularCut, filtered));
    return coverage;
}

HighlightSample evaluateHighlights(const HighlightSurfacePoint& point, const HighlightLight& light, const Vector3f& eye,
    const std::vector<HighlightLayer>& layers, const HighlightFootprint* footprint)
{
    HighlightCompositor layersSoFar;
    for (const HighlightLayer& layer : layers)
        layersSoFar.paintOver(layer.color, layerCoverage(point, light, eye, layer, footprint));
    return layersSoFar.sample();
}

bool sameHighlightStructure(const HighlightLayer& a, const HighlightLayer& b)
{
    if (!sameOperationTypes(a.shape, b.shape) || a.combinations.size() != b.combinations.size())
        return false;
    for (size_t i = 0; i < a.combinations.size(); ++i)
        if (a.combinations[i].mode != b.combinations[i].mode
            || !sameOperationTypes(a.combinations[i].shape, b.combinations[i].shape))
            return false;
    return true;
}

std::optional<HighlightLayer> interpolateHighlightKeys(const std::vector<HighlightKey>& keys, double frame)
{
    if (keys.empty())
        return std::nullopt;
    assert(std::is_sorted(
        keys.begin(), keys.end(), [](const HighlightKey& x, const HighlightKey& y) { return x.frame < y.frame; }));
    // Held outside the keyed range.
    if (!(frame > keys.front().frame))
        return keys.front().layer;
    if (!(frame < keys.back().frame))
        return keys.back().layer;
    // First key after frame; keys[next - 1].frame <= frame < keys[next].frame.
    const auto after = std::upper_bound(
        keys.begin(), keys.end(), frame, [](double f, const HighlightKey& k) { return f < k.frame; });
    const HighlightKey& k1 = *after;
    const HighlightKey& k0 = *(after - 1);
    if (!sameHighlightStructure(k0.layer, k1.layer) || !(k1.frame > k0.frame))
        return k0.layer;
    // Paper, "Making highlight animation": the operations' parameters linearly interpolated.
    const float t = static_cast<float>((frame - k0.frame) / (k1.frame - k0.frame));
    HighlightLayer out = k0.layer;
    out.color = k0.layer.color + (k1.layer.color - k0.layer.color) * t;
    lerpShape(out.shape, k0.layer.shape, k1.layer.shape, t);
    for (size_t i = 0; i < out.combinations.size(); ++i)
        lerpShape(out.combinations[i].shape, k0.layer.combinations[i].shape, k1.layer.combinations[i].shape, t);
    out.offSpecularCut = lerp(k0.layer.offSpecularCut, k1.layer.offSpecularCut, t);
    return out;
}

} // namespace celform::algo
