#include "celform/model/io/png_encoder.h"
#include "celform/model/io/run_deflate.h"

#include <QCoreApplication>

#include <libdeflate.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>

namespace celform::model {
namespace {

struct PngText {
    Q_DECLARE_TR_FUNCTIONS(celform::model::PngEncoder)
};

/// libdeflate's level (1-12): 7 was the fastest level whose files were no larger than libpng's at
/// zlib's default level on every picture measured (header comment).
constexpr int kLevel = 7;
/// PNG filter type 2, "Up": each byte less the byte above it (PNG 1.2, section 6.3).
constexpr unsigned char kFilterUp = 2;

void putBigEndian(std::vector<unsigned char>& out, std::uint32_t v)
{
    const unsigned char bytes[4] = {static_cast<unsigned char>(v >> 24), static_cast<unsigned char>(v >> 16),
        static_cast<unsigned char>(v >> 8), static_cast<unsigned char>(v)};
    out.insert(out.end(), bytes, bytes + 4);
}

/// Appends a chunk whose data already sits at the end of out, after the 8 bytes of its length and
/// type (PNG 1.2, section 5.3: length, type, data, CRC-32 of type and data).
void closeChunk(std::vector<unsigned char>& out, std::size_t chunkStart)
{
    const std::size_t dataLength = out.size() - chunkStart - 8;
    const std::uint32_t crc = libdeflate_crc32(0, out.data() + chunkStart + 4, dataLength + 4);
    for (int k = 0; k < 4; ++k)
        out[chunkStart + std::size_t(k)] = static_cast<unsigned char>(std::uint32_t(dataLength) >> (24 - 8 * k));
    putBigEndian(out, crc);
}

std::size_t openChunk(std::vector<unsigned char>& out, const char* type)
{
    const std::size_t start = out.size();
    out.insert(out.end(), 4, 0); // the length, filled in by closeChunk
    out.insert(out.end(), type, type + 4);
    return start;
}

struct CompressorDeleter {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

/// Per thread, the compressor (about 1 MB of tables at this level), the filtered rows and the
/// samples' streams, kept from frame to frame (issue 29: one allocation per sequence).
struct Scratch {
    std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor{libdeflate_alloc_compressor(kLevel)};
    std::vector<unsigned char> filtered;
    std::vector<unsigned char> sample;
};

/// The run coder is taken when its streams of the sample rows are larger than libdeflate's by at
/// most this fraction of the rows' raw bytes (8 KB of a 1920x1080 RGBA frame): flat tones, where
/// both streams are small (dragon frames: toon 0.05 %, Gooch 0.04 %; a synthetic ellipse of two
/// tones 0.03 %), not gradients (a Lambert dragon frame 1.1 %, test_png_encoder's gradient 2 %).
constexpr double kRunExtraOfRaw = 0.001;
/// Pictures of fewer rows go to libdeflate without trying: too few to sample, and quick anyway.
constexpr int kSampledFromRows = 64;

/// Whether the picture's filtered rows are better compressed by the run coder (run_deflate.h):
/// both coders compress four bands of rows, each about 1/64 of the picture, at 1/8, 3/8, 5/8 and
/// 7/8 of its height, and the run coder's streams are at most kRunExtraOfRaw of the bands' bytes
/// larger than libdeflate's.
/// About a sixteenth of libdeflate's work on the whole picture: 1 ms of a dragon frame's 13.
bool runsPay(const unsigned char* filtered, std::size_t stride, int height, int channels, Scratch& scratch)
{
    if (height < kSampledFromRows)
        return false;
    const int rows = height / 64;
    std::size_t runBytes = 0, generalBytes = 0, rawBytes = 0;
    for (int band = 0; band < 4; ++band) {
        const int first = (2 * band + 1) * height / 8 - rows / 2;
        const unsigned char* at = filtered + std::size_t(first) * stride;
        const std::size_t bytes = std::size_t(rows) * stride;
        const std::size_t bound = libdeflate_zlib_compress_bound(scratch.compressor.get(), bytes);
        scratch.sample.resize(bound);
        const std::size_t general
            = libdeflate_zlib_compress(scratch.compressor.get(), at, bytes, scratch.sample.data(), bound);
        if (general == 0)
            return false;
        generalBytes += general;
        rawBytes += bytes;
        scratch.sample.clear();
        if (!deflateRuns(at, bytes, std::size_t(channels), stride, bound, scratch.sample))
            return false;
        runBytes += scratch.sample.size();
    }
    return double(runBytes) <= double(generalBytes) + kRunExtraOfRaw * double(rawBytes);
}

} // namespace

QString encodePng(const unsigned char* pixels, int width, int height, int channels, std::vector<unsigned char>& out)
{
    out.clear();
    if (channels != 1 && channels != 3 && channels != 4)
        return PngText::tr("a PNG holds 1, 3 or 4 channels, not %1").arg(channels);
    // PNG 1.2, section 11.2.2: width and height at most 2^31 - 1; rows are far smaller here.
    if (width <= 0 || height <= 0 || !pixels)
        return PngText::tr("the image is empty");
    thread_local Scratch scratch;
    if (!scratch.compressor)
        return PngText::tr("the PNG encoder failed: out of memory");
    const std::size_t rowBytes = std::size_t(width) * std::size_t(channels);
    const std::size_t filteredBytes = std::size_t(height) * (rowBytes + 1);
    try {
        // The filtered scanlines: a filter byte, then each byte less the one above it (zeros above
        // the first row, so "Up" leaves it as it is).
        scratch.filtered.resize(filteredBytes);
        for (int y = 0; y < height; ++y) {
            unsigned char* row = scratch.filtered.data() + std::size_t(y) * (rowBytes + 1);
            const unsigned char* source = pixels + std::size_t(y) * rowBytes;
            row[0] = kFilterUp;
            if (y == 0) {
                std::memcpy(row + 1, source, rowBytes);
                continue;
            }
            const unsigned char* above = source - rowBytes;
            for (std::size_t i = 0; i < rowBytes; ++i)
                row[1 + i] = static_cast<unsigned char>(source[i] - above[i]);
        }

        static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        const std::size_t bound = libdeflate_zlib_compress_bound(scratch.compressor.get(), filteredBytes);
        out.reserve(8 + 25 + 12 + bound + 12);
        out.insert(out.end(), kSignature, kSignature + 8);

        // IHDR: size, 8 bits a sample, colour type (6 RGBA, 2 RGB, 0 grey), deflate, adaptive
        // filtering (the method; the type is per row), no interlace.
        std::size_t chunk = openChunk(out, "IHDR");
        putBigEndian(out, std::uint32_t(width));
        putBigEndian(out, std::uint32_t(height));
        const unsigned char colourType = channels == 4 ? 6 : (channels == 3 ? 2 : 0);
        const unsigned char header[5] = {8, colourType, 0, 0, 0};
        out.insert(out.end(), header, header + 5);
        closeChunk(out, chunk);

        // One IDAT chunk holding the whole zlib stream.
        chunk = openChunk(out, "IDAT");
        const std::size_t at = out.size();
        const std::size_t stride = rowBytes + 1;
        // Runs: a frame of flat tones by the run coder, about 3 times as fast as libdeflate for
        // files 2 % larger (issue 29, the writer's part of a sequence); others by libdeflate.
        if (!runsPay(scratch.filtered.data(), stride, height, channels, scratch)
            || !deflateRuns(scratch.filtered.data(), filteredBytes, std::size_t(channels), stride, bound, out)) {
            out.resize(at + bound);
            const std::size_t written = libdeflate_zlib_compress(
                scratch.compressor.get(), scratch.filtered.data(), filteredBytes, out.data() + at, bound);
            if (written == 0) {
                out.clear();
                return PngText::tr("the PNG encoder failed: the compressed image does not fit");
            }
            out.resize(at + written);
        }
        if (out.size() - at > 0x7fffffffu) {
            out.clear();
            return PngText::tr("the PNG encoder failed: the compressed image does not fit");
        }
        closeChunk(out, chunk);

        chunk = openChunk(out, "IEND");
        closeChunk(out, chunk);
    } catch (const std::bad_alloc&) {
        out.clear();
        return PngText::tr("the PNG encoder failed: out of memory");
    }
    return {};
}

} // namespace celform::model
