// The displayed surface at the viewport's subdivision level (subdivided_display.h).
#include "celform/views/viewport/subdivided_display.h"

#include "celform/algorithms/mesh_topology.h"
#include "celform/model/render/subdivided_surface.h"
#include "celform/views/viewport/displayed_shape.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace celform::views {

SubdividedDisplay::SubdividedDisplay() = default;
SubdividedDisplay::~SubdividedDisplay() = default;

bool SubdividedDisplay::setLevel(const model::ProjectData& data, int level)
{
    level = data.baseMesh ? std::clamp(level, 0, algo::kMaxSubdivisionLevel) : 0;
    if (!m_lookUp && level == this->level())
        return false;
    m_lookUp = false;
    const auto before = m_surface;
    // The stencil is built once per base model and level and shared with the renderer's cache;
    // a face-set or base-offset change only rebuilds the stand-in project.
    m_surface = level > 0 ? model::subdividedSurface(data, level) : nullptr;
    m_level = level;
    const bool sameTopology = before && m_surface && before->stencil == m_surface->stencil;
    if (!sameTopology)
        m_source = 0; // the next refresh is a full one
    return !(sameTopology || (!before && !m_surface));
}

void SubdividedDisplay::refresh(const DisplayedShape& control, std::uint64_t controlBefore)
{
    if (!m_surface) {
        m_source = 0;
        return;
    }
    const algo::Shape& source = control.shape();
    if (source.generation == m_source)
        return;
    const algo::SubdivisionStencil& stencil = *m_surface->stencil;
    m_changed.clear();
    const std::vector<std::uint32_t>& rows = control.changedVertices();
    if (!rows.empty() && m_source != 0 && m_source == controlBefore && m_shape.positions.rows() == stencil.vertexCount()
        && m_limitNormals.rows() == stencil.vertexCount()) {
        // Issue 25: a brush step re-subdivides only the stencil rows the brushed vertices reach,
        // and the limit normals of the rows whose ring holds one of them.
        algo::updateSubdivision(stencil, source.positions, rows, m_shape.positions, m_limitNormals, m_scratch);
        m_moved.assign(m_scratch.positionRows.begin(), m_scratch.positionRows.end());
        std::sort(m_moved.begin(), m_moved.end());
        m_normalRows.assign(m_scratch.tangentRows.begin(), m_scratch.tangentRows.end());
        std::sort(m_normalRows.begin(), m_normalRows.end());
        std::set_union(
            m_moved.begin(), m_moved.end(), m_normalRows.begin(), m_normalRows.end(), std::back_inserter(m_changed));
    } else {
        // One sparse product (V_L = S V) on the blended, animated, deformed control shape, shaded
        // with its limit normals as `celform render` shades it.
        m_surface->apply(source.positions, m_shape.positions);
        algo::limitNormals(stencil, m_shape.positions, m_limitNormals);
    }
    m_shape.touch();
    m_source = source.generation;
}

SubdividedDisplay::View SubdividedDisplay::view(
    const model::ProjectData& controlData, const DisplayedShape& control) const
{
    if (!m_surface)
        return {
            &controlData, controlData.baseMesh.get(), &control.shape(), &control.normals(), &control.changedVertices()};
    return {&m_surface->display, m_surface->display.baseMesh.get(), &m_shape, &m_limitNormals, &m_changed};
}

const std::vector<float>& SubdividedDisplay::perVertex(const std::vector<float>& control, std::vector<float>& out) const
{
    if (!m_surface)
        return control;
    m_surface->apply(control, out);
    return out;
}

std::pair<std::int64_t, Eigen::Vector3d> SubdividedDisplay::toControl(std::int64_t face,
    const Eigen::Vector3d& position, const algo::Faces& controlFaces, const algo::Positions& controlShape) const
{
    if (!m_surface || face < 0 || face >= m_surface->stencil->faceCount()
        || m_surface->stencil->controlFaces != controlFaces.rows())
        return {face, position};
    const algo::SubdivisionStencil& s = *m_surface->stencil;
    const std::int64_t parent = s.parentFace[std::size_t(face)];
    // The hit's barycentric coordinates in the displayed triangle (least squares in its plane),
    // then in the control face through the corners' coordinates there (cornerBarycentric).
    Eigen::Vector3d corner[3];
    for (int k = 0; k < 3; ++k)
        corner[k] = m_shape.positions.row(s.faces(face, k)).cast<double>().transpose();
    const Eigen::Vector3d e1 = corner[1] - corner[0], e2 = corner[2] - corner[0], d = position - corner[0];
    const double a = e1.dot(e1), b = e1.dot(e2), c = e2.dot(e2), p = d.dot(e1), q = d.dot(e2);
    const double det = a * c - b * b;
    double u = 1.0 / 3.0, v = 1.0 / 3.0;
    if (std::abs(det) > 1e-30) {
        u = (c * p - b * q) / det;
        v = (a * q - b * p) / det;
    }
    const Eigen::RowVector3d local(1.0 - u - v, u, v);
    Eigen::RowVector3d bary = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 3; ++k)
        bary += local(k) * cornerBarycentric(s, face, k);
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
        point += bary(k) * controlShape.row(controlFaces(parent, k)).cast<double>().transpose();
    return {parent, point};
}

const algo::BrushSelection* SubdividedDisplay::selection(
    const algo::BrushSelection* selection, const algo::BrushSelection* mirror, Eigen::Index controlVertices)
{
    if (!m_surface)
        return selection;
    m_controlWeights.assign(std::size_t(controlVertices), 0.0f);
    for (const algo::BrushSelection* s : {selection, mirror})
        if (s)
            for (std::size_t k = 0; k < s->indices.size() && k < s->weights.size(); ++k)
                if (s->indices[k] < m_controlWeights.size())
                    m_controlWeights[s->indices[k]] = s->weights[k];
    m_surface->apply(m_controlWeights, m_weights);
    m_selection.indices.clear();
    m_selection.weights.clear();
    // A displayed vertex is tinted where the stencil carries a visible share of the weights.
    constexpr float kShown = 0.05f;
    for (std::size_t i = 0; i < m_weights.size(); ++i)
        if (m_weights[i] > kShown) {
            m_selection.indices.push_back(std::uint32_t(i));
            m_selection.weights.push_back(std::min(1.0f, m_weights[i]));
        }
    return &m_selection;
}

} // namespace celform::views
