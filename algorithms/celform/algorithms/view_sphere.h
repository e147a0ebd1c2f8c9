// The viewing sphere of paper 1, section 3.2: key view directions hulled on the unit sphere
// (CGAL), facet lookup for a view direction, and blend weights, including the unspecified-region
// modes of section 3.3.
#pragma once

#include <Eigen/Core>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace celform::algo {

/// Paper 1, section 3.3 (DESIGN.md "Unspecified regions").
enum class UnspecifiedRegions { Dummy, Cosine, Cosine2 };

/// One key's share of a blend. key indexes the directions given to ViewSphere::build.
struct KeyWeight {
    int key = -1;
    double weight = 0.0;
};

/// Result of a blend-weight query. weights are the sharpened weights w' of the real keys that
/// take part (dummies are left out: they carry zero offsets), already multiplied by the cosine
/// falloff where the view lies outside the keys' coverage; 1 - sum(weights) is the base model's
/// share.
struct ViewBlend {
    std::vector<KeyWeight> weights;
    /// Hull facet hit by the view ray (index into ViewSphere::facets()), -1 when none was hit
    /// (an unspecified region handled by falloff).
    int facet = -1;
    /// Barycentric coordinates of the hit in that facet (unsharpened), when facet >= 0.
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
    /// Falloff factor c in [0, 1] applied in an unspecified region; 1 inside the coverage.
    double falloff = 1.0;
};

class ViewSphere {
public:
    /// Builds the sphere for unit key directions (model space, from the centroid towards the eye).
    /// In Dummy mode, base-model copies are added at the six axis directions, leaving out each
    /// one within 45 degrees of a key. Returns nothing and sets error when two directions are the
    /// same (within kDuplicateAngleDegrees) or a direction is not finite. Any other set, including
    /// none, one, two, or all on one great circle, gives a usable sphere.
    static std::optional<ViewSphere> build(
        const std::vector<Eigen::Vector3d>& keyDirections, UnspecifiedRegions mode, std::string* error = nullptr);

    /// Directions closer than this are "the same direction".
    static constexpr double kDuplicateAngleDegrees = 0.5;

    /// Blend weights for a view direction (need not be unit length; zero or non-finite gives the
    /// base model, with falloff 0), sharpened with alpha (paper 1, section 3.2.2:
    /// w' = w^alpha / sum w^alpha); a sharpness that is not finite and positive counts as 1.
    /// At a key's exact direction the result is {key, 1.0} exactly. Outside the keys' coverage
    /// (facet -1) the weights fall off from the nearest covered direction; view_sphere.cpp
    /// documents the scheme.
    [[nodiscard]] ViewBlend blend(const Eigen::Vector3d& viewDirection, double sharpness) const;
    /// The same into out, reusing its storage (per-frame callers allocate nothing once warm).
    void blend(const Eigen::Vector3d& viewDirection, double sharpness, ViewBlend& out) const;

    // --- for display (viewing-sphere panel, paper figure 4) ----------------------------------
    /// All hull points: the keys first (index = key index), then the dummies.
    [[nodiscard]] const std::vector<Eigen::Vector3d>& points() const;
    [[nodiscard]] int keyCount() const;
    /// Hull triangles (indices into points()) that take part in lookups.
    [[nodiscard]] const std::vector<std::array<int, 3>>& facets() const;

    ViewSphere(ViewSphere&&) noexcept;
    ViewSphere& operator=(ViewSphere&&) noexcept;
    ViewSphere(const ViewSphere&);
    ViewSphere& operator=(const ViewSphere&);
    ~ViewSphere();

private:
    ViewSphere();
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace celform::algo
