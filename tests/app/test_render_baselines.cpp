// Rendering regression: `celform render` of the bundled sample in each style against reference
// pictures looked at by a person (tests/data/baselines, made by scripts/update-baselines.sh).
#include "test_support.h"

#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

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
};

QTEST_GUILESS_MAIN(TestRenderBaselines)
#include "test_render_baselines.moc"
