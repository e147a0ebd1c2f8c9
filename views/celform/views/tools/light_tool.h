// Moving the key light by its gizmo: Ctrl+left drag on the handle (whatever tool is on) moves it
// on a sphere about the model, towards or away from the viewer as it was; one undo step per drag.
#pragma once

#include "celform/views/tools/viewport_tool.h"

namespace celform::views {

class LightTool : public ViewportTool {
public:
    using ViewportTool::ViewportTool;

    /// Takes the press only on the handle with Ctrl held.
    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    [[nodiscard]] Qt::CursorShape cursor() const override { return Qt::ClosedHandCursor; }
};

} // namespace celform::views
