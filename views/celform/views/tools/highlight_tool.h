// Direct manipulation of a stylized highlight (Anjyo & Hiramitsu 2003) in the viewport: drag moves
// the target layer along the surface, Shift+drag rotates it, Ctrl+drag scales it, keyed at the
// playhead; one undo step per drag (Document::nudgeHighlight).
#pragma once

#include "celform/views/tools/viewport_tool.h"

#include <QPointF>

namespace celform::views {

class HighlightTool : public ViewportTool {
public:
    using ViewportTool::ViewportTool;

    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;

private:
    QPointF m_du{1.0, 0.0}, m_dv{0.0, -1.0}; ///< screen directions (unit) of du, dv at the picked point
    double m_unitsPerPixel = 0.005; ///< translation parameter per pixel of drag
};

} // namespace celform::views
