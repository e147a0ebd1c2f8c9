// The depth analysis of a viewport on a worker thread (depth_analysis_runner.h).
#include "celform/views/overlays/depth_analysis_runner.h"

#include "celform/model/document/change_set.h"
#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/srgb_bytes.h"
#include "celform/views/viewport/viewport.h"

#include <QMetaObject>

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace celform::views {

/// What the worker needs, copied on the GUI thread: the parts of the document the renderer
/// reads (the base mesh is shared and immutable), the shape on screen and the camera.
struct DepthAnalysisRunner::Job {
    model::ProjectData data;
    algo::Positions shape;
    std::uint64_t generation = 0;
    std::vector<float> offsets; ///< in effect for the shape shown (Viewport::displayedShadingOffsets)
    model::Camera camera;
    int frame = 0;
    int width = 0;
    int height = 0;
    model::AnalysisSettings settings;
};

namespace {

/// The overlay as the screen shows it: sRGB, premultiplied; off-model pixels stay transparent.
QImage toImage(const algo::ImageRGBA& image)
{
    QImage out(image.width, image.height, QImage::Format_ARGB32_Premultiplied);
    out.fill(Qt::transparent);
    for (int y = 0; y < image.height; ++y) {
        auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.at(x, y);
            const float a = std::clamp(p[3], 0.f, 1.f);
            if (a <= 0.f)
                continue;
            auto channel = [a](float linear) { return int(std::lround(float(srgbByte(linear)) * a)); };
            line[x] = qRgba(channel(p[0]), channel(p[1]), channel(p[2]), int(std::lround(a * 255.f)));
        }
    }
    return out;
}

} // namespace

/// The worker's algo::Progress: no bar (a new picture comes within a second or so, and the
/// Depth panel shows that one is on its way), cancelled when the runner is destroyed.
class DepthAnalysisRunner::WorkerProgress : public algo::Progress {
public:
    explicit WorkerProgress(DepthAnalysisRunner* runner)
        : m_runner(runner)
    { }
    void progress(std::int64_t, std::int64_t, const std::string&) override { }
    [[nodiscard]] bool isCancelRequested() const override
    {
        const std::lock_guard<std::mutex> lock(m_runner->m_mutex);
        return m_runner->m_stop;
    }

private:
    DepthAnalysisRunner* m_runner;
};

DepthAnalysisRunner::DepthAnalysisRunner(model::Document* document, Viewport* viewport, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_viewport(viewport)
{
    m_coalesce.setSingleShot(true);
    m_coalesce.setInterval(0);
    connect(&m_coalesce, &QTimer::timeout, this, &DepthAnalysisRunner::submit);
    connect(viewport, &Viewport::cameraChanged, this, &DepthAnalysisRunner::requestUpdate);
    connect(document, &model::Document::changed, this, &DepthAnalysisRunner::documentChanged);
    m_worker = std::thread([this] { workerLoop(); });
}

DepthAnalysisRunner::~DepthAnalysisRunner()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
        m_pending.reset();
    }
    m_wake.notify_all();
    m_worker.join();
}

void DepthAnalysisRunner::setActive(bool on)
{
    if (m_active == on)
        return;
    m_active = on;
    if (on)
        requestUpdate();
}

void DepthAnalysisRunner::setSettings(const model::AnalysisSettings& settings)
{
    m_settings = settings;
    requestUpdate();
}

void DepthAnalysisRunner::setMaximumSide(int pixels)
{
    m_maximumSide = std::max(64, pixels);
    requestUpdate();
}

bool DepthAnalysisRunner::isCurrent() const
{
    if (!m_result || !m_viewport)
        return false;
    const model::Camera now = m_viewport->camera();
    return m_result->camera == now && m_result->frame == m_document->data().currentFrame;
}

void DepthAnalysisRunner::setHeld(bool held)
{
    if (m_held == held)
        return;
    m_held = held;
    if (!held && m_missed) {
        m_missed = false;
        requestUpdate();
    }
}

void DepthAnalysisRunner::requestUpdate()
{
    if (!m_active)
        return;
    if (m_held) {
        m_missed = true;
        m_coalesce.stop();
        return;
    }
    m_coalesce.start();
}

void DepthAnalysisRunner::documentChanged(const model::ChangeSet&)
{
    // Any change may show: shape, look, light, offsets, playhead. The analysis of an unchanged
    // shape reuses its curvature, so a look edit costs only the picture.
    requestUpdate();
}

void DepthAnalysisRunner::submit()
{
    if (!m_active || !m_viewport)
        return;
    auto job = std::make_unique<Job>();
    const model::ProjectData& data = m_document->data();
    if (!data.baseMesh) {
        auto result = std::make_shared<DepthAnalysisResult>();
        result->error = tr("No base model to analyse");
        deliver(result);
        return;
    }
    // The renderer reads the mesh, its face sets, the offsets in effect and the look; keys and
    // drawings stay.
    job->data.baseMesh = data.baseMesh;
    job->data.faceSets = data.faceSets;
    job->offsets = m_viewport->displayedShadingOffsets();
    job->data.look = data.look;
    job->data.currentFrame = data.currentFrame;
    job->shape = m_viewport->displayedShape();
    job->generation = m_viewport->displayedShapeGeneration();
    job->camera = m_viewport->camera();
    job->frame = data.currentFrame;
    const QSize size = analysisSize();
    job->width = size.width();
    job->height = size.height();
    job->settings = m_settings;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_pending = std::move(job);
    }
    m_wake.notify_one();
    if (!m_busy) {
        m_busy = true;
        emit busyChanged(true);
    }
}

QSize DepthAnalysisRunner::analysisSize() const
{
    if (!m_viewport)
        return {1, 1};
    const double scale
        = std::min(1.0, double(m_maximumSide) / std::max(1, std::max(m_viewport->width(), m_viewport->height())));
    return {std::max(1, int(std::lround(m_viewport->width() * scale))),
        std::max(1, int(std::lround(m_viewport->height() * scale)))};
}

void DepthAnalysisRunner::workerLoop()
{
#ifdef __linux__
    // Below the GUI and the GL threads: on a machine with few cores (farm nodes, software GL) the
    // picture on screen keeps its frame rate and the analysis takes what is left.
    ::setpriority(PRIO_PROCESS, pid_t(::syscall(SYS_gettid)), 10);
#endif
    model::DepthAnalyser analyser; // keeps the curvature of a still shape and the buffers
    model::FrameAnalysis frame;
    WorkerProgress progress(this);
    for (;;) {
        std::unique_ptr<Job> job;
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_wake.wait(lock, [this] { return m_stop || m_pending; });
            if (m_stop)
                return;
            job = std::move(m_pending);
            m_running = true;
        }
        auto result = std::make_shared<DepthAnalysisResult>();
        result->camera = job->camera;
        result->frame = job->frame;
        result->width = job->width;
        result->height = job->height;
        result->window = job->settings.window;
        try {
            analyser.analyse(job->data, job->data.look, job->shape, job->generation, job->frame, job->camera,
                job->width, job->height, job->settings, frame, &job->offsets, &progress);
            if (frame.cancelled)
                return; // the runner is going: nobody waits for this picture
            const algo::DepthAnalysis& a = frame.analysis;
            result->segments = toImage(model::analysisImage(a, model::AnalysisPicture::Segments, false));
            result->curvature
                = toImage(model::analysisImage(a, model::AnalysisPicture::Curvature, false, &result->curvatureScale));
            result->depthError
                = toImage(model::analysisImage(a, model::AnalysisPicture::DepthError, false, &result->depthErrorScale));
            result->segmentStats = a.stats;
            result->meanSquaredError = a.meanSquaredError;
            result->maxAbsError = a.maxAbsError;
            result->modelPixels = a.modelPixels;
            result->featurePixels = a.featurePixels;
            result->depthThreshold = frame.depthThreshold;
            result->milliseconds = frame.milliseconds;
            result->curvatureMilliseconds = frame.curvatureMilliseconds;
        } catch (const std::bad_alloc&) {
            result->error = tr("Not enough memory for the analysis at %1 x %2").arg(job->width).arg(job->height);
        } catch (const std::exception& e) {
            result->error = QString::fromLocal8Bit(e.what());
        }
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_running = false;
        }
        QMetaObject::invokeMethod(
            this,
            [this, result] {
                deliver(result);
                bool working = false;
                {
                    std::lock_guard<std::mutex> lock(m_mutex);
                    working = m_running || m_pending;
                }
                if (!working && m_busy) {
                    m_busy = false;
                    emit busyChanged(false);
                }
            },
            Qt::QueuedConnection);
    }
}

void DepthAnalysisRunner::deliver(std::shared_ptr<const DepthAnalysisResult> result)
{
    m_result = std::move(result);
    emit analysed();
}

} // namespace celform::views
