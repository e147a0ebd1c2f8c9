// The editor window: viewport in the centre, scene / properties / history docks, menus, status
// bar, file handling (open, save, recent files, drag and drop) and autosave with recovery.
#pragma once

#include "celform/algorithms/stereo.h"
#include "celform/model/document/document.h"

#include <QMainWindow>
#include <QPointer>

#include <functional>

class QAction;
class QLabel;
class QMenu;
class QPlainTextEdit;
class QUndoView;

namespace celform::views {
class Viewport;
class ScenePanel;
class PropertiesPanel;
class ViewSpherePanel;
class LookPanel;
class DepthPanel;
} // namespace celform::views

namespace celform::app {

class RecoveryManager;
class JobRunner;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Batch mode never asks questions (screenshots, tests): no recovery prompt, no dialogs.
    enum class Mode { Interactive, Batch };

    explicit MainWindow(Mode mode = Mode::Interactive, QWidget* parent = nullptr);
    ~MainWindow() override;

    [[nodiscard]] Mode mode() const { return m_mode; }
    [[nodiscard]] model::Document* document() const { return m_document; }
    [[nodiscard]] views::Viewport* viewport() const { return m_viewport; }
    [[nodiscard]] views::ScenePanel* scenePanel() const { return m_scene; }
    [[nodiscard]] views::DepthPanel* depthPanel() const { return m_depth; }
    [[nodiscard]] views::PropertiesPanel* propertiesPanel() const { return m_properties; }
    [[nodiscard]] views::Viewport* observer() const { return m_observer; }
    [[nodiscard]] RecoveryManager* recovery() const { return m_recovery; }
    /// The action with the given object name (tests and shortcuts), or null.
    [[nodiscard]] QAction* action(const QString& name) const;

    /// Opens a project, or starts a new project on a mesh, or adds a drawing, by file type.
    /// Errors are shown (interactive) or logged (batch); returns success.
    bool openFile(const QString& path);
    /// Renders once and saves a PNG of the whole window.
    bool saveScreenshot(const QString& path);
    bool save();
    bool saveAs(const QString& path = {});
    /// Reads a mesh as a job (JobRunner, as every import) and makes it a key's deformation at
    /// the playhead's frame, replacing one stored there (one undo step); Properties > Import Deformation asks for the
    /// file. Errors are shown (interactive) or logged (batch); returns success.
    bool importKeyDeformation(model::ObjectId key, const QString& path);
    /// An error in the Log, the status bar and (interactive mode) a message box.
    void showError(const QString& message);

public slots:
    /// Offers the recovery files of crashed sessions (interactive mode only).
    void offerRecovery();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void updateTitle();
    void updateRecentMenu();
    void addRecentFile(const QString& path);
    enum class LogLevel { Info, Warning, Error };
    /// Appends to the Log dock; warnings and errors also go to the process log (stderr).
    void log(LogLevel level, const QString& message);
    /// showError as a function, for the file jobs.
    [[nodiscard]] std::function<void(const QString&)> shownError();
    void showWarnings(const QString& file, const QStringList& warnings);
    bool maybeSave();
    bool openProject(const QString& path);
    bool importMesh(const QString& path, bool asNewProject);
    bool importDrawing(const QString& path);
    void newFromMeshDialog();
    void openDialog();
    void importMeshDialog();
    void importDrawingDialog();
    void importKeyDeformationDialog(model::ObjectId key);
    void updateStatistics();
    void processDropQueue();
    /// Optimise Light for Stereo through the viewport's camera at the Depth tab's analysis size.
    void optimiseLightForStereo();
    /// Look > Optimise Light Along Shot (issue 26): a light track over the scene's frames.
    void optimiseLightAlongShot();

    Mode m_mode;
    model::Document* m_document;
    views::Viewport* m_viewport = nullptr;
    views::ScenePanel* m_scene = nullptr;
    views::PropertiesPanel* m_properties = nullptr;
    views::ViewSpherePanel* m_sphere = nullptr;
    views::LookPanel* m_look = nullptr;
    views::DepthPanel* m_depth = nullptr;
    views::Viewport* m_observer = nullptr;
    QUndoView* m_history = nullptr;
    RecoveryManager* m_recovery = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    algo::StereoOutput m_lastStereo = algo::StereoOutput::Anaglyph; ///< what Ctrl+3 turns on
    QLabel* m_statistics = nullptr;
    QPlainTextEdit* m_log = nullptr;
    QStringList m_dropQueue;
    bool m_processingDrops = false;
    QPointer<JobRunner> m_lightRunner;
    QPointer<JobRunner> m_lightTrackRunner;
};

} // namespace celform::app
