// Rendering regression: `celform render` of the bundled sample in each style against reference
// pictures looked at by a person (tests/data/baselines, made by scripts/update-baselines.sh), and
// the lines pass as SVG (issue 28, "Vector lines") against the PNG lines pass of the same frame.
#include "cli_run.h"
#include "test_support.h"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QProcess>
#include <QSet>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include <cmath>

namespace {

QString plainSample()
{
    return QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform");
}

/// What an SVG of lines holds, read with a real XML parser: the ids of its groups, and per
/// stroke path its data-kind; error is the parser's, empty when the file is well-formed.
struct SvgContents {
    QString error;
    QSize size;
    QStringList groups;
    QStringList strokeKinds;
    int tonePaths = 0;
};

SvgContents readSvg(const QString& path)
{
    SvgContents c;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        c.error = f.errorString();
        return c;
    }
    QXmlStreamReader xml(&f);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const QXmlStreamAttributes a = xml.attributes();
        if (xml.name() == QLatin1String("svg"))
            c.size = QSize(a.value("width").toInt(), a.value("height").toInt());
        else if (xml.name() == QLatin1String("g"))
            c.groups << a.value("id").toString();
        else if (xml.name() == QLatin1String("path") && a.value("class").startsWith(QLatin1String("stroke")))
            c.strokeKinds << a.value("data-kind").toString();
        else if (xml.name() == QLatin1String("path") && a.value("class") == QLatin1String("tone"))
            ++c.tonePaths;
    }
    if (xml.hasError())
        c.error = xml.errorString();
    return c;
}

/// Where the lines pass has ink: coverage at least one half (the file holds it sRGB-encoded).
std::vector<char> pngInk(const QImage& image)
{
    const QImage grey = image.convertToFormat(QImage::Format_Grayscale8);
    std::vector<char> ink(std::size_t(grey.width()) * std::size_t(grey.height()));
    for (int y = 0; y < grey.height(); ++y)
        for (int x = 0; x < grey.width(); ++x) {
            const double v = grey.constScanLine(y)[x] / 255.0;
            const double linear = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
            ink[std::size_t(y) * std::size_t(grey.width()) + std::size_t(x)] = linear >= 0.5;
        }
    return ink;
}

/// Where an SVG rasterised by Qt SVG over a transparent image has ink: alpha at least one half.
std::vector<char> svgInk(const QString& path, const QSize& size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QSvgRenderer renderer(path);
    if (!renderer.isValid())
        return {};
    QPainter painter(&image);
    renderer.render(&painter, QRectF(QPointF(0, 0), QSizeF(size)));
    painter.end();
    std::vector<char> ink(std::size_t(size.width()) * std::size_t(size.height()));
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x)
            ink[std::size_t(y) * std::size_t(size.width()) + std::size_t(x)] = qAlpha(image.pixel(x, y)) >= 128;
    return ink;
}

double iou(const std::vector<char>& a, const std::vector<char>& b)
{
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? double(both) / double(either) : 0.0;
}

QStringList renderArgs(const QString& out, const QStringList& extra)
{
    return QStringList{QStringLiteral("render"), plainSample(), QStringLiteral("--size"), QStringLiteral("240x180"),
               QStringLiteral("--out"), out}
    + extra;
}

} // namespace

class TestRenderBaselines : public QObject {
    Q_OBJECT
private slots:
    void matchesBaseline_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("baseline");
        for (const char* style : {"toon", "gooch", "comic", "lambert"})
            QTest::newRow(style) << QStringList{"--style", QLatin1String(style)}
                                 << QStringLiteral("elephant_%1.png").arg(QLatin1String(style));
        QTest::newRow("anaglyph") << QStringList{"--stereo", "anaglyph"} << QStringLiteral("elephant_anaglyph.png");
    }

    void matchesBaseline()
    {
        QFETCH(QStringList, options);
        QFETCH(QString, baseline);
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("frame.png"));
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        p.setProcessEnvironment(env);
        QStringList args{QStringLiteral("render"),
            QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"), QStringLiteral("--size"),
            QStringLiteral("240x180"), QStringLiteral("--out"), out};
        args << options;
        p.start(QStringLiteral(CELFORM_EXECUTABLE), args);
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitCode(), 0);
        const QImage rendered = QImage(out).convertToFormat(QImage::Format_RGB32);
        const QImage expected = QImage(celform::test::testDataPath(QStringLiteral("baselines/") + baseline))
                                    .convertToFormat(QImage::Format_RGB32);
        QVERIFY2(!expected.isNull(), "baseline missing: run scripts/update-baselines.sh and look at the pictures");
        QCOMPARE(rendered.size(), expected.size());
        // Tolerance for compiler and library differences between machines, not for changes of look:
        // a mean of half a level and under 0.5% of pixels off by more than 16 levels.
        double sum = 0;
        int far = 0;
        for (int y = 0; y < rendered.height(); ++y)
            for (int x = 0; x < rendered.width(); ++x) {
                const QRgb a = rendered.pixel(x, y), b = expected.pixel(x, y);
                const int d
                    = std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b));
                sum += d / 3.0;
                far += d > 48;
            }
        const double mean = sum / (rendered.width() * rendered.height());
        QVERIFY2(mean < 0.5, qPrintable(QStringLiteral("mean difference %1 levels").arg(mean)));
        QVERIFY2(far < rendered.width() * rendered.height() / 200,
            qPrintable(QStringLiteral("%1 pixels differ a lot").arg(far)));
    }

    // The SVG of the lines pass is well-formed XML, one path per stroke grouped by kind, and
    // rasterised by Qt SVG it inks the pixels the PNG lines pass inks (IoU >= 0.9), with and
    // without apparent ridges.
    void svgLinesMatchThePngPass_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::newRow("default lines") << QStringList{};
        QTest::newRow("every kind") << QStringList{"--lines", "silhouette,crease,border,material,ridge"};
    }

    void svgLinesMatchThePngPass()
    {
        QFETCH(QStringList, options);
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("lines.png")), svg = dir.filePath(QStringLiteral("lines.svg"));
        Run r = runCelform(renderArgs(png, QStringList{"--pass", "lines"} + options));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCelform(renderArgs(svg, QStringList{"--pass", "lines"} + options));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const SvgContents contents = readSvg(svg);
        QVERIFY2(contents.error.isEmpty(), qPrintable(contents.error));
        QCOMPARE(contents.size, QSize(240, 180));
        QVERIFY(contents.strokeKinds.size() > 10);
        const QSet<QString> kinds(contents.strokeKinds.begin(), contents.strokeKinds.end());
        for (const QString& kind : kinds) {
            QVERIFY2(
                QStringList({"silhouette", "crease", "border", "material", "ridge"}).contains(kind), qPrintable(kind));
            QVERIFY(contents.groups.contains(kind));
        }
        QVERIFY(kinds.contains(QStringLiteral("silhouette")));
        const QImage lines(png);
        const double overlap = iou(pngInk(lines), svgInk(svg, lines.size()));
        qInfo("SVG ink against the PNG lines pass: IoU %.3f", overlap);
        QVERIFY2(overlap >= 0.9, qPrintable(QStringLiteral("IoU %1").arg(overlap)));
    }

    // --svg-tones adds the tone regions, --strokes the strokes' JSON (the same strokes as the
    // SVG's paths), and a sequence numbers both files as it does images.
    void svgTonesAndStrokesJson()
    {
        QTemporaryDir dir;
        const Run r = runCelform(renderArgs(dir.filePath(QStringLiteral("shot_##.svg")),
            {"--frames", "0-1", "--svg-tones", "--strokes", dir.filePath(QStringLiteral("shot_##.json"))}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (const char* frame : {"00", "01"}) {
            const SvgContents contents = readSvg(dir.filePath(QStringLiteral("shot_%1.svg").arg(QLatin1String(frame))));
            QVERIFY2(contents.error.isEmpty(), qPrintable(contents.error));
            QVERIFY(contents.groups.contains(QStringLiteral("tones")));
            QVERIFY(contents.tonePaths >= 2);
            QFile json(dir.filePath(QStringLiteral("shot_%1.json").arg(QLatin1String(frame))));
            QVERIFY(json.open(QIODevice::ReadOnly));
            QJsonParseError error;
            const QJsonObject doc = QJsonDocument::fromJson(json.readAll(), &error).object();
            QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
            QCOMPARE(doc["width"].toInt(), 240);
            const QJsonArray strokes = doc["eyes"].toArray().at(0)["strokes"].toArray();
            QCOMPARE(strokes.size(), contents.strokeKinds.size());
            for (const QJsonValue& s : strokes) {
                const qsizetype n = s["points"].toArray().size();
                QVERIFY(n >= 1);
                QCOMPARE(s["widths"].toArray().size(), n);
                QCOMPARE(s["depths"].toArray().size(), n);
                QVERIFY(s["depths"].toArray().at(0).toDouble() > 0.0);
                QVERIFY(contents.strokeKinds.contains(s["kind"].toString()));
            }
        }
    }

    // In stereo each eye is a group of its own: side by side on a canvas twice as wide, and the
    // right eye's lines moved by the width.
    void svgStereoHasAGroupPerEye()
    {
        QTemporaryDir dir;
        const QString svg = dir.filePath(QStringLiteral("sbs.svg"));
        const Run r = runCelform(renderArgs(svg, {"--stereo", "sbs"}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const SvgContents contents = readSvg(svg);
        QVERIFY2(contents.error.isEmpty(), qPrintable(contents.error));
        QCOMPARE(contents.size, QSize(480, 180));
        for (const char* id : {"left", "right", "left-silhouette", "right-silhouette"})
            QVERIFY2(contents.groups.contains(QLatin1String(id)), id);
        const std::vector<char> ink = svgInk(svg, contents.size);
        std::size_t leftInk = 0, rightInk = 0;
        for (std::size_t i = 0; i < ink.size(); ++i)
            (i % 480 < 240 ? leftInk : rightInk) += ink[i];
        QVERIFY(leftInk > 100 && rightInk > 100);
        // Usage errors render nothing.
        QCOMPARE(runCelform(renderArgs(dir.filePath(QStringLiteral("x.png")), {"--svg-tones"})).exitCode, 2);
        QCOMPARE(runCelform(renderArgs(dir.filePath(QStringLiteral("x.svg")), {"--pass", "tone"})).exitCode, 2);
        QCOMPARE(runCelform(renderArgs(dir.filePath(QStringLiteral("x.svg")), {"--stereo", "dubois"})).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestRenderBaselines)
#include "test_render_baselines.moc"
