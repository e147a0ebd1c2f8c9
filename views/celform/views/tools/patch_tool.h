// Painting a highlight patch (paper 2 shapes each highlight on one patch): drag adds the faces
// turned towards the camera under the brush to the target face set, Ctrl+drag removes them; one
// undo step per drag.
#pragma once

#include "celform/views/tools/viewport_tool.h"

namespace celform::views {

class PatchTool : public ViewportTool {
public:
    using ViewportTool::ViewportTool;

    void activate() override;
    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void cancel() override;

private:
    void paint(const ToolEvent& event);
    void finish();
    int m_gesture = 0;
};

} // namespace celform::views
