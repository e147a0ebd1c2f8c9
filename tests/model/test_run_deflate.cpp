// The run coder of the PNG writer (run_deflate.h, issue 29): its streams inflate back to the same
// bytes through zlib (whose inflate is the reference decoder of RFC 1950/1951), in several blocks,
// with skewed alphabets whose Huffman codes had to be cut to 15 bits, and within a size limit.
#include "celform/model/io/run_deflate.h"

#include <QTest>

#include <zlib.h>

#include <cstring>
#include <random>
#include <vector>

using celform::model::deflateRuns;

namespace {

/// zlib's inflate of a stream that should hold expected.size() bytes; empty on a refusal.
std::vector<unsigned char> inflated(const std::vector<unsigned char>& stream, std::size_t expected, int* status)
{
    std::vector<unsigned char> back(expected + 1);
    uLongf length = uLongf(back.size());
    *status = uncompress(back.data(), &length, stream.data(), uLong(stream.size()));
    back.resize(*status == Z_OK ? length : 0);
    return back;
}

/// Rows like a PNG's "Up"-filtered frame of flat tones: a filter byte, zeros, and edges that move
/// a pixel or two from row to row.
std::vector<unsigned char> filteredFrame(int width, int height)
{
    const std::size_t stride = std::size_t(width) * 4 + 1;
    std::vector<unsigned char> data(stride * std::size_t(height), 0);
    for (int y = 0; y < height; ++y) {
        unsigned char* row = data.data() + std::size_t(y) * stride;
        row[0] = 2;
        const int edge = width / 3 + (y * 7) / 5 % width / 4;
        for (int c = 0; c < 4 && 1 + std::size_t(edge) * 4 + std::size_t(c) < stride; ++c)
            row[1 + std::size_t(edge) * 4 + std::size_t(c)] = static_cast<unsigned char>(200 + c);
    }
    return data;
}

} // namespace

class TestRunDeflate : public QObject {
    Q_OBJECT

private slots:
    void roundTrip_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("size");
        QTest::addRow("empty") << 0 << 0;
        QTest::addRow("one byte") << 0 << 1;
        QTest::addRow("three bytes") << 0 << 3;
        QTest::addRow("noise, several blocks") << 0 << 200000;
        QTest::addRow("zeros") << 1 << 100000;
        QTest::addRow("sparse") << 2 << 150000;
        QTest::addRow("period 3") << 3 << 70001;
        QTest::addRow("skewed alphabet, cut codes") << 4 << 300000;
        QTest::addRow("two letters") << 5 << 5000;
        QTest::addRow("a filtered frame") << 6 << 0;
    }

    void roundTrip()
    {
        QFETCH(int, kind);
        QFETCH(int, size);
        std::mt19937 random(std::uint32_t(kind * 1000 + size));
        std::vector<unsigned char> data(std::size_t(size), 0);
        std::size_t period = 4, scanline = 1000;
        for (std::size_t i = 0; i < data.size(); ++i) {
            switch (kind) {
            case 0:
                data[i] = static_cast<unsigned char>(random());
                break;
            case 2:
                data[i] = random() % 40 == 0 ? static_cast<unsigned char>(random()) : 0;
                break;
            case 3:
                data[i] = static_cast<unsigned char>((i / 3) % 5 + (random() % 97 == 0 ? 9 : 0));
                break;
            case 4: {
                // Symbol k with probability about 2^-(k+1): 20 and more symbols would need codes
                // longer than deflate's 15 bits.
                int k = 0;
                while (k < 40 && (random() & 1u))
                    ++k;
                data[i] = static_cast<unsigned char>(k * 5);
                break;
            }
            case 5:
                data[i] = random() % 2 ? 'a' : 'b';
                break;
            default:
                break;
            }
        }
        if (kind == 6) {
            data = filteredFrame(640, 360);
            period = 4;
            scanline = 640 * 4 + 1;
        }
        std::vector<unsigned char> stream = {0xAB}; // what was there stays
        QVERIFY(deflateRuns(data.data(), data.size(), period, scanline, std::size_t(-1), stream));
        QCOMPARE(stream.front(), (unsigned char)0xAB);
        stream.erase(stream.begin());
        QCOMPARE(int(stream[0]), 0x78); // deflate, 32 KB window
        QCOMPARE((stream[0] * 256 + stream[1]) % 31, 0);
        int status = 0;
        const std::vector<unsigned char> back = inflated(stream, data.size(), &status);
        QCOMPARE(status, Z_OK);
        QVERIFY(back == data);
        if (kind == 1 || kind == 6)
            QVERIFY2(stream.size() * 200 < data.size() + 2000, qPrintable(QString::number(stream.size())));
    }

    /// A stream that would pass the limit is not made: false, and out as it was.
    void limitIsKept()
    {
        std::mt19937 random(3);
        std::vector<unsigned char> noise(50000);
        for (unsigned char& b : noise)
            b = static_cast<unsigned char>(random());
        std::vector<unsigned char> out = {1, 2, 3};
        QVERIFY(!deflateRuns(noise.data(), noise.size(), 4, 100, 40000, out));
        QCOMPARE(out, (std::vector<unsigned char>{1, 2, 3}));
        QVERIFY(deflateRuns(noise.data(), noise.size(), 4, 100, 60000, out));
        QVERIFY(out.size() > 50000 && out.size() <= 60003);
    }
};

QTEST_APPLESS_MAIN(TestRunDeflate)
#include "test_run_deflate.moc"
