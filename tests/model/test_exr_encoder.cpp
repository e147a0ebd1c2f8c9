// The EXR encoder of rendered frames (io/exr_encoder.h, issue 29): the same samples as went in,
// bit for bit, read back by OpenImageIO's EXR reader (OpenEXR's own decompression), for every
// kind of source, odd widths and blocks that do not compress; files no larger than OpenEXR's own
// ZIP writer made of the same pixels at zlib's level 1 (Celform's EXRs before), within 1 % of its
// default level; clear refusals.
#include "celform/model/io/exr_encoder.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <QtTest/QtTest>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using celform::model::encodeExr;
using celform::model::ExrChannelSource;
using Kind = ExrChannelSource::Kind;

namespace {

/// A decoded EXR: its channel names in OpenImageIO's order and the interleaved floats.
struct Decoded {
    std::vector<std::string> names;
    std::vector<float> pixels;
    int width = 0, height = 0;
    std::string compression;

    /// Sample (x, y) of the named channel; NaN when there is no such channel.
    float at(const std::string& name, int x, int y) const
    {
        for (std::size_t c = 0; c < names.size(); ++c)
            if (names[c] == name)
                return pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * names.size() + c];
        return std::numeric_limits<float>::quiet_NaN();
    }
};

Decoded decode(std::vector<unsigned char>& bytes)
{
    Decoded d;
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open("frame.exr", nullptr, &reader);
    if (!in)
        return d;
    const OIIO::ImageSpec& spec = in->spec();
    d.width = spec.width;
    d.height = spec.height;
    d.names = spec.channelnames;
    d.compression = spec.get_string_attribute("compression");
    d.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, d.pixels.data()))
        d.pixels.clear();
    return d;
}

/// The same interleaved floats written by OpenImageIO with OpenEXR's own ZIP over single scanlines
/// at zlib's level (as "zips:N"): the sizes to compare with.
std::size_t openExrSize(
    int w, int h, const std::vector<std::string>& names, const std::vector<float>& pixels, const char* compression)
{
    OIIO::ImageSpec spec(w, h, int(names.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.attribute("compression", compression);
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create("frame.exr");
    if (!out || !out->set_ioproxy(&proxy) || !out->open("frame.exr", spec)
        || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
        return 0;
    return bytes.size();
}

/// Interleaved R G B A of a render-like frame: a background, a lit ellipse with smooth shading
/// (noisy low bits, as real floats have), an outline.
std::vector<float> renderLike(int w, int h)
{
    std::vector<float> px(std::size_t(w) * std::size_t(h) * 4, 0.f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x - 0.5 * w) / (0.35 * w), v = (y - 0.5 * h) / (0.4 * h);
            const double r = u * u + v * v;
            float* p = px.data() + (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4;
            if (r >= 1.0)
                continue;
            const float lit = float(0.5 + 0.5 * std::sin(3.0 * u - 2.0 * v) * std::sqrt(1.0 - r));
            p[0] = 0.2f + 0.7f * lit;
            p[1] = 0.3f + 0.5f * lit;
            p[2] = 0.6f - 0.2f * lit;
            p[3] = 1.f;
        }
    return px;
}

} // namespace

class TestExrEncoder : public QObject {
    Q_OBJECT

private slots:
    void everyKindReadsBackBitForBit_data()
    {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::newRow("1x1") << 1 << 1;
        QTest::newRow("odd 37x23 (the vector loops' tails)") << 37 << 23;
        QTest::newRow("640x360") << 640 << 360;
    }

    void everyKindReadsBackBitForBit()
    {
        QFETCH(int, width);
        QFETCH(int, height);
        const std::size_t n = std::size_t(width) * std::size_t(height);
        const std::vector<float> rgba = renderLike(width, height);
        std::vector<float> depth(n), normals(n * 3), noise(n);
        std::vector<std::int32_t> ids(n);
        std::mt19937 random(7);
        std::uniform_real_distribution<float> any(-1e6f, 1e6f);
        for (std::size_t i = 0; i < n; ++i) {
            depth[i] = i % 5 == 0 ? std::numeric_limits<float>::infinity()
                : i % 7 == 0      ? std::numeric_limits<float>::quiet_NaN()
                                  : 1.5f + 0.001f * float(i);
            for (int c = 0; c < 3; ++c)
                normals[i * 3 + std::size_t(c)] = std::cos(0.01f * float(i) + float(c));
            ids[i] = i % 3 == 0 ? -1 : std::int32_t(i * 2654435761u % 1000003u);
            noise[i] = any(random);
        }
        const std::vector<ExrChannelSource> sources
            = {{"R", rgba.data(), 4, Kind::Float}, {"G", rgba.data() + 1, 4, Kind::Float},
                {"B", rgba.data() + 2, 4, Kind::Float}, {"A", rgba.data() + 3, 4, Kind::Float},
                {"depth.Z", depth.data(), 1, Kind::FiniteFloat}, {"normal.X", normals.data(), 3, Kind::Float},
                {"normal.Y", normals.data() + 1, 3, Kind::Float}, {"normal.Z", normals.data() + 2, 3, Kind::Float},
                {"id.ID", ids.data(), 1, Kind::Int32}, {"noise.Y", noise.data(), 1, Kind::Float}};
        std::vector<unsigned char> bytes;
        QVERIFY2(encodeExr(width, height, sources, bytes).isEmpty(), "the encoder refused");
        Decoded d = decode(bytes);
        QCOMPARE(d.width, width);
        QCOMPARE(d.height, height);
        QCOMPARE(int(d.names.size()), int(sources.size()));
        QCOMPARE(d.compression, std::string("zips"));
        QVERIFY(!d.pixels.empty());
        const auto same = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
                for (int c = 0; c < 4; ++c)
                    QVERIFY(same(d.at(std::string(1, "RGBA"[c]), x, y), rgba[i * 4 + std::size_t(c)]));
                QVERIFY(same(d.at("depth.Z", x, y), std::isfinite(depth[i]) ? depth[i] : 0.f));
                QVERIFY(same(d.at("normal.X", x, y), normals[i * 3]));
                QVERIFY(same(d.at("normal.Z", x, y), normals[i * 3 + 2]));
                QVERIFY(same(d.at("id.ID", x, y), float(ids[i])));
                QVERIFY(same(d.at("noise.Y", x, y), noise[i]));
            }
    }

    void blocksThatDoNotCompressAreStoredAsTheyAre()
    {
        // Random bits do not deflate: every scanline is kept as it is, which the reader tells by
        // its size, and the file is about as large as the floats.
        const int w = 301, h = 7;
        std::vector<std::uint32_t> bits(std::size_t(w) * std::size_t(h));
        std::mt19937 random(11);
        for (std::uint32_t& b : bits)
            b = (random() & 0x7f7fffffu) | 0x00800000u; // finite, normal floats
        std::vector<unsigned char> bytes;
        QVERIFY(encodeExr(w, h, {{"Y", bits.data()}}, bytes).isEmpty());
        QVERIFY(bytes.size() >= bits.size() * 4);
        Decoded d = decode(bytes);
        QCOMPARE(d.pixels.size(), bits.size());
        QVERIFY(std::memcmp(d.pixels.data(), bits.data(), bits.size() * 4) == 0);
    }

    void repeatedScanlinesReadBack()
    {
        // Rows in runs of equal ones, compressible (flat) and not (random bits): each run's
        // chunk is compressed once and written for every row of it.
        const int w = 97, h = 24;
        std::vector<std::uint32_t> bits(std::size_t(w) * std::size_t(h));
        std::mt19937 random(5);
        std::vector<std::uint32_t> row(static_cast<std::size_t>(w));
        for (int y = 0; y < h; ++y) {
            if (y % 4 == 0)
                for (std::uint32_t& b : row)
                    b = y % 8 == 0 ? 0x3f000000u : (random() & 0x7f7fffffu) | 0x00800000u;
            std::copy(row.begin(), row.end(), bits.begin() + std::ptrdiff_t(y) * w);
        }
        std::vector<unsigned char> bytes;
        QVERIFY(encodeExr(w, h, {{"Y", bits.data()}}, bytes).isEmpty());
        Decoded d = decode(bytes);
        QCOMPARE(d.pixels.size(), bits.size());
        QVERIFY(std::memcmp(d.pixels.data(), bits.data(), bits.size() * 4) == 0);
    }

    void noLargerThanOpenExrsOwnZip()
    {
        const int w = 960, h = 540;
        const std::vector<float> rgba = renderLike(w, h);
        const std::vector<ExrChannelSource> sources
            = {{"R", rgba.data(), 4, Kind::Float}, {"G", rgba.data() + 1, 4, Kind::Float},
                {"B", rgba.data() + 2, 4, Kind::Float}, {"A", rgba.data() + 3, 4, Kind::Float}};
        std::vector<unsigned char> bytes;
        QVERIFY(encodeExr(w, h, sources, bytes).isEmpty());
        const std::size_t fastest = openExrSize(w, h, {"R", "G", "B", "A"}, rgba, "zips:1");
        const std::size_t standard = openExrSize(w, h, {"R", "G", "B", "A"}, rgba, "zips");
        QVERIFY(fastest > 0 && standard > 0);
        qInfo("EXR of %dx%d RGBA: %zu bytes; OpenEXR's ZIP writer: %zu bytes at zlib's level 1, %zu at its "
              "default",
            w, h, bytes.size(), fastest, standard);
        QVERIFY2(bytes.size() <= fastest, "larger than OpenEXR's ZIP at zlib's level 1");
        QVERIFY2(double(bytes.size()) <= 1.01 * double(standard), "1 % larger than OpenEXR's ZIP at its default");
        // And well below the 8.3 MB of floats.
        QVERIFY(bytes.size() < std::size_t(w) * std::size_t(h) * 16 / 2);
    }

    void sameInputSameBytes()
    {
        const std::vector<float> rgba = renderLike(64, 48);
        const std::vector<ExrChannelSource> sources = {{"R", rgba.data(), 4, Kind::Float}, {"A", rgba.data() + 3, 4}};
        std::vector<unsigned char> a, b;
        QVERIFY(encodeExr(64, 48, sources, a).isEmpty());
        QVERIFY(encodeExr(64, 48, sources, b).isEmpty());
        QVERIFY(a == b); // no time stamp: a frame has the same bytes wherever it is rendered
    }

    void refusesWhatCannotBeWritten()
    {
        const std::vector<float> px(16, 0.5f);
        std::vector<unsigned char> bytes = {1, 2, 3};
        QVERIFY(!encodeExr(0, 4, {{"Y", px.data()}}, bytes).isEmpty());
        QVERIFY(bytes.empty());
        QVERIFY(!encodeExr(4, 4, {}, bytes).isEmpty());
        const QString twice = encodeExr(4, 4, {{"Y", px.data()}, {"Y", px.data()}}, bytes);
        QVERIFY(!twice.isEmpty());
        QVERIFY(!encodeExr(4, 4, {{"", px.data()}}, bytes).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestExrEncoder)
#include "test_exr_encoder.moc"
