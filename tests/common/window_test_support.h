// Helper of the editor-window tests (tests/app): the main window shown with the bundled sample.
#pragma once

#include "ui_test_support.h"

#include "editor/main_window.h"
#include "celform/views/panels/fit_group.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"

#include <QApplication>
#include <QDockWidget>
#include <QSignalSpy>
#include <QTreeWidget>

#include <optional>

namespace celform::test {

/// Resizes and shows a window, waits until it is on screen and opens the bundled sample in it;
/// false when either fails (use as QVERIFY(showSample(window))).
inline bool showSample(app::MainWindow& window, const QSize& size = QSize(1400, 900))
{
    window.resize(size);
    window.show();
    return QTest::qWaitForWindowExposed(&window) && window.openFile(sampleProject());
}

/// showSample, then makes the window the active one (keyboard shortcuts reach it); false when
/// any step fails.
inline bool showActive(app::MainWindow& window)
{
    if (!showSample(window))
        return false;
    window.activateWindow();
    QApplication::setActiveWindow(&window);
    QApplication::processEvents();
    return QApplication::activeWindow() == &window;
}

/// Clicks the Scene tree's row named `name`, as the artist does; false when there is none.
inline bool clickSceneItem(app::MainWindow& window, const QString& name)
{
    QTreeWidget* tree = window.scenePanel()->tree();
    const QList<QTreeWidgetItem*> items = tree->findItems(name, Qt::MatchExactly | Qt::MatchRecursive);
    if (items.isEmpty())
        return false;
    tree->scrollToItem(items.front());
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, tree->visualItemRect(items.front()).center());
    QApplication::processEvents();
    return true;
}

/// Brings the dock holding a panel forward (its tab, when tabbed), as an artist would.
inline void raiseDockOf(QWidget* panel)
{
    for (QWidget* w = panel; w; w = w->parentWidget())
        if (auto* dock = qobject_cast<QDockWidget*>(w)) {
            dock->raise();
            return;
        }
}

/// The selected key's live fit figures (Properties > Fit to Drawing) once the panel has measured
/// them after the last edit.
inline std::optional<algo::FitMetrics> fitFigures(app::MainWindow& window)
{
    views::FitGroup* group = window.propertiesPanel()->fitGroup();
    QSignalSpy measured(group, &views::FitGroup::measured);
    measured.wait(3000);
    return group->metrics();
}

} // namespace celform::test
