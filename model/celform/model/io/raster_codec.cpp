// Finding and loading the OpenImageIO module (raster_codec.h) the first time a raster image is
// read or written.
#include "celform/model/io/raster_codec.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLibrary>

#include <dlfcn.h>
#include <link.h>

namespace celform::model {
namespace {

struct RasterModule {
    Q_DECLARE_TR_FUNCTIONS(celform::model::RasterModule)
};

struct Loaded {
    const RasterCodec* codec = nullptr;
    QString problem;
};

/// The folder of the program or shared library this code was linked into.
QString folderOfThisCode()
{
    // A shared library's link map names the file it was loaded from; the program's is empty (and
    // dladdr's name for it is argv[0], which may be a bare name found on PATH).
    Dl_info info{};
    link_map* map = nullptr;
    if (dladdr1(
            reinterpret_cast<const void*>(&folderOfThisCode), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP)
            != 0
        && map && map->l_name && *map->l_name)
        return QFileInfo(QFile::decodeName(map->l_name)).absolutePath();
    const QString program = QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath();
    return program.isEmpty() ? QString() : QFileInfo(program).absolutePath();
}

Loaded load()
{
    const QString name = QStringLiteral(CELFORM_RASTER_MODULE);
    QStringList candidates;
    if (const QString here = folderOfThisCode(); !here.isEmpty())
        candidates << QDir(here).filePath(name) << QDir::cleanPath(here + QStringLiteral("/../lib/celform/") + name);
    // Test and benchmark programs run from the build tree, away from the module.
    candidates << QDir(QStringLiteral(CELFORM_RASTER_MODULE_BUILD_DIR)).filePath(name);
    Loaded loaded;
    for (const QString& candidate : candidates) {
        if (!QFileInfo::exists(candidate))
            continue;
        // Never unloaded: the images it decodes hold no pointers into it, but OpenImageIO's
        // plug-ins and threads stay until the process ends.
        QLibrary library(candidate);
        if (!library.load()) {
            loaded.problem = library.errorString();
            return loaded;
        }
        const auto entry = reinterpret_cast<RasterCodecEntry>(library.resolve(kRasterCodecEntry));
        loaded.codec = entry ? entry() : nullptr;
        if (!loaded.codec)
            loaded.problem = library.errorString();
        return loaded;
    }
    loaded.problem = RasterModule::tr("%1 is not in %2").arg(name, candidates.join(QStringLiteral(", ")));
    return loaded;
}

} // namespace

const RasterCodec& rasterCodec(const QString& fileLabel)
{
    static const Loaded loaded = load(); // thread-safe, once
    if (!loaded.codec)
        throw IoError(fileLabel,
            RasterModule::tr("raster images cannot be read or written: the OpenImageIO module cannot be loaded (%1)")
                .arg(loaded.problem));
    return *loaded.codec;
}

} // namespace celform::model
