// Running the `celform` binary from a test as a script would: without a display, with its exit
// code, exit status and both outputs.
#pragma once

#include "test_support.h"

#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

#include <csignal>

#include <sys/resource.h>

namespace {

struct Run {
    int exitCode = -1;
    QProcess::ExitStatus status = QProcess::CrashExit;
    QString out;
    QString err;
};

/// The test's environment without a display: sub-commands must not need one.
inline QProcessEnvironment displayFreeEnvironment()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    return env;
}

/// Runs celform without a display. environment: NAME=VALUE sets a variable, NAME alone removes it.
Run runCelform(const QStringList& args, const QStringList& environment = {},
    const QString& program = QStringLiteral(CELFORM_EXECUTABLE))
{
    QProcess p;
    QProcessEnvironment env = displayFreeEnvironment();
    for (const QString& e : environment) {
        const qsizetype equals = e.indexOf(QLatin1Char('='));
        if (equals < 0)
            env.remove(e);
        else
            env.insert(e.left(equals), e.mid(equals + 1));
    }
    p.setProcessEnvironment(env);
    p.start(program, args);
    if (!p.waitForFinished(120000))
        p.kill();
    return {p.exitCode(), p.exitStatus(), QString::fromUtf8(p.readAllStandardOutput()),
        QString::fromUtf8(p.readAllStandardError())};
}

/// Runs celform as runCelform does, with its address space capped at addressSpace bytes and
/// killed after timeoutMs: a regression that allocates gigabytes or blocks fails its test.
/// Under AddressSanitizer, which cannot start within such a cap, ASan's own limits stand in: one
/// allocation larger than the cap, or a resident size beyond it and ASan's quarantine (256 MB),
/// ends celform with a report, a crash that fails the test as running out of memory would.
inline Run runCelformLimited(const QStringList& args, qint64 addressSpace, int timeoutMs)
{
    QProcess p;
    QProcessEnvironment env = displayFreeEnvironment();
    if (celform::test::kAddressSanitizer) {
        const qint64 mb = addressSpace >> 20;
        env.insert(QStringLiteral("ASAN_OPTIONS"),
            env.value(QStringLiteral("ASAN_OPTIONS"))
                + QStringLiteral(":max_allocation_size_mb=%1:hard_rss_limit_mb=%2").arg(mb).arg(mb + 256));
    } else {
        p.setChildProcessModifier([addressSpace] {
            const rlimit limit{rlim_t(addressSpace), rlim_t(addressSpace)};
            ::setrlimit(RLIMIT_AS, &limit);
        });
    }
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(CELFORM_EXECUTABLE), args);
    Run run;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        run.err = QStringLiteral("(killed after %1 ms)").arg(timeoutMs);
        return run;
    }
    return {p.exitCode(), p.exitStatus(), QString::fromUtf8(p.readAllStandardOutput()),
        QString::fromUtf8(p.readAllStandardError())};
}

/// Runs celform as runCelform does on a disk that is full after fileBytes bytes of any one file:
/// the file-size limit (RLIMIT_FSIZE) makes every write beyond it fail (EFBIG, "File too large"),
/// as ENOSPC would on a full file system, with SIGXFSZ ignored so that the write reports it rather
/// than the signal ending the process. What a program does with a failing write is then tested
/// without a small file system to fill (issue 27).
inline Run runCelformOnFullDisk(const QStringList& args, qint64 fileBytes)
{
    QProcess p;
    p.setProcessEnvironment(displayFreeEnvironment());
    p.setChildProcessModifier([fileBytes] {
        ::signal(SIGXFSZ, SIG_IGN); // ignored signals stay ignored across exec
        const rlimit limit{rlim_t(fileBytes), rlim_t(fileBytes)};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    });
    p.start(QStringLiteral(CELFORM_EXECUTABLE), args);
    if (!p.waitForFinished(120000))
        p.kill();
    return {p.exitCode(), p.exitStatus(), QString::fromUtf8(p.readAllStandardOutput()),
        QString::fromUtf8(p.readAllStandardError())};
}

/// A file's bytes, empty when it cannot be read.
inline QByteArray fileBytes(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace
