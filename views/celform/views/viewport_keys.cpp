// The viewport's own keys (viewport_keys.h).
#include "celform/views/viewport_keys.h"

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
    static const std::vector<ViewportKeyBinding> bindings = {
        {ViewportKeyCommand::FrameAll, Qt::Key_F, QT_TRANSLATE_NOOP("celform::views::Viewport", "Frame all")},
        {ViewportKeyCommand::FrontView, Qt::Key_Home,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Front view, framed")},
        {ViewportKeyCommand::BrushSmaller, Qt::Key_BracketLeft,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Brush radius smaller (× 0.8)")},
        {ViewportKeyCommand::BrushLarger, Qt::Key_BracketRight,
            QT_TRANSLATE_NOOP("celform::views::Viewport", "Brush radius larger (× 1.25)")},
    };
    return bindings;
}

std::optional<ViewportKeyCommand> viewportKeyCommand(const QKeyEvent& event)
{
    if (event.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return std::nullopt;
    for (const ViewportKeyBinding& binding : viewportKeyBindings())
        if (event.key() == binding.key)
            return binding.command;
    return std::nullopt;
}

} // namespace celform::views
