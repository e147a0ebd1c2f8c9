#include "celform/model/io/exr_encoder.h"

#include <QCoreApplication>

#include <libdeflate.h>
#include <openexr.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace celform::model {
namespace {

struct ExrText {
    Q_DECLARE_TR_FUNCTIONS(celform::model::ExrEncoder)
};

/// libdeflate's level (1-12) for the chunks. On an every-pass dragon frame (95 MB, 1080 single
/// scanlines), levels 2 to 4 took 136-139 ms and made 8.50 MB, level 6 153 ms and 8.38 MB, level
/// 8 281 ms and 8.41 MB, level 1 (a separate method) 202 ms; zlib at its level 1, as OpenEXR
/// compressed Celform's frames before, 195 ms and 8.78 MB. Level 2 was the fastest in each run.
constexpr int kLevel = 2;

static_assert(sizeof(float) == 4 && sizeof(std::int32_t) == 4, "EXR float and int samples are 4 bytes");

struct CompressorDeleter {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

/// Per thread, the compressor and one scanline's buffers, kept from frame to frame (issue 29: one
/// allocation per sequence).
struct Scratch {
    std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor{libdeflate_alloc_compressor(kLevel)};
    std::vector<unsigned char> line; ///< the scanline as the file holds it uncompressed
    std::vector<unsigned char> above; ///< the scanline before it, the same way
    std::vector<unsigned char> split; ///< its even bytes, then its odd ones
    std::vector<unsigned char> predicted; ///< each byte of split less the one before it
    std::vector<unsigned char> compressed;
};

/// Where OpenEXRCore's writes and messages go.
struct Sink {
    std::vector<unsigned char>* out = nullptr;
    std::string error;
};

int64_t writeToMemory(exr_const_context_t, void* userData, const void* buffer, uint64_t size, uint64_t offset,
    exr_stream_error_func_ptr_t)
{
    std::vector<unsigned char>& out = *static_cast<Sink*>(userData)->out;
    if (offset + size > out.size())
        out.resize(std::size_t(offset + size));
    std::memcpy(out.data() + offset, buffer, std::size_t(size));
    return int64_t(size);
}

/// The sink of the encode running on this thread: OpenEXRCore calls the error handler with its
/// context locked, so the handler cannot ask the context for its user data.
thread_local Sink* t_sink = nullptr;

void keepError(exr_const_context_t, exr_result_t, const char* message)
{
    if (t_sink && t_sink->error.empty())
        t_sink->error = message;
}

/// One channel's samples of row y, as floats, into row (width floats, unaligned: memcpy).
void fillRow(const ExrChannelSource& source, int width, int y, unsigned char* row)
{
    const std::size_t stride = source.stride;
    const std::size_t start = std::size_t(y) * std::size_t(width) * stride;
    switch (source.kind) {
    case ExrChannelSource::Kind::Float: {
        const float* in = static_cast<const float*>(source.first) + start;
        if (stride == 1) {
            std::memcpy(row, in, std::size_t(width) * 4);
            return;
        }
        for (int x = 0; x < width; ++x, row += 4)
            std::memcpy(row, in + std::size_t(x) * stride, 4);
        return;
    }
    case ExrChannelSource::Kind::FiniteFloat: {
        const float* in = static_cast<const float*>(source.first) + start;
        for (int x = 0; x < width; ++x, row += 4) {
            const float v = in[std::size_t(x) * stride];
            const float kept = std::isfinite(v) ? v : 0.f;
            std::memcpy(row, &kept, 4);
        }
        return;
    }
    case ExrChannelSource::Kind::Int32: {
        const std::int32_t* in = static_cast<const std::int32_t*>(source.first) + start;
        for (int x = 0; x < width; ++x, row += 4) {
            const float v = float(in[std::size_t(x) * stride]);
            std::memcpy(row, &v, 4);
        }
        return;
    }
    }
}

/// OpenEXR's ZIP preparation of a block of n bytes (ImfZip.cpp, and the file layout's "ZIP
/// compression"): the even bytes then the odd ones into split, then each byte of that less the
/// one before it, plus 128, into predicted (the first byte as it is).
void prepareZipBlock(const unsigned char* in, std::size_t n, unsigned char* split, unsigned char* predicted)
{
    unsigned char* even = split;
    unsigned char* odd = split + (n + 1) / 2;
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128i lowBytes = _mm_set1_epi16(0x00ff);
    for (; i + 32 <= n; i += 32) {
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i + 16));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(even + i / 2),
            _mm_packus_epi16(_mm_and_si128(a, lowBytes), _mm_and_si128(b, lowBytes)));
        _mm_storeu_si128(
            reinterpret_cast<__m128i*>(odd + i / 2), _mm_packus_epi16(_mm_srli_epi16(a, 8), _mm_srli_epi16(b, 8)));
    }
#endif
    for (; i < n; ++i)
        (i % 2 == 0 ? even : odd)[i / 2] = in[i];
    if (n == 0)
        return;
    predicted[0] = split[0];
    std::size_t k = 1;
#if defined(__SSE2__)
    const __m128i half = _mm_set1_epi8(char(0x80));
    for (; k + 16 <= n; k += 16) {
        const __m128i now = _mm_loadu_si128(reinterpret_cast<const __m128i*>(split + k));
        const __m128i before = _mm_loadu_si128(reinterpret_cast<const __m128i*>(split + k - 1));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(predicted + k), _mm_add_epi8(_mm_sub_epi8(now, before), half));
    }
#endif
    for (; k < n; ++k)
        predicted[k] = static_cast<unsigned char>(int(split[k]) - int(split[k - 1]) + 128);
}

/// Closes the context on every path out.
struct ContextCloser {
    exr_context_t context = nullptr;
    ~ContextCloser()
    {
        if (context)
            exr_finish(&context);
    }
};

} // namespace

QString encodeExr(int width, int height, const std::vector<ExrChannelSource>& channels, std::vector<unsigned char>& out)
{
    out.clear();
    if (width <= 0 || height <= 0 || channels.empty())
        return ExrText::tr("an image of %1 x %2 pixels and %3 channels cannot be written")
            .arg(width)
            .arg(height)
            .arg(channels.size());
    thread_local Scratch scratch;
    if (!scratch.compressor)
        return ExrText::tr("out of memory");

    Sink sink;
    sink.out = &out;
    t_sink = &sink;
    struct Forget {
        ~Forget() { t_sink = nullptr; }
    } forget;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &sink;
    init.write_fn = writeToMemory;
    init.error_handler_fn = keepError;
    ContextCloser closer;
    const auto failed = [&](exr_result_t result) {
        return sink.error.empty() ? QString::fromUtf8(exr_get_error_code_as_string(result))
                                  : QString::fromStdString(sink.error);
    };
    // The name is only for OpenEXRCore's messages: with a write function nothing is opened.
    exr_result_t result = exr_start_write(&closer.context, "frame.exr", EXR_WRITE_FILE_DIRECTLY, &init);
    int part = 0;
    if (result == EXR_ERR_SUCCESS)
        result = exr_add_part(closer.context, nullptr, EXR_STORAGE_SCANLINE, &part);
    if (result == EXR_ERR_SUCCESS)
        result = exr_initialize_required_attr_simple(closer.context, part, width, height, EXR_COMPRESSION_ZIPS);
    for (const ExrChannelSource& c : channels)
        if (result == EXR_ERR_SUCCESS)
            result = exr_add_channel(
                closer.context, part, c.name.c_str(), EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    const exr_attr_chlist_t* list = nullptr;
    if (result == EXR_ERR_SUCCESS)
        result = exr_get_channels(closer.context, part, &list);
    if (result == EXR_ERR_SUCCESS)
        result = exr_write_header(closer.context);
    if (result != EXR_ERR_SUCCESS)
        return failed(result);

    // The file holds the channels sorted by name: the sources in that order.
    std::vector<const ExrChannelSource*> order;
    order.reserve(channels.size());
    for (int k = 0; k < list->num_channels; ++k) {
        const char* name = list->entries[k].name.str;
        const auto found = std::find_if(
            channels.begin(), channels.end(), [name](const ExrChannelSource& c) { return c.name == name; });
        if (found == channels.end())
            return ExrText::tr("channel %1 is not among those given").arg(QString::fromUtf8(name));
        order.push_back(&*found);
    }
    if (order.size() != channels.size())
        return ExrText::tr("two channels have the same name");

    const std::size_t lineBytes = std::size_t(width) * order.size() * 4;
    const std::size_t bound = libdeflate_zlib_compress_bound(scratch.compressor.get(), lineBytes);
    scratch.line.resize(lineBytes);
    scratch.above.resize(lineBytes);
    scratch.split.resize(lineBytes);
    scratch.predicted.resize(lineBytes);
    scratch.compressed.resize(bound);
    std::size_t packed = 0;
    for (int y = 0; y < height; ++y) {
        unsigned char* row = scratch.line.data();
        for (const ExrChannelSource* source : order) {
            fillRow(*source, width, y, row);
            row += std::size_t(width) * 4;
        }
        // A scanline the same as the one above it (a background's rows above and below the
        // model) is the same chunk: compressed once. Deflating the 381 such rows of the dragon
        // frame took 33 ms of the 136; comparing them reads their 35 MB once (a row that differs
        // stops at its first difference, most often in its first channel).
        if (y == 0 || std::memcmp(scratch.line.data(), scratch.above.data(), lineBytes) != 0) {
            prepareZipBlock(scratch.line.data(), lineBytes, scratch.split.data(), scratch.predicted.data());
            packed = libdeflate_zlib_compress(
                scratch.compressor.get(), scratch.predicted.data(), lineBytes, scratch.compressed.data(), bound);
        }
        // A block whose compressed form is not smaller is stored as it is (the reader tells by
        // its size).
        const bool keep = packed > 0 && packed < lineBytes;
        result = exr_write_scanline_chunk(
            closer.context, part, y, keep ? scratch.compressed.data() : scratch.line.data(), keep ? packed : lineBytes);
        if (result != EXR_ERR_SUCCESS)
            return failed(result);
        std::swap(scratch.line, scratch.above);
    }
    // Writes the chunk offset table.
    result = exr_finish(&closer.context);
    closer.context = nullptr;
    if (result != EXR_ERR_SUCCESS)
        return failed(result);
    return {};
}

} // namespace celform::model
