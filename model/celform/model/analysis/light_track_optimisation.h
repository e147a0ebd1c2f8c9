// Optimise Light Along Shot (issue 26, "a light for the shot"): the light optimised at sampled
// frames of the shot through the shot camera, each frame starting from the previous frame's
// answer, and kept close to it (no key turns more than a limit per frame: no flicker). The result
// is a light track (light_track.h) that LookEdits::applyOptimisedLightTrack stores as one undo
// step. One code path for `celform optimize-light --frames` and the editor's action.
#pragma once

#include "celform/algorithms/progress.h"
#include "celform/model/analysis/light_optimisation.h"
#include "celform/model/data/light_track.h"
#include "celform/model/data/project_data.h"
#include "celform/model/render/render_job.h"

#include <QString>

#include <vector>

namespace celform::model {

struct LightTrackRequest {
    /// Each frame's optimisation; its start applies to the first frame only (the later frames
    /// start from the previous frame's light).
    LightOptimisationRequest light;
    /// The most a key may turn from the previous key per frame between them (the temporal term:
    /// directions as seen from the model's centre), in degrees.
    double maxTurnDegrees = 3.0;
};

/// What happened at one sampled frame.
struct LightTrackFrame {
    int frame = 0;
    Light original; ///< the project's light at the frame before the run (Look::lightAt)
    Light start; ///< where the frame's optimisation started (the previous key, or original)
    Light light; ///< the key stored
    double mseOriginal = 0.0; ///< the depth error (4.4) with original, at the analysed size
    double mseStart = 0.0; ///< with start
    double mse = 0.0; ///< with the key
    double turnDegrees = 0.0; ///< from the previous key (0 for the first)
    bool limited = false; ///< the optimiser's answer turned too far and was turned back
    double milliseconds = 0.0;
};

struct LightTrackReport {
    LightTrack before; ///< the project's light track before the run (may be empty)
    Light lightBefore; ///< the project's single light before the run
    LightTrack after; ///< before with a key at every sampled frame
    std::vector<LightTrackFrame> frames;
    int width = 0, height = 0;
    bool cancelled = false;
    double milliseconds = 0.0;

    [[nodiscard]] double meanMseOriginal() const;
    [[nodiscard]] double meanMse() const;
    [[nodiscard]] double largestTurnDegrees() const;
};

/// Optimises the light at job.firstFrame, firstFrame + step, ... up to job.lastFrame, each
/// resolved as `celform analyze` resolves a frame (the job's camera, else the shot camera at the
/// frame; the project's look). progress counts a step per frame and is asked after each frame
/// and inside it whether to stop: then the report is cancelled and after == before. Reads data
/// only: safe on a worker thread with a copy of the project. Throws IoError naming source.
LightTrackReport optimiseLightTrack(const ProjectData& data, const QString& source, const RenderJob& job,
    const LightTrackRequest& request, algo::Progress* progress = nullptr);

} // namespace celform::model
