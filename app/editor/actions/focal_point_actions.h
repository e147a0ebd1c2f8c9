// The editor's focal points (paper 3, 6.2; issue 26): the patch tool's importance mode, its value
// and strength, and Clear. Each calls a document operation; nothing here edits data.
#pragma once

class QMenu;

namespace celform::app {

class MainWindow;

/// Creates the actions on window (found by name through MainWindow::action) and a "Focal Points"
/// submenu of menu holding them.
void installFocalPointActions(MainWindow* window, QMenu* menu);

} // namespace celform::app
