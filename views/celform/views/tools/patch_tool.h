// Painting a highlight patch (paper 2 shapes each highlight on one patch): drag adds the faces
// turned towards the camera under the brush to the target face set, Ctrl+drag removes them; one
// undo step per drag.
#pragma once

#include "celform/model/document/face_set_stroke.h"
#include "celform/views/tools/viewport_tool.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace celform::views {

class BrushSize;

class PatchTool : public ViewportTool {
    Q_OBJECT
public:
    /// size: the radius the brushes share.
    PatchTool(Viewport* viewport, const BrushSize& size);

    /// The face set (highlight patch) painted into; created by the first stroke when missing.
    /// Its faces are tinted while the tool is on.
    void setTarget(const QString& name);
    [[nodiscard]] QString target() const { return m_target; }
    /// Also paint across the project's mirror plane (ProjectData::mirrorPlane), as the brushes do.
    void setMirror(bool on) { m_mirror = on; }
    [[nodiscard]] bool mirror() const { return m_mirror; }

    /// What a drag paints: the target patch, or the faces' importance (focal points, issue 26:
    /// a drag takes each face under the brush towards importance() by strength(), Ctrl+drag
    /// towards 1; the faces painted below 1 are tinted while the tool is on).
    /// MergeSegments and SplitSegment are the segment brush (issue 26, thesis 6.2): a click on one
    /// segment of the depth analysis of the picture shown and a click on another merge them; a
    /// drag across a segment splits it along the drag. Each edit is one undo step.
    enum class Mode { Patch, Importance, MergeSegments, SplitSegment };
    void setMode(Mode mode);
    [[nodiscard]] Mode mode() const { return m_mode; }
    void setImportance(float value) { m_importance = value; }
    [[nodiscard]] float importance() const { return m_importance; }
    void setStrength(float strength) { m_strength = strength; }
    [[nodiscard]] float strength() const { return m_strength; }

    void activate() override;
    bool press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;

    /// Faces a paint dab at a widget position touches: the face under it and every face turned
    /// towards the camera around a vertex within the brush radius of the picked point, reached
    /// over the surface from it, ascending. Empty when nothing is picked. Valid until the next
    /// call (the tool's working memory).
    [[nodiscard]] const std::vector<std::int32_t>& facesUnderBrush(const QPointF& position);

signals:
    void targetChanged(); ///< the target or the mode: what the tint shows changed

private:
    void paint(const ToolEvent& event);
    /// The segment brush: the picture the viewport shows, analysed at the widget's size (so widget
    /// positions are its pixels), with the base face at each pixel; false when there is none.
    bool analysePicture(struct SegmentEdit& edit);
    void pickSegment(const QPointF& position);
    void splitAlong();
    void endDrag() override;

    const BrushSize& m_size;
    QString m_target;
    bool m_mirror = false;
    Mode m_mode = Mode::Patch;
    float m_importance = 0.f;
    float m_strength = 1.f;
    int m_firstSegment = -1; ///< MergeSegments: the segment the first click chose
    std::vector<QPointF> m_strokePoints; ///< SplitSegment: the drag's positions
    model::FaceSetStroke m_stroke; ///< the drag's, open from press to release
    // Working memory of facesUnderBrush(), sized once per mesh.
    std::vector<char> m_seen;
    std::vector<std::int32_t> m_frontier, m_visited, m_faces;
};

} // namespace celform::views
