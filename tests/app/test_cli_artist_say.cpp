// The artist's say over the depth analysis from the command line (issue 26): `patch --importance`
// paints focal points that `info --json` reports and that change what `optimize-light` finds;
// `segments` merges, splits, releases and clears segments that `analyze` then reports.
#include "cli_run.h"
#include "test_support.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

namespace {

const QString kSize = QStringLiteral("320x240");

QString copyOfSample(const QTemporaryDir& dir, const QString& name)
{
    const QString path = dir.filePath(name);
    QFile::copy(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"), path);
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    return path;
}

QJsonObject json(const QStringList& args)
{
    const Run r = runCelform(args + QStringList{QStringLiteral("--json")});
    if (r.exitCode != 0)
        qWarning("%s", qPrintable(r.err));
    return QJsonDocument::fromJson(r.out.toUtf8()).object();
}

QJsonArray segmentsOf(const QString& project)
{
    return json({QStringLiteral("analyze"), project, QStringLiteral("--size"), kSize})
        .value(QStringLiteral("segments"))
        .toArray();
}

} // namespace

class TestCliArtistSay : public QObject {
    Q_OBJECT

private slots:
    void focalPointsArePaintedReportedAndCleared()
    {
        QTemporaryDir dir;
        const QString p = copyOfSample(dir, QStringLiteral("focus.celform"));
        QJsonObject info = json({QStringLiteral("info"), p});
        QCOMPARE(
            info.value(QStringLiteral("face_importance")).toObject().value(QStringLiteral("painted")).toBool(), false);
        const QJsonObject painted = json({QStringLiteral("patch"), p, QStringLiteral("--importance"),
            QStringLiteral("0"), QStringLiteral("--strength"), QStringLiteral("0.5"), QStringLiteral("--faces"),
            QStringLiteral("0-99")});
        QCOMPARE(painted.value(QStringLiteral("faces_changed")).toInt(), 100);
        info = json({QStringLiteral("info"), p});
        const QJsonObject importance = info.value(QStringLiteral("face_importance")).toObject();
        QVERIFY(importance.value(QStringLiteral("painted")).toBool());
        QCOMPARE(importance.value(QStringLiteral("faces_below_1")).toInt(), 100);
        const int faces
            = info.value(QStringLiteral("base_mesh")).toObject().value(QStringLiteral("triangle_count")).toInt();
        // 100 faces at 0.5, the rest at 1.
        QVERIFY(std::abs(importance.value(QStringLiteral("mean")).toDouble() - (faces - 50.0) / faces) < 1e-9);
        // Usage: --strength alone, a value outside [0, 1], --importance without a selection.
        QCOMPARE(runCelform({QStringLiteral("patch"), p, QStringLiteral("--strength"), QStringLiteral("0.5"),
                                QStringLiteral("--faces"), QStringLiteral("0")})
                     .exitCode,
            2);
        QCOMPARE(runCelform({QStringLiteral("patch"), p, QStringLiteral("--importance"), QStringLiteral("2"),
                                QStringLiteral("--faces"), QStringLiteral("0")})
                     .exitCode,
            2);
        QCOMPARE(
            runCelform({QStringLiteral("patch"), p, QStringLiteral("--importance"), QStringLiteral("0")}).exitCode, 2);
        json({QStringLiteral("patch"), p, QStringLiteral("--clear-importance")});
        info = json({QStringLiteral("info"), p});
        QCOMPARE(
            info.value(QStringLiteral("face_importance")).toObject().value(QStringLiteral("painted")).toBool(), false);
    }

    void aFocalPointChangesTheOptimisedLight()
    {
        QTemporaryDir dir;
        const QString plain = copyOfSample(dir, QStringLiteral("plain.celform"));
        const QString focus = copyOfSample(dir, QStringLiteral("focus.celform"));
        // Everything at 0 but a sphere at the top of the model.
        json({QStringLiteral("patch"), focus, QStringLiteral("--importance"), QStringLiteral("0"),
            QStringLiteral("--sphere"), QStringLiteral("0,0,0,10")});
        json({QStringLiteral("patch"), focus, QStringLiteral("--importance"), QStringLiteral("1"),
            QStringLiteral("--sphere"), QStringLiteral("0,0.35,0,0.25")});
        const QStringList run = {QStringLiteral("--size"), kSize, QStringLiteral("--objective"),
            QStringLiteral("ratios"), QStringLiteral("--dry-run")};
        const QJsonObject a = json(QStringList{QStringLiteral("optimize-light"), plain} + run);
        const QJsonObject b = json(QStringList{QStringLiteral("optimize-light"), focus} + run);
        QVERIFY(a.value(QStringLiteral("light_after")) != b.value(QStringLiteral("light_after")));
        // The objective counts each segment's distance from the window times its importance.
        double byHand = 0.0, zero = 0;
        for (const QJsonValue& v : b.value(QStringLiteral("segments")).toArray()) {
            const QJsonObject s = v.toObject();
            const double ratio = s.value(QStringLiteral("ratio_before")).toDouble();
            const double importance = s.value(QStringLiteral("importance")).toDouble();
            byHand += importance * std::max({0.0, 0.35 - ratio, ratio - 0.65});
            zero += importance == 0.0 ? 1 : 0;
        }
        QVERIFY(zero > 0);
        const double before = b.value(QStringLiteral("objective_before")).toDouble();
        QVERIFY2(std::abs(before - byHand) < 1e-4 * std::max(1.0, byHand), qPrintable(QString::number(before)));
        QVERIFY(before < a.value(QStringLiteral("objective_before")).toDouble());
    }

    void segmentsAreMergedSplitAndCleared()
    {
        QTemporaryDir dir;
        const QString p = copyOfSample(dir, QStringLiteral("segments.celform"));
        const QJsonArray original = segmentsOf(p);
        QVERIFY(original.size() >= 4);
        // The two largest segments.
        int first = -1, second = -1;
        for (qsizetype i = 0; i < original.size(); ++i) {
            const int px = original[i].toObject().value(QStringLiteral("pixels")).toInt();
            if (first < 0 || px > original[first].toObject().value(QStringLiteral("pixels")).toInt()) {
                second = first;
                first = int(i);
            } else if (second < 0 || px > original[second].toObject().value(QStringLiteral("pixels")).toInt()) {
                second = int(i);
            }
        }
        const QStringList where = {QStringLiteral("--size"), kSize};
        const QJsonObject merged = json(QStringList{QStringLiteral("segments"), p, QStringLiteral("--merge"),
                                            QStringLiteral("%1,%2").arg(first).arg(second)}
            + where);
        QCOMPARE(merged.value(QStringLiteral("segments_before")).toInt(), int(original.size()));
        QCOMPARE(merged.value(QStringLiteral("groups")).toInt(), 1);
        const QJsonArray afterMerge = segmentsOf(p);
        QVERIFY(afterMerge.size() <= original.size() - 1);
        QCOMPARE(merged.value(QStringLiteral("segments_after")).toInt(), int(afterMerge.size()));
        // The merged segment holds both segments' pixels (give or take the faces on their rims).
        const int both = original[first].toObject().value(QStringLiteral("pixels")).toInt()
            + original[second].toObject().value(QStringLiteral("pixels")).toInt();
        int largest = 0;
        for (const QJsonValue& v : afterMerge)
            largest = std::max(largest, v.toObject().value(QStringLiteral("pixels")).toInt());
        QVERIFY2(std::abs(largest - both) < both / 20, qPrintable(QStringLiteral("%1 %2").arg(largest).arg(both)));

        // Split the merged one with a horizontal stroke through its centroid: one more segment.
        int mergedId = 0;
        for (qsizetype i = 0; i < afterMerge.size(); ++i)
            if (afterMerge[i].toObject().value(QStringLiteral("pixels")).toInt() == largest)
                mergedId = int(i);
        const QJsonArray c = afterMerge[mergedId].toObject().value(QStringLiteral("centroid")).toArray();
        const QString stroke = QStringLiteral("0,%1,320,%1").arg(c[1].toDouble());
        const QJsonObject split = json(QStringList{QStringLiteral("segments"), p, QStringLiteral("--split"),
                                           QString::number(mergedId), QStringLiteral("--stroke"), stroke}
            + where);
        QCOMPARE(split.value(QStringLiteral("segments_after")).toInt(), int(afterMerge.size()) + 1);
        QCOMPARE(segmentsOf(p).size(), afterMerge.size() + 1);
        const QJsonObject list = json({QStringLiteral("segments"), p, QStringLiteral("--list")});
        QCOMPARE(list.value(QStringLiteral("overrides")).toArray().size(), 2);
        // Usage and refusals: --split without --stroke, a segment the picture lacks.
        QCOMPARE(
            runCelform({QStringLiteral("segments"), p, QStringLiteral("--split"), QStringLiteral("0")}).exitCode, 2);
        const Run missing = runCelform(
            QStringList{QStringLiteral("segments"), p, QStringLiteral("--merge"), QStringLiteral("0,999")} + where);
        QVERIFY(missing.exitCode != 0);
        QVERIFY(missing.err.contains(QStringLiteral("999")));
        // Cleared, the analysis gives the original segments again.
        json({QStringLiteral("segments"), p, QStringLiteral("--clear")});
        QCOMPARE(segmentsOf(p), original);
        const QJsonObject info = json({QStringLiteral("info"), p});
        QCOMPARE(info.value(QStringLiteral("segment_overrides")).toObject().value(QStringLiteral("groups")).toInt(), 0);
    }
};

QTEST_GUILESS_MAIN(TestCliArtistSay)
#include "test_cli_artist_say.moc"
