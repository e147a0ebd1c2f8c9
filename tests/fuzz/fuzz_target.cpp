// The libFuzzer target for every kind of input: the name it runs under picks the kind (fuzz_ply,
// fuzz_cli_options, ... are links to it: tests/fuzz/CMakeLists.txt), or CELFORM_FUZZ_KIND names
// it. A finding is a crash or sanitizer report, a hang or huge allocation
// (libFuzzer's -timeout and -rss_limit_mb), an exception other than the loader's refusal, or an
// accepted input that breaks a promise the loader makes (fuzz_inputs.cpp).
//
// CELFORM_FUZZ_SAVE=FILE writes each input as the loader saw it (for the project target: with its
// checksums fixed), to turn a crash artifact into a file for tests/data/fuzz-regressions/.
// CELFORM_FUZZ_VERBOSE=1 keeps Qt's warnings (dropped otherwise: QtSvg prints one per bad element).
#include "fuzz_inputs.h"

#include "cli_process.h"

#include <QFile>
#include <QFontDatabase>
#include <QGuiApplication>

#include <sanitizer/lsan_interface.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

QString g_kind; // set once in LLVMFuzzerInitialize

/// The kind from the program's name: "fuzz_animated_gltf" is "animated-gltf".
QString kindFromName(const char* program)
{
    const char* slash = std::strrchr(program, '/');
    QString name = QString::fromLocal8Bit(slash ? slash + 1 : program);
    if (!name.startsWith(QLatin1String("fuzz_")))
        return {};
    return name.mid(5).replace(QLatin1Char('_'), QLatin1Char('-'));
}

void printCliSummary()
{
    std::fprintf(stderr, "celform fuzz: cli-process: %s\n", qPrintable(celform::fuzz::cliProcessSummary()));
}

void quietMessages(QtMsgType type, const QMessageLogContext&, const QString& message)
{
    if (type == QtFatalMsg || qEnvironmentVariableIsSet("CELFORM_FUZZ_VERBOSE"))
        std::fprintf(stderr, "%s\n", qPrintable(message));
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc0, char*** argv0)
{
    g_kind = qEnvironmentVariable("CELFORM_FUZZ_KIND");
    if (g_kind.isEmpty() && argc0 && *argc0 > 0)
        g_kind = kindFromName((*argv0)[0]);
    if (!celform::fuzz::kinds().contains(g_kind)) {
        std::fprintf(stderr,
            "celform fuzz: no kind of input \"%s\": run as fuzz_KIND or set CELFORM_FUZZ_KIND to one of %s\n",
            qPrintable(g_kind), qPrintable(celform::fuzz::kinds().join(QStringLiteral(", "))));
        std::exit(2);
    }
    qInstallMessageHandler(quietMessages);
    // SVG text needs fonts and fonts need a QGuiApplication; the offscreen platform needs no
    // display. It lives until the process ends (reachable, so not a leak) and never sees
    // libFuzzer's flags.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "celform-fuzz";
    static char* argv[] = {name, nullptr};
    static QGuiApplication* app = new QGuiApplication(argc, argv);
    Q_UNUSED(app);
    {
        // Fontconfig 2.14 (Debian 12) keeps 288 bytes of its configuration parse where LeakSanitizer
        // counts them lost, once per process, when Qt's font database first loads it. Loaded here,
        // with those allocations ignored, rather than in the first input that draws text: libFuzzer's
        // leak check after an input reports every leak in the process, so every later input would.
        const __lsan::ScopedDisabler fontconfigLoad;
        (void)QFontDatabase::families();
    }
    if (g_kind == QLatin1String("cli-process"))
        std::atexit(printCliSummary); // how the children ended: the share that got past the options
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray raw = QByteArray::fromRawData(reinterpret_cast<const char*>(data), qsizetype(size));
    const QByteArray input = g_kind == QLatin1String("project") ? celform::fuzz::fixProjectChecksums(raw) : raw;
    if (const QByteArray save = qgetenv("CELFORM_FUZZ_SAVE"); !save.isEmpty()) {
        QFile file(QFile::decodeName(save));
        if (file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            file.write(input);
    }
    const celform::fuzz::Outcome outcome = celform::fuzz::feed(g_kind, input);
    if (!outcome.broken.isEmpty() && g_kind == QLatin1String("cli-process")) {
        std::fprintf(stderr, "celform fuzz: a command line breaks its promise: %s\n", qPrintable(outcome.broken));
        std::abort();
    }
    if (!outcome.broken.isEmpty()) {
        std::fprintf(stderr, "celform fuzz: the %s loader accepted an input that breaks its promise: %s\n",
            qPrintable(g_kind), qPrintable(outcome.broken));
        std::abort();
    }
    return 0;
}
