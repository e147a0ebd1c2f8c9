// Blend settings and the cartoon look, property by property: each setter is one undo step with
// its own text, and within one gesture (a light drag, a slider press-to-release) it merges only
// with edits of the same property.
#include "celform/model/document/document.h"

#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"

#include <cmath>

namespace celform::model {
namespace {

/// Locates a member of the look.
template <typename T> std::function<T*(ProjectData&)> lookField(T Look::*member)
{
    return [member](ProjectData& d) { return &(d.look.*member); };
}

template <typename T> std::function<T*(ProjectData&)> blendField(T BlendSettings::*member)
{
    return [member](ProjectData& d) { return &(d.blend.*member); };
}

/// The step that sets one member of the look (null when it already has the value).
template <typename T>
QUndoCommand* lookCommand(
    Document* doc, const QString& text, Property property, T Look::*member, const T& value, int gesture)
{
    if (doc->data().look.*member == value)
        return nullptr;
    return new PropertyCommand<T>(
        doc, text, property, {}, lookField(member), value, ChangeSet::of(Part::Look), gesture);
}

} // namespace

// --- blend settings -------------------------------------------------------------------------------

void Document::setSharpness(double alpha)
{
    // Paper 1, section 3.2.2: w' = w^alpha / sum(w^alpha) needs alpha > 0.
    if (!(alpha > 0.0) || !std::isfinite(alpha) || alpha == m_data.blend.sharpness)
        return;
    push(new PropertyCommand<double>(this, tr("Change Blend Sharpness"), Property::Sharpness, {},
        blendField(&BlendSettings::sharpness), alpha, ChangeSet::of(Part::Blend), m_gesture));
}

void Document::setUnspecifiedMode(UnspecifiedMode mode)
{
    if (mode == m_data.blend.unspecified)
        return;
    push(new PropertyCommand<UnspecifiedMode>(this, tr("Change Unspecified Regions"), Property::UnspecifiedMode, {},
        blendField(&BlendSettings::unspecified), mode, ChangeSet::of(Part::Blend), m_gesture));
}

void Document::setTimeInterpolation(TimeInterpolation time)
{
    if (time == m_data.blend.time)
        return;
    push(new PropertyCommand<TimeInterpolation>(this, tr("Change Time Interpolation"), Property::TimeInterpolation, {},
        blendField(&BlendSettings::time), time, ChangeSet::of(Part::Blend), m_gesture));
}

// --- the look ---------------------------------------------------------------------------------------

void Document::setShadingStyle(ShadingStyle style, int material)
{
    const Look& look = m_data.look;
    if (material < 0) {
        if (look.style == style && look.materialStyles.empty())
            return;
        auto* cmd = new CompositeCommand(this, tr("Change Shading Style"));
        new PropertyCommand<ShadingStyle>(
            this, {}, Property::ShadingStyle, {}, lookField(&Look::style), style, ChangeSet::of(Part::Look), 0, cmd);
        if (!look.materialStyles.empty())
            new PropertyCommand<std::map<int, ShadingStyle>>(this, {}, Property::MaterialStyles, {},
                lookField(&Look::materialStyles), {}, ChangeSet::of(Part::Look), 0, cmd);
        push(cmd);
        return;
    }
    std::map<int, ShadingStyle> styles = look.materialStyles;
    if (const auto it = styles.find(material); it != styles.end() && it->second == style)
        return;
    styles[material] = style;
    push(new PropertyCommand<std::map<int, ShadingStyle>>(this, tr("Change Material Style"), Property::MaterialStyles,
        QString::number(material), lookField(&Look::materialStyles), std::move(styles), ChangeSet::of(Part::Look),
        m_gesture));
}

void Document::setLight(const Light& light)
{
    if (light == m_data.look.light || !light.vector.allFinite())
        return;
    if (light.type == LightType::Directional && light.vector.norm() == 0.0)
        return; // a directional light needs a direction
    const QString text = light.type != m_data.look.light.type ? tr("Change Light Type") : tr("Move Light");
    push(new PropertyCommand<Light>(
        this, text, Property::Light, {}, lookField(&Look::light), light, ChangeSet::of(Part::Look), m_gesture));
}

void Document::applyOptimisedLight(const Light& startedFrom, const Light& found)
{
    if (found == startedFrom)
        return;
    if (!(startedFrom == m_data.look.light))
        throw EditRefused(tr("The light changed while it was being optimised; run Optimise Light for Stereo again."));
    const Light& light = found;
    if (!light.vector.allFinite() || (light.type == LightType::Directional && light.vector.norm() == 0.0))
        throw EditRefused(tr("The optimised light is not usable."));
    push(new PropertyCommand<Light>(this, tr("Optimise Light for Stereo"), Property::Light, {}, lookField(&Look::light),
        light, ChangeSet::of(Part::Look), 0));
}

void Document::setBackgroundColor(const Eigen::Vector3f& color)
{
    if (color == m_data.look.backgroundColor || !color.allFinite())
        return;
    push(new PropertyCommand<Eigen::Vector3f>(this, tr("Change Background Colour"), Property::Background, {},
        lookField(&Look::backgroundColor), color, ChangeSet::of(Part::Look), m_gesture));
}

void Document::setToonRamp(const algo::ToonRamp& ramp)
{
    if (!ramp.isValid())
        return; // never store tones the renderer cannot use
    if (QUndoCommand* cmd
        = lookCommand(this, tr("Change Toon Tones"), Property::ToonRamp, &Look::toon, ramp, m_gesture))
        push(cmd);
}

void Document::setToonEvaluation(algo::ToonEvaluation evaluation)
{
    if (QUndoCommand* cmd = lookCommand(
            this, tr("Change Toon Evaluation"), Property::ToonEvaluation, &Look::toonEvaluation, evaluation, m_gesture))
        push(cmd);
}

void Document::setGooch(const algo::GoochParams& gooch)
{
    if (QUndoCommand* cmd
        = lookCommand(this, tr("Change Gooch Shading"), Property::Gooch, &Look::gooch, gooch, m_gesture))
        push(cmd);
}

void Document::setHatch(const algo::HatchParams& hatch)
{
    if (QUndoCommand* cmd = lookCommand(this, tr("Change Hatching"), Property::Hatch, &Look::hatch, hatch, m_gesture))
        push(cmd);
}

void Document::setShowLines(bool show)
{
    if (QUndoCommand* cmd = lookCommand(
            this, show ? tr("Show Lines") : tr("Hide Lines"), Property::ShowLines, &Look::showLines, show, m_gesture))
        push(cmd);
}

void Document::setLineSettings(const algo::LineSettings& settings)
{
    if (QUndoCommand* cmd
        = lookCommand(this, tr("Change Line Kinds"), Property::LineSettings, &Look::lines, settings, m_gesture))
        push(cmd);
}

void Document::setLineStyle(const algo::LineStyle& style)
{
    if (QUndoCommand* cmd
        = lookCommand(this, tr("Change Line Style"), Property::LineStyle, &Look::lineStyle, style, m_gesture))
        push(cmd);
}

void Document::setStereo(const StereoLook& stereo)
{
    if (QUndoCommand* cmd
        = lookCommand(this, tr("Change Stereo Settings"), Property::Stereo, &Look::stereo, stereo, m_gesture))
        push(cmd);
}

void Document::setRenderCamera(const std::optional<Camera>& camera)
{
    if (camera == m_data.look.renderCamera)
        return;
    if (camera && !camera->isValid())
        throw EditRefused(tr("The render camera is not valid (eye, target and up must differ)."));
    push(new PropertyCommand<std::optional<Camera>>(this, camera ? tr("Set Render Camera") : tr("Remove Render Camera"),
        Property::RenderCamera, {}, lookField(&Look::renderCamera), camera, ChangeSet::of(Part::Look), m_gesture));
}

void Document::setLook(const Look& look)
{
    // The highlight layers have edits of their own: this step leaves them as they are.
    Look wanted = look;
    wanted.highlights = m_data.look.highlights;
    if (wanted == m_data.look)
        return;
    if (!wanted.toon.isValid())
        throw EditRefused(tr("The look's toon tones are not valid."));
    if (wanted.renderCamera && !wanted.renderCamera->isValid())
        throw EditRefused(tr("The render camera is not valid (eye, target and up must differ)."));
    push(new PropertyCommand<Look>(
        this, tr("Apply Look"), Property::WholeLook, {}, [](ProjectData& d) { return &d.look; }, std::move(wanted),
        ChangeSet::of(Part::Look), 0));
}

} // namespace celform::model
