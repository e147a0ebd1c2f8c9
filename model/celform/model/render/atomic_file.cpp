// Files written whole or not at all (atomic_file.h).
#include "celform/model/render/atomic_file.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>

#include <atomic>
#include <cerrno>
#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

namespace celform::model {
namespace {

// The render writers' context, so their translations stay.
struct RenderOutput {
    Q_DECLARE_TR_FUNCTIONS(celform::model::RenderOutput)
};

} // namespace

QString createTemporaryBeside(const QString& path)
{
    static std::atomic<unsigned> counter{0};
    const QFileInfo info(path);
    const QString owner = QStringLiteral("%1-%2").arg(QSysInfo::machineHostName()).arg(::getpid());
    for (int attempt = 0;; ++attempt) {
        const QString name = info.dir().filePath(QStringLiteral(".%1.%2-%3.tmp.%4")
                                                     .arg(info.completeBaseName(), owner)
                                                     .arg(counter.fetch_add(1))
                                                     .arg(info.suffix()));
        // 0666 less the umask, as OpenImageIO would create the file.
        const int fd = ::open(QFile::encodeName(name).constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return name;
        }
        if (errno != EEXIST || attempt >= 100)
            throw IoError(path, RenderOutput::tr("could not be written: %1").arg(qt_error_string(errno)));
    }
}

void commitTemporary(const QString& temporary, const QString& path)
{
    const QByteArray from = QFile::encodeName(temporary);
    const int fd = ::open(from.constData(), O_RDONLY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::fsync(fd) == 0;
    const int syncError = errno;
    if (fd >= 0)
        ::close(fd);
    if (!synced) {
        QFile::remove(temporary);
        throw IoError(path, RenderOutput::tr("could not be written: %1").arg(qt_error_string(syncError)));
    }
    if (std::rename(from.constData(), QFile::encodeName(path).constData()) != 0) {
        const int renameError = errno;
        QFile::remove(temporary);
        throw IoError(path, RenderOutput::tr("could not be written: %1").arg(qt_error_string(renameError)));
    }
}

void writeFileAtomically(const QString& path, const QByteArray& bytes)
{
    const QString temporary = createTemporaryBeside(path);
    QFile file(temporary);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size() || !file.flush()) {
        const QString problem = file.errorString();
        file.close();
        QFile::remove(temporary);
        throw IoError(path, RenderOutput::tr("could not be written: %1").arg(problem));
    }
    file.close();
    commitTemporary(temporary, path);
}

} // namespace celform::model
