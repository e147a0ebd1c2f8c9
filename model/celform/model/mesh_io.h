// Mesh import and export. OBJ, PLY and OFF keep the file's vertex order (key deformations made
// in other tools are matched by vertex index); STL is welded; glTF/GLB and FBX go through Assimp.
#pragma once

#include "celform/algorithms/mesh_analysis.h"
#include "celform/algorithms/tri_mesh.h"

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
/// indices. Holes, several components and non-manifold edges only add warnings.
MeshImport importMesh(const QString& path);

/// Suffixes importMesh() understands, lower case without the dot.
QStringList meshSuffixes();
/// A file dialog filter for meshes, translated.
QString meshFileFilter();

/// Writes positions and faces as OBJ or PLY (binary) by suffix, keeping vertex order. The write is
/// atomic. Throws IoError.
void exportMesh(const algo::TriMesh& mesh, const QString& path);

} // namespace celform::model
