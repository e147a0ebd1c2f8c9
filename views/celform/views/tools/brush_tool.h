// The falloff brush on the displayed key at the playhead (paper 1, section 3.1.2): drag moves the
// selection in the image plane, Ctrl+drag pushes it along the view, Shift+drag rotates it,
// Ctrl+Shift+drag scales it; the Smooth mode relaxes it. One document brush stroke per drag.
#pragma once

#include "celform/model/brush_stroke.h"
#include "celform/views/tools/viewport_tool.h"

namespace celform::views {

class BrushTool : public ViewportTool {
public:
    using ViewportTool::ViewportTool;

    void deactivate() override;
    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void cancel() override;

private:
    void finish();

    model::BrushStroke m_stroke;
    double m_unitsPerPixel = 0.0; ///< world units per pixel at the picked vertex
};

} // namespace celform::views
