// Reference drawing import: raster bytes decoded by OpenImageIO (through the module of
// raster_codec.h), SVG rendered by Qt Svg; both end as 8-bit RGBA for display.
#include "celform/model/io/image_io.h"

#include "celform/model/data/io_error.h"
#include "celform/model/io/raster_codec.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QGuiApplication>
#include <QPainter>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTemporaryDir>
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

/// A JPEG marker segment: its marker, where it starts and where the next one starts. Marker 0 when
/// the bytes end (at + 4 > the size) or hold no marker at `at`.
struct JpegSegment {
    uchar marker = 0;
    qsizetype at = 0;
    qsizetype next = 0;
};

/// The next segment from offset i (after SOI), past fill bytes and the markers without a length;
/// the end of image (0xd9) has none either, and is returned.
JpegSegment nextJpegSegment(const uchar* p, qsizetype n, qsizetype i)
{
    while (i + 4 <= n) {
        if (p[i] != 0xff)
            return {0, i, i};
        const uchar marker = p[i + 1];
        if (marker == 0xff) { // fill byte
            ++i;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) { // no length
            i += 2;
            continue;
        }
        if (marker == 0xd9)
            return {marker, i, i + 2};
        return {marker, i, i + 2 + (qsizetype(p[i + 2]) << 8 | p[i + 3])};
    }
    return {0, i, i};
}

/// Width and height from a PNG's IHDR, a JPEG's frame header, a BMP's info header or a PSD's, read here
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
        for (JpegSegment s = nextJpegSegment(p, n, 2); s.marker != 0 && s.marker != 0xd9 && s.marker != 0xda;
             s = nextJpegSegment(p, n, s.next)) { // up to the end of image or the start of scan: no frame header
            if (s.next < s.at + 4) // a length below 2
                return std::nullopt;
            if (s.marker >= 0xc0 && s.marker <= 0xcf && s.marker != 0xc4 && s.marker != 0xc8 && s.marker != 0xcc) {
                // length, precision, height, width
                if (s.at + 9 > n)
                    return std::nullopt;
                return QSize(int(p[s.at + 7]) << 8 | p[s.at + 8], int(p[s.at + 5]) << 8 | p[s.at + 6]);
            }
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
    if (format == QLatin1String("psd")) {
        // "8BPS", version, 6 reserved bytes, channels, then height and width (big-endian): the
        // composite's size, which is what is decoded. Read here, `celform info` starts no child.
        if (n < 26 || std::memcmp(p, "8BPS", 4) != 0)
            return std::nullopt;
        const quint32 h = bigEndian32(p + 14), w = bigEndian32(p + 18);
        return inRange(w, h) ? std::optional<QSize>(QSize(int(w), int(h))) : std::nullopt;
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

/// Whether a JPEG ends before its end-of-image marker (libjpeg only warns, and fills the rest
/// grey). The markers are walked to the first scan; in the entropy-coded data after it a 0xff byte
/// is always followed by 0x00 or a marker, so "ff d9" there is the end of the image (a thumbnail's
/// own end marker sits in an APP1 segment, before the first scan).
bool jpegIsTruncated(const QByteArray& data)
{
    const auto* p = reinterpret_cast<const uchar*>(data.constData());
    const qsizetype n = data.size();
    if (n < 4 || p[0] != 0xff || p[1] != 0xd8)
        return false; // not a JPEG: the decoder says so
    JpegSegment s = nextJpegSegment(p, n, 2);
    while (s.marker != 0 && s.marker != 0xd9 && s.marker != 0xda)
        s = nextJpegSegment(p, n, s.next);
    if (s.marker == 0xda)
        return s.next >= n || data.indexOf(QByteArrayView("\xff\xd9", 2), s.next) < 0;
    // The end of image, or a byte that is no marker (damaged, not short: the decoder says so), or the
    // end of the bytes among the headers.
    return s.marker == 0 && s.at + 4 > n;
}

/// Whether a JPEG has an APP1, APP2 or APP13 segment before its first scan whose data holds no
/// zero byte. Those segments start with a zero-terminated name ("Exif", the XMP and ICC names,
/// "Photoshop 3.0"), and OpenImageIO 2.4's JPEG reader compares that name with strcmp, reading
/// past the end of a segment that has none (a heap over-read, found by fuzz_jpg). Such a segment
/// is malformed: the file is refused here, before the reader runs.
bool jpegHasUnterminatedAppName(const QByteArray& data)
{
    const auto* p = reinterpret_cast<const uchar*>(data.constData());
    const qsizetype n = data.size();
    if (n < 4 || p[0] != 0xff || p[1] != 0xd8)
        return false; // not a JPEG: the decoder says so
    qsizetype i = 2;
    for (;;) {
        JpegSegment s = nextJpegSegment(p, n, i);
        if (s.marker == 0 && i + 4 <= n) {
            // Not a marker here: libjpeg skips such bytes to the next 0xff that starts a marker
            // and reads on, so the walk does too.
            qsizetype j = i + 1;
            while (j + 1 < n && !(p[j] == 0xff && p[j + 1] != 0x00 && p[j + 1] != 0xff))
                ++j;
            if (j + 1 >= n)
                return false;
            i = j;
            continue;
        }
        if (s.marker == 0 || s.marker == 0xd9 || s.marker == 0xda)
            return false;
        i = s.next;
        if (s.marker != 0xe1 && s.marker != 0xe2 && s.marker != 0xed)
            continue;
        const qsizetype begin = s.at + 4, end = std::min(s.next, n); // the data, after the length
        if (begin >= end || std::memchr(p + begin, 0, std::size_t(end - begin)) == nullptr)
            return true;
    }
    return false;
}

/// Why a PSD's sections cannot be what their lengths say, or nothing. After the 26-byte header come
/// the colour mode data, the image resources and the layer and mask information, each behind a
/// big-endian 32-bit length. OpenImageIO's PSD reader allocates each section as stated before it
/// reads it: a 207-byte file stating 4.2 GB of colour mode data (found by fuzz_psd) cost 4.2 GB,
/// contained only by the import child's memory limit. A length beyond the end of the file is
/// refused here, before any decoder runs.
QString psdSectionProblem(const QByteArray& data)
{
    const auto* p = reinterpret_cast<const uchar*>(data.constData());
    const qsizetype n = data.size();
    if (n < 26 || std::memcmp(p, "8BPS", 4) != 0)
        return {}; // not a PSD: the decoder says so
    const char* const names[] = {QT_TRANSLATE_NOOP("celform::model::ImageIo", "colour mode data"),
        QT_TRANSLATE_NOOP("celform::model::ImageIo", "image resources"),
        QT_TRANSLATE_NOOP("celform::model::ImageIo", "layer and mask information")};
    qsizetype at = 26;
    for (const char* name : names) {
        if (n - at < 4)
            return ImageIo::tr("the PSD file is truncated (it ends before its %1)").arg(ImageIo::tr(name));
        const quint32 length = bigEndian32(p + at);
        at += 4;
        if (qint64(length) > qint64(n - at))
            return ImageIo::tr("the PSD file states %1 bytes of %2, but holds %3 bytes after that point")
                .arg(length)
                .arg(ImageIo::tr(name))
                .arg(n - at);
        at += qsizetype(length);
    }
    return {};
}

/// Whether an SVG drawing draws text (text, textArea, an SVG font), which needs the fonts of a
/// QGuiApplication: without one, Qt's font database aborts the process (issue 27).
bool svgNeedsFonts(const QByteArray& data)
{
    static const QRegularExpression element(QStringLiteral("<([A-Za-z_][\\w.-]*:)?(text|textArea|font|font-face)\\b"));
    return element.match(QString::fromUtf8(data)).hasMatch();
}

/// Whether this process has the fonts text needs: a QGuiApplication (the editor's, or the import
/// child's on the offscreen platform).
bool hasFonts()
{
    return qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr;
}

/// Whether a format's decoder runs in a child process: OpenImageIO's own parsers (PSD, TGA, HDR, BMP)
/// and the libraries behind TIFF, EXR, WebP and GIF are not ours to fix. PNG and JPEG stay here: the
/// most exercised decoders there are (libpng, libjpeg-turbo), and headerSize() checks their headers
/// before they decode. SVG is Qt's, drawn here unless it has text and this process no fonts (the
/// command line): the child `celform import-image` then draws it on the offscreen platform.
bool decodedInChild(const QString& format, const QByteArray& data)
{
    if (format == QLatin1String("svg"))
        return !hasFonts() && svgNeedsFonts(data);
    return format != QLatin1String("png") && format != QLatin1String("jpg");
}

// The pixels a child hands back, a file per image: this magic, width and height (native 32-bit),
// then RGBA8888 rows.
constexpr char kTransferMagic[8] = {'C', 'E', 'L', 'F', 'R', 'G', 'B', 'A'};
constexpr qint64 kTransferHeader = sizeof kTransferMagic + 2 * sizeof(qint32);

QString transferName(const QString& inputName)
{
    return QFileInfo(inputName).completeBaseName() + QStringLiteral(".pixels");
}

void writeTransfer(const QImage& decoded, const QString& path)
{
    const QImage image = decoded.convertToFormat(QImage::Format_RGBA8888);
    QFile out(path);
    const qint32 size[2] = {image.width(), image.height()};
    bool written = out.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && out.write(kTransferMagic, sizeof kTransferMagic) == qint64(sizeof kTransferMagic)
        && out.write(reinterpret_cast<const char*>(size), sizeof size) == qint64(sizeof size);
    const qint64 rowBytes = qint64(image.width()) * 4;
    for (int y = 0; written && y < image.height(); ++y)
        written = out.write(reinterpret_cast<const char*>(image.constScanLine(y)), rowBytes) == rowBytes;
    if (!written || !out.flush())
        throw IoError(path, ImageIo::tr("the file cannot be written: %1").arg(out.errorString()));
}

QImage readTransfer(const QString& path, const EncodedImage& source)
{
    QFile file(path);
    char magic[sizeof kTransferMagic] = {};
    qint32 size[2] = {};
    if (!file.open(QIODevice::ReadOnly) || file.read(magic, sizeof magic) != qint64(sizeof magic)
        || file.read(reinterpret_cast<char*>(size), sizeof size) != qint64(sizeof size)
        || std::memcmp(magic, kTransferMagic, sizeof magic) != 0)
        throw IoError(source.label, ImageIo::tr("the importer's result is damaged"));
    // The child checked the size before decoding; its answer is checked again before allocating.
    if (!imageSizeProblem(size[0], size[1], source.data.size()).isEmpty()
        || file.size() != kTransferHeader + qint64(size[0]) * size[1] * 4)
        throw IoError(source.label, ImageIo::tr("the importer's result is damaged"));
    QImage image(size[0], size[1], QImage::Format_RGBA8888);
    if (image.isNull())
        throw IoError(source.label, ImageIo::tr("the image is too large (%1 x %2 pixels)").arg(size[0]).arg(size[1]));
    const qint64 rowBytes = qint64(size[0]) * 4;
    for (int y = 0; y < image.height(); ++y)
        if (file.read(reinterpret_cast<char*>(image.scanLine(y)), rowBytes) != rowBytes)
            throw IoError(source.label, ImageIo::tr("the importer's result is damaged"));
    return image;
}

/// Decodes the images (formats normalised and checked) in one child process: `celform
/// import-image IN OUT` decodes each file of the folder IN into OUT. When that fails, each image
/// is decoded in a child of its own, so that the error names the image that fails.
std::vector<QImage> decodeInChild(const std::vector<EncodedImage>& images)
{
    if (images.empty())
        return {};
    const QTemporaryDir folder;
    const QString in = folder.filePath(QStringLiteral("in")), out = folder.filePath(QStringLiteral("out"));
    if (!folder.isValid() || !QDir(folder.path()).mkdir(QStringLiteral("in"))
        || !QDir(folder.path()).mkdir(QStringLiteral("out")))
        throw IoError(images.front().label,
            ImageIo::tr("a temporary folder for the importer cannot be made: %1").arg(folder.errorString()));
    QStringList inputs;
    for (std::size_t i = 0; i < images.size(); ++i) {
        inputs << QDir(in).filePath(QString::number(i) + QLatin1Char('.') + images[i].format);
        QFile file(inputs.constLast());
        if (!file.open(QIODevice::WriteOnly) || file.write(images[i].data) != images[i].data.size() || !file.flush())
            throw IoError(images[i].label, ImageIo::tr("a temporary copy of the image cannot be written"));
    }
    try {
        // "--": a folder name starting with a dash is not an option.
        runImportChild(
            {QStringLiteral("import-image"), QStringLiteral("--"), in, out}, images.front().label, int(images.size()));
    } catch (const IoError&) {
        if (images.size() == 1)
            throw;
        std::vector<QImage> decoded;
        for (const EncodedImage& image : images)
            decoded.push_back(decodeInChild({image}).front());
        return decoded;
    }
    std::vector<QImage> decoded;
    for (std::size_t i = 0; i < images.size(); ++i)
        decoded.push_back(readTransfer(QDir(out).filePath(transferName(inputs[int(i)])), images[i]));
    return decoded;
}

QImage renderSvg(const QByteArray& data, const QString& fileLabel)
{
    if (svgNeedsFonts(data)) {
        if (!hasFonts())
            throw IoError(fileLabel, ImageIo::tr("the SVG drawing has text, which cannot be drawn without fonts here"));
        if (QFontDatabase::families().isEmpty())
            throw IoError(fileLabel,
                ImageIo::tr("the SVG drawing has text and no fonts are installed (fontconfig finds none; install "
                            "fonts-dejavu-core)"));
    }
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

/// The checks decodeImage() makes before any decoder runs (an empty file, an unknown format, a header
/// stating too many pixels). Returns the normalised format.
QString checkedFormat(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    if (data.isEmpty())
        throw IoError(fileLabel, ImageIo::tr("the file is empty"));
    const QString f = normalisedFormat(format);
    if (f == QLatin1String("svg"))
        return f;
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
    if (f == QLatin1String("jpg") && jpegIsTruncated(data))
        throw IoError(fileLabel, ImageIo::tr("the JPEG file is truncated (it ends before its end-of-image marker)"));
    if (f == QLatin1String("jpg") && jpegHasUnterminatedAppName(data))
        throw IoError(fileLabel,
            ImageIo::tr("the JPEG file has a damaged metadata segment (APP1, APP2 or APP13 without its name)"));
    if (f == QLatin1String("psd"))
        if (const QString problem = psdSectionProblem(data); !problem.isEmpty())
            throw IoError(fileLabel, problem);
    return f;
}

/// Decodes checked bytes in this process.
QImage decodeHere(const QByteArray& data, const QString& format, const QString& fileLabel)
{
    if (format == QLatin1String("svg"))
        return renderSvg(data, fileLabel);
    QString problem;
    QImage image = rasterCodec(fileLabel).decode(data, format, fileLabel, &problem);
    if (image.isNull())
        throw IoError(fileLabel, problem);
    return image;
}

} // namespace

QImage decodeImage(const QByteArray& data, const QString& format, const QString& fileLabel, ImportIsolation isolation)
{
    const QString f = checkedFormat(data, format, fileLabel);
    if (isolation == ImportIsolation::ChildProcess && decodedInChild(f, data))
        return decodeInChild({{data, f, fileLabel}}).front();
    return decodeHere(data, f, fileLabel);
}

std::vector<QImage> decodeImages(const std::vector<EncodedImage>& images)
{
    std::vector<EncodedImage> checked;
    for (const EncodedImage& image : images)
        checked.push_back({image.data, checkedFormat(image.data, image.format, image.label), image.label});
    std::vector<EncodedImage> forChild;
    for (const EncodedImage& image : checked)
        if (decodedInChild(image.format, image.data))
            forChild.push_back(image);
    const std::vector<QImage> fromChild = decodeInChild(forChild);
    std::vector<QImage> decoded;
    auto next = fromChild.cbegin();
    for (const EncodedImage& image : checked)
        decoded.push_back(
            decodedInChild(image.format, image.data) ? *next++ : decodeHere(image.data, image.format, image.label));
    return decoded;
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

void decodeImagesForParent(const QString& inFolder, const QString& outFolder)
{
    for (const QFileInfo& input : QDir(inFolder).entryInfoList(QDir::Files, QDir::Name)) {
        QFile file(input.filePath());
        if (!file.open(QIODevice::ReadOnly))
            throw IoError(inFolder, ImageIo::tr("the file cannot be opened: %1").arg(file.errorString()));
        QImage image;
        try {
            image = decodeImage(file.readAll(), input.suffix(), input.filePath(), ImportIsolation::ThisProcess);
        } catch (const IoError& e) {
            throw IoError(inFolder, e.problem()); // the parent names the image
        }
        writeTransfer(image, QDir(outFolder).filePath(transferName(input.fileName())));
    }
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
