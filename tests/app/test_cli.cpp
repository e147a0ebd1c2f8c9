// The `celform` command line run as a process: exit codes 0 / 2 / 3, one-line errors naming the
// file, JSON output, and no crash on any file of ../shared/data/bad.
#include "test_support.h"

#include "celform/model/project_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

namespace {

struct Run {
    int exitCode = -1;
    QProcess::ExitStatus status = QProcess::CrashExit;
    QString out;
    QString err;
};

Run runCelform(const QStringList& args)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY")); // sub-commands must not need a display
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(CELFORM_EXECUTABLE), args);
    if (!p.waitForFinished(120000))
        p.kill();
    return {p.exitCode(), p.exitStatus(), QString::fromUtf8(p.readAllStandardOutput()),
        QString::fromUtf8(p.readAllStandardError())};
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString bunnyProject()
    {
        const QString mesh = celform::test::sharedDataPath(QStringLiteral("meshes/npm_bunny.off"));
        const QString out = m_dir.filePath(QStringLiteral("bunny.celform"));
        if (!mesh.isEmpty() && !QFileInfo::exists(out))
            runCelform({QStringLiteral("new"), mesh, QStringLiteral("--out"), out});
        return QFileInfo::exists(out) ? out : QString();
    }

private slots:
    void version()
    {
        const Run r = runCelform({QStringLiteral("--version")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("celform ")));
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("info without file") << QStringList{"info"};
        QTest::newRow("info unknown option") << QStringList{"info", "x.celform", "--bogus"};
        QTest::newRow("new without --out") << QStringList{"new", "mesh.obj"};
        QTest::newRow("new without mesh") << QStringList{"new", "--out", "p.celform"};
        QTest::newRow("new two meshes") << QStringList{"new", "a.obj", "b.obj", "--out", "p.celform"};
    }
    void usageErrors()
    {
        QFETCH(QStringList, args);
        const Run r = runCelform(args);
        QCOMPARE(r.status, QProcess::NormalExit);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("usage")), qPrintable(r.err));
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("named");
        QTest::newRow("missing project") << QStringList{"info", "/nonexistent/p.celform"} << "/nonexistent/p.celform";
        QTest::newRow("missing mesh") << QStringList{"new", "/nonexistent/m.obj", "--out", "/tmp/x.celform"}
                                      << "/nonexistent/m.obj";
        QTest::newRow("project is text") << QStringList{"info", QStringLiteral(CELFORM_SOURCE_DIR "/README.md")}
                                         << "README.md";
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, named);
        const Run r = runCelform(args);
        QCOMPARE(r.status, QProcess::NormalExit);
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(named), qPrintable(r.err));
        QCOMPARE(r.err.trimmed().count(QLatin1Char('\n')), 0); // one line
    }

    void newAndInfoJson()
    {
        CELFORM_REQUIRE_SHARED(drawing, QStringLiteral("drawings/tuxpaint_elephant.png"));
        CELFORM_REQUIRE_SHARED(mesh, QStringLiteral("meshes/cgal_elephant.off"));
        const QString out = m_dir.filePath(QStringLiteral("elephant.celform"));
        Run r = runCelform({"new", mesh, "--drawing", drawing, "--out", out});
        QCOMPARE(r.exitCode, 0);
        r = runCelform({"info", out, "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject info = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(info["format_version"].toInt(), celform::model::kProjectFormatVersion);
        const QJsonObject mesh0 = info["base_mesh"].toObject();
        QCOMPARE(mesh0["vertex_count"].toInt(), 2775);
        QCOMPARE(mesh0["triangle_count"].toInt(), 5558);
        QCOMPARE(mesh0["bounding_box"].toObject()["max"].toArray()[1].toDouble(), 0.5);
        QCOMPARE(mesh0["centroid"].toArray().size(), 3);
        const QJsonArray drawings = info["drawings"].toArray();
        QCOMPARE(drawings.size(), 1);
        QCOMPARE(drawings[0].toObject()["name"].toString(), QStringLiteral("tuxpaint_elephant"));
        QVERIFY(drawings[0].toObject()["width"].toInt() > 0);
        QVERIFY(info["key_viewpoints"].toArray().isEmpty());
        // Plain text form too.
        r = runCelform({"info", out});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("2775")));
    }

    void newWarnsOnDefectiveMesh()
    {
        CELFORM_REQUIRE_SHARED(mesh, QStringLiteral("bad/cgal_elephant-with-holes.off"));
        const Run r = runCelform({"new", mesh, "--out", m_dir.filePath(QStringLiteral("holes.celform"))});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(
            r.err.contains(QStringLiteral("warning")) && r.err.contains(QStringLiteral("hole")), qPrintable(r.err));
    }

    void everyBadFileGivesExitCodeNotCrash_data()
    {
        QTest::addColumn<QString>("path");
        const QString dir = celform::test::sharedDataPath(QStringLiteral("bad"));
        if (dir.isEmpty()) {
            QTest::newRow("none") << QString();
            return;
        }
        for (const QFileInfo& f : QDir(dir).entryInfoList(QDir::Files, QDir::Name))
            QTest::newRow(qPrintable(f.fileName())) << f.absoluteFilePath();
    }
    void everyBadFileGivesExitCodeNotCrash()
    {
        QFETCH(QString, path);
        if (path.isEmpty())
            QSKIP("shared test data not found: ../shared/data/bad");
        const Run r = runCelform({"new", path, "--out", m_dir.filePath(QStringLiteral("bad.celform"))});
        QCOMPARE(r.status, QProcess::NormalExit);
        QVERIFY2(r.exitCode == 0 || r.exitCode == 3, qPrintable(r.err));
        if (r.exitCode == 3) {
            QVERIFY2(r.err.contains(QFileInfo(path).fileName()), qPrintable(r.err));
        } else {
            QVERIFY2(r.err.contains(QStringLiteral("warning")), qPrintable(r.err)); // bad files are never clean
        }
    }

    void infoOnTruncatedProject()
    {
        const QString good = bunnyProject();
        if (good.isEmpty())
            QSKIP("shared test data not found: ../shared/data/meshes/npm_bunny.off");
        QFile in(good);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray bytes = in.readAll();
        const QString bad = m_dir.filePath(QStringLiteral("cut.celform"));
        QFile out(bad);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes.left(bytes.size() * 2 / 3));
        out.close();
        const Run r = runCelform({"info", bad, "--json"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY(r.err.contains(QStringLiteral("cut.celform")));
        QVERIFY(r.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
