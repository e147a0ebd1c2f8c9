// Automatic per-segment shading offsets (paper 3, section 4.3): the solve, off the document. It
// reads the project as it is and returns the values; ShadingEdits::applyAutoOffsets stores them as
// one undo step. The editor runs it on a worker thread, `celform offsets --auto` in line.
#pragma once

#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/progress.h"
#include "celform/algorithms/shading_offsets.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/data/shading_layers.h"

#include <vector>

namespace celform::model {

/// Which segments the automatic offsets solve.
enum class OffsetSegments {
    Outside, ///< those whose ratio is outside the window (thesis 4.3; the default)
    All, ///< every covered segment, to exactly 1 - Q
};

/// What solveAutoOffsets is asked for.
struct AutoOffsetsRequest {
    ShadingTarget target; ///< for the base, target.frame is the frame analysed
    Camera camera; ///< the view the segments are found in (the centre eye)
    int width = 1280;
    int height = 720;
    float aggressiveness = 1.f; ///< A in [0, 1]
    float percentile = 0.5f; ///< Q in [0, 1]: fraction of each segment left dark
    int bleed = 2; ///< rounds of bleeding over the mesh, [0, kMaxOffsetRounds]
    OffsetSegments segments = OffsetSegments::Outside;
    AnalysisSettings analysis; ///< its window chooses the segments outside it
};

/// What it found: the target's new values, and the analysis before and after (segments are the
/// same: they follow curvature and depth, not the shading) with the solve's report.
struct AutoOffsetsResult {
    ShadingTarget target;
    std::vector<float> values; ///< #V, the target's layer that gives each segment its ratio
    std::vector<algo::SegmentStats> before, after;
    double mseBefore = 0.0, mseAfter = 0.0;
    algo::SegmentOffsetReport report;
    double milliseconds = 0.0;
    bool cancelled = false; ///< stopped through progress: values is empty
};

/// Solves the offsets of request.target for the view of request.camera at the target's frame: the
/// offsets in effect there give each segment of the depth analysis outside the window (or every
/// segment, OffsetSegments::All) the ratio 1 - Q (aggressiveness 1). A key layer's values are its
/// share of the field divided by the key's weight in this view, clamped to the solve's limit
/// (algo::SegmentOffsetSettings::limit), so a key seen with little weight never stores huge values. Throws EditRefused
/// (no base model or key, settings out of range, a key without weight in that view, a picture that cannot be solved).
/// Three analyses; progress counts them.
AutoOffsetsResult solveAutoOffsets(
    const ProjectData& data, const AutoOffsetsRequest& request, algo::Progress* progress = nullptr);

} // namespace celform::model
