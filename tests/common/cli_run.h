// Running the `celform` binary from a test as a script would: without a display, with its exit
// code, exit status and both outputs.
#pragma once

#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace {

struct Run {
    int exitCode = -1;
    QProcess::ExitStatus status = QProcess::CrashExit;
    QString out;
    QString err;
};

/// Runs celform without a display. environment: NAME=VALUE sets a variable, NAME alone removes it.
Run runCelform(const QStringList& args, const QStringList& environment = {},
    const QString& program = QStringLiteral(CELFORM_EXECUTABLE))
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY")); // sub-commands must not need a display
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
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

} // namespace
