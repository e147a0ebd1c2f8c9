// `celform analyze`, `celform curvature` and the analysis passes of `celform render` run as a
// script runs them: the JSON's shape and figures, the EXR's channels, the PLY's
// properties, determinism, and usage errors before any work.
#include "cli_run.h"
#include "test_support.h"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cmath>
#include <cstring>

namespace {

QString sample()
{
    return QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform");
}

QJsonObject analyzeJson(const QStringList& extra = {})
{
    const Run r = runCelform(QStringList{QStringLiteral("analyze"), sample(), QStringLiteral("--size"),
                                 QStringLiteral("480x360"), QStringLiteral("--json")}
        + extra);
    if (r.exitCode != 0)
        qWarning("%s", qPrintable(r.err));
    return QJsonDocument::fromJson(r.out.toUtf8()).object();
}

} // namespace

class TestCliAnalysis : public QObject {
    Q_OBJECT

private slots:
    void analyzePrintsSegmentsAndTheError()
    {
        const QJsonObject json = analyzeJson();
        const QJsonArray segments = json.value(QStringLiteral("segments")).toArray();
        QVERIFY(segments.size() >= 3);
        qint64 pixels = 0;
        for (qsizetype i = 0; i < segments.size(); ++i) {
            const QJsonObject s = segments[i].toObject();
            QCOMPARE(s.value(QStringLiteral("id")).toInt(), int(i)); // compact labels 0..k-1
            QVERIFY(s.value(QStringLiteral("pixels")).toInt() >= 64); // smaller ones are dropped
            const double ratio = s.value(QStringLiteral("ratio")).toDouble();
            QVERIFY(ratio >= 0.0 && ratio <= 1.0);
            QCOMPARE(s.value(QStringLiteral("bright")).toInt(),
                int(std::lround(ratio * s.value(QStringLiteral("pixels")).toInt())));
            QCOMPARE(s.value(QStringLiteral("in_window")).toBool(), ratio >= 0.35 && ratio <= 0.65);
            pixels += s.value(QStringLiteral("pixels")).toInt();
        }
        const QJsonObject error = json.value(QStringLiteral("depth_error")).toObject();
        const double mse = error.value(QStringLiteral("mse")).toDouble();
        QVERIFY(mse > 0.0 && std::isfinite(mse));
        QCOMPARE(error.value(QStringLiteral("rmse")).toDouble(), std::sqrt(mse));
        QVERIFY(error.value(QStringLiteral("max")).toDouble() * error.value(QStringLiteral("max")).toDouble() >= mse);
        const double model = error.value(QStringLiteral("model_pixels")).toDouble();
        QVERIFY(model >= double(pixels)); // segments cover model pixels only
        QVERIFY(error.value(QStringLiteral("feature_pixels")).toDouble() > 0.0);
        QVERIFY(json.value(QStringLiteral("milliseconds")).toDouble() > 0.0);
        QCOMPARE(json.value(QStringLiteral("window")).toArray(), QJsonArray({0.35, 0.65}));

        // The same command gives the same figures.
        QJsonObject again = analyzeJson();
        QCOMPARE(again.value(QStringLiteral("segments")), json.value(QStringLiteral("segments")));
        QCOMPARE(again.value(QStringLiteral("depth_error")), json.value(QStringLiteral("depth_error")));

        // A stricter window keeps the ratios and changes only what is inside it; a larger
        // smallest segment drops segments.
        const QJsonObject strict = analyzeJson({QStringLiteral("--window"), QStringLiteral("strict")});
        QCOMPARE(strict.value(QStringLiteral("segments")).toArray().size(), segments.size());
        const QJsonObject fewer = analyzeJson({QStringLiteral("--min-pixels"), QStringLiteral("2000")});
        QVERIFY(fewer.value(QStringLiteral("segments")).toArray().size() < segments.size());
        // Lines off: fewer colour edges, so fewer features.
        const QJsonObject flat = analyzeJson({QStringLiteral("--lines"), QStringLiteral("off")});
        QVERIFY(flat.value(QStringLiteral("depth_error")).toObject().value(QStringLiteral("feature_pixels")).toDouble()
            < error.value(QStringLiteral("feature_pixels")).toDouble());
    }

    // Issue 26, fix 7: analyze takes --ridge-threshold as render does; a lower threshold draws
    // more ridges, so more feature pixels.
    void analyzeTakesTheRidgeThreshold()
    {
        auto features = [](const char* threshold) {
            const Run r = runCelform({QStringLiteral("analyze"), sample(), QStringLiteral("--size"),
                QStringLiteral("160x120"), QStringLiteral("--lines"), QStringLiteral("ridge"),
                QStringLiteral("--ridge-threshold"), QLatin1String(threshold), QStringLiteral("--json")});
            if (r.exitCode != 0)
                qWarning("%s", qPrintable(r.err));
            return QJsonDocument::fromJson(r.out.toUtf8())
                .object()
                .value(QStringLiteral("depth_error"))
                .toObject()
                .value(QStringLiteral("feature_pixels"))
                .toDouble(-1.0);
        };
        const double few = features("5");
        const double many = features("0.05");
        QVERIFY2(few >= 0.0 && many > few, qPrintable(QStringLiteral("%1 %2").arg(few).arg(many)));
        QCOMPARE(
            runCelform({QStringLiteral("analyze"), sample(), QStringLiteral("--ridge-threshold"), QStringLiteral("-1")})
                .exitCode,
            2);
    }

    // Issue 26, "along the timeline": a frame range in one process, JSON per frame, a CSV row per
    // frame and one EXR per frame through a # pattern.
    void analyzeTakesAFrameRange()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("shot.csv"));
        const QString exr = dir.filePath(QStringLiteral("shot_##.exr"));
        // The sample with its 48-frame turntable (a camera path).
        const QString shot = QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform");
        const Run r = runCelform({QStringLiteral("analyze"), shot, QStringLiteral("--size"), QStringLiteral("160x120"),
            QStringLiteral("--frames"), QStringLiteral("0-8:4"), QStringLiteral("--json"), QStringLiteral("--csv"), csv,
            QStringLiteral("--out"), exr});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonArray frames = json.value(QStringLiteral("frames")).toArray();
        QCOMPARE(frames.size(), 3);
        QCOMPARE(frames[2].toObject().value(QStringLiteral("frame")).toInt(), 8);
        QVERIFY(frames[0].toObject().value(QStringLiteral("depth_error")).toObject().contains(QStringLiteral("mse")));
        // The shot camera moves: frame 0's eye is not frame 8's.
        QVERIFY(frames[0].toObject().value(QStringLiteral("camera")).toObject().value(QStringLiteral("eye"))
            != frames[2].toObject().value(QStringLiteral("camera")).toObject().value(QStringLiteral("eye")));
        QCOMPARE(json.value(QStringLiteral("size")).toArray().size(), 2);
        // Stable segment numbers (issue 26): unique within a frame, mostly kept from frame to frame.
        for (const QJsonValue& f : frames) {
            QSet<int> ids;
            for (const QJsonValue& s : f.toObject().value(QStringLiteral("segments")).toArray())
                ids.insert(s.toObject().value(QStringLiteral("id")).toInt());
            QCOMPARE(ids.size(), f.toObject().value(QStringLiteral("segments")).toArray().size());
        }
        const double stability = json.value(QStringLiteral("segment_stability")).toDouble(-1.0);
        QVERIFY2(stability >= 0.5 && stability <= 1.0, qPrintable(QString::number(stability)));
        QFile rows(csv);
        QVERIFY(rows.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(rows.readAll()).trimmed().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 4);
        QCOMPARE(lines[0], QStringLiteral("frame,mse,rmse,segments,segments_in_window,milliseconds"));
        QVERIFY(lines[2].startsWith(QStringLiteral("4,")));
        for (const char* name : {"shot_00.exr", "shot_04.exr", "shot_08.exr"})
            QVERIFY2(QFile::exists(dir.filePath(QLatin1String(name))), name);
        // --out without a # and --csv without --frames are usage errors.
        QCOMPARE(runCelform({QStringLiteral("analyze"), sample(), QStringLiteral("--frames"), QStringLiteral("0-1"),
                                QStringLiteral("--out"), dir.filePath(QStringLiteral("a.exr"))})
                     .exitCode,
            2);
        QCOMPARE(runCelform({QStringLiteral("analyze"), sample(), QStringLiteral("--csv"), csv}).exitCode, 2);
    }

    void optimiseLightAlongTheShot()
    {
        // issue 26: `optimize-light --frames` keys the light at the sampled frames of the shot
        // (the sample's turntable), each no worse than the project's light at its frame (the
        // starting light, mse_before) and within the turn limit.
        QTemporaryDir dir;
        const QString shot = dir.filePath(QStringLiteral("shot.celform"));
        QVERIFY(QFile::copy(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform"), shot));
        const QStringList small = {
            QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--iterations"), QStringLiteral("12")};
        const Run r = runCelform(
            QStringList{QStringLiteral("optimize-light"), shot, QStringLiteral("--frames"), QStringLiteral("0-8:4"),
                QStringLiteral("--max-turn"), QStringLiteral("2"), QStringLiteral("--json")}
            + small);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonArray frames = json.value(QStringLiteral("frames")).toArray();
        QCOMPARE(frames.size(), 3);
        for (qsizetype i = 0; i < frames.size(); ++i) {
            const QJsonObject f = frames[i].toObject();
            QCOMPARE(f.value(QStringLiteral("frame")).toInt(), int(4 * i));
            const QJsonObject error = f.value(QStringLiteral("depth_error")).toObject();
            QVERIFY(error.value(QStringLiteral("mse_after")).toDouble()
                <= error.value(QStringLiteral("mse_before")).toDouble());
            QVERIFY(f.value(QStringLiteral("turn_degrees")).toDouble() <= 2.0 * 4 + 1e-6);
        }
        QVERIFY(json.value(QStringLiteral("largest_turn_degrees")).toDouble() <= 8.0 + 1e-6);
        QVERIFY(json.value(QStringLiteral("saved")).toBool());

        // Saved as light keys: info lists them; analyze at a keyed frame sees the keyed light.
        const Run info = runCelform({QStringLiteral("info"), shot, QStringLiteral("--json")});
        const QJsonArray keys
            = QJsonDocument::fromJson(info.out.toUtf8()).object().value(QStringLiteral("light_keys")).toArray();
        QCOMPARE(keys.size(), 3);
        QCOMPARE(keys[1].toObject().value(QStringLiteral("frame")).toInt(), 4);
        QCOMPARE(keys[1].toObject().value(QStringLiteral("light")),
            frames[1].toObject().value(QStringLiteral("light_after")));
        const Run analysed = runCelform({QStringLiteral("analyze"), shot, QStringLiteral("--size"),
            QStringLiteral("160x120"), QStringLiteral("--frames"), QStringLiteral("4-4"), QStringLiteral("--json")});
        QVERIFY2(analysed.exitCode == 0, qPrintable(analysed.err));
        const double mse = QJsonDocument::fromJson(analysed.out.toUtf8())
                               .object()
                               .value(QStringLiteral("frames"))
                               .toArray()[0]
                               .toObject()
                               .value(QStringLiteral("depth_error"))
                               .toObject()
                               .value(QStringLiteral("mse"))
                               .toDouble();
        QCOMPARE(mse,
            frames[1]
                .toObject()
                .value(QStringLiteral("depth_error"))
                .toObject()
                .value(QStringLiteral("mse_after"))
                .toDouble());

        // A plain optimize-light with a track keys the light at its frame.
        const Run one = runCelform(QStringList{QStringLiteral("optimize-light"), shot, QStringLiteral("--frame"),
                                       QStringLiteral("2"), QStringLiteral("--json")}
            + small);
        QVERIFY2(one.exitCode == 0, qPrintable(one.err));
        const bool saved = QJsonDocument::fromJson(one.out.toUtf8()).object().value(QStringLiteral("saved")).toBool();
        const Run again = runCelform({QStringLiteral("info"), shot, QStringLiteral("--json")});
        QCOMPARE(
            QJsonDocument::fromJson(again.out.toUtf8()).object().value(QStringLiteral("light_keys")).toArray().size(),
            saved ? 4 : 3);

        // --max-turn without --frames, and --frame with --frames, are usage errors.
        QCOMPARE(runCelform({QStringLiteral("optimize-light"), shot, QStringLiteral("--max-turn"), QStringLiteral("2")})
                     .exitCode,
            2);
        QCOMPARE(runCelform({QStringLiteral("optimize-light"), shot, QStringLiteral("--frame"), QStringLiteral("1"),
                                QStringLiteral("--frames"), QStringLiteral("0-2")})
                     .exitCode,
            2);
    }

    void analyzeWritesTheBuffersAsExr()
    {
        QTemporaryDir dir;
        const QString exr = dir.filePath(QStringLiteral("analysis.exr"));
        const Run r = runCelform({QStringLiteral("analyze"), sample(), QStringLiteral("--size"),
            QStringLiteral("320x240"), QStringLiteral("--out"), exr});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("depth error: MSE")));
        QVERIFY(QFile::exists(exr));
        const QString iinfo = QStandardPaths::findExecutable(QStringLiteral("iinfo"));
        if (iinfo.isEmpty())
            QSKIP("OpenImageIO's iinfo is not installed (openimageio-tools)");
        QProcess p;
        p.start(iinfo, {QStringLiteral("-v"), exr});
        QVERIFY(p.waitForFinished(60000));
        const QString info = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(info.contains(QStringLiteral("320 x  240")) || info.contains(QStringLiteral("320 x 240")),
            qPrintable(info));
        // Issue 26, fix 8: N.L and the light gradient (figure 4.3) too.
        for (const char* channel : {"curvature.K", "segment.ID", "depth.Z", "depth_error.Z", "feature.Y",
                 "shading.NdotL", "light_gradient.X", "light_gradient.Y", "light_gradient.Z"})
            QVERIFY2(info.contains(QLatin1String(channel)), channel);
    }

    void renderWritesTheAnalysisPasses()
    {
        QTemporaryDir dir;
        for (const char* pass : {"segments", "curvature", "depth-error"}) {
            const QString png = dir.filePath(QStringLiteral("%1.png").arg(QLatin1String(pass)));
            const Run r
                = runCelform({QStringLiteral("render"), sample(), QStringLiteral("--size"), QStringLiteral("320x240"),
                    QStringLiteral("--pass"), QLatin1String(pass), QStringLiteral("--out"), png});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QImage image(png);
            QCOMPARE(image.size(), QSize(320, 240));
            // Colour on the model, transparent around it.
            int opaque = 0, coloured = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    opaque += c.alpha() == 255 ? 1 : 0;
                    coloured += c.alpha() == 255 && c.hsvSaturation() > 60 ? 1 : 0;
                }
            QVERIFY2(opaque > 2000 && opaque < 320 * 240 / 2, pass);
            QVERIFY2(coloured > opaque / 20, pass);
        }
        // A stereo render has no analysis pass.
        const Run stereo = runCelform({QStringLiteral("render"), sample(), QStringLiteral("--pass"),
            QStringLiteral("segments"), QStringLiteral("--stereo"), QStringLiteral("anaglyph"), QStringLiteral("--out"),
            dir.filePath(QStringLiteral("s.png"))});
        QCOMPARE(stereo.exitCode, 2);
    }

    void curvatureWritesPlyProperties()
    {
        QTemporaryDir dir;
        const QString ply = dir.filePath(QStringLiteral("k.ply"));
        const Run r = runCelform({QStringLiteral("curvature"), sample(), QStringLiteral("--out"), ply});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(ply);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        const qsizetype end = bytes.indexOf("end_header\n");
        QVERIFY(end > 0);
        const QByteArray header = bytes.left(end);
        QVERIFY(header.contains("element vertex 2775"));
        for (const char* p :
            {"property float k1", "property float k2", "property float K\n", "property float K_smooth"})
            QVERIFY2(header.contains(p), p);
        // Every vertex: 7 floats, k1 >= k2 and K = k1 k2, all finite.
        const char* data = bytes.constData() + end + 11;
        for (int v = 0; v < 2775; ++v) {
            float row[7];
            std::memcpy(row, data + std::size_t(v) * sizeof(row), sizeof(row));
            for (float x : row)
                QVERIFY(std::isfinite(x));
            QVERIFY(row[3] >= row[4]);
            QCOMPARE(row[5], row[3] * row[4]);
        }
    }

    void usageErrorsComeFirst()
    {
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("missing.celform"));
        const struct {
            QStringList args;
            int exit;
        } cases[] = {
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--window"), QStringLiteral("0.7,0.3")}, 2},
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--window"), QStringLiteral("wide")}, 2},
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--depth-threshold"), QStringLiteral("0")}, 2},
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--depth-threshold"), QStringLiteral("nan")}, 2},
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--min-pixels"), QStringLiteral("0")}, 2},
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--out"), dir.filePath(QStringLiteral("a.png"))}, 2},
            {{QStringLiteral("analyze"), sample(), QStringLiteral("--view"), QStringLiteral("0,0,0")}, 2},
            {{QStringLiteral("analyze"), missing}, 3},
            {{QStringLiteral("curvature"), sample()}, 2},
            {{QStringLiteral("curvature"), sample(), QStringLiteral("--out"), dir.filePath(QStringLiteral("k.obj"))},
                2},
            {{QStringLiteral("curvature"), missing, QStringLiteral("--out"), dir.filePath(QStringLiteral("k.ply"))}, 3},
        };
        for (const auto& c : cases) {
            const Run r = runCelform(c.args);
            QVERIFY2(r.exitCode == c.exit, qPrintable(c.args.join(QLatin1Char(' ')) + QStringLiteral(" -> ") + r.err));
            QCOMPARE(r.err.trimmed().count(QLatin1Char('\n')) <= 2, true);
        }
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("a.png"))));
    }
};

QTEST_GUILESS_MAIN(TestCliAnalysis)
#include "test_cli_analysis.moc"
