// Mesh import and export. OBJ, PLY and OFF keep the file's vertex order (key deformations made
// in other tools are matched by vertex index); STL is welded; glTF/GLB and FBX go through Assimp,
// in a child process (import_process.h).
#pragma once

#include "celform/algorithms/mesh_analysis.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/io/import_process.h"

#include <QString>
#include <QStringList>

namespace celform::model {

struct MeshImport {
    algo::TriMesh mesh;
    algo::TopologyReport topology;
    /// Translated, user-facing warnings ("3 holes, 2 components"); empty for a clean mesh.
    QStringList warnings;
};

/// Reads a mesh file, triangulating polygons. Throws IoError naming the file and the problem for
/// a missing, empty, unparseable or truncated file, non-finite coordinates or out-of-range
/// indices. Holes, several components and non-manifold edges only add warnings. The formats read
/// by Assimp are read in a child process unless isolation says otherwise: a crash, hang or huge
/// allocation inside Assimp is then an IoError too ("the importer crashed on it (signal 11, ...)").
MeshImport importMesh(const QString& path, ImportIsolation isolation = ImportIsolation::ChildProcess);

/// The child's half of importMesh() (`celform import-mesh MESH OUT`): reads the mesh file in this
/// process, as importMesh() with ImportIsolation::ThisProcess would before its checks, and writes
/// the mesh and the reader's warnings to transferPath for the parent. Throws IoError.
void importMeshForParent(const QString& path, const QString& transferPath);

/// Suffixes importMesh() understands, lower case without the dot.
QStringList meshSuffixes();
/// A file dialog filter for meshes, translated.
QString meshFileFilter();

/// Writes positions and faces as OBJ or PLY (binary) by suffix, keeping vertex order. The write is
/// atomic. Throws IoError.
void exportMesh(const algo::TriMesh& mesh, const QString& path);

} // namespace celform::model
