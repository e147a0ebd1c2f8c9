// The PNG encoder of rendered frames (io/png_encoder.h, issue 29): the same pixels as went in,
// read back by Qt's own PNG reader (libpng, which checks the chunks' CRCs), for every channel
// layout it takes; files about the size of libpng's adaptive filters on pictures like renders;
// clear refusals.
#include "celform/model/io/png_encoder.h"

#include <QBuffer>
#include <QImage>
#include <QImageWriter>
#include <QtTest/QtTest>

#include <cstdint>
#include <random>
#include <vector>

using celform::model::encodePng;

namespace {

/// A frame like a toon render: a background, two flat tones inside an ellipse, a dark outline
/// along its edge, and (smooth) a Gooch-like gradient instead of the tones.
std::vector<unsigned char> picture(int w, int h, int channels, bool smooth)
{
    std::vector<unsigned char> px(std::size_t(w) * std::size_t(h) * std::size_t(channels));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x - 0.5 * w) / (0.35 * w), v = (y - 0.5 * h) / (0.4 * h);
            const double r = u * u + v * v;
            unsigned char rgba[4] = {236, 236, 232, 0};
            if (r < 1.0) {
                const double lit = 0.5 + 0.5 * (0.6 * u - 0.8 * v);
                const double t = smooth ? lit : (lit > 0.45 ? 0.75 : 0.25);
                rgba[0] = (unsigned char)(40 + 180 * t);
                rgba[1] = (unsigned char)(60 + 150 * t);
                rgba[2] = (unsigned char)(150 - 60 * t);
                rgba[3] = 255;
                if (r > 0.96)
                    rgba[0] = rgba[1] = rgba[2] = 20; // the outline
            }
            unsigned char* p = px.data() + (std::size_t(y) * std::size_t(w) + std::size_t(x)) * std::size_t(channels);
            if (channels == 1)
                p[0] = rgba[1];
            else
                for (int c = 0; c < channels; ++c)
                    p[c] = rgba[c];
        }
    return px;
}

QImage::Format formatOf(int channels)
{
    return channels == 4 ? QImage::Format_RGBA8888
                         : (channels == 3 ? QImage::Format_RGB888 : QImage::Format_Grayscale8);
}

/// The file Qt's writer makes of the same pixels (libpng with its adaptive filters).
qsizetype qtPngSize(const std::vector<unsigned char>& px, int w, int h, int channels)
{
    const QImage image(px.data(), w, h, qsizetype(w) * channels, formatOf(channels));
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, "png");
    return writer.write(image) ? bytes.size() : -1;
}

} // namespace

class TestPngEncoder : public QObject {
    Q_OBJECT

private slots:
    void samePixelsBack_data()
    {
        QTest::addColumn<int>("channels");
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::addColumn<bool>("noise");
        for (const int c : {1, 3, 4}) {
            QTest::addRow("%d channels, a toon picture", c) << c << 320 << 240 << false;
            QTest::addRow("%d channels, noise", c) << c << 97 << 61 << true;
            QTest::addRow("%d channels, one pixel", c) << c << 1 << 1 << true;
        }
    }

    void samePixelsBack()
    {
        QFETCH(int, channels);
        QFETCH(int, width);
        QFETCH(int, height);
        QFETCH(bool, noise);
        std::vector<unsigned char> px = picture(width, height, channels, false);
        if (noise) {
            std::mt19937 random(7);
            for (unsigned char& b : px)
                b = (unsigned char)(random() & 0xff);
        }
        std::vector<unsigned char> file;
        QCOMPARE(encodePng(px.data(), width, height, channels, file), QString());
        QVERIFY(file.size() > 8);
        QImage back;
        QVERIFY(back.loadFromData(file.data(), int(file.size()), "png"));
        QCOMPARE(back.size(), QSize(width, height));
        back = back.convertToFormat(formatOf(channels));
        for (int y = 0; y < height; ++y)
            QVERIFY2(std::memcmp(back.constScanLine(y), px.data() + std::size_t(y) * std::size_t(width * channels),
                         std::size_t(width * channels))
                    == 0,
                qPrintable(QStringLiteral("row %1 differs").arg(y)));
    }

    /// The reader does check what the encoder computes: a file with one bit of its header's CRC
    /// flipped is refused.
    void chunkChecksumsAreChecked()
    {
        const std::vector<unsigned char> px = picture(16, 8, 4, false);
        std::vector<unsigned char> file;
        QCOMPARE(encodePng(px.data(), 16, 8, 4, file), QString());
        QImage back;
        QVERIFY(back.loadFromData(file.data(), int(file.size()), "png"));
        file[8 + 8 + 13] ^= 1; // signature, IHDR's length and type, its 13 bytes: the CRC
        QVERIFY(!back.loadFromData(file.data(), int(file.size()), "png"));
    }

    /// The storage of out is reused: a second, smaller picture leaves no bytes of the first.
    void outputIsReplacedNotAppended()
    {
        std::vector<unsigned char> file;
        const std::vector<unsigned char> big = picture(200, 100, 4, true);
        QCOMPARE(encodePng(big.data(), 200, 100, 4, file), QString());
        const std::vector<unsigned char> small = picture(8, 4, 3, false);
        QCOMPARE(encodePng(small.data(), 8, 4, 3, file), QString());
        QImage back;
        QVERIFY(back.loadFromData(file.data(), int(file.size()), "png"));
        QCOMPARE(back.size(), QSize(8, 4));
    }

    /// One fixed filter and the two coders cost little size against Qt's writer (libpng's adaptive
    /// filters, zlib's default level). A smooth gradient goes to libdeflate: within 5 % (measured
    /// here: 8 % smaller). Flat tones go to the run coder, whose file may be larger by what
    /// png_encoder.cpp allows it, 1/1000 of the raw pixels' bytes (here 2,074 bytes; measured: 1,453,
    /// 22 %, where libdeflate was 0.5 % larger than Qt's writer). On the dragon at 1920x1080 both
    /// coders' files are smaller than Qt's writer's.
    void sizeNearTheAdaptiveFilters_data()
    {
        QTest::addColumn<bool>("smooth");
        QTest::addColumn<double>("bound");
        QTest::addColumn<double>("extraOfRaw");
        QTest::newRow("toon") << false << 1.0 << 0.001;
        QTest::newRow("gradient") << true << 1.05 << 0.0;
    }

    void sizeNearTheAdaptiveFilters()
    {
        QFETCH(bool, smooth);
        QFETCH(double, bound);
        QFETCH(double, extraOfRaw);
        const int w = 960, h = 540;
        const std::vector<unsigned char> px = picture(w, h, 4, smooth);
        std::vector<unsigned char> file;
        QCOMPARE(encodePng(px.data(), w, h, 4, file), QString());
        const qsizetype qt = qtPngSize(px, w, h, 4);
        QVERIFY(qt > 0);
        qInfo("%s: %zu bytes, Qt's writer %lld", QTest::currentDataTag(), file.size(), qlonglong(qt));
        QVERIFY2(double(file.size()) <= bound * double(qt) + extraOfRaw * double(px.size()),
            qPrintable(QStringLiteral("%1 bytes against %2").arg(file.size()).arg(qt)));
    }

    /// Which coder made the IDAT, by its zlib header: the run coder's says "fastest" (0x78 0x01),
    /// libdeflate's at level 7 "default" (0x78 0x9C). A frame of flat tones (an ellipse in two tones
    /// with its outline, as the toon picture, but as large as a frame) takes the run coder; the
    /// gradient and noise, and pictures too low to sample, take libdeflate. Both read back the same.
    void coderByPicture_data()
    {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::addColumn<int>("content"); // 0 flat tones, 1 gradient, 2 noise
        QTest::addColumn<bool>("runs");
        QTest::newRow("flat tones, 1920x1080") << 1920 << 1080 << 0 << true;
        QTest::newRow("gradient, 1920x1080") << 1920 << 1080 << 1 << false;
        QTest::newRow("noise, 640x480") << 640 << 480 << 2 << false;
        QTest::newRow("flat tones, 63 rows") << 1920 << 63 << 0 << false;
    }

    void coderByPicture()
    {
        QFETCH(int, width);
        QFETCH(int, height);
        QFETCH(int, content);
        QFETCH(bool, runs);
        std::vector<unsigned char> px = picture(width, height, 4, content == 1);
        if (content == 2) {
            std::mt19937 random(11);
            for (unsigned char& b : px)
                b = (unsigned char)(random() & 0xff);
        }
        std::vector<unsigned char> file;
        QCOMPARE(encodePng(px.data(), width, height, 4, file), QString());
        const std::size_t idat = 8 + 25 + 8; // signature, IHDR chunk, IDAT's length and type
        QVERIFY(file.size() > idat + 2);
        QCOMPARE(std::memcmp(file.data() + idat - 4, "IDAT", 4), 0);
        QCOMPARE(int(file[idat]), 0x78);
        QCOMPARE(int(file[idat + 1]), runs ? 0x01 : 0x9C);
        QImage back;
        QVERIFY(back.loadFromData(file.data(), int(file.size()), "png"));
        back = back.convertToFormat(QImage::Format_RGBA8888);
        for (int y = 0; y < height; ++y)
            QVERIFY(std::memcmp(back.constScanLine(y), px.data() + std::size_t(y) * std::size_t(width) * 4,
                        std::size_t(width) * 4)
                == 0);
    }

    void refusesWhatIsNotAnImage()
    {
        std::vector<unsigned char> file(10, 1);
        const unsigned char px[8] = {};
        QVERIFY(encodePng(px, 2, 2, 2, file).contains(QLatin1String("2")));
        QVERIFY(file.empty());
        QVERIFY(!encodePng(px, 0, 2, 4, file).isEmpty());
        QVERIFY(!encodePng(nullptr, 2, 2, 4, file).isEmpty());
        QVERIFY(file.empty());
    }
};

QTEST_GUILESS_MAIN(TestPngEncoder)
#include "test_png_encoder.moc"
