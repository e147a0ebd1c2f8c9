// Mesh export for exportMesh(): OBJ as shortest round-trip text, PLY as binary little-endian; both
// write positions and faces in the mesh's vertex order.
#include "celform/model/io/mesh_io_common.h"
#include "celform/model/io/output_file.h"

#include <charconv>
#include <cstring>
#include <string>
#include <vector>

namespace celform::model::meshio {

void writeObj(const algo::TriMesh& mesh, OutputFile& file)
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

void writePly(const algo::TriMesh& mesh, OutputFile& file)
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

} // namespace celform::model::meshio
