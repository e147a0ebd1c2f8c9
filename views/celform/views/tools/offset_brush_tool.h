// Painting shading offsets O_v (paper 3, section 4.3, eq. 4.3) on the model: drag adds, Ctrl+drag
// subtracts, Shift+drag smooths, the Erase mode takes offsets back towards zero; the radius is the
// viewport's brush radius (F resizes it, as for the geometry brush), the falloff (1 - d/r)^2,
// optionally mirrored across x = 0. It paints into the base layer or into a key's layer at the
// playhead. One document stroke (one undo step) per drag.
#pragma once

#include "celform/model/document/offset_stroke.h"
#include "celform/views/tools/brush_hover.h"
#include "celform/views/tools/viewport_tool.h"

namespace celform::views {

class OffsetBrushTool : public ViewportTool {
public:
    explicit OffsetBrushTool(Viewport* viewport);
    ~OffsetBrushTool() override;

    /// The mode of a plain drag (Ctrl+drag subtracts and Shift+drag smooths whatever it is).
    void setMode(model::OffsetPaintMode mode) { m_mode = mode; }
    [[nodiscard]] model::OffsetPaintMode mode() const { return m_mode; }
    /// Offset added at the centre by one dab.
    void setStrength(double strength);
    [[nodiscard]] double strength() const { return m_strength; }
    void setMirrorX(bool on) { m_mirrorX = on; }
    [[nodiscard]] bool mirrorX() const { return m_mirrorX; }
    /// The layer painted: 0 the base layer, else that key's layer at the playhead.
    void setTargetKey(model::ObjectId key) { m_targetKey = key; }
    [[nodiscard]] model::ObjectId targetKey() const { return m_targetKey; }
    /// The target a stroke would paint into now, and its name for the panels.
    [[nodiscard]] model::ShadingTarget target() const;
    [[nodiscard]] QString targetText() const;

    void activate() override;
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

    [[nodiscard]] const BrushCursor* cursorCircle() const { return m_hover.circle(); }

private:
    void dab(const QPointF& position);
    void finish();

    model::OffsetPaintMode m_mode = model::OffsetPaintMode::Add;
    double m_strength = 0.05;
    bool m_mirrorX = false;
    model::ObjectId m_targetKey = 0;
    model::OffsetStroke m_stroke;
    BrushHover m_hover; ///< the circle under the cursor and F-resize, as the geometry brush's
};

} // namespace celform::views
