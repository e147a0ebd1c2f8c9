// The document's animation edits (issue 13): the scene's time, the camera path and the animated
// base model. Each is one undo step.
#include "celform/model/document/document.h"

#include "celform/model/io/animation_io.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"
#include "celform/model/data/framed_camera.h"

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

void Document::setSceneTime(const SceneTime& time)
{
    const QString problem = sceneTimeProblem(time);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    if (time == m_data.time)
        return;
    const QString text = time.fps != m_data.time.fps ? tr("Change Frame Rate") : tr("Change Frame Range");
    push(new PropertyCommand<SceneTime>(
        this, text, Property::SceneTime, {}, timeField(), time, ChangeSet::of(Part::SceneTime), m_gesture));
}

void Document::setCameraPath(const CameraPath& path, const QString& undoText)
{
    const QString problem = cameraPathProblem(path);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    if (path == m_data.look.cameraPath)
        return;
    push(new PropertyCommand<CameraPath>(
        this, undoText, Property::CameraPath, {}, pathField(), path, ChangeSet::of(Part::CameraPath), 0));
}

void Document::setCameraKey(int frame, const Camera& camera)
{
    if (!camera.isValid())
        throw EditRefused(tr("The camera is not valid (eye, target and up must differ)."));
    if (std::abs(frame) > kMaxFrame)
        throw EditRefused(tr("Frame %1 is out of range.").arg(frame));
    CameraPath path = m_data.look.cameraPath;
    path.setKey(frame, camera);
    setCameraPath(path, tr("Key Camera at Frame %1").arg(frame));
}

void Document::removeCameraKey(int frame)
{
    CameraPath path = m_data.look.cameraPath;
    const auto it
        = std::find_if(path.keys.begin(), path.keys.end(), [frame](const CameraKey& k) { return k.frame == frame; });
    if (it == path.keys.end())
        return;
    path.keys.erase(it);
    setCameraPath(path, tr("Remove Camera Key at Frame %1").arg(frame));
}

void Document::clearCameraPath()
{
    setCameraPath({}, tr("Clear Camera Path"));
}

void Document::makeTurntable(const Turntable& turntable, double aspect)
{
    if (!m_data.baseMesh)
        throw EditRefused(tr("Import a base model before making a turntable."));
    const QString problem = turntableProblem(turntable);
    if (!problem.isEmpty())
        throw EditRefused(problem);
    // The lens of the shot's camera, and the distance at which a framed view holds the model.
    const Camera lens = m_data.look.renderCamera ? *m_data.look.renderCamera : Camera{};
    const Camera framed = cameraFromView(m_data, defaultRenderView(), std::max(aspect, 1e-3));
    const double distance = (framed.eye - framed.target).norm();
    const Eigen::Vector3d target = m_data.baseCentre(turntable.startFrame);
    SceneTime time = m_data.time;
    time.firstFrame = turntable.startFrame;
    time.lastFrame = turntable.startFrame + turntable.frames - 1;
    auto* cmd = new CompositeCommand(this, tr("Make Turntable"));
    new PropertyCommand<CameraPath>(this, {}, Property::CameraPath, {}, pathField(),
        turntablePath(turntable, target, distance, lens), ChangeSet::of(Part::CameraPath), 0, cmd);
    if (time != m_data.time)
        new PropertyCommand<SceneTime>(
            this, {}, Property::SceneTime, {}, timeField(), time, ChangeSet::of(Part::SceneTime), 0, cmd);
    push(cmd);
}

void Document::setAnimatedBase(AnimatedImport&& imported, const QString& sourceName)
{
    auto animation = imported.animation.empty()
        ? nullptr
        : std::make_shared<const algo::BaseAnimation>(std::move(imported.animation));
    setAnimatedBase(std::move(imported.mesh), std::move(animation), imported.fps, sourceName);
}

void Document::setAnimatedBase(std::shared_ptr<const algo::TriMesh> mesh,
    std::shared_ptr<const algo::BaseAnimation> animation, double fps, const QString& sourceName)
{
    Q_ASSERT(mesh);
    if (animation) {
        const std::string problem = animation->problem(mesh->vertexCount());
        if (!problem.empty())
            throw EditRefused(
                tr("The animation of %1 is not usable: %2").arg(sourceName, QString::fromStdString(problem)));
    }
    SceneTime time = m_data.time;
    if (animation && !animation->empty()) {
        time.fps = fps;
        time.firstFrame = animation->firstFrame;
        time.lastFrame = animation->lastFrame();
        const QString problem = sceneTimeProblem(time);
        if (!problem.isEmpty())
            throw EditRefused(problem);
    }
    // setBaseMesh refuses a mesh the keys' offsets do not fit before it changes anything.
    for (const KeyViewpoint& key : m_data.keys)
        for (const auto& [frame, offsets] : key.offsetsByFrame)
            if (!offsets.indices.empty() && offsets.indices.back() >= std::uint32_t(mesh->vertexCount()))
                throw IoError(sourceName,
                    tr("has %1 vertices, but the key deformations use vertex %2; "
                       "a replacement base model needs the same vertex count and order")
                        .arg(mesh->vertexCount())
                        .arg(offsets.indices.back()));
    Batch batch(this);
    // The mesh, the animation and the time in one undo step.
    m_undo->beginMacro(tr("Import Animated Base"));
    setBaseMesh(std::move(mesh), sourceName);
    push(new PropertyCommand<std::shared_ptr<const algo::BaseAnimation>>(
        this, {}, Property::BaseAnimation, {}, [](ProjectData& d) { return &d.baseAnimation; }, std::move(animation),
        ChangeSet::of(Part::Mesh), 0));
    if (time != m_data.time)
        push(new PropertyCommand<SceneTime>(
            this, {}, Property::SceneTime, {}, timeField(), time, ChangeSet::of(Part::SceneTime), 0));
    m_undo->endMacro();
}

} // namespace celform::model
