// The editor's dialogs as a user drives them, under Xvfb: File > Render Image and Render Sequence
// (a picture of the right size, Cancel between frames, errors naming the file), Help > Keyboard
// Shortcuts (every key listed, the filter) and Edit > Preferences (applied to the live window,
// stored, conflicts reported). Settings live in QStandardPaths' test location.
#include "test_support.h"
#include "ui_test_support.h"
#include "window_test_support.h"

#include "main_window.h"
#include "recovery.h"
#include "render_dialog.h"
#include "render_runner.h"
#include "review_window.h"
#include "shortcuts.h"
#include "shortcuts_dialog.h"

#include "celform/model/document.h"
#include "celform/views/viewport.h"
#include "celform/views/viewport_keys.h"

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

        auto* runner = window.findChild<app::RenderRunner*>();
        QVERIFY(runner);
        QVERIFY(runner->progressDialog() && runner->progressDialog()->isVisible());
        QSignalSpy finished(runner, &app::RenderRunner::finished);
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
        auto* dialog
            = openRenderDialog(window, "actionRenderImage", dir.filePath(QStringLiteral("gui.png")), {160, 120});
        QVERIFY(dialog);
        child<QCheckBox>(dialog, "renderOpenWhenDone")->setChecked(false);
        auto* camera = child<QComboBox>(dialog, "renderCamera");
        camera->setCurrentIndex(camera->findData(QStringLiteral("default")));
        okButton(dialog)->click();
        auto* runner = window.findChild<app::RenderRunner*>();
        QVERIFY(runner);
        QSignalSpy finished(runner, &app::RenderRunner::finished);
        QVERIFY(finished.wait(120000));
        QVERIFY(m_opened.urls.isEmpty());

        QProcess cli;
        cli.start(QStringLiteral(CELFORM_EXECUTABLE),
            {QStringLiteral("render"), test::sampleProject(), QStringLiteral("--view"), QStringLiteral("0.35,0.25,1"),
                QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--out"),
                dir.filePath(QStringLiteral("cli.png"))});
        QVERIFY(cli.waitForFinished(120000));
        QCOMPARE(cli.exitCode(), 0);
        const QImage gui(dir.filePath(QStringLiteral("gui.png"))), fromCli(dir.filePath(QStringLiteral("cli.png")));
        QVERIFY(!gui.isNull() && !fromCli.isNull());
        QCOMPARE(gui.convertToFormat(QImage::Format_RGBA8888), fromCli.convertToFormat(QImage::Format_RGBA8888));
    }

    void cancelsASequenceBetweenFrames()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        auto* dialog = openRenderDialog(
            window, "actionRenderSequence", dir.filePath(QStringLiteral("shot_####.png")), QSize(160, 120));
        QVERIFY(dialog);
        QCOMPARE(dialog->windowTitle(), QStringLiteral("Render Sequence"));
        child<QSpinBox>(dialog, "renderFirstFrame")->setValue(0);
        child<QSpinBox>(dialog, "renderLastFrame")->setValue(2);
        QVERIFY(child<QLabel>(dialog, "renderFiles")->text().contains(QStringLiteral("shot_0002.png")));
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        test::keepScreenshot(dialog, "render-sequence-dialog");
        okButton(dialog)->click();

        auto* runner = window.findChild<app::RenderRunner*>();
        QVERIFY(runner);
        QProgressDialog* progress = runner->progressDialog();
        QVERIFY(progress);
        QCOMPARE(progress->maximum(), 3);
        QVERIFY(QTest::qWaitForWindowExposed(progress));
        test::keepScreenshot(progress, "render-progress");
        // The user presses Cancel once the first frame is written.
        int valueAtCancel = -1;
        connect(runner, &app::RenderRunner::frameWritten, this, [&](int frame, const QString&) {
            if (frame != 0)
                return;
            valueAtCancel = progress->value();
            auto* cancel = progress->findChild<QPushButton*>();
            QVERIFY(cancel);
            cancel->click();
        });
        QSignalSpy finished(runner, &app::RenderRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(valueAtCancel, 1);
        // The frame written before Cancel stays; nothing after it, no temporary files.
        QCOMPARE(filesIn(dir.path()), QStringList{QStringLiteral("shot_0000.png")});
        QCOMPARE(QImage(dir.filePath(QStringLiteral("shot_0000.png"))).size(), QSize(160, 120));
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
        auto* runner = window.findChild<app::RenderRunner*>();
        QVERIFY(runner);
        QSignalSpy failed(runner, &app::RenderRunner::failed);
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
        for (const char* expected : {"Brush radius larger (× 1.25): ]", "Brush radius smaller (× 0.8): [",
                 "Preview View-Dependent Shape: P", "Create Key from View: Ctrl+K", "Navigate Only: Esc",
                 "Stereo Review: F11", "Turntable on / off: Space"})
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

    void viewportKeysAreTheTablesKeys()
    {
        // The viewport's keyPressEvent and the help read one table: each key does what it says.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        views::Viewport* vp = window.viewport();
        const double radius = vp->brushRadius();
        for (const views::ViewportKeyBinding& binding : views::viewportKeyBindings()) {
            if (binding.command != views::ViewportKeyCommand::BrushLarger)
                continue;
            QKeyEvent press(QEvent::KeyPress, binding.key, Qt::NoModifier);
            QApplication::sendEvent(vp, &press);
        }
        QCOMPARE(vp->brushRadius(), radius * 1.25);
        // The review's keys: S steps the stereo mode, as its table says.
        app::ReviewWindow review(window.document(), vp->camera());
        const auto before = review.viewport()->stereo();
        QKeyEvent s(QEvent::KeyPress, Qt::Key_S, Qt::NoModifier);
        QApplication::sendEvent(review.viewport(), &s);
        QCOMPARE(review.viewport()->stereo(), app::ReviewWindow::nextOutput(before));
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
