// The editor window and its file handling.
#include "main_window.h"

#include "editor_dialogs.h"
#include "first_steps_hint.h"
#include "getting_started.h"
#include "preferences.h"
#include "recovery.h"
#include "review_window.h"

#include "celform/model/image_io.h"
#include "celform/model/io_error.h"
#include "celform/model/mesh_io.h"
#include "celform/model/project_file.h"
#include "celform/views/highlight_panel.h"
#include "celform/views/look_panel.h"
#include "celform/views/properties_panel.h"
#include "celform/views/scene_panel.h"
#include "celform/views/view_sphere_panel.h"
#include "celform/views/viewport.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QActionGroup>
#include <QKeyEvent>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPainter>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QPlainTextEdit>
#include <QTime>
#include <QTimer>
#include <QToolBar>
#include <QUndoView>
#include <QtConcurrent/QtConcurrentRun>

#include <optional>

// The icons live in the celform_app static library: register them before first use.
static void initResources()
{
    Q_INIT_RESOURCE(celform);
}

namespace celform::app {
namespace {

/// Lets the window's Undo and Redo through when a spin box has the keyboard: its line edit would
/// otherwise take Ctrl+Z for its own text, and the project's undo would seem dead (a spin box's
/// text undo is of no use; text fields such as names keep theirs).
class UndoFromSpinBoxes : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::ShortcutOverride)
            return false;
        auto* key = static_cast<QKeyEvent*>(event);
        const QKeySequence pressed(key->keyCombination());
        const bool undoRedo = pressed == QKeySequence(Qt::CTRL | Qt::Key_Z)
            || pressed == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)
            || pressed == QKeySequence(Qt::CTRL | Qt::Key_Y);
        auto* widget = qobject_cast<QWidget*>(watched);
        const bool inSpinBox = widget
            && (qobject_cast<QAbstractSpinBox*>(widget) || qobject_cast<QAbstractSpinBox*>(widget->parentWidget()));
        if (!undoRedo || !inSpinBox)
            return false;
        event->ignore(); // not overridden: the shortcut (the window's Undo or Redo) runs
        return true;
    }
};

constexpr int kMaxRecentFiles = 10;
const char* const kRecentKey = "files/recent";

/// A value or the message of the IoError that prevented it.
template <typename T> struct Outcome {
    std::optional<T> value;
    QString error;
};

/// Runs work on a pool thread while the window stays responsive; a progress dialog with Cancel
/// appears when it takes longer than half a second. Cancel drops the result (nothing changes).
template <typename T, typename Work> Outcome<T> runWithProgress(QWidget* parent, const QString& label, Work work)
{
    QFutureWatcher<Outcome<T>> watcher;
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcher<Outcome<T>>::finished, &loop, &QEventLoop::quit);
    watcher.setFuture(QtConcurrent::run([work]() -> Outcome<T> {
        try {
            return {work(), {}};
        } catch (const model::IoError& e) {
            return {std::nullopt, e.message()};
        } catch (const std::bad_alloc&) {
            return {std::nullopt, QCoreApplication::translate("celform::app::MainWindow", "Not enough memory.")};
        }
    }));
    QProgressDialog progress(label, QCoreApplication::translate("celform::app::MainWindow", "Cancel"), 0, 0, parent);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    bool canceled = false;
    QObject::connect(&progress, &QProgressDialog::canceled, &loop, [&] {
        canceled = true;
        loop.quit();
    });
    if (!watcher.isFinished())
        loop.exec(QEventLoop::ExcludeUserInputEvents);
    progress.reset();
    if (canceled)
        return {std::nullopt, QString()};
    return watcher.result();
}

QString suffixOf(const QString& path)
{
    return QFileInfo(path).suffix().toLower();
}

} // namespace

MainWindow::MainWindow(Mode mode, QWidget* parent)
    : QMainWindow(parent)
    , m_mode(mode)
    , m_document(new model::Document(this))
{
    setObjectName(QStringLiteral("CelformMainWindow"));
    initResources();
    qApp->installEventFilter(new UndoFromSpinBoxes(this));
    setWindowIcon(QIcon(QStringLiteral(":/celform/icon.svg")));
    setAcceptDrops(true);
    setDockNestingEnabled(true);

    m_viewport = new views::Viewport(m_document, this);
    m_viewport->setObjectName(QStringLiteral("viewport"));
    new FirstStepsHint(m_document, m_viewport);
    m_viewport->setMinimumSize(320, 240);
    setCentralWidget(m_viewport);

    createDocks();
    createActions();
    createMenus();

    m_statistics = new QLabel(this);
    statusBar()->addPermanentWidget(m_statistics);
    statusBar()->showMessage(tr("Ready"), 3000);

    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(m_document, &model::Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        using model::Part;
        if (change.reset)
            updateTitle();
        // The status bar counts vertices, drawings and keys: only structure changes them.
        if (change.reset || change.has(Part::Mesh)
            || ((change.has(Part::Drawings) || change.has(Part::Keys)) && change.structure))
            updateStatistics();
    });

    const QString recoveryDir
        = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/recovery");
    m_recovery = new RecoveryManager(m_document, recoveryDir, this);
    QSettings settings;
    const int minutes = settings.value(QStringLiteral("autosave/minutes"), 3).toInt();
    m_recovery->setInterval(m_mode == Mode::Interactive ? minutes * 60 * 1000 : 0);
    connect(m_recovery, &RecoveryManager::autosaved, this,
        [this] { statusBar()->showMessage(tr("Autosaved a recovery copy"), 3000); });
    connect(m_recovery, &RecoveryManager::autosaveFailed, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 10000);
        qWarning("autosave failed: %s", qPrintable(message));
    });

    if (m_mode == Mode::Interactive) {
        restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
        restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    }
    if (!settings.contains(QStringLiteral("window/geometry")) || m_mode == Mode::Batch)
        resize(1400, 900);
    updateTitle();
    updateStatistics();
    updateRecentMenu();
    installEditorDialogs(this); // render, preferences, keyboard shortcuts (editor_dialogs.cpp)
}

MainWindow::~MainWindow() = default;

QAction* MainWindow::action(const QString& name) const
{
    return findChild<QAction*>(name);
}

// --- construction -----------------------------------------------------------------------------

void MainWindow::createDocks()
{
    auto makeDock = [this](const QString& title, const QString& name, QWidget* content, Qt::DockWidgetArea area) {
        auto* dock = new QDockWidget(title, this);
        dock->setObjectName(name);
        dock->setWidget(content);
        addDockWidget(area, dock);
        return dock;
    };
    m_scene = new views::ScenePanel(m_document, this);
    makeDock(tr("Scene"), QStringLiteral("sceneDock"), m_scene, Qt::LeftDockWidgetArea);
    m_history = new QUndoView(m_document->undoStack(), this);
    m_history->setEmptyLabel(tr("<Opened project>"));
    m_history->setToolTip(tr("Every edit of the project; click an entry to go back to it"));
    makeDock(tr("History"), QStringLiteral("historyDock"), m_history, Qt::LeftDockWidgetArea);
    m_properties = new views::PropertiesPanel(m_document, this);
    makeDock(tr("Properties"), QStringLiteral("propertiesDock"), m_properties, Qt::RightDockWidgetArea);
    m_properties->setViewport(m_viewport);
    connect(m_properties, &views::PropertiesPanel::keyCreated, this, [this](model::ObjectId key) {
        m_scene->select({views::ScenePanel::ItemKind::Key, key});
        statusBar()->showMessage(tr("Key created: select Edit Key with the Brush to deform it"), 8000);
    });
    connect(m_properties, &views::PropertiesPanel::message, this,
        [this](const QString& text) { statusBar()->showMessage(text, 10000); });
    connect(m_viewport, &views::Viewport::message, this,
        [this](const QString& text) { statusBar()->showMessage(text, 6000); });

    m_look = new views::LookPanel(m_document, this);
    makeDock(tr("Look"), QStringLiteral("lookDock"), m_look, Qt::RightDockWidgetArea);
    tabifyDockWidget(
        findChild<QDockWidget*>(QStringLiteral("propertiesDock")), findChild<QDockWidget*>(QStringLiteral("lookDock")));
    // Stylized highlights and their keys (Anjyo & Hiramitsu 2003), tabbed with the Look.
    auto* highlights = new views::HighlightPanel(m_document, this);
    highlights->setViewport(m_viewport);
    makeDock(tr("Highlights"), QStringLiteral("highlightsDock"), highlights, Qt::RightDockWidgetArea);
    tabifyDockWidget(
        findChild<QDockWidget*>(QStringLiteral("lookDock")), findChild<QDockWidget*>(QStringLiteral("highlightsDock")));
    findChild<QDockWidget*>(QStringLiteral("propertiesDock"))->raise();

    // Paper 1, figure 4: the key directions on the viewing sphere and the facet of this view.
    m_sphere = new views::ViewSpherePanel(m_document, this);
    makeDock(tr("Viewing Sphere"), QStringLiteral("sphereDock"), m_sphere, Qt::RightDockWidgetArea);
    auto followCamera = [this] { m_sphere->setViewDirection(m_viewport->viewDirection()); };
    connect(m_viewport, &views::Viewport::cameraChanged, this, followCamera);
    connect(m_document, &model::Document::changed, this, [followCamera](const model::ChangeSet& change) {
        if (change.reset || (change.has(model::Part::Keys) && !change.offsetsOnly))
            followCamera();
    });
    connect(m_sphere, &views::ViewSpherePanel::keyActivated, this, [this](model::ObjectId key) {
        m_scene->select({views::ScenePanel::ItemKind::Key, key});
        if (const auto* k = m_document->data().key(key))
            m_viewport->setCamera(k->camera);
    });

    // Paper 1, figure 6 (bottom row): the blended model from a fixed camera of its own, so the
    // distortion shows while the main camera orbits.
    m_observer = new views::Viewport(m_document, this);
    m_observer->setObjectName(QStringLiteral("observerViewport"));
    m_observer->setMinimumSize(160, 120);
    m_observer->setObserved(m_viewport);
    m_observer->setToolTip(tr("The view-dependent shape for the main camera, seen from this camera of its own"));
    QDockWidget* observerDock
        = makeDock(tr("Observer"), QStringLiteral("observerDock"), m_observer, Qt::BottomDockWidgetArea);
    observerDock->hide(); // a second GL view costs frames: shown on demand from the View menu
    // The panels people edit get most of the right column; the sphere is a glance.
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("propertiesDock")),
                    findChild<QDockWidget*>(QStringLiteral("sphereDock"))},
        {620, 240}, Qt::Vertical);
    m_log = new QPlainTextEdit(this);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    m_log->setToolTip(tr("Messages of this session: files opened and saved, import warnings, errors"));
    QDockWidget* logDock = makeDock(tr("Log"), QStringLiteral("logDock"), m_log, Qt::LeftDockWidgetArea);
    // Tabbed with the History: a third panel in the right column would not fit a 1366x768 screen.
    tabifyDockWidget(findChild<QDockWidget*>(QStringLiteral("historyDock")), logDock);
    logDock->hide(); // shown on demand from the View menu; warnings also reach the status bar
    connect(m_scene, &views::ScenePanel::selectionChanged, m_properties, &views::PropertiesPanel::showSelection);
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("sceneDock")),
                    findChild<QDockWidget*>(QStringLiteral("propertiesDock"))},
        {260, 300}, Qt::Horizontal);
}

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
        [this](bool on) { m_viewport->setShadingEnabled(on); });
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
            m_document->setRenderCamera(m_viewport->camera());
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
                m_viewport->setStereo(output);
                if (output != algo::StereoOutput::Off)
                    m_lastStereo = output;
            });
        a->setCheckable(true);
        a->setChecked(mode.output == algo::StereoOutput::Off);
        stereoGroup->addAction(a);
    }
    make(QStringLiteral("actionStereoToggle"), tr("Toggle Stereo &Preview"), QKeySequence(Qt::CTRL | Qt::Key_3),
        tr("Switch the viewport between mono and the last stereo mode (anaglyph at first)"), [this] {
            const bool on = m_viewport->stereo() == algo::StereoOutput::Off;
            const algo::StereoOutput output = on ? m_lastStereo : algo::StereoOutput::Off;
            for (QAction* a : findChildren<QAction*>())
                if (a->objectName().startsWith(QLatin1String("actionStereo")) && a->isCheckable() && a->data().isValid()
                    && algo::StereoOutput(a->data().toInt()) == output)
                    a->setChecked(true);
            m_viewport->setStereo(output);
        });
    for (const auto& mode : stereoModes)
        action(QString::fromLatin1(mode.name))->setData(int(mode.output));
    make(QStringLiteral("actionDrawingOutline"), tr("Drawing &Outline Only"), QKeySequence(Qt::Key_O),
        tr("Show only the lines and silhouette edge of the drawing in the viewport, so the model's contours can be "
           "matched to them"),
        [this](bool on) { m_viewport->setOverlayOutline(on); })
        ->setCheckable(true);
    make(QStringLiteral("actionNavigate"), tr("&Navigate Only"), QKeySequence(Qt::Key_Escape),
        tr("Leave alignment and brush tools"), [this] { m_viewport->setTool(views::Viewport::Tool::Navigate); });
    make(QStringLiteral("actionCreateKeyFromView"), tr("Create Key from &View"), QKeySequence(Qt::CTRL | Qt::Key_K),
        tr("Make a key viewpoint seen from the current camera, starting as a copy of the base model"), [this] {
            try {
                const auto id = m_document->createKey(tr("Key"), m_viewport->camera());
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
    m_viewMenu->addAction(action(QStringLiteral("actionStereoReview")));
    m_viewMenu->addAction(action(QStringLiteral("actionShowLook")));
    m_viewMenu->addAction(action(QStringLiteral("actionDrawingOutline")));
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

void MainWindow::updateTitle()
{
    const QString path = m_document->filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1[*] — Celform").arg(name));
    setWindowModified(m_document->isModified());
    action(QStringLiteral("actionSave"))->setEnabled(true);
}

void MainWindow::updateStatistics()
{
    const auto& data = m_document->data();
    if (!data.baseMesh) {
        m_statistics->setText(tr("No base model"));
        return;
    }
    const QLocale locale;
    m_statistics->setText(tr("%1 vertices · %2 triangles · %3 drawings · %4 keys")
                              .arg(locale.toString(qlonglong(data.baseMesh->vertexCount())),
                                  locale.toString(qlonglong(data.baseMesh->faceCount())))
                              .arg(data.drawings.size())
                              .arg(data.keys.size()));
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        updateTitle();
    QMainWindow::changeEvent(event);
}

void MainWindow::log(LogLevel level, const QString& message)
{
    const QString time = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
    const char* colour = level == LogLevel::Error ? "#c0392b" : level == LogLevel::Warning ? "#b9770e" : "#555555";
    const QString label = level == LogLevel::Error ? tr("Error")
        : level == LogLevel::Warning               ? tr("Warning")
                                                   : tr("Info");
    m_log->appendHtml(QStringLiteral("<span style=\"color:#888\">%1</span> <b style=\"color:%2\">%3</b> %4")
                          .arg(time, QLatin1String(colour), label, message.toHtmlEscaped()));
    if (level != LogLevel::Info)
        qWarning("%s", qPrintable(message));
}

void MainWindow::showError(const QString& message)
{
    log(LogLevel::Error, message);
    statusBar()->showMessage(message, 15000);
    if (m_mode == Mode::Interactive)
        QMessageBox::warning(this, tr("Celform"), message);
}

void MainWindow::showWarnings(const QString& file, const QStringList& warnings)
{
    if (warnings.isEmpty())
        return;
    const QString text
        = tr("%1 loaded with warnings: %2").arg(QFileInfo(file).fileName(), warnings.join(QStringLiteral("; ")));
    log(LogLevel::Warning, text);
    statusBar()->showMessage(text, 20000);
}

// --- files ------------------------------------------------------------------------------------

bool MainWindow::openFile(const QString& path)
{
    const QString suffix = suffixOf(path);
    if (suffix == QLatin1String("celform") || suffix == QLatin1String("bak"))
        return openProject(path);
    if (model::meshSuffixes().contains(suffix))
        return importMesh(path, !m_document->hasMesh());
    if (model::imageSuffixes().contains(suffix))
        return importDrawing(path);
    showError(tr("%1: not a project, mesh or image file Celform can read").arg(path));
    return false;
}

bool MainWindow::openProject(const QString& path)
{
    if (!maybeSave())
        return false;
    auto outcome = runWithProgress<model::ProjectData>(
        this, tr("Opening %1…").arg(QFileInfo(path).fileName()), [path] { return model::loadProject(path); });
    if (!outcome.value) {
        if (!outcome.error.isEmpty())
            showError(outcome.error);
        return false;
    }
    m_document->reset(std::move(*outcome.value), QFileInfo(path).absoluteFilePath());
    addRecentFile(path);
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    log(LogLevel::Info, tr("Opened %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool MainWindow::importMesh(const QString& path, bool asNewProject)
{
    if (asNewProject && !maybeSave())
        return false;
    auto outcome = runWithProgress<model::MeshImport>(
        this, tr("Reading %1…").arg(QFileInfo(path).fileName()), [path] { return model::importMesh(path); });
    if (!outcome.value) {
        if (!outcome.error.isEmpty())
            showError(outcome.error);
        return false;
    }
    auto mesh = std::make_shared<const algo::TriMesh>(std::move(outcome.value->mesh));
    if (asNewProject) {
        model::ProjectData data = model::newProject(std::move(mesh), QFileInfo(path).fileName());
        data.look.style = Preferences::load().newProjectStyle; // Edit > Preferences
        m_document->reset(std::move(data));
    } else {
        try {
            m_document->setBaseMesh(std::move(mesh), QFileInfo(path).fileName());
        } catch (const model::IoError& e) {
            showError(e.message());
            return false;
        }
    }
    showWarnings(path, outcome.value->warnings);
    if (outcome.value->warnings.isEmpty())
        statusBar()->showMessage(tr("Loaded %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::importDrawing(const QString& path)
{
    auto outcome = runWithProgress<model::Drawing>(
        this, tr("Reading %1…").arg(QFileInfo(path).fileName()), [path] { return model::importDrawing(path); });
    if (!outcome.value) {
        if (!outcome.error.isEmpty())
            showError(outcome.error);
        return false;
    }
    const auto id = m_document->addDrawing(std::move(*outcome.value));
    m_scene->select({views::ScenePanel::ItemKind::Drawing, id});
    statusBar()->showMessage(tr("Added drawing %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::save()
{
    if (m_document->filePath().isEmpty())
        return saveAs();
    try {
        m_document->saveAs(m_document->filePath());
    } catch (const model::IoError& e) {
        showError(e.message());
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(m_document->filePath()).fileName()), 5000);
    addRecentFile(m_document->filePath());
    return true;
}

bool MainWindow::saveAs(const QString& given)
{
    QString path = given;
    if (path.isEmpty()) {
        if (m_mode == Mode::Batch)
            return false;
        QString start = m_document->filePath();
        if (start.isEmpty())
            start = QFileInfo(m_document->data().baseMeshName).completeBaseName() + QStringLiteral(".celform");
        path = QFileDialog::getSaveFileName(this, tr("Save Project"), start, tr("Celform projects (*.celform)"));
        if (path.isEmpty())
            return false;
        if (suffixOf(path) != QLatin1String("celform"))
            path += QStringLiteral(".celform");
    }
    try {
        m_document->saveAs(path);
    } catch (const model::IoError& e) {
        showError(e.message());
        return false;
    }
    addRecentFile(path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 5000);
    log(LogLevel::Info, tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool MainWindow::maybeSave()
{
    if (!m_document->isModified() || m_mode == Mode::Batch)
        return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved changes"),
        tr("The project “%1” has unsaved changes. Save them first?")
            .arg(m_document->filePath().isEmpty() ? tr("Untitled") : QFileInfo(m_document->filePath()).fileName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::newFromMeshDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("New Project from Mesh"), {}, model::meshFileFilter());
    if (!path.isEmpty())
        importMesh(path, true);
}

void MainWindow::openDialog()
{
    const QString filter = tr("Celform projects (*.celform)") + QStringLiteral(";;") + model::meshFileFilter();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Project"), {}, filter);
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::importMeshDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Mesh"), {}, model::meshFileFilter());
    if (!path.isEmpty())
        importMesh(path, !m_document->hasMesh());
}

void MainWindow::importDrawingDialog()
{
    const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Import Drawings"), {}, model::imageFileFilter());
    for (const QString& path : paths)
        importDrawing(path);
}

void MainWindow::addRecentFile(const QString& path)
{
    if (suffixOf(path) != QLatin1String("celform"))
        return;
    QSettings settings;
    QStringList recent = settings.value(kRecentKey).toStringList();
    const QString abs = QFileInfo(path).absoluteFilePath();
    recent.removeAll(abs);
    recent.prepend(abs);
    while (recent.size() > kMaxRecentFiles)
        recent.removeLast();
    settings.setValue(kRecentKey, recent);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(kRecentKey).toStringList();
    int n = 0;
    for (const QString& path : recent) {
        ++n;
        QAction* a = m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(n % 10).arg(QFileInfo(path).fileName()));
        a->setToolTip(path);
        a->setStatusTip(path);
        connect(a, &QAction::triggered, this, [this, path] { openFile(path); });
    }
    if (recent.isEmpty())
        m_recentMenu->addAction(tr("No recent projects"))->setEnabled(false);
    else {
        m_recentMenu->addSeparator();
        m_recentMenu->addAction(tr("&Clear List"), this, [this] {
            QSettings().remove(kRecentKey);
            updateRecentMenu();
        });
    }
}

void MainWindow::offerRecovery()
{
    if (m_mode != Mode::Interactive)
        return;
    for (const auto& orphan : m_recovery->orphans()) {
        const QString name
            = orphan.originalFile.isEmpty() ? tr("an untitled project") : QFileInfo(orphan.originalFile).fileName();
        QMessageBox box(QMessageBox::Question, tr("Recover unsaved work"),
            tr("Celform did not close normally. A recovery copy of %1 from %2 was found.\n\n"
               "Recover it now?")
                .arg(name, QLocale().toString(orphan.savedAt, QLocale::ShortFormat)),
            QMessageBox::NoButton, this);
        QPushButton* recover = box.addButton(tr("&Recover"), QMessageBox::AcceptRole);
        QPushButton* later = box.addButton(tr("&Keep for Later"), QMessageBox::RejectRole);
        QPushButton* discard = box.addButton(tr("&Discard…"), QMessageBox::DestructiveRole);
        box.setDefaultButton(recover);
        box.exec();
        if (box.clickedButton() == recover) {
            if (!maybeSave())
                return;
            try {
                model::ProjectData data = model::loadProject(orphan.recoveryFile);
                m_document->reset(std::move(data), orphan.originalFile);
                m_document->undoStack()->resetClean(); // recovered work is unsaved work
                m_recovery->adopt(orphan);
                statusBar()->showMessage(tr("Recovered %1; save it to keep it").arg(name), 10000);
            } catch (const model::IoError& e) {
                showError(e.message());
            }
            return; // one document at a time: later orphans are offered on the next launch
        }
        if (box.clickedButton() == discard) {
            if (QMessageBox::question(
                    this, tr("Discard recovery copy"), tr("Delete the recovery copy of %1 for good?").arg(name))
                == QMessageBox::Yes)
                RecoveryManager::discard(orphan);
        }
        Q_UNUSED(later);
    }
}

bool MainWindow::saveScreenshot(const QString& path)
{
    // Let the window lay out and the viewport render at least once before grabbing.
    QElapsedTimer timer;
    timer.start();
    while (m_viewport->renderCount() == 0 && timer.elapsed() < 10000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    // A second frame once the layout has settled (docks resize the viewport after the first).
    const int first = m_viewport->renderCount();
    m_viewport->update();
    while (m_viewport->renderCount() == first && timer.elapsed() < 10000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    QCoreApplication::processEvents();
    QPixmap shot = grab();
    // QWidget::grab() re-renders GL children mono and without their painter overlays: paste
    // what the viewport really shows (lines, stereo) over its place.
    {
        QPainter painter(&shot);
        const QImage viewport = m_viewport->renderedImage();
        const QPoint origin = m_viewport->mapTo(this, QPoint(0, 0));
        painter.drawImage(QRect(origin, m_viewport->size()), viewport);
        // Then the widgets over it (axis gizmo, banners, the brush circle), as the screen shows them.
        for (QWidget* child : m_viewport->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
            if (child->isVisible())
                child->render(&painter, origin + child->pos(), QRegion(), QWidget::DrawChildren);
    }
    if (shot.isNull() || !shot.save(path, "PNG")) {
        qWarning("celform: %s: the screenshot could not be written", qPrintable(path));
        return false;
    }
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    if (m_mode == Mode::Interactive) {
        QSettings settings;
        settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
        settings.setValue(QStringLiteral("window/state"), saveState());
    }
    m_recovery->removeOwn(); // a clean exit: the user saved or chose to discard
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (!event->mimeData()->hasUrls())
        return;
    const QStringList accepted
        = model::meshSuffixes() + model::imageSuffixes() + QStringList{QStringLiteral("celform")};
    for (const QUrl& url : event->mimeData()->urls()) {
        if (url.isLocalFile() && accepted.contains(suffixOf(url.toLocalFile()))) {
            event->acceptProposedAction();
            return;
        }
    }
}

void MainWindow::dropEvent(QDropEvent* event)
{
    event->acceptProposedAction();
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile())
            m_dropQueue << url.toLocalFile();
    // Open after the drop returns (a modal dialog inside a drop handler blocks the drag source),
    // one file after another: a drop that arrives while a file loads waits its turn.
    if (!m_processingDrops)
        QTimer::singleShot(0, this, &MainWindow::processDropQueue);
}

void MainWindow::processDropQueue()
{
    if (m_processingDrops)
        return;
    m_processingDrops = true;
    while (!m_dropQueue.isEmpty())
        openFile(m_dropQueue.takeFirst());
    m_processingDrops = false;
}

} // namespace celform::app
