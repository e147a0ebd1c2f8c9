// One stroke of the shading-offset brush (paper 3, section 4.3: O_v painted by hand) and the
// settings of the automatic per-segment offsets, as the document runs them for the editor's tools
// and `celform offsets` alike.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/shading_offsets.h"
#include "celform/model/camera.h"
#include "celform/model/depth_analysis.h"
#include "celform/model/shading_layers.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace celform::model {

/// What a dab does to the offsets under it, weighted by the falloff f = (1 - d/r)^2.
enum class OffsetPaintMode {
    Add, ///< O += strength f
    Subtract, ///< O -= strength f
    Smooth, ///< O += f / 2 (mean of the neighbours - O)
    Erase, ///< O *= 1 - f (towards zero)
};

struct OffsetBrush {
    OffsetPaintMode mode = OffsetPaintMode::Add;
    double radius = 0.1; ///< model units, on the shape painted on
    double strength = 0.05; ///< offset added at the centre by one dab (Add, Subtract)
    bool mirrorX = false; ///< also paint the mirror image across x = 0
};

/// Made by Document::beginOffsetStroke; pass it to applyOffsetStroke for each dab.
struct OffsetStroke {
    ShadingTarget target;
    OffsetBrush brush;
    int gesture = 0;
    QString undoText;
    algo::Positions shape; ///< the shape painted on (the one shown), #V by 3
    algo::VertexGrid grid; ///< over shape
    algo::VertexNeighbours neighbours; ///< for Smooth
    std::vector<float> values; ///< the target's values as the stroke left them (#V)
    // Working memory of the dabs.
    std::vector<std::uint32_t> indices, mirrorIndices, merged;
    std::vector<float> distances, mirrorDistances, falloff, after;

    [[nodiscard]] bool active() const { return gesture != 0; }
};

/// What Document::autoShadingOffsets is asked for (paper 3, section 4.3).
struct AutoOffsetsRequest {
    ShadingTarget target; ///< for the base, target.frame is the frame analysed
    Camera camera; ///< the view the segments are found in (the centre eye)
    int width = 1280;
    int height = 720;
    float aggressiveness = 1.f; ///< A in [0, 1]
    float percentile = 0.5f; ///< Q in [0, 1]: fraction of each segment left dark
    int bleed = 2; ///< rounds of bleeding over the mesh, [0, kMaxOffsetRounds]
    AnalysisSettings analysis;
};

/// What it did: the analysis before and after (segments are the same: they follow curvature and
/// depth, not the shading), and the solve's report.
struct AutoOffsetsResult {
    std::vector<algo::SegmentStats> before, after;
    double mseBefore = 0.0, mseAfter = 0.0;
    algo::SegmentOffsetReport report;
    double milliseconds = 0.0;
};

/// The most rounds of smoothing or bleeding an edit may ask for.
constexpr int kMaxOffsetRounds = 1000;

} // namespace celform::model
