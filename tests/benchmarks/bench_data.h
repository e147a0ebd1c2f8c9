// Shared meshes of the benchmarks, loaded once per program; null when ../shared is absent.
#pragma once

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/io/mesh_io.h"

#include <QDir>
#include <QFileInfo>

#include <map>
#include <memory>
#include <string>

namespace celform::bench {

/// A mesh under ../shared/data (for example "meshes/stanford_dragon.ply"), imported on first use.
inline const algo::TriMesh* sharedMesh(const char* relative)
{
    static std::map<std::string, std::unique_ptr<algo::TriMesh>> cache;
    auto& slot = cache[relative];
    if (!slot) {
        const QString path = QDir(QStringLiteral(CELFORM_SHARED_DATA_DIR)).filePath(QString::fromUtf8(relative));
        if (!QFileInfo::exists(path))
            return nullptr;
        slot = std::make_unique<algo::TriMesh>(model::importMesh(path).mesh);
    }
    return slot.get();
}

inline const algo::TriMesh* dragon()
{
    return sharedMesh("meshes/stanford_dragon.ply");
}

} // namespace celform::bench
