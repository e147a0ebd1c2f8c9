// Mesh import/export. OFF and PLY have hand-written parsers over the mapped file (vertex order
// kept, large files in tens of milliseconds); OBJ goes through tinyobjloader, the rest through Assimp.
#include "celform/model/mesh_io.h"

#include "celform/model/io_error.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_obj_loader.h>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSaveFile>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace celform::model {

namespace {

// Gives lupdate the context "celform::model::MeshIo" for every MeshIo::tr() below.
struct MeshIo {
    Q_DECLARE_TR_FUNCTIONS(celform::model::MeshIo)
};

constexpr std::int64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();

// ---------------------------------------------------------------------------------------------
// Whole-file access: mapped where possible, so a 16 MB PLY costs no copy.

class FileBytes {
public:
    explicit FileBytes(const QString& path)
        : m_file(path)
    {
        if (!QFileInfo::exists(path))
            throw IoError(path, MeshIo::tr("the file does not exist"));
        if (!m_file.open(QIODevice::ReadOnly))
            throw IoError(path, MeshIo::tr("the file cannot be opened: %1").arg(m_file.errorString()));
        const qint64 size = m_file.size();
        if (size == 0)
            throw IoError(path, MeshIo::tr("the file is empty"));
        if (uchar* mapped = m_file.map(0, size)) {
            m_data = reinterpret_cast<const char*>(mapped);
            m_size = static_cast<std::size_t>(size);
        } else {
            m_copy = m_file.readAll();
            if (m_copy.size() != size)
                throw IoError(path, MeshIo::tr("the file cannot be read: %1").arg(m_file.errorString()));
            m_data = m_copy.constData();
            m_size = static_cast<std::size_t>(m_copy.size());
        }
    }
    [[nodiscard]] const char* data() const { return m_data; }
    [[nodiscard]] std::size_t size() const { return m_size; }

private:
    QFile m_file;
    QByteArray m_copy;
    const char* m_data = nullptr;
    std::size_t m_size = 0;
};

// ---------------------------------------------------------------------------------------------
// Shared builders.

/// Collects triangles, fan-triangulating polygons, and checks indices as they arrive so that an
/// out-of-range index names the face it came from.
class FaceBuilder {
public:
    FaceBuilder(const QString& path, std::int64_t vertexCount)
        : m_path(path)
        , m_vertexCount(vertexCount)
    { }
    void reserve(std::int64_t triangles) { m_indices.reserve(static_cast<std::size_t>(triangles) * 3); }

    void addTriangle(std::int64_t sourceFace, std::int64_t a, std::int64_t b, std::int64_t c)
    {
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

    algo::Faces take()
    {
        algo::Faces faces(static_cast<Eigen::Index>(m_indices.size() / 3), 3);
        if (!m_indices.empty())
            std::memcpy(faces.data(), m_indices.data(), m_indices.size() * sizeof(std::int32_t));
        m_indices = {};
        return faces;
    }

private:
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

QString skippedFacesWarning(std::int64_t skipped)
{
    if (skipped == 1)
        return MeshIo::tr("1 face with fewer than three corners ignored");
    return MeshIo::tr("%n faces with fewer than three corners ignored", nullptr, static_cast<int>(skipped));
}

[[noreturn]] void throwTooLarge(const QString& path, std::int64_t vertices, std::int64_t faces)
{
    throw IoError(path,
        MeshIo::tr("the header announces %1 vertices and %2 faces, more than the file holds").arg(vertices).arg(faces));
}

// ---------------------------------------------------------------------------------------------
// Text tokenizer for OFF and ASCII PLY; counts lines for the error messages.

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
    [[noreturn]] void fail(const char* what) const
    {
        if (m_p >= m_end)
            throw IoError(m_path, MeshIo::tr("the file ends early, while reading %1").arg(MeshIo::tr(what)));
        throw IoError(m_path, MeshIo::tr("line %1: expected %2").arg(m_line).arg(MeshIo::tr(what)));
    }
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
const char* const kWhatCoordinate = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a vertex coordinate");
const char* const kWhatCount = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a count");
const char* const kWhatIndex = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a vertex index");
const char* const kWhatValue = QT_TRANSLATE_NOOP("celform::model::MeshIo", "a property value");

float toCoordinate(const QString& path, double v, std::int64_t vertex)
{
    const auto f = static_cast<float>(v);
    if (!std::isfinite(f))
        throw IoError(path, MeshIo::tr("vertex %1 has a coordinate that is not a finite number").arg(vertex + 1));
    return f;
}

// ---------------------------------------------------------------------------------------------
// OFF (Geomview): "[C][N]OFF", counts, one vertex per line, "n i0 i1 ... [colour]" per face.

void readOff(const QString& path, MeshImport& out)
{
    const FileBytes bytes(path);
    const char* const end = bytes.data() + bytes.size();
    TextCursor in(path, bytes.data(), end, true);

    in.skipSpace();
    const char* const beforeHeader = in.position();
    const std::string_view head = in.token();
    if (head.size() >= 3 && head.substr(head.size() - 3) == "OFF") {
        if (head.find_first_of("4n") != std::string_view::npos)
            throw IoError(path, MeshIo::tr("only three-dimensional OFF files are supported"));
        const char* p = in.position();
        while (p < end && (*p == ' ' || *p == '\t'))
            ++p;
        if (std::string_view(p, static_cast<std::size_t>(std::min<std::ptrdiff_t>(6, end - p))) == "BINARY")
            throw IoError(path, MeshIo::tr("binary OFF files are not supported"));
    } else if (!head.empty() && std::isdigit(static_cast<unsigned char>(head[0])) != 0) {
        // Headerless OFF: the counts come first.
        in.rewind(beforeHeader);
    } else {
        throw IoError(path, MeshIo::tr("not an OFF file (it does not start with \"OFF\")"));
    }
    const std::int64_t nv = in.integer(kWhatCount);
    const std::int64_t nf = in.integer(kWhatCount);
    in.skipLine(); // the edge count, unused and sometimes missing
    if (nv < 0 || nf < 0)
        throw IoError(path, MeshIo::tr("the header has a negative vertex or face count"));
    // A vertex takes at least "0 0 0\n", a face at least "3 0 1 2\n".
    if (nv > kMaxIndex || nf > kMaxIndex
        || static_cast<double>(nv) * 6 + static_cast<double>(nf) * 8 > static_cast<double>(in.remaining()) + 1)
        throwTooLarge(path, nv, nf);

    algo::Positions& v = out.mesh.vertices;
    v.resize(nv, 3);
    float* pv = v.data();
    for (std::int64_t i = 0; i < nv; ++i) {
        if (!in.skipSpace())
            throw IoError(path, MeshIo::tr("the file ends after %1 of %2 vertices").arg(i).arg(nv));
        for (int k = 0; k < 3; ++k)
            *pv++ = toCoordinate(path, in.real(kWhatCoordinate), i);
        in.skipLine();
    }

    FaceBuilder faces(path, nv);
    faces.reserve(nf);
    std::vector<std::int64_t> corners;
    for (std::int64_t f = 0; f < nf; ++f) {
        if (!in.skipSpace())
            throw IoError(path, MeshIo::tr("the file ends after %1 of %2 faces").arg(f).arg(nf));
        const std::int64_t n = in.integer(kWhatCount);
        if (n < 0 || n > static_cast<std::int64_t>(in.remaining()))
            throw IoError(path, MeshIo::tr("face %1 has an invalid corner count %2").arg(f + 1).arg(n));
        corners.resize(static_cast<std::size_t>(n));
        for (auto& c : corners)
            c = in.integer(kWhatIndex);
        faces.addPolygon(f, corners.data(), corners.size());
        in.skipLine();
    }
    out.mesh.faces = faces.take();
    if (faces.skipped() > 0)
        out.warnings << skippedFacesWarning(faces.skipped());
}

// ---------------------------------------------------------------------------------------------
// PLY: header of elements and typed properties, then ASCII or binary rows.

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Invalid };

PlyType plyType(std::string_view s)
{
    if (s == "char" || s == "int8")
        return PlyType::Int8;
    if (s == "uchar" || s == "uint8")
        return PlyType::UInt8;
    if (s == "short" || s == "int16")
        return PlyType::Int16;
    if (s == "ushort" || s == "uint16")
        return PlyType::UInt16;
    if (s == "int" || s == "int32")
        return PlyType::Int32;
    if (s == "uint" || s == "uint32")
        return PlyType::UInt32;
    if (s == "float" || s == "float32")
        return PlyType::Float32;
    if (s == "double" || s == "float64")
        return PlyType::Float64;
    return PlyType::Invalid;
}

std::size_t plySize(PlyType t)
{
    switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
        return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
        return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
        return 4;
    case PlyType::Float64:
        return 8;
    case PlyType::Invalid:
        break;
    }
    return 0;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Invalid; ///< the value type, or the item type of a list
    PlyType countType = PlyType::Invalid; ///< set for list properties
    [[nodiscard]] bool isList() const { return countType != PlyType::Invalid; }
};

struct PlyElement {
    std::string name;
    std::int64_t count = 0;
    std::vector<PlyProperty> properties;

    /// Bytes per binary row, or 0 when a list makes the rows variable.
    [[nodiscard]] std::size_t fixedStride() const
    {
        std::size_t s = 0;
        for (const auto& p : properties) {
            if (p.isList())
                return 0;
            s += plySize(p.type);
        }
        return s;
    }
    /// The smallest binary row: lists with zero items.
    [[nodiscard]] std::size_t minStride() const
    {
        std::size_t s = 0;
        for (const auto& p : properties)
            s += plySize(p.isList() ? p.countType : p.type);
        return s;
    }
    [[nodiscard]] int find(std::string_view n) const
    {
        for (std::size_t i = 0; i < properties.size(); ++i)
            if (properties[i].name == n)
                return static_cast<int>(i);
        return -1;
    }
};

enum class PlyFormat { Ascii, BinaryLittle, BinaryBig };

template <typename T> T loadRaw(const char* p, bool swap)
{
    T v;
    if (!swap) {
        std::memcpy(&v, p, sizeof(T));
    } else {
        char b[sizeof(T)];
        for (std::size_t i = 0; i < sizeof(T); ++i)
            b[i] = p[sizeof(T) - 1 - i];
        std::memcpy(&v, b, sizeof(T));
    }
    return v;
}

double loadBinary(PlyType t, const char* p, bool swap)
{
    switch (t) {
    case PlyType::Int8:
        return static_cast<std::int8_t>(*p);
    case PlyType::UInt8:
        return static_cast<std::uint8_t>(*p);
    case PlyType::Int16:
        return loadRaw<std::int16_t>(p, swap);
    case PlyType::UInt16:
        return loadRaw<std::uint16_t>(p, swap);
    case PlyType::Int32:
        return loadRaw<std::int32_t>(p, swap);
    case PlyType::UInt32:
        return loadRaw<std::uint32_t>(p, swap);
    case PlyType::Float32:
        return loadRaw<float>(p, swap);
    case PlyType::Float64:
        return loadRaw<double>(p, swap);
    case PlyType::Invalid:
        break;
    }
    return 0.0;
}

std::int64_t loadBinaryIndex(PlyType t, const char* p, bool swap)
{
    switch (t) {
    case PlyType::Int8:
        return static_cast<std::int8_t>(*p);
    case PlyType::UInt8:
        return static_cast<std::uint8_t>(*p);
    case PlyType::Int16:
        return loadRaw<std::int16_t>(p, swap);
    case PlyType::UInt16:
        return loadRaw<std::uint16_t>(p, swap);
    case PlyType::Int32:
        return loadRaw<std::int32_t>(p, swap);
    case PlyType::UInt32:
        return loadRaw<std::uint32_t>(p, swap);
    case PlyType::Float32:
        return static_cast<std::int64_t>(loadRaw<float>(p, swap));
    case PlyType::Float64:
        return static_cast<std::int64_t>(loadRaw<double>(p, swap));
    case PlyType::Invalid:
        break;
    }
    return -1;
}

constexpr bool kHostLittleEndian = Q_BYTE_ORDER == Q_LITTLE_ENDIAN;

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    std::size_t bodyOffset = 0;
};

PlyHeader readPlyHeader(const QString& path, const char* data, std::size_t size)
{
    PlyHeader h;
    std::size_t pos = 0;
    std::int64_t lineNo = 0;
    bool sawFormat = false;
    auto nextLine = [&]() -> std::optional<std::string_view> {
        if (pos >= size)
            return std::nullopt;
        const void* nl = std::memchr(data + pos, '\n', size - pos);
        const std::size_t end = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - data) : size;
        std::string_view line(data + pos, end - pos);
        pos = nl ? end + 1 : size;
        ++lineNo;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
            line.remove_suffix(1);
        return line;
    };
    auto split = [](std::string_view line) {
        std::vector<std::string_view> words;
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
                ++i;
            const std::size_t s = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t')
                ++i;
            if (i > s)
                words.push_back(line.substr(s, i - s));
        }
        return words;
    };
    auto bad
        = [&](const QString& why) { return IoError(path, MeshIo::tr("PLY header line %1: %2").arg(lineNo).arg(why)); };

    const auto magic = nextLine();
    if (!magic || *magic != "ply")
        throw IoError(path, MeshIo::tr("not a PLY file (it does not start with \"ply\")"));
    for (;;) {
        const auto line = nextLine();
        if (!line)
            throw IoError(path, MeshIo::tr("the PLY header has no end_header line"));
        const auto w = split(*line);
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
            continue;
        if (w[0] == "end_header")
            break;
        if (w[0] == "format") {
            if (w.size() < 2)
                throw bad(MeshIo::tr("incomplete format line"));
            if (w[1] == "ascii")
                h.format = PlyFormat::Ascii;
            else if (w[1] == "binary_little_endian")
                h.format = PlyFormat::BinaryLittle;
            else if (w[1] == "binary_big_endian")
                h.format = PlyFormat::BinaryBig;
            else
                throw bad(MeshIo::tr("unknown format \"%1\"").arg(QString::fromUtf8(w[1].data(), int(w[1].size()))));
            sawFormat = true;
        } else if (w[0] == "element") {
            std::int64_t count = -1;
            if (w.size() == 3)
                std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
            if (count < 0)
                throw bad(MeshIo::tr("invalid element line"));
            h.elements.push_back({std::string(w[1]), count, {}});
        } else if (w[0] == "property") {
            if (h.elements.empty())
                throw bad(MeshIo::tr("property before any element"));
            PlyProperty p;
            if (w.size() == 5 && w[1] == "list") {
                p.countType = plyType(w[2]);
                p.type = plyType(w[3]);
                p.name = std::string(w[4]);
                if (p.countType == PlyType::Invalid || p.type == PlyType::Invalid)
                    throw bad(MeshIo::tr("unknown property type"));
            } else if (w.size() == 3) {
                p.type = plyType(w[1]);
                p.name = std::string(w[2]);
                if (p.type == PlyType::Invalid)
                    throw bad(MeshIo::tr("unknown property type"));
            } else {
                throw bad(MeshIo::tr("invalid property line"));
            }
            h.elements.back().properties.push_back(std::move(p));
        } else {
            throw bad(MeshIo::tr("unknown keyword \"%1\"").arg(QString::fromUtf8(w[0].data(), int(w[0].size()))));
        }
    }
    if (!sawFormat)
        throw IoError(path, MeshIo::tr("the PLY header has no format line"));
    h.bodyOffset = pos;
    return h;
}

/// Finds the face list: "vertex_indices" by the specification, "vertex_index" by some writers.
int plyFaceList(const PlyElement& e)
{
    for (const char* n : {"vertex_indices", "vertex_index"}) {
        const int i = e.find(n);
        if (i >= 0 && e.properties[std::size_t(i)].isList())
            return i;
    }
    return -1;
}

void readPlyBinary(
    const QString& path, const PlyHeader& h, const char* data, std::size_t size, std::int64_t nv, MeshImport& out)
{
    const bool swap = (h.format == PlyFormat::BinaryLittle) != kHostLittleEndian;
    const char* p = data + h.bodyOffset;
    const char* const end = data + size;
    auto truncated = [&](const PlyElement& e) {
        return IoError(path,
            MeshIo::tr("the file is truncated: it ends inside the \"%1\" element").arg(QString::fromStdString(e.name)));
    };
    FaceBuilder faces(path, nv);
    bool sawFaces = false;

    for (const PlyElement& e : h.elements) {
        const std::size_t remaining = static_cast<std::size_t>(end - p);
        const std::size_t minStride = e.minStride();
        if (minStride > 0 && static_cast<std::uint64_t>(e.count) > remaining / minStride)
            throw truncated(e);
        const std::size_t stride = e.fixedStride();

        if (e.name == "vertex") {
            const int ix = e.find("x"), iy = e.find("y"), iz = e.find("z");
            std::array<std::size_t, 3> offset{};
            std::array<PlyType, 3> type{};
            if (stride > 0) {
                std::size_t off = 0;
                for (std::size_t i = 0; i < e.properties.size(); ++i) {
                    for (int k = 0; k < 3; ++k)
                        if (static_cast<int>(i) == std::array<int, 3>{ix, iy, iz}[std::size_t(k)]) {
                            offset[std::size_t(k)] = off;
                            type[std::size_t(k)] = e.properties[i].type;
                        }
                    off += plySize(e.properties[i].type);
                }
                float* pv = out.mesh.vertices.data();
                const bool allFloat = !swap && type[0] == PlyType::Float32 && type[1] == PlyType::Float32
                    && type[2] == PlyType::Float32;
                if (allFloat) {
                    // The common layout: native floats at fixed offsets.
                    for (std::int64_t i = 0; i < e.count; ++i, p += stride, pv += 3) {
                        std::memcpy(pv + 0, p + offset[0], 4);
                        std::memcpy(pv + 1, p + offset[1], 4);
                        std::memcpy(pv + 2, p + offset[2], 4);
                    }
                } else {
                    for (std::int64_t i = 0; i < e.count; ++i, p += stride)
                        for (std::size_t k = 0; k < 3; ++k)
                            *pv++ = static_cast<float>(loadBinary(type[k], p + offset[k], swap));
                }
            } else {
                // Vertices with list properties: walk each row.
                float* pv = out.mesh.vertices.data();
                for (std::int64_t i = 0; i < e.count; ++i) {
                    std::array<double, 3> xyz{};
                    for (std::size_t j = 0; j < e.properties.size(); ++j) {
                        const PlyProperty& prop = e.properties[j];
                        if (prop.isList()) {
                            if (end - p < static_cast<std::ptrdiff_t>(plySize(prop.countType)))
                                throw truncated(e);
                            const std::int64_t n = loadBinaryIndex(prop.countType, p, swap);
                            p += plySize(prop.countType);
                            if (n < 0
                                || static_cast<std::uint64_t>(n) * plySize(prop.type)
                                    > static_cast<std::uint64_t>(end - p))
                                throw truncated(e);
                            p += static_cast<std::size_t>(n) * plySize(prop.type);
                        } else {
                            if (end - p < static_cast<std::ptrdiff_t>(plySize(prop.type)))
                                throw truncated(e);
                            const int ji = static_cast<int>(j);
                            const double value = loadBinary(prop.type, p, swap);
                            if (ji == ix)
                                xyz[0] = value;
                            else if (ji == iy)
                                xyz[1] = value;
                            else if (ji == iz)
                                xyz[2] = value;
                            p += plySize(prop.type);
                        }
                    }
                    for (double c : xyz)
                        *pv++ = static_cast<float>(c);
                }
            }
            continue;
        }

        if (e.name == "face" && !sawFaces) {
            sawFaces = true;
            const int listIndex = plyFaceList(e);
            if (listIndex < 0)
                throw IoError(path, MeshIo::tr("the face element has no vertex_indices list"));
            faces.reserve(e.count);
            const PlyProperty& list = e.properties[std::size_t(listIndex)];
            const bool fast = e.properties.size() == 1 && list.countType == PlyType::UInt8
                && (list.type == PlyType::Int32 || list.type == PlyType::UInt32) && !swap;
            std::int64_t corners[256];
            std::vector<std::int64_t> many;
            if (fast) {
                // The common layout: "list uchar int", mostly triangles.
                for (std::int64_t f = 0; f < e.count; ++f) {
                    if (p >= end)
                        throw truncated(e);
                    const auto n = static_cast<std::uint8_t>(*p++);
                    if (static_cast<std::size_t>(end - p) < std::size_t(n) * 4)
                        throw truncated(e);
                    if (n == 3) {
                        std::int32_t t[3];
                        std::memcpy(t, p, 12);
                        if (list.type == PlyType::UInt32)
                            faces.addTriangle(f, std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2]));
                        else
                            faces.addTriangle(f, t[0], t[1], t[2]);
                    } else {
                        for (std::size_t k = 0; k < n; ++k)
                            corners[k] = loadBinaryIndex(list.type, p + 4 * k, false);
                        faces.addPolygon(f, corners, n);
                    }
                    p += std::size_t(n) * 4;
                }
                continue;
            }
            for (std::int64_t f = 0; f < e.count; ++f) {
                for (std::size_t j = 0; j < e.properties.size(); ++j) {
                    const PlyProperty& prop = e.properties[j];
                    const std::size_t cs = plySize(prop.countType);
                    const std::size_t is = plySize(prop.type);
                    if (!prop.isList()) {
                        if (static_cast<std::size_t>(end - p) < is)
                            throw truncated(e);
                        p += is;
                        continue;
                    }
                    if (static_cast<std::size_t>(end - p) < cs)
                        throw truncated(e);
                    const std::int64_t n = loadBinaryIndex(prop.countType, p, swap);
                    p += cs;
                    if (n < 0 || static_cast<std::uint64_t>(n) * is > static_cast<std::uint64_t>(end - p))
                        throw truncated(e);
                    if (static_cast<int>(j) == listIndex) {
                        many.resize(static_cast<std::size_t>(n));
                        for (std::size_t k = 0; k < many.size(); ++k)
                            many[k] = loadBinaryIndex(prop.type, p + is * k, swap);
                        faces.addPolygon(f, many.data(), many.size());
                    }
                    p += static_cast<std::size_t>(n) * is;
                }
            }
            continue;
        }

        // Any other element (edges, materials, ...) is skipped by size.
        if (stride > 0) {
            p += static_cast<std::size_t>(e.count) * stride;
            continue;
        }
        for (std::int64_t i = 0; i < e.count; ++i)
            for (const PlyProperty& prop : e.properties) {
                const std::size_t cs = plySize(prop.isList() ? prop.countType : prop.type);
                if (static_cast<std::size_t>(end - p) < cs)
                    throw truncated(e);
                if (!prop.isList()) {
                    p += cs;
                    continue;
                }
                const std::int64_t n = loadBinaryIndex(prop.countType, p, swap);
                p += cs;
                const std::size_t bytes = static_cast<std::size_t>(std::max<std::int64_t>(n, 0)) * plySize(prop.type);
                if (n < 0 || bytes > static_cast<std::size_t>(end - p))
                    throw truncated(e);
                p += bytes;
            }
    }
    out.mesh.faces = faces.take();
    if (faces.skipped() > 0)
        out.warnings << skippedFacesWarning(faces.skipped());
}

void readPlyAscii(
    const QString& path, const PlyHeader& h, const char* data, std::size_t size, std::int64_t nv, MeshImport& out)
{
    TextCursor in(path, data + h.bodyOffset, data + size, false);
    FaceBuilder faces(path, nv);
    bool sawFaces = false;
    std::vector<std::int64_t> corners;
    for (const PlyElement& e : h.elements) {
        // Each value takes at least one digit and one separator.
        if (static_cast<double>(e.count) * static_cast<double>(std::max<std::size_t>(e.properties.size(), 1)) * 2
            > static_cast<double>(in.remaining()) + 1)
            throw IoError(path,
                MeshIo::tr("the file is truncated: it ends inside the \"%1\" element")
                    .arg(QString::fromStdString(e.name)));
        const bool isVertex = e.name == "vertex";
        const bool isFace = e.name == "face" && !sawFaces;
        const int ix = e.find("x"), iy = e.find("y"), iz = e.find("z");
        const int listIndex = isFace ? plyFaceList(e) : -1;
        if (isFace) {
            sawFaces = true;
            if (listIndex < 0)
                throw IoError(path, MeshIo::tr("the face element has no vertex_indices list"));
            faces.reserve(e.count);
        }
        float* pv = out.mesh.vertices.data();
        for (std::int64_t i = 0; i < e.count; ++i) {
            for (std::size_t j = 0; j < e.properties.size(); ++j) {
                const PlyProperty& prop = e.properties[j];
                const int ji = static_cast<int>(j);
                if (!prop.isList()) {
                    const double value = in.real(kWhatValue);
                    if (isVertex) {
                        if (ji == ix)
                            pv[3 * i + 0] = toCoordinate(path, value, i);
                        else if (ji == iy)
                            pv[3 * i + 1] = toCoordinate(path, value, i);
                        else if (ji == iz)
                            pv[3 * i + 2] = toCoordinate(path, value, i);
                    }
                    continue;
                }
                const std::int64_t n = in.integer(kWhatCount);
                if (n < 0 || n > static_cast<std::int64_t>(in.remaining()))
                    throw IoError(path,
                        MeshIo::tr("element \"%1\" row %2 has an invalid list length %3")
                            .arg(QString::fromStdString(e.name))
                            .arg(i + 1)
                            .arg(n));
                if (ji == listIndex) {
                    corners.resize(static_cast<std::size_t>(n));
                    for (auto& c : corners)
                        c = in.integer(kWhatIndex);
                    faces.addPolygon(i, corners.data(), corners.size());
                } else {
                    for (std::int64_t k = 0; k < n; ++k)
                        in.real(kWhatValue);
                }
            }
        }
    }
    out.mesh.faces = faces.take();
    if (faces.skipped() > 0)
        out.warnings << skippedFacesWarning(faces.skipped());
}

void readPly(const QString& path, MeshImport& out)
{
    const FileBytes bytes(path);
    const PlyHeader h = readPlyHeader(path, bytes.data(), bytes.size());
    const auto vertexElement
        = std::find_if(h.elements.begin(), h.elements.end(), [](const PlyElement& e) { return e.name == "vertex"; });
    if (vertexElement == h.elements.end())
        throw IoError(path, MeshIo::tr("the PLY file has no vertex element"));
    if (vertexElement->find("x") < 0 || vertexElement->find("y") < 0 || vertexElement->find("z") < 0)
        throw IoError(path, MeshIo::tr("the vertex element lacks an x, y or z property"));
    const std::int64_t nv = vertexElement->count;
    // Reject impossible counts before allocating: each binary vertex row holds at least its
    // properties, each ASCII one at least two characters per property.
    const std::size_t body = bytes.size() - h.bodyOffset;
    const std::size_t rowMin = h.format == PlyFormat::Ascii ? vertexElement->properties.size() * 2
                                                            : std::max<std::size_t>(vertexElement->minStride(), 1);
    if (nv > kMaxIndex || static_cast<std::uint64_t>(nv) > body / rowMin) {
        std::int64_t nf = 0;
        for (const auto& e : h.elements)
            if (e.name == "face")
                nf = e.count;
        throwTooLarge(path, nv, nf);
    }
    out.mesh.vertices.resize(nv, 3);
    if (h.format == PlyFormat::Ascii)
        readPlyAscii(path, h, bytes.data(), bytes.size(), nv, out);
    else
        readPlyBinary(path, h, bytes.data(), bytes.size(), nv, out);
}

// ---------------------------------------------------------------------------------------------
// OBJ through tinyobjloader.

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

/// tinyobjloader reads a coordinate it cannot parse ("nan", "1,5", "x") as 0 without a word; check
/// the "v" lines first so such a file is an error rather than a silently flattened mesh.
void checkObjCoordinates(const QString& path)
{
    const FileBytes bytes(path); // also gives missing and empty files the usual messages
    const char* p = bytes.data();
    const char* const end = p + bytes.size();
    std::int64_t line = 0;
    std::int64_t vertex = 0;
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
        }
        p = eol + 1;
    }
}

void readObj(const QString& path, MeshImport& out)
{
    checkObjCoordinates(path);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn;
    std::string err;
    const QByteArray file = QFile::encodeName(path);
    const QByteArray dir = QFile::encodeName(QFileInfo(path).absolutePath() + QLatin1Char('/'));
    // tinyobjloader's own triangulation skips faces with bad indices (a warning only) and reads
    // positions through them; we check every index first, then fan-triangulate like OFF and PLY.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, file.constData(), dir.constData(),
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
    if (warn.find("not found") != std::string::npos)
        out.warnings << MeshIo::tr("some materials could not be read: %1").arg(firstLine(warn));
}

// ---------------------------------------------------------------------------------------------
// Everything else through Assimp: one TriMesh from all meshes, node transforms applied.

/// Assimp quotes the rest of the file into some messages, newlines shown as '?': keep them short.
QString readableAssimpError(const char* message)
{
    QString text = QString::fromUtf8(message);
    text.replace(QRegularExpression(QStringLiteral("[?\\s]*\\n[?\\s]*|\\?\\s+")), QStringLiteral(" "));
    text.replace(QRegularExpression(QStringLiteral("\"([^\"]{24})[^\"]+\"")), QStringLiteral("\"\\1...\""));
    text = text.simplified();
    if (text.size() > 160)
        text = text.left(157) + QStringLiteral("...");
    return text;
}

void appendNode(const QString& path, const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
    std::vector<float>& positions, std::vector<std::int32_t>& indices, std::vector<std::int32_t>& materials,
    std::int64_t& skipped)
{
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        const auto base = static_cast<std::int64_t>(positions.size() / 3);
        if (base + mesh.mNumVertices > kMaxIndex)
            throw IoError(path, MeshIo::tr("the scene has more vertices than Celform can hold"));
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            positions.insert(positions.end(), {p.x, p.y, p.z});
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) { // points and lines
                ++skipped;
                continue;
            }
            for (unsigned k = 0; k < 3; ++k)
                indices.push_back(static_cast<std::int32_t>(base + face.mIndices[k]));
            materials.push_back(static_cast<std::int32_t>(mesh.mMaterialIndex));
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        appendNode(path, scene, *node.mChildren[c], transform, positions, indices, materials, skipped);
}

void readWithAssimp(const QString& path, const QString& suffix, MeshImport& out)
{
    {
        const FileBytes check(path);
    }
    Assimp::Importer importer;
    // STL repeats each corner with the facet normal; without removing normals the welding
    // below would keep every triangle separate.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
        aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS | aiComponent_TEXCOORDS
            | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS | aiComponent_LIGHTS | aiComponent_CAMERAS);
    const unsigned flags = aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices | aiProcess_Triangulate;
    const aiScene* scene = importer.ReadFile(QFile::encodeName(path).constData(), flags);
    if (!scene || !scene->mRootNode) {
        const QString why = readableAssimpError(importer.GetErrorString());
        throw IoError(path, MeshIo::tr("not a readable %1 file: %2").arg(suffix.toUpper(), why));
    }
    std::vector<float> positions;
    std::vector<std::int32_t> indices;
    std::vector<std::int32_t> materials;
    std::int64_t skipped = 0;
    appendNode(path, *scene, *scene->mRootNode, aiMatrix4x4(), positions, indices, materials, skipped);
    const auto nv = static_cast<Eigen::Index>(positions.size() / 3);
    out.mesh.vertices = Eigen::Map<const algo::Positions>(positions.data(), nv, 3);
    out.mesh.faces = Eigen::Map<const algo::Faces>(indices.data(), static_cast<Eigen::Index>(indices.size() / 3), 3);
    if (skipped > 0)
        out.warnings << (skipped == 1 ? MeshIo::tr("1 point or line ignored")
                                      : MeshIo::tr("%n points or lines ignored", nullptr, static_cast<int>(skipped)));

    if (scene->mNumMaterials > 1) {
        for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
            const aiMaterial& source = *scene->mMaterials[m];
            algo::Material material;
            aiString name;
            if (source.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS)
                material.name = name.C_Str();
            aiColor4D colour;
            if (source.Get(AI_MATKEY_BASE_COLOR, colour) == aiReturn_SUCCESS
                || source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == aiReturn_SUCCESS)
                material.baseColor = Eigen::Vector3f(colour.r, colour.g, colour.b);
            out.mesh.materials.push_back(std::move(material));
        }
        out.mesh.faceMaterials = std::move(materials);
    }
}

// ---------------------------------------------------------------------------------------------

/// Translated counterpart of algo::findFatalDefect(), which the parsers above mostly pre-empt.
void throwIfUnusable(const QString& path, const algo::TriMesh& mesh)
{
    const auto defect = algo::findFatalDefect(mesh);
    if (!defect)
        return;
    if (mesh.vertexCount() == 0)
        throw IoError(path, MeshIo::tr("the file contains no vertices"));
    if (mesh.faceCount() == 0)
        throw IoError(path, MeshIo::tr("the file contains no faces"));
    for (Eigen::Index i = 0; i < mesh.vertexCount(); ++i)
        if (!mesh.vertices.row(i).allFinite())
            throw IoError(path, MeshIo::tr("vertex %1 has a coordinate that is not a finite number").arg(i + 1));
    throw IoError(path, MeshIo::tr("the mesh is unusable: %1").arg(QString::fromStdString(*defect)));
}

QString topologyWarning(const algo::TopologyReport& r)
{
    // "1 hole" is its own message and "%n holes" carries the numerus forms for every other n, so
    // English reads right without a translation file and translators still get plural forms.
    QStringList parts;
    const auto count = [](std::int64_t n) { return static_cast<int>(std::min<std::int64_t>(n, kMaxIndex)); };
    if (r.boundaryLoops == 1)
        parts << MeshIo::tr("1 hole");
    else if (r.boundaryLoops > 1)
        parts << MeshIo::tr("%n holes", nullptr, count(r.boundaryLoops));
    if (r.components > 1)
        parts << MeshIo::tr("%n components", nullptr, count(r.components));
    if (r.nonManifoldEdges == 1)
        parts << MeshIo::tr("1 non-manifold edge");
    else if (r.nonManifoldEdges > 1)
        parts << MeshIo::tr("%n non-manifold edges", nullptr, count(r.nonManifoldEdges));
    if (r.inconsistentEdges == 1)
        parts << MeshIo::tr("1 edge with inconsistent face orientation");
    else if (r.inconsistentEdges > 1)
        parts << MeshIo::tr("%n edges with inconsistent face orientation", nullptr, count(r.inconsistentEdges));
    if (r.degenerateFaces == 1)
        parts << MeshIo::tr("1 degenerate face");
    else if (r.degenerateFaces > 1)
        parts << MeshIo::tr("%n degenerate faces", nullptr, count(r.degenerateFaces));
    return parts.join(MeshIo::tr(", "));
}

void writeObj(const algo::TriMesh& mesh, QSaveFile& file)
{
    // Shortest round-trip float text: re-reading gives the same bits.
    std::string text;
    text.reserve(static_cast<std::size_t>(mesh.vertexCount() * 36 + mesh.faceCount() * 24 + 64));
    text += "# Written by Celform\n";
    char buf[64];
    for (Eigen::Index i = 0; i < mesh.vertexCount(); ++i) {
        text += 'v';
        for (int k = 0; k < 3; ++k) {
            text += ' ';
            const auto r = std::to_chars(buf, buf + sizeof buf, mesh.vertices(i, k));
            text.append(buf, r.ptr);
        }
        text += '\n';
    }
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
        text += 'f';
        for (int k = 0; k < 3; ++k) {
            text += ' ';
            const auto r = std::to_chars(buf, buf + sizeof buf, static_cast<std::int64_t>(mesh.faces(f, k)) + 1);
            text.append(buf, r.ptr);
        }
        text += '\n';
    }
    file.write(text.data(), static_cast<qint64>(text.size()));
}

void writePly(const algo::TriMesh& mesh, QSaveFile& file)
{
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment Written by Celform\nelement vertex "
        + std::to_string(mesh.vertexCount()) + "\nproperty float x\nproperty float y\nproperty float z\nelement face "
        + std::to_string(mesh.faceCount()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<char> body(header.begin(), header.end());
    const std::size_t vbytes = static_cast<std::size_t>(mesh.vertexCount()) * 12;
    body.resize(header.size() + vbytes + static_cast<std::size_t>(mesh.faceCount()) * 13);
    char* p = body.data() + header.size();
    static_assert(kHostLittleEndian, "the PLY writer stores native floats as little-endian");
    if (vbytes > 0)
        std::memcpy(p, mesh.vertices.data(), vbytes); // row-major: x y z per vertex, as PLY wants
    p += vbytes;
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
        *p++ = 3;
        std::memcpy(p, mesh.faces.row(f).data(), 12);
        p += 12;
    }
    file.write(body.data(), static_cast<qint64>(body.size()));
}

} // namespace

MeshImport importMesh(const QString& path)
{
    MeshImport out;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("off"))
        readOff(path, out);
    else if (suffix == QLatin1String("ply"))
        readPly(path, out);
    else if (suffix == QLatin1String("obj"))
        readObj(path, out);
    else if (meshSuffixes().contains(suffix))
        readWithAssimp(path, suffix, out);
    else
        throw IoError(path,
            MeshIo::tr("unknown mesh format \"%1\"; use one of: %2")
                .arg(suffix, meshSuffixes().join(QStringLiteral(", "))));

    throwIfUnusable(path, out.mesh);
    out.topology = algo::analyzeTopology(out.mesh);
    if (!out.topology.isClean())
        out.warnings.prepend(topologyWarning(out.topology));
    return out;
}

QStringList meshSuffixes()
{
    return {QStringLiteral("obj"), QStringLiteral("ply"), QStringLiteral("off"), QStringLiteral("stl"),
        QStringLiteral("gltf"), QStringLiteral("glb"), QStringLiteral("fbx"), QStringLiteral("dae"),
        QStringLiteral("3ds")};
}

QString meshFileFilter()
{
    QStringList patterns;
    for (const QString& s : meshSuffixes())
        patterns << QStringLiteral("*.") + s;
    return MeshIo::tr("Meshes (%1)").arg(patterns.join(QLatin1Char(' ')));
}

void exportMesh(const algo::TriMesh& mesh, const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("obj") && suffix != QLatin1String("ply"))
        throw IoError(path, MeshIo::tr("cannot write \"%1\" files; use .obj or .ply").arg(suffix));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw IoError(path, MeshIo::tr("the file cannot be written: %1").arg(file.errorString()));
    if (suffix == QLatin1String("obj"))
        writeObj(mesh, file);
    else
        writePly(mesh, file);
    if (!file.commit())
        throw IoError(path, MeshIo::tr("the file cannot be written: %1").arg(file.errorString()));
}

} // namespace celform::model
