// Drawing import: the shared PNG and SVG drawings, small EXR/TIFF/JPEG files written here with
// OpenImageIO (HDR clamping and sRGB encoding, 16-bit scaling), and damaged files as IoError.
#include "celform/model/io/image_io.h"
#include "celform/model/io/raster_codec.h"
#include "celform/model/data/io_error.h"
#include "test_support.h"

#include <OpenImageIO/imageio.h>

#include <QBuffer>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <csignal>
#include <functional>
#include <new>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using celform::model::Drawing;
using celform::model::importDrawing;
using celform::model::IoError;

/// Runs an import expected to succeed; an IoError fails the test instead of aborting the run.
#define CELFORM_IMPORT_OR_FAIL(var, expr)                                                                              \
    decltype(expr) var;                                                                                                \
    try {                                                                                                              \
        var = (expr);                                                                                                  \
    } catch (const IoError& e) {                                                                                       \
        QFAIL(qPrintable(e.message()));                                                                                \
    }

namespace {

int opaquePixels(const QImage& image)
{
    int n = 0;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4)
            n += qAlpha(image.pixel(x, y)) > 0 ? 1 : 0;
    return n;
}

/// A 4 x 2 image: pixel (0,0) = (0.5, 2.0, 0.0), others a ramp; alpha 1 where present.
void writeWithOiio(const QString& path, OIIO::TypeDesc type, int channels)
{
    auto out = OIIO::ImageOutput::create(path.toStdString());
    QVERIFY(out);
    const OIIO::ImageSpec spec(4, 2, channels, type);
    QVERIFY(out->open(path.toStdString(), spec));
    std::vector<float> pixels(std::size_t(4 * 2 * channels), 1.0f);
    pixels[0] = 0.5f;
    pixels[1] = 2.0f;
    pixels[2] = 0.0f;
    QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    QVERIFY(out->close());
}

QString writeBytes(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

/// How a call run in a child process ended, with what it printed on standard error.
struct ChildOutcome {
    enum Kind { IoErrorThrown, OtherException, Returned, Crashed, TimedOut } kind = Crashed;
    QString message; ///< the exception's text
    QString standardError; ///< everything the child wrote to file descriptor 2
    qint64 milliseconds = 0;

    [[nodiscard]] QString describe() const
    {
        const char* names[] = {"IoError", "another exception", "no exception", "crash", "time-out"};
        return QStringLiteral("%1 after %2 ms: %3 [stderr: %4]")
            .arg(names[kind])
            .arg(milliseconds)
            .arg(message, standardError);
    }
};

/// Runs body in a forked child whose address space may grow by at most budget bytes, killed after
/// timeoutMs, its standard error captured: a decode that allocates gigabytes, hangs or prints
/// its library's own lines fails the test instead of taking the run (or the machine) down.
ChildOutcome runInChild(const std::function<void()>& body, qint64 budget = 512ll << 20, int timeoutMs = 10000)
{
    QTemporaryFile result, errors;
    if (!result.open() || !errors.open())
        qFatal("cannot make temporary files");
    std::fflush(stdout);
    std::fflush(stderr);
    QElapsedTimer timer;
    timer.start();
    const pid_t pid = ::fork();
    if (pid == 0) {
        for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL})
            std::signal(sig, SIG_DFL); // die by the signal, without QtTest's crash report
        ::dup2(int(errors.handle()), STDERR_FILENO);
        QFile statm(QStringLiteral("/proc/self/statm"));
        const qint64 pages = statm.open(QIODevice::ReadOnly) ? statm.readAll().split(' ').value(0).toLongLong() : 0;
        const auto limit = rlim_t(pages * ::sysconf(_SC_PAGESIZE) + budget);
        const rlimit rl{limit, limit};
        ::setrlimit(RLIMIT_AS, &rl);
        ChildOutcome::Kind kind = ChildOutcome::Returned;
        QByteArray message;
        try {
            body();
        } catch (const IoError& e) {
            kind = ChildOutcome::IoErrorThrown;
            message = e.message().toUtf8();
        } catch (const std::bad_alloc&) {
            kind = ChildOutcome::OtherException;
            message = "std::bad_alloc";
        } catch (const std::exception& e) {
            kind = ChildOutcome::OtherException;
            message = e.what();
        }
        const QByteArray out = QByteArray::number(int(kind)) + ' ' + message;
        [[maybe_unused]] const auto written = ::write(int(result.handle()), out.constData(), std::size_t(out.size()));
        ::_exit(0);
    }
    ChildOutcome outcome;
    int status = 0;
    bool finished = false;
    while (!finished && timer.elapsed() < timeoutMs) {
        finished = ::waitpid(pid, &status, WNOHANG) == pid;
        if (!finished)
            QThread::msleep(5);
    }
    outcome.milliseconds = timer.elapsed();
    QFile resultFile(result.fileName()), errorFile(errors.fileName());
    const QByteArray out = resultFile.open(QIODevice::ReadOnly) ? resultFile.readAll() : QByteArray();
    outcome.standardError = QString::fromUtf8(errorFile.open(QIODevice::ReadOnly) ? errorFile.readAll() : "");
    if (!finished) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        outcome.kind = ChildOutcome::TimedOut;
    } else if (WIFEXITED(status) && !out.isEmpty()) {
        outcome.kind = ChildOutcome::Kind(out.left(out.indexOf(' ')).toInt());
        outcome.message = QString::fromUtf8(out.mid(out.indexOf(' ') + 1));
    }
    return outcome;
}

QByteArray fileBytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestImageIo : public QObject {
    Q_OBJECT

public:
    // QSvgRenderer needs a QGuiApplication; the offscreen platform needs no display.
    static void initMain() { qputenv("QT_QPA_PLATFORM", "offscreen"); }

private slots:
    void sharedPng();
    void sharedSvg();
    void generated_data();
    void generated();
    void damaged_data();
    void damaged();
    void suffixesAndFilter();
    void refusesFuzzRegressions_data();
    void refusesFuzzRegressions();
    void psdSectionsAreCheckedBeforeDecoding();
    void decoderMessagesStayQuiet();
    void mostCompressiblePngIsRead();
    void refusesPipesAndFolders_data();
    void refusesPipesAndFolders();
};

void TestImageIo::sharedPng()
{
    CELFORM_REQUIRE_SHARED(path, QStringLiteral("drawings/tuxpaint_elephant.png"));
    CELFORM_IMPORT_OR_FAIL(d, importDrawing(path))
    QCOMPARE(d.name, QStringLiteral("tuxpaint_elephant"));
    QCOMPARE(d.imageFormat, QStringLiteral("png"));
    QCOMPARE(d.imageData.size(), QFileInfo(path).size());
    QCOMPARE(d.id, celform::model::ObjectId(0));
    QCOMPARE(d.image.height(), 1024); // the README's renders are 1024 px high
    QVERIFY(d.image.width() > 100);
    QVERIFY(opaquePixels(d.image) > 100);
    // Same pixels as Qt's own PNG reader (straight alpha, no colour shift) where opaque.
    const QImage reference = QImage(path).convertToFormat(QImage::Format_RGBA8888);
    QCOMPARE(reference.size(), d.image.size());
    int compared = 0;
    for (int y = 0; y < reference.height(); y += 7)
        for (int x = 0; x < reference.width(); x += 7) {
            const QRgb a = reference.pixel(x, y);
            const QRgb b = d.image.pixel(x, y);
            if (qAlpha(a) == 255) {
                QVERIFY(
                    qAbs(qRed(a) - qRed(b)) <= 1 && qAbs(qGreen(a) - qGreen(b)) <= 1 && qAbs(qBlue(a) - qBlue(b)) <= 1);
                ++compared;
            }
            QVERIFY(qAbs(qAlpha(a) - qAlpha(b)) <= 1);
        }
    QVERIFY(compared > 0);
}

void TestImageIo::sharedSvg()
{
    CELFORM_REQUIRE_SHARED(path, QStringLiteral("drawings/openclipart_contour_elephant.svg"));
    CELFORM_IMPORT_OR_FAIL(d, importDrawing(path))
    QCOMPARE(d.imageFormat, QStringLiteral("svg"));
    QCOMPARE(d.image.height(), 1024);
    // The PNG next to it is the same drawing rendered 1024 px high: same aspect ratio.
    const QString png = celform::test::sharedDataPath(QStringLiteral("drawings/openclipart_contour_elephant.png"));
    if (!png.isEmpty())
        QVERIFY(qAbs(d.image.width() - QImage(png).width()) <= 2);
    QVERIFY(opaquePixels(d.image) > 100);
    QCOMPARE(qAlpha(d.image.pixel(0, 0)), 0); // transparent background
}

void TestImageIo::generated_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("type");
    QTest::addColumn<int>("channels");
    QTest::addColumn<int>("red"); // expected 8-bit red of pixel (0,0)
    QTest::addColumn<int>("green"); // expected 8-bit green of pixel (0,0)
    // Linear 0.5 encodes to sRGB 188; 2.0 clamps to 255.
    QTest::newRow("exr half rgba") << "a.exr" << int(OIIO::TypeDesc::HALF) << 4 << 188 << 255;
    QTest::newRow("exr float grey") << "g.exr" << int(OIIO::TypeDesc::FLOAT) << 1 << 188 << 188;
    QTest::newRow("tiff 16-bit rgb") << "b.tif" << int(OIIO::TypeDesc::UINT16) << 3 << 128 << 255;
    QTest::newRow("tiff 8-bit grey+alpha") << "c.tiff" << int(OIIO::TypeDesc::UINT8) << 2 << 128 << 128;
    QTest::newRow("jpeg") << "d.jpg" << int(OIIO::TypeDesc::UINT8) << 3 << -1 << -1;
    QTest::newRow("png 16-bit") << "e.png" << int(OIIO::TypeDesc::UINT16) << 3 << 128 << 255;
}

void TestImageIo::generated()
{
    QFETCH(QString, name);
    QFETCH(int, type);
    QFETCH(int, channels);
    QFETCH(int, red);
    QFETCH(int, green);
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    writeWithOiio(path, OIIO::TypeDesc(OIIO::TypeDesc::BASETYPE(type)), channels);
    CELFORM_IMPORT_OR_FAIL(d, importDrawing(path))
    QCOMPARE(d.image.size(), QSize(4, 2));
    QCOMPARE(d.name, QFileInfo(name).completeBaseName());
    QVERIFY(d.imageFormat == QLatin1String("exr") || d.imageFormat == QLatin1String("tif")
        || d.imageFormat == QLatin1String("jpg") || d.imageFormat == QLatin1String("png"));
    const QRgb p = d.image.pixel(0, 0);
    QCOMPARE(qAlpha(p), 255);
    if (red >= 0) {
        QVERIFY2(qAbs(qRed(p) - red) <= 1, qPrintable(QString::number(qRed(p))));
        QVERIFY2(qAbs(qGreen(p) - green) <= 1, qPrintable(QString::number(qGreen(p))));
    }
    QCOMPARE(qRed(d.image.pixel(3, 1)), 255);
}

void TestImageIo::damaged_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QByteArray png;
    if (const QString p = celform::test::sharedDataPath(QStringLiteral("drawings/tuxpaint_frog.png")); !p.isEmpty()) {
        QFile f(p);
        if (f.open(QIODevice::ReadOnly))
            png = f.readAll();
    }
    if (!png.isEmpty()) {
        QTest::newRow("truncated png") << "frog.png" << png.left(png.size() / 2);
        QTest::newRow("png cut in the pixel data") << "frog90.png" << png.left(png.size() * 9 / 10);
    }
    // Issue 27: JPEG and TIFF cut in half (libjpeg only warned and filled the rest grey).
    std::vector<unsigned char> pixels(std::size_t(64) * 48 * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = static_cast<unsigned char>((i * 37) % 251);
    for (const char* format : {"jpg", "tif"}) {
        std::vector<unsigned char> encoded;
        const QString problem
            = celform::model::rasterCodec(QStringLiteral("test"))
                  .encode(QString::fromLatin1(format), 64, 48, {"R", "G", "B"}, pixels.data(), &encoded);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QTest::newRow(qPrintable(QStringLiteral("truncated %1").arg(QLatin1String(format))))
            << QStringLiteral("half.%1").arg(QLatin1String(format))
            << QByteArray(reinterpret_cast<const char*>(encoded.data()), qsizetype(encoded.size() / 2));
    }
    QTest::newRow("png header only") << "header.png" << QByteArray("\x89PNG\r\n\x1a\n", 8);
    QTest::newRow("garbage png") << "garbage.png" << QByteArray(300, 'x');
    QTest::newRow("garbage exr") << "garbage.exr" << QByteArray(300, 'x');
    QTest::newRow("garbage jpg") << "garbage.jpg" << QByteArray("\xff\xd8\xff garbage", 12);
    QTest::newRow("empty") << "empty.png" << QByteArray();
    QTest::newRow("invalid svg") << "bad.svg" << QByteArray("<svg><g></svg");
    QTest::newRow("unknown suffix") << "drawing.xyz" << QByteArray("abc");
}

void TestImageIo::damaged()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QTemporaryDir dir;
    const QString path = writeBytes(dir, name, bytes);
    try {
        importDrawing(path);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), path);
        QVERIFY(!e.problem().isEmpty());
        QVERIFY2(!e.problem().contains(QLatin1Char('\n')), qPrintable(e.message()));
        qInfo("%s -> %s", qPrintable(name), qPrintable(e.problem()));
        // Refused before OpenImageIO reads past the end (where its PNG reader leaks, which the
        // sanitize preset's LeakSanitizer reports).
        if (name.startsWith(QLatin1String("frog")) || name == QLatin1String("header.png")
            || name.startsWith(QLatin1String("half.")))
            QVERIFY2(e.problem().contains(QStringLiteral("truncated")), qPrintable(e.problem()));
    }
}

// Found by fuzz_psd: an 8x8 PSD of 207 bytes stating 4.2 GB of colour mode data made
// OpenImageIO allocate the 4.2 GB (stopped only by the import child's memory limit). Section
// lengths beyond the end of the file are refused before any decoder runs, in this process; real
// PSDs still decode.
void TestImageIo::psdSectionsAreCheckedBeforeDecoding()
{
    const QString bomb
        = celform::test::testDataPath(QStringLiteral("fuzz-regressions/image/psd-8x8-colour-mode-4.2-gb.psd"));
    QElapsedTimer timer;
    timer.start();
    try {
        importDrawing(bomb);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), bomb);
        QCOMPARE(e.problem(),
            QStringLiteral("the PSD file states 4194303999 bytes of colour mode data, but holds 177 bytes after that "
                           "point"));
    }
    QVERIFY2(timer.elapsed() < 2000, qPrintable(QString::number(timer.elapsed())));
    for (const char* name : {"rgb_raw.psd", "rgba_rle.psd"}) {
        const QString path = celform::test::testDataPath(QStringLiteral("fuzz-corpus/psd/%1").arg(QLatin1String(name)));
        const Drawing d = importDrawing(path);
        QVERIFY2(!d.image.isNull(), name);
    }
}

void TestImageIo::suffixesAndFilter()
{
    const QStringList s = celform::model::imageSuffixes();
    for (const char* needed : {"png", "jpg", "tif", "exr", "psd", "svg"})
        QVERIFY(s.contains(QLatin1String(needed)));
    QVERIFY(celform::model::imageFileFilter().contains(QStringLiteral("*.svg")));
    QVERIFY_THROWS_EXCEPTION(IoError, importDrawing(QStringLiteral("/nonexistent/drawing.png")));
}

void TestImageIo::refusesFuzzRegressions_data()
{
    QTest::addColumn<QString>("path");
    const QDir dir(celform::test::testDataPath(QStringLiteral("fuzz-regressions/image")));
    QStringList files = dir.entryList(QDir::Files, QDir::Name);
    files.removeAll(QStringLiteral("png-1000x1000-libpng-error-line.png")); // decoderMessagesStayQuiet
    files.removeAll(QStringLiteral("psd-8x8-colour-mode-4.2-gb.psd")); // psdSectionsAreCheckedBeforeDecoding
    QVERIFY(!files.isEmpty());
    for (const QString& name : files)
        QTest::newRow(qPrintable(name)) << dir.filePath(name);
}

// Images whose header states more pixels than allowed, or more than their file can hold
// (a 69-byte PNG of 11585 x 11585 pixels took 1.7 GB), are refused from the header, before any
// buffer is allocated, in one line naming the file; both for a drawing being imported and for the
// sizes `celform info` reads, and for formats whose header OpenImageIO reads (TIFF).
void TestImageIo::refusesFuzzRegressions()
{
    QFETCH(QString, path);
    const ChildOutcome imported = runInChild([&] { importDrawing(path); });
    QVERIFY2(imported.kind == ChildOutcome::IoErrorThrown, qPrintable(imported.describe()));
    QVERIFY2(imported.message.startsWith(path + QStringLiteral(": ")), qPrintable(imported.message));
    QVERIFY2(imported.message.contains(QStringLiteral("too large")), qPrintable(imported.message));
    QVERIFY2(!imported.message.contains(QLatin1Char('\n')), qPrintable(imported.message));
    QVERIFY2(imported.standardError.isEmpty(), qPrintable(imported.describe()));
    QVERIFY2(imported.milliseconds < 5000, qPrintable(imported.describe()));

    const QByteArray bytes = fileBytes(path);
    const QString suffix = QFileInfo(path).suffix();
    const ChildOutcome sized
        = runInChild([&] { celform::model::decodedImageSize(bytes, suffix, QStringLiteral("label")); });
    QVERIFY2(sized.kind == ChildOutcome::IoErrorThrown, qPrintable(sized.describe()));
    QVERIFY2(sized.message.startsWith(QStringLiteral("label: ")), qPrintable(sized.message));
    QVERIFY2(sized.message.contains(QStringLiteral("too large")), qPrintable(sized.message));
}

// libpng printed "libpng error: Not enough image data" on standard error beside the one-line
// refusal; the decoder's own messages are silenced, the refusal says what they said.
void TestImageIo::decoderMessagesStayQuiet()
{
    const QString path
        = celform::test::testDataPath(QStringLiteral("fuzz-regressions/image/png-1000x1000-libpng-error-line.png"));
    const ChildOutcome outcome = runInChild([&] { importDrawing(path); });
    QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
    QVERIFY2(outcome.message.startsWith(path + QStringLiteral(": ")), qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains(QStringLiteral("Not enough image data")), qPrintable(outcome.message));
    QVERIFY2(outcome.standardError.isEmpty(), qPrintable(outcome.describe()));
    // Standard error works again after the decode.
    const ChildOutcome after = runInChild([&] {
        try {
            importDrawing(path);
        } catch (const IoError&) { }
        std::fputs("still here\n", stderr);
    });
    QCOMPARE(after.standardError, QStringLiteral("still here\n"));
}

// The limit on pixels per byte of the file keeps clear of real files: a blank 1-bit PNG, about the
// most a PNG is compressed (zlib: 3,300 pixels a byte), beyond the 16-megapixel floor, is read.
void TestImageIo::mostCompressiblePngIsRead()
{
    QImage blank(4200, 4200, QImage::Format_Mono);
    blank.fill(1);
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    QVERIFY(blank.save(&buffer, "PNG", 0));
    QVERIFY(qint64(4200) * 4200 > qint64(png.size()) * 2000); // far beyond a drawing's usual ratio
    QTemporaryDir dir;
    const QString path = writeBytes(dir, QStringLiteral("blank.png"), png);
    CELFORM_IMPORT_OR_FAIL(d, importDrawing(path))
    QCOMPARE(d.image.size(), QSize(4200, 4200));
    QCOMPARE(celform::model::decodedImageSize(png, QStringLiteral("png"), path), QSize(4200, 4200));
}

void TestImageIo::refusesPipesAndFolders_data()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("named pipe") << "fifo";
    QTest::newRow("folder") << "folder";
}

// A named pipe given as a drawing blocked in open() for ever, waiting for a writer;
// anything but a regular file is refused before it is opened.
void TestImageIo::refusesPipesAndFolders()
{
    QFETCH(QString, kind);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("special.png"));
    if (kind == QLatin1String("fifo"))
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    else
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("special.png")));
    const ChildOutcome outcome = runInChild([&] { importDrawing(path); }, 512ll << 20, 5000);
    QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
    QVERIFY2(outcome.message.startsWith(path + QStringLiteral(": ")), qPrintable(outcome.message));
    QVERIFY2(outcome.message.contains(QStringLiteral("not a regular file")), qPrintable(outcome.message));
}

QTEST_MAIN(TestImageIo)
#include "test_image_io.moc"
