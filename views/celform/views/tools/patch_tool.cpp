// Dabs of the patch brush go to the document as one face-set stroke (FaceSetEdits::applyFaceSetStroke).
#include "celform/views/tools/patch_tool.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/viewport/viewport.h"

#include "celform/algorithms/tri_mesh.h"

#include <algorithm>

#include <QCoreApplication>

namespace celform::views {
namespace {

struct Patch {
    Q_DECLARE_TR_FUNCTIONS(celform::views::PatchTool)
};

} // namespace

PatchTool::PatchTool(Viewport* viewport, const BrushSize& size)
    : ViewportTool(viewport)
    , m_size(size)
{ }

void PatchTool::setTarget(const QString& name)
{
    if (name == m_target)
        return;
    m_target = name;
    emit targetChanged();
}

void PatchTool::setMode(Mode mode)
{
    if (mode == m_mode)
        return;
    m_mode = mode;
    emit targetChanged();
}

void PatchTool::activate()
{
    if (m_mode == Mode::Importance)
        emit message(Patch::tr("Paint focal points: drag takes the faces towards importance %1 (strength %2), "
                               "Ctrl+drag back towards 1, [ and ] change the radius.")
                         .arg(double(m_importance), 0, 'g', 3)
                         .arg(double(m_strength), 0, 'g', 3));
    else
        emit message(
            Patch::tr("Paint the patch “%1”: drag adds faces, Ctrl+drag removes them, [ and ] change the radius.")
                .arg(m_target));
}

bool PatchTool::press(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !document->hasMesh())
        return false;
    if (m_mode == Mode::Patch && m_target.trimmed().isEmpty()) {
        emit message(Patch::tr("Choose or create a patch in the Highlights dock first."));
        return true;
    }
    try {
        const model::MirrorPlane mirror = m_mirror ? document->data().mirrorPlane : model::MirrorPlane::Off;
        m_stroke = m_mode == Mode::Importance
            ? document->faceSets().beginImportanceStroke(m_importance, m_strength, mirror)
            : document->faceSets().beginFaceSetStroke(m_target, mirror);
    } catch (const model::EditRefused& e) {
        emit message(e.message());
        return true;
    }
    paint(event);
    return true;
}

void PatchTool::move(const ToolEvent& event)
{
    paint(event);
}

void PatchTool::endDrag()
{
    if (model::Document* document = m_viewport->document())
        document->faceSets().endFaceSetStroke(m_stroke);
    m_stroke = {};
}

void PatchTool::paint(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !m_stroke.active())
        return;
    const std::vector<std::int32_t>& dab = facesUnderBrush(event.position);
    if (dab.empty())
        return;
    try {
        document->faceSets().applyFaceSetStroke(m_stroke, dab, event.modifiers & Qt::ControlModifier);
        if (m_stroke.twinMissing)
            emit message(
                Patch::tr("The mirror finds no twin of these faces across the %1 plane: only this side is painted.")
                    .arg(model::mirrorPlaneName(document->data().mirrorPlane).toUpper()));
    } catch (const model::EditRefused& e) {
        emit message(e.message());
    }
}

const std::vector<std::int32_t>& PatchTool::facesUnderBrush(const QPointF& position)
{
    std::vector<std::int32_t>& faces = m_faces;
    faces.clear();
    const auto hit = m_viewport->pickSurface(position);
    if (!hit)
        return faces;
    const algo::TriMesh& mesh = *m_viewport->document()->data().baseMesh;
    const algo::Positions& shape = m_viewport->displayedShape();
    const algo::VertexFaces& around = mesh.vertexFaces();
    // Only faces turned towards the camera, as the brush of a paint program works on what is
    // seen: painting one side of a thin part (an ear) leaves the other side alone.
    const model::Camera c = m_viewport->camera();
    const Eigen::Vector3f eye = c.eye.cast<float>();
    const Eigen::Vector3f forward = c.forward().cast<float>();
    const bool parallel = c.projection == model::Projection::Orthographic;
    auto facesCamera = [&](std::int32_t f) {
        const Eigen::Vector3f a = shape.row(mesh.faces(f, 0)), b = shape.row(mesh.faces(f, 1)),
                              d = shape.row(mesh.faces(f, 2));
        const Eigen::Vector3f normal = (b - a).cross(d - a);
        const Eigen::Vector3f towardsEye = parallel ? Eigen::Vector3f(-forward) : Eigen::Vector3f(eye - a);
        return normal.dot(towardsEye) > 0.f;
    };
    faces.push_back(std::int32_t(hit->first));
    const Eigen::Vector3f centre = hit->second.cast<float>();
    const float r2 = float(m_size.radius() * m_size.radius());
    // Vertices within the radius: the picked face's corners grown over shared vertices, so the
    // cost follows the dab, not the mesh, and paint does not jump gaps between parts.
    if (m_seen.size() != std::size_t(mesh.vertexCount()))
        m_seen.assign(std::size_t(mesh.vertexCount()), 0);
    m_frontier.assign({mesh.faces(hit->first, 0), mesh.faces(hit->first, 1), mesh.faces(hit->first, 2)});
    m_visited.clear();
    while (!m_frontier.empty()) {
        const std::int32_t v = m_frontier.back();
        m_frontier.pop_back();
        if (m_seen[std::size_t(v)])
            continue;
        m_seen[std::size_t(v)] = 1;
        m_visited.push_back(v);
        if ((shape.row(v).transpose() - centre).squaredNorm() > r2)
            continue;
        for (auto i = around.start[std::size_t(v)]; i < around.start[std::size_t(v) + 1]; ++i) {
            const std::int32_t f = around.faces[std::size_t(i)];
            if (facesCamera(f))
                faces.push_back(f);
            for (int k = 0; k < 3; ++k)
                if (!m_seen[std::size_t(mesh.faces(f, k))])
                    m_frontier.push_back(mesh.faces(f, k));
        }
    }
    for (const std::int32_t v : m_visited)
        m_seen[std::size_t(v)] = 0; // ready for the next dab without a pass over the mesh
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
}

} // namespace celform::views
