// What a viewport shows of the document's geometry at the playhead (paper 1, section 3): the base
// model, one key's shape, or the view-dependent blend for a view direction. Document changes only
// mark it stale (sparsely when some vertices' offsets changed); refresh() recomputes what is stale
// when the viewport is about to paint, so a hidden viewport does no work.
#pragma once

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/document/change_set.h"

#include <Eigen/Core>

#include <vector>

namespace celform::model {
class Document;
struct ProjectData;
} // namespace celform::model

namespace celform::views {

class DisplayedShape {
public:
    enum class Source {
        Base, ///< the base model
        Key, ///< a key's shape (base plus its offsets at the frame)
        Blend, ///< the blend of the keys for a view direction (preview, observer)
    };

    void setSource(Source source, model::ObjectId key = 0);
    [[nodiscard]] Source source() const { return m_source; }
    [[nodiscard]] model::ObjectId key() const { return m_key; }

    /// Notes a document change; returns whether the shape on screen may have changed.
    bool noteChange(const model::ChangeSet& change);
    /// The blend's view direction moved (preview while orbiting, the observed camera).
    void viewChanged();
    /// Everything is stale (new mesh, new source).
    void invalidate();
    [[nodiscard]] bool isStale() const { return m_stale || !m_dirtyVertices.empty(); }

    /// Recomputes what is stale for the document at its playhead; viewDirection is used by the
    /// blend. Returns true when positions changed. A key edit on some vertices updates only
    /// those rows and the normals around them.
    bool refresh(model::Document& document, const Eigen::Vector3d& viewDirection);

    [[nodiscard]] const algo::Shape& shape() const { return m_shape; }
    [[nodiscard]] const algo::Positions& positions() const { return m_shape.positions; }
    [[nodiscard]] const algo::Positions& normals() const { return m_normals; }
    /// Rows whose position or normal the last refresh changed, ascending, when it was a partial
    /// one (a key edit on some vertices); empty after a full recomputation or none.
    [[nodiscard]] const std::vector<std::uint32_t>& changedVertices() const { return m_changed; }

private:
    /// The base model's vertices at the frame (the animated base there), normals with them.
    void showBase(const model::ProjectData& data, int frame);

    Source m_source = Source::Base;
    bool m_animated = false; ///< the base moves over time: the playhead moves the base model too
    model::ObjectId m_key = 0;
    bool m_stale = true;
    std::vector<std::uint32_t> m_dirtyVertices; ///< rows to recompute when not m_stale
    std::vector<std::uint32_t> m_changed;
    std::vector<std::int32_t> m_scratch; ///< the rows updateVertexNormals recomputed
    algo::Shape m_shape;
    algo::Positions m_normals;
    algo::Positions m_baseScratch; ///< the animated base at the frame
};

} // namespace celform::views
