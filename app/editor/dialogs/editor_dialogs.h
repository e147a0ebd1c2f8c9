// The actions of the editor's dialogs, kept out of MainWindow: File > Render Image and Render
// Sequence, Edit > Preferences and Help > Keyboard Shortcuts, and the preferences applied at start.
#pragma once

namespace celform::app {

class MainWindow;

/// Adds the dialogs' actions to the window's File, Edit and Help menus and applies the stored
/// preferences (shortcuts included). Call once, after the window made its own actions and menus.
void installEditorDialogs(MainWindow* window);

} // namespace celform::app
