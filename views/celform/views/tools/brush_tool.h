// The falloff brush on the displayed key at the playhead (paper 1, section 3.1.2): drag moves the
// selection in the image plane, Ctrl+drag pushes it along the view, Shift+drag rotates it,
// Ctrl+Shift+drag scales it; the Smooth mode relaxes it. One document brush stroke per drag.
#pragma once

#include "celform/model/brush_stroke.h"
#include "celform/views/tools/viewport_tool.h"

class QTimer;

namespace celform::views {

class BrushCursor;

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
    [[nodiscard]] const BrushCursor* cursorCircle() const { return m_circle; }
    [[nodiscard]] bool isResizing() const { return m_resizing; }

private:
    void finish();
    /// Picks under the last hover position and shows the circle there (or hides it).
    void updateCircle();
    /// The radius in widget pixels at a point with unitsPerPixel world units per pixel.
    [[nodiscard]] double radiusPixels(double unitsPerPixel) const;
    void endResize(bool keep);

    model::BrushStroke m_stroke;
    double m_unitsPerPixel = 0.0; ///< world units per pixel at the picked vertex
    BrushCursor* m_circle; ///< child of the viewport
    QTimer* m_hoverTimer; ///< coalesces hover picks to one per frame
    QPointF m_hoverPos;
    double m_hoverUnitsPerPixel = 0.0; ///< at the surface point under the cursor, 0: none
    // F: resize by dragging, from the circle's centre (Blender's radial control).
    bool m_resizing = false;
    QPointF m_resizeCentre;
    double m_radiusBeforeResize = 0.0;
};

} // namespace celform::views
