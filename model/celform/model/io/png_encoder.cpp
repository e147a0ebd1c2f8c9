#include "celform/model/io/png_encoder.h"

#include <QCoreApplication>

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <new>

namespace celform::model {
namespace {

struct PngText {
    Q_DECLARE_TR_FUNCTIONS(celform::model::PngEncoder)
};

/// What libpng's callbacks share with encodePng: the output and the first error's text.
struct Sink {
    std::vector<unsigned char>* out;
    char error[256];
};

void appendBytes(png_structp png, png_bytep data, png_size_t length)
{
    auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
    try {
        sink->out->insert(sink->out->end(), data, data + length);
    } catch (const std::bad_alloc&) {
        png_error(png, "out of memory"); // no C++ exception through libpng's C frames
    }
}

void noFlush(png_structp) { }

[[noreturn]] void onError(png_structp png, png_const_charp message)
{
    auto* sink = static_cast<Sink*>(png_get_error_ptr(png));
    std::strncpy(sink->error, message ? message : "unknown error", sizeof sink->error - 1);
    sink->error[sizeof sink->error - 1] = '\0';
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) { }

/// The libpng calls, in a function of their own that holds no C++ object with a destructor: an
/// error returns through longjmp to the setjmp here. Returns false after an error (in sink.error).
bool writePng(Sink& sink, const unsigned char* pixels, int width, int height, int channels)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, onError, onWarning);
    if (!png) {
        std::strcpy(sink.error, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : nullptr);
        if (!sink.error[0])
            std::strcpy(sink.error, "out of memory");
        return false;
    }
    png_set_write_fn(png, &sink, appendBytes, noFlush);
    const int colorType
        = channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : (channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, colorType, PNG_INTERLACE_NONE,
        PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // One fixed filter (header comment): no per-row filter search. zlib keeps its default level
    // and strategy: its run-length strategy was twice as fast on the dragon but made files 2 to 5
    // times larger on synthetic pictures (test_png_encoder), and lower levels up to 1.7 times.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_write_info(png, info);
    const std::size_t rowBytes = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height; ++y)
        png_write_row(png, pixels + std::size_t(y) * rowBytes);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

} // namespace

QString encodePng(const unsigned char* pixels, int width, int height, int channels, std::vector<unsigned char>& out)
{
    out.clear();
    if (channels != 1 && channels != 3 && channels != 4)
        return PngText::tr("a PNG holds 1, 3 or 4 channels, not %1").arg(channels);
    if (width <= 0 || height <= 0 || !pixels)
        return PngText::tr("the image is empty");
    Sink sink{&out, {}};
    if (!writePng(sink, pixels, width, height, channels)) {
        out.clear();
        return PngText::tr("the PNG encoder failed: %1").arg(QString::fromLocal8Bit(sink.error));
    }
    return {};
}

} // namespace celform::model
