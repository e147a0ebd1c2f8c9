// OBJ import through tinyobjloader, after a check of the "v" lines it would read as 0; vertex order,
// UVs and materials kept, polygons fan-triangulated like OFF and PLY. Material libraries are read
// only from the OBJ's folder, and only when they are regular files of a sane size.
#include "celform/model/io/mesh_io_common.h"

#include <tiny_obj_loader.h>

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <istream>
#include <map>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace celform::model::meshio {

namespace {

QString firstLine(const std::string& s)
{
    QString text = QString::fromStdString(s).trimmed();
    const auto nl = text.indexOf(QLatin1Char('\n'));
    if (nl >= 0)
        text.truncate(nl);
    if (text.size() > 160)
        text = text.left(157) + QStringLiteral("...");
    return text.trimmed();
}

/// The largest material library read. An MTL file holds a few lines per material, so this is far
/// more than any real one; a larger file is something else, and reading it would only fill memory.
constexpr qint64 kMaxMaterialLibraryBytes = qint64(16) << 20;

/// A read-only stream buffer over the mapped OBJ file, so that tinyobjloader parses the bytes
/// already checked instead of opening the path a second time.
class MemoryStreamBuffer : public std::streambuf {
public:
    MemoryStreamBuffer(const char* data, std::size_t size)
    {
        char* begin = const_cast<char*>(data); // the get area is only ever read
        setg(begin, begin, begin + size);
    }
};

/// Reads the material libraries an OBJ file names ("mtllib"), confined to the OBJ's folder and its
/// sub-folders: an absolute path or one that climbs out with ".." is refused (a file could
/// otherwise make us read /dev/zero until memory runs out, or /dev/urandom for ever), and so is
/// anything that is not a regular file or is larger than kMaxMaterialLibraryBytes. A refused or
/// missing library is a warning; its faces then get default materials.
class ConfinedMaterialReader : public tinyobj::MaterialReader {
public:
    explicit ConfinedMaterialReader(const QString& objPath)
        : m_folder(QFileInfo(objPath).absoluteDir())
    { }

    bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
        std::map<std::string, int>* matMap, std::string* warn, std::string* err) override
    {
        QByteArray bytes;
        const QString problem = read(QFile::decodeName(matId.c_str()), bytes);
        if (!problem.isEmpty()) {
            m_problems << MeshIo::tr("some materials could not be read: %1").arg(problem);
            return false;
        }
        std::istringstream in(std::string(bytes.constData(), static_cast<std::size_t>(bytes.size())));
        tinyobj::LoadMtl(matMap, materials, &in, warn, err);
        return true;
    }

    /// One translated line per library not read.
    [[nodiscard]] const QStringList& problems() const { return m_problems; }

private:
    /// A long name (a chain of "../") keeps its end, which says what it points at, from a '/' on.
    static QString shortName(const QString& name)
    {
        if (name.size() <= 80)
            return name;
        const QString tail = name.right(78);
        return QChar(0x2026) + tail.mid(std::max<qsizetype>(tail.indexOf(QLatin1Char('/')), 0));
    }

    /// Fills bytes with the library's contents, or returns why it was not read.
    QString read(const QString& name, QByteArray& bytes) const
    {
        const QString shown = shortName(name);
        const QString clean = QDir::cleanPath(name);
        if (QDir::isAbsolutePath(name) || clean == QLatin1String("..") || clean.startsWith(QLatin1String("../")))
            return MeshIo::tr("\"%1\" is outside the folder of the OBJ file").arg(shown);
        const QString path = m_folder.filePath(clean);
        const QFileInfo info(path);
        if (!info.exists())
            return MeshIo::tr("\"%1\" does not exist").arg(shown);
        if (!info.isFile()) // a FIFO would block the open, a device never ends
            return MeshIo::tr("\"%1\" is not a regular file").arg(shown);
        const QString tooLarge
            = MeshIo::tr("\"%1\" is larger than %2 MB").arg(shown).arg(kMaxMaterialLibraryBytes >> 20);
        if (info.size() > kMaxMaterialLibraryBytes)
            return tooLarge;
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            return MeshIo::tr("\"%1\" cannot be opened: %2").arg(shown, file.errorString());
        bytes = file.read(kMaxMaterialLibraryBytes + 1); // bounded even if it grew since the check
        if (bytes.size() > kMaxMaterialLibraryBytes)
            return tooLarge;
        return {};
    }

    QDir m_folder;
    QStringList m_problems;
};

/// Checks the index parts of an "f" line (from p to eol) as tinyobjloader will read them, with
/// atoi(): an index beyond 32 bits would wrap there (99999999999 to 1215752191, 4294967299 to a
/// valid 3), so it is refused here, quoted as written. Returns the number of corners.
std::int64_t checkObjFaceIndices(
    const QString& path, const char* p, const char* eol, std::int64_t line, std::int64_t face)
{
    const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    std::int64_t corners = 0;
    bool inCorner = false;
    while (p < eol) {
        if (*p == ' ' || *p == '\t' || *p == '\r') {
            inCorner = false;
            ++p;
            continue;
        }
        if (!inCorner) {
            inCorner = true;
            ++corners;
        }
        if (*p == '/') {
            ++p;
            continue;
        }
        const char* const start = p;
        if (*p == '-' || *p == '+')
            ++p;
        const char* const digits = p;
        while (p < eol && isDigit(*p))
            ++p;
        if (p > digits) {
            std::int64_t value = 0;
            const auto [next, ec] = std::from_chars(digits, p, value);
            if (ec == std::errc::result_out_of_range || next != p || value > kMaxIndex) {
                const auto length = std::min<std::ptrdiff_t>(p - start, 40);
                throw IoError(path,
                    MeshIo::tr("line %1: face %2 has the index %3, which is too large")
                        .arg(line)
                        .arg(face)
                        .arg(QString::fromLatin1(start, static_cast<qsizetype>(length))
                            + (p - start > length ? QStringLiteral("...") : QString())));
            }
        }
        while (p < eol && *p != ' ' && *p != '\t' && *p != '\r' && *p != '/')
            ++p; // the rest of the part, as atoi() ignores it
    }
    return corners;
}

/// tinyobjloader reads a coordinate it cannot parse ("nan", "1,5", "x") as 0 without a word; check
/// the "v" lines first so such a file is an error rather than a silently flattened mesh. The "f"
/// lines' indices are checked too (checkObjFaceIndices), and the counts against the mesh size
/// limits, before tinyobjloader allocates anything.
void checkObjLines(const QString& path, const FileBytes& bytes)
{
    const char* p = bytes.data();
    const char* const end = p + bytes.size();
    std::int64_t line = 0;
    std::int64_t vertex = 0;
    std::int64_t face = 0;
    std::int64_t triangles = 0;
    while (p < end) {
        ++line;
        const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        if (!eol)
            eol = end;
        while (p < eol && (*p == ' ' || *p == '\t'))
            ++p;
        if (eol - p >= 2 && p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
            ++vertex;
            p += 2;
            for (int k = 0; k < 3; ++k) {
                while (p < eol && (*p == ' ' || *p == '\t' || *p == '\r'))
                    ++p;
                const char* start = p < eol && *p == '+' ? p + 1 : p;
                double value = 0.0;
                const auto [next, ec] = std::from_chars(start, eol, value);
                const bool endsToken = next == eol || *next == ' ' || *next == '\t' || *next == '\r';
                if (ec == std::errc::result_out_of_range && endsToken) {
                    p = next; // too large for a float anyway: reported as not finite below
                    continue;
                }
                if (ec != std::errc() || !endsToken || !std::isfinite(value))
                    throw IoError(path,
                        MeshIo::tr("line %1: vertex %2 has a coordinate that is not a finite number")
                            .arg(line)
                            .arg(vertex));
                p = next;
            }
        } else if (eol - p >= 2 && p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
            const std::int64_t corners = checkObjFaceIndices(path, p + 2, eol, line, ++face);
            triangles += std::max<std::int64_t>(corners - 2, 0);
        }
        p = eol + 1;
    }
    checkVertexCount(path, vertex);
    checkFaceCount(path, face);
    checkTriangleCount(path, triangles);
}

} // namespace

void readObj(const QString& path, MeshImport& out)
{
    const FileBytes bytes(path); // also gives missing and empty files the usual messages
    checkObjLines(path, bytes);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn;
    std::string err;
    MemoryStreamBuffer buffer(bytes.data(), bytes.size());
    std::istream stream(&buffer);
    ConfinedMaterialReader materialReader(path);
    // tinyobjloader's own triangulation skips faces with bad indices (a warning only) and reads
    // positions through them; we check every index first, then fan-triangulate like OFF and PLY.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream, &materialReader,
            /*triangulate=*/false, /*default_vcols_fallback=*/false))
        throw IoError(path, MeshIo::tr("not a readable OBJ file: %1").arg(firstLine(err)));

    const std::int64_t nv = static_cast<std::int64_t>(attrib.vertices.size() / 3);
    const std::int64_t nt = static_cast<std::int64_t>(attrib.texcoords.size() / 2);
    if (nv > kMaxIndex || nt > kMaxIndex)
        throwTooLarge(path, nv, 0);
    out.mesh.vertices.resize(nv, 3);
    for (std::int64_t i = 0; i < nv; ++i)
        for (int k = 0; k < 3; ++k)
            out.mesh.vertices(i, k) = toCoordinate(path, attrib.vertices[std::size_t(3 * i + k)], i);

    FaceBuilder faces(path, nv);
    std::vector<std::int32_t> uvIndices;
    std::vector<std::int32_t> faceMaterials;
    bool allCornersHaveUv = nt > 0;
    bool anyMaterial = false;
    std::vector<std::int64_t> corners;
    std::int64_t sourceFace = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& m = shape.mesh;
        std::size_t offset = 0;
        for (std::size_t f = 0; f < m.num_face_vertices.size(); ++f, ++sourceFace) {
            const std::size_t n = m.num_face_vertices[f];
            if (offset + n > m.indices.size())
                throw IoError(path, MeshIo::tr("face %1 is incomplete").arg(sourceFace + 1));
            corners.resize(n);
            for (std::size_t k = 0; k < n; ++k)
                corners[k] = m.indices[offset + k].vertex_index;
            faces.addPolygon(sourceFace, corners.data(), n);
            const int material = f < m.material_ids.size() ? m.material_ids[f] : -1;
            anyMaterial = anyMaterial || material >= 0;
            for (std::size_t k = 1; n >= 3 && k + 1 < n; ++k) {
                faceMaterials.push_back(material);
                for (const std::size_t c : {std::size_t(0), k, k + 1}) {
                    const int t = m.indices[offset + c].texcoord_index;
                    if (t < 0) {
                        allCornersHaveUv = false;
                    } else if (t >= nt) {
                        throw IoError(path,
                            MeshIo::tr("face %1 refers to texture coordinate %2, but the file has %3")
                                .arg(sourceFace + 1)
                                .arg(t + 1)
                                .arg(nt));
                    }
                    uvIndices.push_back(t);
                }
            }
            offset += n;
        }
    }
    out.mesh.faces = faces.take();
    if (faces.skipped() > 0)
        out.warnings << skippedFacesWarning(faces.skipped());

    if (allCornersHaveUv && !uvIndices.empty()) {
        out.mesh.uvs = Eigen::Map<const algo::TexCoords>(attrib.texcoords.data(), nt, 2);
        out.mesh.uvFaces = Eigen::Map<const algo::Faces>(uvIndices.data(), out.mesh.faces.rows(), 3);
    }
    if (anyMaterial && !materials.empty()) {
        for (const auto& mat : materials) {
            algo::Material material;
            material.name = mat.name;
            material.baseColor = Eigen::Vector3f(mat.diffuse[0], mat.diffuse[1], mat.diffuse[2]);
            out.mesh.materials.push_back(std::move(material));
        }
        // Faces before the first usemtl (or naming an unknown material) get a default material.
        const bool needsDefault = std::any_of(faceMaterials.begin(), faceMaterials.end(),
            [&](std::int32_t m) { return m < 0 || m >= static_cast<std::int32_t>(materials.size()); });
        const auto fallback = static_cast<std::int32_t>(out.mesh.materials.size());
        if (needsDefault)
            out.mesh.materials.push_back(algo::Material{"default", {0.8f, 0.8f, 0.8f}});
        for (auto& m : faceMaterials)
            if (m < 0 || m >= fallback)
                m = fallback;
        out.mesh.faceMaterials = std::move(faceMaterials);
    }
    // A library not read makes its materials "not found" too: its own line says it all.
    out.warnings << materialReader.problems();
    if (materialReader.problems().isEmpty() && warn.find("not found") != std::string::npos)
        out.warnings << MeshIo::tr("some materials could not be read: %1").arg(firstLine(warn));
}

} // namespace celform::model::meshio
