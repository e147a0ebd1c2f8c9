// `celform outline` and `celform fit` as a script runs them: a project on the shared elephant with a
// synthetic model sheet (the model pulled in the image plane, drawn from a known camera) and a key
// aligned a few degrees off; the outline written as SVG and PNG, the fit's JSON, bad drawings
// refused with the file untouched, and usage errors.
#include "cli_run.h"
#include "fit_model_sheet.h"
#include "test_meshes.h"

#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <QCryptographicHash>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace celform;

namespace {

QString vec(const Eigen::Vector3d& v)
{
    return QStringLiteral("%1,%2,%3").arg(v.x(), 0, 'g', 10).arg(v.y(), 0, 'g', 10).arg(v.z(), 0, 'g', 10);
}

QByteArray digest(const QString& path)
{
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

} // namespace

class TestCliFit : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_mesh;
    QString m_project;
    algo::RasterCamera m_truth;

    QString path(const QString& name) const { return m_dir.filePath(name); }

    /// The project: the elephant, the sheet's drawing, and key "side" linked to it from a camera
    /// yaw, pitch degrees off the sheet's.
    bool makeProject(const QString& project, const QString& drawing, const algo::RasterCamera& start)
    {
        if (runCelform({"new", m_mesh, "--out", project}).exitCode != 0)
            return false;
        return runCelform({"key", "add", project, "--name", "side", "--from-base", "--eye", vec(start.eye), "--target",
                              vec(start.target), "--up", vec(start.up), "--drawing", drawing})
                   .exitCode
            == 0;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_mesh = test::sharedDataPath(QStringLiteral("meshes/cgal_elephant.off"));
        if (m_mesh.isEmpty())
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        const algo::TriMesh mesh = model::importMesh(m_mesh).mesh;
        const test::ModelSheet sheet = test::makeModelSheet(mesh, Eigen::Vector3d(0.15, 0.1, 1.0), 768, 0.04);
        m_truth = sheet.camera;
        const algo::DrawingImage ink = test::silhouetteDrawing(sheet.pulled, mesh.faces, sheet.camera);
        QImage image(ink.width, ink.height, QImage::Format_Grayscale8);
        for (int y = 0; y < ink.height; ++y)
            std::memcpy(
                image.scanLine(y), ink.pixels.data() + std::size_t(y) * std::size_t(ink.width), std::size_t(ink.width));
        QVERIFY(image.save(path(QStringLiteral("sheet.png"))));
        QImage white(400, 300, QImage::Format_RGB32);
        white.fill(Qt::white);
        QVERIFY(white.save(path(QStringLiteral("blank.png"))));

        m_project = path(QStringLiteral("fit.celform"));
        const algo::RasterCamera start = algo::orbitCamera(sheet.camera, algo::centroid(mesh.vertices), 6.0, 3.0);
        QVERIFY(makeProject(m_project, path(QStringLiteral("sheet.png")), start));
    }

    void outlineIsWrittenAndSaved()
    {
        const QString svg = path(QStringLiteral("outline.svg"));
        Run r = runCelform({"outline", m_project, "--drawing", "sheet", "--out", svg, "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(json["width"].toInt(), 768);
        QCOMPARE(json["contours"].toInt(), 1);
        QVERIFY(json["area_pixels"].toDouble() > 1000.0);
        QFile file(svg);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.startsWith("<?xml") && text.contains("<path") && text.contains(" Z"));

        const QString png = path(QStringLiteral("outline.png"));
        r = runCelform(
            {"outline", m_project, "--drawing", "sheet", "--closing", "3", "--threshold", "0.4", "--out", png});
        QCOMPARE(r.exitCode, 0);
        const QImage image(png);
        QCOMPARE(image.size(), QSize(768, 768));
        QVERIFY(image.hasAlphaChannel());
        const model::ProjectData saved = model::loadProject(m_project, model::DrawingImages::Skip);
        QCOMPARE(saved.drawings.at(0).outline.closingRadius, 3.0);
        QCOMPARE(saved.drawings.at(0).outline.threshold, 0.4);
        // Back to the defaults for the fit below.
        QCOMPARE(runCelform({"outline", m_project, "--drawing", "sheet", "--closing", "2", "--threshold", "auto",
                                "--out", png})
                     .exitCode,
            0);
    }

    void fitMeetsTheDrawing()
    {
        const Run r = runCelform({"fit", m_project, "--key", "side", "--camera", "--shape", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        for (const char* key : {"iou_before", "iou_after", "chamfer_px_before", "chamfer_px_after", "camera_before",
                 "camera_after", "rounds", "milliseconds"})
            QVERIFY2(json.contains(QLatin1String(key)), key);
        qInfo("celform fit: IoU %.4f -> %.4f, chamfer %.2f -> %.2f px, %d rounds, %.0f ms",
            json["iou_before"].toDouble(), json["iou_after"].toDouble(), json["chamfer_px_before"].toDouble(),
            json["chamfer_px_after"].toDouble(), json["rounds"].toInt(), json["milliseconds"].toDouble());
        QVERIFY(json["iou_after"].toDouble() >= 0.97);
        QVERIFY(json["chamfer_px_after"].toDouble() <= 1.5);
        QVERIFY(json["iou_before"].toDouble() < json["iou_after"].toDouble());
        QVERIFY(json["rounds"].toInt() >= 1);
        const model::ProjectData saved = model::loadProject(m_project, model::DrawingImages::Skip);
        const model::KeyViewpoint& key = saved.keys.at(0);
        QVERIFY(!key.offsetsByFrame.at(0).indices.empty());
        QVERIFY(saved.drawings.at(0).aligned && saved.drawings.at(0).camera == key.camera);
    }

    void badDrawingLeavesTheFile()
    {
        const QString project = path(QStringLiteral("blank.celform"));
        QVERIFY(makeProject(project, path(QStringLiteral("blank.png")), m_truth));
        const QByteArray before = digest(project);
        Run r = runCelform({"fit", project, "--key", "side", "--camera"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(QLatin1String("blank")) && r.err.contains(QLatin1String("blank.celform")),
            qPrintable(r.err));
        QCOMPARE(digest(project), before);
        r = runCelform({"outline", project, "--drawing", "blank", "--out", path(QStringLiteral("none.svg"))});
        QCOMPARE(r.exitCode, 3);
        QVERIFY(!QFile::exists(path(QStringLiteral("none.svg"))));
        QCOMPARE(digest(project), before);
    }

    void usageErrors()
    {
        const QByteArray before = digest(m_project);
        const QList<QStringList> cases = {{"fit", m_project, "--key", "side"},
            {"fit", m_project, "--key", "side", "--shape", "--strength", "2"},
            {"fit", m_project, "--key", "side", "--shape", "--iterations", "0"},
            {"outline", m_project, "--drawing", "sheet", "--out", path(QStringLiteral("x.jpg"))},
            {"outline", m_project, "--drawing", "sheet", "--closing", "-1", "--out", path(QStringLiteral("x.svg"))}};
        for (const QStringList& args : cases)
            QCOMPARE(runCelform(args).exitCode, 2);
        QCOMPARE(runCelform({"fit", m_project, "--key", "nobody", "--camera"}).exitCode, 3);
        QCOMPARE(digest(m_project), before);
    }

    /// Issue 24: `info --json` names the plane detected on the elephant (z: it faces +x), and
    /// `brush --mirror` moves the other hind leg too; --mirror x finds its twins elsewhere.
    void brushMirror()
    {
        const QString project = path(QStringLiteral("mirror.celform"));
        QVERIFY(QFile::copy(m_project, project));
        Run r = runCelform({"info", project, "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject info = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(info["mirror_plane"].toString(), QStringLiteral("z"));
        const QJsonObject symmetry = info["base_mesh"].toObject()["symmetry"].toObject();
        QCOMPARE(symmetry["detected"].toString(), QStringLiteral("z"));
        const QJsonObject error = symmetry["error"].toObject();
        qInfo("elephant symmetry error: x %.4f, y %.4f, z %.4f", error["x"].toDouble(), error["y"].toDouble(),
            error["z"].toDouble());
        QVERIFY(error["z"].toDouble() < error["x"].toDouble() && error["z"].toDouble() < error["y"].toDouble());

        const QString vertex = QString::number(test::elephantHindLegVertex(model::importMesh(m_mesh).mesh));
        auto brush = [&](const char* mirror) {
            const Run run = runCelform({"brush", project, "--key", "side", "--vertex", vertex, "--radius", "0.08",
                "--drag", "0,0.01", "--mirror", QString::fromLatin1(mirror), "--json"});
            [&] { QCOMPARE(run.exitCode, 0); }();
            return QJsonDocument::fromJson(run.out.toUtf8()).object();
        };
        const QJsonObject off = brush("off");
        QCOMPARE(off["mirrored_vertices"].toInt(), 0);
        const QJsonObject automatic = brush("auto");
        qInfo("brush on vertex %s: off moves %d; auto (%s) moves %d, %d of them mirrored", qPrintable(vertex),
            off["moved_vertices"].toInt(), qPrintable(automatic["mirror_plane"].toString()),
            automatic["moved_vertices"].toInt(), automatic["mirrored_vertices"].toInt());
        QCOMPARE(automatic["mirror_plane"].toString(), QStringLiteral("z"));
        QVERIFY(automatic["mirrored_vertices"].toInt() > off["moved_vertices"].toInt() / 2);
        QVERIFY(automatic["moved_vertices"].toInt() > off["moved_vertices"].toInt());
        // z by name is the same plane (the shape has moved since: a vertex more or less in reach).
        QVERIFY(std::abs(brush("z")["mirrored_vertices"].toInt() - automatic["mirrored_vertices"].toInt()) <= 3);
        QCOMPARE(runCelform({"brush", project, "--key", "side", "--vertex", vertex, "--radius", "0.08", "--drag",
                                "0,0.01", "--mirror", "w"})
                     .exitCode,
            2);
    }
};

QTEST_GUILESS_MAIN(TestCliFit)
#include "test_cli_fit.moc"
