// The viewport's frame composition: one VTK render into Qt's framebuffer, or two (left and right
// eye) read back and composed into an anaglyph or side-by-side image (paper 3, section 3.1), with
// the offline renderer's feature lines drawn over them, hidden by the GL depth and taken from the
// centre eye (paper 3, section 4.2.2).
#pragma once

#include "celform/algorithms/stereo.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/project_data.h"
#include "celform/views/overlays/line_overlay.h"

class QOpenGLWidget;

namespace celform::views {

class ViewportScene;
class ViewportCamera;

class ViewportCompositor {
public:
    ViewportCompositor(QOpenGLWidget* widget, ViewportScene& scene, const ViewportCamera& camera);

    enum class Eye { Both, Left, Right };
    struct Frame {
        const algo::Shape* shape = nullptr; ///< what is on screen
        const algo::TriMesh* mesh = nullptr;
        const model::Look* look = nullptr;
        bool lines = false;
        algo::StereoOutput stereo = algo::StereoOutput::Off;
        algo::StereoSettings stereoSettings;
        algo::DuboisMatrices dubois = algo::DuboisMatrices::redCyan();
        Eye eyeOnly = Eye::Both; ///< with stereo: show one eye's full-colour image (tests)
    };

    /// Draws the frame into the widget's framebuffer (inside paintGL).
    void paint(const Frame& frame);
    /// Wall time of the last frame's line extraction and drawing, ms.
    [[nodiscard]] double lastLineMilliseconds() const { return m_lineMilliseconds; }
    /// Drops the line cache (a new mesh).
    void clearLines() { m_lines.clear(); }

private:
    /// One VTK frame into Qt's framebuffer, read back (colour only when wanted, depth when lines
    /// are shown), camera and clipping as they are now.
    void renderVtkFrame(bool readColor, bool readDepth, GlFrame& out);
    /// Line coverage of the frame's shape for camera, strokes from lineEye, hidden by depth;
    /// returns the rect the lines may touch.
    QRect lineCoverage(const Frame& frame, const algo::RasterCamera& camera, const algo::RasterCamera& lineEye,
        const std::vector<float>& depth);
    void paintMono(const Frame& frame);
    void paintStereo(const Frame& frame);

    QOpenGLWidget* m_widget;
    ViewportScene& m_scene;
    const ViewportCamera& m_camera;
    LineOverlay m_lines;
    GlFrame m_frames[2]; ///< kept between frames: their buffers are reused
    std::vector<float> m_coverage;
    std::vector<uchar> m_regionPixels; ///< the lines' box read back, kept between frames
    double m_lineMilliseconds = 0.0;
};

} // namespace celform::views
