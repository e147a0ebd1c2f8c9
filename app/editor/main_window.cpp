// The editor window and its file handling.
#include "editor/main_window.h"

#include "editor/actions/animation_actions.h"
#include "editor/actions/subdivision_actions.h"
#include "editor/actions/tool_keys.h"
#include "editor/actions/tool_panels.h"

#include "editor/dialogs/editor_dialogs.h"
#include "editor/first_steps_hint.h"
#include "editor/getting_started.h"
#include "editor/jobs/job_runner.h"
#include "editor/settings/preferences.h"
#include "editor/recovery_manager.h"
#include "editor/review_window.h"

#include "celform/model/io/animation_io.h"
#include "celform/model/io/image_io.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/panels/highlight_panel.h"
#include "celform/views/panels/look_panel.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/panels/view_sphere_panel.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/viewport/viewport.h"

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
#include <QGuiApplication>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPainter>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QPlainTextEdit>
#include <QTime>
#include <QTimer>
#include <QToolBar>
#include <QUndoView>

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

/// Runs work (reading a file) as a job of the JobRunner and waits for it; the window keeps
/// painting, and a progress dialog appears when it takes longer than half a second. Returns the
/// value, or nothing after giving showError the message of the error that prevented it.
template <typename T, typename Work>
std::optional<T> runWithProgress(
    QWidget* parent, const QString& label, const std::function<void(const QString&)>& showError, Work work)
{
    std::optional<T> value;
    JobSpec spec;
    spec.progressName = QStringLiteral("fileProgress");
    spec.label = label;
    spec.delayMs = 500;
    spec.outOfMemory = QCoreApplication::translate("celform::app::MainWindow", "Not enough memory.");
    spec.showError = [showError](const QString& error) {
        if (!error.isEmpty())
            showError(error);
    };
    JobRunner runner(
        std::move(spec),
        [&value, work](algo::Progress&) -> JobRunner::Finish {
            auto read = std::make_shared<T>(work());
            return [&value, read] {
                value = std::move(*read);
                return true;
            };
        },
        parent);
    runner.exec();
    return value;
}

QString suffixOf(const QString& path)
{
    return QFileInfo(path).suffix().toLower();
}

/// The size of the first window, and of the batch mode's screenshots.
constexpr QSize kDefaultWindowSize(1400, 900);

/// The first launch (no saved geometry): the default size when the screen's available area holds
/// it, else the whole available area, maximised (a 1366x768 screen would lose the Timeline, the
/// status bar and the window's own buttons below its edge).
void fitFirstWindowToScreen(QMainWindow& window)
{
    const QScreen* screen = window.screen() ? window.screen() : QGuiApplication::primaryScreen();
    if (!screen) {
        window.resize(kDefaultWindowSize);
        return;
    }
    const QRect available = screen->availableGeometry();
    // Room for the title bar and borders a window manager adds around the window.
    const QSize frame(16, 48);
    if (available.width() >= kDefaultWindowSize.width() + frame.width()
        && available.height() >= kDefaultWindowSize.height() + frame.height()) {
        window.resize(kDefaultWindowSize);
        window.move(available.topLeft()
            + QPoint((available.width() - kDefaultWindowSize.width() - frame.width()) / 2,
                (available.height() - kDefaultWindowSize.height() - frame.height()) / 2));
        return;
    }
    // Without a window manager to honour the maximised state, the size alone fits the screen.
    window.setGeometry(QRect(available.topLeft(), available.size() - frame).intersected(available));
    window.setWindowState(window.windowState() | Qt::WindowMaximized);
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
    routeToolKeys(this, m_viewport);
    auto* hint = new FirstStepsHint(m_document, m_viewport);
    m_viewport->setMinimumSize(320, 240);
    setCentralWidget(m_viewport);

    createDocks();
    connect(m_scene, &views::ScenePanel::selectionChanged, hint, [hint](views::ScenePanel::Selection selection) {
        hint->setSelectedDrawing(selection.kind == views::ScenePanel::ItemKind::Drawing ? selection.id : 0);
    });
    createActions();
    createMenus();
    installAnimationActions(this); // Timeline dock, playback, shot camera, Observer layout
    installSubdivisionActions(this); // View: control mesh, smooth surface, cage; the level's note

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
    if (m_mode == Mode::Batch)
        resize(kDefaultWindowSize);
    else if (!settings.contains(QStringLiteral("window/geometry")))
        fitFirstWindowToScreen(*this);
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
    connect(m_properties, &views::PropertiesPanel::keyCreated, this, [this](model::ObjectId key) {
        m_scene->select({views::ScenePanel::ItemKind::Key, key});
        statusBar()->showMessage(tr("Key created: select Edit Key with the Brush to deform it"), 8000);
    });
    connect(m_properties, &views::PropertiesPanel::importDeformationRequested, this,
        &MainWindow::importKeyDeformationDialog);
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
    makeDock(tr("Highlights"), QStringLiteral("highlightsDock"), highlights, Qt::RightDockWidgetArea);
    tabifyDockWidget(
        findChild<QDockWidget*>(QStringLiteral("lookDock")), findChild<QDockWidget*>(QStringLiteral("highlightsDock")));
    // Stereo depth analysis (paper 3, chapter 4): overlays, segment ratios and the depth error.
    m_depth = new views::DepthPanel(m_document, m_viewport, this);
    connectToolPanels(*m_viewport, *m_properties, *highlights, *m_depth);
    m_properties->setViewport(m_viewport);
    highlights->setViewport(m_viewport);
    makeDock(tr("Depth"), QStringLiteral("depthDock"), m_depth, Qt::RightDockWidgetArea);
    tabifyDockWidget(findChild<QDockWidget*>(QStringLiteral("highlightsDock")),
        findChild<QDockWidget*>(QStringLiteral("depthDock")));
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
    m_scene->setDrawingOverlay(&m_viewport->drawingOverlay());
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("sceneDock")),
                    findChild<QDockWidget*>(QStringLiteral("propertiesDock"))},
        {260, 300}, Qt::Horizontal);
}

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

std::function<void(const QString&)> MainWindow::shownError()
{
    return [this](const QString& message) { showError(message); };
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
    auto outcome = runWithProgress<model::ProjectData>(this, tr("Opening %1…").arg(QFileInfo(path).fileName()),
        shownError(), [path] { return model::loadProject(path); });
    if (!outcome)
        return false;
    m_document->reset(std::move(*outcome), QFileInfo(path).absoluteFilePath());
    addRecentFile(path);
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    log(LogLevel::Info, tr("Opened %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool MainWindow::importMesh(const QString& path, bool asNewProject)
{
    if (asNewProject && !maybeSave())
        return false;
    // An animated glTF/GLB (skins, morph targets) or a "walk_####.obj" pattern: the base moves
    // (paper 1, section 4.1), and the scene takes the animation's frames and rate.
    if (model::opensAsAnimatedBase(path)) {
        auto animated = runWithProgress<model::AnimatedImport>(this, tr("Reading %1…").arg(QFileInfo(path).fileName()),
            shownError(), [path] { return model::readAnimatedBase(path); });
        if (!animated)
            return false;
        const QString name = QFileInfo(path).fileName();
        const int frames = std::max(1, animated->animation.frameCount);
        const double fps = animated->fps;
        const QStringList warnings = animated->warnings; // a sequence's missing numbers
        if (asNewProject) {
            model::ProjectData data = model::newAnimatedProject(std::move(*animated), name);
            data.look.style = Preferences::load().newProjectStyle; // Edit > Preferences
            m_document->reset(std::move(data));
        } else {
            try {
                m_document->animation().setAnimatedBase(std::move(*animated), name);
            } catch (const model::IoError& e) {
                showError(e.message());
                return false;
            } catch (const model::EditRefused& e) {
                showError(QStringLiteral("%1: %2").arg(name, e.message()));
                return false;
            }
        }
        statusBar()->showMessage(
            tr("Loaded %1: an animated base, %n frame(s) at %2 fps", nullptr, frames).arg(name).arg(fps), 8000);
        showWarnings(path, warnings); // logged, and in the status bar over the line above
        return true;
    }
    auto outcome = runWithProgress<model::MeshImport>(this, tr("Reading %1…").arg(QFileInfo(path).fileName()),
        shownError(), [path] { return model::importMesh(path); });
    if (!outcome)
        return false;
    auto mesh = std::make_shared<const algo::TriMesh>(std::move(outcome->mesh));
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
    showWarnings(path, outcome->warnings);
    if (outcome->warnings.isEmpty())
        statusBar()->showMessage(tr("Loaded %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::importDrawing(const QString& path)
{
    auto outcome = runWithProgress<model::Drawing>(this, tr("Reading %1…").arg(QFileInfo(path).fileName()),
        shownError(), [path] { return model::importDrawing(path); });
    if (!outcome)
        return false;
    const auto id = m_document->drawings().addDrawing(std::move(*outcome));
    m_scene->select({views::ScenePanel::ItemKind::Drawing, id});
    statusBar()->showMessage(tr("Added drawing %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::importKeyDeformation(model::ObjectId key, const QString& path)
{
    auto outcome = runWithProgress<model::MeshImport>(this, tr("Reading %1…").arg(QFileInfo(path).fileName()),
        shownError(), [path] { return model::importMesh(path); });
    if (!outcome)
        return false;
    try {
        // At the playhead (issue 26): a new keyed frame there, or the one stored there replaced.
        showWarnings(path, m_document->keys().importKeyDeformation(key, *outcome, path, m_document->currentFrame()));
    } catch (const model::IoError& e) {
        showError(e.message());
        return false;
    }
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

void MainWindow::importKeyDeformationDialog(model::ObjectId key)
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Key Deformation"), {}, model::meshFileFilter());
    if (!path.isEmpty())
        importKeyDeformation(key, path);
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
