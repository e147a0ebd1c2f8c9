// View ▸ Control Mesh, Smooth Surface, Show Control Cage and the status-bar note
// (subdivision_actions.h).
#include "editor/actions/subdivision_actions.h"

#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_display.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QStatusBar>

namespace celform::app {
namespace {

struct SubdivisionText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::SubdivisionActions)
};

/// The note for the status bar, empty when the viewport shows the render level in full.
QString subdivisionNote(const views::ViewportDisplay::Subdivision& s, bool smooth)
{
    if (!smooth && s.viewportLevel > 0)
        return SubdivisionText::tr("Control mesh shown (3: smooth surface, level %1)").arg(s.viewportLevel);
    if (s.capped)
        return SubdivisionText::tr("Viewport subdivision capped at level %1 of %2: %3 triangles")
            .arg(s.level)
            .arg(s.viewportLevel)
            .arg(QLocale().toString(qlonglong(s.triangles)));
    if (s.viewportLevel != s.renderLevel)
        return SubdivisionText::tr("Viewport subdivision level %1 (renders use level %2)")
            .arg(s.viewportLevel)
            .arg(s.renderLevel);
    return {};
}

} // namespace

void installSubdivisionActions(MainWindow* window)
{
    views::Viewport* viewport = window->viewport();
    auto* note = new QLabel(window);
    note->setObjectName(QStringLiteral("subdivisionStatus"));
    note->setToolTip(SubdivisionText::tr("The subdivision level the viewport shows (Look dock, Smooth surface)"));
    note->hide();
    window->statusBar()->addPermanentWidget(note);
    auto updateNote = [viewport, note] {
        const views::ViewportDisplay& display = viewport->display();
        const QString text = subdivisionNote(display.subdivision(), display.smoothShown());
        note->setText(text);
        note->setVisible(!text.isEmpty());
    };

    // Maya's display keys: 1 the control mesh, 3 the smooth surface, 2 the cage over it.
    auto* group = new QActionGroup(window);
    QAction* cage = addWindowAction(window, QStringLiteral("actionShowControlMesh"),
        SubdivisionText::tr("Control &Mesh"), QKeySequence(Qt::Key_1),
        SubdivisionText::tr("Show the control mesh in the viewport, without subdivision (as Maya's 1)"));
    QAction* smooth = addWindowAction(window, QStringLiteral("actionShowSmoothSurface"),
        SubdivisionText::tr("&Smooth Surface"), QKeySequence(Qt::Key_3),
        SubdivisionText::tr("Show the subdivided surface at the look's viewport level, as renders show it (as "
                            "Maya's 3)"));
    QAction* wire = addWindowAction(window, QStringLiteral("actionShowControlCage"),
        SubdivisionText::tr("Show Control &Cage"), QKeySequence(Qt::Key_2),
        SubdivisionText::tr("Draw the control mesh as a wireframe over the smooth surface"));
    for (QAction* a : {cage, smooth, wire})
        a->setCheckable(true);
    group->addAction(cage);
    group->addAction(smooth);
    smooth->setChecked(viewport->display().smoothShown());
    cage->setChecked(!viewport->display().smoothShown());
    QObject::connect(cage, &QAction::triggered, window, [viewport, updateNote] {
        viewport->display().setSmoothShown(false);
        updateNote();
    });
    QObject::connect(smooth, &QAction::triggered, window, [viewport, updateNote] {
        viewport->display().setSmoothShown(true);
        updateNote();
    });
    QObject::connect(wire, &QAction::toggled, window, [viewport](bool on) { viewport->display().setCageShown(on); });
    QObject::connect(window->document(), &model::Document::changed, note, [updateNote](const model::ChangeSet& c) {
        if (c.reset || c.has(model::Part::Look) || c.has(model::Part::Mesh))
            updateNote();
    });
    updateNote();

    if (QMenu* view = menuOf(window->action(QStringLiteral("actionFrameAll")))) {
        QAction* before = window->action(QStringLiteral("actionShowLook"));
        view->insertSeparator(before);
        view->insertActions(before, {cage, smooth, wire});
    }
}

} // namespace celform::app
