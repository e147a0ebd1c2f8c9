// Highlight layers bound to the document: refresh() keeps every control in step with the layers
// after undo, redo, a change from the command line or the viewport, and with the playhead. Edits
// are document operations on the selected layer's id.
#include "celform/views/panels/highlight_panel.h"

#include "celform/views/panels/color_swatch.h"
#include "celform/views/timeline/frame_timeline.h"
#include "celform/views/panels/gesture_tracker.h"
#include "celform/views/panels/highlight_combinations.h"
#include "celform/views/panels/highlight_operations.h"
#include "celform/views/viewport/look_shading.h"
#include "celform/views/panels/scrolling_panel.h"
#include "celform/views/viewport/viewport.h"

#include "celform/model/data/io_error.h"

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
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>

namespace celform::views {
namespace {

constexpr int kLayerIdRole = Qt::UserRole + 1;

} // namespace

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
        const auto id = model::ObjectId(item->data(kLayerIdRole).toULongLong());
        const model::HighlightTrack* t = m_document->data().highlight(id);
        if (!t)
            return;
        const QString name = item->text().trimmed();
        const bool visible = item->checkState() == Qt::Checked;
        if (name != t->name)
            run([&] { m_document->highlights().renameHighlightLayer(id, name); });
        else if (visible != t->visible)
            m_document->highlights().setHighlightVisible(id, visible);
        refresh(); // a refused name goes back to the stored one
    });
    connect(m_addLayer, &QPushButton::clicked, this, [this] {
        const auto& tracks = m_document->data().look.highlights;
        QString name;
        for (int n = int(tracks.size()) + 1;; ++n) {
            name = tr("Highlight %1").arg(n);
            if (!m_document->data().highlightByName(name))
                break;
        }
        m_document->highlights().addHighlightLayer(name, m_document->currentFrame());
        selectLayer(int(m_document->data().look.highlights.size()) - 1);
    });
    // Presets: the paper's two worked examples as starting points (Figures 5 and 6).
    auto* presetMenu = new QMenu(m_addPreset);
    presetMenu->addAction(tr("&Window"), this, [this] { addPreset(model::HighlightPreset::Window); })
        ->setToolTip(tr("Rotation, directional scaling and split on a nearly flat part: the car window of the "
                        "paper's Figure 5"));
    presetMenu->addAction(tr("&Crescent"), this, [this] { addPreset(model::HighlightPreset::Crescent); })
        ->setToolTip(tr("A highlight minus a hidden, shifted copy of itself: the crescent of the paper's Figure 6"));
    presetMenu->setToolTipsVisible(true);
    m_addPreset->setMenu(presetMenu);
    connect(m_removeLayer, &QPushButton::clicked, this, [this] {
        if (const model::ObjectId id = selectedLayerId())
            m_document->highlights().removeHighlightLayer(id);
    });

    // --- timeline --------------------------------------------------------------------------------
    auto* timeBox = new QGroupBox(tr("Keys"), content);
    auto* timeLayout = new QVBoxLayout(timeBox);
    m_timeline = new FrameTimeline(m_document, timeBox);
    m_timeline->setObjectName(QStringLiteral("highlightTimeline"));
    timeLayout->addWidget(m_timeline);
    auto* frameRow = new QHBoxLayout;
    m_previousKey = new QToolButton(timeBox);
    m_previousKey->setArrowType(Qt::LeftArrow);
    m_previousKey->setToolTip(tr("Go to the previous key of the layer"));
    m_frameSpin = new QSpinBox(timeBox);
    m_frameSpin->setObjectName(QStringLiteral("highlightFrame"));
    m_frameSpin->setToolTip(tr("Current frame: parameters show the layer at this frame, and edits key it here"));
    m_nextKey = new QToolButton(timeBox);
    m_nextKey->setArrowType(Qt::RightArrow);
    m_nextKey->setToolTip(tr("Go to the next key of the layer"));
    // The strip shows the scene's frame range (the Timeline's): shown, not set, here.
    m_lastFrame = new QSpinBox(timeBox);
    m_lastFrame->setObjectName(QStringLiteral("highlightLastFrame"));
    m_lastFrame->setRange(-model::kMaxFrame, model::kMaxFrame);
    m_lastFrame->setReadOnly(true);
    m_lastFrame->setButtonSymbols(QAbstractSpinBox::NoButtons);
    m_lastFrame->setPrefix(tr("of "));
    m_lastFrame->setToolTip(tr("The scene's last frame (set the range in the Timeline)"));
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
    connect(m_frameSpin, qOverload<int>(&QSpinBox::valueChanged), this, [this](int f) {
        if (!m_updating)
            setCurrentFrame(f);
    });
    syncFrameRange();
    connect(m_previousKey, &QToolButton::clicked, this, [this] { jumpToKey(-1); });
    connect(m_nextKey, &QToolButton::clicked, this, [this] { jumpToKey(1); });
    connect(m_key, &QPushButton::clicked, this, [this] {
        if (const model::HighlightTrack* t = track())
            run([&] { m_document->highlights().setHighlightKey(t->id, currentFrame(), t->layerAt(currentFrame())); });
    });
    connect(m_deleteKey, &QPushButton::clicked, this, [this] {
        if (const model::ObjectId id = selectedLayerId())
            m_document->highlights().removeHighlightKey(id, currentFrame());
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
        const QColor chosen
            = QColorDialog::getColor(toQColor(t->layerAt(currentFrame()).color), this, tr("Highlight Colour"));
        if (chosen.isValid())
            editKey([&](algo::HighlightLayer& l) { l.color = fromQColor(chosen); });
    });
    m_epsilon = makeSpin(0.001, 1.0, 0.01, 3, tr("epsilon: size of the area where (N, H) > 1 - epsilon (keyed)"));
    m_epsilon->setObjectName(QStringLiteral("highlightEpsilon"));
    form->addRow(tr("&Epsilon:"), m_epsilon);
    connect(m_epsilon, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editKey([v](algo::HighlightLayer& l) { l.shape.epsilon = float(v); }, GestureTracker::of(m_epsilon));
    });
    m_cut = makeSpin(-1.0, 1.0, 0.05, 3,
        tr("Off-specular cut: no highlight where N·L is at most this value; -1 turns it off (keyed)"));
    form->addRow(tr("Off-specular c&ut:"), m_cut);
    connect(m_cut, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        editKey([v](algo::HighlightLayer& l) { l.offSpecularCut = float(v); }, GestureTracker::of(m_cut));
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
    auto* mirrorPatch = new QToolButton(patchRow);
    mirrorPatch->setObjectName(QStringLiteral("highlightPatchMirror"));
    mirrorPatch->setText(tr("Mirror"));
    mirrorPatch->setCheckable(true);
    mirrorPatch->setToolTip(tr("Paint the mirror image across the project's mirror plane too (the brush's plane, "
                               "Properties > Mirror)"));
    connect(mirrorPatch, &QToolButton::toggled, this, &HighlightPanel::patchMirrorToggled);
    patchLayout->addWidget(mirrorPatch);
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
            m_document->faceSets().renameFaceSet(t->patch, name);
        } catch (const model::EditRefused& e) {
            QMessageBox::warning(this, tr("Rename Patch"), e.message());
        }
    });
    m_deletePatch = patchMenu->addAction(tr("&Delete Patch"), this, [this] {
        if (const model::HighlightTrack* t = track(); t && !t->patch.isEmpty())
            m_document->faceSets().removeFaceSet(t->patch);
    });
    patchMenuButton->setMenu(patchMenu);
    patchLayout->addWidget(patchMenuButton);
    form->addRow(tr("&Patch:"), patchRow);
    connect(m_patch, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        if (const model::ObjectId id = selectedLayerId())
            run([&] { m_document->highlights().setHighlightPatch(id, m_patch->itemData(index).toString()); });
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
        emit patchTargetChosen(t->patch);
        m_viewport->setTool(Viewport::Tool::Patch);
    });
    auto* guideRow = new QWidget(m_parameters);
    auto* guideLayout = new QHBoxLayout(guideRow);
    guideLayout->setContentsMargins(0, 0, 0, 0);
    for (int axis = 0; axis < 3; ++axis) {
        m_guide[axis] = makeSpin(-1e3, 1e3, 0.1, 3,
            tr("Guide direction (x, y, z): the u axis of the highlight on models without UVs (not keyed)"));
        m_guide[axis]->setMinimumWidth(m_guide[axis]->minimumSizeHint().width());
        m_guide[axis]->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        guideLayout->addWidget(m_guide[axis]);
        connect(m_guide[axis], qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, axis](double v) {
            if (const model::HighlightTrack* t = track()) {
                Eigen::Vector3f guide = t->guide;
                guide[axis] = float(v);
                run([&] {
                    m_document->highlights().setHighlightGuide(t->id, guide, GestureTracker::of(m_guide[axis]));
                });
            }
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
    GestureTracker::track(m_smoothing, m_document);
    form->addRow(tr("&Smooth normals:"), m_smoothing);
    connect(m_smoothing, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        if (const model::ObjectId id = selectedLayerId(); id && !m_updating)
            run([&] { m_document->highlights().setHighlightSmoothing(id, v, GestureTracker::of(m_smoothing)); });
    });
    m_editInViewport = new QPushButton(tr("Edit in &Viewport"), m_parameters);
    m_editInViewport->setObjectName(QStringLiteral("highlightEditInViewport"));
    m_editInViewport->setCheckable(true);
    m_editInViewport->setToolTip(tr("Drag on the model to move the highlight; Shift+drag rotates it, Ctrl+drag "
                                    "scales it (keyed at the current frame)"));
    form->addRow(m_editInViewport);
    connect(m_editInViewport, &QPushButton::toggled, this, [this](bool on) {
        if (!m_viewport)
            return;
        emit highlightTargetChosen(selectedLayerId());
        if (on || m_viewport->tool() == Viewport::Tool::Highlight)
            m_viewport->setTool(on ? Viewport::Tool::Highlight : Viewport::Tool::Navigate);
    });
    layout->addWidget(m_parameters);

    m_operations = new HighlightOperationsBox(m_document, content);
    layout->addWidget(m_operations);
    m_combinations = new HighlightCombinationsBox(m_document, content);
    layout->addWidget(m_combinations);
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

    connect(m_document, &model::Document::changed, this, &HighlightPanel::documentChanged);
    refresh();
    letRowsNarrow(this);
}

void HighlightPanel::syncFrameRange()
{
    const model::SceneTime& time = m_document->data().time;
    m_lastFrame->setValue(time.lastFrame);
    m_timeline->setLastFrame(time.lastFrame);
    const QSignalBlocker block(m_frameSpin);
    m_frameSpin->setRange(time.firstFrame, time.lastFrame);
}

void HighlightPanel::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    if (change.reset || change.has(Part::SceneTime))
        syncFrameRange();
    if (change.reset || change.has(Part::Highlights) || change.has(Part::FaceSets) || change.has(Part::Mesh)
        || change.has(Part::Playhead))
        refresh();
}

void HighlightPanel::run(const std::function<void()>& operation)
{
    if (m_updating)
        return;
    try {
        operation();
    } catch (const model::EditRefused&) {
        refresh(); // never stored: the controls go back to the layer
    }
}

void HighlightPanel::editKey(const std::function<void(algo::HighlightLayer&)>& change, model::GestureId gesture)
{
    const model::HighlightTrack* t = track();
    if (!t || m_updating)
        return;
    const int frame = currentFrame();
    algo::HighlightLayer layer = t->layerAt(frame);
    change(layer);
    run([&] { m_document->highlights().setHighlightKey(t->id, frame, layer, gesture); });
}

void HighlightPanel::addPreset(model::HighlightPreset preset)
{
    // The new layers sit on the selected layer's patch, with its guide and smoothing.
    std::vector<model::ObjectId> added;
    run([&] { added = m_document->highlights().addHighlightPreset(preset, selectedLayerId(), currentFrame()); });
    if (!added.empty())
        selectLayer(int(m_document->data().look.highlights.size()) - 1);
}

void HighlightPanel::newPatchForLayer()
{
    const model::HighlightTrack* t = track();
    if (!t || !m_document->hasMesh())
        return;
    const model::ObjectId id = t->id;
    QString name;
    run([&] { name = m_document->faceSets().newFaceSetForLayer(id, tr("%1 patch").arg(t->name)); });
    if (m_viewport && m_viewport->tool() == Viewport::Tool::Patch && !name.isEmpty())
        emit patchTargetChosen(name);
}

QDoubleSpinBox* HighlightPanel::makeSpin(double min, double max, double step, int decimals, const QString& tip)
{
    auto* spin = new QDoubleSpinBox(this);
    spin->setRange(min, max);
    spin->setSingleStep(step);
    spin->setDecimals(decimals);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(false); // typing "0.35" is one edit, not four
    GestureTracker::track(spin, m_document); // holding an arrow or a key is one undo step
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
}

void HighlightPanel::setCurrentFrame(int frame)
{
    const model::SceneTime& time = m_document->data().time;
    m_document->setCurrentFrame(std::clamp(frame, time.firstFrame, time.lastFrame));
}

void HighlightPanel::jumpToKey(int direction)
{
    const model::HighlightTrack* t = track();
    if (!t)
        return;
    const int now = currentFrame();
    std::optional<int> target;
    for (const auto& k : t->keys) {
        const int f = int(std::lround(k.frame));
        if (direction < 0 && f < now)
            target = f;
        if (direction > 0 && f > now && !target)
            target = f;
    }
    if (target)
        setCurrentFrame(*target);
}

int HighlightPanel::selectedLayer() const
{
    const int row = m_layers->currentRow();
    return row >= 0 && row < int(m_document->data().look.highlights.size()) ? row : -1;
}

model::ObjectId HighlightPanel::selectedLayerId() const
{
    const int row = selectedLayer();
    return row < 0 ? 0 : m_document->data().look.highlights[std::size_t(row)].id;
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

void HighlightPanel::refresh()
{
    m_updating = true;
    const auto& tracks = m_document->data().look.highlights;
    const int frame = currentFrame();
    {
        // The selection follows the layer's id through insertions and removals.
        const QSignalBlocker block(m_layers);
        const QListWidgetItem* current = m_layers->currentItem();
        const auto selectedId = current ? model::ObjectId(current->data(kLayerIdRole).toULongLong()) : 0;
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
            item->setData(kLayerIdRole, QVariant::fromValue<qulonglong>(tracks[std::size_t(i)].id));
            item->setCheckState(tracks[std::size_t(i)].visible ? Qt::Checked : Qt::Unchecked);
            if (tracks[std::size_t(i)].id == selectedId)
                row = i;
        }
        if (row < 0 || row >= int(tracks.size()))
            row = tracks.empty() ? -1 : 0;
        m_layers->setCurrentRow(row);
    }
    {
        const QSignalBlocker block(m_frameSpin);
        m_frameSpin->setValue(frame);
    }

    const model::HighlightTrack* t = track();
    m_removeLayer->setEnabled(t != nullptr);
    m_parameters->setEnabled(t != nullptr);
    m_key->setEnabled(t != nullptr);
    m_editInViewport->setEnabled(t != nullptr && m_viewport != nullptr);
    m_paintPatch->setEnabled(t != nullptr && m_viewport != nullptr && m_document->hasMesh());
    m_newPatch->setEnabled(t != nullptr && m_document->hasMesh());
    m_renamePatch->setEnabled(t != nullptr && !t->patch.isEmpty());
    m_deletePatch->setEnabled(t != nullptr && !t->patch.isEmpty());
    if (m_viewport) {
        emit highlightTargetChosen(t ? t->id : 0);
        // Painting follows the selected layer's patch; a layer on all faces ends painting.
        if (m_viewport->tool() == Viewport::Tool::Patch && (!t || t->patch.isEmpty()))
            m_viewport->setTool(Viewport::Tool::Navigate);
        else if (t)
            emit patchTargetChosen(t->patch);
    }
    const bool keyHere = t && std::any_of(t->keys.begin(), t->keys.end(), [frame](const algo::HighlightKey& k) {
        return k.frame == double(frame);
    });
    m_deleteKey->setEnabled(keyHere && t->keys.size() > 1);
    m_previousKey->setEnabled(t && !t->keys.empty() && t->keys.front().frame < frame);
    m_nextKey->setEnabled(t && !t->keys.empty() && t->keys.back().frame > frame);

    std::vector<double> keyFrames;
    const algo::HighlightLayer layer = t ? t->layerAt(frame) : algo::HighlightLayer{};
    if (t)
        for (const auto& k : t->keys)
            keyFrames.push_back(k.frame);
    m_timeline->setKeys(keyFrames);

    // A new icon asks for a new layout of the dock: only when the colour changed (this runs on
    // every played frame).
    const QColor colour = toQColor(layer.color);
    if (colour != m_swatchColour || m_color->icon().isNull()) {
        m_swatchColour = colour;
        QPixmap swatch(28, 16);
        swatch.fill(colour);
        m_color->setIcon(QIcon(swatch));
    }
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
        // Rebuilt only when the face sets change: a key edit leaves the list as it is.
        const QSignalBlocker block(m_patch);
        QStringList wanted{QString()};
        for (const QString& name : m_document->data().faceSetNames())
            wanted << name;
        const QString patch = t ? t->patch : QString();
        if (!wanted.contains(patch))
            wanted << patch;
        QStringList shown;
        for (int i = 0; i < m_patch->count(); ++i)
            shown << m_patch->itemData(i).toString();
        if (shown != wanted) {
            m_patch->clear();
            for (const QString& name : wanted)
                m_patch->addItem(name.isEmpty() ? tr("All faces") : name, name);
        }
        m_patch->setCurrentIndex(m_patch->findData(patch));
    }
    m_operations->showLayer(t ? t->id : 0);
    m_combinations->showLayer(t ? t->id : 0);
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
