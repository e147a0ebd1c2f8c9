// Starting `celform`: the application's identity and translations, the editor's own arguments,
// and handing over to the editor module, which maps VTK, OpenGL and Qt Widgets only when a window
// is wanted. Everything here runs before any QApplication exists.
#pragma once

#include <QString>
#include <QStringList>

class QCoreApplication;
class QLocale;

namespace celform::app {

/// Organisation, application name and version, for settings paths and --version.
void setApplicationIdentity();

/// Loads Qt's own strings and ours for the system locale; English needs none.
void installTranslations(QCoreApplication& app);
/// The same for a given locale (the editor's language preference).
void installTranslations(QCoreApplication& app, const QLocale& locale);

/// The editor's command line: celform [PROJECT] [--screenshot FILE.png].
struct EditorArguments {
    QString project; ///< empty: an empty editor
    QString screenshot; ///< empty: interactive
    bool help = false;
    bool version = false;
};

/// Parses the editor's arguments (arguments[0] is the program). Returns 0, or the exit code of a
/// problem found before any window opens, with its one-line message: an unknown option or a
/// second project (2), a word that is neither a sub-command nor a file (2), a missing file (3),
/// and with checkDisplay, no display to open a window on (2).
int parseEditorArguments(
    const QStringList& arguments, EditorArguments& parsed, QString* message, bool checkDisplay = true);

/// Runs the editor: checks the arguments, loads the editor module beside the binary (or in
/// ../lib/celform) and calls it. Prints a message and returns 2 or 3 when it cannot start.
int launchEditor(int argc, char** argv);

} // namespace celform::app
