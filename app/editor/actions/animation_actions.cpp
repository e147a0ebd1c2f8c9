// The Timeline dock, playback, shot camera, camera path and Observer layout actions
// (animation_actions.h).
#include "editor/actions/animation_actions.h"

#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"
#include "editor/dialogs/turntable_dialog.h"

#include "celform/model/document/document.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/data/io_error.h"
#include "celform/views/overlays/camera_path_overlay.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/timeline/playback.h"
#include "celform/views/timeline/timeline_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace celform::app {
namespace {

struct AnimationText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::AnimationActions)
};

/// Keeps the main viewport looking through the shot camera (the camera path, else the render
/// camera, at the playhead) while "Look Through Shot Camera" is on; navigating turns it off.
class ShotCameraFollower : public QObject {
public:
    ShotCameraFollower(MainWindow* window, QAction* toggle)
        : QObject(window)
        , m_window(window)
        , m_toggle(toggle)
    {
        setObjectName(QStringLiteral("shotCameraFollower"));
        connect(toggle, &QAction::toggled, this, [this](bool on) {
            if (!on)
                return;
            // The shot shows the view-dependent model as the camera sees it.
            if (QAction* preview = m_window->action(QStringLiteral("actionPreview")); preview && !preview->isChecked())
                preview->trigger();
            apply();
        });
        connect(window->viewport(), &views::Viewport::cameraChanged, this, [this] {
            if (!m_applying && m_toggle->isChecked())
                m_toggle->setChecked(false); // the artist turned the view: it is theirs now
        });
        connect(window->document(), &model::Document::changed, this, &ShotCameraFollower::documentChanged);
    }

    void apply()
    {
        model::Document* doc = m_window->document();
        views::Viewport* viewport = m_window->viewport();
        if (!m_toggle->isChecked() || !doc->hasMesh())
            return;
        const double aspect = viewport->height() > 0 ? double(viewport->width()) / viewport->height() : 16.0 / 9.0;
        const model::Camera camera = model::cameraAtFrame(doc->data(), doc->data().look, doc->currentFrame(), aspect);
        m_applying = true;
        viewport->setCamera(camera);
        m_applying = false;
    }

private:
    void documentChanged(const model::ChangeSet& change)
    {
        using model::Part;
        if (change.reset) {
            // A shot opens looking through its camera (the viewport already took the render camera).
            const bool path = m_window->document()->hasMesh() && !m_window->document()->data().look.cameraPath.empty();
            if (m_toggle->isChecked() != path)
                m_toggle->setChecked(path);
            else
                apply();
            return;
        }
        if (change.has(Part::Playhead) || change.has(Part::CameraPath) || change.has(Part::SceneTime)
            || change.has(Part::Look) || change.has(Part::Mesh))
            apply();
    }

    MainWindow* m_window;
    QAction* m_toggle;
    bool m_applying = false;
};

/// Places the Observer's camera at a fixed vantage point that sees the model and the whole path:
/// a three-quarter view from above (paper 1, figures 10-12).
void frameObserver(MainWindow* window)
{
    const model::Document* doc = window->document();
    if (!doc->hasMesh())
        return;
    const algo::Positions& v = doc->data().baseMesh->vertices;
    Eigen::AlignedBox3d box;
    if (v.rows() > 0) {
        box.extend(Eigen::Vector3d(v.colwise().minCoeff().transpose().cast<double>()));
        box.extend(Eigen::Vector3d(v.colwise().maxCoeff().transpose().cast<double>()));
    }
    for (const model::CameraKey& key : doc->data().look.cameraPath.keys)
        box.extend(key.camera.eye);
    box.extend(window->viewport()->camera().eye);
    if (box.isEmpty())
        return;
    const Eigen::Vector3d centre = box.center();
    const double radius = std::max(1e-6, 0.5 * box.diagonal().norm());
    model::Camera camera;
    camera.fovYDegrees = 30.0;
    const views::Viewport* observer = window->observer();
    const double aspect = observer->height() > 0 ? double(observer->width()) / observer->height() : 1.0;
    const double halfY = 0.5 * camera.fovYDegrees * M_PI / 180.0;
    const double halfAngle = std::min(halfY, std::atan(std::tan(halfY) * aspect));
    const Eigen::Vector3d side = Eigen::Vector3d(0.8, 0.9, 1.2).normalized();
    camera.target = centre;
    camera.eye = centre + side * (1.05 * radius / std::sin(halfAngle));
    camera.up = Eigen::Vector3d::UnitY();
    window->observer()->setCamera(camera);
}

} // namespace

void installAnimationActions(MainWindow* window)
{
    model::Document* doc = window->document();
    views::Viewport* viewport = window->viewport();
    views::Viewport* observer = window->observer();

    auto* panel = new views::TimelinePanel(doc, window);
    auto* dock = new QDockWidget(AnimationText::tr("Timeline"), window);
    dock->setObjectName(QStringLiteral("timelineDock"));
    dock->setWidget(panel);
    dock->setToolTip(AnimationText::tr("The scene's frames: range, frame rate, playback and every kind of key"));
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    views::Playback* playback = panel->playback();
    // The depth analysis of every played frame would take the cores playback needs: it waits for
    // the stop and then analyses the frame shown.
    if (views::DepthPanel* depth = window->depthPanel())
        QObject::connect(
            playback, &views::Playback::playingChanged, depth->runner(), &views::DepthAnalysisRunner::setHeld);
    new views::CameraPathOverlay(observer, viewport);

    auto make = [window](const char* name, const QString& text, const QKeySequence& key, const QString& tip) {
        return addWindowAction(window, QString::fromLatin1(name), text, key, tip);
    };
    // Playback keys as in Blender (Space, arrows). They act where frames are looked at — the
    // viewports and the Timeline — so the arrows still move through lists and text fields.
    auto transport = [&](const char* name, const QString& text, const QKeySequence& key, const QString& tip) {
        QAction* a = make(name, text, key, tip);
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        window->removeAction(a);
        for (QWidget* w : std::initializer_list<QWidget*>{viewport, observer, dock})
            w->addAction(a);
        return a;
    };
    QAction* play = transport("actionPlayPause", AnimationText::tr("&Play / Pause"), QKeySequence(Qt::Key_Space),
        AnimationText::tr("Play the scene at its frame rate, or pause"));
    QObject::connect(play, &QAction::triggered, playback, &views::Playback::toggle);
    QAction* loop = make("actionLoopPlayback", AnimationText::tr("&Loop"), QKeySequence(),
        AnimationText::tr("After the last frame of the range, play the first again"));
    loop->setCheckable(true);
    loop->setChecked(playback->isLooping());
    QObject::connect(loop, &QAction::toggled, playback, &views::Playback::setLooping);
    QObject::connect(playback, &views::Playback::loopingChanged, loop, &QAction::setChecked);
    QAction* first = transport("actionFirstFrame", AnimationText::tr("&First Frame"),
        QKeySequence(Qt::SHIFT | Qt::Key_Left), AnimationText::tr("Go to the first frame of the range"));
    QObject::connect(first, &QAction::triggered, panel, &views::TimelinePanel::jumpToStart);
    QAction* last = transport("actionLastFrame", AnimationText::tr("La&st Frame"),
        QKeySequence(Qt::SHIFT | Qt::Key_Right), AnimationText::tr("Go to the last frame of the range"));
    QObject::connect(last, &QAction::triggered, panel, &views::TimelinePanel::jumpToEnd);
    QAction* previous = transport("actionPreviousFrame", AnimationText::tr("P&revious Frame"),
        QKeySequence(Qt::Key_Left), AnimationText::tr("One frame back"));
    QObject::connect(previous, &QAction::triggered, panel, [panel] { panel->stepFrame(-1); });
    QAction* next = transport("actionNextFrame", AnimationText::tr("&Next Frame"), QKeySequence(Qt::Key_Right),
        AnimationText::tr("One frame on"));
    QObject::connect(next, &QAction::triggered, panel, [panel] { panel->stepFrame(1); });
    QAction* previousKey = transport("actionPreviousKeyFrame", AnimationText::tr("Previous &Key"),
        QKeySequence(Qt::Key_Down), AnimationText::tr("Go to the previous frame holding a key of any kind"));
    QObject::connect(previousKey, &QAction::triggered, panel, [panel] { panel->jumpToKey(-1); });
    QAction* nextKey = transport("actionNextKeyFrame", AnimationText::tr("Next K&ey"), QKeySequence(Qt::Key_Up),
        AnimationText::tr("Go to the next frame holding a key of any kind"));
    QObject::connect(nextKey, &QAction::triggered, panel, [panel] { panel->jumpToKey(1); });

    // The shot camera and the Observer layout (paper 1, figures 10-12).
    QAction* lookThrough
        = make("actionLookThroughShotCamera", AnimationText::tr("Look Through &Shot Camera"), QKeySequence(),
            AnimationText::tr("The main view follows the camera path at the current frame; turning the "
                              "view with the mouse leaves it"));
    lookThrough->setCheckable(true);
    new ShotCameraFollower(window, lookThrough);
    QAction* layout = make("actionObserverLayout", AnimationText::tr("&Observer Layout"), QKeySequence(),
        AnimationText::tr("Show the Observer beside the main view: the view-dependent model as the shot camera sees "
                          "it, the camera path and the camera, from a fixed vantage point"));
    layout->setCheckable(true);
    auto* observerDock = window->findChild<QDockWidget*>(QStringLiteral("observerDock"));
    QObject::connect(layout, &QAction::toggled, window, [window, observerDock](bool on) {
        if (!observerDock)
            return;
        if (!on) {
            observerDock->hide();
            return;
        }
        // Beside the main view: its own column on the left area's inner side, as wide as half the
        // main view, next to the panels' columns.
        observerDock->setFloating(false);
        window->addDockWidget(Qt::LeftDockWidgetArea, observerDock, Qt::Horizontal);
        observerDock->show();
        window->resizeDocks({observerDock}, {std::max(240, window->viewport()->width() / 2)}, Qt::Horizontal);
        // Framed once the dock has its size (the fit depends on the view's aspect).
        QTimer::singleShot(0, window, [window] { frameObserver(window); });
    });
    if (observerDock)
        QObject::connect(observerDock, &QDockWidget::visibilityChanged, layout, [layout, observerDock](bool) {
            if (observerDock->isHidden() && layout->isChecked())
                layout->setChecked(false);
        });

    // The camera path, keyed by hand or generated.
    QAction* keyCamera = make("actionKeyCamera", AnimationText::tr("&Key Camera"), QKeySequence(Qt::SHIFT | Qt::Key_K),
        AnimationText::tr("Key the current view as the shot camera at the current frame"));
    QObject::connect(keyCamera, &QAction::triggered, window, [window] {
        if (!window->document()->hasMesh())
            return;
        window->document()->animation().setCameraKey(window->document()->currentFrame(), window->viewport()->camera());
        window->statusBar()->showMessage(
            AnimationText::tr("Camera keyed at frame %1").arg(window->document()->currentFrame()), 4000);
    });
    QAction* removeKey = make("actionRemoveCameraKey", AnimationText::tr("&Remove Camera Key"), QKeySequence(),
        AnimationText::tr("Remove the camera key at the current frame"));
    QObject::connect(removeKey, &QAction::triggered, window,
        [window] { window->document()->animation().removeCameraKey(window->document()->currentFrame()); });
    QAction* clear = make("actionClearCameraPath", AnimationText::tr("&Clear Camera Path"), QKeySequence(),
        AnimationText::tr("Remove every camera key: the render camera applies again"));
    QObject::connect(
        clear, &QAction::triggered, window, [window] { window->document()->animation().clearCameraPath(); });
    QAction* turntable = make("actionTurntable", AnimationText::tr("&Turntable…"), QKeySequence(),
        AnimationText::tr("Replace the camera path by one revolution around the model"));
    QObject::connect(turntable, &QAction::triggered, window, [window, lookThrough] {
        model::Document* d = window->document();
        if (!d->hasMesh())
            return;
        TurntableDialog dialog(d->data().time.firstFrame, window);
        if (dialog.exec() != QDialog::Accepted)
            return;
        const views::Viewport* v = window->viewport();
        try {
            d->animation().makeTurntable(
                dialog.turntable(), v->height() > 0 ? double(v->width()) / v->height() : 16.0 / 9.0);
            lookThrough->setChecked(true);
        } catch (const model::EditRefused& e) {
            window->statusBar()->showMessage(AnimationText::tr("Turntable refused: %1").arg(e.what()), 10000);
        }
    });
    auto updateEnabled = [window, removeKey, clear, lookThrough, keyCamera, turntable] {
        const model::Document* d = window->document();
        const auto& path = d->data().look.cameraPath;
        removeKey->setEnabled(path.hasKey(d->currentFrame()));
        clear->setEnabled(!path.empty());
        for (QAction* a : {lookThrough, keyCamera, turntable})
            a->setEnabled(d->hasMesh());
    };
    QObject::connect(doc, &model::Document::changed, window, [updateEnabled](const model::ChangeSet& change) {
        using model::Part;
        if (change.reset || change.has(Part::CameraPath) || change.has(Part::Playhead) || change.has(Part::Mesh))
            updateEnabled();
    });
    updateEnabled();

    // Menus: View ▸ Playback, the shot and layout toggles in View, and a Camera menu before Help.
    if (QMenu* view = menuOf(window->action(QStringLiteral("actionFrameAll")))) {
        QMenu* playbackMenu = new QMenu(AnimationText::tr("Play&back"), view);
        playbackMenu->setObjectName(QStringLiteral("menuPlayback"));
        playbackMenu->addActions({play, loop});
        playbackMenu->addSeparator();
        playbackMenu->addActions({first, previous, next, last});
        playbackMenu->addSeparator();
        playbackMenu->addActions({previousKey, nextKey});
        QAction* before = window->action(QStringLiteral("actionStereoReview"));
        view->insertMenu(before, playbackMenu);
        view->insertAction(before, lookThrough);
        view->insertAction(before, layout);
        view->insertAction(before, dock->toggleViewAction());
    }
    auto* camera = new QMenu(AnimationText::tr("&Camera"), window);
    camera->setObjectName(QStringLiteral("menuCamera"));
    camera->addActions({keyCamera, removeKey, clear});
    camera->addSeparator();
    camera->addAction(turntable);
    camera->addSeparator();
    camera->addActions({lookThrough, layout});
    const QMenu* help = menuOf(window->action(QStringLiteral("actionAbout")));
    if (help)
        window->menuBar()->insertMenu(help->menuAction(), camera);
    else
        window->menuBar()->addMenu(camera);
}

} // namespace celform::app
