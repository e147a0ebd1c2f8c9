// The plane the brushes mirror across (the brush's mirror option, the offset brush and Fit Shape):
// perpendicular to one model axis through the base model's bounding-box centre, saved with the
// project and detected when a model is imported (algo::detectSymmetry).
#pragma once

#include "celform/algorithms/symmetry.h"
#include "celform/algorithms/tri_mesh.h"

#include <QString>

#include <optional>

namespace celform::model {

enum class MirrorPlane { Off, X, Y, Z };

/// The plane whose reflection brings the model closest to itself; Off when no plane is good.
[[nodiscard]] MirrorPlane detectMirrorPlane(const algo::TriMesh& mesh);
/// The plane on the base model: through its bounding-box centre (none for Off).
[[nodiscard]] std::optional<algo::AxisPlane> mirrorGeometry(const algo::TriMesh& mesh, MirrorPlane plane);
/// 0, 1, 2 for X, Y, Z; -1 for Off.
[[nodiscard]] int mirrorAxis(MirrorPlane plane);
/// "off", "x", "y", "z" (the project file and the command line).
[[nodiscard]] QString mirrorPlaneName(MirrorPlane plane);
/// The plane named by mirrorPlaneName (case-insensitive), none for an unknown name.
[[nodiscard]] std::optional<MirrorPlane> mirrorPlaneFromName(const QString& name);

} // namespace celform::model
