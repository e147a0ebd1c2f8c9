// The editor's dialogs as a user drives them, under Xvfb: File > Render Image and Render Sequence
// (a picture of the right size, Cancel between frames, errors naming the file), Help > Keyboard
// Shortcuts (every key listed, the filter) and Edit > Preferences (applied to the live window,
// stored, conflicts reported). Settings live in QStandardPaths' test location.
#include "test_support.h"
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"
#include "editor/settings/preferences.h"
#include "editor/dialogs/preferences_dialog.h"
#include "editor/recovery_manager.h"
#include "editor/dialogs/render_dialog.h"
#include "editor/jobs/job_runner.h"
#include "editor/review_window.h"
#include "editor/settings/shortcuts.h"
#include "editor/dialogs/shortcuts_dialog.h"

#include "celform/model/document/document.h"
#include "celform/model/io/project_file.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/viewport/viewport_display.h"
#include "celform/views/viewport/viewport_keys.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>

using namespace celform;

namespace {

/// Catches QDesktopServices::openUrl for file URLs, so a test run opens no viewer.
class UrlCatcher : public QObject {
    Q_OBJECT
public:
    QList<QUrl> urls;
public slots:
    void open(const QUrl& url) { urls << url; }
};

/// Share of sampled pixels that differ clearly from the top-left corner (the background).
double coverage(const QImage& image)
{
    const QImage img = image.convertToFormat(QImage::Format_RGB32);
    const QRgb bg = img.pixel(0, 0);
    qint64 differing = 0, total = 0;
    for (int y = 0; y < img.height(); y += 2)
        for (int x = 0; x < img.width(); x += 2, ++total) {
            const QRgb p = img.pixel(x, y);
            if (std::abs(qRed(p) - qRed(bg)) + std::abs(qGreen(p) - qGreen(bg)) + std::abs(qBlue(p) - qBlue(bg)) > 60)
                ++differing;
        }
    return total ? double(differing) / double(total) : 0.0;
}

template <typename T> T* child(QObject* parent, const char* name)
{
    return parent->findChild<T*>(QString::fromLatin1(name));
}

/// An action as the shortcuts dialog lists it: "Save As: Ctrl+Shift+S".
QString entryText(const QAction* action)
{
    QStringList keys;
    for (const QKeySequence& key : action->shortcuts())
        keys << key.toString(QKeySequence::NativeText);
    return app::actionName(action) + QStringLiteral(": ") + keys.join(QStringLiteral(", "));
}

QPushButton* okButton(QDialog* dialog)
{
    return dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
}

/// `celform render` of the sample as the dialog renders it with the framed default view at 160x120,
/// with extra options, into out; whether it succeeded.
bool renderWithTheCommandLine(const QStringList& extra, const QString& out)
{
    QProcess cli;
    cli.start(QStringLiteral(CELFORM_EXECUTABLE),
        QStringList{QStringLiteral("render"), test::sampleProject(), QStringLiteral("--view"),
            QStringLiteral("0.35,0.25,1"), QStringLiteral("--size"), QStringLiteral("160x120")}
            + extra + QStringList{QStringLiteral("--out"), out});
    return cli.waitForFinished(120000) && cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0;
}

/// Opens the render dialog of kind through its File menu action and sets output and size.
app::RenderDialog* openRenderDialog(app::MainWindow& window, const char* actionName, const QString& output, QSize size)
{
    window.action(QString::fromLatin1(actionName))->trigger();
    auto* dialog = window.findChild<app::RenderDialog*>();
    if (!dialog || !dialog->isVisible())
        return nullptr;
    child<QLineEdit>(dialog, "renderOutput")->setText(output);
    child<QSpinBox>(dialog, "renderWidth")->setValue(size.width());
    child<QSpinBox>(dialog, "renderHeight")->setValue(size.height());
    return dialog;
}

/// Render Image set as renderWithTheCommandLine renders (the framed default view, 160x120) into
/// output, not opened when done.
app::RenderDialog* openDefaultViewImage(app::MainWindow& window, const QString& output)
{
    auto* dialog = openRenderDialog(window, "actionRenderImage", output, {160, 120});
    if (!dialog)
        return nullptr;
    child<QCheckBox>(dialog, "renderOpenWhenDone")->setChecked(false);
    auto* camera = child<QComboBox>(dialog, "renderCamera");
    camera->setCurrentIndex(camera->findData(QStringLiteral("default")));
    return dialog;
}

/// Clicks Render and waits for the job runner: whether the job finished and succeeded.
bool renderAndWait(app::MainWindow& window, app::RenderDialog* dialog)
{
    okButton(dialog)->click();
    auto* runner = window.findChild<app::JobRunner*>();
    if (!runner)
        return false;
    QSignalSpy finished(runner, &app::JobRunner::finished);
    return finished.wait(120000) && finished.at(0).at(0).toBool();
}

/// Opens Edit > Preferences.
app::PreferencesDialog* openPreferences(app::MainWindow& window)
{
    window.action(QStringLiteral("actionPreferences"))->trigger();
    auto* dialog = window.findChild<app::PreferencesDialog*>();
    return dialog && QTest::qWaitForWindowExposed(dialog) ? dialog : nullptr;
}

void choose(QComboBox* combo, int data)
{
    combo->setCurrentIndex(combo->findData(data));
}

/// The file names in a folder, hidden ones (temporary files) included.
QStringList filesIn(const QString& folder)
{
    return QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

class TestEditorDialogs : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QDesktopServices::setUrlHandler(QStringLiteral("file"), &m_opened, "open");
    }
    void cleanupTestCase() { QDesktopServices::unsetUrlHandler(QStringLiteral("file")); }
    void init()
    {
        QSettings().clear();
        m_opened.urls.clear();
    }

    // --- File > Render Image / Render Sequence -------------------------------------------------

    void rendersAnImageAndOpensIt()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("still.png"));
        auto* dialog = openRenderDialog(window, "actionRenderImage", path, QSize(240, 180));
        QVERIFY(dialog);
        QCOMPARE(dialog->windowTitle(), QStringLiteral("Render Image"));
        QVERIFY2(dialog->problem().isEmpty(), qPrintable(dialog->problem()));
        QVERIFY(child<QCheckBox>(dialog, "renderOpenWhenDone")->isChecked());
        QVERIFY(child<QLabel>(dialog, "renderFiles")->text().contains(QStringLiteral("still.png")));
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        test::keepScreenshot(dialog, "render-dialog");
        okButton(dialog)->click();

        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QVERIFY(runner->progressDialog() && runner->progressDialog()->isVisible());
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);

        const QImage image(path);
        QVERIFY2(!image.isNull(), "the render wrote no readable PNG");
        QCOMPARE(image.size(), QSize(240, 180));
        QVERIFY2(coverage(image) > 0.05, "the render is blank");
        // Opened when done (caught here instead of starting a viewer).
        QCOMPARE(m_opened.urls, QList<QUrl>{QUrl::fromLocalFile(path)});
        QCOMPARE(filesIn(dir.path()), QStringList{QStringLiteral("still.png")});

        // The options are remembered for the next render.
        window.action(QStringLiteral("actionRenderImage"))->trigger();
        auto* again = window.findChild<app::RenderDialog*>();
        QVERIFY(again);
        QCOMPARE(child<QSpinBox>(again, "renderWidth")->value(), 240);
        QCOMPARE(QFileInfo(child<QLineEdit>(again, "renderOutput")->text()).absolutePath(), dir.path());
        again->reject();
    }

    void rendersTheSameAsTheCommandLine()
    {
        // The dialog and `celform render` go through model::renderFrames: the same picture.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        auto* dialog = openDefaultViewImage(window, dir.filePath(QStringLiteral("gui.png")));
        QVERIFY(dialog);
        QVERIFY(renderAndWait(window, dialog));
        QVERIFY(m_opened.urls.isEmpty());

        QVERIFY(renderWithTheCommandLine({}, dir.filePath(QStringLiteral("cli.png"))));
        const QImage gui(dir.filePath(QStringLiteral("gui.png"))), fromCli(dir.filePath(QStringLiteral("cli.png")));
        QVERIFY(!gui.isNull() && !fromCli.isNull());
        QCOMPARE(gui.convertToFormat(QImage::Format_RGBA8888), fromCli.convertToFormat(QImage::Format_RGBA8888));
    }

    void writesVectorLinesAsTheCommandLine()
    {
        // Issue 28: an .svg output from the dialog is the lines pass as strokes, with the tone
        // regions when asked, byte for byte what `celform render --out F.svg --svg-tones` writes.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        auto* dialog = openDefaultViewImage(window, dir.filePath(QStringLiteral("gui.svg")));
        QVERIFY(dialog);
        auto* pass = child<QComboBox>(dialog, "renderPass");
        QCOMPARE(pass->currentData().toString(), QStringLiteral("lines"));
        QVERIFY(!pass->isEnabled());
        auto* tones = child<QCheckBox>(dialog, "renderSvgTones");
        QVERIFY(tones->isEnabled());
        tones->setChecked(true);
        auto* stereo = child<QComboBox>(dialog, "renderStereo");
        stereo->setCurrentIndex(stereo->findData(int(algo::StereoOutput::Dubois)));
        QVERIFY(!dialog->problem().isEmpty()); // one group of strokes per eye: no Dubois mix
        stereo->setCurrentIndex(stereo->findData(int(algo::StereoOutput::Off)));
        QVERIFY2(dialog->problem().isEmpty(), qPrintable(dialog->problem()));
        QVERIFY(renderAndWait(window, dialog));

        QVERIFY(
            renderWithTheCommandLine({QStringLiteral("--pass"), QStringLiteral("lines"), QStringLiteral("--svg-tones")},
                dir.filePath(QStringLiteral("cli.svg"))));
        QFile gui(dir.filePath(QStringLiteral("gui.svg"))), fromCli(dir.filePath(QStringLiteral("cli.svg")));
        QVERIFY(gui.open(QIODevice::ReadOnly) && fromCli.open(QIODevice::ReadOnly));
        const QByteArray svg = gui.readAll();
        QVERIFY(svg.contains("<path"));
        QCOMPARE(svg, fromCli.readAll());
    }

    void cancelsASequenceBetweenFrames()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        auto* dialog = openRenderDialog(
            window, "actionRenderSequence", dir.filePath(QStringLiteral("shot_####.png")), QSize(1280, 960));
        QVERIFY(dialog);
        QCOMPARE(dialog->windowTitle(), QStringLiteral("Render Sequence"));
        child<QSpinBox>(dialog, "renderFirstFrame")->setValue(0);
        child<QSpinBox>(dialog, "renderLastFrame")->setValue(2);
        QVERIFY(child<QLabel>(dialog, "renderFiles")->text().contains(QStringLiteral("shot_0002.png")));
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        test::keepScreenshot(dialog, "render-sequence-dialog");
        okButton(dialog)->click();

        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QProgressDialog* progress = runner->progressDialog();
        QVERIFY(progress);
        QCOMPARE(progress->maximum(), 3);
        QVERIFY(QTest::qWaitForWindowExposed(progress));
        test::keepScreenshot(progress, "render-progress");
        // The user presses Cancel once the first frame is written. The frames are large enough
        // (1280x960) that the next one is still rendering when the click arrives: at 160x120 the
        // writer thread let the whole sequence finish first now and then.
        int valueAtCancel = -1;
        connect(runner, &app::JobRunner::progressed, this, [&](qint64 done, qint64) {
            if (done != 1) // frame 0 written
                return;
            valueAtCancel = progress->value();
            auto* cancel = progress->findChild<QPushButton*>();
            QVERIFY(cancel);
            cancel->click();
        });
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(valueAtCancel, 1);
        // The frame written before Cancel stays; nothing after it, no temporary files.
        QCOMPARE(filesIn(dir.path()), QStringList{QStringLiteral("shot_0000.png")});
        QCOMPARE(QImage(dir.filePath(QStringLiteral("shot_0000.png"))).size(), QSize(1280, 960));
        QVERIFY(m_opened.urls.isEmpty());
    }

    void reportsAWriteErrorNamingTheFile()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        // Frame 1's file name is taken by a folder: frame 0 is written, frame 1 fails.
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("bad_0001.png")));
        auto* dialog
            = openRenderDialog(window, "actionRenderSequence", dir.filePath(QStringLiteral("bad_####.png")), {64, 48});
        QVERIFY(dialog);
        child<QSpinBox>(dialog, "renderFirstFrame")->setValue(0);
        child<QSpinBox>(dialog, "renderLastFrame")->setValue(2);
        okButton(dialog)->click();
        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QSignalSpy failed(runner, &app::JobRunner::failed);
        QVERIFY(failed.wait(120000));
        QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("bad_0001.png")),
            qPrintable(failed.at(0).at(0).toString()));
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("renderErrorBox"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        QVERIFY(box->informativeText().contains(QStringLiteral("bad_0001.png")));
        QVERIFY(box->informativeText().contains(QStringLiteral("kept (1)")));
        test::keepScreenshot(box, "render-error");
        box->accept();
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("bad_0000.png"))).isFile());
        QVERIFY(m_opened.urls.isEmpty());
    }

    void refusesWhatCannotBeRendered()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        auto* dialog = openRenderDialog(window, "actionRenderImage", dir.filePath(QStringLiteral("x.gif")), {64, 48});
        QVERIFY(dialog);
        auto* problem = child<QLabel>(dialog, "renderProblem");
        QVERIFY(problem->isVisible());
        QVERIFY(problem->text().contains(QStringLiteral("x.gif")));
        QVERIFY(!okButton(dialog)->isEnabled());
        child<QLineEdit>(dialog, "renderOutput")->setText(dir.filePath(QStringLiteral("missing/x.png")));
        QVERIFY(problem->text().contains(QStringLiteral("missing")));
        child<QLineEdit>(dialog, "renderOutput")->setText(dir.filePath(QStringLiteral("x.png")));
        QVERIFY(!problem->isVisible());
        QVERIFY(okButton(dialog)->isEnabled());
        // Every pass at once needs an EXR; stereo writes the beauty.
        auto* pass = child<QComboBox>(dialog, "renderPass");
        pass->setCurrentIndex(pass->findData(QString()));
        QCOMPARE(pass->currentData().toString(), QStringLiteral("beauty"));
        auto* stereo = child<QComboBox>(dialog, "renderStereo");
        stereo->setCurrentIndex(1);
        QVERIFY(!pass->isEnabled());
        dialog->reject();

        // Without a base model there is nothing to render.
        app::MainWindow empty(app::MainWindow::Mode::Batch);
        QVERIFY(!empty.action(QStringLiteral("actionRenderImage"))->isEnabled());
        QVERIFY(!empty.action(QStringLiteral("actionRenderSequence"))->isEnabled());
    }

    // --- Help > Keyboard Shortcuts ---------------------------------------------------------------

    void shortcutsDialogListsAndFilters()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        window.action(QStringLiteral("actionKeyboardShortcuts"))->trigger();
        auto* dialog = window.findChild<app::ShortcutsDialog*>();
        QVERIFY(dialog);
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        const QStringList all = dialog->visibleEntries();
        const QString saveAs = QStringLiteral("Save As: ")
            + QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S).toString(QKeySequence::NativeText);
        QVERIFY2(all.contains(saveAs), qPrintable(all.join(QStringLiteral("\n"))));
        // Every action with keys and every fixed key is listed: brush size, P, Ctrl+K, Esc, F11.
        for (QAction* action : app::shortcutActions(&window))
            if (!action->shortcut().isEmpty())
                QVERIFY2(all.contains(entryText(action)), qPrintable(entryText(action)));
        for (const char* expected :
            {"Brush radius larger (× 1.25): ]", "Brush radius smaller (× 0.8): [", "Preview View-Dependent Shape: P",
                "Create Key from View: Ctrl+K", "Navigate Only: Esc", "Stereo Review: F11", "Turntable on / off: Space",
                "Resize the brush with the mouse (click or Enter keeps, Esc cancels): F"})
            QVERIFY2(all.contains(QString::fromUtf8(expected)), expected);

        test::keepScreenshot(dialog, "shortcuts");
        QTest::keyClicks(dialog->filterEdit(), QStringLiteral("save"));
        test::keepScreenshot(dialog, "shortcuts-filtered");
        const QStringList saves = dialog->visibleEntries();
        QVERIFY(saves.contains(saveAs));
        QVERIFY(saves.size() < all.size());
        QVERIFY(!saves.contains(QStringLiteral("Frame All: F")));
        QVERIFY(saves.contains(entryText(window.action(QStringLiteral("actionSave")))));
        // Keys are found by their text too.
        dialog->filterEdit()->setText(QStringLiteral("ctrl+shift+s"));
        QCOMPARE(dialog->visibleEntries(), QStringList{saveAs});
        dialog->filterEdit()->setText(QStringLiteral("no such command"));
        QCOMPARE(dialog->visibleCount(), 0);
        dialog->filterEdit()->clear();
        QCOMPARE(dialog->visibleEntries(), all);
    }

    void actionNamesDropMnemonicsAndEllipses()
    {
        QAction action(QStringLiteral("Save &As…"));
        QCOMPARE(app::actionName(&action), QStringLiteral("Save As"));
        action.setText(QStringLiteral("Fish && &Chips..."));
        QCOMPARE(app::actionName(&action), QStringLiteral("Fish & Chips"));
        // Japanese menus put the mnemonic in brackets after the text.
        action.setText(QStringLiteral("名前を付けて保存(&A)…"));
        QCOMPARE(app::actionName(&action), QStringLiteral("名前を付けて保存"));
    }

    void viewportKeysAreTheTablesKeys()
    {
        // The viewport's keyPressEvent and the help read one table: each key does what it says.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        views::Viewport* vp = window.viewport();
        const double radius = vp->tool<views::BrushTool>().size().radius();
        for (const views::ViewportKeyBinding& binding : views::viewportKeyBindings()) {
            if (binding.command != views::ViewportKeyCommand::BrushLarger)
                continue;
            QKeyEvent press(QEvent::KeyPress, binding.key, Qt::NoModifier);
            QApplication::sendEvent(vp, &press);
        }
        QCOMPARE(vp->tool<views::BrushTool>().size().radius(), radius * 1.25);
        // The review's keys: S steps the stereo mode, as its table says.
        app::ReviewWindow review(window.document(), vp->camera());
        const auto before = review.viewport()->display().stereo();
        QKeyEvent s(QEvent::KeyPress, Qt::Key_S, Qt::NoModifier);
        QApplication::sendEvent(review.viewport(), &s);
        QCOMPARE(review.viewport()->display().stereo(), app::ReviewWindow::nextOutput(before));
    }

    // --- Edit > Preferences ----------------------------------------------------------------------

    void preferencesApplyToTheLiveWindowAndAreStored()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QUndoStack* stack = window.document()->undoStack();
        QCOMPARE(stack->count(), 0);
        // The defaults: Maya navigation, turntable orbit, no undo limit.
        QCOMPARE(window.viewport()->navigation().style, views::NavigationStyle::Maya);
        QCOMPARE(window.viewport()->navigation().orbitMode, views::OrbitMode::Turntable);

        auto* dialog = openPreferences(window);
        QVERIFY(dialog);
        test::keepScreenshot(dialog, "preferences");
        choose(child<QComboBox>(dialog, "prefNavigationStyle"), int(views::NavigationStyle::Blender));
        choose(child<QComboBox>(dialog, "prefOrbitMode"), int(views::OrbitMode::Trackball));
        child<QDoubleSpinBox>(dialog, "prefOrbitSpeed")->setValue(2.0);
        child<QCheckBox>(dialog, "prefOrbitAroundCursor")->setChecked(true);
        dialog->tabs()->setCurrentIndex(1);
        test::keepScreenshot(dialog, "preferences-general");
        child<QSpinBox>(dialog, "prefAutosave")->setValue(7);
        child<QSpinBox>(dialog, "prefUndoLimit")->setValue(50);
        dialog->tabs()->setCurrentIndex(2);
        const QKeySequence newKey(Qt::CTRL | Qt::ALT | Qt::Key_S);
        dialog->shortcutEdit(QStringLiteral("actionSaveAs"))->setKeySequence(newKey);
        QVERIFY(dialog->conflicts().isEmpty());
        test::keepScreenshot(dialog, "preferences-shortcuts");
        okButton(dialog)->click();
        QVERIFY(!dialog->isVisible());

        // Stored...
        QSettings settings;
        QCOMPARE(settings.value(QStringLiteral("navigation/style")).toString(), QStringLiteral("blender"));
        QCOMPARE(settings.value(QStringLiteral("navigation/orbitMode")).toString(), QStringLiteral("trackball"));
        QCOMPARE(settings.value(QStringLiteral("navigation/orbitSpeed")).toDouble(), 2.0);
        QCOMPARE(settings.value(QStringLiteral("autosave/minutes")).toInt(), 7);
        QCOMPARE(settings.value(QStringLiteral("editing/undoLimit")).toInt(), 50);
        QCOMPARE(settings.value(QStringLiteral("shortcuts/actionSaveAs")).toString(), QStringLiteral("Ctrl+Alt+S"));
        // Keys left at their default are not stored (a new default would reach the user).
        QVERIFY(!settings.contains(QStringLiteral("shortcuts/actionSave")));

        // ... and applied to the live window: both viewports, the history, the action.
        for (views::Viewport* vp : {window.viewport(), window.observer()}) {
            QCOMPARE(vp->navigation().style, views::NavigationStyle::Blender);
            QCOMPARE(vp->navigation().orbitMode, views::OrbitMode::Trackball);
            QCOMPARE(vp->navigation().orbitSpeed, 2.0);
            QVERIFY(vp->navigation().orbitAroundCursor);
        }
        QCOMPARE(stack->undoLimit(), 50);
        QCOMPARE(window.action(QStringLiteral("actionSaveAs"))->shortcut(), newKey);
        // A batch window (screenshots, tests) never autosaves, whatever the preference.
        QCOMPARE(window.recovery()->interval(), 0);

        // The new key works, the old one no longer does.
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QSignalSpy saveAs(window.action(QStringLiteral("actionSaveAs")), &QAction::triggered);
        QTest::keyClick(&window, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(saveAs.count(), 1);
        QTest::keyClick(&window, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(saveAs.count(), 1);

        // Help > Keyboard Shortcuts shows the user's key.
        window.action(QStringLiteral("actionKeyboardShortcuts"))->trigger();
        auto* shortcuts = window.findChild<app::ShortcutsDialog*>();
        QVERIFY(shortcuts);
        QVERIFY(shortcuts->visibleEntries().contains(
            QStringLiteral("Save As: ") + newKey.toString(QKeySequence::NativeText)));
        shortcuts->close();

        // The stereo review, opened later, navigates the same way.
        window.action(QStringLiteral("actionStereoReview"))->trigger();
        auto* review = window.findChild<app::ReviewWindow*>();
        QVERIFY(review);
        QTRY_VERIFY(review->isVisible());
        QCOMPARE(review->viewport()->navigation().orbitMode, views::OrbitMode::Trackball);
        QCOMPARE(review->viewport()->navigation().style, views::NavigationStyle::Blender);
        review->close();

        // The next start applies them (a new window reads the stored preferences).
        app::MainWindow next(app::MainWindow::Mode::Batch);
        QCOMPARE(next.action(QStringLiteral("actionSaveAs"))->shortcut(), newKey);
        QCOMPARE(next.viewport()->navigation().orbitMode, views::OrbitMode::Trackball);
        QCOMPARE(next.document()->undoStack()->undoLimit(), 50);

        // Restore Defaults and OK put everything back.
        dialog = openPreferences(window);
        QVERIFY(dialog);
        dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::RestoreDefaults)->click();
        okButton(dialog)->click();
        QCOMPARE(
            window.action(QStringLiteral("actionSaveAs"))->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
        QCOMPARE(window.viewport()->navigation().orbitMode, views::OrbitMode::Turntable);
        QCOMPARE(stack->undoLimit(), 0);
        QVERIFY(!QSettings().contains(QStringLiteral("shortcuts/actionSaveAs")));
    }

    void undoLimitWaitsForAnEmptyHistory()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QUndoStack* stack = window.document()->undoStack();
        window.document()->look().setSharpness(2.0);
        QCOMPARE(stack->count(), 1);
        auto* dialog = openPreferences(window);
        QVERIFY(dialog);
        child<QSpinBox>(dialog, "prefUndoLimit")->setValue(5);
        QVERIFY(child<QLabel>(dialog, "prefUndoNote")->text().contains(QStringLiteral("next empty")));
        okButton(dialog)->click();
        // QUndoStack takes a limit only while empty: the step stays, the limit waits.
        QCOMPARE(stack->count(), 1);
        QCOMPARE(stack->undoLimit(), 0);
        QVERIFY(window.openFile(test::sampleProject()));
        QCOMPARE(stack->count(), 0);
        QCOMPARE(stack->undoLimit(), 5);
        for (int i = 0; i < 8; ++i)
            window.document()->look().setSharpness(1.5 + 0.1 * i);
        QCOMPARE(stack->count(), 5);
    }

    void conflictingShortcutIsReported()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        auto* dialog = openPreferences(window);
        QVERIFY(dialog);
        dialog->tabs()->setCurrentIndex(2);
        auto* conflicts = child<QLabel>(dialog, "prefConflicts");
        QVERIFY(conflicts->isHidden());
        // The key list filters like Help > Keyboard Shortcuts.
        auto* tree = child<QTreeWidget>(dialog, "prefShortcutTree");
        child<QLineEdit>(dialog, "prefShortcutFilter")->setText(QStringLiteral("render"));
        QStringList shown;
        for (QTreeWidgetItemIterator it(tree, QTreeWidgetItemIterator::NotHidden | QTreeWidgetItemIterator::NoChildren);
             *it; ++it)
            shown << (*it)->text(0);
        QVERIFY2(shown.contains(QStringLiteral("Render Image")) && shown.contains(QStringLiteral("Render Sequence")),
            qPrintable(shown.join(QStringLiteral(", "))));
        QVERIFY(!shown.contains(QStringLiteral("Save")));
        child<QLineEdit>(dialog, "prefShortcutFilter")->clear();
        // Render Image gets Save's key.
        QKeySequenceEdit* render = dialog->shortcutEdit(QStringLiteral("actionRenderImage"));
        QVERIFY(render);
        render->setKeySequence(QKeySequence(Qt::CTRL | Qt::Key_S));
        QCOMPARE(dialog->conflicts().size(), 1);
        QVERIFY(dialog->conflicts().constFirst().contains(QStringLiteral("“Save”")));
        QVERIFY(dialog->conflicts().constFirst().contains(QStringLiteral("“Render Image”")));
        QVERIFY(conflicts->isVisible());
        QVERIFY(conflicts->text().contains(QStringLiteral("Render Image")));
        QVERIFY(!okButton(dialog)->isEnabled());
        test::keepScreenshot(dialog, "preferences-conflict");
        // OK is refused: nothing is stored or applied.
        dialog->accept();
        QVERIFY(dialog->isVisible());
        QVERIFY(!QSettings().contains(QStringLiteral("shortcuts/actionRenderImage")));
        QCOMPARE(window.action(QStringLiteral("actionRenderImage"))->shortcut(), QKeySequence(Qt::Key_F12));

        // A key the viewport keeps (brush size) is a note, not a conflict.
        render->setKeySequence(QKeySequence(Qt::Key_BracketRight));
        QVERIFY(dialog->conflicts().isEmpty());
        QVERIFY(conflicts->text().contains(QStringLiteral("viewport")));
        QVERIFY(okButton(dialog)->isEnabled());

        // Tab leaves a key editor instead of becoming the key (keyboard use of the page).
        render->setKeySequence(QKeySequence(Qt::Key_F12));
        QVERIFY(QTest::qWaitForWindowActive(dialog));
        render->setFocus();
        QVERIFY(render->hasFocus());
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QVERIFY(!render->hasFocus());
        QCOMPARE(render->keySequence(), QKeySequence(Qt::Key_F12));
        dialog->reject();
    }

    void languageAppliesAtTheNextStart()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        auto* dialog = openPreferences(window);
        QVERIFY(dialog);
        dialog->tabs()->setCurrentIndex(1);
        auto* note = child<QLabel>(dialog, "prefLanguageNote");
        QVERIFY(!note->text().contains(QStringLiteral("Restart")));
        choose(child<QComboBox>(dialog, "prefLanguage"), int(app::Preferences::Language::Japanese));
        QVERIFY(note->text().contains(QStringLiteral("Restart")));
        okButton(dialog)->click();
        QCOMPARE(QSettings().value(QStringLiteral("ui/language")).toString(), QStringLiteral("ja"));
        QCOMPARE(app::Preferences::load().locale().language(), QLocale::Japanese);
        // Not live: the menus keep their language until the next start.
        QCOMPARE(window.action(QStringLiteral("actionSave"))->text(), QStringLiteral("&Save"));
    }

    // Under a desktop that takes Alt + drag, the Maya style's help says to choose Blender.
    void preferencesWarnOfDesktopsThatTakeAlt()
    {
        const QByteArray saved = qgetenv("XDG_CURRENT_DESKTOP");
        qputenv("XDG_CURRENT_DESKTOP", "GNOME");
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        auto* dialog = openPreferences(window);
        QVERIFY(dialog);
        choose(child<QComboBox>(dialog, "prefNavigationStyle"), int(views::NavigationStyle::Maya));
        const QString maya = child<QLabel>(dialog, "prefNavigationHelp")->text();
        QVERIFY2(maya.contains(QStringLiteral("GNOME")) && maya.contains(QStringLiteral("Blender")), qPrintable(maya));
        choose(child<QComboBox>(dialog, "prefNavigationStyle"), int(views::NavigationStyle::Blender));
        QVERIFY(!child<QLabel>(dialog, "prefNavigationHelp")->text().contains(QStringLiteral("GNOME")));
        dialog->reject();
        if (saved.isNull())
            qunsetenv("XDG_CURRENT_DESKTOP");
        else
            qputenv("XDG_CURRENT_DESKTOP", saved);
    }

    void newProjectsStartWithTheChosenStyle()
    {
        app::Preferences prefs;
        prefs.newProjectStyle = model::ShadingStyle::Gooch;
        prefs.save();
        QTemporaryDir dir;
        const QString mesh = dir.filePath(QStringLiteral("tetra.obj"));
        QFile file(mesh);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
        file.close();
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(window.openFile(mesh));
        QCOMPARE(window.document()->data().look.style, model::ShadingStyle::Gooch);
        // An opened project keeps its own look.
        QVERIFY(window.openFile(test::sampleProject()));
        QCOMPARE(window.document()->data().look.style, model::loadProject(test::sampleProject()).look.style);
    }

private:
    UrlCatcher m_opened;
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    app.setOrganizationName(QStringLiteral("CelformTest"));
    app.setApplicationName(QStringLiteral("CelformTestEditorDialogs"));
    TestEditorDialogs test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_editor_dialogs.moc"
