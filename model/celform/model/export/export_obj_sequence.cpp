// An OBJ mesh per frame (export.h): the blended shape with the base model's faces, written by
// exportMesh (shortest round-trip floats, atomically), one file per frame named like a rendered
// sequence.
#include "celform/model/export/export.h"

#include "celform/model/io/mesh_io.h"

namespace celform::model::exporting {

void writeObjSequence(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result)
{
    FrameWalk walk(data, source, job, progress);
    algo::TriMesh mesh;
    mesh.faces = walk.faces();
    while (walk.next()) {
        // Same size every frame: the assignment copies into the rows already there.
        mesh.vertices = walk.shape();
        const QString path = job.framePath(walk.frame());
        exportMesh(mesh, path);
        result.files << path;
        ++result.frames;
    }
    result.cancelled = walk.cancelled();
}

} // namespace celform::model::exporting
