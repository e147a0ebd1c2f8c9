// The artist's say over the depth analysis (paper 3, 6.2; issue 26): focal points (per-face
// importance weighing each segment in the light optimisation) and the segment brush (per-face
// overrides merging and splitting the analysis's segments), through the document with undo and
// through the project file.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/light_optimisation.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/light_optimisation.h"
#include "celform/model/analysis/segment_overrides.h"
#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"

#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>

using namespace celform;

namespace {

/// Two unit icospheres side by side (centres at x = -1.6 and +1.6): seen from +Z each is one
/// segment of the analysis. Faces of the left sphere come first (leftFaces of them).
std::shared_ptr<algo::TriMesh> twoSpheres(Eigen::Index* leftFaces = nullptr)
{
    const auto one = test::icosphere(3);
    auto mesh = std::make_shared<algo::TriMesh>();
    const Eigen::Index v = one->vertices.rows(), f = one->faces.rows();
    mesh->vertices.resize(2 * v, 3);
    mesh->faces.resize(2 * f, 3);
    mesh->vertices.topRows(v) = one->vertices;
    mesh->vertices.bottomRows(v) = one->vertices;
    mesh->vertices.topRows(v).col(0).array() -= 1.6f;
    mesh->vertices.bottomRows(v).col(0).array() += 1.6f;
    mesh->faces.topRows(f) = one->faces;
    mesh->faces.bottomRows(f) = one->faces.array() + std::int32_t(v);
    if (leftFaces)
        *leftFaces = f;
    return mesh;
}

model::ProjectData projectOn(std::shared_ptr<const algo::TriMesh> mesh)
{
    model::ProjectData data = model::newProject(std::move(mesh), QStringLiteral("spheres.obj"));
    data.look.light.vector = Eigen::Vector3d(0.1, 0.15, 1.0).normalized(); // front-lit (thesis 5.0.3)
    return data;
}

model::RenderJob frontJob()
{
    model::RenderJob job;
    job.size = QSize(320, 160);
    job.view = Eigen::Vector3d(0, 0, 1);
    return job;
}

/// The segments of the analysis seen from +Z, with the base face at each pixel and the vote.
model::SegmentPicture pictureOf(const model::ProjectData& data, model::FrameAnalysis* analysed = nullptr)
{
    model::SegmentPicture picture;
    const model::FrameAnalysis a
        = model::analyseProject(data, QStringLiteral("test.celform"), frontJob(), {}, &picture.faces);
    picture.segments = a.analysis.segments;
    model::voteSegmentFaces(picture, std::int32_t(data.baseMesh->faceCount()));
    if (analysed)
        *analysed = a;
    return picture;
}

/// The segment whose centroid is on the given side of the picture's middle.
int segmentOnSide(const model::FrameAnalysis& a, bool right)
{
    int best = -1;
    for (std::size_t s = 0; s < a.analysis.stats.size(); ++s)
        if ((a.analysis.stats[s].centroid.x() > 160.f) == right
            && (best < 0 || a.analysis.stats[s].pixels > a.analysis.stats[std::size_t(best)].pixels))
            best = int(s);
    return best;
}

/// Samples of two segments of eight pixels each, by hand: A's normals lean to +X, B's to -X, all
/// towards the viewer a little (z 0.3); the toon threshold 0.5 everywhere.
algo::ShadingSamples handSamples(bool withB = true)
{
    algo::ShadingSamples s;
    const int segments = withB ? 2 : 1;
    for (int seg = 0; seg < segments; ++seg)
        for (int i = 0; i < 8; ++i) {
            const Eigen::Vector3f n = Eigen::Vector3f(seg == 0 ? 1.f : -1.f, -1.f + float(i) / 3.5f, 0.3f).normalized();
            s.nx.push_back(n.x());
            s.ny.push_back(n.y());
            s.nz.push_back(n.z());
            s.px.push_back(0.f);
            s.py.push_back(0.f);
            s.pz.push_back(0.f);
            s.threshold.push_back(0.5f);
        }
    s.segmentStart = withB ? std::vector<std::int32_t>{0, 8, 16} : std::vector<std::int32_t>{0, 8};
    s.normalSum.assign(std::size_t(segments), Eigen::Vector3d::Zero());
    for (int seg = 0; seg < segments; ++seg)
        for (int i = seg * 8; i < seg * 8 + 8; ++i)
            s.normalSum[std::size_t(seg)]
                += Eigen::Vector3d(s.nx[std::size_t(i)], s.ny[std::size_t(i)], s.nz[std::size_t(i)]);
    s.importance.assign(std::size_t(segments), 1.0);
    return s;
}

} // namespace

class TestArtistSay : public QObject {
    Q_OBJECT

private slots:
    void importanceWeighsTheObjective()
    {
        // By hand: a light straight at the viewer gives every pixel N.L = 0.3 / |n| < 0.5, so both
        // segments are dark (ratio 0), each 0.35 below the medium window: the objective is
        // 0.35 w_A + 0.35 w_B with constant weights w = importance.
        algo::ShadingSamples samples = handSamples();
        algo::LightOptimisationSettings settings;
        algo::LightEvaluation e;
        const algo::LightPose front{false, {0, 0, 1}};
        algo::evaluateLight(samples, front, settings, true, e);
        QCOMPARE(e.bright, (std::vector<std::int32_t>{0, 0}));
        QVERIFY(std::abs(e.objective - 0.70) < 1e-6);
        samples.importance = {1.0, 0.0};
        algo::evaluateLight(samples, front, settings, true, e);
        QVERIFY(std::abs(e.objective - 0.35) < 1e-6); // B's ratio no longer counts
        samples.importance = {1.0, 0.5};
        algo::evaluateLight(samples, front, settings, true, e);
        QVERIFY(std::abs(e.objective - 0.525) < 1e-6);
        // Area weights are multiplied too: A's share 8/16 times 1, B's 8/16 times 0.5.
        settings.weight = algo::SegmentWeight::Area;
        algo::evaluateLight(samples, front, settings, true, e);
        QVERIFY(std::abs(e.objective - (0.5 * 0.35 + 0.25 * 0.35)) < 1e-6);
    }

    void importanceZeroIsTheSegmentLeftOut()
    {
        // The run with B at importance 0 is the run without B: the same lights, step for step;
        // with B counting, A and B pull the light opposite ways and it ends elsewhere.
        algo::LightOptimisationSettings settings;
        algo::LightOptimisationWorkspace work;
        const algo::LightPose front{false, {0, 0, 1}};
        algo::ShadingSamples weighted = handSamples();
        weighted.importance = {1.0, 0.0};
        const algo::LightOptimisationResult withZero = algo::optimiseLight(weighted, front, settings, work);
        const algo::LightOptimisationResult alone = algo::optimiseLight(handSamples(false), front, settings, work);
        const algo::LightOptimisationResult both = algo::optimiseLight(handSamples(), front, settings, work);
        QVERIFY((withZero.after.vector - alone.after.vector).norm() < 1e-12);
        QCOMPARE(withZero.iterations.size(), alone.iterations.size());
        QVERIFY(withZero.after.vector.x() > 0.1); // turned towards A's side
        QVERIFY((both.after.vector - withZero.after.vector).norm() > 0.05);
        QCOMPARE(withZero.objectiveAfter, alone.objectiveAfter);
    }

    void segmentImportanceIsTheMeanOfItsFaces()
    {
        Eigen::Index left = 0;
        model::ProjectData data = projectOn(twoSpheres(&left));
        model::FrameAnalysis plain;
        pictureOf(data, &plain);
        QCOMPARE(plain.analysis.stats.size(), std::size_t(2));
        for (const algo::SegmentStats& s : plain.analysis.stats)
            QCOMPARE(s.importance, 1.f); // nothing painted: 1
        // The left sphere at 0.25, the right at 1 but for one in four of its faces at 0.
        data.faceImportance.assign(std::size_t(data.baseMesh->faceCount()), 1.f);
        for (Eigen::Index f = 0; f < left; ++f)
            data.faceImportance[std::size_t(f)] = 0.25f;
        for (Eigen::Index f = left; f < data.baseMesh->faceCount(); f += 4)
            data.faceImportance[std::size_t(f)] = 0.f;
        model::FrameAnalysis painted;
        const model::SegmentPicture picture = pictureOf(data, &painted);
        const int l = segmentOnSide(painted, false), r = segmentOnSide(painted, true);
        QCOMPARE(painted.analysis.stats[std::size_t(l)].importance, 0.25f);
        // The right one: the mean over the faces the vote gives it, counted here by hand.
        double sum = 0.0;
        int faces = 0;
        for (std::size_t f = 0; f < picture.owner.size(); ++f)
            if (picture.owner[f] == r) {
                sum += data.faceImportance[f];
                ++faces;
            }
        QVERIFY(faces > 100);
        QVERIFY(std::abs(painted.analysis.stats[std::size_t(r)].importance - float(sum / faces)) < 1e-6f);
        QVERIFY(painted.analysis.stats[std::size_t(r)].importance < 0.9f);
        // The segments themselves do not change.
        QCOMPARE(painted.analysis.segments.labels, plain.analysis.segments.labels);
    }

    void importanceChangesTheOptimisedLight()
    {
        Eigen::Index left = 0;
        model::ProjectData data = projectOn(twoSpheres(&left));
        model::LightOptimisationRequest request;
        request.objective = model::LightObjective::Ratios;
        const QString source = QStringLiteral("test.celform");
        const model::LightOptimisationReport plain = model::optimiseLightForJob(data, source, frontJob(), request);
        // The right sphere without any say: the objective before is the left one's distance alone.
        data.faceImportance.assign(std::size_t(data.baseMesh->faceCount()), 1.f);
        for (Eigen::Index f = left; f < data.baseMesh->faceCount(); ++f)
            data.faceImportance[std::size_t(f)] = 0.f;
        const model::LightOptimisationReport focused = model::optimiseLightForJob(data, source, frontJob(), request);
        QCOMPARE(focused.segmentsBefore.size(), std::size_t(2));
        auto distance = [](float ratio) { return std::max({0.0, 0.35 - double(ratio), double(ratio) - 0.65}); };
        double byHand = 0.0, all = 0.0;
        for (const algo::SegmentStats& s : focused.segmentsBefore) {
            byHand += double(s.importance) * distance(s.ratio);
            all += distance(s.ratio);
        }
        QVERIFY(std::abs(focused.ratiosBefore - byHand) < 1e-6);
        QVERIFY(std::abs(plain.ratiosBefore - all) < 1e-6);
        QVERIFY(focused.ratiosBefore < plain.ratiosBefore);
        QVERIFY(!(focused.after == plain.after));
        // The left sphere, the only one counting, ends inside the window.
        for (const algo::SegmentStats& s : focused.segmentsAfter)
            if (s.importance > 0.5f)
                QVERIFY2(s.inWindow, qPrintable(QString::number(double(s.ratio))));
    }

    void importanceStrokeIsOneUndoStep()
    {
        model::Document doc;
        doc.reset(projectOn(twoSpheres()));
        QVERIFY(doc.data().faceImportance.empty());
        QVERIFY_THROWS_EXCEPTION(model::EditRefused, (void)doc.faceSets().beginImportanceStroke(1.5f, 1.f));
        QVERIFY_THROWS_EXCEPTION(model::EditRefused, (void)doc.faceSets().beginImportanceStroke(0.f, 0.f));
        model::FaceSetStroke stroke = doc.faceSets().beginImportanceStroke(0.f, 0.5f);
        QCOMPARE(doc.faceSets().applyFaceSetStroke(stroke, {1, 2, 3}, false), std::size_t(3));
        // Faces the stroke has painted are not painted again: 3 stays at 0.5, 4 is new.
        QCOMPARE(doc.faceSets().applyFaceSetStroke(stroke, {3, 4}, false), std::size_t(1));
        doc.faceSets().endFaceSetStroke(stroke);
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Paint Focal Points"));
        const std::vector<float>& v = doc.data().faceImportance;
        QCOMPARE(v.size(), std::size_t(doc.data().baseMesh->faceCount()));
        QCOMPARE(v[0], 1.f);
        QCOMPARE(v[3], 0.5f);
        QCOMPARE(v[4], 0.5f);
        // A second stroke goes half the rest of the way; erase (Ctrl) paints towards 1.
        stroke = doc.faceSets().beginImportanceStroke(0.f, 0.5f);
        doc.faceSets().applyFaceSetStroke(stroke, {3}, false);
        doc.faceSets().endFaceSetStroke(stroke);
        QCOMPARE(doc.data().faceImportance[3], 0.25f);
        stroke = doc.faceSets().beginImportanceStroke(0.f, 1.f);
        doc.faceSets().applyFaceSetStroke(stroke, {4}, true);
        doc.faceSets().endFaceSetStroke(stroke);
        QCOMPARE(doc.data().faceImportance[4], 1.f);
        QCOMPARE(doc.undoStack()->count(), 3);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.data().faceImportance[3], 0.5f);
        doc.undoStack()->undo();
        QVERIFY(doc.data().faceImportance.empty()); // as before the first stroke
        doc.undoStack()->redo();
        QCOMPARE(doc.data().faceImportance[1], 0.5f);
        doc.faceSets().clearFaceImportance();
        QVERIFY(doc.data().faceImportance.empty());
        doc.undoStack()->undo();
        QCOMPARE(doc.data().faceImportance[2], 0.5f);
    }

    void sayRoundTripsThroughTheFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        model::ProjectData data = projectOn(twoSpheres());
        const std::size_t faces = std::size_t(data.baseMesh->faceCount());
        data.faceImportance.assign(faces, 1.f);
        data.faceImportance[7] = 0.125f;
        data.faceImportance[faces - 1] = 0.f;
        data.segmentOverrides.assign(faces, model::kNoSegmentOverride);
        data.segmentOverrides[3] = 0;
        data.segmentOverrides[9] = 1;
        const QString path = dir.filePath(QStringLiteral("say.celform"));
        model::saveProject(data, path);
        const model::ProjectData back = model::loadProject(path);
        QCOMPARE(back.faceImportance, data.faceImportance);
        QCOMPARE(back.segmentOverrides, data.segmentOverrides);
        QVERIFY(back == data);
        // Without the say the manifest has no such keys, and the project opens without one.
        const QString plainPath = dir.filePath(QStringLiteral("plain.celform"));
        model::saveProject(projectOn(twoSpheres()), plainPath);
        QFile plainFile(plainPath);
        QVERIFY(plainFile.open(QIODevice::ReadOnly));
        const QByteArray bytes = plainFile.readAll();
        QVERIFY(!bytes.contains("face_importance"));
        QVERIFY(!bytes.contains("segment_overrides"));
        QVERIFY(model::loadProject(plainPath).faceImportance.empty());
    }

    void damagedSayIsRefusedAndANewModelDropsIt()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::size_t faces = std::size_t(twoSpheres()->faceCount());
        // Values out of range do not open: the file is damaged.
        for (int which = 0; which < 2; ++which) {
            model::ProjectData data = projectOn(twoSpheres());
            if (which == 0)
                data.faceImportance.assign(faces, 2.f);
            else
                data.segmentOverrides.assign(faces, -7);
            const QString path = dir.filePath(QStringLiteral("bad%1.celform").arg(which));
            model::saveProject(data, path);
            try {
                (void)model::loadProject(path);
                QFAIL("a damaged say opened");
            } catch (const model::IoError& e) {
                QVERIFY2(e.message().contains(QStringLiteral("damaged")), qPrintable(e.message()));
            }
        }
        // A base model with other faces takes the say away in the same step; undo brings it back.
        model::Document doc;
        doc.reset(projectOn(twoSpheres()));
        model::FaceSetStroke stroke = doc.faceSets().beginImportanceStroke(0.f, 1.f);
        doc.faceSets().applyFaceSetStroke(stroke, {0, 1}, false);
        doc.faceSets().endFaceSetStroke(stroke);
        doc.faceSets().setSegmentOverrides(std::vector<std::int32_t>(faces, 0), QStringLiteral("Merge Segments"));
        doc.setBaseMesh(test::icosphere(2), QStringLiteral("other.obj"));
        QVERIFY(doc.data().faceImportance.empty());
        QVERIFY(doc.data().segmentOverrides.empty());
        doc.undoStack()->undo();
        QCOMPARE(doc.data().faceImportance.size(), faces);
        QCOMPARE(doc.data().segmentOverrides.size(), faces);
    }

    void oldFilesOpenWithImportanceOne()
    {
        // The bundled sample was written before focal points: every segment's importance is 1.
        const QString sample = QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform");
        const model::ProjectData data = model::loadProject(sample);
        QVERIFY(data.faceImportance.empty());
        QVERIFY(data.segmentOverrides.empty());
        model::RenderJob job;
        job.size = QSize(240, 180);
        const model::FrameAnalysis a = model::analyseProject(data, sample, job, {});
        QVERIFY(a.analysis.stats.size() >= 3);
        for (const algo::SegmentStats& s : a.analysis.stats)
            QCOMPARE(s.importance, 1.f);
    }

    void mergeMakesTwoSegmentsOneAndUndoRestores()
    {
        model::Document doc;
        doc.reset(projectOn(twoSpheres()));
        model::FrameAnalysis before;
        const model::SegmentPicture picture = pictureOf(doc.data(), &before);
        QCOMPARE(before.analysis.stats.size(), std::size_t(2));
        QVERIFY_THROWS_EXCEPTION(model::EditRefused, (void)model::mergedSegmentOverrides(doc.data(), picture, {0, 0}));
        QVERIFY_THROWS_EXCEPTION(model::EditRefused, (void)model::mergedSegmentOverrides(doc.data(), picture, {0, 5}));
        doc.faceSets().setSegmentOverrides(
            model::mergedSegmentOverrides(doc.data(), picture, {0, 1}), QStringLiteral("Merge Segments"));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(model::segmentOverrideSizes(doc.data().segmentOverrides).size(), std::size_t(1));
        model::FrameAnalysis merged;
        pictureOf(doc.data(), &merged);
        QCOMPARE(merged.analysis.stats.size(), std::size_t(1));
        QCOMPARE(merged.analysis.stats[0].pixels, before.analysis.stats[0].pixels + before.analysis.stats[1].pixels);
        doc.undoStack()->undo();
        QVERIFY(doc.data().segmentOverrides.empty());
        model::FrameAnalysis undone;
        pictureOf(doc.data(), &undone);
        QCOMPARE(undone.analysis.segments.labels, before.analysis.segments.labels);
        doc.undoStack()->redo();
        pictureOf(doc.data(), &merged);
        QCOMPARE(merged.analysis.stats.size(), std::size_t(1));
    }

    void splitMakesOneSegmentTwoAndUndoRestores()
    {
        model::Document doc;
        doc.reset(projectOn(twoSpheres()));
        model::FrameAnalysis before;
        const model::SegmentPicture picture = pictureOf(doc.data(), &before);
        const int right = segmentOnSide(before, true);
        const Eigen::Vector2f centre = before.analysis.stats[std::size_t(right)].centroid;
        // A vertical stroke through the right sphere's middle, in the analysed picture's pixels.
        const std::vector<Eigen::Vector2d> stroke{{double(centre.x()), 0.0}, {double(centre.x()), 160.0}};
        const model::AnalysisView view = model::resolveAnalysisView(doc.data(), QStringLiteral("t"), frontJob());
        const algo::RasterCamera camera = model::rasterCamera(view.camera, 320, 160);
        // A stroke beside the segment leaves every face on one side: refused.
        QVERIFY_THROWS_EXCEPTION(model::EditRefused,
            (void)model::splitSegmentOverrides(
                doc.data(), picture, right, {{5.0, 0.0}, {5.0, 160.0}}, view.shape, camera));
        doc.faceSets().setSegmentOverrides(
            model::splitSegmentOverrides(doc.data(), picture, right, stroke, view.shape, camera),
            QStringLiteral("Split Segment"));
        model::FrameAnalysis split;
        pictureOf(doc.data(), &split);
        QCOMPARE(split.analysis.stats.size(), std::size_t(3));
        // The halves meet at the stroke: one centroid on each side of it, their pixels the whole.
        int halves = 0, pixels = 0;
        for (const algo::SegmentStats& s : split.analysis.stats)
            if (s.centroid.x() > 160.f) {
                ++halves;
                pixels += s.pixels;
            }
        QCOMPARE(halves, 2);
        QCOMPARE(pixels, before.analysis.stats[std::size_t(right)].pixels);
        doc.undoStack()->undo();
        model::FrameAnalysis undone;
        pictureOf(doc.data(), &undone);
        QCOMPARE(undone.analysis.segments.labels, before.analysis.segments.labels);
        // Released, the faces go back to the analysis's own segments.
        doc.undoStack()->redo();
        model::FrameAnalysis again;
        const model::SegmentPicture splitPicture = pictureOf(doc.data(), &again);
        std::vector<int> all;
        for (std::size_t s = 0; s < again.analysis.stats.size(); ++s)
            all.push_back(int(s));
        doc.faceSets().setSegmentOverrides(
            model::releasedSegmentOverrides(doc.data(), splitPicture, all), QStringLiteral("Release"));
        QVERIFY(doc.data().segmentOverrides.empty());
        pictureOf(doc.data(), &undone);
        QCOMPARE(undone.analysis.segments.labels, before.analysis.segments.labels);
    }

    void overridesFollowTheSubdividedSurface()
    {
        // At a render subdivision level the analysis sees child faces: they take their control
        // face's override, so a merge holds there too.
        model::Document doc;
        doc.reset(projectOn(twoSpheres()));
        const model::SegmentPicture picture = pictureOf(doc.data());
        doc.faceSets().setSegmentOverrides(
            model::mergedSegmentOverrides(doc.data(), picture, {0, 1}), QStringLiteral("Merge Segments"));
        model::ProjectData data = doc.data();
        data.look.subdivision.level = 1;
        model::FrameAnalysis merged;
        pictureOf(data, &merged);
        QCOMPARE(merged.analysis.stats.size(), std::size_t(1));
    }
};

QTEST_GUILESS_MAIN(TestArtistSay)
#include "test_artist_say.moc"
