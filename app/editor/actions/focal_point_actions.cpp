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

    QAction* paint = make("actionPaintFocalPoints", FocalText::tr("&Paint Focal Points"),
        FocalText::tr("Patch brush in importance mode: drag takes the faces towards the importance, Ctrl+drag back "
                      "towards 1; the light optimisation weighs each segment by its faces' mean importance "
                      "(thesis 6.2)"));
    paint->setCheckable(true);
    QObject::connect(paint, &QAction::toggled, viewport, [viewport, tool](bool on) {
        if (on) {
            tool->setMode(views::PatchTool::Mode::Importance);
            viewport->setTool(views::Viewport::Tool::Patch);
        } else if (viewport->tool() == views::Viewport::Tool::Patch
            && tool->mode() == views::PatchTool::Mode::Importance) {
            viewport->setTool(views::Viewport::Tool::Navigate);
        }
    });
    auto follow = [paint, viewport, tool] {
        const QSignalBlocker block(paint);
        paint->setChecked(viewport->tool() == views::Viewport::Tool::Patch
            && tool->mode() == views::PatchTool::Mode::Importance);
    };
    QObject::connect(viewport, &views::Viewport::toolChanged, paint, follow);
    QObject::connect(tool, &views::PatchTool::targetChanged, paint, follow);
    sub->addAction(paint);

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
}

} // namespace celform::app
