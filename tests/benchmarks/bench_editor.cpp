// Edits in the editor window, end to end: from the event a control or tool receives to the document
// change handled by every listener (viewport, observer, scene, properties, sphere, look, highlights,
// history), before any paint. Needs an X server: run under xvfb-run.
// - brush step: one mouse move of a brush stroke on a key, on the bundled elephant sample and on
//   the 871k-triangle dragon with about 5,000 vertices in the radius. Baseline in the same run: the
//   same step through a document nobody listens to (Document::applyBrushStroke alone).
// - brush step with upload: the same step followed by what the next paint does first, bringing
//   the viewport's VTK arrays up to date (the displayed shape's touched rows and their normals),
//   on the elephant and on the dragon with about 500 and about 5,000 vertices in the radius: the
//   cost follows the brush, not the mesh. (The GL draw itself, VTK's buffer upload and the
//   rasterisation, is not in it.)
// - highlight spin-box step: one step of the Highlights dock's epsilon spin box on the armadillo
//   with three layers, with the number of change notifications it caused. Baseline: the same key
//   edit through a document nobody listens to.
#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"

#include "bench_data.h"
#include "bench_gui.h"
#include "editor/main_window.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QUndoStack>

#include <algorithm>
#include <memory>

namespace {

using namespace celform;

/// Draws frames until the viewport has drawn one more than it had; false after 20 s.
bool awaitFrame(views::Viewport& viewport)
{
    const int before = viewport.renderCount();
    viewport.update();
    QElapsedTimer timer;
    timer.start();
    while (viewport.renderCount() == before) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        if (timer.elapsed() > 20000)
            return false;
    }
    return true;
}

std::unique_ptr<app::MainWindow>& windowSlot()
{
    static std::unique_ptr<app::MainWindow> slot;
    return slot;
}

/// The editor window, shown at 1400x900 with the sample (observer dock closed, as by default).
app::MainWindow* window()
{
    auto& slot = windowSlot();
    if (slot || qEnvironmentVariableIsEmpty("DISPLAY"))
        return slot.get();
    slot = std::make_unique<app::MainWindow>(app::MainWindow::Mode::Batch);
    slot->resize(1400, 900);
    slot->show();
    if (!slot->openFile(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"))
        || !awaitFrame(*slot->viewport()))
        slot.reset();
    return slot.get();
}

/// The radius around vertex picked that selects about `count` vertices of shape.
double radiusFor(const algo::Positions& shape, std::uint32_t picked, std::size_t count)
{
    std::vector<float> d(std::size_t(shape.rows()));
    for (Eigen::Index v = 0; v < shape.rows(); ++v)
        d[std::size_t(v)] = (shape.row(v) - shape.row(picked)).norm();
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(count), d.end());
    return double(d[count]) * 1.0001;
}

struct BrushRun {
    std::int64_t selected = 0;
    bool ok = false;
};

/// Puts the window's document on `data` with one key from the front, the key shown with the brush
/// tool, and presses at the model's centre. radiusVertices > 0 sizes the brush to that many.
BrushRun startStroke(app::MainWindow& w, model::ProjectData data, std::size_t radiusVertices)
{
    model::Document& doc = *w.document();
    views::Viewport& vp = *w.viewport();
    doc.reset(std::move(data));
    vp.resetView();
    const model::ObjectId key = doc.createKey(QStringLiteral("front"), vp.camera());
    vp.setDisplayedKey(key);
    vp.setTool(views::Viewport::Tool::Brush);
    if (!awaitFrame(vp))
        return {};
    const QPoint centre(vp.width() / 2, vp.height() / 2);
    const std::int64_t picked = vp.pickVertex(centre);
    if (picked < 0)
        return {};
    if (radiusVertices > 0)
        vp.tool<views::BrushTool>().size().setRadius(
            radiusFor(vp.displayedShape(), std::uint32_t(picked), radiusVertices));
    QMouseEvent press(
        QEvent::MouseButtonPress, centre, vp.mapToGlobal(centre), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&vp, &press);
    // The first step keys the frame (allocations of a new undo step): outside the timing.
    QPoint p = centre + QPoint(1, 0);
    QMouseEvent move(QEvent::MouseMove, p, vp.mapToGlobal(p), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&vp, &move);
    BrushRun run;
    run.ok = true;
    const model::KeyViewpoint* k = doc.data().key(key);
    run.selected = k && !k->offsetsByFrame.empty() ? std::int64_t(k->offsetsByFrame.begin()->second.indices.size()) : 0;
    return run;
}

void endStroke(app::MainWindow& w)
{
    views::Viewport& vp = *w.viewport();
    const QPoint centre(vp.width() / 2, vp.height() / 2);
    QMouseEvent release(
        QEvent::MouseButtonRelease, centre, vp.mapToGlobal(centre), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(&vp, &release);
    vp.setTool(views::Viewport::Tool::Navigate);
    awaitFrame(vp); // the frames the steps asked for, outside the timing
}

/// One mouse move per iteration, alternating right and left by two pixels; withUpload: each
/// followed by the viewport's scene sync a paint starts with (its VTK arrays updated).
void brushSteps(benchmark::State& state, model::ProjectData data, std::size_t radiusVertices, bool withUpload = false)
{
    app::MainWindow* w = window();
    if (!w) {
        state.SkipWithError("needs an X server (run under xvfb-run)");
        return;
    }
    const BrushRun run = startStroke(*w, std::move(data), radiusVertices);
    if (!run.ok) {
        state.SkipWithError("nothing picked at the centre");
        return;
    }
    views::Viewport& vp = *w->viewport();
    const QPoint centre(vp.width() / 2, vp.height() / 2);
    int dx = 3;
    for (auto _ : state) {
        const QPoint p = centre + QPoint(dx, 0);
        dx = dx == 3 ? 1 : 3;
        QMouseEvent move(QEvent::MouseMove, p, vp.mapToGlobal(p), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&vp, &move);
        if (withUpload)
            benchmark::DoNotOptimize(vp.displayedShape().data()); // brings the scene in step first
    }
    state.counters["selected"] = double(run.selected);
    endStroke(*w);
}

/// The same steps through a document with no listener: the document's own share.
void documentOnlySteps(benchmark::State& state, model::ProjectData data, std::size_t radiusVertices, double radius)
{
    model::Document doc;
    doc.reset(std::move(data));
    model::Camera camera;
    camera.eye = doc.data().baseMesh->centre() + Eigen::Vector3d(0, 0, 5);
    camera.target = doc.data().baseMesh->centre();
    const model::ObjectId key = doc.createKey(QStringLiteral("front"), camera);
    // The vertex nearest the centre, as the viewport's pick roughly finds.
    const algo::Positions& base = doc.data().baseMesh->vertices;
    Eigen::Index picked = 0;
    (base.rowwise() - camera.target.cast<float>().transpose()).rowwise().squaredNorm().minCoeff(&picked);
    if (radiusVertices > 0)
        radius = radiusFor(base, std::uint32_t(picked), radiusVertices);
    model::BrushStroke stroke = doc.beginBrushStroke(key, 0, std::uint32_t(picked), radius, camera);
    doc.applyBrushStroke(stroke, {model::BrushMotion::Drag, 1e-4, 0.0});
    double dx = 3e-4;
    for (auto _ : state) {
        doc.applyBrushStroke(stroke, {model::BrushMotion::Drag, dx, 0.0});
        dx = -dx;
    }
    doc.endBrushStroke(stroke);
    state.counters["selected"] = double(stroke.indices.size());
}

model::ProjectData sampleData()
{
    model::Document doc;
    doc.open(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"));
    return doc.data();
}

model::ProjectData meshData(const algo::TriMesh* mesh, const char* name)
{
    return model::newProject(std::make_shared<algo::TriMesh>(*mesh), QString::fromLatin1(name));
}

void BM_BrushStepElephant(benchmark::State& state)
{
    // The editor's default radius for the model (8% of the diagonal).
    brushSteps(state, sampleData(), 0);
}

void BM_BrushStepElephantDocumentOnly(benchmark::State& state)
{
    const model::ProjectData data = sampleData();
    documentOnlySteps(state, data, 0, 0.08 * algo::boundingBox(data.baseMesh->vertices).diagonal().norm());
}

void BM_BrushStepDragon(benchmark::State& state)
{
    if (!bench::dragon()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    brushSteps(state, meshData(bench::dragon(), "stanford_dragon.ply"), 5000);
}

void BM_BrushStepElephantWithUpload(benchmark::State& state)
{
    brushSteps(state, sampleData(), 0, true);
}

void BM_BrushStepDragonWithUpload(benchmark::State& state)
{
    if (!bench::dragon()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    brushSteps(state, meshData(bench::dragon(), "stanford_dragon.ply"), std::size_t(state.range(0)), true);
}

void BM_BrushStepDragonDocumentOnly(benchmark::State& state)
{
    if (!bench::dragon()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    documentOnlySteps(state, meshData(bench::dragon(), "stanford_dragon.ply"), 5000, 0.0);
}

// --- the Highlights dock's epsilon spin box ---------------------------------------------------------

model::ProjectData armadilloWithLayers()
{
    const algo::TriMesh* armadillo = bench::sharedMesh("meshes/cgal_armadillo.off");
    model::ProjectData data = meshData(armadillo, "cgal_armadillo.off");
    using Op = algo::HighlightOperation;
    auto layer = [](const char* name, float epsilon, std::vector<Op> ops) {
        model::HighlightTrack t;
        t.name = QString::fromLatin1(name);
        algo::HighlightLayer l;
        l.shape.epsilon = epsilon;
        l.shape.operations = std::move(ops);
        t.keys.push_back({0.0, l});
        return t;
    };
    data.look.highlights.push_back(layer("key", 0.05f, {}));
    data.look.highlights.push_back(layer("shaped", 0.05f,
        {Op::rotation(30.f), Op::directionalScaling(0.5f), Op::split(0.3f, 0.2f), Op::squaring(0.2f, 2.f)}));
    data.look.highlights.push_back(layer("ring", 0.06f, {Op::translation(0.1f, 0.0f)}));
    return data;
}

void BM_HighlightSpinStep(benchmark::State& state)
{
    if (!bench::sharedMesh("meshes/cgal_armadillo.off")) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    app::MainWindow* w = window();
    if (!w) {
        state.SkipWithError("needs an X server (run under xvfb-run)");
        return;
    }
    model::Document& doc = *w->document();
    doc.reset(armadilloWithLayers());
    w->findChild<QDockWidget*>(QStringLiteral("highlightsDock"))->raise();
    auto* epsilon = w->findChild<QDoubleSpinBox*>(QStringLiteral("highlightEpsilon"));
    if (!epsilon || !awaitFrame(*w->viewport())) {
        state.SkipWithError("no Highlights dock");
        return;
    }
    int notifications = 0;
    const auto connection = QObject::connect(
        &doc, &model::Document::changed, [&notifications](const model::ChangeSet&) { ++notifications; });
    // A held arrow key: the steps of one gesture (GestureTracker opens it on the key press).
    doc.beginGesture();
    bool up = true;
    for (auto _ : state) {
        if (up)
            epsilon->stepUp();
        else
            epsilon->stepDown();
        up = !up;
    }
    doc.endGesture();
    QObject::disconnect(connection);
    state.counters["notifications_per_step"]
        = double(notifications) / double(std::max<std::int64_t>(state.iterations(), 1));
    doc.undoStack()->clear();
    awaitFrame(*w->viewport());
}

void BM_HighlightSpinStepDocumentOnly(benchmark::State& state)
{
    if (!bench::sharedMesh("meshes/cgal_armadillo.off")) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    model::Document doc;
    doc.reset(armadilloWithLayers());
    const model::ObjectId id = doc.data().look.highlights.front().id;
    float value = 0.05f;
    doc.beginGesture();
    for (auto _ : state) {
        algo::HighlightLayer layer = doc.data().highlight(id)->layerAt(0);
        value = value == 0.05f ? 0.06f : 0.05f;
        layer.shape.epsilon = value;
        doc.setHighlightKey(id, 0, layer);
    }
    doc.endGesture();
}

void microseconds(benchmark::internal::Benchmark* b)
{
    b->Unit(benchmark::kMicrosecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
}

} // namespace

BENCHMARK(BM_BrushStepElephant)->Apply(microseconds);
BENCHMARK(BM_BrushStepElephantDocumentOnly)->Apply(microseconds);
BENCHMARK(BM_BrushStepDragon)->Apply(microseconds);
BENCHMARK(BM_BrushStepDragonDocumentOnly)->Apply(microseconds);
BENCHMARK(BM_BrushStepElephantWithUpload)->Apply(microseconds);
BENCHMARK(BM_BrushStepDragonWithUpload)->Arg(500)->Arg(5000)->Apply(microseconds);
BENCHMARK(BM_HighlightSpinStep)->Apply(microseconds);
BENCHMARK(BM_HighlightSpinStepDocumentOnly)->Apply(microseconds);

int main(int argc, char** argv)
{
    return celform::bench::runViewportBenchmarks(argc, argv, [] { windowSlot().reset(); });
}
