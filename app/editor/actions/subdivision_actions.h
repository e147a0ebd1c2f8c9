// The smooth surface in the editor (issue 25), as Maya's Smooth Mesh Preview: View ▸ Control Mesh
// (1) and Smooth Surface (3), Show Control Cage (2: the control mesh's wireframe over the smooth
// surface), and a status-bar note while the viewport's level differs from the render level or is
// capped for a big mesh. The levels themselves are the look's (Look dock, undoable).
#pragma once

namespace celform::app {

class MainWindow;

/// Creates the actions (found by name through MainWindow::action), puts them in the View menu and
/// the note in the status bar. Call once, after the window's own menus exist.
void installSubdivisionActions(MainWindow* window);

} // namespace celform::app
