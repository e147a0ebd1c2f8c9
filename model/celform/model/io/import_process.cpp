// Both halves of an isolated import (import_process.h): the parent starts `celform import-...` with
// its limits and turns how it ended into one line naming the file; the child reports what it can.
#include "celform/model/io/import_process.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QProcess>
#include <QProcessEnvironment>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <new>

#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

// Whether this build runs under AddressSanitizer (GCC defines the first, Clang answers the second).
#if defined(__SANITIZE_ADDRESS__)
#define CELFORM_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CELFORM_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef CELFORM_ADDRESS_SANITIZER
#define CELFORM_ADDRESS_SANITIZER 0
#endif

namespace celform::model {
namespace {

// Gives lupdate the context "celform::model::ImportProcess" for every ImportProcess::tr() below.
struct ImportProcess {
    Q_DECLARE_TR_FUNCTIONS(celform::model::ImportProcess)
};

constexpr std::int64_t kMegabyte = std::int64_t(1) << 20;
constexpr std::int64_t kDefaultMemoryBytes = std::int64_t(4) << 30;
constexpr int kDefaultSeconds = 60;

// The child's exit codes besides 0.
constexpr int kExitRefused = 3; ///< a bad file: the problem is on standard error
constexpr int kExitOutOfMemory = 4; ///< an allocation failed under the memory limit

/// A positive whole number from the environment, or fallback.
std::int64_t environmentNumber(const char* name, std::int64_t fallback)
{
    bool ok = false;
    const qint64 value = qEnvironmentVariable(name).trimmed().toLongLong(&ok);
    return ok && value > 0 ? value : fallback;
}

QString memoryText(std::int64_t bytes)
{
    constexpr std::int64_t gigabyte = std::int64_t(1) << 30;
    if (bytes % gigabyte == 0)
        return ImportProcess::tr("%1 GB").arg(bytes / gigabyte);
    return ImportProcess::tr("%1 MB").arg(bytes / kMegabyte);
}

/// The child's report, one line: the last non-empty line of its standard error.
QString lastLine(const QByteArray& output)
{
    const QStringList lines = QString::fromUtf8(output).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (auto it = lines.crbegin(); it != lines.crend(); ++it)
        if (!it->trimmed().isEmpty())
            return it->trimmed();
    return {};
}

void writeLine(const QString& line)
{
    QString text = line;
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    const QByteArray bytes = text.toUtf8() + '\n';
    std::fflush(stderr);
    [[maybe_unused]] const auto written = ::write(STDERR_FILENO, bytes.constData(), std::size_t(bytes.size()));
}

} // namespace

ImportLimits importLimits()
{
    return {environmentNumber("CELFORM_IMPORT_MEMORY_MB", kDefaultMemoryBytes / kMegabyte) * kMegabyte,
        int(std::min<std::int64_t>(environmentNumber("CELFORM_IMPORT_SECONDS", kDefaultSeconds), 24 * 3600))};
}

QString importProgram()
{
    const QString configured = qEnvironmentVariable("CELFORM_EXECUTABLE");
    if (!configured.isEmpty())
        return configured;
    // /proc/self/exe rather than applicationFilePath(): no QCoreApplication is needed.
    const QString self = QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath();
    if (QFileInfo(self).fileName() == QLatin1String("celform"))
        return self;
#ifdef CELFORM_BUILD_EXECUTABLE
    if (QFileInfo(QStringLiteral(CELFORM_BUILD_EXECUTABLE)).isExecutable())
        return QStringLiteral(CELFORM_BUILD_EXECUTABLE);
#endif
    return {};
}

void runImportChild(const QStringList& arguments, const QString& fileLabel, int files)
{
    const QString program = importProgram();
    if (program.isEmpty())
        throw IoError(fileLabel,
            ImportProcess::tr(
                "cannot be read: the importer (the celform program) was not found; set CELFORM_EXECUTABLE"));
    ImportLimits limits = importLimits();
    limits.seconds = int(std::min<std::int64_t>(std::int64_t(limits.seconds) * std::max(files, 1), 24 * 3600));
    QProcess process;
    process.setProgram(program);
    process.setArguments(arguments);
    process.setStandardInputFile(QProcess::nullDevice());
    process.setStandardOutputFile(QProcess::nullDevice());
#if CELFORM_ADDRESS_SANITIZER
    // AddressSanitizer reserves terabytes of address space for its shadow memory, so a child
    // under RLIMIT_AS cannot even start: the sanitizer's own allocator enforces the limit instead,
    // failing an allocation beyond it (std::bad_alloc, then kExitOutOfMemory as without ASan).
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    const QString megabytes = QString::number(limits.memoryBytes / kMegabyte);
    QString asanOptions = environment.value(QStringLiteral("ASAN_OPTIONS"));
    if (!asanOptions.isEmpty())
        asanOptions += QLatin1Char(':');
    asanOptions
        += QStringLiteral("allocator_may_return_null=1:max_allocation_size_mb=%1:soft_rss_limit_mb=%1").arg(megabytes);
    environment.insert(QStringLiteral("ASAN_OPTIONS"), asanOptions);
    process.setProcessEnvironment(environment);
    constexpr bool limitAddressSpace = false;
#else
    constexpr bool limitAddressSpace = true;
#endif
    // Runs in the child between fork and exec: only system calls here.
    process.setChildProcessModifier([limits] {
        // Never above a limit this process was given (raising a hard limit fails).
        if (limitAddressSpace) {
            rlimit memory{};
            ::getrlimit(RLIMIT_AS, &memory);
            memory.rlim_cur = std::min(memory.rlim_max, rlim_t(limits.memoryBytes));
            memory.rlim_max = memory.rlim_cur;
            ::setrlimit(RLIMIT_AS, &memory);
        }
        // A backstop should the parent be stopped: the parent's clock is the real bound (threads
        // may spend CPU time faster than wall-clock time passes).
        const rlim_t cpu = rlim_t(limits.seconds) * 2 + 5;
        const rlimit time{cpu, cpu + 5};
        ::setrlimit(RLIMIT_CPU, &time);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // an editor that crashes takes its importer along
    });
    process.start();
    if (!process.waitForStarted(-1))
        throw IoError(fileLabel,
            ImportProcess::tr("cannot be read: the importer (%1) cannot be started: %2")
                .arg(program, process.errorString()));
    if (!process.waitForFinished(limits.seconds * 1000)) {
        process.kill();
        process.waitForFinished(-1);
        throw IoError(fileLabel,
            ImportProcess::tr(
                "the importer took longer than %1 s and was stopped (the limit is CELFORM_IMPORT_SECONDS)")
                .arg(limits.seconds));
    }
    if (process.exitStatus() == QProcess::CrashExit) {
#if CELFORM_ADDRESS_SANITIZER
        // Under AddressSanitizer, operator new beyond the limit ends the child with a fatal report
        // (it never throws std::bad_alloc): the report says which.
        const QByteArray report = process.readAllStandardError();
        if (report.contains("AddressSanitizer: out-of-memory") || report.contains("allocator is out of memory")
            || report.contains("allocation-size-too-big") || report.contains("rss limit"))
            throw IoError(fileLabel,
                ImportProcess::tr("the importer needs more than %1 of memory for it and was stopped (the limit is "
                                  "CELFORM_IMPORT_MEMORY_MB)")
                    .arg(memoryText(limits.memoryBytes)));
#endif
        // On Unix a crashed child's exit code is the signal that ended it.
        const int signal = process.exitCode();
        if (signal == SIGXCPU)
            throw IoError(fileLabel,
                ImportProcess::tr("the importer used more than %1 s of processor time and was stopped")
                    .arg(limits.seconds * 2 + 5));
        const char* name = ::sigdescr_np(signal);
        throw IoError(fileLabel,
            ImportProcess::tr("the importer crashed on it (signal %1, %2)")
                .arg(signal)
                .arg(QString::fromUtf8(name ? name : "unknown")));
    }
    switch (process.exitCode()) {
    case 0:
        return;
    case kExitRefused: {
        const QString problem = lastLine(process.readAllStandardError());
        throw IoError(fileLabel, problem.isEmpty() ? ImportProcess::tr("the importer refused it") : problem);
    }
    case kExitOutOfMemory:
        throw IoError(fileLabel,
            ImportProcess::tr("the importer needs more than %1 of memory for it and was stopped (the limit is "
                              "CELFORM_IMPORT_MEMORY_MB)")
                .arg(memoryText(limits.memoryBytes)));
    default:
        throw IoError(fileLabel,
            ImportProcess::tr("the importer failed on it (exit code %1): %2")
                .arg(process.exitCode())
                .arg(lastLine(process.readAllStandardError())));
    }
}

int serveImport(const QString& path, const std::function<void()>& work)
{
    // Libraries catch std::bad_alloc and report it as their own error ("std::bad_alloc", or a
    // format error): ending here keeps the reason.
    std::set_new_handler([] { ::_exit(kExitOutOfMemory); });
    try {
        work();
        return 0;
    } catch (const IoError& e) {
        // The parent names the file itself; another file (an OBJ's material library) stays named.
        writeLine(e.file() == path ? e.problem() : e.message());
        return kExitRefused;
    } catch (const std::bad_alloc&) {
        return kExitOutOfMemory;
    } catch (const std::exception& e) {
        writeLine(QString::fromLocal8Bit(e.what()));
        return kExitRefused;
    }
}

} // namespace celform::model
