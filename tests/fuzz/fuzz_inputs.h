// One input of one kind handed to the loader that reads it: shared by the libFuzzer targets
// (fuzz_target.cpp) and the regression replay (test_fuzz_regressions.cpp), so a file that crashed
// a fuzzer is replayed exactly as the fuzzer fed it.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace celform::model {
struct ProjectData;
}

namespace celform::fuzz {

/// Every kind, as the folders of tests/data/fuzz-corpus and tests/data/fuzz-regressions name
/// them: the mesh suffixes (model::importMesh), the drawing suffixes (model::importDrawing),
/// "project" (model::loadProject), "cli-options" (the option parsers of app/cli/options.h) and
/// "cli-process" (a `celform` sub-command in a child process: cli_process.h) and "png-writer" (the
/// PNG writer and its run coder, whose output must read back the same: fuzz_inputs.cpp).
QStringList kinds();

/// What a loader made of one input.
struct Outcome {
    bool loaded = false; ///< accepted
    QString refusal; ///< the IoError (or UsageError) message when refused
    /// A promise that an accepted input broke (a face index out of range, a non-finite offset):
    /// a finding like a crash. Empty when none.
    QString broken;
};

/// Feeds bytes to the loader of kind. Files go through input.SUFFIX in a temporary folder (the
/// loaders take paths; the suffix picks the reader). "cli-options": the first byte picks a parser,
/// the rest is its text in UTF-8 ('\0' separates the arguments of the camera options).
/// "cli-process": a command line run as a child on a copy of a generated project (cli_process.h).
/// Exceptions other than the loaders' refusals propagate: they are findings too.
Outcome feed(const QString& kind, const QByteArray& bytes);

/// What an accepted project breaks of the loader's promises (docs/file-format.md's reading
/// rules), empty when nothing: the project fuzzer's check, and the command-line fuzzer's on the
/// projects the child leaves.
QString projectProblem(const model::ProjectData& data);

/// The project fuzzer's helper: the bytes with the trailer's manifest checksum and the chunk
/// checksums the manifest lists recomputed (the manifest re-serialised), so that mutations reach
/// the reader behind the checksums. Bytes without a readable trailer or manifest come back with
/// as much fixed as could be.
QByteArray fixProjectChecksums(const QByteArray& bytes);

} // namespace celform::fuzz
