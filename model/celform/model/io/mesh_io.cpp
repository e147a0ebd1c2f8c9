// Mesh import and export entry points: importMesh() dispatches through the one reader table (which
// also gives meshSuffixes() and the file filter), then checks the mesh; exportMesh() picks a writer.
#include "celform/model/io/mesh_io.h"

#include "celform/model/io/mesh_io_common.h"
#include "celform/model/io/output_file.h"

#include <QFileInfo>

#include <algorithm>
#include <cstdint>
#include <iterator>

namespace celform::model {

namespace {

using meshio::kMaxIndex;

/// One importable suffix: the reader for it, whether that reader keeps the file's vertex order
/// (key deformations made in other tools are matched by vertex index), and whether it runs in a
/// child process (a third-party library: its crashes, hangs and allocations are not ours to fix).
struct MeshReader {
    const char* suffix; ///< lower case, without the dot
    void (*read)(const QString& path, MeshImport& out);
    bool keepsVertexOrder;
    bool inChild;
};

/// The reader table, in the order meshSuffixes() lists the suffixes. STL is welded and the other
/// Assimp formats are rebuilt from its meshes, so only OBJ, PLY and OFF keep vertex order; those
/// three readers are our own and run in this process.
constexpr MeshReader kReaders[] = {
    {"obj", meshio::readObj, true, false},
    {"ply", meshio::readPly, true, false},
    {"off", meshio::readOff, true, false},
    {"stl", meshio::readWithAssimp, false, true},
    {"gltf", meshio::readWithAssimp, false, true},
    {"glb", meshio::readWithAssimp, false, true},
    {"fbx", meshio::readWithAssimp, false, true},
    {"dae", meshio::readWithAssimp, false, true},
    {"3ds", meshio::readWithAssimp, false, true},
};

/// The reader for the file's suffix. Throws IoError for an unknown suffix or anything but a regular file.
const MeshReader& readerFor(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    const auto it = std::find_if(std::begin(kReaders), std::end(kReaders),
        [&](const MeshReader& r) { return suffix == QLatin1String(r.suffix); });
    if (it == std::end(kReaders))
        throw IoError(path,
            MeshIo::tr("unknown mesh format \"%1\"; use one of: %2")
                .arg(suffix, meshSuffixes().join(QStringLiteral(", "))));
    // Before any reader (or Assimp, or tinyobjloader) opens it: a FIFO would block the open for
    // ever, a directory or device would be read without end.
    meshio::requireRegularFile(path);
    return *it;
}

/// Translated counterpart of algo::findFatalDefect(), which the readers mostly pre-empt.
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

} // namespace

MeshImport importMesh(const QString& path, ImportIsolation isolation)
{
    MeshImport out;
    const MeshReader& reader = readerFor(path);
    if (reader.inChild && isolation == ImportIsolation::ChildProcess)
        meshio::readInChild(path, out);
    else
        reader.read(path, out);

    throwIfUnusable(path, out.mesh);
    out.topology = algo::analyseTopology(out.mesh);
    if (!out.topology.isClean())
        out.warnings.prepend(topologyWarning(out.topology));
    return out;
}

void importMeshForParent(const QString& path, const QString& transferPath)
{
    MeshImport out;
    readerFor(path).read(path, out);
    meshio::writeTransfer(out, transferPath);
}

namespace meshio {

void readMeshInOrder(const QString& path, MeshImport& out)
{
    const MeshReader& reader = readerFor(path);
    if (!reader.keepsVertexOrder)
        throw IoError(path,
            MeshIo::tr("\"%1\" files do not keep their vertex order; use .obj, .ply or .off")
                .arg(QFileInfo(path).suffix().toLower()));
    reader.read(path, out);
    throwIfUnusable(path, out.mesh);
}

} // namespace meshio

QStringList meshSuffixes()
{
    QStringList suffixes;
    for (const MeshReader& r : kReaders)
        suffixes << QLatin1String(r.suffix);
    return suffixes;
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
    OutputFile file(path); // whole or not at all; every write checked (issue 27)
    if (suffix == QLatin1String("obj"))
        meshio::writeObj(mesh, file);
    else
        meshio::writePly(mesh, file);
    file.commit();
}

} // namespace celform::model
