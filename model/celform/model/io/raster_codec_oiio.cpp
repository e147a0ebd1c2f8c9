// The OpenImageIO module (libcelform_oiio.so, see raster_codec.h): raster bytes decoded from
// memory (a temporary file for readers without I/O proxy support) to 8-bit RGBA for display, and
// render passes written as 8-bit TIFF and JPEG files. Loaded by rasterCodec() on first use.
#include "celform/model/io/raster_codec.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>

#include <fcntl.h>
#include <unistd.h>

namespace celform::model {
namespace {

// The contexts of the messages' translations, as before they moved here.
struct ImageIo {
    Q_DECLARE_TR_FUNCTIONS(celform::model::ImageIo)
};

/// A problem that ends a decode or write; the entry functions turn it into their result.
struct Problem {
    QString text;
};

float linearToSrgb(float v)
{
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

/// OpenImageIO's first error line, kept short enough for one line of the command line.
QString shortError(const std::string& error)
{
    QString why = QString::fromStdString(error).trimmed().section(QLatin1Char('\n'), 0, 0);
    if (why.size() > 160)
        why = why.left(157) + QStringLiteral("...");
    return why;
}

/// Opens the bytes through an in-memory proxy, or through a temporary file for readers that
/// cannot use one. The returned proxy/file must outlive the input.
struct OpenedImage {
    std::unique_ptr<OIIO::Filesystem::IOMemReader> proxy;
    std::unique_ptr<QTemporaryFile> temporary;
    std::unique_ptr<OIIO::ImageInput> input;
};

OpenedImage openImage(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    OpenedImage opened;
    // The name only selects the reader and appears in its messages; the bytes come from memory.
    const std::string nameForPlugin
        = (QFileInfo(fileLabel).completeBaseName() + QLatin1Char('.') + format).toStdString();
    // create() with a bare format name only picks the plugin; with a file name it tries to open it.
    auto probe = OIIO::ImageInput::create(format.toStdString());
    if (!probe)
        throw Problem{ImageIo::tr("images of type \"%1\" cannot be read").arg(format)};
    if (probe->supports("ioproxy")) {
        opened.proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(data.constData(), std::size_t(data.size()));
        opened.input = OIIO::ImageInput::open(nameForPlugin, nullptr, opened.proxy.get());
    } else {
        opened.temporary = std::make_unique<QTemporaryFile>(QStringLiteral("celform_XXXXXX.") + format);
        if (!opened.temporary->open() || opened.temporary->write(data) != data.size() || !opened.temporary->flush())
            throw Problem{ImageIo::tr("a temporary copy of the image cannot be written")};
        opened.input = OIIO::ImageInput::open(QFile::encodeName(opened.temporary->fileName()).toStdString());
    }
    if (!opened.input)
        throw Problem{ImageIo::tr("the image cannot be read: %1").arg(shortError(OIIO::geterror()))};
    return opened;
}

QImage decodeRaster(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    OpenedImage opened = openImage(data, format, fileLabel);
    OIIO::ImageInput& in = *opened.input;
    // Subimage 0 is the composite for PSD and the first page of a TIFF.
    const OIIO::ImageSpec spec = in.spec();
    const std::int64_t pixels = std::int64_t(spec.width) * spec.height;
    if (spec.nchannels <= 0)
        throw Problem{ImageIo::tr("the image has no pixels")};
    // The header is all that has been read: refuse before the buffers below are allocated.
    if (const QString problem = imageSizeProblem(spec.width, spec.height, data.size()); !problem.isEmpty())
        throw Problem{problem};
    const int channels = std::min(spec.nchannels, 4);
    std::vector<float> buffer(static_cast<std::size_t>(pixels) * static_cast<std::size_t>(channels));
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, buffer.data()))
        throw Problem{ImageIo::tr("the image data is damaged or truncated: %1").arg(shortError(in.geterror()))};
    // Float and half pixels (EXR, HDR) are scene-linear; integer pixels are already display-encoded.
    const bool linear = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF
        || spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    // With one or two channels the second is alpha; otherwise OIIO says where alpha is.
    int alpha = -1;
    if (channels == 2)
        alpha = 1;
    else if (channels == 4)
        alpha = spec.alpha_channel >= 0 && spec.alpha_channel < 4 ? spec.alpha_channel : 3;

    QImage image(spec.width, spec.height, QImage::Format_RGBA8888);
    if (image.isNull())
        throw Problem{ImageIo::tr("the image is too large (%1 x %2 pixels)").arg(spec.width).arg(spec.height)};
    auto toByte = [](float v) { return static_cast<uchar>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    const float* src = buffer.data();
    for (int y = 0; y < spec.height; ++y) {
        uchar* dst = image.scanLine(y);
        for (int x = 0; x < spec.width; ++x, src += channels, dst += 4) {
            float rgb[3];
            float a = 1.0f;
            if (channels <= 2) {
                rgb[0] = rgb[1] = rgb[2] = src[0];
            } else {
                int c = 0;
                for (int k = 0; k < channels && c < 3; ++k)
                    if (k != alpha)
                        rgb[c++] = src[k];
            }
            if (alpha >= 0)
                a = std::clamp(src[alpha], 0.0f, 1.0f);
            // OIIO hands out associated alpha; QImage::Format_RGBA8888 is straight alpha.
            if (alpha >= 0 && a > 0.0f && a < 1.0f)
                for (float& v : rgb)
                    v /= a;
            for (int k = 0; k < 3; ++k)
                dst[k] = toByte(linear ? linearToSrgb(rgb[k]) : rgb[k]);
            dst[3] = toByte(a);
        }
    }
    return image;
}

/// Libraries under OpenImageIO print their own diagnostics (libpng's "libpng error: ..." line, which
/// comes on top of the error OpenImageIO reports); while decodes run, standard error goes to
/// /dev/null so the one line naming the file is all the user sees. Counted, so overlapping decodes
/// on several threads restore it once, after the last; another thread's output in that time is lost.
class QuietStandardError {
public:
    QuietStandardError()
    {
        const std::lock_guard<std::mutex> lock(s_mutex);
        if (s_depth++ > 0)
            return;
        std::fflush(stderr);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        s_saved = null >= 0 ? ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0) : -1;
        if (s_saved >= 0)
            ::dup2(null, STDERR_FILENO);
        if (null >= 0)
            ::close(null);
    }
    ~QuietStandardError()
    {
        const std::lock_guard<std::mutex> lock(s_mutex);
        if (--s_depth > 0 || s_saved < 0)
            return;
        std::fflush(stderr);
        ::dup2(s_saved, STDERR_FILENO);
        ::close(s_saved);
        s_saved = -1;
    }
    QuietStandardError(const QuietStandardError&) = delete;
    QuietStandardError& operator=(const QuietStandardError&) = delete;

private:
    static inline std::mutex s_mutex;
    static inline int s_depth = 0;
    static inline int s_saved = -1;
};

QImage decode(const QByteArray& data, const QString& format, const QString& fileLabel, QString* problem)
{
    const QuietStandardError quiet;
    try {
        return decodeRaster(data, format, fileLabel);
    } catch (const Problem& p) {
        *problem = p.text;
    } catch (const std::exception& e) {
        *problem = ImageIo::tr("the image cannot be read: %1").arg(QString::fromLocal8Bit(e.what()));
    }
    return {};
}

QString encode(const QString& format, int width, int height, const std::vector<std::string>& channels,
    const unsigned char* pixels, std::vector<unsigned char>* encoded)
{
    OIIO::ImageSpec spec(width, height, int(channels.size()), OIIO::TypeDesc::UINT8);
    spec.channelnames = channels;
    spec.alpha_channel = -1;
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (channels[c] == "A")
            spec.alpha_channel = int(c);
    // The TIFF writer stamps the time of writing unless DateTime is set; an empty one
    // leaves the field out. A frame then has the same bytes whenever and wherever it is rendered
    // (farm nodes are compared by checksum).
    spec.attribute("DateTime", "");
    // The name only picks the writer: with an output proxy nothing is opened on the disk.
    const std::string name = "image." + format.toStdString();
    encoded->clear();
    OIIO::Filesystem::IOVecOutput proxy(*encoded);
    auto out = OIIO::ImageOutput::create(name);
    if (!out)
        return shortError(OIIO::geterror());
    if (!out->supports("ioproxy"))
        return ImageIo::tr("images of type \"%1\" cannot be written").arg(format);
    if (!out->set_ioproxy(&proxy) || !out->open(name, spec))
        return shortError(out->geterror());
    bool ok = out->write_image(OIIO::TypeDesc::UINT8, pixels);
    ok = out->close() && ok;
    if (!ok)
        return shortError(out->geterror());
    return encoded->empty() ? ImageIo::tr("the encoder gave no bytes") : QString();
}

const RasterCodec kCodec{decode, encode};

} // namespace
} // namespace celform::model

extern "C" Q_DECL_EXPORT const celform::model::RasterCodec* celform_raster_codec()
{
    return &celform::model::kCodec;
}
