// Every edit made in the editor is its own undo step with its own text (DESIGN.md, "The document":
// a command merges only with the next one of the same property on the same target in the same
// gesture). Driven through the real window under Xvfb, as an artist would: a style change, a lines
// toggle, a light drag, "Set Render Camera", sharpness and the unspecified mode.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"

#include "celform/model/document/document.h"
#include "celform/views/panels/look_panel.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_display.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QUndoStack>

using namespace celform;

class TestUndoSteps : public QObject {
    Q_OBJECT

    /// The texts of the undo stack's steps from index `from` on.
    static QStringList stepTexts(const QUndoStack* stack, int from)
    {
        QStringList texts;
        for (int i = from; i < stack->count(); ++i)
            texts << stack->text(i);
        return texts;
    }

    /// The Look dock raised, and its panel.
    static views::LookPanel* raisedLookPanel(app::MainWindow& window)
    {
        window.findChild<QDockWidget*>(QStringLiteral("lookDock"))->raise();
        return window.findChild<views::LookPanel*>();
    }

    /// The Look panel's spin box whose tool tip starts with tip, or null.
    static QDoubleSpinBox* spinWithTip(const views::LookPanel* look, const char* tip)
    {
        for (auto* spin : look->findChildren<QDoubleSpinBox*>())
            if (spin->toolTip().startsWith(QLatin1String(tip)))
                return spin;
        return nullptr;
    }

private slots:
    void unrelatedEditsAreSeparateSteps()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        views::Viewport* viewport = window.viewport();
        QUndoStack* stack = doc->undoStack();
        const int start = stack->count();
        test::waitForRender(viewport);

        // 1. The shading style, in the Look dock.
        window.findChild<QDockWidget*>(QStringLiteral("lookDock"))->raise();
        auto* look = window.findChild<views::LookPanel*>();
        QVERIFY(look);
        QComboBox* style = look->styleBox();
        const int gooch = style->findText(QStringLiteral("Gooch warm/cool"));
        QVERIFY(gooch >= 0);
        style->setCurrentIndex(gooch);
        emit style->activated(gooch);
        QCOMPARE(doc->data().look.style, model::ShadingStyle::Gooch);

        // 2. Lines off.
        QGroupBox* lines = nullptr;
        for (auto* box : look->findChildren<QGroupBox*>())
            if (box->isCheckable())
                lines = box;
        QVERIFY(lines);
        lines->setChecked(false);
        QVERIFY(!doc->data().look.showLines);

        // 3. A drag of the light gizmo (Ctrl+drag on its handle).
        viewport->display().setLightGizmoVisible(true);
        test::waitForRender(viewport);
        const Eigen::Vector3d lightBefore = doc->data().look.light.vector;
        const QPoint handle = viewport->projectToWidget(viewport->display().lightGizmoHandle()).toPoint();
        QVERIFY(viewport->rect().contains(handle));
        test::drag(viewport, Qt::LeftButton, Qt::ControlModifier, handle, handle + QPoint(-40, 25), 8);
        QVERIFY((doc->data().look.light.vector - lightBefore).norm() > 0.05);

        // 4. The render camera from the view.
        QAction* setRenderCamera = window.findChild<QAction*>(QStringLiteral("actionSetRenderCamera"));
        QVERIFY(setRenderCamera);
        setRenderCamera->trigger();
        QVERIFY(doc->data().look.renderCamera.has_value());

        // 5. Sharpness held up with the keyboard, then the unspecified mode.
        window.findChild<QDockWidget*>(QStringLiteral("propertiesDock"))->raise();
        QDoubleSpinBox* sharpness = nullptr;
        for (auto* spin : window.findChildren<QDoubleSpinBox*>())
            if (spin->toolTip().startsWith(QStringLiteral("Sharpness")))
                sharpness = spin;
        QVERIFY(sharpness);
        celform::test::holdKey(sharpness, Qt::Key_Up, 3);
        QVERIFY(doc->data().blend.sharpness > 1.3);
        QComboBox* unspecified = nullptr;
        for (auto* combo : window.findChildren<QComboBox*>())
            if (combo->findText(QStringLiteral("Cosine falloff")) >= 0)
                unspecified = combo;
        QVERIFY(unspecified);
        unspecified->setCurrentIndex(unspecified->findText(QStringLiteral("Cosine falloff")));
        QCOMPARE(doc->data().blend.unspecified, model::UnspecifiedMode::Cosine);

        // Six edits, six steps, each named after what it did.
        const QStringList texts = stepTexts(stack, start);
        QCOMPARE(texts,
            (QStringList{QStringLiteral("Change Shading Style"), QStringLiteral("Hide Lines"),
                QStringLiteral("Move Light"), QStringLiteral("Set Render Camera"),
                QStringLiteral("Change Blend Sharpness"), QStringLiteral("Change Unspecified Regions")}));

        // Ctrl+Z takes back one edit at a time, from anywhere in the window.
        auto undo = [&] {
            window.findChild<QAction*>(QStringLiteral("actionUndo"))->trigger();
            QApplication::processEvents();
        };
        undo();
        QCOMPARE(doc->data().blend.unspecified, model::UnspecifiedMode::Dummy);
        QVERIFY(doc->data().blend.sharpness > 1.3);
        undo();
        QCOMPARE(doc->data().blend.sharpness, 1.0); // the whole hold at once
        undo();
        QVERIFY(!doc->data().look.renderCamera.has_value());
        QVERIFY((doc->data().look.light.vector - lightBefore).norm() > 0.05);
        undo();
        QVERIFY((doc->data().look.light.vector - lightBefore).norm() < 1e-12); // the whole drag at once
        QVERIFY(!doc->data().look.showLines);
        undo();
        QVERIFY(doc->data().look.showLines);
        QCOMPARE(doc->data().look.style, model::ShadingStyle::Gooch);
        undo();
        QCOMPARE(doc->data().look.style, model::ShadingStyle::Toon);
        QCOMPARE(stack->index(), start);
    }

    void ridgeControlsAreOneStepEach()
    {
        // The Look panel's apparent-ridge controls: the checkbox is one step, a held key on the
        // threshold is one step, and undo restores what the file had.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        QUndoStack* stack = doc->undoStack();
        const int start = stack->count();
        auto* look = raisedLookPanel(window);
        QVERIFY(look);
        QCheckBox* ridges = nullptr;
        for (auto* check : look->findChildren<QCheckBox*>())
            if (check->text() == QStringLiteral("Apparent ridges"))
                ridges = check;
        QVERIFY(ridges);
        QVERIFY(!ridges->isChecked());
        QDoubleSpinBox* threshold = spinWithTip(look, "Apparent ridges are drawn");
        QVERIFY(threshold);
        QVERIFY(!threshold->isEnabled()); // until ridges are on
        const algo::LineSettings before = doc->data().look.lines;
        ridges->click();
        QVERIFY(doc->data().look.lines.ridges);
        QVERIFY(threshold->isEnabled());
        celform::test::holdKey(threshold, Qt::Key_Up, 3);
        QVERIFY(doc->data().look.lines.ridgeThreshold > before.ridgeThreshold + 0.1f);
        QCOMPARE(stack->count() - start, 2);
        stack->undo();
        QVERIFY(doc->data().look.lines.ridges);
        QCOMPARE(doc->data().look.lines.ridgeThreshold, before.ridgeThreshold);
        stack->undo();
        QVERIFY(doc->data().look.lines == before);
        QVERIFY(!ridges->isChecked());
    }

    void strokeCleanUpControlsAreOneStepEach()
    {
        // Issue 25's line controls in the Look panel: a held key on the taper, the minimum length
        // and the crease hysteresis is one step each, and undo restores the file's values.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        QUndoStack* stack = doc->undoStack();
        const int start = stack->count();
        auto* look = raisedLookPanel(window);
        QVERIFY(look);
        QDoubleSpinBox* taper = spinWithTip(look, "Length over which strokes thin");
        QDoubleSpinBox* minLength = spinWithTip(look, "Strokes shorter than this");
        QDoubleSpinBox* low = spinWithTip(look, "Hysteresis:");
        QVERIFY(taper && minLength && low);
        const algo::LineStyle style = doc->data().look.lineStyle;
        const algo::LineSettings settings = doc->data().look.lines;
        QCOMPARE(taper->value(), double(style.taper));
        QVERIFY(std::abs(minLength->value() - 100.0 * double(style.minLength)) < 1e-4);
        celform::test::holdKey(taper, Qt::Key_Up, 3);
        QVERIFY(doc->data().look.lineStyle.taper > style.taper);
        celform::test::holdKey(minLength, Qt::Key_Down, 2);
        QVERIFY(doc->data().look.lineStyle.minLength < style.minLength);
        celform::test::holdKey(low, Qt::Key_Down, 2);
        QVERIFY(doc->data().look.lines.creaseLowAngleDegrees < settings.creaseLowAngleDegrees);
        QCOMPARE(stack->count() - start, 3);
        stack->undo();
        QVERIFY(doc->data().look.lines == settings);
        stack->undo();
        stack->undo();
        QVERIFY(doc->data().look.lineStyle == style);
        QCOMPARE(taper->value(), double(style.taper));
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestUndoSteps test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_undo_steps.moc"
