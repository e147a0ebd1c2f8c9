// `celform offsets` run as a script runs it: automatic per-segment offsets lower or
// hold the depth error and are saved in the project (and `analyze` then sees them), each segment
// reaches 1 - Q, clear and smooth, and usage errors before any work.
#include "cli_run.h"
#include "test_support.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>

namespace {

QString copySample(const QTemporaryDir& dir)
{
    const QString path = dir.filePath(QStringLiteral("elephant.celform"));
    QFile::copy(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"), path);
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    return path;
}

QJsonObject json(const Run& r)
{
    if (r.exitCode != 0)
        qWarning("%s", qPrintable(r.err));
    return QJsonDocument::fromJson(r.out.toUtf8()).object();
}

} // namespace

class TestCliOffsets : public QObject {
    Q_OBJECT

private slots:
    void autoLowersTheErrorAndSaves()
    {
        QTemporaryDir dir;
        const QString path = copySample(dir);
        const QStringList view{QStringLiteral("--size"), QStringLiteral("480x360")};
        const QJsonObject before
            = json(runCelform(QStringList{QStringLiteral("analyze"), path, QStringLiteral("--json")} + view));
        const Run r = runCelform(
            QStringList{QStringLiteral("offsets"), path, QStringLiteral("--auto"), QStringLiteral("--json")} + view);
        QCOMPARE(r.exitCode, 0);
        const QJsonObject result = json(r);
        const QJsonObject mse = result.value(QStringLiteral("depth_error_mse")).toObject();
        const double mseBefore = mse.value(QStringLiteral("before")).toDouble();
        const double mseAfter = mse.value(QStringLiteral("after")).toDouble();
        QCOMPARE(
            mseBefore, before.value(QStringLiteral("depth_error")).toObject().value(QStringLiteral("mse")).toDouble());
        QVERIFY2(mseAfter <= mseBefore * 1.0001, qPrintable(QStringLiteral("%1 -> %2").arg(mseBefore).arg(mseAfter)));
        // Every covered segment is at 0.5 within one pixel.
        const QJsonArray segments = result.value(QStringLiteral("segments")).toArray();
        QVERIFY(!segments.isEmpty());
        for (const QJsonValue& v : segments) {
            const QJsonObject s = v.toObject();
            if (!s.value(QStringLiteral("covered")).toBool())
                continue;
            QVERIFY(std::abs(s.value(QStringLiteral("ratio_after")).toDouble() - 0.5)
                <= 1.0 / s.value(QStringLiteral("pixels")).toDouble() + 1e-9);
        }
        // Saved: the project now analyses with the offsets.
        const QJsonObject after
            = json(runCelform(QStringList{QStringLiteral("analyze"), path, QStringLiteral("--json")} + view));
        QCOMPARE(
            after.value(QStringLiteral("depth_error")).toObject().value(QStringLiteral("mse")).toDouble(), mseAfter);

        // Smooth, then clear: back to the picture of before.
        QCOMPARE(
            runCelform({QStringLiteral("offsets"), path, QStringLiteral("--smooth"), QStringLiteral("3")}).exitCode, 0);
        QCOMPARE(runCelform({QStringLiteral("offsets"), path, QStringLiteral("--clear")}).exitCode, 0);
        const QJsonObject cleared
            = json(runCelform(QStringList{QStringLiteral("analyze"), path, QStringLiteral("--json")} + view));
        QCOMPARE(cleared.value(QStringLiteral("depth_error")), before.value(QStringLiteral("depth_error")));
    }

    void usageAndBadInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::newRow("no operation") << QStringList{} << 2;
        QTest::newRow("two operations") << QStringList{"--auto", "--clear"} << 2;
        QTest::newRow("aggressiveness") << QStringList{"--auto", "--aggressiveness", "1.5"} << 2;
        QTest::newRow("percentile") << QStringList{"--auto", "--percentile", "-0.1"} << 2;
        QTest::newRow("bleed") << QStringList{"--auto", "--bleed", "-1"} << 2;
        QTest::newRow("segments") << QStringList{"--auto", "--segments", "inside"} << 2;
        QTest::newRow("analysis too small") << QStringList{"--auto", "--size", "8x6"} << 2; // found by fuzz_cli_process
        QTest::newRow("segments without auto") << QStringList{"--clear", "--segments", "all"} << 2;
        QTest::newRow("smooth zero") << QStringList{"--smooth", "0"} << 2;
        QTest::newRow("camera without auto") << QStringList{"--clear", "--view", "0,0,1"} << 2;
        QTest::newRow("unknown key") << QStringList{"--clear", "--key", "nobody"} << 3;
    }
    void usageAndBadInput()
    {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QTemporaryDir dir;
        const QString path = copySample(dir);
        const QByteArray original = [&] {
            QFile f(path);
            f.open(QIODevice::ReadOnly);
            return f.readAll();
        }();
        const Run r = runCelform(QStringList{QStringLiteral("offsets"), path} + args);
        QCOMPARE(r.exitCode, exitCode);
        QCOMPARE(
            r.err.trimmed().count(QLatin1Char('\n')), exitCode == 2 ? r.err.trimmed().count(QLatin1Char('\n')) : 0);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), original); // nothing written
    }
};

QTEST_GUILESS_MAIN(TestCliOffsets)
#include "test_cli_offsets.moc"
