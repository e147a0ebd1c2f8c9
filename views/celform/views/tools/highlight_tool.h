// Direct manipulation of a stylized highlight (Anjyo & Hiramitsu 2003) in the viewport: drag moves
// the target layer along the surface with the grabbed point under the cursor, Shift+drag rotates
// it, Ctrl+drag scales it, keyed at the playhead; one undo step per drag.
#pragma once

#include "celform/algorithms/render.h"
#include "celform/model/data/object_id.h"
#include "celform/model/document/highlight_drag.h"
#include "celform/views/tools/viewport_tool.h"

#include <Eigen/Core>

#include <optional>

namespace celform::views {

class HighlightTool : public ViewportTool {
public:
    using ViewportTool::ViewportTool;

    /// The highlight layer dragged (0: none).
    void setTarget(model::ObjectId layer) { m_target = layer; }
    [[nodiscard]] model::ObjectId target() const { return m_target; }

    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;

private:
    /// The translation (along the unturned du, dv) that centres the highlight on the surface
    /// point under a widget position; nothing off the model, off the patch or in shadow.
    std::optional<Eigen::Vector2d> centringTranslation(const QPointF& position);
    void endDrag() override;

    model::ObjectId m_target = 0;
    algo::RenderHighlight m_layer; ///< the target layer's geometry at the press
    model::HighlightDrag m_drag; ///< the drag's, open from press to release
    /// the translation centring the highlight on the press point (none: off the model)
    std::optional<Eigen::Vector2d> m_pressCentring;
};

} // namespace celform::views
