// The hidden sub-commands the model runs as its child processes (celform/model/io/import_process.h): each reads
// one untrusted file with a third-party library and writes the result for the parent. They are
// left out of `celform --help` and the README: nobody types them.
#include "cli/command.h"

#include "celform/model/io/image_io.h"
#include "celform/model/io/import_process.h"
#include "celform/model/io/mesh_io.h"

namespace celform::app {
namespace {

int runImportMesh(const Invocation& in)
{
    const QString path = in.argument(0);
    return model::serveImport(path, [&] { model::importMeshForParent(path, in.argument(1)); });
}

int runImportImage(const Invocation& in)
{
    const QString path = in.argument(0);
    return model::serveImport(path, [&] { model::decodeImagesForParent(path, in.argument(1)); });
}

} // namespace

std::vector<SubCommand> importCommands()
{
    // Not translated: only the parent reads them.
    return {
        {"import-mesh", {"celform import-mesh MESH OUT"},
            "Internal: reads a mesh for the editor or another command, which runs this in a child process.",
            {{"MESH", "Mesh file read by a third-party library (glTF, FBX, ...)."},
                {"OUT", "File to write the mesh to, in a private format."}},
            {}, runImportMesh},
        {"import-image", {"celform import-image IN OUT"},
            "Internal: decodes drawings for the editor or another command, which runs this in a child process.",
            {{"IN", "Folder of image files decoded by OpenImageIO (PSD, TIFF, ...)."},
                {"OUT", "Folder to write each image's pixels to, in a private format."}},
            {}, runImportImage},
    };
}

} // namespace celform::app
