// Helper of the editor-window tests (tests/app): the main window shown with the bundled sample.
#pragma once

#include "ui_test_support.h"

#include "editor/main_window.h"

#include <QApplication>

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

} // namespace celform::test
