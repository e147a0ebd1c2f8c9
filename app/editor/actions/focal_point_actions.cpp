// Focal point actions (focal_point_actions.h).
#include "editor/actions/focal_point_actions.h"

#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QCoreApplication>
#include <QInputDialog>
#include <QMenu>
#include <QStatusBar>

namespace celform::app {
namespace {

struct FocalText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::FocalPointActions)
};

} // namespace

void installFocalPointActions(MainWindow* window, QMenu* menu)
{
    views::Viewport* viewport = window->viewport();
    model::Document* doc = window->document();
    views::PatchTool* tool = &viewport->tool<views::PatchTool>();
    auto make = [window](const char* name, const QString& text, const QString& tip) {
        return addWindowAction(window, QString::fromLatin1(name), text, QKeySequence(), tip);
    };
    QMenu* sub = menu->addMenu(FocalText::tr("&Focal Points"));
    sub->setObjectName(QStringLiteral("menuFocalPoints"));

    // A checkable action per mode of the patch tool: on, the tool in that mode; it follows the tool.
    auto modeAction = [&](const char* name, const QString& text, const QString& tip, views::PatchTool::Mode mode) {
        QAction* a = make(name, text, tip);
        a->setCheckable(true);
        QObject::connect(a, &QAction::toggled, viewport, [viewport, tool, mode](bool on) {
            if (on) {
                tool->setMode(mode);
                viewport->setTool(views::Viewport::Tool::Patch);
            } else if (viewport->tool() == views::Viewport::Tool::Patch && tool->mode() == mode) {
                viewport->setTool(views::Viewport::Tool::Navigate);
            }
        });
        auto follow = [a, viewport, tool, mode] {
            const QSignalBlocker block(a);
            a->setChecked(viewport->tool() == views::Viewport::Tool::Patch && tool->mode() == mode);
        };
        QObject::connect(viewport, &views::Viewport::toolChanged, a, follow);
        QObject::connect(tool, &views::PatchTool::targetChanged, a, follow);
        return a;
    };
    sub->addAction(modeAction("actionPaintFocalPoints", FocalText::tr("&Paint Focal Points"),
        FocalText::tr("Patch brush in importance mode: drag takes the faces towards the importance, Ctrl+drag back "
                      "towards 1; the light optimisation weighs each segment by its faces' mean importance "
                      "(thesis 6.2)"),
        views::PatchTool::Mode::Importance));

    QAction* importance = make("actionFocalPointImportance", FocalText::tr("&Importance…"),
        FocalText::tr("The importance a drag paints towards: 0 leaves the faces out of the light optimisation, 1 "
                      "counts them fully"));
    QObject::connect(importance, &QAction::triggered, window, [window, tool] {
        bool ok = false;
        const double value = QInputDialog::getDouble(window, FocalText::tr("Focal Point Importance"),
            FocalText::tr("Importance painted (0 to 1):"), double(tool->importance()), 0.0, 1.0, 2, &ok);
        if (ok)
            tool->setImportance(float(value));
    });
    sub->addAction(importance);
    QAction* strength = make("actionFocalPointStrength", FocalText::tr("S&trength…"),
        FocalText::tr("The share of the way to the importance one drag takes each face"));
    QObject::connect(strength, &QAction::triggered, window, [window, tool] {
        bool ok = false;
        const double value = QInputDialog::getDouble(window, FocalText::tr("Focal Point Strength"),
            FocalText::tr("Share of the way one drag goes (0.01 to 1):"), double(tool->strength()), 0.01, 1.0, 2, &ok);
        if (ok)
            tool->setStrength(float(value));
    });
    sub->addAction(strength);
    QAction* clear = make("actionClearFocalPoints", FocalText::tr("&Clear Focal Points"),
        FocalText::tr("Every face's importance back to 1"));
    QObject::connect(clear, &QAction::triggered, window, [window, doc] {
        try {
            doc->faceSets().clearFaceImportance();
        } catch (const model::EditRefused& e) {
            window->statusBar()->showMessage(e.message(), 6000);
        }
    });
    sub->addAction(clear);

    // The segment brush (thesis 6.2: "a brush tool ... that allows artists to manually select
    // segments"), on the depth analysis of the picture the viewport shows.
    QMenu* brush = menu->addMenu(FocalText::tr("Segment &Brush"));
    brush->setObjectName(QStringLiteral("menuSegmentBrush"));
    brush->addAction(modeAction("actionMergeSegments", FocalText::tr("&Merge Segments"),
        FocalText::tr("Click a segment of the depth analysis, then another: they become one segment"),
        views::PatchTool::Mode::MergeSegments));
    brush->addAction(modeAction("actionSplitSegment", FocalText::tr("&Split Segment"),
        FocalText::tr("Drag across a segment of the depth analysis: it becomes two, one on each side of the drag"),
        views::PatchTool::Mode::SplitSegment));
    QAction* release = make("actionClearSegmentOverrides", FocalText::tr("&Clear Segment Overrides"),
        FocalText::tr("Every face back to the segments the analysis finds"));
    QObject::connect(release, &QAction::triggered, window, [window, doc] {
        try {
            doc->faceSets().setSegmentOverrides({}, FocalText::tr("Clear Segment Overrides"));
        } catch (const model::EditRefused& e) {
            window->statusBar()->showMessage(e.message(), 6000);
        }
    });
    brush->addAction(release);
}

} // namespace celform::app
