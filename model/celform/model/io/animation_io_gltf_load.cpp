// Opening a glTF file for the animated base import: tinygltf parses it with file access confined
// to regular files, after a check of the JSON's depth; and a look at the JSON alone for
// isAnimatedBaseFile().
#include "celform/model/io/animation_io_gltf.h"

#include "celform/model/io/mesh_io_common.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <dlfcn.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string_view>

namespace celform::model::animio {

namespace gltf {

namespace {

// tinygltf's file access, confined like mesh_io's Assimp reader: regular files only (a buffer
// naming a FIFO would block for ever, /dev/zero be read without end), no shell expansion of
// paths, no writing, and no image files (Celform takes only the base colour of a material).
/// The folder of the file being read and the first reference refused outside it.
struct Confinement {
    QString folder;
    QString refused;
};

/// False, noting the first such path, for a file outside the folder being read.
bool allowed(void* user, const QString& path)
{
    auto* confinement = static_cast<Confinement*>(user);
    if (!confinement || meshio::referenceAllowed(confinement->folder, path))
        return true;
    if (confinement->refused.isEmpty())
        confinement->refused = path;
    return false;
}

bool fileExists(const std::string& file, void* user)
{
    const QString path = QString::fromStdString(file);
    return allowed(user, path) && QFileInfo(path).isFile();
}

std::string expandPath(const std::string& file, void*)
{
    return file;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& file, void* user)
{
    const QString path = QString::fromStdString(file);
    if (!allowed(user, path)) {
        *err = "outside the file's folder";
        return false;
    }
    static const QStringList kImages = {QStringLiteral("png"), QStringLiteral("jpg"), QStringLiteral("jpeg"),
        QStringLiteral("webp"), QStringLiteral("ktx2"), QStringLiteral("dds"), QStringLiteral("bmp")};
    const QFileInfo info(path);
    if (kImages.contains(info.suffix().toLower())) {
        *err = "images are not read";
        return false;
    }
    QFile f(path);
    if (!info.isFile() || !f.open(QIODevice::ReadOnly) || f.isSequential()) {
        *err = "not a readable regular file";
        return false;
    }
    if (f.size() > qint64(std::numeric_limits<std::uint32_t>::max())) {
        *err = "larger than 4 GB";
        return false;
    }
    out->resize(std::size_t(f.size()));
    if (f.read(reinterpret_cast<char*>(out->data()), f.size()) != f.size()) {
        *err = f.errorString().toStdString();
        return false;
    }
    return true;
}

bool refuseWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*)
{
    return false;
}

bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true;
}

/// tinygltf's error text on one line, shortened.
QString readableError(const std::string& err)
{
    QString text = QString::fromStdString(err).simplified();
    if (text.isEmpty())
        text = AnimationIo::tr("unknown error");
    if (text.size() > 200)
        text = text.left(197) + QStringLiteral("...");
    return text;
}

bool isGlb(const char* data, std::size_t size)
{
    return size >= 4 && std::memcmp(data, "glTF", 4) == 0;
}

/// glTF's own structure is a few levels deep; "extras" may hold anything, and tinygltf converts it
/// recursively: 100,000 nested arrays overflowed the stack. Deeper JSON is refused unparsed.
constexpr int kMaxJsonDepth = 100;

/// The deepest nesting of arrays and objects in the JSON text (brackets inside strings skipped).
int jsonDepth(const char* p, std::size_t size)
{
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    for (const char* end = p + size; p < end; ++p) {
        const char c = *p;
        if (inString) {
            if (c == '\\')
                ++p;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > kMaxJsonDepth)
                return deepest;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

/// The JSON of a .gltf file, or of a GLB's first chunk (whatever its header claims, within the file).
std::pair<const char*, std::size_t> jsonText(const char* data, std::size_t size)
{
    if (!isGlb(data, size))
        return {data, size};
    if (size < 20)
        return {data, 0};
    const auto length = qFromLittleEndian<quint32>(data + 12);
    return {data + 20, std::min<std::size_t>(length, size - 20)};
}

/// libdraco (which Assimp links) exports a copy of another tinygltf version under the same
/// symbol names, with another layout of TinyGLTF: whichever library a program lists first provides
/// every tinygltf function, and draco's corrupts the heap here. model/CMakeLists.txt lists
/// tinygltf first; this refuses to read, rather than crash, in a program where draco still won.
QString foreignTinygltf()
{
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&tinygltf::ReadWholeFile), &info) == 0 || !info.dli_fname)
        return {}; // cannot tell
    const QString library = QFileInfo(QFile::decodeName(info.dli_fname)).fileName();
    return library.contains(QLatin1String("tinygltf")) ? QString() : library;
}

} // namespace

Source load(const QString& path)
{
    static const QString foreign = foreignTinygltf();
    if (!foreign.isEmpty())
        throw IoError(path,
            AnimationIo::tr("this build cannot read glTF: its tinygltf functions come from %1, not from tinygltf's "
                            "library (link TinyGLTF before Assimp)")
                .arg(foreign));
    const meshio::FileBytes bytes(path); // missing, empty, not a regular file: refused here
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw IoError(path, AnimationIo::tr("the file is larger than the 4 GB glTF allows"));
    if (const QString problem = gltfJsonProblem(bytes.data(), bytes.size()); !problem.isEmpty())
        throw IoError(path, problem);
    Source src;
    src.path = path;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    Confinement confinement{QFileInfo(path).absolutePath(), {}};
    loader.SetFsCallbacks({&fileExists, &expandPath, &readWholeFile, &refuseWrite, &confinement});
    std::string err;
    std::string warn;
    const std::string folder = QFile::encodeName(QFileInfo(path).absolutePath()).toStdString();
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok = isGlb(bytes.data(), bytes.size())
        ? loader.LoadBinaryFromMemory(
            &src.model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, folder)
        : loader.LoadASCIIFromString(&src.model, &err, &warn, bytes.data(), size, folder);
    if (!ok && !confinement.refused.isEmpty())
        throw IoError(path, meshio::outsideReferenceProblem(confinement.refused));
    if (!ok)
        throw IoError(path, AnimationIo::tr("not a readable glTF file: %1").arg(readableError(err)));
    // Compressed geometry leaves its accessors without data: read as zeros, it would look valid.
    for (const std::string& extension : src.model.extensionsRequired)
        if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression"
            || extension == "KHR_meshopt_compression")
            throw IoError(path,
                AnimationIo::tr("the file needs the glTF extension %1, which Celform does not read")
                    .arg(QString::fromStdString(extension)));
    return src;
}

} // namespace gltf

QString gltfJsonProblem(const char* data, std::size_t size, bool refuseDeep)
{
    const auto [json, jsonSize] = gltf::jsonText(data, size);
    if (gltf::jsonDepth(json, jsonSize) > gltf::kMaxJsonDepth) // QJsonDocument recurses too
        return !refuseDeep ? QString()
                           : AnimationIo::tr("its JSON is nested more than %1 levels deep, which no glTF file needs")
                                 .arg(gltf::kMaxJsonDepth);
    QJsonParseError error{};
    QJsonDocument::fromJson(QByteArray::fromRawData(json, qsizetype(jsonSize)), &error);
    if (error.error == QJsonParseError::NoError)
        return {};
    const std::size_t at = std::min<std::size_t>(std::size_t(std::max(0, error.offset)), jsonSize);
    // A number JSON does not have: the token around the offset names it.
    const std::string_view around(
        json + (at >= 12 ? at - 12 : 0), std::min<std::size_t>(jsonSize - at, 12) + std::min<std::size_t>(at, 12));
    const bool nonFinite
        = around.find("NaN") != std::string_view::npos || around.find("Infinity") != std::string_view::npos;
    return AnimationIo::tr("not a readable glTF file: its JSON cannot be read: %1 at byte %2%3")
        .arg(error.errorString())
        .arg(qulonglong(at + std::size_t(json - data)))
        .arg(nonFinite ? AnimationIo::tr(" (NaN and Infinity are not JSON numbers)") : QString());
}

bool gltfIsAnimated(const QString& path)
{
    const meshio::FileBytes bytes(path);
    const auto [text, size] = gltf::jsonText(bytes.data(), bytes.size());
    if (gltf::jsonDepth(text, size) > gltf::kMaxJsonDepth) // QJsonDocument recurses too
        return false;
    const QJsonObject root = QJsonDocument::fromJson(QByteArray::fromRawData(text, qsizetype(size))).object();
    if (!root.value(QStringLiteral("animations")).toArray().isEmpty()
        || !root.value(QStringLiteral("skins")).toArray().isEmpty())
        return true;
    for (const QJsonValue mesh : root.value(QStringLiteral("meshes")).toArray())
        for (const QJsonValue prim : mesh.toObject().value(QStringLiteral("primitives")).toArray())
            if (!prim.toObject().value(QStringLiteral("targets")).toArray().isEmpty())
                return true;
    return false;
}

} // namespace celform::model::animio
