// Blend settings and the cartoon look, property by property (doc.look()): each setter is one
// undo step with its own text, and given a gesture (a light drag, a slider press-to-release) it
// merges only with edits of the same property in it.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/gesture.h"

#include <optional>

namespace celform::model {

class LookEdits : public DocumentFacade {
public:
    // --- blend settings (paper 1, sections 3.2-3.3 and 4.2) -----------------------------------
    void setSharpness(double alpha, GestureId gesture = {});
    void setUnspecifiedMode(UnspecifiedMode mode, GestureId gesture = {});
    void setTimeInterpolation(TimeInterpolation time, GestureId gesture = {});

    // --- the look ------------------------------------------------------------------------------
    /// The style of every material (material < 0: clears per-material styles) or of one.
    void setShadingStyle(ShadingStyle style, int material = -1, GestureId gesture = {});
    /// The key light; a change of vector is "Move Light", of type "Change Light Type". When the
    /// look has a light track, keys the light at the current frame instead.
    void setLight(const Light& light, GestureId gesture = {});
    /// Optimise Light for Stereo (paper 3, 4.1): stores the light a finished run of
    /// model::optimiseLight at frame found (found) as one undo step; nothing when it kept the
    /// light. With a light track the light is keyed at frame, else it is the single light. Throws
    /// EditRefused when the light at frame is no longer the one the run started from (startedFrom).
    void applyOptimisedLight(const Light& startedFrom, const Light& found, int frame);
    /// Replaces the light track (one undo step named undoText; empty: the single light serves
    /// every frame again). Throws EditRefused (lightTrackProblem).
    void setLightTrack(const LightTrack& track, const QString& undoText);
    /// Optimise Light Along Shot (issue 26): stores the track a finished run of
    /// model::optimiseLightTrack found as one undo step; nothing when it is unchanged. Throws
    /// EditRefused when the track is no longer the one the run started from.
    void applyOptimisedLightTrack(const LightTrack& startedFrom, const LightTrack& found);
    void setBackgroundColor(const Eigen::Vector3f& color, GestureId gesture = {});
    /// Refused (no change) when the ramp is not valid.
    void setToonRamp(const algo::ToonRamp& ramp, GestureId gesture = {});
    void setToonEvaluation(algo::ToonEvaluation evaluation, GestureId gesture = {});
    void setGooch(const algo::GoochParams& gooch, GestureId gesture = {});
    void setHatch(const algo::HatchParams& hatch, GestureId gesture = {});
    void setShowLines(bool show, GestureId gesture = {});
    void setLineSettings(const algo::LineSettings& settings, GestureId gesture = {});
    void setLineStyle(const algo::LineStyle& style, GestureId gesture = {});
    void setStereo(const StereoLook& stereo, GestureId gesture = {});
    /// The render and viewport subdivision levels (issue 25) as one step; throws EditRefused for
    /// levels out of range (subdivisionProblem).
    void setSubdivision(const SubdivisionLook& subdivision, GestureId gesture = {});
    /// The shot's camera (none: a framed default view). Refuses an invalid camera.
    void setRenderCamera(const std::optional<Camera>& camera, GestureId gesture = {});
    /// Replaces the whole look but its highlight layers in one step ("Apply Look", presets);
    /// never merges.
    void setLook(const Look& look);

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
};

} // namespace celform::model
