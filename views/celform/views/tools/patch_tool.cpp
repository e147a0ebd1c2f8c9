// Dabs of the patch brush go to the document as one face-set stroke (FaceSetEdits::applyFaceSetStroke).
#include "celform/views/tools/patch_tool.h"

#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/segment_overrides.h"
#include "celform/model/document/document.h"
#include "celform/model/render/render_output.h"
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
    m_firstSegment = -1;
    m_strokePoints.clear();
    if (mode == m_mode)
        return;
    m_mode = mode;
    emit targetChanged();
}

/// One analysed picture of the segment brush.
struct SegmentEdit {
    model::SegmentPicture picture;
    model::RenderJob job;
};

bool PatchTool::analysePicture(SegmentEdit& edit)
{
    model::Document* document = m_viewport->document();
    edit.job.camera = m_viewport->camera();
    edit.job.firstFrame = edit.job.lastFrame = document->currentFrame();
    edit.job.size = m_viewport->size();
    try {
        const model::FrameAnalysis analysed
            = model::analyseProject(document->data(), QString(), edit.job, {}, &edit.picture.faces);
        edit.picture.segments = analysed.analysis.segments;
        model::voteSegmentFaces(edit.picture, std::int32_t(document->data().baseMesh->faceCount()));
        return true;
    } catch (const model::IoError& e) {
        emit message(e.message());
    } catch (const std::bad_alloc&) {
        emit message(Patch::tr("There is not enough memory to analyse the picture."));
    }
    return false;
}

void PatchTool::pickSegment(const QPointF& position)
{
    SegmentEdit edit;
    if (!analysePicture(edit))
        return;
    const int x = int(position.x()), y = int(position.y());
    const algo::SegmentLabels& labels = edit.picture.segments;
    const int segment = x >= 0 && y >= 0 && x < labels.width && y < labels.height
        ? labels.labels[std::size_t(y) * std::size_t(labels.width) + std::size_t(x)]
        : -1;
    if (segment < 0) {
        emit message(Patch::tr("No segment of the depth analysis is under the cursor."));
        return;
    }
    if (m_firstSegment < 0 || m_firstSegment == segment) {
        m_firstSegment = segment;
        emit message(Patch::tr("Segment %1 chosen: click the segment to merge it with.").arg(segment));
        return;
    }
    model::Document* document = m_viewport->document();
    try {
        document->faceSets().setSegmentOverrides(
            model::mergedSegmentOverrides(document->data(), edit.picture, {m_firstSegment, segment}),
            Patch::tr("Merge Segments"));
        emit message(Patch::tr("Segments %1 and %2 merged.").arg(m_firstSegment).arg(segment));
    } catch (const model::EditRefused& e) {
        emit message(e.message());
    }
    m_firstSegment = -1;
}

void PatchTool::splitAlong()
{
    std::vector<QPointF> points;
    points.swap(m_strokePoints);
    if (points.size() < 2)
        return;
    SegmentEdit edit;
    if (!analysePicture(edit))
        return;
    // The segment the stroke crosses: the one most of its positions lie on.
    const algo::SegmentLabels& labels = edit.picture.segments;
    std::vector<int> votes(labels.sizes.size(), 0);
    std::vector<Eigen::Vector2d> stroke;
    for (const QPointF& p : points) {
        stroke.emplace_back(p.x(), p.y());
        const int x = int(p.x()), y = int(p.y());
        if (x >= 0 && y >= 0 && x < labels.width && y < labels.height)
            if (const std::int32_t s = labels.labels[std::size_t(y) * std::size_t(labels.width) + std::size_t(x)];
                s >= 0)
                ++votes[std::size_t(s)];
    }
    const auto most = std::max_element(votes.begin(), votes.end());
    if (most == votes.end() || *most == 0) {
        emit message(Patch::tr("The stroke crosses no segment of the depth analysis."));
        return;
    }
    const int segment = int(most - votes.begin());
    model::Document* document = m_viewport->document();
    try {
        const model::AnalysisView view = model::resolveAnalysisView(document->data(), QString(), edit.job);
        document->faceSets().setSegmentOverrides(
            model::splitSegmentOverrides(document->data(), edit.picture, segment, stroke, view.shape,
                model::rasterCamera(view.camera, edit.job.size.width(), edit.job.size.height())),
            Patch::tr("Split Segment"));
        emit message(Patch::tr("Segment %1 split along the stroke.").arg(segment));
    } catch (const model::EditRefused& e) {
        emit message(e.message());
    } catch (const model::IoError& e) {
        emit message(e.message());
    }
}

void PatchTool::activate()
{
    if (m_mode == Mode::MergeSegments)
        emit message(
            Patch::tr("Merge segments: click a segment of the depth analysis, then the one to merge it with."));
    else if (m_mode == Mode::SplitSegment)
        emit message(Patch::tr("Split a segment: drag across a segment of the depth analysis along the cut."));
    else if (m_mode == Mode::Importance)
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
    if (m_mode == Mode::MergeSegments) {
        pickSegment(event.position);
        return true; // a click: the release ends it
    }
    if (m_mode == Mode::SplitSegment) {
        m_strokePoints.assign(1, event.position);
        return true;
    }
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
    if (m_mode == Mode::SplitSegment)
        m_strokePoints.push_back(event.position);
    else
        paint(event);
}

void PatchTool::release(const ToolEvent& event)
{
    if (m_mode == Mode::SplitSegment) {
        m_strokePoints.push_back(event.position);
        splitAlong();
    }
    endDrag();
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
