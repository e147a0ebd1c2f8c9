// Frame composition of the viewport: VTK renders, read-back, lines and stereo in linear light, so
// the viewport shows what the offline renderer writes.
#include "celform/views/viewport/viewport_compositor.h"

#include "celform/views/viewport/viewport_camera.h"
#include "celform/views/viewport/viewport_scene.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLWidget>
#include <QPainter>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

namespace celform::views {
namespace {

/// The layers leave the framebuffer's alpha below one: the widget is opaque.
void makeOpaque(QImage& rgba)
{
    for (int y = 0; y < rgba.height(); ++y) {
        uchar* row = rgba.scanLine(y);
        for (int x = 0; x < rgba.width(); ++x)
            row[4 * x + 3] = 255;
    }
}

} // namespace

ViewportCompositor::ViewportCompositor(QOpenGLWidget* widget, ViewportScene& scene, const ViewportCamera& camera)
    : m_widget(widget)
    , m_scene(scene)
    , m_camera(camera)
{ }

void ViewportCompositor::paint(const Frame& frame)
{
    m_lineMilliseconds = 0.0;
    if (frame.stereo != algo::StereoOutput::Off)
        paintStereo(frame);
    else
        paintMono(frame);
    // Blending the drawing layer lowers the framebuffer's alpha, and Qt composites the widget
    // with it (premultiplied): the viewport must stay opaque whatever the layers did.
    QOpenGLFunctions* gl = m_widget->context()->functions();
    gl->glBindFramebuffer(GL_FRAMEBUFFER, m_widget->defaultFramebufferObject());
    gl->glDisable(GL_SCISSOR_TEST);
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClearColor(0.f, 0.f, 0.f, 1.f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void ViewportCompositor::renderVtkFrame(bool readColor, bool readDepth, GlFrame& out)
{
    vtkGenericOpenGLRenderWindow* window = m_scene.window();
    // Qt touched the GL state (its framebuffer, depth function) since VTK last looked: make VTK
    // re-read it rather than trust its cache, and hand Qt its state back afterwards.
    vtkOpenGLState* state = window->GetState();
    state->Reset();
    state->Push();
    m_scene.renderer()->ResetCameraClippingRange();
    const int* size = window->GetSize();
    m_scene.placeTriad(int(size[0] / m_widget->devicePixelRatioF()), int(size[1] / m_widget->devicePixelRatioF()), 90);
    m_scene.captureDepthOnNextRender(readDepth);
    window->Render();
    m_scene.captureDepthOnNextRender(false);
    state->Pop();

    const int w = size[0], h = size[1];
    if (readDepth) {
        vtkCamera* cam = m_scene.camera();
        double range[2];
        cam->GetClippingRange(range);
        viewDepthFromWindowDepth(
            m_scene.capturedDepth(), w, h, range[0], range[1], cam->GetParallelProjection() != 0, out.depth);
    }
    if (readColor && w > 0 && h > 0) {
        if (out.color.size() != QSize(w, h))
            out.color = QImage(w, h, QImage::Format_RGBA8888);
        QOpenGLFunctions* gl = m_widget->context()->functions();
        gl->glBindFramebuffer(GL_FRAMEBUFFER, m_widget->defaultFramebufferObject());
        gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out.color.bits());
        out.color = out.color.mirrored();
        makeOpaque(out.color);
    }
}

QRect ViewportCompositor::lineCoverage(const Frame& frame, const algo::RasterCamera& camera,
    const algo::RasterCamera& lineEye, const std::vector<float>& depth)
{
    if (!frame.mesh || !frame.shape || !frame.look || frame.shape->positions.rows() != frame.mesh->vertexCount())
        return {};
    algo::LineView view;
    view.eye = lineEye.eye.cast<float>();
    view.direction = lineEye.forward().cast<float>();
    view.orthographic = lineEye.orthographic;
    m_lines.update(*frame.shape, *frame.mesh, view, frame.look->lines, lineEye);
    return m_lines.draw(frame.shape->positions, frame.look->lineStyle, camera, depth, m_coverage);
}

void ViewportCompositor::paintMono(const Frame& frame)
{
    GlFrame& glFrame = m_frames[0];
    renderVtkFrame(false, frame.lines, glFrame);
    if (!frame.lines)
        return;
    // Only the pixels the strokes can touch go through the CPU: read them back, blend the
    // coverage in linear light (as the offline renderer), write them back.
    QElapsedTimer lineTimer;
    lineTimer.start();
    const int* size = m_scene.window()->GetSize();
    const algo::RasterCamera centre = m_camera.rasterCamera(size[0], size[1]);
    const QRect box = lineCoverage(frame, centre, centre, glFrame.depth);
    if (!box.isEmpty()) {
        // The strokes' box of the frame, read into storage kept between frames (as large as the
        // view once), rows flipped in place.
        const std::size_t bytes = std::size_t(box.width()) * std::size_t(box.height()) * 4;
        if (m_regionPixels.size() < bytes)
            m_regionPixels.resize(std::size_t(std::max(1, centre.width)) * std::size_t(std::max(1, centre.height)) * 4);
        QImage region(m_regionPixels.data(), box.width(), box.height(), box.width() * 4, QImage::Format_RGBA8888);
        QOpenGLFunctions* gl = m_widget->context()->functions();
        gl->glBindFramebuffer(GL_FRAMEBUFFER, m_widget->defaultFramebufferObject());
        gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->glReadPixels(box.x(), centre.height - 1 - box.bottom(), box.width(), box.height(), GL_RGBA,
            GL_UNSIGNED_BYTE, m_regionPixels.data());
        region.mirror(false, true);
        makeOpaque(region);
        blendLines(region, box.topLeft(), m_coverage, centre.width, frame.look->lineStyle.color);
        const qreal dpr = m_widget->devicePixelRatioF();
        QPainter painter(m_widget);
        painter.setCompositionMode(QPainter::CompositionMode_Source);
        painter.drawImage(QRectF(box.x() / dpr, box.y() / dpr, box.width() / dpr, box.height() / dpr), region);
    }
    m_lineMilliseconds = double(lineTimer.nsecsElapsed()) / 1e6;
}

void ViewportCompositor::paintStereo(const Frame& frame)
{
    vtkCamera* cam = m_scene.camera();
    double position[3], focal[3], up[3], windowCenter[2];
    cam->GetPosition(position);
    cam->GetFocalPoint(focal);
    cam->GetViewUp(up);
    cam->GetWindowCenter(windowCenter);

    // Paper 3, section 3.1: the offline renderer's eye pair (off-axis by default) from VTK's
    // own projection; lines come from the centre eye (section 4.2.2), projected per eye.
    const int* size = m_scene.window()->GetSize();
    const algo::RasterCamera centre = m_camera.rasterCamera(size[0], size[1]);
    const auto eyes = algo::stereoPair(centre, frame.stereoSettings);
    const algo::RasterCamera* eyeCameras[2] = {&eyes.first, &eyes.second};
    QElapsedTimer lineTimer;
    qint64 lineNanoseconds = 0;
    for (int k = 0; k < 2; ++k) {
        m_frames[k].color = QImage();
        if ((frame.eyeOnly == Eye::Left && k == 1) || (frame.eyeOnly == Eye::Right && k == 0))
            continue;
        const algo::RasterCamera& eye = *eyeCameras[k];
        cam->SetPosition(eye.eye.data());
        cam->SetFocalPoint(eye.target.data());
        cam->SetViewUp(eye.up.data());
        cam->SetWindowCenter(-2.0 * eye.horizontalShift, 0.0);
        renderVtkFrame(true, frame.lines, m_frames[k]);
        if (frame.lines && !m_frames[k].color.isNull()) {
            lineTimer.start();
            if (!lineCoverage(frame, eye, centre, m_frames[k].depth).isEmpty())
                blendLines(m_frames[k].color, QPoint(0, 0), m_coverage, eye.width, frame.look->lineStyle.color);
            lineNanoseconds += lineTimer.nsecsElapsed();
        }
    }
    cam->SetPosition(position);
    cam->SetFocalPoint(focal);
    cam->SetViewUp(up);
    cam->SetWindowCenter(windowCenter[0], windowCenter[1]);
    m_lineMilliseconds = double(lineNanoseconds) / 1e6;

    QImage shown;
    if (frame.eyeOnly == Eye::Left)
        shown = m_frames[0].color;
    else if (frame.eyeOnly == Eye::Right)
        shown = m_frames[1].color;
    else if (!m_frames[0].color.isNull() && !m_frames[1].color.isNull())
        shown = toSrgb(
            composeStereo(frame.stereo, toLinear(m_frames[0].color), toLinear(m_frames[1].color), frame.dubois));
    if (shown.isNull())
        return;
    // Side by side and top-bottom are squeezed into the widget, as 3D displays expect them.
    QPainter painter(m_widget);
    painter.setCompositionMode(QPainter::CompositionMode_Source);
    const QSize eyeSize = m_frames[0].color.isNull() ? m_frames[1].color.size() : m_frames[0].color.size();
    painter.setRenderHint(QPainter::SmoothPixmapTransform, shown.size() != eyeSize);
    painter.drawImage(QRectF(m_widget->rect()), shown);
}

} // namespace celform::views
