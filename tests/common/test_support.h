// Shared helpers of the test suites: where the shared data lives, and skipping when it does not.
#pragma once

#include <QDir>
#include <QFileInfo>
#include <QString>
#include <QtTest/QtTest>

// AddressSanitizer (the sanitize preset): GCC defines __SANITIZE_ADDRESS__, Clang has the feature.
#if defined(__SANITIZE_ADDRESS__)
#define CELFORM_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CELFORM_TEST_ASAN 1
#endif
#endif

namespace celform::test {

/// Whether this build runs under AddressSanitizer. Its shadow memory reserves terabytes of address
/// space when a program starts, so a test cannot cap a child's address space (RLIMIT_AS) there.
#ifdef CELFORM_TEST_ASAN
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

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
