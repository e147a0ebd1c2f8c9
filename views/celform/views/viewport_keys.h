// The keys the viewport handles itself rather than through the window's actions (frame, front
// view, brush size). One table drives Viewport::keyPressEvent and Help > Keyboard Shortcuts, so
// what the help lists is what the viewport does.
#pragma once

#include <QKeySequence>
#include <QString>

#include <optional>
#include <vector>

class QKeyEvent;

namespace celform::views {

enum class ViewportKeyCommand { FrameAll, FrontView, BrushSmaller, BrushLarger };

struct ViewportKeyBinding {
    ViewportKeyCommand command;
    /// Pressed without Ctrl, Alt or Meta (Shift and the keypad do not matter).
    Qt::Key key;
    /// What it does, untranslated (context celform::views::Viewport): see description().
    const char* text;

    [[nodiscard]] QKeySequence sequence() const { return QKeySequence(key); }
    [[nodiscard]] QString description() const;
};

/// Every key the viewport handles in keyPressEvent.
[[nodiscard]] const std::vector<ViewportKeyBinding>& viewportKeyBindings();

/// The command of a key press, or none (the press goes on to the parent).
[[nodiscard]] std::optional<ViewportKeyCommand> viewportKeyCommand(const QKeyEvent& event);

} // namespace celform::views
