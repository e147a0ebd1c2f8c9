// The editor's Fit to Drawing actions (docs/fit-to-drawing.md): Fit Camera to Drawing and Fit
// Shape to Drawing, for the key or drawing selected in the Scene panel, each a job of the
// JobRunner (jobs/fit_job.h) whose result the Document applies as one undo step. The Properties
// panel's buttons are these actions.
#pragma once

class QMenu;

namespace celform::app {

class MainWindow;

/// Creates the actions on window (found by name through MainWindow::action), a "Fit to Drawing"
/// submenu of menu holding them, and gives them to the Properties panel.
void installFitActions(MainWindow* window, QMenu* menu);

} // namespace celform::app
