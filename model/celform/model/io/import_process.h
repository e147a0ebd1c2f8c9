// Readers of third-party libraries (Assimp's meshes, OpenImageIO's PSD and other formats) run in a
// child process, `celform import-mesh` or `import-image`, under memory and time limits: a crash,
// a hang or a runaway allocation inside them then costs the import, never the open document.
#pragma once

#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>

namespace celform::model {

/// Where importMesh() and decodeImage() run the readers of third-party libraries.
enum class ImportIsolation {
    ChildProcess, ///< in `celform import-mesh` / `import-image`, under importLimits() (the default)
    ThisProcess, ///< in the calling process: the child itself, fuzzing targets, benchmarks
};

/// The bounds of one child process.
struct ImportLimits {
    std::int64_t memoryBytes; ///< address space (RLIMIT_AS)
    int seconds; ///< wall-clock time, from start to exit
};

/// 4 GB and 60 s, or the environment's CELFORM_IMPORT_MEMORY_MB and CELFORM_IMPORT_SECONDS when
/// they hold positive whole numbers (tests lower the time; a studio with huge scenes raises both).
/// The largest drawing image_io accepts (134 million RGBA pixels, a 537 MB PSD) decodes within 4 GB
/// in 34 s on a busy 2-core machine; Assimp's endless loops reach 4 GB in about 6 s.
ImportLimits importLimits();

/// The program run as the child: CELFORM_EXECUTABLE when set; this program when it is celform
/// (the editor and the command line); else the celform of the build tree (test and benchmark
/// programs). Empty when there is none.
QString importProgram();

/// Runs importProgram() with the arguments under importLimits() and waits for it, the time limit
/// once for each of the files it reads. Returns when it exits with 0; otherwise throws IoError
/// naming fileLabel with one line: the problem the child reported for a bad file, or that the
/// importer crashed, ran out of time or needed more memory.
void runImportChild(const QStringList& arguments, const QString& fileLabel, int files = 1);

/// The child's side: runs work (which reads path and writes the result for the parent) and returns
/// the exit code runImportChild() understands, printing an IoError's problem on standard error.
/// An allocation that fails ends the process at once with the out-of-memory code.
int serveImport(const QString& path, const std::function<void()>& work);

} // namespace celform::model
