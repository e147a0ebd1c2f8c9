// OBJ import through tinyobjloader, after a check of the "v" lines it would read as 0; vertex order,
// UVs and materials kept, polygons fan-triangulated like OFF and PLY.
#include "celform/model/mesh_io_common.h"

#include <tiny_obj_loader.h>

#include <QFileInfo>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
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

} // namespace

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

} // namespace celform::model::meshio
