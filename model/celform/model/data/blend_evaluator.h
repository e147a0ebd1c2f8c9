// The view-dependent shape of a document (paper 1, section 3.2): the viewing sphere of the
// enabled keys, rebuilt only when keys or blend settings change, and the blended shape for a view.
#pragma once

#include "celform/algorithms/blend.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/algorithms/view_sphere.h"
#include "celform/model/data/project_data.h"

#include <QString>

#include <optional>
#include <vector>

namespace celform::model {

/// One key's share in a blend, by id, for display and the command line.
struct KeyShare {
    ObjectId key = 0;
    double weight = 0.0;
};

struct BlendResult {
    std::vector<KeyShare> shares; ///< keys with a non-zero weight
    double baseShare = 1.0; ///< 1 - sum of the key weights (dummies, falloff)
    algo::ViewBlend raw; ///< facet, barycentric coordinates, falloff
};

/// Buffers a caller keeps between blends so that a blend allocates nothing once they have grown.
struct BlendScratch {
    std::vector<ProjectData::FrameOffsets> atFrame;
    std::vector<algo::WeightedOffsets> parts;
};

class BlendEvaluator {
public:
    /// Rebuilds the sphere when the enabled keys' directions or the unspecified-region mode
    /// changed since the last call; cheap otherwise. Returns false (with a message) when the keys
    /// cannot be hulled (two with the same direction); blends then give the base model.
    bool update(const ProjectData& data, QString* error = nullptr);

    /// View direction convention (DESIGN.md): unit vector from the base centroid towards the eye.
    [[nodiscard]] BlendResult weights(const ProjectData& data, const Eigen::Vector3d& viewDirection) const;
    /// The same into out, reusing its storage.
    void weights(const ProjectData& data, const Eigen::Vector3d& viewDirection, BlendResult& out) const;
    /// The blended shape (#V by 3) for a view direction at a frame. Call update() first. base: the
    /// base model's vertices at that frame when the caller has them (ProjectData::basePositions);
    /// null evaluates them here.
    void shape(const ProjectData& data, const Eigen::Vector3d& viewDirection, int frame, algo::Positions& out,
        const algo::Positions* base = nullptr) const;
    /// The blended shape for weights already computed by weights(): base + the keys' offsets at
    /// the frame, each times its share. base: the base's vertices at the frame.
    void shapeFor(const ProjectData& data, const BlendResult& blend, int frame, const algo::Positions& base,
        algo::Positions& out, BlendScratch* scratch = nullptr) const;

    /// View direction for an eye point at a frame (viewDirectionFromEye).
    [[nodiscard]] static Eigen::Vector3d viewDirection(const ProjectData& data, const Eigen::Vector3d& eye, int frame);

    /// The sphere for display; null when there is none.
    [[nodiscard]] const algo::ViewSphere* sphere() const { return m_sphere ? &*m_sphere : nullptr; }
    /// Key ids in sphere point order (the first keyCount() points).
    [[nodiscard]] const std::vector<ObjectId>& sphereKeys() const { return m_keyIds; }

private:
    std::optional<algo::ViewSphere> m_sphere;
    std::vector<ObjectId> m_keyIds;
    std::vector<Eigen::Vector3d> m_directions;
    UnspecifiedMode m_mode = UnspecifiedMode::Dummy;
    bool m_built = false;
};

/// Direction from the centroid of the base model at a frame towards an eye point (unit; zero when
/// the eye is at the centroid).
Eigen::Vector3d viewDirectionFromEye(const ProjectData& data, const Eigen::Vector3d& eye, int frame);
/// The same from a centroid already known.
Eigen::Vector3d viewDirectionFromCentre(const Eigen::Vector3d& centre, const Eigen::Vector3d& eye);

} // namespace celform::model
