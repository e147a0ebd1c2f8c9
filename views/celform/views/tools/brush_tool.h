// The falloff brush on the displayed key at the playhead (paper 1, section 3.1.2): drag moves the
// selection in the image plane, Ctrl+drag pushes it along the view, Shift+drag rotates it,
// Ctrl+Shift+drag scales it; the Smooth mode relaxes it. One document brush stroke per drag.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/model/document/brush_stroke.h"
#include "celform/views/tools/brush_hover.h"

namespace celform::views {

enum class BrushMode { Move, Smooth, Relax };

/// What the next strokes do (the radius is the brushes' shared BrushSize).
struct BrushSettings {
    BrushMode mode = BrushMode::Move;
    algo::BrushProfile profile; ///< the falloff curve and strength
    /// The twins across the project's mirror plane (ProjectData::mirrorPlane) move as the reflection.
    bool mirror = false;
};

class BrushTool : public BrushHover {
    Q_OBJECT
public:
    BrushTool(Viewport* viewport, BrushSize& size);
    ~BrushTool() override;

    [[nodiscard]] BrushSettings& settings() { return m_settings; }
    [[nodiscard]] const BrushSettings& settings() const { return m_settings; }

    void deactivate() override;
    /// Brushing a key is done in the key's camera, its drawing over it (paper 1, section 3.1.2).
    [[nodiscard]] bool holdsCamera() const override;
    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void cancel() override;

signals:
    /// The selection to show in red (during a stroke) or none (nulls); the viewport shows it.
    void selectionChanged(const algo::BrushSelection* selection, const algo::BrushSelection* mirror);

protected:
    [[nodiscard]] bool strokeActive() const override { return m_stroke.active(); }
    [[nodiscard]] algo::BrushFalloff falloff() const override { return m_settings.profile.falloff; }

private:
    /// Ends the stroke and lets go of its working memory (a copy of the key's shape).
    void finish();

    BrushSettings m_settings;
    model::BrushStroke m_stroke;
    double m_unitsPerPixel = 0.0; ///< world units per pixel at the picked vertex
};

} // namespace celform::views
