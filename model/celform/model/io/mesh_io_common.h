// Internal to the mesh_io files: the MeshIo translation context, the mapped file, the face builder,
// the text cursor and number helpers the readers share, and the readers and writers mesh_io.cpp drives.
#pragma once

#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"

#include <QCoreApplication>
#include <QFile>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace celform::model {

class OutputFile;

// Gives lupdate the context "celform::model::MeshIo" for every MeshIo::tr() in the mesh_io files.
struct MeshIo {
    Q_DECLARE_TR_FUNCTIONS(celform::model::MeshIo)
};

namespace meshio {

constexpr std::int64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();
constexpr bool kHostLittleEndian = Q_BYTE_ORDER == Q_LITTLE_ENDIAN;

/// The largest mesh importMesh() accepts: 50 M vertices and 50 M triangles, 600 MB of positions and
/// as much of indices (the Stanford dragon has 0.9 M triangles). The counts a file declares (PLY
/// and OFF headers) or that a first pass finds (OBJ) are checked before any array is allocated, so
/// a small file claiming 60 M faces is refused at once; polygons that fan into more triangles than
/// the faces declared stop at the limit as they are added. Not configurable yet.
constexpr std::int64_t kMaxMeshVertices = 50'000'000;
constexpr std::int64_t kMaxMeshTriangles = 50'000'000;

/// Throw IoError naming the file when a count exceeds the limits above: checkFaceCount() is for
/// faces of any size (each gives at least one triangle), checkTriangleCount() for triangles.
void checkVertexCount(const QString& path, std::int64_t vertices);
void checkFaceCount(const QString& path, std::int64_t faces);
void checkTriangleCount(const QString& path, std::int64_t triangles);

/// Throws IoError naming the file unless path is an existing regular file (symbolic links
/// followed). Checked before anything opens the file: opening a FIFO with no writer blocks for
/// ever, and a directory or a device such as /dev/zero has no end to read to.
void requireRegularFile(const QString& path);
/// Whether a model may read a file it refers to (a glTF buffer, an FBX texture): one in the
/// model's folder or below it. A reference that climbs out with "../" or names an absolute path
/// elsewhere is refused, so that a downloaded model cannot read the user's other files, unless
/// the environment sets CELFORM_ALLOW_OUTSIDE_REFERENCES=1. A file that does not exist is left to
/// the reader to report.
[[nodiscard]] bool referenceAllowed(const QString& modelFolder, const QString& file);
/// The refusal's text, naming the reference and the way to allow it.
[[nodiscard]] QString outsideReferenceProblem(const QString& reference);

/// Whole-file access: mapped where possible, so a 16 MB PLY costs no copy.
class FileBytes {
public:
    /// Throws IoError for a missing, unopenable, empty or unreadable file, and for anything that
    /// is not a regular file (refused before it is opened).
    explicit FileBytes(const QString& path);
    [[nodiscard]] const char* data() const { return m_data; }
    [[nodiscard]] std::size_t size() const { return m_size; }

private:
    QFile m_file;
    QByteArray m_copy;
    const char* m_data = nullptr;
    std::size_t m_size = 0;
};

/// Collects triangles, fan-triangulating polygons, and checks indices as they arrive so that an
/// out-of-range index names the face it came from.
class FaceBuilder {
public:
    FaceBuilder(const QString& path, std::int64_t vertexCount)
        : m_path(path)
        , m_vertexCount(vertexCount)
    { }
    /// Callers pass what the bytes left can hold; never more than the limit is reserved.
    void reserve(std::int64_t triangles)
    {
        m_indices.reserve(static_cast<std::size_t>(std::clamp<std::int64_t>(triangles, 0, kMaxMeshTriangles)) * 3);
    }

    /// Throws before a polygon of that many corners is read when its triangles would take the mesh
    /// over kMaxMeshTriangles (a corner list as long as the file allows is refused unread).
    void checkPolygon(std::int64_t sourceFace, std::int64_t corners) const
    {
        if (corners - 2 > kMaxMeshTriangles - triangleCount())
            throwTooManyTriangles(sourceFace);
    }

    void addTriangle(std::int64_t sourceFace, std::int64_t a, std::int64_t b, std::int64_t c)
    {
        if (triangleCount() >= kMaxMeshTriangles)
            throwTooManyTriangles(sourceFace);
        check(sourceFace, a);
        check(sourceFace, b);
        check(sourceFace, c);
        m_indices.push_back(static_cast<std::int32_t>(a));
        m_indices.push_back(static_cast<std::int32_t>(b));
        m_indices.push_back(static_cast<std::int32_t>(c));
    }
    /// A fan from the first corner: exact for the convex polygons mesh files hold in practice.
    void addPolygon(std::int64_t sourceFace, const std::int64_t* corners, std::size_t n)
    {
        if (n < 3) {
            ++m_skipped;
            return;
        }
        for (std::size_t k = 1; k + 1 < n; ++k)
            addTriangle(sourceFace, corners[0], corners[k], corners[k + 1]);
    }
    [[nodiscard]] std::int64_t skipped() const { return m_skipped; }
    [[nodiscard]] std::int64_t triangleCount() const { return static_cast<std::int64_t>(m_indices.size() / 3); }

    algo::Faces take()
    {
        algo::Faces faces(static_cast<Eigen::Index>(m_indices.size() / 3), 3);
        if (!m_indices.empty())
            std::memcpy(faces.data(), m_indices.data(), m_indices.size() * sizeof(std::int32_t));
        m_indices = {};
        return faces;
    }

private:
    [[noreturn]] void throwTooManyTriangles(std::int64_t sourceFace) const
    {
        throw IoError(m_path,
            MeshIo::tr("face %1 makes more than the %2 triangles Celform can load")
                .arg(sourceFace + 1)
                .arg(kMaxMeshTriangles));
    }
    void check(std::int64_t sourceFace, std::int64_t v) const
    {
        if (v < 0 || v >= m_vertexCount)
            throw IoError(m_path,
                MeshIo::tr("face %1 refers to vertex %2, but the file has %3 vertices")
                    .arg(sourceFace + 1)
                    .arg(v)
                    .arg(m_vertexCount));
    }

    const QString& m_path;
    std::int64_t m_vertexCount;
    std::vector<std::int32_t> m_indices;
    std::int64_t m_skipped = 0;
};

/// "1 face with fewer than three corners ignored", "%n faces ...": for FaceBuilder::skipped().
QString skippedFacesWarning(std::int64_t skipped);

/// For a header whose counts cannot fit in the rest of the file; the message also says when they
/// are over the size limits (a header alone, declaring 60 M faces, is told about the limit too).
[[noreturn]] void throwTooLarge(const QString& path, std::int64_t vertices, std::int64_t faces);

/// Text tokeniser for OFF and ASCII PLY; counts lines for the error messages.
class TextCursor {
public:
    TextCursor(const QString& path, const char* begin, const char* end, bool hashComments)
        : m_path(path)
        , m_p(begin)
        , m_end(end)
        , m_hashComments(hashComments)
    { }

    /// Skips blanks, newlines and '#' comments; false at the end of the data.
    bool skipSpace()
    {
        while (m_p < m_end) {
            const char c = *m_p;
            if (c == '\n') {
                ++m_line;
                ++m_p;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++m_p;
            } else if (c == '#' && m_hashComments) {
                while (m_p < m_end && *m_p != '\n')
                    ++m_p;
            } else {
                return true;
            }
        }
        return false;
    }
    /// Moves past the end of the current line (extra colours, normals, comments).
    void skipLine()
    {
        while (m_p < m_end && *m_p != '\n')
            ++m_p;
        if (m_p < m_end) {
            ++m_p;
            ++m_line;
        }
    }
    std::string_view token()
    {
        if (!skipSpace())
            return {};
        const char* start = m_p;
        while (m_p < m_end && !isSpace(*m_p))
            ++m_p;
        return {start, static_cast<std::size_t>(m_p - start)};
    }
    template <typename T> std::optional<T> number()
    {
        if (!skipSpace())
            return std::nullopt;
        const char* start = m_p;
        if (*start == '+' && start + 1 < m_end)
            ++start;
        T value{};
        const auto [ptr, ec] = std::from_chars(start, m_end, value);
        if (ec != std::errc() || (ptr < m_end && !isSpace(*ptr) && *ptr != '#'))
            return std::nullopt;
        m_p = ptr;
        return value;
    }
    double real(const char* what)
    {
        if (auto v = number<double>())
            return *v;
        fail(what);
    }
    std::int64_t integer(const char* what)
    {
        if (auto v = number<std::int64_t>())
            return *v;
        // Some writers put integers as "3.0"; accept them when they are whole.
        if (auto d = number<double>(); d && std::floor(*d) == *d && std::fabs(*d) < 9e15)
            return static_cast<std::int64_t>(*d);
        fail(what);
    }
    /// Throws "line N: expected <what>", or "the file ends early" at the end of the data.
    [[noreturn]] void fail(const char* what) const;
    void rewind(const char* p) { m_p = p; }
    [[nodiscard]] std::size_t remaining() const { return static_cast<std::size_t>(m_end - m_p); }
    [[nodiscard]] const char* position() const { return m_p; }

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

    const QString& m_path;
    const char* m_p;
    const char* m_end;
    bool m_hashComments;
    std::int64_t m_line = 1;
};

// Source texts of the "expected ..." messages, listed for lupdate.
inline constexpr const char* kWhatCoordinate = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a vertex coordinate");
inline constexpr const char* kWhatCount = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a count");
inline constexpr const char* kWhatIndex = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a vertex index");
inline constexpr const char* kWhatValue = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a property value");

/// The float of a parsed coordinate; throws naming the vertex when it is not finite.
inline float toCoordinate(const QString& path, double v, std::int64_t vertex)
{
    const auto f = static_cast<float>(v);
    if (!std::isfinite(f))
        throw IoError(path, MeshIo::tr("vertex %1 has a coordinate that is not a finite number").arg(vertex + 1));
    return f;
}

// The readers in importMesh()'s table, one file each: they fill out.mesh (and out.warnings) from
// the file at path or throw IoError; importMesh() then checks the mesh and its topology.
void readOff(const QString& path, MeshImport& out); // mesh_io_off.cpp
void readPly(const QString& path, MeshImport& out); // mesh_io_ply.cpp
void readObj(const QString& path, MeshImport& out); // mesh_io_obj.cpp
void readWithAssimp(const QString& path, MeshImport& out); // mesh_io_assimp.cpp: STL, glTF/GLB, FBX, ...

// For readers of several files of one topology (the frames of a mesh sequence, animation_io):
// reads path with its table reader in this process and checks it as importMesh() does, without
// the topology report. Throws IoError, also for a format whose reader does not keep vertex order.
void readMeshInOrder(const QString& path, MeshImport& out); // mesh_io.cpp

// The two ends of an import in a child process (mesh_io_transfer.cpp): readInChild() runs
// `celform import-mesh` on the file and reads what its importMeshForParent() wrote with
// writeTransfer(): the mesh (with its materials and UVs) and the reader's warnings.
void readInChild(const QString& path, MeshImport& out);
void writeTransfer(const MeshImport& in, const QString& transferPath);

// The writers behind exportMesh() (mesh_io_write.cpp): positions and faces in vertex order.
void writeObj(const algo::TriMesh& mesh, OutputFile& file);
void writePly(const algo::TriMesh& mesh, OutputFile& file);

} // namespace meshio
} // namespace celform::model
