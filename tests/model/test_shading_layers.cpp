// Layers of shading offsets in the document (paper 3, section 4.3): effective offsets = base +
// blended key layers (exactly a key's layer at its own view), each operation one undo step that
// undo and redo restore exactly, refusals that change nothing, the file round trip, old files,
// and automatic offsets through the document.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/model/analysis/auto_offsets.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/data/blend_evaluator.h"
#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"
#include "celform/model/data/shading_layers.h"

#include <QTemporaryDir>

#include <cmath>
#include <limits>

using namespace celform;
using namespace celform::model;

namespace {

Camera cameraAt(const Eigen::Vector3d& eye)
{
    Camera c;
    c.eye = eye;
    c.target = Eigen::Vector3d::Zero();
    c.up = std::abs(eye.normalized().y()) > 0.99 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(0, 1, 0);
    return c;
}

std::vector<float> ramp(std::size_t n, float scale)
{
    std::vector<float> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = scale * std::sin(0.37f * float(i));
    return v;
}

} // namespace

class TestShadingLayers : public QObject {
    Q_OBJECT

private:
    Document m_doc;
    std::size_t m_n = 0;

    /// The document holds an icosphere lit from (1, 0.2, 0.3); the request sees it from +z at
    /// size x size pixels, the window's percentile 0.5.
    AutoOffsetsRequest litSphere(int size)
    {
        ProjectData data;
        data.baseMesh = test::icosphere(4);
        data.look.light.vector = Eigen::Vector3d(1.0, 0.2, 0.3);
        m_doc.reset(std::move(data));
        AutoOffsetsRequest request;
        request.camera = cameraAt({0, 0, 5});
        request.width = size;
        request.height = size;
        request.percentile = 0.5f;
        return request;
    }

private slots:
    void init()
    {
        ProjectData data;
        data.baseMesh = test::icosphere(3);
        data.baseMeshName = QStringLiteral("sphere");
        m_n = std::size_t(data.baseMesh->vertexCount());
        m_doc.reset(std::move(data));
    }

    void effectiveIsBasePlusBlendedKeys()
    {
        const ObjectId front = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const ObjectId side = m_doc.keys().createKey(QStringLiteral("side"), cameraAt({5, 0, 0}));
        const std::vector<float> base = ramp(m_n, 0.1f), a = ramp(m_n, -0.3f), b = ramp(m_n, 0.2f);
        m_doc.shading().setShadingOffsets({0, 0}, base);
        m_doc.shading().setShadingOffsets({front, 0}, a);
        m_doc.shading().setShadingOffsets({side, 0}, b);
        BlendEvaluator& blender = m_doc.blender();
        std::vector<float> out;
        // At a key's exact view: base + that key's layer.
        effectiveShadingOffsets(m_doc.data(), blender, Eigen::Vector3d(0, 0, 1), 0, out);
        QCOMPARE(out.size(), m_n);
        for (std::size_t v = 0; v < m_n; ++v)
            QVERIFY(std::abs(out[v] - (base[v] + a[v])) < 1e-6f);
        // Between the keys: base + the blend's weights times the layers.
        const Eigen::Vector3d between = Eigen::Vector3d(1, 0, 1).normalized();
        const BlendResult w = blender.weights(m_doc.data(), between);
        double wa = 0, wb = 0;
        for (const KeyShare& s : w.shares)
            (s.key == front ? wa : wb) += s.key == front || s.key == side ? s.weight : 0.0;
        QVERIFY(wa > 0.1 && wb > 0.1);
        effectiveShadingOffsets(m_doc.data(), blender, between, 0, out);
        for (std::size_t v = 0; v < m_n; ++v)
            QVERIFY(std::abs(out[v] - float(base[v] + wa * a[v] + wb * b[v])) < 1e-5f);
        // Over time: a key layer keyed at 0 and 10 is halfway at 5 (two knots: linear).
        m_doc.shading().setShadingOffsets({front, 10}, std::vector<float>(m_n, 1.f));
        effectiveShadingOffsets(m_doc.data(), blender, Eigen::Vector3d(0, 0, 1), 5, out);
        for (std::size_t v = 0; v < m_n; ++v)
            QVERIFY(std::abs(out[v] - (base[v] + 0.5f * (a[v] + 1.f))) < 1e-5f);
    }

    void renderAndAnalysisSeeTheKeyLayer()
    {
        // celform render / analyze at a key's own view: the picture of base + the key's layer is
        // the picture of a project whose base layer holds that sum.
        const ObjectId front = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const std::vector<float> a = ramp(m_n, 0.4f);
        m_doc.shading().setShadingOffsets({front, 0}, a);
        RenderJob job;
        job.view = Eigen::Vector3d(0, 0, 1);
        job.size = QSize(96, 96);
        const FrameAnalysis withKey = analyseProject(m_doc.data(), QStringLiteral("k"), job, AnalysisSettings{});
        ProjectData flat = m_doc.data();
        flat.keys.front().shadingOffsetsByFrame.clear();
        flat.shadingOffsets = a;
        const FrameAnalysis withBase = analyseProject(flat, QStringLiteral("b"), job, AnalysisSettings{});
        QVERIFY(withKey.analysis.lambert == withBase.analysis.lambert);
        QVERIFY(withKey.passes.beauty.pixels == withBase.passes.beauty.pixels);
        // Without the layer the picture differs.
        flat.shadingOffsets.clear();
        const FrameAnalysis none = analyseProject(flat, QStringLiteral("n"), job, AnalysisSettings{});
        QVERIFY(none.analysis.lambert != withKey.analysis.lambert);
    }

    void everyOperationUndoesExactly()
    {
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const ProjectData start = m_doc.data();
        const int steps = m_doc.undoStack()->count();
        auto check = [&](const char* what) {
            const ProjectData after = m_doc.data();
            QVERIFY2(!(after == start), what);
            QCOMPARE(m_doc.undoStack()->count(), steps + 1);
            m_doc.undoStack()->undo();
            QVERIFY2(m_doc.data() == start, what);
            m_doc.undoStack()->redo();
            QVERIFY2(m_doc.data() == after, what);
            m_doc.undoStack()->undo();
            QVERIFY(m_doc.data() == start);
        };
        m_doc.shading().setShadingOffsets({0, 0}, ramp(m_n, 0.2f));
        check("set base");
        m_doc.shading().setShadingOffsets({key, 3}, ramp(m_n, 0.2f));
        check("set key");
        // Smooth and clear on a layer that exists (set first, so count one more step).
        m_doc.shading().setShadingOffsets({0, 0}, ramp(m_n, 0.2f));
        const ProjectData withBase = m_doc.data();
        m_doc.shading().smoothShadingOffsets({0, 0}, 3);
        QCOMPARE(m_doc.undoStack()->count(), steps + 2);
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data() == withBase);
        m_doc.shading().clearShadingOffsets({0, 0});
        QVERIFY(m_doc.data().shadingOffsets.empty());
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data() == withBase);
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data() == start);

        // A paint stroke of many dabs is one step.
        OffsetBrush brush;
        brush.radius = 0.5;
        brush.strength = 0.1;
        brush.mirror = MirrorPlane::X;
        OffsetStroke stroke = m_doc.shading().beginOffsetStroke({key, 0}, brush, m_doc.data().baseMesh->vertices);
        std::size_t touched = 0;
        for (int i = 0; i < 5; ++i)
            touched += m_doc.shading().applyOffsetStroke(stroke, Eigen::Vector3d(0.2 * i, 0.0, 1.0).normalized());
        m_doc.shading().endOffsetStroke(stroke);
        QVERIFY(touched > 0);
        const auto& layer = m_doc.data().key(key)->shadingOffsetsByFrame.at(0);
        // Mirror: a vertex near (x, 0, z) and its twin near (-x, 0, z) both got paint.
        QVERIFY(*std::max_element(layer.begin(), layer.end()) > 0.05f);
        check("paint stroke");
    }

    void refusalsChangeNothing()
    {
        const ProjectData start = m_doc.data();
        std::vector<float> bad = ramp(m_n, 0.1f);
        bad[2] = std::numeric_limits<float>::quiet_NaN();
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.shading().setShadingOffsets({0, 0}, bad));
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.shading().setShadingOffsets({0, 0}, ramp(m_n + 1, 0.1f)));
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.shading().setShadingOffsets({999, 0}, ramp(m_n, 0.1f)));
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.shading().smoothShadingOffsets({0, 0}, 0));
        AutoOffsetsRequest request;
        request.camera = cameraAt({0, 0, 5});
        request.aggressiveness = 2.f;
        QVERIFY_THROWS_EXCEPTION(EditRefused, solveAutoOffsets(m_doc.data(), request));
        request.aggressiveness = 1.f;
        request.percentile = -0.5f;
        QVERIFY_THROWS_EXCEPTION(EditRefused, solveAutoOffsets(m_doc.data(), request));
        QVERIFY(m_doc.data() == start);
        QCOMPARE(m_doc.undoStack()->count(), 0);
    }

    void fileRoundTripAndOldFiles()
    {
        QTemporaryDir dir;
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        // Files written before key layers (the bundled samples) load unchanged, without layers.
        const ProjectData sample
            = loadProject(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-highlights.celform"));
        QVERIFY(sample.shadingOffsets.empty());
        for (const KeyViewpoint& k : sample.keys)
            QVERIFY(k.shadingOffsetsByFrame.empty());
        // A file without layers written now: it loads with none.
        const QString old = dir.filePath(QStringLiteral("old.celform"));
        m_doc.saveAs(old);
        const ProjectData oldData = loadProject(old);
        QVERIFY(oldData.shadingOffsets.empty());
        QVERIFY(oldData.keys.front().shadingOffsetsByFrame.empty());

        m_doc.shading().setShadingOffsets({0, 0}, ramp(m_n, 0.1f));
        m_doc.shading().setShadingOffsets({key, 0}, ramp(m_n, 0.3f));
        m_doc.shading().setShadingOffsets({key, 12}, ramp(m_n, -0.2f));
        const QString path = dir.filePath(QStringLiteral("layers.celform"));
        m_doc.saveAs(path);
        const ProjectData loaded = loadProject(path);
        QVERIFY(loaded == m_doc.data());
        QCOMPARE(loaded.keys.front().shadingOffsetsByFrame.size(), std::size_t(2));
    }

    void automaticOffsetsThroughTheDocument()
    {
        // A lit sphere seen from the side of the light: one segment, its ratio goes to 1 - Q.
        AutoOffsetsRequest request = litSphere(160);
        request.segments = OffsetSegments::All;
        const AutoOffsetsResult result = solveAutoOffsets(m_doc.data(), request);
        QVERIFY(!result.after.empty());
        // The solve reads the document and changes nothing; applying it is one undo step.
        QCOMPARE(m_doc.undoStack()->count(), 0);
        m_doc.shading().applyAutoOffsets(result.target, result.values);
        QCOMPARE(m_doc.undoStack()->count(), 1);
        QCOMPARE(m_doc.undoStack()->text(0), QStringLiteral("Automatic Shading Offsets (base)"));
        for (std::size_t s = 0; s < result.after.size(); ++s) {
            if (!result.report.covered[s])
                continue;
            QVERIFY2(std::abs(result.after[s].ratio - 0.5f) <= 1.f / float(result.after[s].pixels) + 1e-6f,
                qPrintable(QStringLiteral("segment %1: %2 -> %3")
                               .arg(s)
                               .arg(double(result.before[s].ratio))
                               .arg(double(result.after[s].ratio))));
        }
        QCOMPARE(m_doc.data().shadingOffsets.size(), std::size_t(m_doc.data().baseMesh->vertexCount()));
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data().shadingOffsets.empty());
    }

    // Issue 26, fix 5: by default only the segments outside the window are solved (thesis 4.3).
    void automaticOffsetsSolveOnlySegmentsOutsideTheWindow()
    {
        AutoOffsetsRequest request = litSphere(96);
        const AutoOffsetsResult all = solveAutoOffsets(m_doc.data(), request);
        QVERIFY(!all.before.empty());
        const float ratio = all.before.front().ratio;
        // A window around the sphere's ratio: nothing to solve, the values stay zero.
        request.analysis.window = {std::max(0.f, ratio - 0.05f), std::min(1.f, ratio + 0.05f)};
        const AutoOffsetsResult inside = solveAutoOffsets(m_doc.data(), request);
        QCOMPARE(inside.report.covered.front(), std::uint8_t(0));
        QCOMPARE(inside.after.front().ratio, inside.before.front().ratio);
        for (float v : inside.values)
            QCOMPARE(v, 0.f);
        // --segments all solves it anyway.
        request.segments = OffsetSegments::All;
        const AutoOffsetsResult forced = solveAutoOffsets(m_doc.data(), request);
        QCOMPARE(forced.report.covered.front(), std::uint8_t(1));
        QVERIFY(std::abs(forced.after.front().ratio - 0.5f) <= 1.f / float(forced.after.front().pixels) + 1e-6f);
    }

    // Issue 26, fix 4: a key layer seen with a tiny weight stores values within the solve's bound,
    // not the field divided by the weight (about +-2,500 for weights near 0.001).
    void keyLayerOffsetsStayWithinTheLimit()
    {
        const ObjectId front = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const ObjectId side = m_doc.keys().createKey(QStringLiteral("side"), cameraAt({5, 0, 0}));
        Q_UNUSED(front);
        BlendEvaluator blend;
        blend.update(m_doc.data());
        // A view near the front key where the side key weighs little but more than 1e-3.
        Eigen::Vector3d view = Eigen::Vector3d::UnitZ();
        double weight = 0.0;
        for (double angle = 0.0; angle < 1.5 && !(weight > 1e-3 && weight < 0.05); angle += 0.002) {
            view = Eigen::Vector3d(std::sin(angle), 0.0, std::cos(angle));
            weight = 0.0;
            for (const KeyShare& share : blend.weights(m_doc.data(), view).shares)
                if (share.key == side)
                    weight = share.weight;
        }
        QVERIFY2(weight > 1e-3 && weight < 0.05, qPrintable(QString::number(weight)));
        AutoOffsetsRequest request;
        request.target = {side, 0};
        request.camera = cameraAt(5.0 * view);
        request.width = 96;
        request.height = 96;
        request.percentile = 0.05f; // nearly all bright: large offsets
        request.segments = OffsetSegments::All;
        const AutoOffsetsResult result = solveAutoOffsets(m_doc.data(), request);
        const algo::SegmentOffsetSettings bound;
        float largest = 0.f;
        for (float v : result.values)
            largest = std::max(largest, std::abs(v));
        QVERIFY2(largest <= bound.limit, qPrintable(QString::number(double(largest))));
        QVERIFY(largest > 0.f);
    }
};

QTEST_GUILESS_MAIN(TestShadingLayers)
#include "test_shading_layers.moc"
