// The `celform` command line: sub-commands that work on project files through the same Document
// and commands as the editor, with exit codes 0 (success), 2 (usage) and 3 (bad input). It needs
// only the model (Qt Core and Gui): the editor is a module loaded when a window opens.
#pragma once

#include <QStringList>

namespace celform::app {

enum ExitCode { kExitOk = 0, kExitFailure = 1, kExitUsage = 2, kExitBadInput = 3 };

/// Whether the arguments name a sub-command (or a global option like --version) that runs
/// without the editor.
bool isCommandLineInvocation(const QStringList& arguments);

/// Runs a sub-command; needs a QCoreApplication. Returns the process exit code.
int runCommandLine(const QStringList& arguments);

/// The names of the sub-commands, in the table's order.
QStringList subCommandNames();

/// Every synopsis line `celform --help` prints, in order: the sub-commands' from the table, then
/// --version and the editor's. README.md's command-line block holds the same lines.
QStringList synopsisLines();

} // namespace celform::app
