// The viewport's own keys (viewport_keys.h).
#include "celform/views/viewport/viewport_keys.h"

#include <QCoreApplication>
#include <QKeyEvent>

namespace celform::views {

QString ViewportKeyBinding::description() const
{
    return QCoreApplication::translate("celform::views::Viewport", text);
}

const std::vector<ViewportKeyBinding>& viewportKeyBindings()
{
    // Krita's and Photoshop's brush-size keys; F and Home as in the View menu, for viewports
    // outside the main window (the review) and when those actions are given other keys.
    using Scope = ViewportKeyBinding::Scope;
    static const std::vector<ViewportKeyBinding> bindings = {
        {ViewportKeyCommand::FrameAll, Scope::Viewport, Qt::Key_F,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Frame all")},
        {ViewportKeyCommand::FrontView, Scope::Viewport, Qt::Key_Home,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Front view, framed")},
        {ViewportKeyCommand::BrushSmaller, Scope::Viewport, Qt::Key_BracketLeft,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Brush radius smaller (× 0.8)")},
        {ViewportKeyCommand::BrushLarger, Scope::Viewport, Qt::Key_BracketRight,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Brush radius larger (× 1.25)")},
        // Blender's F: the circle follows the mouse; click or Enter keeps the radius, Esc cancels.
        {ViewportKeyCommand::BrushResize, Scope::BrushTool, Qt::Key_F,
            QT_TRANSLATE_NOOP(
                "celform::views::Viewport", "Resize the brush with the mouse (click or Enter keeps, Esc cancels)")},
    };
    return bindings;
}

std::optional<ViewportKeyCommand> viewportKeyCommand(const QKeyEvent& event)
{
    if (event.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return std::nullopt;
    for (const ViewportKeyBinding& binding : viewportKeyBindings())
        if (binding.scope == ViewportKeyBinding::Scope::Viewport && event.key() == binding.key)
            return binding.command;
    return std::nullopt;
}

Qt::Key viewportKey(ViewportKeyCommand command)
{
    for (const ViewportKeyBinding& binding : viewportKeyBindings())
        if (binding.command == command)
            return binding.key;
    return Qt::Key_unknown;
}

} // namespace celform::views
