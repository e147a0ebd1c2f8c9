// Painting shading offsets O_v (paper 3, section 4.3, eq. 4.3) on the model: drag adds, Ctrl+drag
// subtracts, Shift+drag smooths, the Erase mode takes offsets back towards zero; the radius is the
// brushes' shared radius (F resizes it, as for the geometry brush), the falloff (1 - d/r)^2,
// optionally mirrored across x = 0. It paints into the base layer or into a key's layer at the
// playhead. One document stroke (one undo step) per drag.
#pragma once

#include "celform/model/document/offset_stroke.h"
#include "celform/views/tools/brush_hover.h"

namespace celform::views {

class OffsetBrushTool : public BrushHover {
public:
    OffsetBrushTool(Viewport* viewport, BrushSize& size);
    ~OffsetBrushTool() override;

    /// The mode of a plain drag (Ctrl+drag subtracts and Shift+drag smooths whatever it is).
    void setMode(model::OffsetPaintMode mode) { m_mode = mode; }
    [[nodiscard]] model::OffsetPaintMode mode() const { return m_mode; }
    /// Offset added at the centre by one dab.
    void setStrength(double strength);
    [[nodiscard]] double strength() const { return m_strength; }
    /// Also paint across the project's mirror plane (ProjectData::mirrorPlane).
    void setMirror(bool on) { m_mirror = on; }
    [[nodiscard]] bool mirror() const { return m_mirror; }
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

protected:
    [[nodiscard]] bool strokeActive() const override { return m_stroke.active(); }
    /// (1 - d/r)^2, as the dabs.
    [[nodiscard]] algo::BrushFalloff falloff() const override { return algo::BrushFalloff::Paper; }

private:
    void dab(const QPointF& position);
    void finish();

    model::OffsetPaintMode m_mode = model::OffsetPaintMode::Add;
    double m_strength = 0.05;
    bool m_mirror = false;
    model::ObjectId m_targetKey = 0;
    model::OffsetStroke m_stroke;
};

} // namespace celform::views
