// Shared helpers of the test suites: where the shared data lives, and skipping when it does not.
#pragma once

#include <QDir>
#include <QFileInfo>
#include <QString>
#include <QtTest/QtTest>

namespace celform::test {

/// Absolute path of a file under ../shared/data, or an empty string when it is absent.
inline QString sharedDataPath(const QString& relative)
{
    const QString root = QStringLiteral(CELFORM_SHARED_DATA_DIR);
    const QString path = QDir(root).filePath(relative);
    return QFileInfo::exists(path) ? QFileInfo(path).absoluteFilePath() : QString();
}

/// Absolute path of a file under tests/data (always present).
inline QString testDataPath(const QString& relative)
{
    return QDir(QStringLiteral(CELFORM_TEST_DATA_DIR)).filePath(relative);
}

} // namespace celform::test

/// Skips the current test with a clear message when a shared data file is absent.
#define CELFORM_REQUIRE_SHARED(var, relative)                                                                          \
    const QString var = celform::test::sharedDataPath(relative);                                                       \
    if (var.isEmpty())                                                                                                 \
    QSKIP(qPrintable(QStringLiteral("shared test data not found: ../shared/data/") + (relative)))
