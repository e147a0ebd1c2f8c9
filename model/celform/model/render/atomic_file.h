// Files written whole or not at all: a temporary file beside the target, synced, then renamed
// over it (the render writers, DESIGN.md, "Rendering"; docs/farm.md: farm nodes share folders).
#pragma once

#include <QByteArray>
#include <QString>

namespace celform::model {

/// Makes a new empty file beside path, with the same suffix (OpenImageIO picks the format by
/// it), and returns its name. The name holds the host, the process and a counter, and the file
/// is created exclusively: threads and farm nodes writing into one shared folder never write into
/// each other's file. A file left by a killed process is hidden (a dot) and never has the target's
/// name. Throws IoError naming path when the folder does not take the file.
QString createTemporaryBeside(const QString& path);

/// Puts the finished temporary file in path's place. Its bytes go to the disk first: after a
/// crash of the machine the target holds the old file or the whole new one, never an empty one.
/// Removes the temporary file and throws IoError naming path when that fails.
void commitTemporary(const QString& temporary, const QString& path);

/// Writes bytes to path atomically (the two steps above). Throws IoError naming path.
void writeFileAtomically(const QString& path, const QByteArray& bytes);

} // namespace celform::model
