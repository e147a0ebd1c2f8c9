// Replays the fuzzers' findings kept under tests/data/fuzz-regressions/fuzzed/KIND/ and the fuzz
// seeds under tests/data/fuzz-corpus/KIND/ through their loaders, in this process, as the fuzz
// targets feed them (fuzz_inputs.h). Each must be refused with the loader's error (model::IoError)
// or accepted keeping its promises; a crash fails the run, and under the sanitize preset so does
// every sanitizer report. The handcrafted regressions beside fuzzed/ belong to the model and
// command-line tests, which read them as the product does (Assimp's in a child process).
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

private:
    /// A row per file in the kind folders of root (files beside them, a README, are not inputs).
    static void addRows(const QDir& root, const QString& label)
    {
        for (const QFileInfo& kind : root.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
            QDirIterator it(kind.filePath(), QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
            QStringList files;
            while (it.hasNext())
                files << it.next();
            files.sort();
            for (const QString& file : files)
                QTest::newRow(qPrintable(label + QLatin1Char('/') + root.relativeFilePath(file)))
                    << kind.fileName() << file;
        }
    }

private slots:
    void replay_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("path");
        const QString data = QStringLiteral(CELFORM_TEST_DATA_DIR "/");
        addRows(QDir(data + QStringLiteral("fuzz-corpus")), QStringLiteral("fuzz-corpus"));
        addRows(QDir(data + QStringLiteral("fuzz-regressions/fuzzed")), QStringLiteral("fuzz-regressions/fuzzed"));
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
