// The editor window's actions, their shortcuts (set explicitly: QKeySequence's standard keys are
// empty outside the KDE and GNOME themes, and the README documents these), its menus and toolbar.
#include "editor/main_window.h"

#include "editor/dialogs/editor_dialogs.h"
#include "editor/getting_started.h"
#include "editor/jobs/job_runner.h"
#include "editor/jobs/light_optimisation_job.h"
#include "editor/jobs/light_track_job.h"
#include "editor/actions/fit_actions.h"
#include "editor/actions/focal_point_actions.h"
#include "editor/actions/shading_offset_actions.h"
#include "editor/settings/preferences.h"
#include "editor/review_window.h"

#include "celform/model/data/io_error.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/panels/highlight_panel.h"
#include "celform/views/panels/look_panel.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/panels/view_sphere_panel.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/viewport/viewport_display.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QKeySequence>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>

namespace celform::app {

void MainWindow::createActions()
{
    auto make = [this](const QString& name, const QString& text, const QKeySequence& shortcut, const QString& tip,
                    auto slot) {
        auto* a = new QAction(text, this);
        a->setObjectName(name);
        a->setShortcut(shortcut);
        a->setStatusTip(tip);
        a->setToolTip(tip);
        connect(a, &QAction::triggered, this, slot);
        addAction(a);
        return a;
    };
    // Explicit key sequences: QKeySequence's standard keys (SaveAs, Quit, ...) are empty outside
    // the KDE and GNOME platform themes, and the README documents these.
    make(QStringLiteral("actionNewFromMesh"), tr("&New from Mesh…"), QKeySequence(Qt::CTRL | Qt::Key_N),
        tr("Start a new project on a base model (OBJ, PLY, STL, OFF, glTF)"), [this] { newFromMeshDialog(); });
    make(QStringLiteral("actionOpen"), tr("&Open…"), QKeySequence(Qt::CTRL | Qt::Key_O), tr("Open a Celform project"),
        [this] { openDialog(); });
    make(QStringLiteral("actionSave"), tr("&Save"), QKeySequence(Qt::CTRL | Qt::Key_S), tr("Save the project"),
        [this] { save(); });
    make(QStringLiteral("actionSaveAs"), tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
        tr("Save the project under a new name"), [this] { saveAs(); });
    make(QStringLiteral("actionImportMesh"), tr("Import &Mesh…"), QKeySequence(Qt::CTRL | Qt::Key_I),
        tr("Replace the base model by a mesh file with the same vertex order"), [this] { importMeshDialog(); });
    make(QStringLiteral("actionImportDrawing"), tr("Import &Drawing…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I),
        tr("Add a reference drawing (PNG, JPEG, TIFF, EXR, PSD, SVG) to the model sheet"),
        [this] { importDrawingDialog(); });
    make(QStringLiteral("actionQuit"), tr("&Quit"), QKeySequence(Qt::CTRL | Qt::Key_Q), tr("Quit Celform"),
        [this] { close(); });

    QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    addAction(undo);
    QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    addAction(redo);
    QAction* del = make(QStringLiteral("actionDelete"), tr("&Delete"), QKeySequence::Delete,
        tr("Remove the selected drawing or key viewpoint"), [this] { m_scene->removeSelected(); });
    // Delete acts in the scene tree only, so it never eats a key press meant for a text field.
    del->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    removeAction(del);
    m_scene->addAction(del);

    make(QStringLiteral("actionFrameAll"), tr("&Frame All"), QKeySequence(Qt::Key_F),
        tr("Fit the whole model in the viewport"), [this] { m_viewport->frameAll(); })
        ->setShortcutContext(Qt::WindowShortcut);
    // View presets, as Blender's numeric keypad (Ctrl for the opposite side) and Home for the front.
    using Preset = views::Viewport::ViewPreset;
    const struct {
        const char* name;
        QString text;
        QList<QKeySequence> keys;
        Preset preset;
    } presets[] = {
        {"actionViewFront", tr("&Front"),
            {QKeySequence(Qt::Key_Home), QKeySequence(QKeyCombination(Qt::KeypadModifier, Qt::Key_1))}, Preset::Front},
        {"actionViewBack", tr("&Back"),
            {QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_1))}, Preset::Back},
        {"actionViewRight", tr("&Right"), {QKeySequence(QKeyCombination(Qt::KeypadModifier, Qt::Key_3))},
            Preset::Right},
        {"actionViewLeft", tr("&Left"),
            {QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_3))}, Preset::Left},
        {"actionViewTop", tr("&Top"), {QKeySequence(QKeyCombination(Qt::KeypadModifier, Qt::Key_7))}, Preset::Top},
        {"actionViewBottom", tr("B&ottom"),
            {QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_7))}, Preset::Bottom},
    };
    for (const auto& p : presets) {
        QAction* a
            = make(QString::fromLatin1(p.name), p.text, QKeySequence(), tr("Look at the model from this side, framed"),
                [this, preset = p.preset] { m_viewport->setViewPreset(preset); });
        a->setShortcuts(p.keys);
    }
    auto* ortho = make(QStringLiteral("actionOrthographic"), tr("&Orthographic"), QKeySequence(Qt::Key_5),
        tr("Switch between perspective and orthographic projection"), [this](bool on) {
            m_viewport->setProjection(on ? model::Projection::Orthographic : model::Projection::Perspective);
        });
    ortho->setCheckable(true);
    auto* preview = make(QStringLiteral("actionPreview"), tr("&Preview View-Dependent Shape"), QKeySequence(Qt::Key_P),
        tr("Show the blend of the keys for the current camera, updated while orbiting"), [this](bool on) {
            if (m_properties->previewButton()->isChecked() != on)
                m_properties->previewButton()->setChecked(on);
        });
    preview->setCheckable(true);
    connect(m_properties->previewButton(), &QAbstractButton::toggled, preview, &QAction::setChecked);
    auto* look = make(QStringLiteral("actionShowLook"), tr("Show Cartoon &Look"), QKeySequence(Qt::SHIFT | Qt::Key_L),
        tr("Shade the model with the document's look as the renderer does (off: neutral clay for modelling); "
           "Ctrl+drag the light gizmo to move the key light"),
        [this](bool on) { m_viewport->display().setShadingEnabled(on); });
    look->setCheckable(true);
    look->setChecked(true);
    // The render camera (DESIGN.md, "Look"): what `celform render` looks through by default.
    make(QStringLiteral("actionSetRenderCamera"), tr("Set &Render Camera from View"),
        QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_0),
        tr("Make the current view the project's render camera: celform render looks through it unless given a "
           "camera"),
        [this] {
            if (!m_document->hasMesh())
                return;
            m_document->look().setRenderCamera(m_viewport->camera());
            statusBar()->showMessage(tr("The render camera is the current view."), 4000);
        });
    make(QStringLiteral("actionViewRenderCamera"), tr("View Through Render &Camera"),
        QKeySequence(Qt::CTRL | Qt::Key_0), tr("Look through the project's render camera"), [this] {
            if (const auto& camera = m_document->data().look.renderCamera)
                m_viewport->setCamera(*camera);
            else
                statusBar()->showMessage(tr("No render camera yet: set one from a view first (Ctrl+Alt+0)."), 4000);
        });
    make(QStringLiteral("actionStereoReview"), tr("Stereo &Review"), QKeySequence(Qt::Key_F11),
        tr("Full-screen stereo review of the look: turntable, keys' cameras, stereo modes (H for help)"), [this] {
            auto* review = new ReviewWindow(m_document, m_viewport->camera(), this);
            review->setAttribute(Qt::WA_DeleteOnClose);
            review->showAs(*m_viewport);
            review->showReview();
        });
    // Stereo in the main viewport (DESIGN.md, "Look"): the look's stereo outputs and Off.
    auto* stereoGroup = new QActionGroup(this);
    const struct {
        const char* name;
        QString text;
        algo::StereoOutput output;
    } stereoModes[] = {{"actionStereoOff", tr("&Off (Mono)"), algo::StereoOutput::Off},
        {"actionStereoAnaglyph", tr("&Anaglyph (Red/Cyan)"), algo::StereoOutput::Anaglyph},
        {"actionStereoDubois", tr("&Dubois Anaglyph"), algo::StereoOutput::Dubois},
        {"actionStereoHalfColor", tr("&Half-Colour Anaglyph"), algo::StereoOutput::HalfColor},
        {"actionStereoSideBySide", tr("&Side by Side"), algo::StereoOutput::SideBySide},
        {"actionStereoTopBottom", tr("&Top/Bottom"), algo::StereoOutput::TopBottom}};
    for (const auto& mode : stereoModes) {
        QAction* a = make(QString::fromLatin1(mode.name), mode.text, QKeySequence(),
            tr("Show the viewport in this stereo mode, with the look's interocular and convergence"),
            [this, output = mode.output] {
                m_viewport->display().setStereo(output);
                if (output != algo::StereoOutput::Off)
                    m_lastStereo = output;
            });
        a->setCheckable(true);
        a->setChecked(mode.output == algo::StereoOutput::Off);
        stereoGroup->addAction(a);
    }
    // The depth analysis overlays (paper 3, chapter 4), one at a time, as the Depth dock's buttons.
    auto* depthGroup = new QActionGroup(this);
    const struct {
        const char* name;
        QString text;
        views::DepthOverlay::Kind kind;
    } depthKinds[] = {{"actionDepthOverlayNone", tr("&None"), views::DepthOverlay::Kind::None},
        {"actionDepthOverlaySegments", tr("&Segments"), views::DepthOverlay::Kind::Segments},
        {"actionDepthOverlayCurvature", tr("Gaussian &Curvature"), views::DepthOverlay::Kind::Curvature},
        {"actionDepthOverlayError", tr("&Depth Error"), views::DepthOverlay::Kind::DepthError}};
    for (const auto& k : depthKinds) {
        QAction* a = make(QString::fromLatin1(k.name), k.text, QKeySequence(),
            tr("Show this depth analysis over the viewport (Depth dock)"),
            [this, kind = k.kind] { m_depth->setOverlayKind(kind); });
        a->setCheckable(true);
        a->setChecked(k.kind == views::DepthOverlay::Kind::None);
        a->setData(int(k.kind));
        depthGroup->addAction(a);
    }
    connect(m_depth, &views::DepthPanel::overlayKindChanged, this, [this](views::DepthOverlay::Kind kind) {
        for (QAction* a : findChildren<QAction*>())
            if (a->objectName().startsWith(QLatin1String("actionDepthOverlay")) && a->isCheckable()
                && a->data().toInt() == int(kind))
                a->setChecked(true);
    });
    make(QStringLiteral("actionDepthOverlayNext"), tr("Next Depth &Overlay"), QKeySequence(Qt::SHIFT | Qt::Key_D),
        tr("Cycle the viewport's depth overlay: none, segments, Gaussian curvature, depth error"),
        [this] { m_depth->setOverlayKind(views::DepthOverlay::Kind((int(m_depth->overlay()->kind()) + 1) % 4)); });
    m_depth->setOptimiseLightAction(make(QStringLiteral("actionOptimiseLight"), tr("Optimise &Light for Stereo"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L),
        tr("Move the key light so that every segment of the Depth tab gets a shading line across it: the depth "
           "error falls (one undo step; method in the Depth tab)"),
        [this] { optimiseLightForStereo(); }));
    make(QStringLiteral("actionOptimiseLightAlongShot"), tr("Optimise Light Along &Shot"), QKeySequence(),
        tr("Optimise the light at every frame of the scene's range through the shot camera, each frame starting "
           "from the last, and key it there: a light track that turns no more than 3° a frame (one undo step)"),
        [this] { optimiseLightAlongShot(); });
    make(QStringLiteral("actionStereoToggle"), tr("Toggle Stereo &Preview"), QKeySequence(Qt::CTRL | Qt::Key_3),
        tr("Switch the viewport between mono and the last stereo mode (anaglyph at first)"), [this] {
            const bool on = m_viewport->display().stereo() == algo::StereoOutput::Off;
            const algo::StereoOutput output = on ? m_lastStereo : algo::StereoOutput::Off;
            for (QAction* a : findChildren<QAction*>())
                if (a->objectName().startsWith(QLatin1String("actionStereo")) && a->isCheckable() && a->data().isValid()
                    && algo::StereoOutput(a->data().toInt()) == output)
                    a->setChecked(true);
            m_viewport->display().setStereo(output);
        });
    for (const auto& mode : stereoModes)
        action(QString::fromLatin1(mode.name))->setData(int(mode.output));
    make(QStringLiteral("actionDrawingOutline"), tr("Drawing &Outline Only"), QKeySequence(Qt::Key_O),
        tr("Show only the drawing's outline in the viewport, the one Fit to Drawing aims at (its threshold and "
           "closing radius are in the drawing's Properties), so the model's contours can be matched to it"),
        [this](bool on) { m_viewport->drawingOverlay().setOutline(on); })
        ->setCheckable(true);
    make(QStringLiteral("actionNavigate"), tr("&Navigate Only"), QKeySequence(Qt::Key_Escape),
        tr("Leave alignment and brush tools; a drawing not asked for with its eye is hidden"), [this] {
            m_viewport->setTool(views::Viewport::Tool::Navigate);
            m_viewport->drawingOverlay().showAskedFor();
        });
    make(QStringLiteral("actionToggleDrawing"), tr("Show/Hide &Drawing"), QKeySequence(Qt::Key_D),
        tr("Show the selected drawing over the model whatever is selected, or hide the drawing shown (the eye in "
           "the Scene panel)"),
        [this] {
            views::DrawingOverlay& overlay = m_viewport->drawingOverlay();
            const views::ScenePanel::Selection selected = m_scene->selection();
            const bool drawingSelected = selected.kind == views::ScenePanel::ItemKind::Drawing;
            overlay.toggleShown(overlay.drawing() != 0 || !drawingSelected ? overlay.drawing() : selected.id);
        });
    make(QStringLiteral("actionCreateKeyFromView"), tr("Create Key from &View"), QKeySequence(Qt::CTRL | Qt::Key_K),
        tr("Make a key viewpoint seen from the current camera, starting as a copy of the base model"), [this] {
            try {
                const auto id = m_document->keys().createKey(tr("Key"), m_viewport->camera());
                m_scene->select({views::ScenePanel::ItemKind::Key, id});
            } catch (const model::EditRefused& e) {
                showError(e.message());
            }
        });
    make(QStringLiteral("actionGettingStarted"), tr("&Getting Started"), QKeySequence(),
        tr("A short illustrated guide: from the sample to a view-dependent model"),
        [this] { showGettingStarted(this); });
    make(QStringLiteral("actionAbout"), tr("&About Celform"), QKeySequence(), tr("Version and licence"), [this] {
        QMessageBox::about(this, tr("About Celform"),
            tr("<h3>Celform %1</h3><p>View-dependent models, shaped highlights and stereo-aware toon "
               "rendering for cel animation.</p>")
                .arg(QCoreApplication::applicationVersion()));
    });
    make(QStringLiteral("actionAboutQt"), tr("About &Qt"), QKeySequence(), tr("Qt version and licence"),
        [] { QApplication::aboutQt(); });
    make(QStringLiteral("actionNavigationHelp"), tr("&Navigation"), QKeySequence::HelpContents,
        tr("Mouse and keyboard navigation in the viewport"), [this] {
            QMessageBox::information(this, tr("Viewport navigation"),
                tr("<table>"
                   "<tr><td><b>Alt + left drag</b>, <b>middle drag</b></td><td>orbit</td></tr>"
                   "<tr><td><b>Alt + middle drag</b>, <b>Shift + middle drag</b></td><td>pan</td></tr>"
                   "<tr><td><b>Alt + right drag</b>, <b>Ctrl + middle drag</b>, <b>wheel</b></td><td>dolly</td></tr>"
                   "<tr><td><b>F</b></td><td>frame all</td></tr>"
                   "<tr><td><b>Home</b></td><td>front view</td></tr>"
                   "<tr><td><b>5</b></td><td>perspective / orthographic</td></tr>"
                   "</table>"));
        });
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(action(QStringLiteral("actionNewFromMesh")));
    file->addAction(action(QStringLiteral("actionOpen")));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("menuRecent"));
    file->addSeparator();
    file->addAction(action(QStringLiteral("actionSave")));
    file->addAction(action(QStringLiteral("actionSaveAs")));
    file->addSeparator();
    file->addAction(action(QStringLiteral("actionImportMesh")));
    file->addAction(action(QStringLiteral("actionImportDrawing")));
    file->addSeparator();
    file->addAction(action(QStringLiteral("actionQuit")));

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(action(QStringLiteral("actionUndo")));
    edit->addAction(action(QStringLiteral("actionRedo")));
    edit->addSeparator();
    edit->addAction(action(QStringLiteral("actionDelete")));
    edit->addSeparator();
    edit->addAction(action(QStringLiteral("actionCreateKeyFromView")));
    installFitActions(this, edit);
    edit->addSeparator();
    installOffsetActions(this, edit);

    QMenu* look = menuBar()->addMenu(tr("&Look"));
    look->setObjectName(QStringLiteral("menuLook"));
    look->addAction(action(QStringLiteral("actionOptimiseLight")));
    look->addAction(action(QStringLiteral("actionOptimiseLightAlongShot")));
    installFocalPointActions(this, look);
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(action(QStringLiteral("actionFrameAll")));
    QMenu* presets = m_viewMenu->addMenu(tr("View &From"));
    presets->setObjectName(QStringLiteral("menuViewFrom"));
    for (const char* name :
        {"actionViewFront", "actionViewBack", "actionViewRight", "actionViewLeft", "actionViewTop", "actionViewBottom"})
        presets->addAction(action(QString::fromLatin1(name)));
    m_viewMenu->addAction(action(QStringLiteral("actionOrthographic")));
    m_viewMenu->addAction(action(QStringLiteral("actionPreview")));
    m_viewMenu->addAction(action(QStringLiteral("actionSetRenderCamera")));
    m_viewMenu->addAction(action(QStringLiteral("actionViewRenderCamera")));
    QMenu* stereo = m_viewMenu->addMenu(tr("&Stereo Preview"));
    stereo->setObjectName(QStringLiteral("menuStereo"));
    stereo->addAction(action(QStringLiteral("actionStereoToggle")));
    stereo->addSeparator();
    for (const char* name : {"actionStereoOff", "actionStereoAnaglyph", "actionStereoDubois", "actionStereoHalfColor",
             "actionStereoSideBySide", "actionStereoTopBottom"})
        stereo->addAction(action(QString::fromLatin1(name)));
    QMenu* depth = m_viewMenu->addMenu(tr("&Depth Overlay"));
    depth->setObjectName(QStringLiteral("menuDepthOverlay"));
    depth->addAction(action(QStringLiteral("actionDepthOverlayNext")));
    depth->addSeparator();
    for (const char* name : {"actionDepthOverlayNone", "actionDepthOverlaySegments", "actionDepthOverlayCurvature",
             "actionDepthOverlayError"})
        depth->addAction(action(QString::fromLatin1(name)));
    m_viewMenu->addAction(action(QStringLiteral("actionStereoReview")));
    m_viewMenu->addAction(action(QStringLiteral("actionShowLook")));
    m_viewMenu->addAction(action(QStringLiteral("actionDrawingOutline")));
    m_viewMenu->addAction(action(QStringLiteral("actionToggleDrawing")));
    m_viewMenu->addAction(action(QStringLiteral("actionNavigate")));
    m_viewMenu->addSeparator();
    for (auto* dock : findChildren<QDockWidget*>())
        m_viewMenu->addAction(dock->toggleViewAction());

    // The toolbar holds what artists reach for most; icons from the desktop theme with Qt's own
    // standard icons as the fallback, so it works on any desktop and on bare farm nodes alike.
    QToolBar* tools = addToolBar(tr("Main"));
    tools->setObjectName(QStringLiteral("mainToolBar"));
    tools->setIconSize(QSize(20, 20));
    auto withIcon = [this](const char* name, const char* themeIcon, QStyle::StandardPixmap fallback) {
        QAction* a = action(QString::fromLatin1(name));
        a->setIcon(QIcon::fromTheme(QString::fromLatin1(themeIcon), style()->standardIcon(fallback)));
        return a;
    };
    tools->addAction(withIcon("actionNewFromMesh", "document-new", QStyle::SP_FileIcon));
    tools->addAction(withIcon("actionOpen", "document-open", QStyle::SP_DialogOpenButton));
    tools->addAction(withIcon("actionSave", "document-save", QStyle::SP_DialogSaveButton));
    tools->addSeparator();
    tools->addAction(withIcon("actionUndo", "edit-undo", QStyle::SP_ArrowBack));
    tools->addAction(withIcon("actionRedo", "edit-redo", QStyle::SP_ArrowForward));
    tools->addSeparator();
    tools->addAction(withIcon("actionImportDrawing", "insert-image", QStyle::SP_FileDialogContentsView));
    tools->addAction(withIcon("actionFrameAll", "zoom-fit-best", QStyle::SP_TitleBarMaxButton));
    tools->addSeparator();
    tools->addAction(withIcon("actionPreview", "view-preview", QStyle::SP_MediaPlay));
    m_viewMenu->addAction(tools->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(action(QStringLiteral("actionGettingStarted")));
    help->addAction(action(QStringLiteral("actionNavigationHelp")));
    help->addSeparator();
    help->addAction(action(QStringLiteral("actionAbout")));
    help->addAction(action(QStringLiteral("actionAboutQt")));
}

// --- state shown in the window -----------------------------------------------------------------

void MainWindow::optimiseLightForStereo()
{
    if (m_lightRunner && m_lightRunner->isRunning())
        return;
    const model::ProjectData& data = m_document->data();
    if (!data.baseMesh) {
        showError(tr("Open a model first: the light is optimised for the picture of a model."));
        return;
    }
    LightOptimisationJob job;
    // What the analysis reads; keys and drawings stay behind (the shape on screen is given).
    job.data.baseMesh = data.baseMesh;
    job.data.faceSets = data.faceSets;
    job.offsets = m_viewport->displayedShadingOffsets();
    job.data.look = data.look;
    job.data.currentFrame = data.currentFrame;
    job.shape = m_viewport->displayedShape();
    job.generation = m_viewport->displayedShapeGeneration();
    job.frame = data.currentFrame;
    job.camera = m_viewport->camera();
    const QSize size = m_depth->runner()->analysisSize();
    job.width = size.width();
    job.height = size.height();
    job.request.analysis = m_depth->runner()->settings();
    job.request.optimiser = m_depth->lightSettings();
    m_lightRunner = startLightOptimisation(
        std::move(job), this,
        [this](const std::shared_ptr<const model::LightOptimisationReport>& report) {
            if (report->cancelled()) {
                statusBar()->showMessage(tr("Light optimisation cancelled: the light is unchanged."), 4000);
                return;
            }
            const int before = algo::segmentsInWindow(report->segmentsBefore);
            if (report->after == report->before) {
                statusBar()->showMessage(
                    tr("The light already suits the analysis (%1 of %2 segments inside the window).")
                        .arg(before)
                        .arg(report->segmentsBefore.size()),
                    6000);
                return;
            }
            try {
                m_document->look().applyOptimisedLight(report->before, report->after, report->frame);
            } catch (const model::EditRefused& e) {
                showError(e.message());
                return;
            }
            const LightOptimisationSummary summary = summariseLightOptimisation(*report);
            log(LogLevel::Info, summary.text);
            if (!summary.warning.isEmpty())
                log(LogLevel::Warning, summary.warning);
            // The warning, when there is one, is what the artist must read first.
            statusBar()->showMessage(summary.warning.isEmpty() ? summary.text : summary.warning, 10000);
        },
        [this](const QString& message) { showError(message); });
}

void MainWindow::optimiseLightAlongShot()
{
    if ((m_lightTrackRunner && m_lightTrackRunner->isRunning()) || (m_lightRunner && m_lightRunner->isRunning()))
        return;
    const model::ProjectData& data = m_document->data();
    if (!data.baseMesh) {
        showError(tr("Open a model first: the light is optimised for the pictures of a model."));
        return;
    }
    LightTrackJob job;
    job.data = data;
    job.frames.firstFrame = data.time.firstFrame;
    job.frames.lastFrame = data.time.lastFrame;
    job.frames.step = 1;
    job.frames.size = m_depth->runner()->analysisSize();
    job.frames.pass = QStringLiteral("segments");
    job.request.light.analysis = m_depth->runner()->settings();
    job.request.light.optimiser = m_depth->lightSettings();
    m_lightTrackRunner = startLightTrackOptimisation(
        std::move(job), this,
        [this](const std::shared_ptr<const model::LightTrackReport>& report) {
            if (report->cancelled) {
                statusBar()->showMessage(tr("Light track optimisation cancelled: the light is unchanged."), 4000);
                return;
            }
            try {
                m_document->look().applyOptimisedLightTrack(report->before, report->after);
            } catch (const model::EditRefused& e) {
                showError(e.message());
                return;
            }
            const QString summary = summariseLightTrack(*report);
            log(LogLevel::Info, summary);
            statusBar()->showMessage(summary, 10000);
        },
        [this](const QString& message) { showError(message); });
}

} // namespace celform::app
