// What the viewport's brushes share (the falloff brush and the shading-offset brush): the circle
// under the cursor with the radius on the surface there (one pick per frame while hovering), and
// F-resize, Blender's radial control (move away from the circle's centre, click or Enter keeps,
// Esc cancels). The tool keeps its stroke; this keeps the circle.
#pragma once

#include "celform/algorithms/brush.h"

#include <QPointF>
#include <QString>

#include <functional>

class QTimer;

namespace celform::views {

class BrushCursor;
class Viewport;

class BrushHover {
public:
    /// falloff: the curve the circle shades (the brush's current profile).
    BrushHover(Viewport* viewport, std::function<algo::BrushFalloff()> falloff);

    [[nodiscard]] BrushCursor* circle() const { return m_circle; }
    [[nodiscard]] bool isResizing() const { return m_resizing; }
    [[nodiscard]] QPointF position() const { return m_position; }

    /// The brush radius in widget pixels at a point with unitsPerPixel world units per pixel.
    [[nodiscard]] double radiusPixels(double unitsPerPixel) const;
    /// Picks under the last hover position and shows the circle there (or hides it).
    void updateCircle();
    /// The pointer moved with no button held: resizes while resizing, else picks (coalesced).
    void hover(const QPointF& position);
    /// The pointer left: the circle hides unless a stroke (strokeActive) or a resize holds it.
    void leave(bool strokeActive);
    void cameraChanged(bool strokeActive);
    /// Shows the circle at position with a radius in pixels (during a stroke); stops hover picks.
    void showAt(const QPointF& position, double radiusPixels);
    /// F (the viewport key BrushResize) when no stroke is on, and Esc / Enter while resizing.
    [[nodiscard]] bool wantsKey(int key, Qt::KeyboardModifiers modifiers, bool strokeActive) const;
    /// Starts or ends a resize; hint is shown when the cursor is off the model, prompt when it
    /// starts (the tool's translated texts). Returns whether it handled the key.
    bool keyPress(
        int key, Qt::KeyboardModifiers modifiers, bool strokeActive, const QString& hint, const QString& prompt);
    /// Ends a resize, keeping the new radius or going back to the old one.
    void endResize(bool keep);
    /// The tool is switched off: no circle, no resize, no pending pick.
    void stop();

private:
    Viewport* m_viewport;
    std::function<algo::BrushFalloff()> m_falloff;
    BrushCursor* m_circle; ///< child of the viewport
    QTimer* m_timer; ///< coalesces hover picks to one per frame
    QPointF m_position;
    double m_unitsPerPixel = 0.0; ///< at the surface point under the cursor, 0: none
    bool m_resizing = false;
    QPointF m_resizeCentre;
    double m_radiusBeforeResize = 0.0;
};

} // namespace celform::views
