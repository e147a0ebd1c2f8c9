// The CPU G-buffer rasteriser of the display-free renderer (DESIGN.md, "Rendering"): position,
// normal, depth and face id per pixel, plus anti-aliased, depth-tested line drawing.
#pragma once

#include "celform/algorithms/image.h"
#include "celform/algorithms/lines.h"
#include "celform/algorithms/tri_mesh.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace celform::algo {

/// A pinhole or orthographic camera for an image of width x height pixels. horizontalShift
/// moves the frustum sideways (off-axis stereo), as a fraction of the image width.
struct RasterCamera {
    Eigen::Vector3d eye{0, 0, 5};
    Eigen::Vector3d target{0, 0, 0};
    Eigen::Vector3d up{0, 1, 0};
    bool orthographic = false;
    double fovYDegrees = 30.0; ///< perspective
    double orthoHeight = 2.0; ///< orthographic, model units
    int width = 640;
    int height = 480;
    double horizontalShift = 0.0;

    /// Model point to (pixel x, pixel y, depth), pixel centres at +0.5, y down; depth is the
    /// distance along the view axis (negative or zero behind the eye). With p = point - eye and the
    /// right-handed frame below: perspective x = w/2 + shift*w + f (p.right)/(p.forward),
    /// y = h/2 - f (p.trueUp)/(p.forward), f = (h/2) / tan(fovY/2); orthographic the same with
    /// f / (p.forward) replaced by h / orthoHeight.
    [[nodiscard]] Eigen::Vector3d project(const Eigen::Vector3d& point) const;
    /// The ray through a pixel position: origin and unit direction (the inverse of project: the
    /// eye for perspective, a point on the plane through the eye for orthographic cameras).
    void ray(double x, double y, Eigen::Vector3d& origin, Eigen::Vector3d& direction) const;
    [[nodiscard]] Eigen::Vector3d forward() const; ///< normalize(target - eye)
    [[nodiscard]] Eigen::Vector3d right() const; ///< normalize(forward x up)
    [[nodiscard]] Eigen::Vector3d trueUp() const; ///< right x forward
};

/// A camera reduced to what projection needs, computed once for many points (RasterCamera::project
/// builds one per call): an orthonormal frame and the pixel mapping, with the same arithmetic, so
/// the same results to the bit.
struct ProjectionFrame {
    Eigen::Vector3d eye;
    Eigen::Vector3d forward;
    Eigen::Vector3d right;
    Eigen::Vector3d up; ///< the true up (RasterCamera::trueUp)
    double scale = 1.0; ///< perspective: focal length in pixels; orthographic: pixels per model unit
    double cx = 0.0; ///< pixel x of the view axis (includes the off-axis shift)
    double cy = 0.0;
    bool orthographic = false;

    explicit ProjectionFrame(const RasterCamera& c);
    /// Camera-space coordinates: (along right, along true up, along forward = depth).
    [[nodiscard]] Eigen::Vector3d toCamera(const Eigen::Vector3d& point) const
    {
        const Eigen::Vector3d p = point - eye;
        return {p.dot(right), p.dot(up), p.dot(forward)};
    }
    [[nodiscard]] double pixelX(const Eigen::Vector3d& c) const
    {
        return orthographic ? cx + scale * c.x() : cx + scale * c.x() / c.z();
    }
    [[nodiscard]] double pixelY(const Eigen::Vector3d& c) const
    {
        return orthographic ? cy - scale * c.y() : cy - scale * c.y() / c.z();
    }
    /// (pixel x, pixel y, depth along the view axis), as RasterCamera::project.
    [[nodiscard]] Eigen::Vector3d project(const Eigen::Vector3d& point) const
    {
        const Eigen::Vector3d c = toCamera(point);
        return {pixelX(c), pixelY(c), c.z()};
    }
    /// The model point at pixel (x, y) and depth: the inverse of project.
    [[nodiscard]] Eigen::Vector3d unproject(double x, double y, double depth) const;
};

/// Per-pixel surface data; faceId -1 and depth +infinity where no triangle covers the pixel
/// centre. Normals are interpolated vertex normals (perspective-correct), positions model space.
struct GBuffer {
    int width = 0;
    int height = 0;
    std::vector<float> depth;
    std::vector<std::int32_t> faceId;
    std::vector<Eigen::Vector3f> position;
    std::vector<Eigen::Vector3f> normal;
    std::vector<Eigen::Vector3f> barycentric; ///< of the covering face, perspective-correct
    /// Made instead of position (rasterise's positions false): 1 where the pixel's normal points
    /// away from the eye, normal . (eye - point) < 0 with the point position would hold and the
    /// eye in float, else 0 (and off the mesh). Empty when position is made.
    std::vector<std::uint8_t> facesAway;
};

/// Rasterises shape (with per-vertex normals) into the G-buffer: pixel-centre sampling,
/// top-left fill rule, depth test, deterministic (the same inputs give the same bytes).
/// - Coverage: vertices snapped to 1/256 pixel, exact integer edge functions; a centre on an
///   edge belongs to the triangle for which that edge is a top or left edge, so meshes cover
///   every pixel once, without cracks. Interpolation uses the unsnapped positions.
/// - Triangles crossing the near plane (1e-5 x the shape's bounding-box diagonal in front of the
///   eye, orthographic cameras too) or reaching beyond a +/-32768-pixel guard band are clipped
///   in camera space; the visible part is drawn. Faces with non-finite vertices are skipped.
/// - Depth test: strictly nearer (float depth) wins, ties go to the lower face id.
/// - Back faces are drawn like front faces (closed meshes hide them by depth); their normals are
///   the interpolated vertex normals as given, not flipped towards the camera.
/// - vertexNormals: #V by 3, or empty to use the geometric face normal.
/// Single-threaded; position, normal and barycentric are zero where faceId is -1.
/// positions false leaves GBuffer::position empty and makes GBuffer::facesAway instead, all a
/// shading with a directional light asks of the point: 11 bytes a pixel less to write and, in a
/// sequence's first frame, to fault in (issue 29: 23 MB at 1920x1080).
void rasterise(const Positions& shape, const Faces& faces, const Positions& vertexNormals, const RasterCamera& camera,
    GBuffer& out, bool positions = true);

/// Draws styled strokes anti-aliased into coverage (single channel, width * height, values in
/// [0, 1], combined with max), hiding the parts behind the surface: a line sample is kept where
/// its depth is not farther than the G-buffer depth there (plus a relative bias), or off the mesh.
/// Each segment is a capsule sampled at pixel centres: coverage = clamp(width/2 + 0.5 - distance,
/// 0, 1), width and depth interpolated linearly at the closest point of the segment (round caps
/// give round joins). Kept where faceId == -1 or depth <= gbufferDepth * (1 + depthBias) + 1e-6.
/// coverage is reset to zeros when its size is not width * height.
void drawStrokes(const std::vector<StyledStroke>& strokes, const GBuffer& gbuffer, std::vector<float>& coverage,
    float depthBias = 0.01f);

} // namespace celform::algo
