// Feeding one input to its loader, and the promises checked on what the loader accepted.
#include "fuzz_inputs.h"

#include "cli_process.h"

#include "cli/options.h"

#include "celform/algorithms/mesh_analysis.h"
#include "celform/model/io/animation_io.h"
#include "celform/model/io/image_io.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/png_encoder.h"
#include "celform/model/io/project_file.h"
#include "celform/model/io/run_deflate.h"

#include <QCommandLineParser>
#include <QDir>
#include <QImage>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtEndian>

#include <zlib.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <set>
#include <vector>

namespace celform::fuzz {
namespace {

const QStringList kMeshKinds = {"ply", "off", "obj", "stl", "gltf", "glb", "fbx"};
const QStringList kDrawingKinds = {"png", "jpg", "tif", "exr", "psd", "svg"};
/// model::readAnimatedBase on glTF (its tinygltf reader runs in the product's own process).
const QStringList kAnimatedKinds = {"animated-gltf", "animated-glb"};

/// input.SUFFIX in a folder of this process, rewritten for every input. The folder's depth under
/// the temporary folder is fixed, so relative references in a file (an OBJ's mtllib ../../x)
/// resolve the same way in the fuzzer and in the replay.
QString writeInput(const QString& suffix, const QByteArray& bytes)
{
    static QTemporaryDir dir(QDir::tempPath() + QStringLiteral("/celform-fuzz-XXXXXX"));
    if (!dir.isValid()) {
        std::fprintf(stderr, "fuzz: no temporary folder: %s\n", qPrintable(dir.errorString()));
        std::abort();
    }
    const QString path = dir.filePath(QStringLiteral("input.") + suffix);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size()) {
        std::fprintf(stderr, "fuzz: cannot write %s\n", qPrintable(path));
        std::abort();
    }
    return path;
}

// --- promises of accepted input -------------------------------------------------------------------

/// What every mesh the readers hand out must satisfy (mesh_io.h, tri_mesh.h): usable (vertices,
/// faces, finite coordinates, indices in range), UV faces one per face and in range, face
/// materials one per face and naming a material (0 stands for the default one).
QString meshProblem(const algo::TriMesh& mesh)
{
    if (const auto defect = algo::findFatalDefect(mesh))
        return QString::fromStdString(*defect);
    const Eigen::Index nf = mesh.faceCount();
    if (mesh.uvFaces.rows() > 0) {
        if (mesh.uvFaces.rows() != nf)
            return QStringLiteral("%1 UV faces for %2 faces").arg(mesh.uvFaces.rows()).arg(nf);
        if (mesh.uvFaces.minCoeff() < 0 || mesh.uvFaces.maxCoeff() >= mesh.uvs.rows())
            return QStringLiteral("a UV index is outside the %1 texture coordinates").arg(mesh.uvs.rows());
    }
    if (!mesh.faceMaterials.empty()) {
        if (Eigen::Index(mesh.faceMaterials.size()) != nf)
            return QStringLiteral("%1 face materials for %2 faces").arg(mesh.faceMaterials.size()).arg(nf);
        for (const std::int32_t m : mesh.faceMaterials)
            if (m < 0 || (m > 0 && std::size_t(m) >= mesh.materials.size()))
                return QStringLiteral("face material %1 of %2 materials").arg(m).arg(mesh.materials.size());
    }
    return {};
}

} // namespace

/// The reading rules of docs/file-format.md on an accepted project: a usable base model, face
/// sets and key offsets in range and in order, finite offsets, valid highlight tracks, shading
/// offsets per vertex, decoded drawings.
QString projectProblem(const model::ProjectData& data)
{
    const Eigen::Index nv = data.baseMesh ? data.baseMesh->vertexCount() : 0;
    if (data.baseMesh) {
        if (QString problem = meshProblem(*data.baseMesh); !problem.isEmpty())
            return QStringLiteral("base model: ") + problem;
    }
    std::set<std::string> names;
    for (const algo::FaceSet& set : data.faceSets) {
        if (set.name.empty() || !names.insert(set.name).second)
            return QStringLiteral("face set name empty or repeated");
        for (std::size_t k = 0; k < set.faces.size(); ++k)
            if (!data.baseMesh || set.faces[k] < 0 || set.faces[k] >= data.baseMesh->faceCount()
                || (k > 0 && set.faces[k] <= set.faces[k - 1]))
                return QStringLiteral("face set %1: face out of range or order").arg(QString::fromStdString(set.name));
    }
    for (const model::KeyViewpoint& key : data.keys)
        for (const auto& [frame, offsets] : key.offsetsByFrame) {
            if (offsets.indices.size() != offsets.deltas.size())
                return QStringLiteral("key %1: %2 indices, %3 offsets")
                    .arg(key.name)
                    .arg(offsets.indices.size())
                    .arg(offsets.deltas.size());
            for (std::size_t i = 0; i < offsets.indices.size(); ++i)
                if (offsets.indices[i] >= nv || (i > 0 && offsets.indices[i] <= offsets.indices[i - 1])
                    || !offsets.deltas[i].allFinite())
                    return QStringLiteral("key %1, frame %2: offset %3 out of range, order or not finite")
                        .arg(key.name)
                        .arg(frame)
                        .arg(i);
        }
    if (const QString problem = model::highlightTracksProblem(data.look.highlights, data.faceSetNames());
        !problem.isEmpty())
        return QStringLiteral("highlights: ") + problem;
    if (!data.shadingOffsets.empty() && Eigen::Index(data.shadingOffsets.size()) != nv)
        return QStringLiteral("%1 shading offsets for %2 vertices").arg(data.shadingOffsets.size()).arg(nv);
    for (const model::Drawing& d : data.drawings)
        if (d.image.isNull())
            return QStringLiteral("drawing %1 accepted but not decoded").arg(d.name);
    return {};
}

namespace {

// --- the option parsers ---------------------------------------------------------------------------

/// Checks a parser's result; empty when it keeps its promise (options.h).
using OptionParser = std::function<QString(const QString&)>;

QString unless(bool ok, const char* promise)
{
    return ok ? QString() : QString::fromLatin1(promise);
}

template <typename Vector> bool unitLength(const Vector& v)
{
    return v.allFinite() && std::abs(double(v.norm()) - 1.0) < 1e-5;
}

template <typename Vector> bool normalises(const Vector& v)
{
    return v.allFinite() && v.norm() > 0 && std::isfinite(double(v.norm())) && v.normalized().allFinite();
}

bool finiteAsFloat(double v)
{
    return std::isfinite(v) && std::isfinite(float(v));
}

const std::vector<OptionParser>& optionParsers()
{
    using namespace celform::app;
    static const std::vector<OptionParser> parsers = {
        [](const QString& t) { return unless(parseNumbers("n", t, 2).allFinite(), "numbers finite"); },
        [](const QString& t) { return unless(parseNumbers("n", t, 3).allFinite(), "numbers finite"); },
        [](const QString& t) { return unless(parseNumbers("n", t, 4).allFinite(), "numbers finite"); },
        [](const QString& t) {
            const Eigen::VectorXd v = parseFloats("f", t, 2);
            return unless(finiteAsFloat(v[0]) && finiteAsFloat(v[1]), "floats finite");
        },
        [](const QString& t) { return unless(std::isfinite(parseNumber("n", t)), "number finite"); },
        [](const QString& t) { return unless(finiteAsFloat(parseFloat("f", t)), "float finite"); },
        [](const QString& t) { return (void)parseInt("i", t), QString(); },
        [](const QString& t) { return unless(std::abs(parseFrame("frame", t)) <= model::kMaxFrame, "frame in range"); },
        [](const QString& t) {
            const auto [a, b, step] = parseFrameRange("frames", t);
            return unless(a <= b && std::abs(a) <= model::kMaxFrame && std::abs(b) <= model::kMaxFrame && step >= 1
                    && (qint64(b) - a) / step + 1 <= kMaxFramesPerRun,
                "frame range in bounds");
        },
        [](const QString& t) {
            const QSize s = parseSize("size", t);
            return unless(s.width() >= 1 && s.height() >= 1 && s.width() <= kMaxRenderSide
                    && s.height() <= kMaxRenderSide && qint64(s.width()) * s.height() <= kMaxRenderPixels,
                "size in bounds");
        },
        [](const QString& t) { return (void)parseOnOff("lines", t), QString(); },
        [](const QString& t) { return unless(parsePoint("eye", t).allFinite(), "point finite"); },
        [](const QString& t) { return unless(normalises(parseDirection("view", t)), "direction normalises"); },
        [](const QString& t) { return unless(normalises(parseFloatDirection("guide", t)), "direction normalises"); },
        [](const QString& t) {
            const model::Light light = parseLight("light", t);
            return unless(light.type == model::LightType::Point ? light.vector.allFinite() : unitLength(light.vector),
                "light finite, directions of unit length");
        },
        [](const QString& t) { return (void)parseStyle("style", t), QString(); },
        [](const QString& t) {
            // The camera options of `key add` and `render`, each '\0'-separated word an argument.
            static const SubCommand command{"render", {}, "", {}, camera_options::specs(), nullptr};
            QCommandLineParser parser;
            for (const OptionSpec& o : command.options)
                parser.addOption(QCommandLineOption(QLatin1String(o.name), QString(), QLatin1String(o.valueName)));
            if (!parser.parse(QStringList{QStringLiteral("celform")} + t.split(QLatin1Char('\0'))))
                throw UsageError{parser.errorText()};
            const Invocation in(command, parser);
            camera_options::checkCombination(in, true);
            if (camera_options::byView(in))
                return unless(normalises(camera_options::view(in)), "view normalises");
            return unless(camera_options::explicitCamera(in).isValid(), "camera valid");
        },
    };
    return parsers;
}

Outcome feedOptions(const QByteArray& bytes)
{
    Outcome out;
    if (bytes.isEmpty()) {
        out.refusal = QStringLiteral("no parser chosen");
        return out;
    }
    const auto& parsers = optionParsers();
    const OptionParser& parse = parsers[std::size_t(static_cast<unsigned char>(bytes[0])) % parsers.size()];
    try {
        out.broken = parse(QString::fromUtf8(bytes.mid(1))); // NULs included
        out.loaded = true;
    } catch (const app::UsageError& e) {
        out.refusal = e.message;
    }
    return out;
}

// --- the project container ----------------------------------------------------------------------

constexpr qint64 kTrailerSize = 32;
constexpr char kEndMagic[8] = {'C', 'E', 'L', 'F', 'E', 'N', 'D', '\n'};

quint32 crc32Of(const char* data, qint64 size)
{
    return quint32(crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(data), uInt(size)));
}

// --- the PNG writer ------------------------------------------------------------------------------

/// The writer's promise: what it encodes reads back the same. Both of its coders are reached: the
/// bytes make a picture by tiling (so that runs, which take the run coder, are common), and
/// deflateRuns alone compresses them as they are, inflated again by zlib.
/// Byte 0: channels (1, 3 or 4) and the coder's period; bytes 1-2: width (1-320); byte 3: height
/// (64-191 rows: pictures are sampled from 64 rows on); the rest: the pixels, repeated.
QString pngWriterProblem(const QByteArray& bytes)
{
    if (bytes.size() < 4)
        return {};
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.constData());
    const int channels = std::array<int, 3>{1, 3, 4}[b[0] % 3];
    const int width = 1 + (b[1] | (b[2] << 8)) % 320;
    const int height = 64 + b[3] % 128;
    const std::size_t rest = std::size_t(bytes.size()) - 4;
    std::vector<unsigned char> px(std::size_t(width) * std::size_t(height) * std::size_t(channels), 0);
    for (std::size_t i = 0; rest > 0 && i < px.size(); ++i)
        px[i] = b[4 + i % rest];
    std::vector<unsigned char> file;
    const QString problem = model::encodePng(px.data(), width, height, channels, file);
    if (!problem.isEmpty())
        return QStringLiteral("the PNG writer refused a picture: ") + problem;
    QImage back;
    if (!back.loadFromData(file.data(), int(file.size()), "png"))
        return QStringLiteral("the PNG written does not read back");
    const QImage::Format format
        = channels == 4 ? QImage::Format_RGBA8888 : (channels == 3 ? QImage::Format_RGB888 : QImage::Format_Grayscale8);
    back = back.convertToFormat(format);
    const std::size_t rowBytes = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height; ++y)
        if (back.width() != width || back.height() != height
            || std::memcmp(back.constScanLine(y), px.data() + std::size_t(y) * rowBytes, rowBytes) != 0)
            return QStringLiteral("the PNG written reads back other pixels (row %1)").arg(y);

    std::vector<unsigned char> stream;
    if (!model::deflateRuns(b + 4, rest, 1 + b[0] % 8, width, std::size_t(-1), stream))
        return QStringLiteral("the run coder refused bytes without a limit");
    std::vector<unsigned char> inflated(rest + 1);
    uLongf length = uLongf(inflated.size());
    if (uncompress(inflated.data(), &length, stream.data(), uLong(stream.size())) != Z_OK || length != rest
        || (rest > 0 && std::memcmp(inflated.data(), b + 4, rest) != 0))
        return QStringLiteral("the run coder's stream does not inflate to its bytes");
    return {};
}

} // namespace

QStringList kinds()
{
    return kMeshKinds + kDrawingKinds + kAnimatedKinds
        + QStringList{QStringLiteral("project"), QStringLiteral("cli-options"), QStringLiteral("cli-process"),
            QStringLiteral("png-writer")};
}

Outcome feed(const QString& kind, const QByteArray& bytes)
{
    if (kind == QLatin1String("cli-options"))
        return feedOptions(bytes);
    if (kind == QLatin1String("cli-process"))
        return feedCliProcess(bytes);
    if (kind == QLatin1String("png-writer")) {
        Outcome written;
        written.loaded = true;
        written.broken = pngWriterProblem(bytes);
        return written;
    }
    Outcome out;
    try {
        // Every reader in this process (the product runs Assimp's and most of OpenImageIO's in a
        // child): its crashes and sanitizer reports are the findings.
        constexpr auto here = model::ImportIsolation::ThisProcess;
        if (kMeshKinds.contains(kind)) {
            const model::MeshImport mesh = model::importMesh(writeInput(kind, bytes), here);
            out.loaded = true;
            out.broken = meshProblem(mesh.mesh);
        } else if (kAnimatedKinds.contains(kind)) {
            const QString suffix = kind.mid(kind.indexOf(QLatin1Char('-')) + 1);
            const model::AnimatedImport anim = model::readAnimatedBase(writeInput(suffix, bytes));
            out.loaded = true;
            out.broken = meshProblem(*anim.mesh);
            if (out.broken.isEmpty())
                out.broken = QString::fromStdString(anim.animation.problem(anim.mesh->vertexCount()));
        } else if (kDrawingKinds.contains(kind)) {
            const QImage image = model::decodeImage(bytes, kind, QStringLiteral("input.") + kind, here);
            out.loaded = true;
            if (image.isNull())
                out.broken = QStringLiteral("accepted but not decoded");
        } else if (kind == QLatin1String("project")) {
            // The drawings are decoded as loadProject() would, but here.
            model::ProjectData data
                = model::loadProject(writeInput(QStringLiteral("celform"), bytes), model::DrawingImages::Skip);
            for (model::Drawing& d : data.drawings)
                d.image = model::decodeImage(d.imageData, d.imageFormat, d.name, here);
            out.loaded = true;
            out.broken = projectProblem(data);
        } else {
            std::fprintf(stderr, "fuzz: unknown kind %s\n", qPrintable(kind));
            std::abort();
        }
    } catch (const model::IoError& e) {
        out.refusal = e.message();
    }
    return out;
}

QByteArray fixProjectChecksums(const QByteArray& bytes)
{
    const qint64 size = bytes.size();
    if (size < 16 + kTrailerSize || std::memcmp(bytes.constData() + size - 8, kEndMagic, 8) != 0)
        return bytes;
    const char* trailer = bytes.constData() + size - kTrailerSize;
    const auto offset = qFromLittleEndian<quint64>(trailer);
    const auto length = qFromLittleEndian<quint64>(trailer + 8);
    if (offset < 16 || length > quint64(size) || offset + length > quint64(size - kTrailerSize))
        return bytes; // refused before any checksum: nothing to fix
    QByteArray manifest = bytes.mid(qsizetype(offset), qsizetype(length));

    // The chunks before the manifest keep their offsets; re-serialise only when a checksum changes,
    // so that mutations of the manifest's text reach the reader as they are.
    const QJsonDocument json = QJsonDocument::fromJson(manifest);
    QJsonObject root = json.object();
    QJsonObject chunks = root.value(QLatin1String("chunks")).toObject();
    bool changed = false;
    for (auto it = chunks.begin(); it != chunks.end(); ++it) {
        QJsonObject entry = it.value().toObject();
        const double at = entry.value(QLatin1String("offset")).toDouble(-1);
        const double n = entry.value(QLatin1String("size")).toDouble(-1);
        if (!(at >= 16 && n >= 0 && at + n <= double(offset)))
            continue;
        const double crc = crc32Of(bytes.constData() + qint64(at), qint64(n));
        if (entry.value(QLatin1String("crc32")).toDouble(-1) != crc) {
            entry.insert(QLatin1String("crc32"), crc);
            it.value() = entry;
            changed = true;
        }
    }
    if (changed) {
        root.insert(QLatin1String("chunks"), chunks);
        manifest = QJsonDocument(root).toJson(QJsonDocument::Compact);
    }

    QByteArray out = bytes.left(qsizetype(offset)) + manifest;
    char fixed[kTrailerSize];
    std::memcpy(fixed, trailer, kTrailerSize);
    qToLittleEndian<quint64>(quint64(manifest.size()), fixed + 8);
    qToLittleEndian<quint32>(crc32Of(manifest.constData(), manifest.size()), fixed + 16);
    out.append(fixed, kTrailerSize);
    return out;
}

} // namespace celform::fuzz
