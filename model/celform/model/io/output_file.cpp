// OutputFile: a temporary file beside the target, checked writes, fsync, close and rename.
#include "celform/model/io/output_file.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace celform::model {
namespace {

struct OutputFileText {
    Q_DECLARE_TR_FUNCTIONS(celform::model::OutputFile)
};

QString writeProblem(int error)
{
    return OutputFileText::tr("could not be written: %1").arg(qt_error_string(error));
}

/// The file a symbolic link names (the link itself when it does not resolve to anything).
QString resolvedTarget(const QString& path)
{
    const QFileInfo info(path);
    if (!info.isSymLink())
        return path;
    return info.exists() ? info.canonicalFilePath() : info.symLinkTarget();
}

} // namespace

OutputFile::OutputFile(const QString& path)
    : m_path(path)
    , m_target(resolvedTarget(path))
{
    const QByteArray target = QFile::encodeName(m_target);
    struct stat existing { };
    const bool exists = ::stat(target.constData(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode))
        throw IoError(m_path, writeProblem(EISDIR));
    if (exists && !S_ISREG(existing.st_mode)) {
        m_fd = ::open(target.constData(), O_WRONLY | O_CLOEXEC);
        if (m_fd < 0)
            throw IoError(m_path, writeProblem(errno));
        return;
    }
    // An unnamed file in the target's folder (O_TMPFILE): a process killed while writing leaves
    // nothing behind; it gets a name just before the rename. Named from the start where the file
    // system or a missing /proc does not allow that.
    const QFileInfo info(m_target);
    const QByteArray folder = QFile::encodeName(info.absolutePath());
#ifdef O_TMPFILE
    if (::access("/proc/self/fd", X_OK) == 0) {
        m_fd = ::open(folder.constData(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
        if (m_fd >= 0)
            m_unnamed = true;
        else if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL && errno != ENOENT)
            throw IoError(m_path, writeProblem(errno));
    }
#endif
    if (!m_unnamed) {
        for (int attempt = 0;; ++attempt) {
            m_temporary = temporaryName();
            // 0666 less the umask, as a new file would be; a replaced file's mode below.
            m_fd = ::open(QFile::encodeName(m_temporary).constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (m_fd >= 0)
                break;
            const int error = errno;
            if (error != EEXIST || attempt >= 100) {
                m_temporary.clear();
                throw IoError(m_path, writeProblem(error));
            }
        }
    }
    if (exists && ::fchmod(m_fd, existing.st_mode & 07777) != 0)
        fail(errno);
}

QString OutputFile::temporaryName() const
{
    // Hidden, named after the target, the host, the process and a counter; never the target's name.
    static std::atomic<unsigned> counter{0};
    const QFileInfo info(m_target);
    const QString owner = QStringLiteral("%1-%2").arg(QSysInfo::machineHostName()).arg(::getpid());
    return info.dir().filePath(QStringLiteral(".%1.%2-%3.tmp.%4")
                                   .arg(info.completeBaseName(), owner)
                                   .arg(counter.fetch_add(1))
                                   .arg(info.suffix()));
}

OutputFile::~OutputFile()
{
    cancel();
}

void OutputFile::fail(int error)
{
    cancel();
    throw IoError(m_path, writeProblem(error));
}

void OutputFile::write(const void* data, qint64 size)
{
    if (m_fd < 0)
        throw IoError(m_path, writeProblem(EBADF));
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        // A short count is followed by another write, which reports the reason (ENOSPC, EFBIG, EIO).
        const ssize_t n = ::write(m_fd, p, std::size_t(std::min<qint64>(size, qint64(1) << 30)));
        if (n < 0) {
            if (errno == EINTR)
                continue;
            fail(errno);
        }
        if (n == 0)
            fail(ENOSPC);
        p += n;
        size -= n;
        m_size += n;
    }
}

void OutputFile::commit(Durability durability)
{
    if (m_fd < 0)
        throw IoError(m_path, writeProblem(EBADF));
    // A device or a pipe may not sync (EINVAL, EROFS): only a regular file's sync is required.
    if (durability == Durability::Synced && ::fsync(m_fd) != 0
        && (m_unnamed || !m_temporary.isEmpty() || (errno != EINVAL && errno != EROFS)))
        fail(errno);
    // The unnamed file gets its hidden name now, from its descriptor; a kill from here to the
    // rename leaves that file, complete, beside the target.
    if (m_unnamed) {
        const QByteArray self = QByteArrayLiteral("/proc/self/fd/") + QByteArray::number(m_fd);
        for (int attempt = 0;; ++attempt) {
            m_temporary = temporaryName();
            if (::linkat(
                    AT_FDCWD, self.constData(), AT_FDCWD, QFile::encodeName(m_temporary).constData(), AT_SYMLINK_FOLLOW)
                == 0)
                break;
            const int error = errno;
            m_temporary.clear();
            if (error != EEXIST || attempt >= 100)
                fail(error);
        }
        m_unnamed = false;
    }
    // close() may report a write the file system deferred (NFS, quotas).
    const int fd = m_fd;
    m_fd = -1;
    if (::close(fd) != 0 && errno != EINTR)
        fail(errno);
    if (m_temporary.isEmpty())
        return;
    if (std::rename(QFile::encodeName(m_temporary).constData(), QFile::encodeName(m_target).constData()) != 0)
        fail(errno);
    m_temporary.clear();
}

void OutputFile::cancel()
{
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
    m_unnamed = false;
    if (!m_temporary.isEmpty()) {
        ::unlink(QFile::encodeName(m_temporary).constData());
        m_temporary.clear();
    }
}

void writeWholeFile(const QString& path, const void* data, qint64 size, Durability durability)
{
    OutputFile file(path);
    file.write(data, size);
    file.commit(durability);
}

void writeWholeFile(const QString& path, const QByteArray& bytes, Durability durability)
{
    writeWholeFile(path, bytes.constData(), bytes.size(), durability);
}

} // namespace celform::model
