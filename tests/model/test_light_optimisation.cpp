// Optimise Light for Stereo on a project: the document stores a run as one undo step
// and refuses a stale one; the run lowers the depth error of the thesis's dented sphere, of the
// armadillo and of the dragon, and the figures it reports are those `celform analyze` gives.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/analysis/light_optimisation.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/render/render_job.h"

#include <QUndoStack>

using namespace celform;

namespace {

model::ProjectData projectOn(std::shared_ptr<const algo::TriMesh> mesh)
{
    model::ProjectData data = model::newProject(std::move(mesh), QStringLiteral("mesh.obj"));
    // Front-lit, as the thesis starts its runs (5.0.3): mostly bright, few shading lines.
    data.look.light.vector = {0.1, 0.15, 1.0};
    return data;
}

model::LightOptimisationReport run(
    const model::ProjectData& data, const QSize& size, const std::optional<Eigen::Vector3d>& view = std::nullopt)
{
    model::RenderJob job;
    job.size = size;
    if (view)
        job.view = *view;
    return model::optimiseLightForJob(data, QStringLiteral("test.celform"), job, {});
}

model::LightOptimisationReport runWith(const model::ProjectData& data, const QSize& size,
    model::LightObjective objective, model::LightStart start = model::LightStart::Current)
{
    model::RenderJob job;
    job.size = size;
    model::LightOptimisationRequest request;
    request.objective = objective;
    request.start = start;
    return model::optimiseLightForJob(data, QStringLiteral("test.celform"), job, request);
}

} // namespace

class TestLightOptimisationModel : public QObject {
    Q_OBJECT

private slots:
    void lightTrackInterpolates()
    {
        // issue 26: directional keys turn along the great circle at a constant rate (slerp); the
        // end keys hold outside; point keys follow a spline through their positions.
        model::LightTrack track;
        const model::Light fallback{model::LightType::Directional, {0.0, 1.0, 0.0}};
        QCOMPARE(track.at(3, fallback), fallback);
        track.setKey(10, {model::LightType::Directional, {1.0, 0.0, 0.0}});
        track.setKey(0, {model::LightType::Directional, {0.0, 0.0, 1.0}});
        QCOMPARE(track.keys.front().frame, 0);
        QCOMPARE(track.at(-5, fallback).vector, Eigen::Vector3d(0, 0, 1));
        QCOMPARE(track.at(15, fallback).vector, Eigen::Vector3d(1, 0, 0));
        const Eigen::Vector3d half = track.at(5, fallback).vector;
        QVERIFY(std::abs(half.norm() - 1.0) < 1e-12);
        QVERIFY((half - Eigen::Vector3d(std::sqrt(0.5), 0.0, std::sqrt(0.5))).norm() < 1e-12);
        const model::Light quarter = track.at(2.5, fallback);
        QVERIFY(std::abs(model::lightTurnDegrees(track.keys[0].light, quarter, Eigen::Vector3d::Zero()) - 22.5) < 1e-9);
        // Point lights: through the keys, and between a directional and a point key the earlier holds.
        model::LightTrack points;
        points.setKey(0, {model::LightType::Point, {0.0, 0.0, 0.0}});
        points.setKey(10, {model::LightType::Point, {10.0, 0.0, 0.0}});
        points.setKey(20, {model::LightType::Point, {20.0, 0.0, 0.0}});
        QVERIFY((points.at(5, fallback).vector - Eigen::Vector3d(5, 0, 0)).norm() < 1e-9);
        points.setKey(30, {model::LightType::Directional, {0.0, 1.0, 0.0}});
        QCOMPARE(points.at(25, fallback).type, model::LightType::Point);
        // The turn limit: turned back along the great circle to the limit.
        const model::Light limited
            = model::limitLightTurn(track.keys[0].light, track.keys[1].light, Eigen::Vector3d::Zero(), 3.0);
        QVERIFY(std::abs(model::lightTurnDegrees(track.keys[0].light, limited, Eigen::Vector3d::Zero()) - 3.0) < 1e-9);
        QVERIFY(model::lightTrackProblem(track).isEmpty());
        track.keys.push_back(track.keys.front()); // frame 0 after frame 10
        QVERIFY(!model::lightTrackProblem(track).isEmpty());
    }

    void lightTrackEditsAreUndoable()
    {
        model::Document doc;
        doc.reset(projectOn(test::dentedSphere(3, {0.4f, 0.3f, 0.87f})));
        const model::Light single = doc.data().look.light;
        model::LightTrack track;
        track.setKey(0, {model::LightType::Directional, {0.0, 0.0, 1.0}});
        track.setKey(8, {model::LightType::Directional, {0.0, 1.0, 0.0}});
        doc.look().applyOptimisedLightTrack({}, track);
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Optimise Light Along Shot"));
        QCOMPARE(doc.data().look.lightTrack, track);
        QCOMPARE(doc.data().look.lightAt(8).vector, Eigen::Vector3d(0, 1, 0));
        // A stale run is refused; an invalid track is refused.
        QVERIFY_THROWS_EXCEPTION(model::EditRefused, doc.look().applyOptimisedLightTrack({}, track));
        model::LightTrack bad = track;
        bad.keys[1].light.vector.setZero();
        QVERIFY_THROWS_EXCEPTION(model::EditRefused, doc.look().setLightTrack(bad, QStringLiteral("Bad")));
        // With a track, moving the light keys the current frame; a single-frame optimisation keys its frame.
        doc.setCurrentFrame(4);
        doc.look().setLight({model::LightType::Directional, {1.0, 0.0, 0.0}});
        QCOMPARE(doc.data().look.lightTrack.keys.size(), std::size_t(3));
        QCOMPARE(doc.data().look.lightAt(4).vector, Eigen::Vector3d(1, 0, 0));
        QCOMPARE(doc.data().look.light, single);
        doc.look().applyOptimisedLight(doc.data().look.lightAt(6), {model::LightType::Directional, {0, 0, -1}}, 6);
        QVERIFY(doc.data().look.lightTrack.hasKey(6));
        QCOMPARE(doc.undoStack()->count(), 3);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.data().look.lightTrack, track);
        doc.undoStack()->undo();
        QVERIFY(doc.data().look.lightTrack.empty());
        QCOMPARE(doc.data().look.lightAt(8), single);
    }

    void oneUndoStepAndNothingStale()
    {
        model::Document doc;
        doc.reset(projectOn(test::dentedSphere(4, {0.4f, 0.3f, 0.87f})));
        const model::Light start = doc.data().look.light;
        const model::LightOptimisationReport report = run(doc.data(), {240, 240}, Eigen::Vector3d(0, 0, 1));
        QVERIFY(!(report.after == report.before));
        QCOMPARE(report.before, start);

        doc.look().applyOptimisedLight(report.before, report.after, report.frame);
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Optimise Light for Stereo"));
        QCOMPARE(doc.data().look.light, report.after);
        doc.undoStack()->undo();
        QCOMPARE(doc.data().look.light, start);
        doc.undoStack()->redo();
        QCOMPARE(doc.data().look.light, report.after);

        // A report made from another light is refused, the document unchanged.
        QVERIFY_THROWS_EXCEPTION(
            model::EditRefused, doc.look().applyOptimisedLight(report.before, report.after, report.frame));
        QCOMPARE(doc.undoStack()->count(), 1);
        // A run that kept the light changes nothing.
        doc.undoStack()->undo();
        doc.look().applyOptimisedLight(start, start, 0);
        QCOMPARE(doc.data().look.light, start);
        QCOMPARE(doc.undoStack()->index(), 0);
    }

    void reportMatchesTheAnalysis()
    {
        const model::ProjectData data = projectOn(test::dentedSphere(4, {0.4f, 0.3f, 0.87f}));
        const model::LightOptimisationReport report = run(data, {240, 240}, Eigen::Vector3d(0, 0, 1));
        // Before: the analysis of the project as it is; after: the analysis with the light found.
        model::RenderJob job;
        job.size = {240, 240};
        job.view = Eigen::Vector3d(0, 0, 1);
        const model::FrameAnalysis before = model::analyseProject(data, QStringLiteral("t"), job, {});
        QCOMPARE(report.mseBefore, before.analysis.meanSquaredError);
        QCOMPARE(report.segmentsBefore.size(), before.analysis.stats.size());
        model::ProjectData moved = data;
        moved.look.light = report.after;
        const model::FrameAnalysis after = model::analyseProject(moved, QStringLiteral("t"), job, {});
        QCOMPARE(report.mseAfter, after.analysis.meanSquaredError);
        for (std::size_t s = 0; s < after.analysis.stats.size(); ++s) {
            QCOMPARE(report.segmentsAfter[s].bright, after.analysis.stats[s].bright);
            // The optimiser's own count of the same pixels agrees within a pixel per 2000.
            QVERIFY(std::abs(report.run.ratioAfter[s] - after.analysis.stats[s].ratio) <= 5e-4f);
        }
        qInfo("dented sphere: MSE %.6g -> %.6g, %d -> %d of %d segments, light (%.3f %.3f %.3f) -> (%.3f %.3f %.3f)",
            report.mseBefore, report.mseAfter, algo::segmentsInWindow(report.segmentsBefore),
            algo::segmentsInWindow(report.segmentsAfter), int(report.segmentsBefore.size()), report.before.vector.x(),
            report.before.vector.y(), report.before.vector.z(), report.after.vector.x(), report.after.vector.y(),
            report.after.vector.z());
        QVERIFY(report.mseAfter < report.mseBefore);
        QVERIFY(algo::segmentsInWindow(report.segmentsAfter) > algo::segmentsInWindow(report.segmentsBefore));
    }

    void lowersTheDepthErrorOfRealModels_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("armadillo") << QStringLiteral("meshes/cgal_armadillo.off");
        QTest::newRow("dragon") << QStringLiteral("meshes/stanford_dragon.ply");
    }
    void lowersTheDepthErrorOfRealModels()
    {
        QFETCH(QString, file);
        CELFORM_REQUIRE_SHARED(path, file);
        if (test::kAddressSanitizer && file.contains(QLatin1String("dragon")))
            QSKIP("the dragon is too slow under AddressSanitizer");
        auto mesh = std::make_shared<algo::TriMesh>(model::importMesh(path, model::ImportIsolation::ThisProcess).mesh);
        const model::ProjectData data = projectOn(mesh);
        const model::LightOptimisationReport report = run(data, {480, 360});
        qInfo("%s: MSE %.6g -> %.6g, %d -> %d of %d segments in the window, light (%.3f %.3f %.3f), %.0f ms "
              "(iterations %.1f ms)",
            qPrintable(file), report.mseBefore, report.mseAfter, algo::segmentsInWindow(report.segmentsBefore),
            algo::segmentsInWindow(report.segmentsAfter), int(report.segmentsBefore.size()), report.after.vector.x(),
            report.after.vector.y(), report.after.vector.z(), report.milliseconds, report.optimiseMilliseconds);
        QVERIFY(report.run.objectiveAfter < report.run.objectiveBefore);
        QVERIFY2(report.mseAfter < report.mseBefore,
            qPrintable(QStringLiteral("%1 -> %2").arg(report.mseBefore).arg(report.mseAfter)));
    }

    // Issue 26, "an objective that cannot make depth worse": on the fandisk the thesis's ratios
    // raise the depth error (docs/light-optimisation.md); both and depth-error never return a
    // light whose MSE is above the start's, and the iteration records carry every segment's ratio.
    void bothNeverRaisesTheDepthError()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_fandisk.off"));
        auto mesh = std::make_shared<algo::TriMesh>(model::importMesh(path, model::ImportIsolation::ThisProcess).mesh);
        const model::ProjectData data = projectOn(mesh);
        const QSize size(240, 180);
        const model::LightOptimisationReport ratios = runWith(data, size, model::LightObjective::Ratios);
        const model::LightOptimisationReport both = runWith(data, size, model::LightObjective::Both);
        const model::LightOptimisationReport depth = runWith(data, size, model::LightObjective::DepthError);
        qInfo("fandisk 240x180: MSE start %.6g; ratios %.6g, both %.6g, depth-error %.6g (%d search visits, %.0f ms)",
            ratios.mseBefore, ratios.mseAfter, both.mseAfter, depth.mseAfter, int(depth.search.visits.size()),
            depth.milliseconds);
        QVERIFY2(both.mseAfter <= both.mseBefore,
            qPrintable(QStringLiteral("%1 -> %2").arg(both.mseBefore).arg(both.mseAfter)));
        QVERIFY(depth.mseAfter <= depth.mseBefore);
        QCOMPARE(both.mseBefore, ratios.mseBefore);
        // Both keeps the thesis's answer when it does not raise the MSE; else it searched.
        if (ratios.mseAfter <= ratios.mseBefore)
            QCOMPARE(both.after, ratios.after);
        else
            QVERIFY(!both.search.visits.empty());
        QVERIFY(!ratios.run.iterations.empty());
        for (const algo::LightIteration& it : ratios.run.iterations)
            QCOMPARE(it.ratios.size(), ratios.segmentsBefore.size());
        // The thesis's start: the light at the camera.
        const model::LightOptimisationReport camera
            = runWith(data, size, model::LightObjective::Both, model::LightStart::Camera);
        QCOMPARE(camera.before, data.look.light);
        QVERIFY(!(camera.start == data.look.light));
        QVERIFY(camera.mseAfter <= camera.mseBefore);
    }
};

QTEST_GUILESS_MAIN(TestLightOptimisationModel)
#include "test_light_optimisation.moc"
