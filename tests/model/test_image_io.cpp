// Drawing import: the shared PNG and SVG drawings, small EXR/TIFF/JPEG files written here with
// OpenImageIO (HDR clamping and sRGB encoding, 16-bit scaling), and damaged files as IoError.
#include "celform/model/image_io.h"
#include "celform/model/io_error.h"
#include "test_support.h"

#include <OpenImageIO/imageio.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <vector>

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
    QTest::newRow("exr float gray") << "g.exr" << int(OIIO::TypeDesc::FLOAT) << 1 << 188 << 188;
    QTest::newRow("tiff 16-bit rgb") << "b.tif" << int(OIIO::TypeDesc::UINT16) << 3 << 128 << 255;
    QTest::newRow("tiff 8-bit gray+alpha") << "c.tiff" << int(OIIO::TypeDesc::UINT8) << 2 << 128 << 128;
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

QTEST_MAIN(TestImageIo)
#include "test_image_io.moc"
