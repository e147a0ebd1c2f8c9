// Recovery after a crash, under Xvfb. An editor with unsaved edits autosaves and is
// killed with SIGKILL (a child process: this test binary run with --editor-child); the next launch
// offers the recovery copy, and the user's answers decide: "Keep for Later" and a discard they do
// not confirm keep it, "Recover" brings the edits back (and a second crash before the next
// autosave still knows the original file), and only a confirmed discard deletes it. Autosave also
// catches edits that merge into the step it last saved (a slider still moving, a brush stroke).
//
// test_main_window covers the autosave copy itself, orphan detection with a hand-made stale lock,
// and saving removing the copy.
#include "test_support.h"
#include "ui_test_support.h"

#include "editor/main_window.h"
#include "editor/recovery_manager.h"

#include "celform/model/io/project_file.h"
#include "celform/views/viewport/viewport.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QMessageBox>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <deque>

using namespace celform;

namespace {

/// The edits the child makes before its autosave, made again here to know what to expect.
void editBeforeAutosave(model::Document& doc)
{
    doc.drawings().renameDrawing(doc.data().drawings.front().id, QStringLiteral("recovered drawing"));
    doc.look().setSharpness(3.25);
    doc.highlights().addHighlightLayer(QStringLiteral("recovered layer"), 0);
}

/// The child: an editor window that opens the project, edits it, autosaves, edits once more (an
/// edit the crash loses), prints its recovery file and waits to be killed.
int editorChild(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    QCoreApplication::setApplicationName(QString::fromLocal8Bit(argv[2]));
    QStandardPaths::setTestModeEnabled(true);
    app::MainWindow window(app::MainWindow::Mode::Batch);
    if (!window.openFile(QString::fromLocal8Bit(argv[3])))
        return 2;
    editBeforeAutosave(*window.document());
    if (!window.recovery()->autosaveNow())
        return 3;
    window.document()->look().setSharpness(4.5);
    std::printf("%s\n", qPrintable(window.recovery()->ownRecoveryFile()));
    std::fflush(stdout);
    return QApplication::exec();
}

/// Answers the message boxes the code under test opens, in order: for each, clicks its button
/// of the given role. A box beyond the list is closed and counted as unexpected.
class DialogAnswers : public QObject {
public:
    explicit DialogAnswers(std::deque<QMessageBox::ButtonRole> roles)
        : m_roles(std::move(roles))
    {
        connect(&m_timer, &QTimer::timeout, this, &DialogAnswers::poll);
        m_timer.start(20);
    }
    [[nodiscard]] int unexpected() const { return m_unexpected; }
    [[nodiscard]] bool allAnswered() const { return m_roles.empty(); }

private:
    void poll()
    {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box || box == m_last)
            return;
        if (m_roles.empty()) {
            ++m_unexpected;
            box->reject();
            return;
        }
        const QMessageBox::ButtonRole role = m_roles.front();
        for (QAbstractButton* button : box->buttons())
            if (box->buttonRole(button) == role) {
                m_roles.pop_front();
                m_last = box;
                button->click();
                return;
            }
        ++m_unexpected; // no such button
        box->reject();
    }

    std::deque<QMessageBox::ButtonRole> m_roles;
    QTimer m_timer;
    QPointer<QMessageBox> m_last;
    int m_unexpected = 0;
};

QString recoveryDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/recovery");
}

QStringList recoveryFiles()
{
    return QDir(recoveryDirectory()).entryList({QStringLiteral("session-*.celform")}, QDir::Files);
}

} // namespace

class TestRecovery : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_project; ///< a copy of the bundled sample
    model::ProjectData m_expected; ///< the project with the edits made before the autosave

    /// Offers recovery in a new editor window (a new launch) and answers with roles.
    bool launchAndAnswer(app::MainWindow& window, std::deque<QMessageBox::ButtonRole> roles)
    {
        DialogAnswers answers(std::move(roles));
        window.offerRecovery();
        return answers.allAnswered() && answers.unexpected() == 0;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QDir(recoveryDirectory()).removeRecursively();
        m_project = m_dir.filePath(QStringLiteral("elephant.celform"));
        QVERIFY(QFile::copy(test::sampleProject(), m_project));
        model::Document doc;
        doc.open(m_project);
        editBeforeAutosave(doc);
        m_expected = doc.data();
    }

    void cleanupTestCase()
    {
        // Everything under this run's own application name.
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).removeRecursively();
        QFile::remove(QSettings().fileName());
    }

    void autosaveCatchesMergedEdits()
    {
        // A slider still moving after an autosave, and a brush stroke going on after one, change
        // the step on top of the history rather than add one; the next autosave still has them.
        QTemporaryDir dir;
        model::Document doc;
        doc.open(m_project);
        app::RecoveryManager recovery(&doc, dir.path());
        model::Gesture g1 = doc.beginGesture();
        doc.look().setSharpness(2.0, g1);
        QVERIFY(recovery.autosaveNow());
        doc.look().setSharpness(2.5, g1); // merges into the step autosaved above
        QVERIFY(recovery.autosaveNow());
        g1.end();
        QCOMPARE(model::loadProject(recovery.ownRecoveryFile()).blend.sharpness, 2.5);

        model::Camera camera;
        camera.eye = doc.data().baseMesh->centre() + Eigen::Vector3d(0, 0, 10);
        camera.target = doc.data().baseMesh->centre();
        const model::ObjectId key = doc.keys().createKey(QStringLiteral("front"), camera);
        model::BrushStroke stroke = doc.keys().beginBrushStroke(key, 0, 0, 0.0, camera);
        doc.keys().applyBrushStroke(stroke, {model::BrushMotion::Drag, 0.01, 0.0});
        QVERIFY(recovery.autosaveNow());
        doc.keys().applyBrushStroke(stroke, {model::BrushMotion::Drag, 0.01, 0.0});
        doc.keys().endBrushStroke(stroke);
        QVERIFY(recovery.autosaveNow());
        model::ProjectData recovered = model::loadProject(recovery.ownRecoveryFile());
        QVERIFY2(recovered == doc.data(), "the recovery copy misses the end of the brush stroke");
    }

    void killedEditorIsOfferedAndRecovered()
    {
        // The crash: an editor process killed after its autosave.
        QProcess child;
        child.setProcessChannelMode(QProcess::SeparateChannels);
        child.start(QCoreApplication::applicationFilePath(),
            {QStringLiteral("--editor-child"), QCoreApplication::applicationName(), m_project});
        QVERIFY(child.waitForStarted(10000));
        QVERIFY2(child.waitForReadyRead(60000), qPrintable(QString::fromLocal8Bit(child.readAllStandardError())));
        const QString recoveryFile = QString::fromLocal8Bit(child.readLine()).trimmed();
        QVERIFY(QFileInfo::exists(recoveryFile));
        child.kill(); // SIGKILL: no clean shutdown, the lock stays behind with a dead pid
        QVERIFY(child.waitForFinished(10000));
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);
        QCOMPARE(recoveryFiles().size(), 1);
        {
            const model::ProjectData autosaved = model::loadProject(recoveryFile);
            QVERIFY2(autosaved == m_expected, "the autosave does not hold the edits made before it");
        }

        // Next launch: "Keep for Later" keeps the copy, also through a clean session of its own.
        {
            app::MainWindow window(app::MainWindow::Mode::Interactive);
            QVERIFY(launchAndAnswer(window, {QMessageBox::RejectRole}));
            QVERIFY(!window.document()->hasMesh());
            QVERIFY(window.openFile(m_project));
            window.close(); // a clean exit removes the session's own copy only
        }
        QVERIFY(QFileInfo::exists(recoveryFile));

        // Next launch: "Discard…", then "No" at the confirmation, keeps it.
        {
            app::MainWindow window(app::MainWindow::Mode::Interactive);
            QVERIFY(launchAndAnswer(window, {QMessageBox::DestructiveRole, QMessageBox::NoRole}));
        }
        QVERIFY(QFileInfo::exists(recoveryFile));

        // Next launch: "Recover" brings back the edits made before the autosave, as unsaved work
        // on the original file; the copy becomes the session's own.
        auto window = std::make_unique<app::MainWindow>(app::MainWindow::Mode::Interactive);
        QVERIFY(launchAndAnswer(*window, {QMessageBox::AcceptRole}));
        QVERIFY2(window->document()->data() == m_expected, "the recovered project is not the autosaved one");
        QVERIFY(window->document()->isModified());
        QCOMPARE(window->document()->filePath(), QFileInfo(m_project).absoluteFilePath());
        QCOMPARE(recoveryFiles().size(), 1);
        QVERIFY(QFileInfo::exists(window->recovery()->ownRecoveryFile()));

        // That session crashes too before its next autosave (the window goes without closing, the
        // lock is released as by a dead process): the copy is offered again, still naming the
        // original file.
        const QString adopted = window->recovery()->ownRecoveryFile();
        window.reset();
        QVERIFY(QFileInfo::exists(adopted));
        window = std::make_unique<app::MainWindow>(app::MainWindow::Mode::Interactive);
        const auto orphans = window->recovery()->orphans();
        QCOMPARE(orphans.size(), std::size_t(1));
        QCOMPARE(orphans.front().originalFile, QFileInfo(m_project).absoluteFilePath());
        QVERIFY(launchAndAnswer(*window, {QMessageBox::AcceptRole}));
        QVERIFY(window->document()->data() == m_expected);
        QCOMPARE(window->document()->filePath(), QFileInfo(m_project).absoluteFilePath());
        window.reset();

        // Only a confirmed discard deletes it.
        {
            app::MainWindow last(app::MainWindow::Mode::Interactive);
            QVERIFY(launchAndAnswer(last, {QMessageBox::DestructiveRole, QMessageBox::YesRole}));
            QVERIFY(last.recovery()->orphans().empty());
        }
        QVERIFY(recoveryFiles().isEmpty());
    }
};

int main(int argc, char** argv)
{
    if (argc >= 4 && qstrcmp(argv[1], "--editor-child") == 0)
        return editorChild(argc, argv);
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    // A name of its own per run: the recovery folder and settings are not shared with other
    // test runs (test mode puts them under ~/.qttest).
    QCoreApplication::setApplicationName(
        QStringLiteral("CelformRecoveryTest-%1").arg(QCoreApplication::applicationPid()));
    TestRecovery test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_recovery.moc"
