// Feature lines and stereo composition of the viewport: the offline renderer's strokes (same
// extraction, chaining and style) drawn over the GL frame, hidden-line tested against its depth.
#pragma once

#include "celform/algorithms/image.h"
#include "celform/algorithms/lines.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/ridge_snakes.h"
#include "celform/algorithms/stereo.h"
#include "celform/algorithms/tri_mesh.h"

#include <QImage>
#include <QRect>

#include <cstdint>
#include <vector>

namespace celform::views {

/// One eye's (or the mono) frame read back from GL: colour as 8-bit sRGB (row 0 at the top) and
/// the view-axis depth per pixel (+infinity where nothing was drawn).
struct GlFrame {
    QImage color; ///< Format_RGBA8888, device pixels
    std::vector<float> depth;
};

/// GL window depth (in [0, 1], rows bottom-up as glReadPixels gives them) to view-axis distances
/// (rows top-down) in out, for a VTK camera with the given clipping range. 1.0 (cleared) is
/// +infinity. out keeps its storage: a viewport reads every frame into the same buffer.
void viewDepthFromWindowDepth(const std::vector<float>& windowDepth, int width, int height, double nearDistance,
    double farDistance, bool orthographic, std::vector<float>& out);

/// Strokes of the displayed shape, cached: the edge topology is the mesh's own (built once per
/// mesh), the feature edges and chains are extracted again only when the shape's generation, the
/// line view or the settings change.
class LineOverlay {
public:
    /// Extracts the feature strokes of shape seen from view (the centre eye in stereo, paper 3,
    /// section 4.2.2). Cheap when nothing changed since the last call.
    /// Apparent ridges (settings.ridges) come from lineCamera, the camera whose eye view is, and
    /// are clustered into snakes in its pixels, as the offline renderer does.
    void update(const algo::Shape& shape, const algo::TriMesh& mesh, const algo::LineView& view,
        const algo::LineSettings& settings, const algo::RasterCamera& lineCamera);
    /// The strokes projected with camera and styled (pixels), drawn anti-aliased into coverage
    /// (camera.width x camera.height), hidden where depth (view-axis, top-down) is nearer.
    /// Returns the bounding box of the covered pixels (empty when no line is visible).
    QRect draw(const algo::Positions& shape, const algo::LineStyle& style, const algo::RasterCamera& camera,
        const std::vector<float>& depth, std::vector<float>& coverage) const;

    [[nodiscard]] std::size_t strokeCount() const { return m_strokes.size() + m_snakes.strokes.size(); }
    /// Drops every cache (a new mesh).
    void clear();

private:
    const algo::TriMesh* m_mesh = nullptr; ///< the mesh the strokes were extracted on (its size)
    std::uint64_t m_generation = 0; ///< of the shape the strokes were extracted from
    algo::LineView m_view;
    algo::LineSettings m_settings;
    bool m_valid = false;
    std::vector<algo::Stroke> m_strokes;
    /// Apparent ridges: the curvature of the shape of generation m_ridgeGeneration, and the
    /// snakes of the last line camera (kept in m_ridgeCache, whose shape copy is not used here).
    algo::RasterCamera m_ridgeCamera;
    std::uint64_t m_ridgeGeneration = 0;
    algo::RidgeShapeData m_ridgeData;
    algo::RidgeScratch m_ridgeScratch;
    algo::RidgeSnakes m_snakes;
};

/// Blends line coverage (coverageWidth pixels a row) over an 8-bit sRGB image whose top-left
/// pixel is coverage pixel origin, in linear light as the offline renderer does:
/// colour * (1 - a) + line * a.
void blendLines(QImage& image, const QPoint& origin, const std::vector<float>& coverage, int coverageWidth,
    const Eigen::Vector3f& lineColor);

/// 8-bit sRGB image to linear float and back (table-driven, exact round trip for 8-bit values).
algo::ImageRGBA toLinear(const QImage& image);
QImage toSrgb(const algo::ImageRGBA& image);

/// The stereo composition of two eye images (linear light) for an output; Off returns left.
algo::ImageRGBA composeStereo(algo::StereoOutput output, const algo::ImageRGBA& left, const algo::ImageRGBA& right,
    const algo::DuboisMatrices& dubois);

} // namespace celform::views
