// What the viewport's brushes share (the falloff brush and the shading-offset brush), as their
// base: the circle under the cursor with the radius on the surface there (one pick per frame
// while hovering), and F-resize, Blender's radial control (move away from the circle's centre,
// click or Enter keeps, Esc cancels). The brush keeps its stroke; this keeps the circle.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/views/tools/viewport_tool.h"

#include <QPointF>

class QTimer;

namespace celform::views {

class BrushCursor;
class BrushSize;

class BrushHover : public ViewportTool {
public:
    /// size: the radius the brushes share (the viewport hands it to each).
    BrushHover(Viewport* viewport, BrushSize& size);
    ~BrushHover() override; // the circle and the timer are children of the viewport

    [[nodiscard]] BrushSize& size() const { return m_size; }
    /// The circle under the cursor (tests read it).
    [[nodiscard]] const BrushCursor* cursorCircle() const { return m_circle; }
    [[nodiscard]] bool isResizing() const { return m_resizing; }

    void cameraChanged() override;
    void hover(const QPointF& position) override;
    void leave() override;
    /// F (the viewport key BrushResize) when no stroke is on, and Esc / Enter while resizing.
    [[nodiscard]] bool wantsKey(int key, Qt::KeyboardModifiers modifiers) const override;
    bool keyPress(int key, Qt::KeyboardModifiers modifiers) override;

protected:
    /// Whether the brush's stroke is on (it holds the circle; F does not resize then).
    [[nodiscard]] virtual bool strokeActive() const = 0;
    /// The curve the circle shades (the brush's current profile).
    [[nodiscard]] virtual algo::BrushFalloff falloff() const = 0;

    /// Picks under the last hover position and shows the circle there (or hides it).
    void updateCircle();
    /// Shows the circle at position with a radius in pixels (during a stroke); stops hover picks.
    void showAt(const QPointF& position, double radiusPixels);
    /// The circle's radius in pixels as last shown.
    [[nodiscard]] double circlePixels() const;
    /// Ends a resize, keeping the new radius or going back to the old one.
    void endResize(bool keep);
    /// The tool is switched off: no circle, no resize, no pending pick.
    void stopHover();

private:
    BrushSize& m_size;
    BrushCursor* m_circle; ///< child of the viewport
    QTimer* m_timer; ///< coalesces hover picks to one per frame
    QPointF m_position;
    double m_unitsPerPixel = 0.0; ///< at the surface point under the cursor, 0: none
    bool m_resizing = false;
    QPointF m_resizeCentre;
    double m_radiusBeforeResize = 0.0;
};

} // namespace celform::views
