// Highlight layers bound to the document's look: refresh() keeps every control in step with the
// look after undo, redo or a change from the command line, and with the panel's current frame.
#include "celform/views/highlight_panel.h"

#include "celform/views/scrolling_panel.h"

#include "celform/views/color_swatch.h"
#include "celform/views/look_shading.h"

#include "celform/views/viewport.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/io_error.h"
#include "celform/model/render_output.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace celform::views {
namespace {

/// Range, step, decimals and the paper's names of an operation's two parameters.
struct ParameterSpec {
    double min, max, step;
    int decimals;
    const char* name;
    const char* tip;
};

std::pair<ParameterSpec, ParameterSpec> operationSpecs(algo::HighlightOperationType type)
{
    using T = algo::HighlightOperationType;
    switch (type) {
    case T::Translation:
        return {{-2, 2, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "α"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "alpha: moves the highlight along du")},
            {-2, 2, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "β"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "beta: moves the highlight along dv")}};
    case T::Rotation:
        return {{-360, 360, 5, 1, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "angle"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel",
                        "Angle in degrees, du turning towards dv: turns the frame of later operations")},
            {0, 0, 0, 0, nullptr, nullptr}};
    case T::DirectionalScaling:
        return {
            {0, 1, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "δ"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "delta in [0, 1]: stretches the area along du")},
            {0, 0, 0, 0, nullptr, nullptr}};
    case T::Split:
        return {{0, 5, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "γ1"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "gamma1 >= 0: cuts the area across du")},
            {0, 5, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "γ2"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "gamma2 >= 0: cuts the area across dv")}};
    case T::Squaring:
        return {{0, 1, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "σ"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel",
                        "sigma in [0, 1]: squareness of the area (about 0.2 is squarest)")},
            {1, 16, 1, 0, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "n"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "n >= 1: exponent of the squaring")}};
    }
    return {};
}

algo::HighlightOperation defaultOperation(algo::HighlightOperationType type)
{
    using T = algo::HighlightOperationType;
    switch (type) {
    case T::Translation:
        return algo::HighlightOperation::translation(0.f, 0.f);
    case T::Rotation:
        return algo::HighlightOperation::rotation(0.f);
    case T::DirectionalScaling:
        return algo::HighlightOperation::directionalScaling(0.f);
    case T::Split:
        return algo::HighlightOperation::split(0.f, 0.f);
    case T::Squaring:
        return algo::HighlightOperation::squaring(0.2f, 2.f);
    }
    return {};
}

QString operationTitle(algo::HighlightOperationType type)
{
    using T = algo::HighlightOperationType;
    switch (type) {
    case T::Translation:
        return HighlightPanel::tr("Translate");
    case T::Rotation:
        return HighlightPanel::tr("Rotate");
    case T::DirectionalScaling:
        return HighlightPanel::tr("Scale");
    case T::Split:
        return HighlightPanel::tr("Split");
    case T::Squaring:
        return HighlightPanel::tr("Square");
    }
    return {};
}

} // namespace

// --- timeline ------------------------------------------------------------------------------------

HighlightTimeline::HighlightTimeline(QWidget* parent)
    : QWidget(parent)
{
    setToolTip(tr("Frames of the animation: diamonds are the selected layer's keys; click or drag to move the "
                  "current frame"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setFixedHeight(40);
}

void HighlightTimeline::setFrameCount(int last)
{
    m_last = std::max(1, last);
    update();
}

void HighlightTimeline::setKeys(std::vector<double> frames)
{
    m_keys = std::move(frames);
    update();
}

void HighlightTimeline::setFrame(int frame)
{
    m_frame = frame;
    update();
}

int HighlightTimeline::xForFrame(int frame) const
{
    const double margin = 8.0;
    return int(std::lround(margin + (width() - 2.0 * margin) * double(frame) / double(m_last)));
}

int HighlightTimeline::frameAt(double x) const
{
    const double margin = 8.0;
    const double t = (x - margin) / std::max(1.0, width() - 2.0 * margin);
    return std::clamp(int(std::lround(t * m_last)), 0, m_last);
}

void HighlightTimeline::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Base));
    const int axisY = height() - 12;
    p.setPen(pal.color(QPalette::Mid));
    p.drawLine(xForFrame(0), axisY, xForFrame(m_last), axisY);
    // Ticks: every frame when there is room, else every 6th; labels every 12th (half a second).
    const double perFrame = (width() - 16.0) / double(m_last);
    const int tickStep = perFrame >= 4.0 ? 1 : 6;
    QFont font = p.font();
    font.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.75));
    p.setFont(font);
    for (int f = 0; f <= m_last; f += tickStep) {
        const int x = xForFrame(f);
        const bool major = f % 12 == 0;
        p.setPen(pal.color(major ? QPalette::Text : QPalette::Mid));
        p.drawLine(x, axisY, x, axisY - (major ? 6 : 3));
        if (major && perFrame * 12 >= 18)
            p.drawText(QRect(x - 15, axisY + 1, 30, 11), Qt::AlignCenter, QString::number(f));
    }
    // Key marks.
    p.setPen(QPen(pal.color(QPalette::Text), 1));
    for (double k : m_keys) {
        const double x = 8.0 + (width() - 16.0) * k / double(m_last);
        QPainterPath diamond;
        diamond.moveTo(x, 6);
        diamond.lineTo(x + 5, 12);
        diamond.lineTo(x, 18);
        diamond.lineTo(x - 5, 12);
        diamond.closeSubpath();
        p.fillPath(diamond, QColor(240, 190, 40));
        p.drawPath(diamond);
    }
    // Current-frame cursor.
    const int cx = xForFrame(m_frame);
    p.setPen(QPen(QColor(220, 50, 40), 2));
    p.drawLine(cx, 2, cx, axisY);
    p.fillRect(QRect(cx - 4, 0, 9, 4), QColor(220, 50, 40));
}

void HighlightTimeline::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        emit frameScrubbed(frameAt(event->position().x()));
}

void HighlightTimeline::mouseMoveEvent(QMouseEvent* event)
{
    if (event->buttons() & Qt::LeftButton) {
        const int f = frameAt(event->position().x());
        if (f != m_frame)
            emit frameScrubbed(f);
    }
}

// --- panel ---------------------------------------------------------------------------------------

HighlightPanel::HighlightPanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    QVBoxLayout* layout = scrollingPanelLayout(this);
    QWidget* content = layout->parentWidget();

    // --- layers ----------------------------------------------------------------------------------
    auto* layersBox = new QGroupBox(tr("Layers"), content);
    auto* layersLayout = new QVBoxLayout(layersBox);
    m_layers = new QListWidget(layersBox);
    m_layers->setObjectName(QStringLiteral("highlightLayers"));
    m_layers->setToolTip(tr("Highlight layers, later ones drawn over earlier ones. Double-click to rename; "
                            "unchecked layers are drawn only as operands of other layers' combinations"));
    m_layers->setMaximumHeight(110);
    layersLayout->addWidget(m_layers);
    auto* layerButtons = new QHBoxLayout;
    m_addLayer = new QPushButton(tr("&Add"), layersBox);
    m_addLayer->setObjectName(QStringLiteral("addHighlightLayer"));
    m_addLayer->setToolTip(tr("Add a highlight layer with a key at the current frame"));
    m_removeLayer = new QPushButton(tr("&Remove"), layersBox);
    m_removeLayer->setObjectName(QStringLiteral("removeHighlightLayer"));
    m_removeLayer->setToolTip(tr("Remove the selected layer and its use in other layers' combinations"));
    m_addPreset = new QToolButton(layersBox);
    m_addPreset->setObjectName(QStringLiteral("addHighlightPreset"));
    m_addPreset->setText(tr("&Preset"));
    m_addPreset->setToolTip(tr("Add a shaped highlight to start from, on the selected layer's patch"));
    m_addPreset->setPopupMode(QToolButton::InstantPopup);
    layerButtons->addWidget(m_addLayer);
    layerButtons->addWidget(m_addPreset);
    layerButtons->addWidget(m_removeLayer);
    layerButtons->addStretch();
    layersLayout->addLayout(layerButtons);
    layout->addWidget(layersBox);
    connect(m_layers, &QListWidget::currentRowChanged, this, [this](int) {
        if (!m_updating)
            refresh();
    });
    connect(m_layers, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        if (m_updating)
            return;
        const int row = m_layers->row(item);
        const auto& tracks = m_document->data().look.highlights;
        if (row < 0 || row >= int(tracks.size()))
            return;
        const QString oldName = tracks[std::size_t(row)].name;
        const QString newName = item->text().trimmed();
        const bool visible = item->checkState() == Qt::Checked;
        if (newName != oldName) {
            edit(tr("Rename Highlight Layer"), [&](model::Look& l) {
                l.highlights[std::size_t(row)].name = newName;
                for (auto& t : l.highlights)
                    for (auto& c : t.combineWith)
                        if (c.second == oldName)
                            c.second = newName;
            });
        } else if (visible != tracks[std::size_t(row)].visible) {
            edit(visible ? tr("Show Highlight Layer") : tr("Hide Highlight Layer"),
                [&](model::Look& l) { l.highlights[std::size_t(row)].visible = visible; });
        }
        refresh(); // a refused name goes back to the stored one
    });
    connect(m_addLayer, &QPushButton::clicked, this, [this] {
        const auto& tracks = m_document->data().look.highlights;
        QString name;
        for (int n = int(tracks.size()) + 1;; ++n) {
            name = tr("Highlight %1").arg(n);
            if (std::none_of(
                    tracks.begin(), tracks.end(), [&](const model::HighlightTrack& t) { return t.name == name; }))
                break;
        }
        const int index = int(tracks.size());
        const int frame = m_frame;
        edit(tr("Add Highlight Layer"), [&](model::Look& l) {
            model::HighlightTrack track;
            track.name = name;
            track.setKey(frame, algo::HighlightLayer{});
            l.highlights.push_back(std::move(track));
        });
        selectLayer(index);
    });
    // Presets: the paper's two worked examples as starting points (Figures 5 and 6).
    auto* presetMenu = new QMenu(m_addPreset);
    presetMenu->addAction(tr("&Window"), this, [this] { addPreset(Preset::Window); })
        ->setToolTip(tr("Rotation, directional scaling and split on a nearly flat part: the car window of the "
                        "paper's Figure 5"));
    presetMenu->addAction(tr("&Crescent"), this, [this] { addPreset(Preset::Crescent); })
        ->setToolTip(tr("A highlight minus a hidden, shifted copy of itself: the crescent of the paper's Figure 6"));
    presetMenu->setToolTipsVisible(true);
    m_addPreset->setMenu(presetMenu);
    connect(m_removeLayer, &QPushButton::clicked, this, [this] {
        const int row = selectedLayer();
        if (row < 0)
            return;
        edit(tr("Remove Highlight Layer"), [row](model::Look& l) {
            const QString name = l.highlights[std::size_t(row)].name;
            l.highlights.erase(l.highlights.begin() + row);
            for (auto& t : l.highlights)
                t.combineWith.erase(std::remove_if(t.combineWith.begin(), t.combineWith.end(),
                                        [&](const auto& c) { return c.second == name; }),
                    t.combineWith.end());
        });
    });

    // --- timeline --------------------------------------------------------------------------------
    auto* timeBox = new QGroupBox(tr("Keys"), content);
    auto* timeLayout = new QVBoxLayout(timeBox);
    m_timeline = new HighlightTimeline(timeBox);
    m_timeline->setObjectName(QStringLiteral("highlightTimeline"));
    timeLayout->addWidget(m_timeline);
    auto* frameRow = new QHBoxLayout;
    m_previousKey = new QToolButton(timeBox);
    m_previousKey->setArrowType(Qt::LeftArrow);
    m_previousKey->setToolTip(tr("Go to the previous key of the layer"));
    m_frameSpin = new QSpinBox(timeBox);
    m_frameSpin->setObjectName(QStringLiteral("highlightFrame"));
    m_frameSpin->setRange(0, 48);
    m_frameSpin->setToolTip(tr("Current frame: parameters show the layer at this frame, and edits key it here"));
    m_nextKey = new QToolButton(timeBox);
    m_nextKey->setArrowType(Qt::RightArrow);
    m_nextKey->setToolTip(tr("Go to the next key of the layer"));
    m_lastFrame = new QSpinBox(timeBox);
    m_lastFrame->setObjectName(QStringLiteral("highlightLastFrame"));
    m_lastFrame->setRange(1, 100000);
    m_lastFrame->setValue(48);
    m_lastFrame->setPrefix(tr("of "));
    m_lastFrame->setToolTip(tr("Last frame shown on the timeline"));
    frameRow->addWidget(new QLabel(tr("Frame:"), timeBox));
    frameRow->addWidget(m_previousKey);
    frameRow->addWidget(m_frameSpin);
    frameRow->addWidget(m_nextKey);
    frameRow->addWidget(m_lastFrame);
    frameRow->addStretch();
    timeLayout->addLayout(frameRow);
    auto* keyRow = new QHBoxLayout;
    m_key = new QPushButton(tr("&Key"), timeBox);
    m_key->setObjectName(QStringLiteral("highlightKey"));
    m_key->setToolTip(tr("Set a key of all the layer's parameters at the current frame"));
    m_deleteKey = new QPushButton(tr("&Delete Key"), timeBox);
    m_deleteKey->setObjectName(QStringLiteral("highlightDeleteKey"));
    m_deleteKey->setToolTip(tr("Remove the layer's key at the current frame (a layer keeps at least one key)"));
    keyRow->addWidget(m_key);
    keyRow->addWidget(m_deleteKey);
    keyRow->addStretch();
    timeLayout->addLayout(keyRow);
    layout->addWidget(timeBox);
    connect(m_timeline, &HighlightTimeline::frameScrubbed, this, &HighlightPanel::setCurrentFrame);
    connect(m_frameSpin, qOverload<int>(&QSpinBox::valueChanged), this, [this](int f) {
        if (!m_updating)
            setCurrentFrame(f);
    });
    connect(m_lastFrame, qOverload<int>(&QSpinBox::valueChanged), this, [this](int last) {
        m_timeline->setFrameCount(last);
        {
            const QSignalBlocker block(m_frameSpin);
            m_frameSpin->setMaximum(last);
        }
        if (m_frame > last)
            setCurrentFrame(last);
    });
    connect(m_previousKey, &QToolButton::clicked, this, [this] { jumpToKey(-1); });
    connect(m_nextKey, &QToolButton::clicked, this, [this] { jumpToKey(1); });
    connect(m_key, &QPushButton::clicked, this, [this] {
        const int frame = m_frame;
        editTrack(tr("Key Highlight"), [frame](model::HighlightTrack& t) { t.setKey(frame, t.layerAt(frame)); });
    });
    connect(m_deleteKey, &QPushButton::clicked, this, [this] {
        const double frame = m_frame;
        editTrack(tr("Delete Highlight Key"), [frame](model::HighlightTrack& t) {
            if (t.keys.size() < 2)
                return;
            t.keys.erase(std::remove_if(t.keys.begin(), t.keys.end(),
                             [frame](const algo::HighlightKey& k) { return k.frame == frame; }),
                t.keys.end());
        });
    });

    // --- parameters ------------------------------------------------------------------------------
    m_parameters = new QGroupBox(tr("Parameters at this frame"), content);
    auto* form = new QFormLayout(m_parameters);
    m_color = new QToolButton(m_parameters);
    m_color->setIconSize(QSize(28, 16));
    m_color->setToolTip(tr("Colour of the highlight (keyed)"));
    form->addRow(tr("&Colour:"), m_color);
    connect(m_color, &QToolButton::clicked, this, [this] {
        const model::HighlightTrack* t = track();
        if (!t)
            return;
        const QColor chosen = QColorDialog::getColor(toQColor(t->layerAt(m_frame).color), this, tr("Highlight Colour"));
        if (chosen.isValid())
            editKey(tr("Change Highlight Colour"), [&](algo::HighlightLayer& l) { l.color = fromQColor(chosen); });
    });
    m_epsilon = makeSpin(0.001, 1.0, 0.01, 3, tr("epsilon: size of the area where (N, H) > 1 - epsilon (keyed)"));
    m_epsilon->setObjectName(QStringLiteral("highlightEpsilon"));
    form->addRow(tr("&Epsilon:"), m_epsilon);
    connect(m_epsilon, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editKey(
            tr("Change Highlight Size"), [v](algo::HighlightLayer& l) { l.shape.epsilon = float(v); },
            QStringLiteral("epsilon"));
    });
    m_cut = makeSpin(-1.0, 1.0, 0.05, 3,
        tr("Off-specular cut: no highlight where N·L is at most this value; -1 turns it off (keyed)"));
    form->addRow(tr("Off-specular c&ut:"), m_cut);
    connect(m_cut, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editKey(
            tr("Change Off-Specular Cut"), [v](algo::HighlightLayer& l) { l.offSpecularCut = float(v); },
            QStringLiteral("cut"));
    });
    // The patch: the paper shapes each highlight on one (u, v) patch; here a face set painted
    // on the model (the Patch tool of the viewport), or all faces.
    auto* patchRow = new QWidget(m_parameters);
    auto* patchLayout = new QHBoxLayout(patchRow);
    patchLayout->setContentsMargins(0, 0, 0, 0);
    m_patch = new QComboBox(patchRow);
    m_patch->setObjectName(QStringLiteral("highlightPatch"));
    m_patch->setToolTip(tr("Face set the highlight may appear on (not keyed)"));
    m_patch->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    patchLayout->addWidget(m_patch, 1);
    m_paintPatch = new QToolButton(patchRow);
    m_paintPatch->setObjectName(QStringLiteral("highlightPaintPatch"));
    m_paintPatch->setText(tr("Paint"));
    m_paintPatch->setCheckable(true);
    m_paintPatch->setToolTip(tr("Paint the layer's patch on the model: drag adds faces, Ctrl+drag removes them, "
                                "[ and ] change the radius. A layer on all faces gets a new patch first."));
    patchLayout->addWidget(m_paintPatch);
    auto* patchMenuButton = new QToolButton(patchRow);
    patchMenuButton->setObjectName(QStringLiteral("highlightPatchMenu"));
    patchMenuButton->setText(tr("…"));
    patchMenuButton->setToolTip(tr("New, rename or delete patches"));
    patchMenuButton->setPopupMode(QToolButton::InstantPopup);
    auto* patchMenu = new QMenu(patchMenuButton);
    m_newPatch = patchMenu->addAction(tr("&New Patch"), this, [this] { newPatchForLayer(); });
    m_renamePatch = patchMenu->addAction(tr("&Rename Patch…"), this, [this] {
        const model::HighlightTrack* t = track();
        if (!t || t->patch.isEmpty())
            return;
        bool ok = false;
        const QString name
            = QInputDialog::getText(this, tr("Rename Patch"), tr("Patch name:"), QLineEdit::Normal, t->patch, &ok);
        if (!ok)
            return;
        try {
            m_document->renameFaceSet(t->patch, name);
        } catch (const model::EditRefused& e) {
            QMessageBox::warning(this, tr("Rename Patch"), e.message());
        }
    });
    m_deletePatch = patchMenu->addAction(tr("&Delete Patch"), this, [this] {
        if (const model::HighlightTrack* t = track(); t && !t->patch.isEmpty())
            m_document->removeFaceSet(t->patch);
    });
    patchMenuButton->setMenu(patchMenu);
    patchLayout->addWidget(patchMenuButton);
    form->addRow(tr("&Patch:"), patchRow);
    connect(m_patch, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        const QString patch = m_patch->itemData(index).toString();
        editTrack(tr("Change Highlight Patch"), [&](model::HighlightTrack& t) { t.patch = patch; });
    });
    connect(m_paintPatch, &QToolButton::toggled, this, [this](bool on) {
        if (!m_viewport)
            return;
        if (!on) {
            if (m_viewport->tool() == Viewport::Tool::Patch)
                m_viewport->setTool(Viewport::Tool::Navigate);
            return;
        }
        const model::HighlightTrack* t = track();
        if (t && t->patch.isEmpty())
            newPatchForLayer();
        t = track();
        if (!t || t->patch.isEmpty()) {
            const QSignalBlocker block(m_paintPatch);
            m_paintPatch->setChecked(false);
            return;
        }
        m_viewport->setPatchTarget(t->patch);
        m_viewport->setTool(Viewport::Tool::Patch);
    });
    auto* guideRow = new QWidget(m_parameters);
    auto* guideLayout = new QHBoxLayout(guideRow);
    guideLayout->setContentsMargins(0, 0, 0, 0);
    for (int axis = 0; axis < 3; ++axis) {
        m_guide[axis] = makeSpin(-1e3, 1e3, 0.1, 3,
            tr("Guide direction (x, y, z): the u axis of the highlight on models without UVs (not keyed)"));
        m_guide[axis]->setMinimumWidth(40);
        m_guide[axis]->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        guideLayout->addWidget(m_guide[axis]);
        connect(m_guide[axis], qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, axis](double v) {
            editTrack(
                tr("Change Highlight Guide"), [axis, v](model::HighlightTrack& t) { t.guide[axis] = float(v); },
                QStringLiteral("guide%1").arg(axis));
        });
    }
    form->addRow(tr("&Guide:"), guideRow);
    m_smoothing = new QSpinBox(m_parameters);
    m_smoothing->setObjectName(QStringLiteral("highlightSmoothing"));
    m_smoothing->setRange(0, model::kMaxHighlightSmoothing);
    m_smoothing->setKeyboardTracking(false);
    m_smoothing->setSpecialValueText(tr("Off"));
    m_smoothing->setToolTip(tr("Rounds of normal smoothing over the patch: the highlight sees a smooth surface, as on "
                               "the paper's spline patches, and coarse meshes give clean shapes. Paint thin parts "
                               "(an ear) one side at a time: smoothing mixes the normals of both sides (not keyed)"));
    form->addRow(tr("&Smooth normals:"), m_smoothing);
    connect(m_smoothing, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        editTrack(
            tr("Change Highlight Smoothing"), [v](model::HighlightTrack& t) { t.smoothing = v; },
            QStringLiteral("smoothing"));
    });
    m_editInViewport = new QPushButton(tr("Edit in &Viewport"), m_parameters);
    m_editInViewport->setObjectName(QStringLiteral("highlightEditInViewport"));
    m_editInViewport->setCheckable(true);
    m_editInViewport->setToolTip(tr("Drag on the model to move the highlight; Shift+drag rotates it, Ctrl+drag "
                                    "scales it (keyed at the current frame)"));
    form->addRow(m_editInViewport);
    connect(m_editInViewport, &QPushButton::toggled, this, [this](bool on) {
        if (m_viewport && (on || m_viewport->tool() == Viewport::Tool::Highlight))
            m_viewport->setTool(on ? Viewport::Tool::Highlight : Viewport::Tool::Navigate);
    });
    layout->addWidget(m_parameters);

    // --- operations ------------------------------------------------------------------------------
    m_operationsBox = new QGroupBox(tr("Operations (in order)"), content);
    auto* opsLayout = new QVBoxLayout(m_operationsBox);
    m_operationRows = new QVBoxLayout;
    opsLayout->addLayout(m_operationRows);
    m_addOperation = new QToolButton(m_operationsBox);
    m_addOperation->setText(tr("Add Operation"));
    m_addOperation->setToolTip(tr("Append an operation on the highlight's vector field to every key of the layer"));
    m_addOperation->setPopupMode(QToolButton::InstantPopup);
    auto* opMenu = new QMenu(m_addOperation);
    using T = algo::HighlightOperationType;
    for (T type : {T::Translation, T::Rotation, T::DirectionalScaling, T::Split, T::Squaring}) {
        QAction* a = opMenu->addAction(operationTitle(type));
        connect(a, &QAction::triggered, this, [this, type] {
            editOperations(tr("Add Highlight Operation"),
                [type](std::vector<algo::HighlightOperation>& ops) { ops.push_back(defaultOperation(type)); });
        });
    }
    m_addOperation->setMenu(opMenu);
    opsLayout->addWidget(m_addOperation, 0, Qt::AlignLeft);
    layout->addWidget(m_operationsBox);

    // --- combinations ----------------------------------------------------------------------------
    m_combinationsBox = new QGroupBox(tr("Combinations"), content);
    auto* combLayout = new QVBoxLayout(m_combinationsBox);
    m_combinationRows = new QVBoxLayout;
    combLayout->addLayout(m_combinationRows);
    m_addCombination = new QPushButton(tr("Add Combination"), m_combinationsBox);
    m_addCombination->setObjectName(QStringLiteral("addHighlightCombination"));
    m_addCombination->setToolTip(tr("Unite this layer's area with, or subtract from it, another layer's area at the "
                                    "same frame"));
    combLayout->addWidget(m_addCombination, 0, Qt::AlignLeft);
    connect(m_addCombination, &QPushButton::clicked, this, [this] {
        const int row = selectedLayer();
        const auto& tracks = m_document->data().look.highlights;
        for (int i = 0; i < int(tracks.size()); ++i)
            if (i != row) {
                const QString other = tracks[std::size_t(i)].name;
                editTrack(tr("Add Highlight Combination"), [&](model::HighlightTrack& t) {
                    t.combineWith.emplace_back(algo::HighlightBoolean::Union, other);
                });
                return;
            }
    });
    layout->addWidget(m_combinationsBox);
    m_viewportLimit = new QLabel(content);
    m_viewportLimit->setObjectName(QStringLiteral("highlightViewportLimit"));
    m_viewportLimit->setWordWrap(true);
    m_viewportLimit->setText(tr("The viewport draws the first %1 visible layers and, of each, %2 operations and %3 "
                                "combinations; the rest shows in renders (celform render).")
                                 .arg(kViewportHighlightLayers)
                                 .arg(kViewportHighlightOperations)
                                 .arg(kViewportHighlightCombinations));
    m_viewportLimit->setStyleSheet(QStringLiteral("color: #a05000;"));
    m_viewportLimit->hide();
    layout->addWidget(m_viewportLimit);
    layout->addStretch();

    connect(m_document, &model::Document::lookChanged, this, &HighlightPanel::refresh);
    connect(m_document, &model::Document::documentReset, this, &HighlightPanel::refresh);
    connect(m_document, &model::Document::meshChanged, this, &HighlightPanel::refresh);
    connect(m_document, &model::Document::faceSetsChanged, this, &HighlightPanel::refresh);
    refresh();
}

void HighlightPanel::addPreset(Preset preset)
{
    const auto& tracks = m_document->data().look.highlights;
    std::vector<QString> taken;
    for (const auto& t : tracks)
        taken.push_back(t.name);
    auto unique = [&](const QString& base) {
        QString name = base;
        for (int n = 2; std::find(taken.begin(), taken.end(), name) != taken.end(); ++n)
            name = QStringLiteral("%1 %2").arg(base).arg(n);
        taken.push_back(name);
        return name;
    };
    // The new layers sit on the selected layer's patch, with its guide and smoothing. The values
    // were tuned on the sample elephant seen from the front (resources/samples/
    // elephant-highlights.celform): its ear is nearly flat like the paper's car window, where the
    // plain highlight covers everything (Figure 5a); smoothed normals give clean outlines.
    const model::HighlightTrack* selected = track();
    model::HighlightTrack base;
    base.smoothing = 8;
    if (selected) {
        base.patch = selected->patch;
        base.guide = selected->guide;
        if (selected->smoothing > 0)
            base.smoothing = selected->smoothing;
    }
    using Op = algo::HighlightOperation;
    std::vector<model::HighlightTrack> added;
    QString undoText;
    if (preset == Preset::Window) {
        // Paper, Figure 5b: rotation, directional scaling and split turn the window-filling
        // highlight into a long streak and a short one.
        model::HighlightTrack window = base;
        window.name = unique(tr("Window"));
        algo::HighlightLayer layer;
        layer.shape.epsilon = 0.03f;
        layer.shape.operations = {Op::rotation(30.f), Op::directionalScaling(0.6f), Op::split(0.25f, 0.f)};
        window.setKey(m_frame, layer);
        added.push_back(std::move(window));
        undoText = tr("Add Window Highlight");
    } else {
        // Paper, Figure 6: G minus H, H the same area moved along du and dv.
        model::HighlightTrack cut = base;
        cut.name = unique(tr("Crescent cut"));
        cut.visible = false;
        algo::HighlightLayer cutLayer;
        cutLayer.shape.epsilon = 0.04f;
        cutLayer.shape.operations = {Op::translation(0.1f, 0.1f)};
        cut.setKey(m_frame, cutLayer);
        model::HighlightTrack crescent = base;
        crescent.name = unique(tr("Crescent"));
        algo::HighlightLayer layer;
        layer.shape.epsilon = 0.04f;
        crescent.setKey(m_frame, layer);
        crescent.combineWith.emplace_back(algo::HighlightBoolean::Subtraction, cut.name);
        added.push_back(std::move(cut));
        added.push_back(std::move(crescent));
        undoText = tr("Add Crescent Highlight");
    }
    const int index = int(tracks.size() + added.size()) - 1;
    edit(undoText, [&](model::Look& l) { l.highlights.insert(l.highlights.end(), added.begin(), added.end()); });
    selectLayer(index);
}

void HighlightPanel::newPatchForLayer()
{
    const model::HighlightTrack* t = track();
    if (!t || !m_document->hasMesh())
        return;
    const QString name = m_document->uniqueFaceSetName(tr("%1 patch").arg(t->name));
    QUndoStack* undo = m_document->undoStack();
    undo->beginMacro(tr("New Patch “%1”").arg(name));
    m_document->setFaceSet(name, {}, tr("New Patch “%1”").arg(name));
    m_lastMergeKey.clear();
    editTrack(tr("Change Highlight Patch"), [&](model::HighlightTrack& track) { track.patch = name; });
    undo->endMacro();
    m_lastMergeKey.clear();
    if (m_viewport && m_viewport->tool() == Viewport::Tool::Patch)
        m_viewport->setPatchTarget(name);
}

QDoubleSpinBox* HighlightPanel::makeSpin(double min, double max, double step, int decimals, const QString& tip)
{
    auto* spin = new QDoubleSpinBox(this);
    spin->setRange(min, max);
    spin->setSingleStep(step);
    spin->setDecimals(decimals);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(false); // typing "0.35" is one edit, not four
    return spin;
}

void HighlightPanel::setViewport(Viewport* viewport)
{
    if (m_viewport)
        disconnect(m_viewport, nullptr, this, nullptr);
    m_viewport = viewport;
    m_editInViewport->setChecked(false);
    m_paintPatch->setChecked(false);
    refresh(); // enables "Edit in Viewport"
    if (!viewport)
        return;
    connect(viewport, &Viewport::toolChanged, this, [this](Viewport::Tool tool) {
        const QSignalBlocker block(m_editInViewport);
        m_editInViewport->setChecked(tool == Viewport::Tool::Highlight);
        const QSignalBlocker blockPaint(m_paintPatch);
        m_paintPatch->setChecked(tool == Viewport::Tool::Patch);
    });
    connect(viewport, &Viewport::highlightDragStarted, this, &HighlightPanel::beginViewportDrag);
    connect(viewport, &Viewport::highlightDragged, this, &HighlightPanel::viewportDrag);
    connect(viewport, &Viewport::highlightDragFinished, this, [this] { m_lastMergeKey.clear(); });
}

void HighlightPanel::beginViewportDrag(const QPointF& position)
{
    ++m_dragCount;
    m_lastMergeKey.clear();
    // Fallback without a picked point: screen axes, a fixed rate.
    m_dragDu = QPointF(1.0, 0.0);
    m_dragDv = QPointF(0.0, -1.0);
    m_dragUnitsPerPixel = 0.005;
    const model::HighlightTrack* t = track();
    const auto& mesh = m_document->data().baseMesh;
    if (!t || !m_viewport || !mesh)
        return;
    const std::int64_t vertex = m_viewport->pickVertex(position);
    const algo::Positions& shape = m_viewport->displayedShape();
    if (vertex < 0 || vertex >= shape.rows() || shape.rows() != mesh->vertices.rows())
        return;
    const Eigen::Vector3f p = shape.row(vertex).transpose();
    // The frame the renderer uses at that vertex (UVs where the model has them, else the guide
    // smoothed over the patch); a hidden layer or a vertex off its patch falls back to the guide.
    algo::HighlightFrame frame;
    bool found = false;
    for (const auto& h : model::renderHighlightsFor(m_document->data(), m_document->data().look, shape, m_frame))
        if (QString::fromStdString(h.layer.name) == t->name && h.du.rows() == shape.rows()
            && h.du.row(vertex).squaredNorm() > 0.5f) {
            frame.du = h.du.row(vertex).transpose();
            frame.dv = h.dv.row(vertex).transpose();
            found = true;
            break;
        }
    if (!found) {
        const algo::Positions normals = algo::vertexNormals(shape, mesh->faces);
        frame = algo::guideTangentFrame(normals.row(vertex).transpose(), t->guide);
    }
    const double perPixel = m_viewport->worldUnitsPerPixel(p.cast<double>());
    const QPointF origin = m_viewport->projectToWidget(p.cast<double>());
    auto screenDirection = [&](const Eigen::Vector3f& d) {
        const QPointF s = m_viewport->projectToWidget((p + d * float(perPixel * 10.0)).cast<double>()) - origin;
        const double length = std::hypot(s.x(), s.y());
        return length > 1e-6 ? s / length : QPointF();
    };
    m_dragDu = screenDirection(frame.du);
    m_dragDv = screenDirection(frame.dv);
    // H + alpha du tilts H by atan(alpha): on a surface of curvature radius r the highlight moves
    // about r * alpha; the distance to the model's centre stands in for r.
    const Eigen::Vector3f centre
        = 0.5f * (mesh->vertices.colwise().minCoeff() + mesh->vertices.colwise().maxCoeff()).transpose();
    const double radius = std::max(double((p - centre).norm()), 1e-9);
    m_dragUnitsPerPixel = perPixel / radius;
}

void HighlightPanel::viewportDrag(const QPointF& delta, Qt::KeyboardModifiers modifiers)
{
    using T = algo::HighlightOperationType;
    const bool rotate = modifiers & Qt::ShiftModifier, scale = modifiers & Qt::ControlModifier;
    const T type = rotate ? T::Rotation : scale ? T::DirectionalScaling : T::Translation;
    const int frame = m_frame;
    const double a = delta.x() * m_dragDu.x() + delta.y() * m_dragDu.y();
    const double b = delta.x() * m_dragDv.x() + delta.y() * m_dragDv.y();
    const double perPixel = m_dragUnitsPerPixel;
    editTrack(
        rotate      ? tr("Rotate Highlight")
            : scale ? tr("Scale Highlight")
                    : tr("Move Highlight"),
        [&](model::HighlightTrack& t) {
            auto first = [type](const std::vector<algo::HighlightOperation>& ops) {
                return std::find_if(ops.begin(), ops.end(), [type](const auto& op) { return op.type == type; })
                    - ops.begin();
            };
            // Add the operation to every key (structure changes keep the keys interpolating):
            // translation and rotation at the front, scaling at the end (after any rotation).
            for (auto& k : t.keys) {
                auto& ops = k.layer.shape.operations;
                if (first(ops) == std::ptrdiff_t(ops.size()))
                    ops.insert(type == T::DirectionalScaling ? ops.end() : ops.begin(), defaultOperation(type));
            }
            algo::HighlightLayer layer = t.layerAt(frame);
            auto& ops = layer.shape.operations;
            const auto index = std::size_t(first(ops));
            if (index == ops.size())
                ops.insert(type == T::DirectionalScaling ? ops.end() : ops.begin(), defaultOperation(type));
            algo::HighlightOperation& op = ops[index];
            if (rotate) {
                op.a = float(std::clamp(op.a + delta.x() * 0.5, -360.0, 360.0));
            } else if (scale) {
                op.a = float(std::clamp(op.a + delta.x() * 0.005, 0.0, 1.0));
            } else {
                // Rotations before the translation turn its frame: undo them on the drag.
                double degrees = 0.0;
                for (std::size_t i = 0; i < index; ++i)
                    if (ops[i].type == T::Rotation)
                        degrees += ops[i].a;
                const double c = std::cos(degrees * 0.017453292519943295), s = std::sin(degrees * 0.017453292519943295);
                op.a += float((c * a + s * b) * perPixel);
                op.b += float((-s * a + c * b) * perPixel);
            }
            t.setKey(frame, layer);
        },
        QStringLiteral("viewportDrag%1@%2").arg(m_dragCount).arg(frame));
}

void HighlightPanel::setCurrentFrame(int frame)
{
    frame = std::clamp(frame, 0, m_lastFrame->value());
    if (frame == m_frame)
        return;
    m_frame = frame;
    refresh();
    emit frameChanged(frame);
    if (m_viewport)
        m_viewport->setFrame(frame);
}

int HighlightPanel::selectedLayer() const
{
    const int row = m_layers->currentRow();
    return row >= 0 && row < int(m_document->data().look.highlights.size()) ? row : -1;
}

void HighlightPanel::selectLayer(int index)
{
    m_layers->setCurrentRow(index);
    refresh();
}

const model::HighlightTrack* HighlightPanel::track() const
{
    const int row = selectedLayer();
    return row < 0 ? nullptr : &m_document->data().look.highlights[std::size_t(row)];
}

std::vector<QString> HighlightPanel::faceSetNames() const
{
    return m_document->data().faceSetNames();
}

void HighlightPanel::edit(
    const QString& undoText, const std::function<void(model::Look&)>& change, const QString& mergeKey)
{
    if (m_updating)
        return;
    model::Look look = m_document->data().look;
    change(look);
    if (look == m_document->data().look)
        return;
    if (!model::highlightTracksProblem(look.highlights, faceSetNames()).isEmpty()) {
        refresh(); // never push tracks the renderer refuses; the controls go back to the look
        return;
    }
    QUndoStack* undo = m_document->undoStack();
    // Document::setLook merges every consecutive look change; each edit here is its own undo step
    // (a macro, which nothing merges into) except a run of the same control on the same key, whose
    // step is replaced by one from the run's start to its latest value.
    const bool continuing = !mergeKey.isEmpty() && mergeKey == m_lastMergeKey && undo->index() == m_lastUndoIndex
        && undo->count() == m_lastUndoIndex && m_lastUndoIndex > 0;
    if (continuing) {
        m_updating = true; // the undone look passes through the controls without editing
        undo->undo();
        m_updating = false;
    }
    if (look != m_document->data().look) {
        undo->beginMacro(undoText);
        m_document->setLook(look);
        undo->endMacro();
    }
    m_lastMergeKey = mergeKey;
    m_lastUndoIndex = undo->index();
}

void HighlightPanel::editTrack(
    const QString& undoText, const std::function<void(model::HighlightTrack&)>& change, const QString& mergeKey)
{
    const int row = selectedLayer();
    if (row < 0)
        return;
    edit(
        undoText, [&](model::Look& l) { change(l.highlights[std::size_t(row)]); },
        mergeKey.isEmpty() ? QString() : QStringLiteral("%1/%2").arg(row).arg(mergeKey));
}

void HighlightPanel::editKey(
    const QString& undoText, const std::function<void(algo::HighlightLayer&)>& change, const QString& mergeKey)
{
    const int frame = m_frame;
    editTrack(
        undoText,
        [&](model::HighlightTrack& t) {
            algo::HighlightLayer layer = t.layerAt(frame);
            change(layer);
            t.setKey(frame, layer);
        },
        mergeKey.isEmpty() ? QString() : QStringLiteral("%1@%2").arg(mergeKey).arg(frame));
}

void HighlightPanel::editOperations(
    const QString& undoText, const std::function<void(std::vector<algo::HighlightOperation>&)>& change)
{
    // Structure changes go to every key so that the keys keep interpolating.
    editTrack(undoText, [&](model::HighlightTrack& t) {
        for (auto& k : t.keys)
            change(k.layer.shape.operations);
    });
}

void HighlightPanel::jumpToKey(int direction)
{
    const model::HighlightTrack* t = track();
    if (!t)
        return;
    std::optional<int> target;
    for (const auto& k : t->keys) {
        const int f = int(std::lround(k.frame));
        if (direction < 0 && f < m_frame)
            target = f;
        if (direction > 0 && f > m_frame && !target)
            target = f;
    }
    if (target) {
        if (*target > m_lastFrame->value())
            m_lastFrame->setValue(*target);
        setCurrentFrame(*target);
    }
}

void HighlightPanel::rebuildOperations(const algo::HighlightLayer& layer)
{
    std::vector<algo::HighlightOperationType> types;
    for (const auto& op : layer.shape.operations)
        types.push_back(op.type);
    if (types != m_operationTypes) {
        while (QLayoutItem* item = m_operationRows->takeAt(0)) {
            if (QWidget* w = item->widget()) {
                w->hide();
                w->deleteLater(); // one of its spin boxes may be emitting now
            }
            delete item;
        }
        m_operationSpins.clear();
        m_operationTypes = types;
        const int count = int(types.size());
        for (int i = 0; i < count; ++i) {
            auto* row = new QWidget(m_operationsBox);
            auto* h = new QHBoxLayout(row);
            h->setContentsMargins(0, 0, 0, 0);
            auto* title = new QLabel(operationTitle(types[std::size_t(i)]), row);
            title->setMinimumWidth(56);
            h->addWidget(title);
            const auto specs = operationSpecs(types[std::size_t(i)]);
            QDoubleSpinBox* spins[2] = {nullptr, nullptr};
            const ParameterSpec* s[2] = {&specs.first, &specs.second};
            for (int p = 0; p < 2; ++p) {
                if (!s[p]->name)
                    continue;
                h->addWidget(new QLabel(tr(s[p]->name), row));
                spins[p] = makeSpin(s[p]->min, s[p]->max, s[p]->step, s[p]->decimals, tr(s[p]->tip) + tr(" (keyed)"));
                spins[p]->setParent(row);
                spins[p]->setObjectName(QStringLiteral("highlightOperation%1%2").arg(i).arg(p == 0 ? 'a' : 'b'));
                spins[p]->setMinimumWidth(40);
                spins[p]->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
                h->addWidget(spins[p], 1);
                connect(spins[p], qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, i, p](double v) {
                    editKey(
                        tr("Change Highlight Operation"),
                        [i, p, v](algo::HighlightLayer& l) {
                            if (i < int(l.shape.operations.size()))
                                (p == 0 ? l.shape.operations[std::size_t(i)].a : l.shape.operations[std::size_t(i)].b)
                                    = float(v);
                        },
                        QStringLiteral("op%1.%2").arg(i).arg(p));
                });
            }
            if (!spins[1])
                h->addStretch(1);
            auto addButton = [&](Qt::ArrowType arrow, const QString& text, const QString& tip, bool enabled) {
                auto* b = new QToolButton(row);
                if (arrow != Qt::NoArrow)
                    b->setArrowType(arrow);
                else
                    b->setText(text);
                b->setToolTip(tip);
                b->setEnabled(enabled);
                h->addWidget(b);
                return b;
            };
            connect(addButton(Qt::UpArrow, {}, tr("Move the operation earlier"), i > 0), &QToolButton::clicked, this,
                [this, i] {
                    editOperations(tr("Move Highlight Operation"), [i](std::vector<algo::HighlightOperation>& ops) {
                        if (i > 0 && i < int(ops.size()))
                            std::swap(ops[std::size_t(i - 1)], ops[std::size_t(i)]);
                    });
                });
            connect(addButton(Qt::DownArrow, {}, tr("Move the operation later"), i + 1 < count), &QToolButton::clicked,
                this, [this, i] {
                    editOperations(tr("Move Highlight Operation"), [i](std::vector<algo::HighlightOperation>& ops) {
                        if (i + 1 < int(ops.size()))
                            std::swap(ops[std::size_t(i)], ops[std::size_t(i + 1)]);
                    });
                });
            connect(addButton(Qt::NoArrow, tr("✕"), tr("Remove the operation from every key"), true),
                &QToolButton::clicked, this, [this, i] {
                    editOperations(tr("Remove Highlight Operation"), [i](std::vector<algo::HighlightOperation>& ops) {
                        if (i < int(ops.size()))
                            ops.erase(ops.begin() + i);
                    });
                });
            m_operationRows->addWidget(row);
            row->show(); // the layout would show it only once the event loop runs
            m_operationSpins.emplace_back(spins[0], spins[1]);
        }
    }
    for (std::size_t i = 0; i < m_operationSpins.size(); ++i) {
        const auto& op = layer.shape.operations[i];
        if (QDoubleSpinBox* a = m_operationSpins[i].first) {
            const QSignalBlocker block(a);
            a->setValue(op.a);
        }
        if (QDoubleSpinBox* b = m_operationSpins[i].second) {
            const QSignalBlocker block(b);
            b->setValue(op.b);
        }
    }
}

void HighlightPanel::rebuildCombinations(const model::HighlightTrack& t)
{
    while (QLayoutItem* item = m_combinationRows->takeAt(0)) {
        if (QWidget* w = item->widget()) {
            w->hide();
            w->deleteLater(); // one of its combo boxes may be emitting now
        }
        delete item;
    }
    const auto& tracks = m_document->data().look.highlights;
    for (int i = 0; i < int(t.combineWith.size()); ++i) {
        const auto& [mode, other] = t.combineWith[std::size_t(i)];
        auto* row = new QWidget(m_combinationsBox);
        auto* h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        auto* modeBox = new QComboBox(row);
        modeBox->addItem(tr("Union with"), int(algo::HighlightBoolean::Union));
        modeBox->addItem(tr("Subtract"), int(algo::HighlightBoolean::Subtraction));
        modeBox->setCurrentIndex(modeBox->findData(int(mode)));
        modeBox->setToolTip(tr("Union adds the other layer's area; Subtract cuts it out of this layer's area"));
        auto* otherBox = new QComboBox(row);
        for (const auto& other2 : tracks)
            if (other2.name != t.name)
                otherBox->addItem(other2.name, other2.name);
        otherBox->setCurrentIndex(otherBox->findData(other));
        otherBox->setToolTip(tr("The other layer, at the same frame"));
        auto* remove = new QToolButton(row);
        remove->setText(tr("✕"));
        remove->setToolTip(tr("Remove this combination"));
        h->addWidget(modeBox);
        h->addWidget(otherBox, 1);
        h->addWidget(remove);
        connect(modeBox, qOverload<int>(&QComboBox::activated), this, [this, i, modeBox](int index) {
            const auto m = algo::HighlightBoolean(modeBox->itemData(index).toInt());
            editTrack(tr("Change Highlight Combination"), [i, m](model::HighlightTrack& tr2) {
                if (i < int(tr2.combineWith.size()))
                    tr2.combineWith[std::size_t(i)].first = m;
            });
        });
        connect(otherBox, qOverload<int>(&QComboBox::activated), this, [this, i, otherBox](int index) {
            const QString name = otherBox->itemData(index).toString();
            editTrack(tr("Change Highlight Combination"), [i, name](model::HighlightTrack& tr2) {
                if (i < int(tr2.combineWith.size()))
                    tr2.combineWith[std::size_t(i)].second = name;
            });
        });
        connect(remove, &QToolButton::clicked, this, [this, i] {
            editTrack(tr("Remove Highlight Combination"), [i](model::HighlightTrack& tr2) {
                if (i < int(tr2.combineWith.size()))
                    tr2.combineWith.erase(tr2.combineWith.begin() + i);
            });
        });
        m_combinationRows->addWidget(row);
        row->show(); // the layout would show it only once the event loop runs
    }
}

void HighlightPanel::refresh()
{
    m_updating = true;
    const auto& tracks = m_document->data().look.highlights;
    {
        const QSignalBlocker block(m_layers);
        int row = m_layers->currentRow();
        while (m_layers->count() > int(tracks.size()))
            delete m_layers->takeItem(m_layers->count() - 1);
        while (m_layers->count() < int(tracks.size())) {
            auto* item = new QListWidgetItem(m_layers);
            item->setFlags(item->flags() | Qt::ItemIsEditable | Qt::ItemIsUserCheckable);
            item->setToolTip(tr("Checked: drawn; unchecked: used only in other layers' combinations"));
        }
        for (int i = 0; i < int(tracks.size()); ++i) {
            QListWidgetItem* item = m_layers->item(i);
            item->setText(tracks[std::size_t(i)].name);
            item->setCheckState(tracks[std::size_t(i)].visible ? Qt::Checked : Qt::Unchecked);
        }
        if (row < 0 || row >= int(tracks.size()))
            row = tracks.empty() ? -1 : 0;
        m_layers->setCurrentRow(row);
    }
    {
        const QSignalBlocker block(m_frameSpin);
        m_frameSpin->setValue(m_frame);
    }
    m_timeline->setFrame(m_frame);

    const model::HighlightTrack* t = track();
    m_removeLayer->setEnabled(t != nullptr);
    m_parameters->setEnabled(t != nullptr);
    m_operationsBox->setEnabled(t != nullptr);
    m_combinationsBox->setEnabled(t != nullptr);
    m_key->setEnabled(t != nullptr);
    m_editInViewport->setEnabled(t != nullptr && m_viewport != nullptr);
    m_paintPatch->setEnabled(t != nullptr && m_viewport != nullptr && m_document->hasMesh());
    m_newPatch->setEnabled(t != nullptr && m_document->hasMesh());
    m_renamePatch->setEnabled(t != nullptr && !t->patch.isEmpty());
    m_deletePatch->setEnabled(t != nullptr && !t->patch.isEmpty());
    if (m_viewport) {
        // Painting follows the selected layer's patch; a layer on all faces ends painting.
        if (m_viewport->tool() == Viewport::Tool::Patch && (!t || t->patch.isEmpty()))
            m_viewport->setTool(Viewport::Tool::Navigate);
        else if (t)
            m_viewport->setPatchTarget(t->patch);
    }
    const bool keyHere = t && std::any_of(t->keys.begin(), t->keys.end(), [this](const algo::HighlightKey& k) {
        return k.frame == double(m_frame);
    });
    m_deleteKey->setEnabled(keyHere && t->keys.size() > 1);
    m_previousKey->setEnabled(t && !t->keys.empty() && t->keys.front().frame < m_frame);
    m_nextKey->setEnabled(t && !t->keys.empty() && t->keys.back().frame > m_frame);
    m_addCombination->setEnabled(t && tracks.size() > 1);

    std::vector<double> keyFrames;
    const algo::HighlightLayer layer = t ? t->layerAt(m_frame) : algo::HighlightLayer{};
    if (t)
        for (const auto& k : t->keys)
            keyFrames.push_back(k.frame);
    m_timeline->setKeys(keyFrames);

    QPixmap swatch(28, 16);
    swatch.fill(toQColor(layer.color));
    m_color->setIcon(QIcon(swatch));
    for (auto [spin, value] :
        {std::pair{m_epsilon, double(layer.shape.epsilon)}, std::pair{m_cut, double(layer.offSpecularCut)}}) {
        const QSignalBlocker block(spin);
        spin->setValue(value);
    }
    const Eigen::Vector3f guide = t ? t->guide : Eigen::Vector3f(0.f, 1.f, 0.f);
    for (int axis = 0; axis < 3; ++axis) {
        const QSignalBlocker block(m_guide[axis]);
        m_guide[axis]->setValue(guide[axis]);
    }
    {
        const QSignalBlocker block(m_smoothing);
        m_smoothing->setValue(t ? t->smoothing : 0);
    }
    {
        const QSignalBlocker block(m_patch);
        m_patch->clear();
        m_patch->addItem(tr("All faces"), QString());
        for (const QString& name : faceSetNames())
            m_patch->addItem(name, name);
        const QString patch = t ? t->patch : QString();
        if (m_patch->findData(patch) < 0)
            m_patch->addItem(patch, patch);
        m_patch->setCurrentIndex(m_patch->findData(patch));
    }
    rebuildOperations(layer);
    rebuildCombinations(t ? *t : model::HighlightTrack{});
    const int visibleLayers = int(
        std::count_if(tracks.begin(), tracks.end(), [](const model::HighlightTrack& track) { return track.visible; }));
    const bool beyond = visibleLayers > kViewportHighlightLayers
        || std::any_of(tracks.begin(), tracks.end(), [](const model::HighlightTrack& track) {
               return int(track.combineWith.size()) > kViewportHighlightCombinations
                   || std::any_of(track.keys.begin(), track.keys.end(), [](const algo::HighlightKey& k) {
                          return int(k.layer.shape.operations.size()) > kViewportHighlightOperations;
                      });
           });
    m_viewportLimit->setVisible(beyond);
    m_updating = false;
}

} // namespace celform::views
