// Blend settings and the cartoon look, property by property: each setter is one undo step with
// its own text, and within one gesture (a light drag, a slider press-to-release) it merges only
// with edits of the same property.
#include "celform/model/document/look_edits.h"

#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"

#include <cmath>

namespace celform::model {
namespace {

/// The step that sets one member of the look (null when it already has the value).
template <typename T>
QUndoCommand* lookCommand(
    Document* doc, const QString& text, Property property, T Look::*member, const T& value, GestureId gesture)
{
    if (doc->data().look.*member == value)
        return nullptr;
    return new PropertyCommand<T>(
        doc, text, {property}, fieldOf(&ProjectData::look, member), value, ChangeSet::of(Part::Look), gesture);
}

} // namespace

// --- blend settings -------------------------------------------------------------------------------

void LookEdits::setSharpness(double alpha, GestureId gesture)
{
    // Paper 1, section 3.2.2: w' = w^alpha / sum(w^alpha) needs alpha > 0.
    if (!(alpha > 0.0) || !std::isfinite(alpha) || alpha == data().blend.sharpness)
        return;
    push(new PropertyCommand<double>(m_doc, tr("Change Blend Sharpness"), {Property::Sharpness},
        fieldOf(&ProjectData::blend, &BlendSettings::sharpness), alpha, ChangeSet::of(Part::Blend), gesture));
}

void LookEdits::setUnspecifiedMode(UnspecifiedMode mode, GestureId gesture)
{
    if (mode == data().blend.unspecified)
        return;
    push(new PropertyCommand<UnspecifiedMode>(m_doc, tr("Change Unspecified Regions"), {Property::UnspecifiedMode},
        fieldOf(&ProjectData::blend, &BlendSettings::unspecified), mode, ChangeSet::of(Part::Blend), gesture));
}

void LookEdits::setTimeInterpolation(TimeInterpolation time, GestureId gesture)
{
    if (time == data().blend.time)
        return;
    push(new PropertyCommand<TimeInterpolation>(m_doc, tr("Change Time Interpolation"), {Property::TimeInterpolation},
        fieldOf(&ProjectData::blend, &BlendSettings::time), time, ChangeSet::of(Part::Blend), gesture));
}

// --- the look ---------------------------------------------------------------------------------------

void LookEdits::setShadingStyle(ShadingStyle style, int material, GestureId gesture)
{
    const Look& look = data().look;
    if (material < 0) {
        if (look.style == style && look.materialStyles.empty())
            return;
        auto* cmd = new CompositeCommand(m_doc, tr("Change Shading Style"));
        new PropertyCommand<ShadingStyle>(m_doc, {}, {Property::ShadingStyle},
            fieldOf(&ProjectData::look, &Look::style), style, ChangeSet::of(Part::Look), {}, cmd);
        if (!look.materialStyles.empty())
            new PropertyCommand<std::map<int, ShadingStyle>>(m_doc, {}, {Property::MaterialStyles},
                fieldOf(&ProjectData::look, &Look::materialStyles), {}, ChangeSet::of(Part::Look), {}, cmd);
        push(cmd);
        return;
    }
    std::map<int, ShadingStyle> styles = look.materialStyles;
    if (const auto it = styles.find(material); it != styles.end() && it->second == style)
        return;
    styles[material] = style;
    push(new PropertyCommand<std::map<int, ShadingStyle>>(m_doc, tr("Change Material Style"),
        {Property::MaterialStyles, 0, material}, fieldOf(&ProjectData::look, &Look::materialStyles), std::move(styles),
        ChangeSet::of(Part::Look), gesture));
}

void LookEdits::setLight(const Light& light, GestureId gesture)
{
    if (!lightProblem(light).isEmpty())
        return; // a directional light needs a direction
    const Look& look = data().look;
    if (!look.lightTrack.empty()) {
        // The light on screen is the track's: move it by keying the current frame.
        const int frame = data().currentFrame;
        if (look.lightTrack.hasKey(frame) && look.lightAt(frame) == light)
            return;
        LightTrack track = look.lightTrack;
        track.setKey(frame, light);
        push(new PropertyCommand<LightTrack>(m_doc, tr("Key Light at Frame %1").arg(frame), {Property::LightTrack},
            fieldOf(&ProjectData::look, &Look::lightTrack), std::move(track), ChangeSet::of(Part::Look), gesture));
        return;
    }
    if (light == look.light)
        return;
    const QString text = light.type != look.light.type ? tr("Change Light Type") : tr("Move Light");
    push(new PropertyCommand<Light>(m_doc, text, {Property::Light}, fieldOf(&ProjectData::look, &Look::light), light,
        ChangeSet::of(Part::Look), gesture));
}

void LookEdits::applyOptimisedLight(const Light& startedFrom, const Light& found, int frame)
{
    if (found == startedFrom)
        return;
    const Look& look = data().look;
    if (!(startedFrom == look.lightAt(frame)))
        throw EditRefused(tr("The light changed while it was being optimised; run Optimise Light for Stereo again."));
    if (!lightProblem(found).isEmpty())
        throw EditRefused(tr("The optimised light is not usable."));
    if (!look.lightTrack.empty()) {
        // A shot with a light track: the light found is keyed at its frame (issue 26).
        LightTrack track = look.lightTrack;
        track.setKey(frame, found);
        push(new PropertyCommand<LightTrack>(m_doc, tr("Optimise Light for Stereo"), {Property::LightTrack},
            fieldOf(&ProjectData::look, &Look::lightTrack), std::move(track), ChangeSet::of(Part::Look), {}));
        return;
    }
    push(new PropertyCommand<Light>(m_doc, tr("Optimise Light for Stereo"), {Property::Light},
        fieldOf(&ProjectData::look, &Look::light), found, ChangeSet::of(Part::Look), {}));
}

void LookEdits::setLightTrack(const LightTrack& track, const QString& undoText)
{
    const QString problem = lightTrackProblem(track);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    if (track == data().look.lightTrack)
        return;
    push(new PropertyCommand<LightTrack>(m_doc, undoText, {Property::LightTrack},
        fieldOf(&ProjectData::look, &Look::lightTrack), track, ChangeSet::of(Part::Look), {}));
}

void LookEdits::applyOptimisedLightTrack(const LightTrack& startedFrom, const LightTrack& found)
{
    if (found == startedFrom)
        return;
    if (startedFrom != data().look.lightTrack)
        throw EditRefused(
            tr("The light track changed while it was being optimised; run Optimise Light Along Shot again."));
    setLightTrack(found, tr("Optimise Light Along Shot"));
}

void LookEdits::setBackgroundColor(const Eigen::Vector3f& color, GestureId gesture)
{
    if (color == data().look.backgroundColor || !color.allFinite())
        return;
    push(new PropertyCommand<Eigen::Vector3f>(m_doc, tr("Change Background Colour"), {Property::Background},
        fieldOf(&ProjectData::look, &Look::backgroundColor), color, ChangeSet::of(Part::Look), gesture));
}

void LookEdits::setToonRamp(const algo::ToonRamp& ramp, GestureId gesture)
{
    if (!ramp.isValid())
        return; // never store tones the renderer cannot use
    if (QUndoCommand* cmd = lookCommand(m_doc, tr("Change Toon Tones"), Property::ToonRamp, &Look::toon, ramp, gesture))
        push(cmd);
}

void LookEdits::setToonEvaluation(algo::ToonEvaluation evaluation, GestureId gesture)
{
    if (QUndoCommand* cmd = lookCommand(
            m_doc, tr("Change Toon Evaluation"), Property::ToonEvaluation, &Look::toonEvaluation, evaluation, gesture))
        push(cmd);
}

void LookEdits::setGooch(const algo::GoochParams& gooch, GestureId gesture)
{
    if (QUndoCommand* cmd
        = lookCommand(m_doc, tr("Change Gooch Shading"), Property::Gooch, &Look::gooch, gooch, gesture))
        push(cmd);
}

void LookEdits::setHatch(const algo::HatchParams& hatch, GestureId gesture)
{
    if (QUndoCommand* cmd = lookCommand(m_doc, tr("Change Hatching"), Property::Hatch, &Look::hatch, hatch, gesture))
        push(cmd);
}

void LookEdits::setShowLines(bool show, GestureId gesture)
{
    if (QUndoCommand* cmd = lookCommand(
            m_doc, show ? tr("Show Lines") : tr("Hide Lines"), Property::ShowLines, &Look::showLines, show, gesture))
        push(cmd);
}

void LookEdits::setLineSettings(const algo::LineSettings& settings, GestureId gesture)
{
    if (QUndoCommand* cmd
        = lookCommand(m_doc, tr("Change Line Kinds"), Property::LineSettings, &Look::lines, settings, gesture))
        push(cmd);
}

void LookEdits::setLineStyle(const algo::LineStyle& style, GestureId gesture)
{
    if (QUndoCommand* cmd
        = lookCommand(m_doc, tr("Change Line Style"), Property::LineStyle, &Look::lineStyle, style, gesture))
        push(cmd);
}

void LookEdits::setStereo(const StereoLook& stereo, GestureId gesture)
{
    if (QUndoCommand* cmd
        = lookCommand(m_doc, tr("Change Stereo Settings"), Property::Stereo, &Look::stereo, stereo, gesture))
        push(cmd);
}

void LookEdits::setSubdivision(const SubdivisionLook& subdivision, GestureId gesture)
{
    if (const QString problem = subdivisionProblem(subdivision); !problem.isEmpty())
        throw EditRefused(problem);
    if (QUndoCommand* cmd
        = lookCommand(m_doc, tr("Change Subdivision"), Property::Subdivision, &Look::subdivision, subdivision, gesture))
        push(cmd);
}

void LookEdits::setRenderCamera(const std::optional<Camera>& camera, GestureId gesture)
{
    if (camera == data().look.renderCamera)
        return;
    if (camera && !camera->isValid())
        throw EditRefused(tr("The render camera is not valid (eye, target and up must differ)."));
    push(new PropertyCommand<std::optional<Camera>>(m_doc,
        camera ? tr("Set Render Camera") : tr("Remove Render Camera"), {Property::RenderCamera},
        fieldOf(&ProjectData::look, &Look::renderCamera), camera, ChangeSet::of(Part::Look), gesture));
}

void LookEdits::setLook(const Look& look)
{
    // The highlight layers have edits of their own: this step leaves them as they are.
    Look wanted = look;
    wanted.highlights = data().look.highlights;
    if (wanted == data().look)
        return;
    if (!wanted.toon.isValid())
        throw EditRefused(tr("The look's toon tones are not valid."));
    if (wanted.renderCamera && !wanted.renderCamera->isValid())
        throw EditRefused(tr("The render camera is not valid (eye, target and up must differ)."));
    if (const QString problem = subdivisionProblem(wanted.subdivision); !problem.isEmpty())
        throw EditRefused(problem);
    if (const QString problem = lightTrackProblem(wanted.lightTrack); !problem.isEmpty())
        throw EditRefused(problem);
    push(new PropertyCommand<Look>(m_doc, tr("Apply Look"), {Property::WholeLook},
        [](ProjectData& d) { return &d.look; }, std::move(wanted), ChangeSet::of(Part::Look), {}));
}

} // namespace celform::model
