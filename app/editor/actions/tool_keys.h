// A tool's keys win wherever the keyboard focus is in the window: while the brush is on, F resizes
// it, [ and ] change its size, Esc or Enter end a resize, even with the Scene tree or a dock
// focused; they never reach the window's shortcuts (F would frame the model). Fields that take
// text keep their keys.
#pragma once

class QWidget;

namespace celform::views {
class Viewport;
}

namespace celform::app {

/// Sends the key presses viewport's tool takes (Viewport::toolTakesKey) from any widget of window
/// to viewport.
void routeToolKeys(QWidget* window, views::Viewport* viewport);

} // namespace celform::app
