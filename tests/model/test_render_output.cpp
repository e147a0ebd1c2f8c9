// The document's highlight tracks resolved for the renderer (model::renderHighlightsFor): patch
// masks, smoothed normals and frames, and the cache that keeps a track's per-vertex geometry across
// parameter edits and frames without changing a single value. Issue 25's line figures: stray
// dashes on the elephant sample and a coarse shared mesh at 1280x960, before and after the
// stroke clean-up. Issue 29: a job's frames are written on one writer thread while the next frame
// renders, in order, with failures and cancelling as before.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/model/data/framed_camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/render/frame_schedule.h"
#include "celform/model/render/render_output.h"
#include "celform/model/render/subdivided_surface.h"

#include <QtTest/QtTest>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

using namespace celform;

namespace {

/// Line coverage that shows: a quarter, so that faint tapered dashes count too.
constexpr float kInk = 0.25f;

/// Line dashes of a picture: 8-connected pieces of the lines pass (coverage above kInk) whose
/// bounding box has a diagonal under maxPixels.
int shortDashes(const algo::RenderPasses& passes, int width, int height, double maxPixels)
{
    std::vector<char> seen(passes.lines.size(), 0);
    std::vector<int> stack;
    int dashes = 0;
    for (int start = 0; start < width * height; ++start) {
        if (seen[std::size_t(start)] || passes.lines[std::size_t(start)] <= kInk)
            continue;
        int x0 = width, y0 = height, x1 = -1, y1 = -1;
        stack.assign(1, start);
        seen[std::size_t(start)] = 1;
        while (!stack.empty()) {
            const int i = stack.back();
            stack.pop_back();
            const int x = i % width, y = i / width;
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
            y0 = std::min(y0, y);
            y1 = std::max(y1, y);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height)
                        continue;
                    const auto j = std::size_t(ny * width + nx);
                    if (!seen[j] && passes.lines[j] > kInk) {
                        seen[j] = 1;
                        stack.push_back(int(j));
                    }
                }
        }
        if (std::hypot(x1 - x0 + 1, y1 - y0 + 1) < maxPixels)
            ++dashes;
    }
    return dashes;
}

/// The lines of a project at 1280x960 from direction (0.3, 0.2, 1) with a directional light at
/// (0.5, 0.8, 0.6), as `celform render --view 0.3,0.2,1 --light directional:0.5,0.8,0.6`; with
/// `before`, the line clean-up of issue 25 is off (no hysteresis, joining, smoothing, minimum
/// length, taper or reduction), as the lines were drawn before it.
int dashesOf(const model::ProjectData& data, bool before)
{
    model::RenderJob job;
    job.view = Eigen::Vector3d(0.3, 0.2, 1.0);
    job.size = QSize(1280, 960);
    job.light = model::Light{model::LightType::Directional, Eigen::Vector3d(0.5, 0.8, 0.6)};
    model::Look look = model::renderJobLook(data, job);
    if (before) {
        look.lines.creaseLowAngleDegrees = look.lines.creaseAngleDegrees;
        look.lineStyle.joinGap = 0.f;
        look.lineStyle.smoothing = 0;
        look.lineStyle.minLength = 0.f;
        look.lineStyle.taper = 0.f;
        look.lineStyle.reduction = 0.f;
    }
    const model::Camera camera = model::renderJobCamera(data, look, job, 0);
    algo::RenderCache cache;
    const algo::RenderPasses passes
        = model::renderShape(data, look, data.baseMesh->vertices, 0, camera, 1280, 960, algo::StereoOutput::Off, cache);
    return shortDashes(passes, 1280, 960, 30.0);
}

model::ProjectData sphereWithTracks()
{
    model::ProjectData data;
    data.baseMesh = test::icosphere(3);
    std::vector<std::int32_t> upper;
    for (Eigen::Index f = 0; f < data.baseMesh->faceCount(); ++f)
        if (data.baseMesh->vertices(data.baseMesh->faces(f, 0), 1) > 0.0f)
            upper.push_back(std::int32_t(f));
    data.faceSets.push_back({"upper", upper});
    for (const char* name : {"plain", "smooth"}) {
        model::HighlightTrack t;
        t.name = QString::fromLatin1(name);
        t.patch = QStringLiteral("upper");
        t.smoothing = t.name == QLatin1String("smooth") ? 5 : 0;
        algo::HighlightLayer key0, key10;
        key10.shape.epsilon = 0.2f;
        t.setKey(0, key0);
        t.setKey(10, key10);
        data.look.highlights.push_back(t);
    }
    return data;
}

void compareGeometry(const std::vector<algo::RenderHighlight>& a, const std::vector<algo::RenderHighlight>& b)
{
    QCOMPARE(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        QVERIFY(a[i].layer == b[i].layer);
        QVERIFY(a[i].faceMask == b[i].faceMask);
        QVERIFY(a[i].normals.rows() == b[i].normals.rows() && a[i].normals == b[i].normals);
        QVERIFY(a[i].du == b[i].du && a[i].dv == b[i].dv);
    }
}

/// A coarse, lumpy closed mesh: an octahedron split once with its new vertices pushed out and down.
model::ProjectData coarseModel()
{
    model::ProjectData data;
    auto mesh = test::subdivided(*test::octahedron());
    for (Eigen::Index v = 6; v < mesh->vertexCount(); ++v)
        mesh->vertices.row(v) *= 1.3f;
    data.baseMesh = mesh;
    return data;
}

/// The frame of data's surface at level (0: the control mesh) seen from (0.3, 0.2, 1), small.
algo::RenderPasses renderAtLevel(const model::ProjectData& data, int level)
{
    model::Look look = data.look;
    look.showLines = false;
    const model::Camera camera = model::cameraFromView(data, Eigen::Vector3d(0.3, 0.2, 1).normalized(), 1.0);
    algo::RenderCache cache;
    const auto surface = model::subdividedSurface(data, level);
    if (!surface)
        return model::renderShape(
            data, look, data.baseMesh->vertices, 0, camera, 160, 160, algo::StereoOutput::Off, cache);
    algo::Positions shape;
    surface->apply(data.baseMesh->vertices, shape);
    return model::renderShape(surface->display, look, shape, 0, camera, 160, 160, algo::StereoOutput::Off, cache);
}

std::vector<bool> silhouette(const algo::RenderPasses& p)
{
    std::vector<bool> mask(p.depth.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        mask[i] = std::isfinite(p.depth[i]);
    return mask;
}

/// Hears the frames a schedule reports done, in order.
struct DoneFrames : model::RenderFrameListener {
    std::vector<int> frames;
    void frameDone(int frame, const QString&, bool skipped) override
    {
        if (!skipped)
            frames.push_back(frame);
    }
};

model::RenderJob scheduleJob(int frames, int threads)
{
    model::RenderJob job;
    job.firstFrame = 0;
    job.lastFrame = frames - 1;
    job.threads = threads;
    job.output = QStringLiteral("/nonexistent/frame_####.png"); // the renderers below write nothing
    return job;
}

} // namespace

class TestRenderOutput : public QObject {
    Q_OBJECT

private slots:
    void framesAreWrittenWhileTheNextRenders()
    {
        // Frame 0's write waits until frame 1's render has begun: with the write on the render
        // thread (no overlap) it would time out and the frame fail.
        std::mutex mutex;
        std::condition_variable changed;
        int rendering = -1;
        const model::RenderJob job = scheduleJob(4, 1);
        DoneFrames done;
        const int written = model::scheduleFrames(job, nullptr, &done, [&]() -> model::FrameRenderer {
            return [&](int frame, const QString&, const std::function<bool()>&) -> model::FrameWrite {
                {
                    const std::lock_guard<std::mutex> lock(mutex);
                    rendering = frame;
                }
                changed.notify_all();
                return [&, frame] {
                    std::unique_lock<std::mutex> lock(mutex);
                    if (frame < 3
                        && !changed.wait_for(lock, std::chrono::seconds(10), [&] { return rendering > frame; }))
                        throw model::IoError(QStringLiteral("frame"), QStringLiteral("no overlap"));
                };
            };
        });
        QCOMPARE(written, 4);
        QCOMPARE(done.frames, (std::vector<int>{0, 1, 2, 3}));
    }

    void aRendererNeverRunsAheadOfItsWrites()
    {
        // A renderer may keep two frames' data: when it renders frame n, frame n - 2 is written.
        std::atomic<int> lastWritten{-1};
        std::atomic<bool> ahead{false};
        for (const int threads : {1, 2}) {
            const model::RenderJob job = scheduleJob(12, threads);
            DoneFrames done;
            const int written = model::scheduleFrames(job, nullptr, &done, [&]() -> model::FrameRenderer {
                auto mine = std::make_shared<std::vector<int>>(); // this renderer's frames, written or not
                auto writtenByMe = std::make_shared<std::atomic<int>>(0);
                return [&, mine, writtenByMe](
                           int frame, const QString&, const std::function<bool()>&) -> model::FrameWrite {
                    if (int(mine->size()) - writtenByMe->load() >= 2)
                        ahead = true;
                    mine->push_back(frame);
                    return [&, frame, writtenByMe] {
                        std::this_thread::sleep_for(std::chrono::milliseconds(5));
                        lastWritten = frame;
                        ++*writtenByMe;
                    };
                };
            });
            QCOMPARE(written, 12);
            QCOMPARE(int(done.frames.size()), 12);
            if (threads == 1)
                QCOMPARE(done.frames, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
        }
        QVERIFY(!ahead);
    }

    void aFailedWriteNamesItsFrameAndStopsTheJob()
    {
        const model::RenderJob job = scheduleJob(20, 1);
        DoneFrames done;
        std::atomic<int> rendered{0};
        try {
            model::scheduleFrames(job, nullptr, &done, [&]() -> model::FrameRenderer {
                return [&](int frame, const QString&, const std::function<bool()>&) -> model::FrameWrite {
                    ++rendered;
                    return [frame] {
                        if (frame == 3)
                            throw model::IoError(
                                QStringLiteral("frame_0003.png"), QStringLiteral("No space left on device"));
                    };
                };
            });
            QFAIL("the failed write was not reported");
        } catch (const model::RenderFrameError& e) {
            QCOMPARE(e.frame(), 3);
            QCOMPARE(e.file(), QStringLiteral("frame_0003.png"));
            QVERIFY(e.problem().contains(QStringLiteral("No space")));
        }
        // Frame 4 may have rendered while frame 3 was being written: it is dropped.
        QCOMPARE(done.frames, (std::vector<int>{0, 1, 2}));
        QVERIFY2(rendered <= 5, "frames went on rendering after the failure");
    }

    void fewShortDashesOnTheElephant()
    {
        const model::ProjectData data
            = model::loadProject(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"));
        const int before = dashesOf(data, true), after = dashesOf(data, false);
        qInfo("elephant sample: %d line dashes under 30 px before the clean-up, %d after", before, after);
        QVERIFY(after <= 3);
        QVERIFY(after < before);
    }

    void fewShortDashesOnACoarseMesh()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/npm_bunny.off"));
        const model::ProjectData data = model::newProject(
            std::make_shared<const algo::TriMesh>(model::importMesh(path).mesh), QStringLiteral("npm_bunny"));
        const int before = dashesOf(data, true), after = dashesOf(data, false);
        qInfo("bunny (3.7k triangles): %d line dashes under 30 px before the clean-up, %d after", before, after);
        QVERIFY(after <= 3);
        QVERIFY(after <= before);
    }

    void subdividedRenderIsSmoothAndKeepsTheSilhouette()
    {
        const model::ProjectData data = coarseModel();
        const algo::RenderPasses l0 = renderAtLevel(data, 0), l2 = renderAtLevel(data, 2), l3 = renderAtLevel(data, 3);
        const std::vector<bool> s0 = silhouette(l0), s2 = silhouette(l2), s3 = silhouette(l3);
        int both = 0, either = 0, differ = 0;
        for (std::size_t i = 0; i < s2.size(); ++i) {
            both += s2[i] && s3[i];
            either += s2[i] || s3[i];
            differ += s0[i] != s2[i] || l0.tone[i] != l2.tone[i];
        }
        const double iou = double(both) / std::max(1, either);
        qInfo("silhouette IoU level 2 vs 3: %.4f; pixels differing from level 0: %d", iou, differ);
        QVERIFY(iou >= 0.97);
        QVERIFY(differ > 100);
    }

    void smoothSurfaceIsShadedWithItsLimitNormals()
    {
        // Issue 25: a render at a subdivision level shades with the limit normals of the stencil
        // (renderJobFrame, as `celform render`), not the faces' area-weighted normals. Given
        // normals reach the tone: normals all facing the light shade every covered pixel bright.
        model::ProjectData data = coarseModel();
        data.look.subdivision.level = 2;
        data.look.showLines = false;
        model::RenderJob job;
        job.size = QSize(160, 160);
        job.view = Eigen::Vector3d(0.3, 0.2, 1).normalized();
        const model::ResolvedRenderJob resolved = model::resolveRenderJob(data, QStringLiteral("coarse"), job);
        algo::RenderPasses passes;
        model::renderJobFrame(data, job, resolved, 0, passes);
        const auto surface = model::subdividedSurface(data, 2);
        QVERIFY(surface);
        algo::Positions shape, limit, area;
        surface->apply(data.baseMesh->vertices, shape);
        algo::limitNormals(*surface->stencil, shape, limit);
        algo::vertexNormals(shape, surface->display.baseMesh->faces, area);
        const model::Camera camera = model::renderJobCamera(data, resolved.look, job, 0);
        algo::RenderCache cache;
        const algo::RenderPasses withLimit = model::renderShape(surface->display, resolved.look, shape, 0, camera, 160,
            160, algo::StereoOutput::Off, cache, 0, nullptr, &limit);
        const algo::RenderPasses withArea = model::renderShape(surface->display, resolved.look, shape, 0, camera, 160,
            160, algo::StereoOutput::Off, cache, 0, nullptr, &area);
        QVERIFY(passes.tone == withLimit.tone);
        QVERIFY(limit != area); // so the comparison above tells them apart
        const Eigen::Vector3f towardsLight = resolved.look.light.vector.cast<float>().normalized();
        algo::Positions lit(shape.rows(), 3);
        lit.rowwise() = towardsLight.transpose();
        const algo::RenderPasses bright = model::renderShape(surface->display, resolved.look, shape, 0, camera, 160,
            160, algo::StereoOutput::Off, cache, 0, nullptr, &lit);
        const float top = *std::max_element(bright.tone.begin(), bright.tone.end());
        int covered = 0, notTop = 0;
        for (std::size_t i = 0; i < bright.depth.size(); ++i)
            if (std::isfinite(bright.depth[i])) {
                ++covered;
                notTop += bright.tone[i] != top;
            }
        QVERIFY(covered > 1000);
        QCOMPARE(notTop, 0);
    }

    void subdividedSurfaceCarriesFaceSetsMaterialsAndOffsets()
    {
        model::ProjectData data = coarseModel();
        auto mesh = std::make_shared<algo::TriMesh>(*data.baseMesh);
        mesh->materials = {{"a", {1, 0, 0}}, {"b", {0, 0, 1}}};
        mesh->faceMaterials.assign(std::size_t(mesh->faceCount()), 0);
        mesh->faceMaterials[3] = 1;
        data.baseMesh = mesh;
        data.faceSets.push_back({"patch", {2, 5}});
        data.shadingOffsets.assign(std::size_t(mesh->vertexCount()), 0.5f);
        const auto surface = model::subdividedSurface(data, 2);
        QVERIFY(surface);
        QCOMPARE(model::subdividedSurface(data, 2), surface); // cached
        const algo::TriMesh& shown = *surface->display.baseMesh;
        QCOMPARE(shown.faceCount(), mesh->faceCount() * 16);
        for (Eigen::Index f = 0; f < shown.faceCount(); ++f)
            QCOMPARE(shown.faceMaterials[std::size_t(f)], f / 16 == 3 ? 1 : 0);
        const algo::FaceSet* patch = surface->display.faceSet(QStringLiteral("patch"));
        QVERIFY(patch);
        QCOMPARE(int(patch->faces.size()), 32);
        QCOMPARE(patch->faces.front(), 32);
        QCOMPARE(int(surface->display.shadingOffsets.size()), int(shown.vertexCount()));
        for (const float o : surface->display.shadingOffsets)
            QVERIFY(std::abs(o - 0.5f) < 1e-6f);
        QVERIFY(!model::subdividedSurface(data, 0));
        QVERIFY(model::subdivisionMemoryProblem(*mesh, 3).isEmpty());
    }

    void keyDeformationShowsThroughUnchanged()
    {
        // One key seen from the front moves two vertices: the subdivided frame is S times the
        // deformed control shape, exactly, and differs from the subdivided base.
        model::ProjectData data = coarseModel();
        model::KeyViewpoint key;
        key.id = 1;
        key.name = QStringLiteral("front");
        key.camera = model::cameraFromView(data, Eigen::Vector3d::UnitZ(), 1.0);
        key.offsetsByFrame[0]
            = model::SparseOffsets{{4, 7}, {Eigen::Vector3f(0, 0, 0.4f), Eigen::Vector3f(0.2f, 0, 0)}};
        data.keys.push_back(key);
        model::FrameEvaluator evaluator;
        QVERIFY(evaluator.prepare(data));
        evaluator.evaluateDirection(data, 0, Eigen::Vector3d::UnitZ());
        const algo::Positions& deformed = evaluator.shape();
        QVERIFY((deformed - data.baseMesh->vertices).cwiseAbs().maxCoeff() > 0.1f);
        const auto surface = model::subdividedSurface(data, 2);
        algo::Positions shown, expected, base;
        surface->apply(deformed, shown);
        algo::applySubdivision(*surface->stencil, deformed, expected);
        algo::applySubdivision(*surface->stencil, data.baseMesh->vertices, base);
        QCOMPARE(shown, expected);
        QVERIFY((shown - base).cwiseAbs().maxCoeff() > 0.05f);
    }

    void tracksResolveWithPatchAndSmoothing()
    {
        const model::ProjectData data = sphereWithTracks();
        const auto layers = model::renderHighlightsFor(data, data.look, data.baseMesh->vertices, 5);
        QCOMPARE(layers.size(), std::size_t(2));
        QCOMPARE(layers[0].layer.shape.epsilon, 0.5f * (0.05f + 0.2f)); // halfway between the keys
        QCOMPARE(layers[0].normals.rows(), Eigen::Index(0)); // no smoothing: the surface's normals
        QCOMPARE(layers[1].normals.rows(), data.baseMesh->vertexCount());
        // Outside the patch: no face, zero frames and normals.
        const auto& mesh = *data.baseMesh;
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
            const bool lower = (mesh.vertices.row(mesh.faces(f, 0)).y() < -0.5f
                && mesh.vertices.row(mesh.faces(f, 1)).y() < -0.5f && mesh.vertices.row(mesh.faces(f, 2)).y() < -0.5f);
            if (lower) {
                QCOMPARE(int(layers[1].faceMask[std::size_t(f)]), 0);
                QCOMPARE(layers[1].normals.row(mesh.faces(f, 0)).norm(), 0.0f);
                QCOMPARE(layers[1].du.row(mesh.faces(f, 0)).norm(), 0.0f);
            }
        }
    }

    void cacheKeepsGeometryAndFollowsChanges()
    {
        model::ProjectData data = sphereWithTracks();
        const algo::Positions& shape = data.baseMesh->vertices;
        algo::RenderCache cache;
        // The shapes are known by their generations (algo::Shape), as the viewport's and the
        // renderer's are: no pass over the positions to recognise them.
        const std::uint64_t still = algo::newShapeGeneration();
        // Cold and warm cache give exactly what no cache gives, at every frame.
        for (int frame : {0, 5, 10}) {
            const auto reference = model::renderHighlightsFor(data, data.look, shape, frame);
            compareGeometry(model::renderHighlightsFor(data, data.look, shape, frame, &cache, still), reference);
            compareGeometry(model::renderHighlightsFor(data, data.look, shape, frame, &cache, still), reference);
        }
        QCOMPARE(cache.highlights.size(), std::size_t(2)); // one entry per track: the keys play no part
        // A new guide, smoothing, patch or shape is a new entry, and the result follows it.
        data.look.highlights[1].guide = Eigen::Vector3f(1.0f, 0.0f, 0.0f);
        data.look.highlights[1].smoothing = 2;
        compareGeometry(model::renderHighlightsFor(data, data.look, shape, 0, &cache, still),
            model::renderHighlightsFor(data, data.look, shape, 0));
        QCOMPARE(cache.highlights.size(), std::size_t(3));
        algo::Positions moved = shape;
        moved.col(0) *= 1.5f;
        compareGeometry(model::renderHighlightsFor(data, data.look, moved, 0, &cache, algo::newShapeGeneration()),
            model::renderHighlightsFor(data, data.look, moved, 0));
        data.faceSets[0].faces.resize(data.faceSets[0].faces.size() / 2);
        compareGeometry(model::renderHighlightsFor(data, data.look, shape, 0, &cache, still),
            model::renderHighlightsFor(data, data.look, shape, 0));
        // Bounded: old entries go.
        for (int i = 0; i < 20; ++i) {
            data.look.highlights[0].guide = Eigen::Vector3f(1.0f, float(i), 0.0f);
            model::renderHighlightsFor(data, data.look, shape, 0, &cache, still);
        }
        QVERIFY(cache.highlights.size() <= 8);
    }
};

QTEST_GUILESS_MAIN(TestRenderOutput)
#include "test_render_output.moc"
