// The document's animation edits: the scene's time, the camera path and the animated base model.
// Each is one undo step.
#include "celform/model/document/animation_edits.h"

#include "celform/model/io/animation_io.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"
#include "celform/model/data/framed_camera.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

std::function<CameraPath*(ProjectData&)> pathField()
{
    return [](ProjectData& d) { return &d.look.cameraPath; };
}

std::function<SceneTime*(ProjectData&)> timeField()
{
    return [](ProjectData& d) { return &d.time; };
}

} // namespace

void AnimationEdits::setSceneTime(const SceneTime& time, GestureId gesture)
{
    const QString problem = sceneTimeProblem(time);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    if (time == data().time)
        return;
    const QString text = time.fps != data().time.fps ? tr("Change Frame Rate") : tr("Change Frame Range");
    push(new PropertyCommand<SceneTime>(
        m_doc, text, {Property::SceneTime}, timeField(), time, ChangeSet::of(Part::SceneTime), gesture));
}

void AnimationEdits::setCameraPath(const CameraPath& path, const QString& undoText)
{
    const QString problem = cameraPathProblem(path);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    if (path == data().look.cameraPath)
        return;
    push(new PropertyCommand<CameraPath>(
        m_doc, undoText, {Property::CameraPath}, pathField(), path, ChangeSet::of(Part::CameraPath), {}));
}

void AnimationEdits::setCameraKey(int frame, const Camera& camera)
{
    if (!camera.isValid())
        throw EditRefused(tr("The camera is not valid (eye, target and up must differ)."));
    if (std::abs(frame) > kMaxFrame)
        throw EditRefused(tr("Frame %1 is out of range.").arg(frame));
    CameraPath path = data().look.cameraPath;
    path.setKey(frame, camera);
    setCameraPath(path, tr("Key Camera at Frame %1").arg(frame));
}

void AnimationEdits::removeCameraKey(int frame)
{
    CameraPath path = data().look.cameraPath;
    const auto it
        = std::find_if(path.keys.begin(), path.keys.end(), [frame](const CameraKey& k) { return k.frame == frame; });
    if (it == path.keys.end())
        return;
    path.keys.erase(it);
    setCameraPath(path, tr("Remove Camera Key at Frame %1").arg(frame));
}

void AnimationEdits::clearCameraPath()
{
    setCameraPath({}, tr("Clear Camera Path"));
}

void AnimationEdits::makeTurntable(const Turntable& turntable, double aspect)
{
    if (!data().baseMesh)
        throw EditRefused(tr("Import a base model before making a turntable."));
    const QString problem = turntableProblem(turntable);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    // The lens of the shot's camera, and the distance at which a framed view holds the model.
    const Camera lens = data().look.renderCamera ? *data().look.renderCamera : Camera{};
    const Camera framed = cameraFromView(data(), defaultRenderView(), std::max(aspect, 1e-3));
    const double distance = (framed.eye - framed.target).norm();
    const Eigen::Vector3d target = data().baseCentre(turntable.startFrame);
    SceneTime time = data().time;
    time.firstFrame = turntable.startFrame;
    time.lastFrame = turntable.startFrame + turntable.frames - 1;
    auto* cmd = new CompositeCommand(m_doc, tr("Make Turntable"));
    new PropertyCommand<CameraPath>(m_doc, {}, {Property::CameraPath}, pathField(),
        turntablePath(turntable, target, distance, lens), ChangeSet::of(Part::CameraPath), {}, cmd);
    if (time != data().time)
        new PropertyCommand<SceneTime>(
            m_doc, {}, {Property::SceneTime}, timeField(), time, ChangeSet::of(Part::SceneTime), {}, cmd);
    push(cmd);
}

void AnimationEdits::importAnimatedBase(const QString& path, double fps)
{
    setAnimatedBase(readAnimatedBase(path, fps), QFileInfo(path).fileName());
}

void AnimationEdits::setAnimatedBase(AnimatedImport&& imported, const QString& sourceName)
{
    auto animation = imported.animation.empty()
        ? nullptr
        : std::make_shared<const algo::BaseAnimation>(std::move(imported.animation));
    setAnimatedBase(std::move(imported.mesh), std::move(animation), imported.fps, sourceName);
}

void AnimationEdits::setAnimatedBase(std::shared_ptr<const algo::TriMesh> mesh,
    std::shared_ptr<const algo::BaseAnimation> animation, double fps, const QString& sourceName)
{
    Q_ASSERT(mesh);
    if (animation) {
        const std::string problem = animation->problem(mesh->vertexCount());
        if (!problem.empty())
            throw EditRefused(
                tr("The animation of %1 is not usable: %2").arg(sourceName, QString::fromStdString(problem)));
    }
    SceneTime time = data().time;
    if (animation && !animation->empty()) {
        time.fps = fps;
        time.firstFrame = animation->firstFrame;
        time.lastFrame = animation->lastFrame();
        const QString problem = sceneTimeProblem(time);
        if (!problem.isEmpty())
            throw EditRefused(problem);
    }
    // setBaseMesh refuses a mesh the keys' deformations do not fit before it changes anything.
    for (const KeyViewpoint& key : data().keys)
        for (const auto& [frame, offsets] : key.offsetsByFrame)
            if (!offsets.indices.empty() && offsets.indices.back() >= std::uint32_t(mesh->vertexCount()))
                throw IoError(sourceName,
                    tr("has %1 vertices, but the key deformations use vertex %2; "
                       "a replacement base model needs the same vertex count and order")
                        .arg(mesh->vertexCount())
                        .arg(offsets.indices.back()));
    const Document::Batch batch(m_doc);
    // The mesh, the animation and the time in one undo step.
    m_doc->undoStack()->beginMacro(tr("Import Animated Base"));
    m_doc->setBaseMesh(std::move(mesh), sourceName);
    push(new PropertyCommand<std::shared_ptr<const algo::BaseAnimation>>(m_doc, {}, {Property::BaseAnimation},
        [](ProjectData& d) { return &d.baseAnimation; }, std::move(animation), ChangeSet::of(Part::Mesh), {}));
    if (time != data().time)
        push(new PropertyCommand<SceneTime>(
            m_doc, {}, {Property::SceneTime}, timeField(), time, ChangeSet::of(Part::SceneTime), {}));
    m_doc->undoStack()->endMacro();
}

} // namespace celform::model
