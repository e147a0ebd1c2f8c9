// Shading-offset actions and the Automatic Shading Offsets dialog (offset_actions.h).
#include "editor/actions/shading_offset_actions.h"

#include "editor/jobs/auto_offsets_job.h"
#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/analysis/auto_offsets.h"
#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/tools/offset_brush_tool.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QSpinBox>
#include <QStatusBar>

#include <algorithm>

namespace celform::app {
namespace {

struct OffsetText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::OffsetActions)
};

/// The target the tool paints into now (its setting), as the dialogs use it too.
model::ShadingTarget currentTarget(MainWindow* window)
{
    return window->viewport()->tool<views::OffsetBrushTool>().target();
}

void autoOffsetsDialog(MainWindow* window)
{
    model::Document* doc = window->document();
    views::Viewport* viewport = window->viewport();
    if (!doc->hasMesh())
        return;
    QDialog dialog(window);
    dialog.setWindowTitle(OffsetText::tr("Automatic Shading Offsets"));
    auto* form = new QFormLayout(&dialog);
    auto* aggressiveness = new QDoubleSpinBox(&dialog);
    aggressiveness->setRange(0.0, 100.0);
    aggressiveness->setSuffix(QStringLiteral(" %"));
    aggressiveness->setValue(100.0);
    aggressiveness->setToolTip(OffsetText::tr("How far towards the solved offsets: 0 % changes nothing, 100 % gives "
                                              "every segment the wanted ratio (thesis figure 4.16)."));
    auto* percentile = new QDoubleSpinBox(&dialog);
    percentile->setRange(0.0, 1.0);
    percentile->setSingleStep(0.05);
    percentile->setValue(0.5);
    percentile->setToolTip(OffsetText::tr("Fraction of each segment left dark: 0.5 puts the shading line through "
                                          "the middle of every segment."));
    auto* bleed = new QSpinBox(&dialog);
    bleed->setRange(0, model::kMaxOffsetRounds);
    bleed->setValue(2);
    bleed->setToolTip(OffsetText::tr("Rounds the offsets bleed to neighbouring vertices, so the edges between "
                                     "segments do not show (thesis figure 4.15)."));
    auto* target = new QComboBox(&dialog);
    target->addItem(OffsetText::tr("Base layer"), 0);
    const model::ShadingTarget now = currentTarget(window);
    if (!now.isBase())
        target->addItem(viewport->tool<views::OffsetBrushTool>().targetText(), double(now.key));
    target->setCurrentIndex(target->count() - 1);
    target->setToolTip(OffsetText::tr("The layer that receives the offsets (the offset brush's target)."));
    form->addRow(OffsetText::tr("Aggressiveness:"), aggressiveness);
    form->addRow(OffsetText::tr("Percentile:"), percentile);
    form->addRow(OffsetText::tr("Bleeding rounds:"), bleed);
    form->addRow(OffsetText::tr("Target:"), target);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted)
        return;
    model::AutoOffsetsRequest request;
    request.target = {model::ObjectId(target->currentData().toDouble()), doc->currentFrame()};
    request.camera = viewport->camera();
    // The Depth tab's own analysis (its picture size and settings), so that the figures said here
    // are the ones the tab shows once it has analysed the new offsets.
    const views::DepthAnalysisRunner* depth = window->depthPanel()->runner();
    const QSize size = depth->analysisSize();
    request.width = std::max(16, size.width());
    request.height = std::max(16, size.height());
    request.analysis = depth->settings();
    request.aggressiveness = float(aggressiveness->value() / 100.0);
    request.percentile = float(percentile->value());
    request.bleed = bleed->value();
    // Solved on a worker thread; the values are stored on the GUI thread, one undo step.
    startAutoOffsets(doc->data(), request, window, [window, doc](const model::AutoOffsetsResult& result) {
        doc->shading().applyAutoOffsets(result.target, result.values);
        window->statusBar()->showMessage(OffsetText::tr("Automatic shading offsets: %1 segments; depth error MSE "
                                                        "%2 before, %3 after.")
                                             .arg(result.after.size())
                                             .arg(result.mseBefore, 0, 'g', 4)
                                             .arg(result.mseAfter, 0, 'g', 4),
            8000);
    });
}

} // namespace

void installOffsetActions(MainWindow* window, QMenu* menu)
{
    views::Viewport* viewport = window->viewport();
    model::Document* doc = window->document();
    auto make = [window](const char* name, const QString& text, const QKeySequence& key, const QString& tip) {
        return addWindowAction(window, QString::fromLatin1(name), text, key, tip);
    };
    QMenu* sub = menu->addMenu(OffsetText::tr("Shading &Offsets"));
    sub->setObjectName(QStringLiteral("menuShadingOffsets"));

    QAction* paint
        = make("actionOffsetBrush", OffsetText::tr("&Paint Shading Offsets"), QKeySequence(Qt::SHIFT | Qt::Key_O),
            OffsetText::tr("Offset brush: drag adds to N·L, Ctrl+drag subtracts, Shift+drag smooths (thesis 4.3)"));
    paint->setCheckable(true);
    QObject::connect(paint, &QAction::toggled, viewport, [viewport](bool on) {
        if (on)
            viewport->setTool(views::Viewport::Tool::OffsetBrush);
        else if (viewport->tool() == views::Viewport::Tool::OffsetBrush)
            viewport->setTool(views::Viewport::Tool::Navigate);
    });
    QObject::connect(viewport, &views::Viewport::toolChanged, paint,
        [paint](views::Viewport::Tool tool) { paint->setChecked(tool == views::Viewport::Tool::OffsetBrush); });
    sub->addAction(paint);

    // The brush's settings: mode of a plain drag, mirror, and the target layer.
    QMenu* modes = sub->addMenu(OffsetText::tr("Brush &Mode"));
    auto* modeGroup = new QActionGroup(window);
    const struct {
        const char* name;
        QString text;
        model::OffsetPaintMode mode;
    } modeList[] = {{"actionOffsetModeAdd", OffsetText::tr("&Add"), model::OffsetPaintMode::Add},
        {"actionOffsetModeSubtract", OffsetText::tr("&Subtract"), model::OffsetPaintMode::Subtract},
        {"actionOffsetModeSmooth", OffsetText::tr("S&mooth"), model::OffsetPaintMode::Smooth},
        {"actionOffsetModeErase", OffsetText::tr("&Erase"), model::OffsetPaintMode::Erase}};
    for (const auto& m : modeList) {
        QAction* a = make(m.name, m.text, QKeySequence(), OffsetText::tr("What a plain drag of the offset brush does"));
        a->setCheckable(true);
        a->setChecked(m.mode == model::OffsetPaintMode::Add);
        modeGroup->addAction(a);
        modes->addAction(a);
        QObject::connect(a, &QAction::triggered, viewport,
            [viewport, mode = m.mode] { viewport->tool<views::OffsetBrushTool>().setMode(mode); });
    }
    QAction* strength = make("actionOffsetStrength", OffsetText::tr("Brush S&trength…"), QKeySequence(),
        OffsetText::tr("The offset one dab adds at the brush's centre"));
    QObject::connect(strength, &QAction::triggered, window, [window, viewport] {
        bool ok = false;
        const double value = QInputDialog::getDouble(window, OffsetText::tr("Offset Brush Strength"),
            OffsetText::tr("Offset added at the centre by one dab:"),
            viewport->tool<views::OffsetBrushTool>().strength(), 0.0, 1.0, 3, &ok);
        if (ok)
            viewport->tool<views::OffsetBrushTool>().setStrength(value);
    });
    sub->addAction(strength);
    QAction* mirror = make("actionOffsetMirrorX", OffsetText::tr("&Mirror"), QKeySequence(),
        OffsetText::tr("Paint the mirror image across the project's mirror plane too (the brush's plane)"));
    mirror->setCheckable(true);
    QObject::connect(mirror, &QAction::toggled, viewport,
        [viewport](bool on) { viewport->tool<views::OffsetBrushTool>().setMirror(on); });
    sub->addAction(mirror);
    QAction* intoKey
        = make("actionOffsetTargetKey", OffsetText::tr("Paint into the Displayed &Key's Layer"), QKeySequence(),
            OffsetText::tr("On: the key shown in the viewport (Edit Key) at the playhead's frame; off: the base layer, "
                           "every view and frame"));
    intoKey->setCheckable(true);
    QObject::connect(intoKey, &QAction::toggled, viewport, [viewport, window](bool on) {
        views::OffsetBrushTool* tool = &viewport->tool<views::OffsetBrushTool>();
        tool->setTargetKey(on ? viewport->displayedKey() : 0);
        if (on && tool->targetKey() == 0)
            window->statusBar()->showMessage(
                OffsetText::tr("No key is shown: choose Edit Key in the Scene panel first; painting the base layer."),
                6000);
        else
            window->statusBar()->showMessage(
                OffsetText::tr("Shading offsets go into the %1.").arg(tool->targetText()), 6000);
        // The Depth panel's line naming the target (it follows tools and edits by itself).
        if (auto* label = window->findChild<QLabel*>(QStringLiteral("offsetTargetLabel")))
            label->setText(OffsetText::tr("Shading offsets go into the %1.").arg(tool->targetText()));
    });
    sub->addAction(intoKey);
    sub->addSeparator();

    QAction* automatic = make("actionAutoOffsets", OffsetText::tr("&Automatic Shading Offsets…"), QKeySequence(),
        OffsetText::tr("Give every segment of the depth analysis its shading line, seen from the current view "
                       "(thesis 4.3)"));
    QObject::connect(automatic, &QAction::triggered, window, [window] { autoOffsetsDialog(window); });
    sub->addAction(automatic);
    QAction* smooth = make("actionSmoothOffsets", OffsetText::tr("S&mooth Shading Offsets"), QKeySequence(),
        OffsetText::tr("Four rounds of smoothing of the target layer over the mesh"));
    QObject::connect(smooth, &QAction::triggered, window, [window, doc] {
        try {
            doc->shading().smoothShadingOffsets(currentTarget(window), 4);
        } catch (const model::EditRefused& e) {
            window->statusBar()->showMessage(e.message(), 6000);
        }
    });
    sub->addAction(smooth);
    QAction* clear = make("actionClearOffsets", OffsetText::tr("&Clear Shading Offsets"), QKeySequence(),
        OffsetText::tr("Remove the target layer's offsets"));
    QObject::connect(clear, &QAction::triggered, window, [window, doc] {
        try {
            doc->shading().clearShadingOffsets(currentTarget(window));
        } catch (const model::EditRefused& e) {
            window->statusBar()->showMessage(e.message(), 6000);
        }
    });
    sub->addAction(clear);
}

} // namespace celform::app
