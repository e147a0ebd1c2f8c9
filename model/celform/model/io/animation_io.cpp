// Entry points of the animated base import: the suffix picks the glTF reader or the mesh
// sequence reader, and the result is checked as a whole before it is handed out.
#include "celform/model/io/animation_io.h"

#include "celform/model/io/animation_io_common.h"

#include <QFileInfo>

#include <cmath>

namespace celform::model {

namespace animio {

void checkFps(const QString& path, double fps)
{
    if (!std::isfinite(fps) || fps <= 0.0 || fps >= 1000.0)
        throw IoError(path, AnimationIo::tr("%1 frames per second is not a usable frame rate").arg(fps));
}

} // namespace animio

namespace {

bool isGltfSuffix(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
}

} // namespace

AnimatedImport readAnimatedBase(const QString& path, double fps)
{
    animio::checkFps(path, fps);
    AnimatedImport out
        = isGltfSuffix(path) ? animio::readGltfAnimation(path, fps) : animio::readMeshSequence(path, fps);
    out.fps = fps;
    // The readers check as they go; this is the last word on what the rest of the program gets.
    if (!out.mesh || out.mesh->vertexCount() == 0 || out.mesh->faceCount() == 0)
        throw IoError(path, AnimationIo::tr("the file contains no triangles"));
    const std::string problem = out.animation.problem(out.mesh->vertexCount());
    if (!problem.empty())
        throw IoError(path, AnimationIo::tr("the animation is unusable: %1").arg(QString::fromStdString(problem)));
    return out;
}

bool isAnimatedBaseFile(const QString& path)
{
    try {
        return isGltfSuffix(path) ? animio::gltfIsAnimated(path) : animio::isMeshSequence(path);
    } catch (const std::exception&) {
        return false;
    }
}

bool opensAsAnimatedBase(const QString& path)
{
    return path.contains(QLatin1Char('#')) || (isGltfSuffix(path) && isAnimatedBaseFile(path));
}

ProjectData newAnimatedProject(AnimatedImport animated, const QString& meshName)
{
    ProjectData data = newProject(std::move(animated.mesh), meshName);
    if (!animated.animation.empty()) {
        data.time.fps = animated.fps;
        data.time.firstFrame = animated.animation.firstFrame;
        data.time.lastFrame = animated.animation.lastFrame();
        data.baseAnimation = std::make_shared<const algo::BaseAnimation>(std::move(animated.animation));
    }
    return data;
}

} // namespace celform::model
