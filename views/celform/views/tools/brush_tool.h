// The falloff brush on the displayed key at the playhead (paper 1, section 3.1.2): drag moves the
// selection in the image plane, Ctrl+drag pushes it along the view, Shift+drag rotates it,
// Ctrl+Shift+drag scales it; the Smooth mode relaxes it. One document brush stroke per drag.
#pragma once

#include "celform/model/document/brush_stroke.h"
#include "celform/views/tools/brush_hover.h"
#include "celform/views/tools/viewport_tool.h"

namespace celform::views {

class BrushTool : public ViewportTool {
public:
    explicit BrushTool(Viewport* viewport);
    ~BrushTool() override;

    void deactivate() override;
    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void cancel() override;
    void cameraChanged() override;
    void hover(const QPointF& position) override;
    void leave() override;
    [[nodiscard]] bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(int key, Qt::KeyboardModifiers modifiers) override;

    /// The circle under the cursor (tests read it).
    [[nodiscard]] const BrushCursor* cursorCircle() const { return m_hover.circle(); }
    [[nodiscard]] bool isResizing() const { return m_hover.isResizing(); }

private:
    void finish();

    model::BrushStroke m_stroke;
    double m_unitsPerPixel = 0.0; ///< world units per pixel at the picked vertex
    BrushHover m_hover; ///< the circle under the cursor and F-resize
};

} // namespace celform::views
