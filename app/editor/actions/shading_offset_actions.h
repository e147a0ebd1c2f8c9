// The editor's shading-offset actions (paper 3, section 4.3), one small adapter in the manner of
// ParaView's reactions: the offset brush tool and its target, Automatic Shading Offsets…, Smooth
// and Clear. Each calls a document operation; nothing here edits data.
#pragma once

class QMenu;

namespace celform::app {

class MainWindow;

/// Creates the actions on window (found by name through MainWindow::action) and a "Shading
/// Offsets" submenu of menu holding them.
void installOffsetActions(MainWindow* window, QMenu* menu);

} // namespace celform::app
