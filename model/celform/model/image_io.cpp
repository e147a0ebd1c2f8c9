// Reference drawing import: raster bytes decoded by OpenImageIO (through the module of
// raster_codec.h), SVG rendered by Qt Svg; both end as 8-bit RGBA for display.
#include "celform/model/image_io.h"

#include "celform/model/io_error.h"
#include "celform/model/raster_codec.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>
#include <QPainter>
#include <QSvgRenderer>

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
    // its first frame, so GIF is decoded like the rest).
    if (f == QLatin1String("png") || f == QLatin1String("jpg") || f == QLatin1String("bmp")) {
        QByteArray bytes = data; // shared, not copied
        QBuffer buffer(&bytes);
        QImageReader reader(&buffer, f.toLatin1());
        const QSize size = reader.size();
        if (size.isValid() && !size.isEmpty())
            return size;
    }
    return decodeImage(data, format, fileLabel).size();
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
