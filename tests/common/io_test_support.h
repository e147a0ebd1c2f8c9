// Helpers of the model's file I/O tests: writing an input file, and running a read expected to
// succeed without letting its IoError end the whole test program.
#pragma once

#include "celform/model/data/io_error.h"

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QTemporaryDir>
#include <QtTest/QtTest>

/// Runs a read expected to succeed into a new variable var; an IoError fails the test (with its
/// message) instead of aborting the run.
#define CELFORM_IMPORT_OR_FAIL(var, expr)                                                                              \
    decltype(expr) var;                                                                                                \
    try {                                                                                                              \
        var = (expr);                                                                                                  \
    } catch (const celform::model::IoError& e) {                                                                       \
        QFAIL(qPrintable(e.message()));                                                                                \
    }

namespace celform::test {

/// Writes bytes to name in dir and returns its path; stops the program when it cannot.
inline QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

} // namespace celform::test
