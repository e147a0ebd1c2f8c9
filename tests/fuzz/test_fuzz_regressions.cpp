// Replays every file under tests/data/fuzz-regressions/KIND/ (inputs that once crashed a loader or
// broke its promises) and the fuzz seeds under tests/data/fuzz-corpus/KIND/ through the loader of
// KIND, as the fuzz targets feed them (fuzz_inputs.h). Each must be refused with the loader's
// error (model::IoError) or accepted keeping its promises; a crash fails the run, and under the
// sanitize preset so does every sanitizer report.
#include "fuzz_inputs.h"

#include <QDirIterator>
#include <QtTest/QtTest>

using celform::fuzz::feed;
using celform::fuzz::kinds;
using celform::fuzz::Outcome;

class TestFuzzRegressions : public QObject {
    Q_OBJECT

public:
    // SVG text needs a QGuiApplication; the offscreen platform needs no display.
    static void initMain()
    {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
    }

private slots:
    void replay_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("path");
        for (const char* folder : {"fuzz-regressions", "fuzz-corpus"}) {
            const QDir root(QStringLiteral(CELFORM_TEST_DATA_DIR "/") + QLatin1String(folder));
            // Files beside the kind folders (a README) are not inputs.
            for (const QFileInfo& kind : root.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
                QDirIterator it(kind.filePath(), QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
                QStringList files;
                while (it.hasNext())
                    files << it.next();
                files.sort();
                for (const QString& file : files)
                    QTest::newRow(qPrintable(QLatin1String(folder) + QLatin1Char('/') + root.relativeFilePath(file)))
                        << kind.fileName() << file;
            }
        }
    }

    void replay()
    {
        QFETCH(QString, kind);
        QFETCH(QString, path);
        QVERIFY2(kinds().contains(kind),
            qPrintable(QStringLiteral("unknown kind folder “%1”; the kinds are %2").arg(kind, kinds().join(", "))));
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.errorString()));
        const Outcome outcome = feed(kind, file.readAll());
        QVERIFY2(outcome.broken.isEmpty(), qPrintable(QStringLiteral("accepted, but ") + outcome.broken));
        QVERIFY(outcome.loaded != !outcome.refusal.isEmpty());
        if (!outcome.loaded)
            qInfo("%s", qPrintable(QStringLiteral("refused: ") + outcome.refusal));
    }
};

QTEST_MAIN(TestFuzzRegressions)
#include "test_fuzz_regressions.moc"
