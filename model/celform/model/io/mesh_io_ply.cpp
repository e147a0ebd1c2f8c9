// PLY import, ASCII and binary (either byte order): a header of elements and typed properties, then
// the rows, parsed by hand over the mapped file; vertex order kept, other elements skipped.
#include "celform/model/io/mesh_io_common.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace celform::model::meshio {

namespace {

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
    std::int64_t headerLine = 0; ///< for messages about the element as a whole

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

/// Reads one binary value of type t at p and hands it, in its own C++ type, to use: the one switch
/// over the PLY types, shared by the value and the index readers below. Returns fallback for Invalid.
template <typename Result, typename Use>
Result visitBinary(PlyType t, const char* p, bool swap, Result fallback, Use use)
{
    switch (t) {
    case PlyType::Int8:
        return use(static_cast<std::int8_t>(*p));
    case PlyType::UInt8:
        return use(static_cast<std::uint8_t>(*p));
    case PlyType::Int16:
        return use(loadRaw<std::int16_t>(p, swap));
    case PlyType::UInt16:
        return use(loadRaw<std::uint16_t>(p, swap));
    case PlyType::Int32:
        return use(loadRaw<std::int32_t>(p, swap));
    case PlyType::UInt32:
        return use(loadRaw<std::uint32_t>(p, swap));
    case PlyType::Float32:
        return use(loadRaw<float>(p, swap));
    case PlyType::Float64:
        return use(loadRaw<double>(p, swap));
    case PlyType::Invalid:
        break;
    }
    return fallback;
}

double loadBinary(PlyType t, const char* p, bool swap)
{
    return visitBinary(t, p, swap, 0.0, [](auto v) { return static_cast<double>(v); });
}

/// A count or an index stored as a float (the format allows it): its whole part, or -1 (which every
/// caller refuses) when it is negative, not a number or beyond 2^53. Converting 6.75e25 to an
/// integer is undefined behaviour (found by fuzz_ply under UBSan).
template <typename Float> std::int64_t floatIndex(Float value)
{
    if (!(value >= Float(0) && value < Float(std::int64_t(1) << 53)))
        return -1;
    return static_cast<std::int64_t>(value);
}

std::int64_t loadBinaryIndex(PlyType t, const char* p, bool swap)
{
    return visitBinary(t, p, swap, std::int64_t(-1), [](auto v) -> std::int64_t {
        if constexpr (std::is_floating_point_v<decltype(v)>)
            return floatIndex(v);
        else
            return static_cast<std::int64_t>(v);
    });
}

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
            // The readers size the vertex array by the one "vertex" element and take faces from
            // the one "face" element: a second "vertex" would write past that array and a second
            // "face" would be dropped without a word, so either is refused.
            const std::string_view name = w[1];
            if ((name == "vertex" || name == "face")
                && std::any_of(
                    h.elements.begin(), h.elements.end(), [&](const PlyElement& e) { return e.name == name; }))
                throw bad(MeshIo::tr("a second \"%1\" element (a PLY file has one)")
                              .arg(QString::fromUtf8(name.data(), int(name.size()))));
            h.elements.push_back({std::string(name), count, {}, lineNo});
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
    // Rows without properties take no bytes, so no file size bounds their count, and the readers
    // would step through every one of them (10^19 is a hang). They carry nothing: refused.
    for (const PlyElement& e : h.elements)
        if (e.count > 0 && e.properties.empty())
            throw IoError(path,
                MeshIo::tr("PLY header line %1: %2")
                    .arg(e.headerLine)
                    .arg(MeshIo::tr("element \"%1\" has %2 rows but no properties")
                             .arg(QString::fromStdString(e.name))
                             .arg(e.count)));
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

    for (const PlyElement& e : h.elements) {
        const std::size_t remaining = static_cast<std::size_t>(end - p);
        // Every row takes at least one byte (the header refuses rows without properties), so the
        // count is always checked against the bytes left, never skipped.
        const std::size_t minStride = std::max<std::size_t>(e.minStride(), 1);
        if (static_cast<std::uint64_t>(e.count) > remaining / minStride)
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

        if (e.name == "face") {
            const int listIndex = plyFaceList(e);
            if (listIndex < 0)
                throw IoError(path, MeshIo::tr("the face element has no vertex_indices list"));
            const PlyProperty& list = e.properties[std::size_t(listIndex)];
            // Reserve for the triangles the bytes left can hold, not for the count: rows with
            // fewer than three corners are smaller than a triangle and give none.
            const std::size_t triangleRow = minStride + 3 * plySize(list.type);
            faces.reserve(std::min<std::int64_t>(e.count, static_cast<std::int64_t>(remaining / triangleRow)));
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
                        faces.checkPolygon(f, n);
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
    std::vector<std::int64_t> corners;
    for (const PlyElement& e : h.elements) {
        // Each value takes at least one digit and one separator.
        if (static_cast<double>(e.count) * static_cast<double>(std::max<std::size_t>(e.properties.size(), 1)) * 2
            > static_cast<double>(in.remaining()) + 1)
            throw IoError(path,
                MeshIo::tr("the file is truncated: it ends inside the \"%1\" element")
                    .arg(QString::fromStdString(e.name)));
        const bool isVertex = e.name == "vertex";
        const bool isFace = e.name == "face";
        const int ix = e.find("x"), iy = e.find("y"), iz = e.find("z");
        const int listIndex = isFace ? plyFaceList(e) : -1;
        if (isFace) {
            if (listIndex < 0)
                throw IoError(path, MeshIo::tr("the face element has no vertex_indices list"));
            // As many triangles as the text left can hold ("3 0 1 2" and a separator), at most.
            faces.reserve(std::min<std::int64_t>(e.count, static_cast<std::int64_t>(in.remaining() / 8)));
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
                    faces.checkPolygon(i, n);
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

} // namespace

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
    std::int64_t nf = 0;
    for (const auto& e : h.elements)
        if (e.name == "face")
            nf = e.count;
    // Reject impossible counts before allocating: each binary vertex row holds at least its
    // properties, each ASCII one at least two characters per property. Then the size limits.
    const std::size_t body = bytes.size() - h.bodyOffset;
    const std::size_t rowMin = h.format == PlyFormat::Ascii ? vertexElement->properties.size() * 2
                                                            : std::max<std::size_t>(vertexElement->minStride(), 1);
    if (nv > kMaxIndex || static_cast<std::uint64_t>(nv) > body / rowMin)
        throwTooLarge(path, nv, nf);
    checkVertexCount(path, nv);
    checkFaceCount(path, nf);
    out.mesh.vertices.resize(nv, 3);
    if (h.format == PlyFormat::Ascii)
        readPlyAscii(path, h, bytes.data(), bytes.size(), nv, out);
    else
        readPlyBinary(path, h, bytes.data(), bytes.size(), nv, out);
}

} // namespace celform::model::meshio
