// Reference drawing import: raster bytes decoded by OpenImageIO (through the module of
// raster_codec.h), SVG rendered by Qt Svg; both end as 8-bit RGBA for display.
#include "celform/model/image_io.h"

#include "celform/model/io_error.h"
#include "celform/model/raster_codec.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QSvgRenderer>
#include <QtEndian>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace celform::model {

namespace {

// Gives lupdate the context "celform::model::ImageIo" for every ImageIo::tr() below.
struct ImageIo {
    Q_DECLARE_TR_FUNCTIONS(celform::model::ImageIo)
};

constexpr int kSvgHeight = 1024;

QString normalisedFormat(const QString& format)
{
    const QString f = format.toLower();
    if (f == QLatin1String("jpeg"))
        return QStringLiteral("jpg");
    if (f == QLatin1String("tiff"))
        return QStringLiteral("tif");
    return f;
}

/// The pixel size an SVG drawing is rendered at: kSvgHeight high, its view box's aspect.
QSize svgSize(const QSvgRenderer& renderer, const QString& fileLabel)
{
    if (!renderer.isValid())
        throw IoError(fileLabel, ImageIo::tr("not a valid SVG drawing"));
    QSizeF size = renderer.viewBoxF().size();
    if (size.isEmpty())
        size = renderer.defaultSize();
    if (size.isEmpty())
        throw IoError(fileLabel, ImageIo::tr("the SVG drawing has no size"));
    return {std::clamp(static_cast<int>(std::lround(kSvgHeight * size.width() / size.height())), 1, 16 * kSvgHeight),
        kSvgHeight};
}

quint32 bigEndian32(const uchar* p)
{
    return quint32(p[0]) << 24 | quint32(p[1]) << 16 | quint32(p[2]) << 8 | p[3];
}

/// Width and height from a PNG's IHDR, a JPEG's frame header or a BMP's info header, read here
/// rather than by Qt's readers (which print libpng's and libjpeg's complaints about a damaged file
/// on standard error) or OpenImageIO (which needs loading). Nothing for other formats or a header
/// that cannot be read: the decoder then judges the file.
std::optional<QSize> headerSize(const QByteArray& data, const QString& format)
{
    const auto* p = reinterpret_cast<const uchar*>(data.constData());
    const qsizetype n = data.size();
    auto inRange = [](quint32 w, quint32 h) {
        return w <= quint32(std::numeric_limits<int>::max()) && h <= quint32(std::numeric_limits<int>::max());
    };
    if (format == QLatin1String("png")) {
        // Signature (8), then the IHDR chunk: length, "IHDR", width, height (big-endian).
        if (n < 24 || std::memcmp(p, "\x89PNG\r\n\x1a\n", 8) != 0 || std::memcmp(p + 12, "IHDR", 4) != 0)
            return std::nullopt;
        const quint32 w = bigEndian32(p + 16), h = bigEndian32(p + 20);
        return inRange(w, h) ? std::optional<QSize>(QSize(int(w), int(h))) : std::nullopt;
    }
    if (format == QLatin1String("jpg")) {
        // Markers from SOI to the first frame header (SOF0-SOF15 but DHT, JPG and DAC).
        if (n < 4 || p[0] != 0xff || p[1] != 0xd8)
            return std::nullopt;
        qsizetype i = 2;
        while (i + 4 <= n) {
            if (p[i] != 0xff)
                return std::nullopt;
            const uchar marker = p[i + 1];
            if (marker == 0xff) { // fill byte
                ++i;
                continue;
            }
            if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) { // no length
                i += 2;
                continue;
            }
            if (marker == 0xd9 || marker == 0xda) // end of image or start of scan: no frame header
                return std::nullopt;
            const qsizetype length = qsizetype(p[i + 2]) << 8 | p[i + 3];
            if (length < 2)
                return std::nullopt;
            if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
                // length, precision, height, width
                if (i + 9 > n)
                    return std::nullopt;
                return QSize(int(p[i + 7]) << 8 | p[i + 8], int(p[i + 5]) << 8 | p[i + 6]);
            }
            i += 2 + length;
        }
        return std::nullopt;
    }
    if (format == QLatin1String("bmp")) {
        // "BM", then at 14 the info header's size: 12 for OS/2's (16-bit sizes), else 32-bit sizes
        // (a negative height is a top-down image).
        if (n < 26 || p[0] != 'B' || p[1] != 'M')
            return std::nullopt;
        const auto infoSize = qFromLittleEndian<quint32>(p + 14);
        if (infoSize == 12)
            return QSize(qFromLittleEndian<quint16>(p + 18), qFromLittleEndian<quint16>(p + 20));
        const auto w = qint64(qFromLittleEndian<qint32>(p + 18)), h = qint64(qFromLittleEndian<qint32>(p + 22));
        if (w < 0 || !inRange(quint32(w), quint32(std::abs(h))))
            return std::nullopt;
        return QSize(int(w), int(std::abs(h)));
    }
    return std::nullopt;
}

/// Whether a PNG's chunks end before its IEND chunk does. OpenImageIO's PNG reader leaks its error
/// message on every read past the end of the data (the message lives in a std::string across
/// libpng's longjmp: fixed upstream in OpenImageIO PR #5289, not in Debian's 2.4), so a truncated
/// file is refused here, with a clearer message, before the decoder reads it.
bool pngIsTruncated(const QByteArray& data)
{
    const auto* p = reinterpret_cast<const uchar*>(data.constData());
    const qsizetype n = data.size();
    if (n < 8 || std::memcmp(p, "\x89PNG\r\n\x1a\n", 8) != 0)
        return false; // not a PNG: the decoder says so
    qsizetype at = 8;
    while (n - at >= 8) {
        const quint32 length = bigEndian32(p + at);
        if (length > 0x7fffffffu) // beyond the format's limit: libpng refuses it without reading on
            return false;
        if (n - at - 12 < qsizetype(length)) // length, type, data and CRC
            return true;
        if (std::memcmp(p + at + 4, "IEND", 4) == 0)
            return false;
        at += 12 + qsizetype(length);
    }
    return true;
}

QImage renderSvg(const QByteArray& data, const QString& fileLabel)
{
    QSvgRenderer renderer(data);
    const int width = svgSize(renderer, fileLabel).width();
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
    // The header first: a bomb is refused before OpenImageIO is even loaded. The module checks the
    // header of every other format the same way before it decodes.
    if (const auto size = headerSize(data, f)) {
        if (const QString problem = imageSizeProblem(size->width(), size->height(), data.size()); !problem.isEmpty())
            throw IoError(fileLabel, problem);
    }
    if (f == QLatin1String("png") && pngIsTruncated(data))
        throw IoError(fileLabel, ImageIo::tr("the PNG file is truncated (it ends before its last chunk)"));
    QString problem;
    QImage image = rasterCodec(fileLabel).decode(data, f, fileLabel, &problem);
    if (image.isNull())
        throw IoError(fileLabel, problem);
    return image;
}

QSize decodedImageSize(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    if (data.isEmpty())
        throw IoError(fileLabel, ImageIo::tr("the file is empty"));
    const QString f = normalisedFormat(format);
    if (f == QLatin1String("svg"))
        return svgSize(QSvgRenderer(data), fileLabel);
    // Formats whose header states the size OpenImageIO decodes (a GIF's screen may be larger than
    // its first frame, so GIF is decoded like the rest). A size decodeImage() would refuse is
    // refused here too, so `celform info` fails where opening the project would.
    if (const auto size = headerSize(data, f); size && !size->isEmpty()) {
        if (const QString problem = imageSizeProblem(size->width(), size->height(), data.size()); !problem.isEmpty())
            throw IoError(fileLabel, problem);
        return *size;
    }
    return decodeImage(data, format, fileLabel).size();
}

Drawing importDrawing(const QString& path)
{
    const QFileInfo info(path);
    if (!info.exists())
        throw IoError(path, ImageIo::tr("the file does not exist"));
    // Before open(): opening a named pipe blocks until something writes to it, for ever.
    if (!info.isFile())
        throw IoError(path, ImageIo::tr("the file is not a regular file (a folder, pipe or device)"));
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
