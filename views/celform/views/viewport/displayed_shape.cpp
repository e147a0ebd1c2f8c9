// Lazy, partial recomputation of the displayed shape (trimesh2's rule: a change invalidates what it
// touched, nothing more).
#include "celform/views/viewport/displayed_shape.h"

#include "celform/model/document/document.h"

#include <algorithm>
#include <iterator>

namespace celform::views {

void DisplayedShape::setSource(Source source, model::ObjectId key)
{
    if (source != Source::Key)
        key = 0;
    if (source == m_source && key == m_key)
        return;
    m_source = source;
    m_key = key;
    invalidate();
}

void DisplayedShape::invalidate()
{
    m_stale = true;
    m_dirtyVertices.clear();
}

void DisplayedShape::viewChanged()
{
    if (m_source == Source::Blend)
        invalidate();
}

bool DisplayedShape::noteChange(const model::ChangeSet& change)
{
    using model::Part;
    if (change.reset || change.has(Part::Mesh)) {
        invalidate();
        return true;
    }
    switch (m_source) {
    case Source::Base:
        // An animated base moves with the playhead (paper 1, section 4.1); a still one does not.
        if (m_animated && change.has(Part::Playhead)) {
            invalidate();
            return true;
        }
        return false;
    case Source::Key:
        if (change.has(Part::Playhead) || change.has(Part::Blend)) {
            // The time interpolation or the frame: every row may move.
            invalidate();
            return true;
        }
        if (!change.has(Part::Keys) || !change.touches(m_key))
            return false;
        if (change.offsetsOnly && !change.vertices.empty() && !m_stale) {
            // Only these vertices' offsets changed: only their rows move, at any frame.
            if (m_dirtyVertices.empty()) {
                m_dirtyVertices.assign(change.vertices.begin(), change.vertices.end());
            } else {
                std::vector<std::uint32_t> merged;
                merged.reserve(m_dirtyVertices.size() + change.vertices.size());
                std::set_union(m_dirtyVertices.begin(), m_dirtyVertices.end(), change.vertices.begin(),
                    change.vertices.end(), std::back_inserter(merged));
                m_dirtyVertices = std::move(merged);
            }
            return true;
        }
        invalidate();
        return true;
    case Source::Blend:
        if (change.has(Part::Keys) || change.has(Part::Blend) || change.has(Part::Playhead)) {
            invalidate();
            return true;
        }
        return false;
    }
    return false;
}

void DisplayedShape::showBase(const model::ProjectData& data, int frame)
{
    const algo::TriMesh& mesh = *data.baseMesh;
    if (data.animated()) {
        m_shape.positions = data.basePositions(frame, m_baseScratch);
        m_normals = algo::vertexNormals(m_shape.positions, mesh.faces);
    } else {
        m_shape.positions = mesh.vertices;
        m_normals = mesh.normals();
    }
}

bool DisplayedShape::refresh(model::Document& document, const Eigen::Vector3d& viewDirection)
{
    m_changed.clear();
    if (!isStale())
        return false;
    const model::ProjectData& data = document.data();
    if (!data.baseMesh) {
        m_shape.positions.resize(0, 3);
        m_normals.resize(0, 3);
        m_shape.touch();
        m_stale = false;
        m_dirtyVertices.clear();
        return true;
    }
    const algo::TriMesh& mesh = *data.baseMesh;
    m_animated = data.animated();
    const model::KeyViewpoint* key = m_source == Source::Key ? data.key(m_key) : nullptr;
    const int frame = document.currentFrame();
    if (!m_stale && key && m_shape.positions.rows() == mesh.vertexCount()) {
        // Some rows of a key shape: the same floats as a full recomputation (updateKeyShape),
        // normals of the faces around them.
        data.updateKeyShape(*key, frame, m_dirtyVertices, m_shape.positions);
        algo::updateVertexNormals(
            m_shape.positions, mesh.faces, mesh.vertexFaces(), m_dirtyVertices, m_normals, m_scratch);
        // The rows whose position or normal changed: the moved vertices (one without faces has
        // no normal to update) and every corner of their faces, whose normals were recomputed.
        std::set_union(m_dirtyVertices.begin(), m_dirtyVertices.end(), m_scratch.begin(), m_scratch.end(),
            std::back_inserter(m_changed));
        m_dirtyVertices.clear();
        m_shape.touch();
        return true;
    }
    if (m_source == Source::Blend && data.keys.empty()) {
        showBase(data, frame);
    } else if (m_source == Source::Blend) {
        document.blender().shape(data, viewDirection, frame, m_shape.positions);
        m_normals = algo::vertexNormals(m_shape.positions, mesh.faces);
    } else if (key) {
        m_shape.positions = data.keyShape(*key, frame);
        m_normals = algo::vertexNormals(m_shape.positions, mesh.faces);
    } else {
        // The base model (at the frame), or a key that no longer exists.
        showBase(data, frame);
    }
    m_shape.touch();
    m_stale = false;
    m_dirtyVertices.clear();
    return true;
}

} // namespace celform::views
