// The keys the viewport and its tools handle themselves rather than through the window's actions
// (frame, front view, brush size, the brush's resize). One table drives Viewport::keyPressEvent,
// the tools' keys and Help > Keyboard Shortcuts, so what the help lists is what the viewport does.
#pragma once

#include <QKeySequence>
#include <QString>

#include <optional>
#include <vector>

class QKeyEvent;

namespace celform::views {

enum class ViewportKeyCommand { FrameAll, FrontView, BrushSmaller, BrushLarger, BrushResize };

struct ViewportKeyBinding {
    /// Who handles the key: the viewport whatever the tool, or a tool while it is on (it takes the
    /// key before the window's shortcuts).
    enum class Scope { Viewport, BrushTool };

    ViewportKeyCommand command;
    Scope scope;
    /// Pressed without Ctrl, Alt or Meta (Shift and the keypad do not matter).
    Qt::Key key;
    /// What it does, untranslated (context celform::views::Viewport): see description().
    const char* text;

    [[nodiscard]] QKeySequence sequence() const { return QKeySequence(key); }
    [[nodiscard]] QString description() const;
};

/// Every key the viewport handles in keyPressEvent.
[[nodiscard]] const std::vector<ViewportKeyBinding>& viewportKeyBindings();

/// The viewport's command of a key press (Scope::Viewport), or none (the press goes on to the
/// parent).
[[nodiscard]] std::optional<ViewportKeyCommand> viewportKeyCommand(const QKeyEvent& event);

/// The key of a command in the table.
[[nodiscard]] Qt::Key viewportKey(ViewportKeyCommand command);

} // namespace celform::views
