// Reference drawing import: raster bytes decoded by OpenImageIO from memory (a temporary file for
// readers without I/O proxy support), SVG rendered by Qt Svg; both end as 8-bit RGBA for display.
#include "celform/model/image_io.h"

#include "celform/model/io_error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QSvgRenderer>
#include <QTemporaryFile>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace celform::model {

namespace {

// Gives lupdate the context "celform::model::ImageIo" for every ImageIo::tr() below.
struct ImageIo {
    Q_DECLARE_TR_FUNCTIONS(celform::model::ImageIo)
};

constexpr int kSvgHeight = 1024;
// Larger than any drawing an artist scans, small enough that the float buffer stays below 2 GB.
constexpr std::int64_t kMaxPixels = std::int64_t(1) << 27;

QString normalisedFormat(const QString& format)
{
    const QString f = format.toLower();
    if (f == QLatin1String("jpeg"))
        return QStringLiteral("jpg");
    if (f == QLatin1String("tiff"))
        return QStringLiteral("tif");
    return f;
}

QImage renderSvg(const QByteArray& data, const QString& fileLabel)
{
    QSvgRenderer renderer(data);
    if (!renderer.isValid())
        throw IoError(fileLabel, ImageIo::tr("not a valid SVG drawing"));
    QSizeF size = renderer.viewBoxF().size();
    if (size.isEmpty())
        size = renderer.defaultSize();
    if (size.isEmpty())
        throw IoError(fileLabel, ImageIo::tr("the SVG drawing has no size"));
    const int width
        = std::clamp(static_cast<int>(std::lround(kSvgHeight * size.width() / size.height())), 1, 16 * kSvgHeight);
    QImage image(width, kSvgHeight, QImage::Format_RGBA8888_Premultiplied);
    if (image.isNull())
        throw IoError(fileLabel, ImageIo::tr("the SVG drawing is too large"));
    image.fill(Qt::transparent);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        renderer.render(&painter, QRectF(0, 0, width, kSvgHeight));
    }
    return image.convertToFormat(QImage::Format_RGBA8888);
}

float linearToSrgb(float v)
{
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
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
        throw IoError(fileLabel, ImageIo::tr("images of type \"%1\" cannot be read").arg(format));
    if (probe->supports("ioproxy")) {
        opened.proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(data.constData(), std::size_t(data.size()));
        opened.input = OIIO::ImageInput::open(nameForPlugin, nullptr, opened.proxy.get());
    } else {
        opened.temporary = std::make_unique<QTemporaryFile>(QStringLiteral("celform_XXXXXX.") + format);
        if (!opened.temporary->open() || opened.temporary->write(data) != data.size() || !opened.temporary->flush())
            throw IoError(fileLabel, ImageIo::tr("a temporary copy of the image cannot be written"));
        opened.input = OIIO::ImageInput::open(QFile::encodeName(opened.temporary->fileName()).toStdString());
    }
    if (!opened.input) {
        QString why = QString::fromStdString(OIIO::geterror()).trimmed().section(QLatin1Char('\n'), 0, 0);
        if (why.size() > 160)
            why = why.left(157) + QStringLiteral("...");
        throw IoError(fileLabel, ImageIo::tr("the image cannot be read: %1").arg(why));
    }
    return opened;
}

QImage decodeRaster(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    OpenedImage opened = openImage(data, format, fileLabel);
    OIIO::ImageInput& in = *opened.input;
    // Subimage 0 is the composite for PSD and the first page of a TIFF.
    const OIIO::ImageSpec spec = in.spec();
    const std::int64_t pixels = std::int64_t(spec.width) * spec.height;
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw IoError(fileLabel, ImageIo::tr("the image has no pixels"));
    if (pixels > kMaxPixels)
        throw IoError(
            fileLabel, ImageIo::tr("the image is too large (%1 x %2 pixels)").arg(spec.width).arg(spec.height));
    const int channels = std::min(spec.nchannels, 4);
    std::vector<float> buffer(static_cast<std::size_t>(pixels) * static_cast<std::size_t>(channels));
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, buffer.data())) {
        QString why = QString::fromStdString(in.geterror()).trimmed().section(QLatin1Char('\n'), 0, 0);
        if (why.size() > 160)
            why = why.left(157) + QStringLiteral("...");
        throw IoError(fileLabel, ImageIo::tr("the image data is damaged or truncated: %1").arg(why));
    }
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
        throw IoError(
            fileLabel, ImageIo::tr("the image is too large (%1 x %2 pixels)").arg(spec.width).arg(spec.height));
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

} // namespace

QImage decodeImage(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    if (data.isEmpty())
        throw IoError(fileLabel, ImageIo::tr("the file is empty"));
    const QString f = normalisedFormat(format);
    if (f == QLatin1String("svg"))
        return renderSvg(data, fileLabel);
    if (!imageSuffixes().contains(f))
        throw IoError(fileLabel, ImageIo::tr("unknown image format \"%1\"").arg(format));
    return decodeRaster(data, f, fileLabel);
}

Drawing importDrawing(const QString& path)
{
    const QFileInfo info(path);
    if (!info.exists())
        throw IoError(path, ImageIo::tr("the file does not exist"));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError(path, ImageIo::tr("the file cannot be opened: %1").arg(file.errorString()));
    Drawing drawing;
    drawing.imageData = file.readAll();
    if (drawing.imageData.size() != file.size())
        throw IoError(path, ImageIo::tr("the file cannot be read: %1").arg(file.errorString()));
    if (drawing.imageData.isEmpty())
        throw IoError(path, ImageIo::tr("the file is empty"));
    drawing.imageFormat = normalisedFormat(info.suffix());
    drawing.image = decodeImage(drawing.imageData, drawing.imageFormat, path);
    drawing.name = info.completeBaseName();
    return drawing;
}

QStringList imageSuffixes()
{
    return {QStringLiteral("png"), QStringLiteral("jpg"), QStringLiteral("jpeg"), QStringLiteral("tif"),
        QStringLiteral("tiff"), QStringLiteral("exr"), QStringLiteral("psd"), QStringLiteral("bmp"),
        QStringLiteral("tga"), QStringLiteral("hdr"), QStringLiteral("webp"), QStringLiteral("gif"),
        QStringLiteral("svg")};
}

QString imageFileFilter()
{
    QStringList patterns;
    for (const QString& s : imageSuffixes())
        patterns << QStringLiteral("*.") + s;
    return ImageIo::tr("Drawings (%1)").arg(patterns.join(QLatin1Char(' ')));
}

} // namespace celform::model
