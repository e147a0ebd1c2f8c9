// The editor's animation (paper 1, section 4 and figures 10-12), one adapter in the
// manner of offset_actions: the Timeline dock, View ▸ Playback, looking through the shot camera
// at the playhead, the Camera menu (key, remove, clear, turntable) and the Observer layout with
// the camera path drawn in the Observer view. Edits go through Document methods only.
#pragma once

namespace celform::app {

class MainWindow;

/// Creates the dock, the actions (found by name through MainWindow::action) and their menus.
/// Call once, after the window's own menus exist.
void installAnimationActions(MainWindow* window);

} // namespace celform::app
