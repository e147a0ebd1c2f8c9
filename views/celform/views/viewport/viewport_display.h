// How a viewport draws the model, as opposed to what it shows: the document's look or the neutral
// clay, the key-light gizmo, the lines and stereo (paper 3, sections 3.1 and 4.2.2). The editor's
// menus and the review window set these; the viewport paints with them.
#pragma once

#include "celform/algorithms/stereo.h"
#include "celform/model/data/project_data.h"

#include <Eigen/Core>

#include <functional>
#include <optional>

namespace celform::model {
class Document;
}

namespace celform::views {

class ViewportCamera;

class ViewportDisplay {
public:
    /// changed(shading): a setting changed; shading says whether the look's state (shader,
    /// background, gizmo) must be applied again, not only a repaint.
    ViewportDisplay(const model::Document* document, const ViewportCamera& camera, std::function<void(bool)> changed);

    // --- the cartoon look (DESIGN.md, "Look") ---------------------------------------------------
    /// On (the default): the model is shaded with the document's look exactly as the offline
    /// renderer shades it (at the playhead), on the look's background. Off: the neutral clay look
    /// for modelling. The clay look also shows while brush selection colours are displayed.
    void setShadingEnabled(bool on);
    [[nodiscard]] bool isShadingEnabled() const { return m_shading; }
    /// The key-light gizmo (an arrow towards a directional light, a sphere at a point light);
    /// Ctrl+left drag on it moves the light around the model.
    void setLightGizmoVisible(bool on);
    [[nodiscard]] bool isLightGizmoVisible() const { return m_lightGizmo; }
    /// Whether the gizmo is on screen now (shading on, a model).
    [[nodiscard]] bool lightGizmoShown() const;
    /// Where the gizmo's handle is drawn (model space): the arrow tip or the point light.
    [[nodiscard]] Eigen::Vector3d lightGizmoHandle() const;
    /// Radius of the sphere the light handle moves on, about the model's centre.
    [[nodiscard]] double lightGizmoRadius() const;

    // --- stereo and lines -----------------------------------------------------------------------
    /// Renders left and right eyes and shows their composition (Off: mono, the default).
    void setStereo(algo::StereoOutput output);
    [[nodiscard]] algo::StereoOutput stereo() const { return m_stereo; }
    /// Stereo settings used instead of the document look's (a review session's own interocular);
    /// nothing follows the look again.
    void setStereoLook(const std::optional<model::StereoLook>& look);
    [[nodiscard]] model::StereoLook stereoLook() const;
    /// The eye pair's settings for the current camera, "auto" distances resolved.
    [[nodiscard]] algo::StereoSettings resolvedStereoSettings() const;
    /// Lines shown or hidden whatever the look says; nothing follows Look::showLines.
    void setLinesOverride(std::optional<bool> show);
    [[nodiscard]] bool linesShown() const;
    /// Test hook: with stereo on, show one eye's full-colour image instead of the composition.
    enum class Eye { Both, Left, Right };
    void setEyeOnly(Eye eye);
    [[nodiscard]] Eye eyeOnly() const { return m_eyeOnly; }

    // --- the smooth surface (issue 25) -----------------------------------------------------------
    /// Maya's 3 (on, the default) and 1 (off): the subdivided surface at the look's viewport level,
    /// or the control mesh.
    void setSmoothShown(bool on);
    [[nodiscard]] bool smoothShown() const { return m_smooth; }
    /// The control mesh drawn as a wireframe over the subdivided surface (Maya's cage).
    void setCageShown(bool on);
    [[nodiscard]] bool cageShown() const { return m_cage; }
    /// Most triangles the viewport displays: a bigger surface is shown a level lower.
    void setTriangleCap(std::int64_t triangles);
    /// What the viewport displays of the subdivision, derived from the look, the base model's
    /// size and the settings above.
    struct Subdivision {
        int level = 0; ///< displayed (0: the control mesh)
        int viewportLevel = 0; ///< the look's viewport level
        int renderLevel = 0; ///< the look's render level
        bool capped = false; ///< level lowered below the wanted one by the triangle cap
        std::int64_t triangles = 0; ///< displayed
    };
    [[nodiscard]] Subdivision subdivision() const;

private:
    [[nodiscard]] bool hasMesh() const;

    const model::Document* m_document;
    const ViewportCamera& m_camera;
    std::function<void(bool)> m_changed;
    bool m_shading = true;
    bool m_lightGizmo = true;
    algo::StereoOutput m_stereo = algo::StereoOutput::Off;
    std::optional<model::StereoLook> m_stereoLook;
    std::optional<bool> m_linesOverride;
    Eye m_eyeOnly = Eye::Both;
    bool m_smooth = true;
    bool m_cage = false;
    std::int64_t m_triangleCap = 2'000'000;
};

} // namespace celform::views
