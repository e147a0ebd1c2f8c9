#include "celform/model/data/mirror_plane.h"

namespace celform::model {

MirrorPlane detectMirrorPlane(const algo::TriMesh& mesh)
{
    switch (mesh.symmetry().axis) {
    case 0:
        return MirrorPlane::X;
    case 1:
        return MirrorPlane::Y;
    case 2:
        return MirrorPlane::Z;
    default:
        return MirrorPlane::Off;
    }
}

int mirrorAxis(MirrorPlane plane)
{
    switch (plane) {
    case MirrorPlane::X:
        return 0;
    case MirrorPlane::Y:
        return 1;
    case MirrorPlane::Z:
        return 2;
    case MirrorPlane::Off:
        break;
    }
    return -1;
}

std::optional<algo::AxisPlane> mirrorGeometry(const algo::TriMesh& mesh, MirrorPlane plane)
{
    const int axis = mirrorAxis(plane);
    if (axis < 0)
        return std::nullopt;
    return algo::centrePlane(mesh.vertices, axis);
}

QString mirrorPlaneName(MirrorPlane plane)
{
    switch (plane) {
    case MirrorPlane::X:
        return QStringLiteral("x");
    case MirrorPlane::Y:
        return QStringLiteral("y");
    case MirrorPlane::Z:
        return QStringLiteral("z");
    case MirrorPlane::Off:
        break;
    }
    return QStringLiteral("off");
}

std::optional<MirrorPlane> mirrorPlaneFromName(const QString& name)
{
    for (MirrorPlane p : {MirrorPlane::Off, MirrorPlane::X, MirrorPlane::Y, MirrorPlane::Z})
        if (name.compare(mirrorPlaneName(p), Qt::CaseInsensitive) == 0)
            return p;
    return std::nullopt;
}

} // namespace celform::model
