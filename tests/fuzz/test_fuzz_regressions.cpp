// Replays every input kept under tests/data/fuzz-regressions (inputs that once crashed a loader or
// broke its promises) and the fuzz seeds under tests/data/fuzz-corpus/KIND/ through their loaders,
// as the fuzz targets feed them (fuzz_inputs.h). Each must be refused with the loader's error
// (model::IoError) or accepted keeping its promises; a crash fails the run, and under the sanitize
// preset so does every sanitizer report.
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
    /// A row per file in the folders of root (files beside them, a README, are not inputs). The
    /// kind is the folder's name when byFolder, else the file's suffix.
    static void addRows(const QDir& root, const QString& label, bool byFolder)
    {
        for (const QFileInfo& folder : root.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
            if (!byFolder && folder.fileName() == QLatin1String("fuzzed"))
                continue;
            QDirIterator it(folder.filePath(), QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
            QStringList files;
            while (it.hasNext())
                files << it.next();
            files.sort();
            for (const QString& file : files)
                QTest::newRow(qPrintable(label + QLatin1Char('/') + root.relativeFilePath(file)))
                    << (byFolder ? folder.fileName() : kindOfSuffix(QFileInfo(file).suffix())) << file;
        }
    }

    static QString kindOfSuffix(const QString& suffix)
    {
        const QString s = suffix.toLower();
        if (s == QLatin1String("celform"))
            return QStringLiteral("project");
        if (s == QLatin1String("jpeg"))
            return QStringLiteral("jpg");
        if (s == QLatin1String("tiff"))
            return QStringLiteral("tif");
        return s;
    }

private slots:
    void replay_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("path");
        const QString data = QStringLiteral(CELFORM_TEST_DATA_DIR "/");
        // Seeds and fuzzers' findings sit in a folder named after their kind; the handcrafted
        // regressions (cli/, image/, mesh/, project/) are sorted by subject, so their suffix names it.
        addRows(QDir(data + QStringLiteral("fuzz-corpus")), QStringLiteral("fuzz-corpus"), true);
        addRows(
            QDir(data + QStringLiteral("fuzz-regressions/fuzzed")), QStringLiteral("fuzz-regressions/fuzzed"), true);
        addRows(QDir(data + QStringLiteral("fuzz-regressions")), QStringLiteral("fuzz-regressions"), false);
    }

    void replay()
    {
        QFETCH(QString, kind);
        QFETCH(QString, path);
        QVERIFY2(kinds().contains(kind),
            qPrintable(QStringLiteral("unknown kind “%1” (a folder or a suffix); the kinds are %2")
                           .arg(kind, kinds().join(", "))));
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
