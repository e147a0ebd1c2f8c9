// OFF (Geomview) import: "[C][N]OFF", counts, one vertex per line, "n i0 i1 ... [colour]" per face;
// a hand-written parser over the mapped file that keeps the vertex order.
#include "celform/model/io/mesh_io_common.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

namespace celform::model::meshio {

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
    // A vertex takes at least "0 0 0\n", a face at least "3 0 1 2\n". Then the size limits.
    if (nv > kMaxIndex || nf > kMaxIndex
        || static_cast<double>(nv) * 6 + static_cast<double>(nf) * 8 > static_cast<double>(in.remaining()) + 1)
        throwTooLarge(path, nv, nf);
    checkVertexCount(path, nv);
    checkFaceCount(path, nf);

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
        faces.checkPolygon(f, n);
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

} // namespace celform::model::meshio
