// Fit Camera to Drawing and Fit Shape to Drawing in the editor (fit_actions.h).
#include "editor/actions/fit_actions.h"

#include "editor/jobs/fit_job.h"
#include "editor/jobs/job_runner.h"
#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/panels/fit_group.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenu>
#include <QPointer>
#include <QStatusBar>

#include <algorithm>
#include <memory>

namespace celform::app {
namespace {

struct FitText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::FitActions)
};

/// What a fit works on: the selected key and its drawing, or the selected drawing and the first
/// key linked to it (none: 0).
struct FitTarget {
    model::ObjectId drawing = 0;
    model::ObjectId key = 0;
};

FitTarget fitTarget(const model::ProjectData& data, const views::ScenePanel::Selection& selection)
{
    FitTarget target;
    if (!data.baseMesh)
        return target;
    if (selection.kind == views::ScenePanel::ItemKind::Key) {
        if (const model::KeyViewpoint* key = data.key(selection.id)) {
            const auto linked = std::find_if(key->drawingIds.begin(), key->drawingIds.end(),
                [&data](model::ObjectId id) { return data.drawing(id) != nullptr; });
            if (linked != key->drawingIds.end())
                target = {*linked, key->id};
        }
    } else if (selection.kind == views::ScenePanel::ItemKind::Drawing && data.drawing(selection.id)) {
        target.drawing = selection.id;
        for (const model::KeyViewpoint& key : data.keys)
            if (std::find(key.drawingIds.begin(), key.drawingIds.end(), selection.id) != key.drawingIds.end()) {
                target.key = key.id;
                break;
            }
    }
    return target;
}

/// "silhouette IoU 0.812 → 0.964, chamfer distance 6.10 → 1.32 px"
QString figures(const algo::FitMetrics& before, const algo::FitMetrics& after)
{
    return FitText::tr("silhouette IoU %1 → %2, chamfer distance %3 → %4 px")
        .arg(before.iou, 0, 'f', 3)
        .arg(after.iou, 0, 'f', 3)
        .arg(before.chamferPx, 0, 'f', 2)
        .arg(after.chamferPx, 0, 'f', 2);
}

class FitActions : public QObject {
public:
    FitActions(MainWindow* window, QAction* camera, QAction* shape)
        : QObject(window)
        , m_window(window)
        , m_camera(camera)
        , m_shape(shape)
    { }

    void refresh()
    {
        const bool idle = !m_runner;
        const FitTarget target = current();
        m_camera->setEnabled(idle && target.drawing != 0);
        m_shape->setEnabled(idle && target.drawing != 0 && target.key != 0);
    }

    void fitCamera()
    {
        const FitTarget target = current();
        if (m_runner || !target.drawing)
            return;
        views::Viewport* viewport = m_window->viewport();
        // A rough alignment in progress is stored first: the fit starts from it.
        const bool aligning = viewport->tool() == views::Viewport::Tool::Align;
        if (aligning)
            viewport->setTool(views::Viewport::Tool::Navigate);
        model::Document* doc = m_window->document();
        QPointer<MainWindow> window = m_window;
        m_runner = startFitCamera(
            doc->data(), target.drawing, target.key, m_window,
            [window, target, aligning](const model::CameraFit& fit) {
                if (!window)
                    return;
                window->document()->keys().applyFittedCamera(target.drawing, target.key, fit.after);
                // The view looks through the fitted camera with its drawing, as after aligning.
                views::Viewport* vp = window->viewport();
                if (vp->tool() != views::Viewport::Tool::Brush)
                    vp->drawingOverlay().setDrawing(target.drawing);
                vp->setCamera(fit.after);
                if (aligning)
                    vp->setTool(views::Viewport::Tool::Align);
                const model::Drawing* drawing = window->document()->data().drawing(target.drawing);
                window->statusBar()->showMessage(
                    FitText::tr("Camera fitted to “%1”: %2.")
                        .arg(drawing ? drawing->name : QString(), figures(fit.metricsBefore, fit.metricsAfter)),
                    10000);
            },
            [window](const QString& error) {
                if (window)
                    window->showError(error);
            });
        watch();
    }

    void fitShape()
    {
        const FitTarget target = current();
        if (m_runner || !target.drawing || !target.key)
            return;
        views::Viewport* viewport = m_window->viewport();
        model::ShapeFitRequest request = m_window->propertiesPanel()->fitGroup()->shapeRequest();
        // The brush's mirror plane holds for the fit too.
        request.mirror = viewport->tool<views::BrushTool>().settings().mirror;
        QPointer<MainWindow> window = m_window;
        m_runner = startFitShape(
            m_window->document()->data(), target.key, target.drawing, request, m_window,
            [window, target](const model::ShapeFit& fit) {
                if (!window)
                    return;
                const model::KeyViewpoint* key = window->document()->data().key(target.key);
                const QString name = key ? key->name : QString();
                if (fit.indices.empty()) {
                    window->statusBar()->showMessage(
                        FitText::tr("The key “%1” already meets its drawing: nothing moved.").arg(name), 8000);
                    return;
                }
                window->document()->keys().applyFittedShape(target.key, fit.frame, fit.indices, fit.displacements);
                window->statusBar()->showMessage(
                    FitText::tr("Shape of “%1” fitted: %2; %n vertices moved.", nullptr, int(fit.indices.size()))
                        .arg(name, figures(fit.metricsBefore, fit.metricsAfter)),
                    10000);
            },
            [window](const QString& error) {
                if (window)
                    window->showError(error);
            });
        watch();
    }

private:
    [[nodiscard]] FitTarget current() const
    {
        return fitTarget(m_window->document()->data(), m_window->scenePanel()->selection());
    }

    void watch()
    {
        refresh();
        if (m_runner)
            connect(m_runner, &JobRunner::finished, this, [this] {
                m_runner = nullptr;
                refresh();
            });
    }

    MainWindow* m_window;
    QAction* m_camera;
    QAction* m_shape;
    QPointer<JobRunner> m_runner;
};

} // namespace

void installFitActions(MainWindow* window, QMenu* menu)
{
    QAction* camera = addWindowAction(window, QStringLiteral("actionFitCamera"), FitText::tr("Fit &Camera to Drawing"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F),
        FitText::tr("Find the camera for which the model's silhouette meets the drawing's outline, starting from the "
                    "drawing's alignment: the drawing's camera and its key's (one undo step)"));
    QAction* shape = addWindowAction(window, QStringLiteral("actionFitShape"), FitText::tr("Fit &Shape to Drawing"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G),
        FitText::tr("Deform the key at its drawing's frame until its silhouette meets the drawing's outline, with the "
                    "Properties panel's region, pins and strength and the brush's X mirror (one undo step)"));
    auto* actions = new FitActions(window, camera, shape);
    QObject::connect(camera, &QAction::triggered, actions, &FitActions::fitCamera);
    QObject::connect(shape, &QAction::triggered, actions, &FitActions::fitShape);
    QObject::connect(window->scenePanel(), &views::ScenePanel::selectionChanged, actions, &FitActions::refresh);
    QObject::connect(window->document(), &model::Document::changed, actions, [actions](const model::ChangeSet& c) {
        if (c.reset || c.structure || c.has(model::Part::Mesh) || c.has(model::Part::Keys))
            actions->refresh();
    });
    actions->refresh();

    QMenu* sub = menu->addMenu(FitText::tr("Fit to &Drawing"));
    sub->setObjectName(QStringLiteral("menuFitToDrawing"));
    sub->addAction(camera);
    sub->addAction(shape);
    window->propertiesPanel()->setFitActions(camera, shape);
}

} // namespace celform::app
