// Stylized highlights for cel animation (Anjyo & Hiramitsu, "Stylized Highlights for Cartoon
// Rendering and Animation", IEEE CG&A 2003; "the paper" below): the highlight vector field, its
// basic operations, post operations, keyframes, and the per-point mask the renderers evaluate.
//
// Everything here is a few dot products per point, written so that a GLSL mirror can follow it
// line by line: no trigonometry in the per-point path except the one cos/sin pair of a rotation.
#pragma once

#include "celform/algorithms/shading.h"
#include "celform/algorithms/tri_mesh.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace celform::algo {

/// Orthonormal tangent frame at a surface point: du, dv span the tangent plane (the paper's
/// "(u, v) coordinated patch"). Make one with makeTangentFrame or the helpers below; the
/// operations assume du . dv = 0 and both orthogonal to the normal.
struct HighlightFrame {
    Eigen::Vector3f du{1.0f, 0.0f, 0.0f};
    Eigen::Vector3f dv{0.0f, 1.0f, 0.0f};
};

/// Orthonormalises (du, dv) against unit normal: du is projected on the tangent plane and
/// normalised, dv becomes +-(normal x du) keeping the side dv was on (mirrored UV charts stay
/// mirrored). A du parallel to the normal is replaced by the projection of dv turned by -90
/// degrees, and if both degenerate, by the world axis least aligned with the normal.
HighlightFrame makeTangentFrame(const Eigen::Vector3f& normal, const Eigen::Vector3f& du, const Eigen::Vector3f& dv);

/// Frame from a guide direction (a "stroke direction" the artist draws): du = guide projected on
/// the tangent plane, dv = normal x du. Falls back as makeTangentFrame where guide || normal.
HighlightFrame guideTangentFrame(const Eigen::Vector3f& normal, const Eigen::Vector3f& guide);

/// Per-face frames from the mesh's per-corner UVs: du, dv = dP/du, dP/dv of each triangle
/// (#F by 3 each), orthonormalised against the face normal. Faces with degenerate UVs get
/// guideTangentFrame(faceNormal, x axis). Returns false (outputs untouched) without UVs.
bool faceTangentFrames(const TriMesh& mesh, Positions& du, Positions& dv);

/// Per-vertex frames from UVs: the incident faces' dP/du, dP/dv summed with area weights, then
/// orthonormalised against normals (#V by 3, e.g. vertexNormals). Across a UV seam whose charts
/// disagree the average is meaningless: use faceTangentFrames on such patches.
bool vertexTangentFramesFromUvs(const TriMesh& mesh, const Positions& normals, Positions& du, Positions& dv);

/// Per-vertex frames from a guide direction, smoothed over a face patch (the paper's single
/// patch; empty patchFaces = all faces). Each vertex starts from the guide projected on its
/// tangent plane, weighted by the projection's length, and `iterations` rounds of averaging with
/// its patch neighbours smooth the field and fill in where the guide is nearly normal to the
/// surface (an isolated zero such as a sphere's pole, where the projections point radially and cancel, stays a
/// fallback). Vertices outside the patch get zero rows. normals: #V by 3 unit. Returns false on sizes that do not match
/// or a zero guide.
bool guideVertexFrames(const Positions& vertices, const Faces& faces, const Positions& normals,
    const std::vector<std::int32_t>& patchFaces, const Eigen::Vector3f& guide, int iterations, Positions& du,
    Positions& dv);

/// Smoothed unit vertex normals over a face patch (empty patchFaces = all faces), standing in for
/// the paper's smooth surface: its highlights live on a smooth (u, v) coordinated patch, where
/// (N, H) > 1 - epsilon is a clean area that the operations reshape; on a polygon model with noisy
/// vertex normals the same threshold gives blotchy, polygonal pieces on nearly flat parts. Each
/// vertex starts from its normal made unit, and `iterations` rounds (0: the normals as they are)
/// average it with its neighbours along the patch's edges, with the uniform weights of
/// guideVertexFrames, and make it unit again. Vertices outside the patch get zero rows.
/// normals: #V by 3. Returns false on sizes that do not match or faces out of range.
bool smoothPatchNormals(const Positions& vertices, const Faces& faces, const Positions& normals,
    const std::vector<std::int32_t>& patchFaces, int iterations, Positions& smoothed);

/// The paper's basic operations on a highlight vector H, applied in list order.
enum class HighlightOperationType {
    Translation, ///< a = alpha, b = beta: H + alpha du + beta dv
    Rotation, ///< a = angle in degrees, du turning towards dv: turns the frame of later operations
    DirectionalScaling, ///< a = delta in [0, 1]: eq. 4, stretches the area along du
    Split, ///< a = gamma1, b = gamma2 >= 0: cuts the area across du / dv
    Squaring, ///< a = sigma in [0, 1], b = n >= 1 (an integer in the paper)
    ///< The area becomes a rounded square along du, dv (reading of the printed formula in
    ///< highlights.cpp); around sigma 0.2 (n = 2) it is squarest, larger sigma or n pull the
    ///< corners out along the diagonals towards a four-pointed star.
};

struct HighlightOperation {
    HighlightOperationType type = HighlightOperationType::Translation;
    float a = 0.0f;
    float b = 0.0f;

    static HighlightOperation translation(float alpha, float beta)
    {
        return {HighlightOperationType::Translation, alpha, beta};
    }
    static HighlightOperation rotation(float degrees) { return {HighlightOperationType::Rotation, degrees, 0.0f}; }
    static HighlightOperation directionalScaling(float delta)
    {
        return {HighlightOperationType::DirectionalScaling, delta, 0.0f};
    }
    static HighlightOperation split(float gamma1, float gamma2)
    {
        return {HighlightOperationType::Split, gamma1, gamma2};
    }
    static HighlightOperation squaring(float sigma, float n) { return {HighlightOperationType::Squaring, sigma, n}; }
    bool operator==(const HighlightOperation& o) const { return type == o.type && a == o.a && b == o.b; }
};

/// One highlight area H*[epsilon] (paper eq. 3): the original highlight (eq. 1) with the
/// operations applied to its vector field.
struct HighlightShape {
    float epsilon = 0.05f; ///< area where (N, H) > 1 - epsilon, 0 < epsilon << 1
    std::vector<HighlightOperation> operations;
    bool operator==(const HighlightShape& o) const { return epsilon == o.epsilon && operations == o.operations; }
};

/// Post operations on areas (paper, "Post operations", figure 6): sum and subtraction, each
/// operand with its own epsilon.
enum class HighlightBoolean { Union, Subtraction };

struct HighlightCombination {
    HighlightBoolean mode = HighlightBoolean::Union;
    HighlightShape shape;
    bool operator==(const HighlightCombination& o) const { return mode == o.mode && shape == o.shape; }
};

/// A highlight layer: shape, then its combinations left to right ((A u B) \ C ...), then the
/// off-specular cut, painted in one uniform colour (paper: "usually white").
struct HighlightLayer {
    std::string name;
    Color color{1.0f, 1.0f, 1.0f};
    HighlightShape shape;
    std::vector<HighlightCombination> combinations;
    /// Off-specular cut (the paper names it without defining it; our reading): no highlight where
    /// (N, L) <= offSpecularCut, i.e. where the key light cannot reach, which operations that
    /// move the virtual light (translation) can otherwise reach. -1 disables the cut.
    float offSpecularCut = -1.0f;
    bool operator==(const HighlightLayer& o) const
    {
        return name == o.name && color == o.color && shape == o.shape && combinations == o.combinations
            && offSpecularCut == o.offSpecularCut;
    }
};

/// The key light, as RenderLook has it.
struct HighlightLight {
    bool point = false;
    Eigen::Vector3f vector{0.0f, 0.0f, 1.0f}; ///< towards the light (directional) or its position (point)
};

/// A surface point: position, unit normal, tangent frame.
struct HighlightSurfacePoint {
    Eigen::Vector3f position = Eigen::Vector3f::Zero();
    Eigen::Vector3f normal{0.0f, 0.0f, 1.0f};
    HighlightFrame frame;
};

/// How position and normal change across one pixel (screen x and y), for anti-aliased edges.
/// A threshold on (N, H) needs the rate of change of (N, H), not just a pixel size: the mask
/// edge is box-filtered over |d Phi / dx| + |d Phi / dy| (what GLSL's fwidth(phi) gives).
struct HighlightFootprint {
    Eigen::Vector3f dPdx = Eigen::Vector3f::Zero();
    Eigen::Vector3f dPdy = Eigen::Vector3f::Zero();
    Eigen::Vector3f dNdx = Eigen::Vector3f::Zero();
    Eigen::Vector3f dNdy = Eigen::Vector3f::Zero();
};

/// Coverage of all layers and the colour to paint: final = mix(shaded, color, coverage).
struct HighlightSample {
    float coverage = 0.0f;
    Color color{0.0f, 0.0f, 0.0f};
};

/// Highlight layers painted one over another, later layers over earlier ones ("over" with
/// premultiplied colour): the one compositing of layers, for evaluateHighlights and the renderer.
class HighlightCompositor {
public:
    void paintOver(const Color& color, float coverage)
    {
        m_premultiplied = m_premultiplied * (1.0f - coverage) + color * coverage;
        m_coverage = coverage + m_coverage * (1.0f - coverage);
    }
    /// The layers so far: their joint coverage and the colour under it (unpremultiplied).
    [[nodiscard]] HighlightSample sample() const
    {
        HighlightSample result;
        result.coverage = m_coverage;
        if (m_coverage > 0.0f)
            result.color = m_premultiplied / m_coverage;
        return result;
    }

private:
    float m_coverage = 0.0f;
    Color m_premultiplied = Color::Zero();
};

/// The original highlight vector (paper eqs. 1-3, Blinn with ks = 1, n = 1): the unit halfway
/// vector of the unit vectors to the light and to the eye. Zero where they are opposite.
Eigen::Vector3f halfwayVector(const Eigen::Vector3f& position, const HighlightLight& light, const Eigen::Vector3f& eye);

/// The highlight vector after the operations (in order), starting from H at a point with this
/// frame. Unit, or zero where an operation cancelled it. The normal is not needed: every
/// operation adds tangent vectors only, so (N, H) changes through the normalisation alone.
Eigen::Vector3f applyHighlightOperations(
    const Eigen::Vector3f& halfway, const HighlightFrame& frame, const std::vector<HighlightOperation>& operations);

/// Paper eq. 2: Phi(p, N, H) = (N, H) for the shape's vector field; the point is in the area iff
/// Phi > 1 - epsilon (eq. 3).
float highlightFunction(const Eigen::Vector3f& halfway, const Eigen::Vector3f& normal, const HighlightFrame& frame,
    const HighlightShape& shape);

/// Coverage in [0, 1] of one layer at a point: 0/1 without footprint, box-filtered edges with.
float layerCoverage(const HighlightSurfacePoint& point, const HighlightLight& light, const Eigen::Vector3f& eye,
    const HighlightLayer& layer, const HighlightFootprint* footprint = nullptr);

/// All layers at a point, later layers painted over earlier ones.
HighlightSample evaluateHighlights(const HighlightSurfacePoint& point, const HighlightLight& light,
    const Eigen::Vector3f& eye, const std::vector<HighlightLayer>& layers,
    const HighlightFootprint* footprint = nullptr);

/// A layer's parameters at a frame (paper, "Making highlight animation").
struct HighlightKey {
    double frame = 0.0;
    HighlightLayer layer;
    bool operator==(const HighlightKey& o) const { return frame == o.frame && layer == o.layer; }
};

/// True iff a and b have the same operation types and combination modes in the same order, so
/// their parameters can be interpolated.
bool sameHighlightStructure(const HighlightLayer& a, const HighlightLayer& b);

/// Linear interpolation of every parameter (epsilons, colour, operation parameters, cut) between
/// the keys around frame; keys sorted by frame; held constant before the first and after the last
/// key. Between keys of different structure the earlier key holds. nullopt without keys.
std::optional<HighlightLayer> interpolateHighlightKeys(const std::vector<HighlightKey>& keys, double frame);

} // namespace celform::algo
