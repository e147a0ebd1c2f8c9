#include "celform/model/io/png_encoder.h"

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

/// Per thread, the compressor (about 1 MB of tables at this level) and the filtered rows, kept
/// from frame to frame (issue 29: one allocation per sequence).
struct Scratch {
    std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor{libdeflate_alloc_compressor(kLevel)};
    std::vector<unsigned char> filtered;
};

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
        out.resize(at + bound);
        const std::size_t written = libdeflate_zlib_compress(
            scratch.compressor.get(), scratch.filtered.data(), filteredBytes, out.data() + at, bound);
        if (written == 0 || written > 0x7fffffffu) {
            out.clear();
            return PngText::tr("the PNG encoder failed: the compressed image does not fit");
        }
        out.resize(at + written);
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
