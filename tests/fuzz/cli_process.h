// The "cli-process" kind: one `celform` sub-command, run as a child process on a copy of a small
// generated project, with options derived from the input; then the project must still open.
// Shared by the libFuzzer target (fuzz_cli_process) and the regression replay through
// fuzz_inputs.h's feed(). README.md here describes the input's two forms and what is a finding.
#pragma once

#include "fuzz_inputs.h"

#include <QByteArray>
#include <QString>

namespace celform::fuzz {

/// Runs the command line the bytes describe and checks what it left. Outcome::loaded: the
/// sub-command exited 0; refusal: its message for exit 2 or 3, or that it was killed at the time
/// limit; broken: a finding (a signal, a sanitizer report, an undocumented exit code, a message-less
/// error, a project that no longer opens).
Outcome feedCliProcess(const QByteArray& bytes);

/// How the runs of this process ended so far, one line ("212 runs: exit 0 x41, exit 2 x150, ...").
QString cliProcessSummary();

} // namespace celform::fuzz
