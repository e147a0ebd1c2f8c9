// Files written whole or not at all (issue 27): every output of Celform (projects, rendered frames,
// exports, meshes, analysis files) goes through OutputFile, so a full disk, a quota or a failing
// device is an error naming the file and the system's reason, and never a short file at the target.
#pragma once

#include <QByteArray>
#include <QString>

namespace celform::model {

/// What OutputFile::commit() promises beyond "the old file or the whole new one for every reader".
enum class Durability {
    /// The bytes reach the disk before the rename: after a crash of the machine too, the target
    /// holds the old file or the whole new one (projects, exports).
    Synced,
    /// No fsync: a rendered frame (issue 29; a flush per frame costs more than its encoding on a
    /// network share). A crash of the machine can leave a short frame, which `render
    /// --skip-existing` finds and renders again.
    Renamed,
};

/// A file written to a temporary file in its target's folder (unnamed, O_TMPFILE, until it is
/// complete; else hidden), each write checked, then flushed
/// to the disk, closed (checked) and renamed over the target. Until commit() the target is as it
/// was; a failure or a destruction without commit() removes the temporary file. A target that exists
/// and is no regular file (a device such as /dev/null or /dev/full, a named pipe) is written in place,
/// since renaming over it would replace the device. Through a symbolic link the file it names is
/// replaced and the link stays. A replaced file's permissions pass to the new one.
class OutputFile {
public:
    /// Creates the temporary file (exclusively: threads and farm nodes writing into one folder never
    /// share one). Throws IoError naming path when the folder does not take it.
    explicit OutputFile(const QString& path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    /// Appends the bytes. Throws IoError naming the target with the system's reason ("No space left
    /// on device"); the temporary file is removed.
    void write(const void* data, qint64 size);
    void write(const QByteArray& bytes) { write(bytes.constData(), bytes.size()); }

    /// Puts the file in the target's place: its bytes reach the disk first, so after a crash of the
    /// machine the target holds the old file or the whole new one. Throws IoError naming the target.
    void commit(Durability durability = Durability::Synced);
    /// Drops what was written; the target stays as it was.
    void cancel();

    /// The target as given.
    [[nodiscard]] const QString& path() const { return m_path; }
    /// The file replaced: the target, or the file a symbolic link names.
    [[nodiscard]] const QString& target() const { return m_target; }
    /// Bytes written so far.
    [[nodiscard]] qint64 size() const { return m_size; }

private:
    [[noreturn]] void fail(int error);
    [[nodiscard]] QString temporaryName() const;

    QString m_path;
    QString m_target;
    QString m_temporary; // the named temporary file; empty while unnamed and when written in place
    bool m_unnamed = false; // an O_TMPFILE file, named at commit()
    int m_fd = -1;
    qint64 m_size = 0;
};

/// Writes bytes to path whole or not at all (OutputFile). Throws IoError naming path.
void writeWholeFile(const QString& path, const QByteArray& bytes, Durability durability = Durability::Synced);
void writeWholeFile(const QString& path, const void* data, qint64 size, Durability durability = Durability::Synced);

} // namespace celform::model
