// File > Export… as a user drives it, under Xvfb: the dialog's defaults (the
// project's frame range), an export to PC2 on the worker thread checked byte for byte, Cancel
// leaving no file behind, and a write error shown in a message box naming the file.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/dialogs/export_dialog.h"
#include "editor/jobs/job_runner.h"
#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/document/document.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <cstring>

using namespace celform;

namespace {

/// Opens File > Export… and fills it in.
app::ExportDialog* openExportDialog(
    app::MainWindow& window, model::ExportFormat format, int first, int last, const QString& file)
{
    window.action(QStringLiteral("actionExport"))->trigger();
    auto* dialog = window.findChild<app::ExportDialog*>();
    if (!dialog || !dialog->isVisible())
        return nullptr;
    dialog->formatBox()->setCurrentIndex(dialog->formatBox()->findData(int(format)));
    dialog->firstFrameBox()->setValue(first);
    dialog->lastFrameBox()->setValue(last);
    dialog->fileEdit()->setText(file);
    return dialog;
}

QPushButton* exportButton(app::ExportDialog* dialog)
{
    return dialog->findChild<QPushButton*>(QStringLiteral("exportButton"));
}

QStringList filesIn(const QString& folder)
{
    return QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

class TestExportDialog : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void menuAndShortcut()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QAction* action = window.action(QStringLiteral("actionExport"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
        QVERIFY(action->isEnabled());
        // In the File menu, with the render actions.
        QMenu* file = app::menuOf(window.action(QStringLiteral("actionQuit")));
        QVERIFY(file && file->actions().contains(action));
        // No other action of the window has the same keys.
        for (QAction* other : window.findChildren<QAction*>())
            if (other != action)
                QVERIFY2(!other->shortcuts().contains(action->shortcut()), qPrintable(other->objectName()));
    }

    // A label with a mnemonic and no buddy shows its '&' as text ("F&rames:").
    void labelsFocusTheirFields()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        app::ExportDialog* dialog
            = openExportDialog(window, model::ExportFormat::Pc2, 0, 1, QDir::temp().filePath(QStringLiteral("x.pc2")));
        QVERIFY(dialog);
        int mnemonics = 0;
        for (QLabel* label : dialog->findChildren<QLabel*>()) {
            if (!label->text().contains(QLatin1Char('&')))
                continue;
            ++mnemonics;
            QVERIFY2(label->buddy(), qPrintable(label->text()));
        }
        QVERIFY(mnemonics >= 3);
        QCOMPARE(dialog->findChild<QLabel*>(QStringLiteral("exportFramesLabel"))->buddy(), dialog->firstFrameBox());
        QCOMPARE(dialog->findChild<QLabel*>(QStringLiteral("exportFileLabel"))->buddy(), dialog->fileEdit());
        dialog->reject();
    }

    void exportsAPointCache()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        const model::SceneTime time = window.document()->data().time;
        window.action(QStringLiteral("actionExport"))->trigger();
        auto* dialog = window.findChild<app::ExportDialog*>();
        QVERIFY(dialog);
        // The project's range by default.
        QCOMPARE(dialog->firstFrameBox()->value(), time.firstFrame);
        QCOMPARE(dialog->lastFrameBox()->value(), time.lastFrame);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("shot.pc2"));
        dialog->formatBox()->setCurrentIndex(dialog->formatBox()->findData(int(model::ExportFormat::Pc2)));
        dialog->firstFrameBox()->setValue(2);
        dialog->lastFrameBox()->setValue(9);
        dialog->fileEdit()->setText(path);
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        test::keepScreenshot(dialog, "export-dialog");
        exportButton(dialog)->click();

        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QVERIFY(runner->progressDialog());
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);

        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        const auto vertices = std::int32_t(window.document()->data().baseMesh->vertexCount());
        QCOMPARE(bytes.size(), 32 + qint64(8) * vertices * 12);
        QCOMPARE(bytes.left(12), QByteArray("POINTCACHE2\0", 12));
        std::int32_t version = 0, points = 0, samples = 0;
        float start = 0;
        std::memcpy(&version, bytes.constData() + 12, 4);
        std::memcpy(&points, bytes.constData() + 16, 4);
        std::memcpy(&start, bytes.constData() + 20, 4);
        std::memcpy(&samples, bytes.constData() + 28, 4);
        QCOMPARE(version, 1);
        QCOMPARE(points, vertices);
        QCOMPARE(start, 2.0f);
        QCOMPARE(samples, 8);
        QCOMPARE(filesIn(dir.path()), QStringList{QStringLiteral("shot.pc2")});
    }

    void exportsAUsdLayerWithBlendShapes()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        // The sample with its two keys.
        QVERIFY(window.openFile(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform")));
        QCOMPARE(window.document()->data().keys.size(), std::size_t(2));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("shot.usda"));
        auto* dialog = openExportDialog(window, model::ExportFormat::Pc2, 0, 1, path);
        QVERIFY(dialog);
        QVERIFY(!dialog->blendShapesBox()->isEnabled()); // USD only
        dialog->formatBox()->setCurrentIndex(dialog->formatBox()->findData(int(model::ExportFormat::Usda)));
        QVERIFY(dialog->blendShapesBox()->isEnabled());
        QCOMPARE(dialog->fileEdit()->text(), QDir::toNativeSeparators(path));
        dialog->blendShapesBox()->click();
        exportButton(dialog)->click();
        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.startsWith("#usda 1.0\n"));
        for (const char* part : {"endTimeCode = 1", "point3f[] points.timeSamples", "def Camera \"camera\"",
                 "def SkelAnimation \"weights\"", "def BlendShape"})
            QVERIFY2(text.contains(part), part);
        // Only the layer is left (the atomic write's temporary file is gone).
        QCOMPARE(filesIn(dir.path()), QStringList{QStringLiteral("shot.usda")});
    }

    void cancelLeavesNoFile()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        // Many frames, so Cancel comes long before the end.
        auto* dialog
            = openExportDialog(window, model::ExportFormat::Glb, 0, 200000, dir.filePath(QStringLiteral("long.glb")));
        QVERIFY(dialog);
        exportButton(dialog)->click();
        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QProgressDialog* progress = runner->progressDialog();
        QVERIFY(progress);
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 0, 60000);
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel);
        cancel->click();
        QVERIFY(finished.count() > 0 || finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(filesIn(dir.path()), QStringList{});
    }

    void reportsAWriteErrorNamingTheFile()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        const QString path = QStringLiteral("/nonexistent-folder/shot.pc2");
        auto* dialog = openExportDialog(window, model::ExportFormat::Pc2, 0, 3, path);
        QVERIFY(dialog);
        exportButton(dialog)->click();
        auto* runner = window.findChild<app::JobRunner*>();
        QVERIFY(runner);
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("exportErrorBox"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        QVERIFY2(box->informativeText().contains(path), qPrintable(box->informativeText()));
        box->close();
    }

    void refusesASuffixUnlikeTheFormat()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir;
        auto* dialog = openExportDialog(window, model::ExportFormat::Pc2, 0, 3, dir.filePath(QStringLiteral("x.pc2")));
        QVERIFY(dialog);
        // Choosing another format renames the file's suffix.
        dialog->formatBox()->setCurrentIndex(dialog->formatBox()->findData(int(model::ExportFormat::Glb)));
        QVERIFY(dialog->fileEdit()->text().endsWith(QStringLiteral("x.glb")));
        dialog->fileEdit()->setText(dir.filePath(QStringLiteral("x.obj")));
        // The refusal is a message box on top of the dialog: close it when it shows.
        QTimer::singleShot(0, this, [] {
            QTRY_VERIFY(
                QApplication::activeModalWidget() && qobject_cast<QMessageBox*>(QApplication::activeModalWidget()));
            QApplication::activeModalWidget()->close();
        });
        exportButton(dialog)->click();
        QVERIFY(dialog->isVisible());
        QVERIFY(!window.findChild<app::JobRunner*>());
    }
};

QTEST_MAIN(TestExportDialog)
#include "test_export_dialog.moc"
