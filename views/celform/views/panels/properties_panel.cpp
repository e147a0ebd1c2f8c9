// Properties of the selection, the tools that work on it, and the blend settings, kept in sync
// with the document and the viewport.
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scrolling_panel.h"

#include <functional>

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/io_error.h"
#include "celform/views/panels/fit_group.h"
#include "celform/views/panels/gesture_tracker.h"
#include "celform/views/panels/outline_settings_box.h"
#include "celform/views/panels/thumbnail.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/viewport/viewport.h"

#include <QApplication>
#include <QCheckBox>
#include <QPointer>
#include <QSignalBlocker>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace celform::views {

PropertiesPanel::PropertiesPanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    // Scrolls rather than raising the window's minimum height (a 1366x768 screen must fit it).
    QVBoxLayout* layout = scrollingPanelLayout(this);

    m_selectionBox = new QGroupBox(tr("Selection"), this);
    m_form = new QFormLayout(m_selectionBox);
    m_summary = new QLabel(m_selectionBox);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_form->addRow(m_summary);
    m_thumbnail = new QLabel(m_selectionBox);
    m_thumbnail->setObjectName(QStringLiteral("selectionThumbnail"));
    m_thumbnail->setAlignment(Qt::AlignCenter);
    m_form->addRow(m_thumbnail);
    m_name = new QLineEdit(m_selectionBox);
    m_name->setToolTip(tr("Name shown in the scene tree and used by the command line"));
    m_form->addRow(tr("&Name:"), m_name);

    // Drawing: overlay and alignment (paper 1, section 3.1.1).
    m_opacityRow = new QWidget(m_selectionBox);
    auto* opacityLayout = new QHBoxLayout(m_opacityRow);
    opacityLayout->setContentsMargins(0, 0, 0, 0);
    m_opacity = new QSlider(Qt::Horizontal, m_opacityRow);
    m_opacity->setRange(0, 100);
    m_opacity->setToolTip(tr("Opacity of the drawing over the model in the viewport"));
    m_opacityValue = new QLabel(m_opacityRow);
    m_opacityValue->setMinimumWidth(40);
    opacityLayout->addWidget(m_opacity);
    opacityLayout->addWidget(m_opacityValue);
    m_form->addRow(tr("&Opacity:"), m_opacityRow);
    m_onTop = new QCheckBox(tr("Drawing over the &model"), m_selectionBox);
    m_onTop->setChecked(true);
    m_onTop->setToolTip(tr("Show the drawing over the model (with its opacity) or behind it as a backdrop"));
    m_form->addRow(m_onTop);
    m_align = new QPushButton(tr("&Align to Drawing"), m_selectionBox);
    m_align->setCheckable(true);
    m_align->setToolTip(tr("Show the drawing fixed in the viewport and move the camera until the model matches it "
                           "(Alt+drag orbit/pan/dolly, Alt+Shift+drag roll). The camera is stored with the drawing."));
    m_form->addRow(m_align);
    m_fov = new QDoubleSpinBox(m_selectionBox);
    m_fov->setRange(1.0, 120.0);
    m_fov->setDecimals(1);
    m_fov->setSuffix(QStringLiteral("°"));
    m_fov->setToolTip(tr("Vertical field of view of the aligned camera (perspective); a narrower angle is a longer "
                         "focal length"));
    m_form->addRow(tr("&Field of view:"), m_fov);
    m_projection = new QComboBox(m_selectionBox);
    m_projection->addItem(tr("Perspective"), int(model::Projection::Perspective));
    m_projection->addItem(tr("Orthographic"), int(model::Projection::Orthographic));
    m_projection->setToolTip(tr("Projection of the aligned camera"));
    m_form->addRow(tr("&Projection:"), m_projection);
    // Beyond the paper: solve the camera from matched points, then refine by hand.
    m_matchRow = new QWidget(m_selectionBox);
    auto* matchLayout = new QVBoxLayout(m_matchRow);
    matchLayout->setContentsMargins(0, 0, 0, 0);
    auto* matchButtons = new QHBoxLayout;
    m_match = new QPushButton(tr("&Match Points"), m_matchRow);
    m_match->setCheckable(true);
    m_match->setToolTip(tr("Click a feature on the model, then Shift+click the same feature on the drawing; repeat "
                           "for six or more features spread over the model, then Solve Camera"));
    m_solve = new QPushButton(tr("S&olve Camera"), m_matchRow);
    m_solve->setToolTip(tr("Find the camera that best projects the model points onto the drawing points"));
    m_clearPoints = new QPushButton(tr("Clear"), m_matchRow);
    m_clearPoints->setToolTip(tr("Remove every matched point"));
    matchButtons->addWidget(m_match);
    matchButtons->addWidget(m_solve);
    matchButtons->addWidget(m_clearPoints);
    matchLayout->addLayout(matchButtons);
    m_matchStatus = new QLabel(m_matchRow);
    m_matchStatus->setWordWrap(true);
    matchLayout->addWidget(m_matchStatus);
    m_form->addRow(m_matchRow);
    m_createKey = new QPushButton(tr("Create &Key from Drawing"), m_selectionBox);
    m_createKey->setToolTip(tr("Make a key viewpoint in the direction of the drawing's aligned camera, starting as a "
                               "copy of the base model"));
    m_form->addRow(m_createKey);

    // Key.
    m_enabled = new QCheckBox(tr("&Enabled in the blend"), m_selectionBox);
    m_enabled->setToolTip(tr("A disabled key keeps its deformation but takes no part in the blend"));
    m_form->addRow(m_enabled);
    m_linkedDrawing = new QComboBox(m_selectionBox);
    m_linkedDrawing->setToolTip(tr("The reference drawing shown while the key is edited"));
    m_form->addRow(tr("&Drawing:"), m_linkedDrawing);
    m_editKey = new QPushButton(tr("&Edit Key with the Brush"), m_selectionBox);
    m_editKey->setCheckable(true);
    m_editKey->setToolTip(tr("Look through the key's camera with its drawing and deform the key: drag moves in the "
                             "image plane, Ctrl+drag pushes or pulls along the view, Shift+drag rotates, "
                             "Ctrl+Shift+drag scales; [ and ] change the radius"));
    m_form->addRow(m_editKey);
    m_importDeformation = new QPushButton(tr("&Import Deformation…"), m_selectionBox);
    m_importDeformation->setToolTip(
        tr("Use a mesh made in another tool (same vertex count and order) as this key's "
           "deformation at the playhead's frame (a new keyed frame, or replacing the one there)"));
    m_form->addRow(m_importDeformation);
    layout->addWidget(m_selectionBox);
    // Fit to Drawing: the drawing's outline settings, the key's figures and fits.
    m_outlineBox = new OutlineSettingsBox(m_document, this);
    layout->addWidget(m_outlineBox);
    m_fit = new FitGroup(m_document, this);
    layout->addWidget(m_fit);

    m_brushBox = new QGroupBox(tr("Brush"), this);
    auto* brushForm = new QFormLayout(m_brushBox);
    m_radius = new QDoubleSpinBox(m_brushBox);
    m_radius->setDecimals(4);
    m_radius->setRange(1e-4, 1e4);
    m_radius->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    m_radius->setToolTip(tr("Vertices within this distance of the picked vertex (world units) follow it with the "
                            "falloff (1 − d/r)²; [ and ] in the viewport"));
    m_pixelRadius = new QSpinBox(m_brushBox);
    m_pixelRadius->setRange(1, 4096);
    m_pixelRadius->setSuffix(tr(" px"));
    m_pixelRadius->setToolTip(tr("The brush circle's radius on screen; the world radius follows the zoom at the "
                                 "picked point. [ and ] in the viewport, F to resize by dragging"));
    m_radiusUnit = new QComboBox(m_brushBox);
    m_radiusUnit->addItem(tr("World units"), false);
    m_radiusUnit->addItem(tr("Screen pixels"), true);
    m_radiusUnit->setToolTip(tr("World: the radius stays the same on the model whatever the zoom. Screen: the "
                                "circle stays the same on screen (Blender's View radius)"));
    auto* radiusRow = new QWidget(m_brushBox);
    auto* radiusLayout = new QHBoxLayout(radiusRow);
    radiusLayout->setContentsMargins(0, 0, 0, 0);
    radiusLayout->addWidget(m_radius, 1);
    radiusLayout->addWidget(m_pixelRadius, 1);
    m_pixelRadius->hide();
    brushForm->addRow(tr("&Radius:"), radiusRow);
    brushForm->addRow(tr("Radius &in:"), m_radiusUnit);
    m_falloff = new QComboBox(m_brushBox);
    m_falloff->addItem(tr("Paper (1 − d/r)²"), int(algo::BrushFalloff::Paper));
    m_falloff->addItem(tr("Smooth"), int(algo::BrushFalloff::Smooth));
    m_falloff->addItem(tr("Sphere"), int(algo::BrushFalloff::Sphere));
    m_falloff->setToolTip(tr("How the pull fades from the picked vertex to the radius. Paper: (1 − d/r)², sharp "
                             "at the centre. Smooth: flat at the centre, no spikes from small radii. Sphere: a dome"));
    brushForm->addRow(tr("&Falloff:"), m_falloff);
    m_strength = new QDoubleSpinBox(m_brushBox);
    m_strength->setRange(0.05, 1.0);
    m_strength->setSingleStep(0.05);
    m_strength->setDecimals(2);
    m_strength->setValue(1.0);
    m_strength->setToolTip(tr("Share of the cursor's motion the picked vertex follows (1: all of it)"));
    brushForm->addRow(tr("S&trength:"), m_strength);
    m_brushMode = new QComboBox(m_brushBox);
    // In the order of the brush tool's modes (brushModeEdited gives the index).
    m_brushMode->addItem(tr("Move"));
    m_brushMode->addItem(tr("Smooth"));
    m_brushMode->addItem(tr("Relax"));
    m_brushMode->setToolTip(tr("Move drags the selection; Smooth pulls it toward its neighbours while you drag (it "
                               "flattens spikes); Relax evens the vertices out along the surface and keeps the "
                               "shape and its silhouette"));
    brushForm->addRow(tr("&Mode:"), m_brushMode);
    m_mirror = new QComboBox(m_brushBox);
    m_mirror->setObjectName(QStringLiteral("brushMirror"));
    for (int i = 0; i < 4; ++i)
        m_mirror->addItem(QString(), i); // labelled by refreshMirror
    m_mirror->setToolTip(tr("Apply every stroke to the mirrored side too, across a plane through the model's centre "
                            "(X, Y or Z in model space; the detected one is marked), for symmetric characters"));
    brushForm->addRow(tr("M&irror:"), m_mirror);
    layout->addWidget(m_brushBox);

    auto* blendBox = new QGroupBox(tr("View-dependent blend"), this);
    auto* blendForm = new QFormLayout(blendBox);
    m_sharpness = new QDoubleSpinBox(blendBox);
    m_sharpness->setRange(0.1, 16.0);
    m_sharpness->setSingleStep(0.1);
    m_sharpness->setDecimals(2);
    m_sharpness->setToolTip(tr("Sharpness α of the blend weights: 1 blends linearly across the viewing sphere; "
                               "larger values hold each key longer and switch faster near facet centres."));
    blendForm->addRow(tr("&Sharpness α:"), m_sharpness);
    m_unspecified = new QComboBox(blendBox);
    m_unspecified->addItem(tr("Dummy keys (base model)"), int(model::UnspecifiedMode::Dummy));
    m_unspecified->addItem(tr("Cosine falloff"), int(model::UnspecifiedMode::Cosine));
    m_unspecified->addItem(tr("Squared cosine falloff"), int(model::UnspecifiedMode::Cosine2));
    m_unspecified->setToolTip(tr("How views far from every key are shaped: dummy keys return to the base model "
                                 "along the main axes; cosine modes fade each key out with the angle."));
    blendForm->addRow(tr("&Unspecified regions:"), m_unspecified);
    m_time = new QComboBox(blendBox);
    m_time->setObjectName(QStringLiteral("blendTime"));
    m_time->addItem(tr("Natural spline"), int(model::TimeInterpolation::NaturalSpline));
    m_time->addItem(tr("Looping cycle"), int(model::TimeInterpolation::PeriodicSpline));
    m_time->setToolTip(tr("How a key's deformations at several frames are interpolated between them: a natural "
                          "cubic spline held before the first and after the last, or a periodic one for looping "
                          "cycles, whose last keyed frame repeats the first"));
    blendForm->addRow(tr("&Time:"), m_time);
    m_preview = new QPushButton(tr("&Preview View-Dependent Shape"), blendBox);
    m_preview->setCheckable(true);
    m_preview->setToolTip(tr("Show the blend of the keys for the viewport's camera, updated while you orbit (P)"));
    blendForm->addRow(m_preview);
    layout->addWidget(blendBox);
    layout->addStretch(1);

    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        if (m_updating)
            return;
        if (m_selection.kind == ScenePanel::ItemKind::Drawing)
            m_document->drawings().renameDrawing(m_selection.id, m_name->text());
        else if (m_selection.kind == ScenePanel::ItemKind::Key)
            m_document->keys().renameKey(m_selection.id, m_name->text());
    });
    connect(m_opacity, &QSlider::valueChanged, this, [this](int value) {
        m_opacityValue->setText(QStringLiteral("%1 %").arg(value));
        if (!m_updating && m_selection.kind == ScenePanel::ItemKind::Drawing)
            m_document->drawings().setDrawingOpacity(m_selection.id, value / 100.0, GestureTracker::of(m_opacity));
    });
    connect(m_onTop, &QCheckBox::toggled, this, [this](bool on) {
        if (m_viewport)
            m_viewport->drawingOverlay().setOnTop(on);
    });
    connect(m_align, &QPushButton::toggled, this, [this](bool on) {
        if (m_updating || !m_viewport)
            return;
        if (on && m_selection.kind == ScenePanel::ItemKind::Drawing) {
            m_viewport->setDisplayedKey(0);
            m_viewport->drawingOverlay().setDrawing(m_selection.id);
            m_viewport->setTool(Viewport::Tool::Align);
        } else {
            m_viewport->setTool(Viewport::Tool::Navigate);
        }
        refreshTools();
    });
    connect(m_match, &QPushButton::toggled, this, [this](bool on) {
        if (m_updating || !m_viewport)
            return;
        if (on && m_viewport->tool() != Viewport::Tool::Align)
            m_align->setChecked(true);
        emit pointMatchingToggled(on);
        refreshMatching();
    });
    connect(m_solve, &QPushButton::clicked, this, [this] {
        if (m_viewport)
            emit solveCameraRequested();
    });
    connect(m_clearPoints, &QPushButton::clicked, this, [this] {
        if (m_viewport)
            emit clearMatchedPointsRequested();
    });
    connect(m_fov, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double degrees) {
        if (m_updating || !m_viewport)
            return;
        model::Camera c = m_viewport->camera();
        c.fovYDegrees = degrees;
        m_viewport->setCamera(c);
    });
    connect(m_projection, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (!m_updating && m_viewport)
            m_viewport->setProjection(model::Projection(m_projection->itemData(index).toInt()));
    });
    connect(m_createKey, &QPushButton::clicked, this, [this] {
        if (m_selection.kind != ScenePanel::ItemKind::Drawing)
            return;
        try {
            if (m_viewport && m_viewport->tool() == Viewport::Tool::Align)
                m_viewport->setTool(Viewport::Tool::Navigate); // stores the alignment first
            emit keyCreated(m_document->keys().createKeyFromDrawing(m_selection.id));
            // The status bar points at Edit Key with the Brush: the panel, scrolled down to Create
            // Key, shows it once the key's rows are laid out.
            QTimer::singleShot(0, this, [this] { revealRow(m_editKey); });
        } catch (const model::EditRefused& e) {
            emit message(e.message());
            QMessageBox::information(this, tr("Create Key"), e.message());
        }
    });
    connect(m_enabled, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_updating && m_selection.kind == ScenePanel::ItemKind::Key)
            m_document->keys().setKeyEnabled(m_selection.id, on);
    });
    connect(m_linkedDrawing, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        if (m_selection.kind != ScenePanel::ItemKind::Key)
            return;
        m_document->keys().linkKeyDrawing(m_selection.id, m_linkedDrawing->itemData(index).toULongLong());
        if (m_viewport && m_viewport->displayedKey() == m_selection.id)
            m_viewport->drawingOverlay().setDrawing(m_linkedDrawing->itemData(index).toULongLong());
    });
    connect(m_editKey, &QPushButton::toggled, this, [this](bool on) {
        if (m_updating || !m_viewport)
            return;
        const model::KeyViewpoint* key
            = m_selection.kind == ScenePanel::ItemKind::Key ? m_document->data().key(m_selection.id) : nullptr;
        if (on && key) {
            // Paper 1, section 3.1.2: deform in the key's camera, with its drawing for reference.
            m_viewport->setTool(Viewport::Tool::Navigate);
            m_viewport->setCamera(key->camera);
            m_viewport->drawingOverlay().setDrawing(key->drawingIds.empty() ? 0 : key->drawingIds.front());
            m_viewport->setDisplayedKey(key->id);
            m_viewport->setTool(Viewport::Tool::Brush);
        } else {
            m_viewport->setTool(Viewport::Tool::Navigate);
            m_viewport->setDisplayedKey(0);
        }
        refreshTools();
    });
    connect(m_importDeformation, &QPushButton::clicked, this, &PropertiesPanel::importDeformation);
    connect(m_radius, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double r) {
        if (!m_updating)
            emit brushRadiusEdited(r);
    });
    connect(m_pixelRadius, qOverload<int>(&QSpinBox::valueChanged), this, [this](int px) {
        if (!m_updating)
            emit brushPixelRadiusEdited(px);
    });
    connect(m_radiusUnit, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        const bool pixels = m_radiusUnit->itemData(index).toBool();
        m_radius->setVisible(!pixels);
        m_pixelRadius->setVisible(pixels);
        emit brushRadiusInPixelsEdited(pixels);
    });
    auto applyProfile = [this] {
        emit brushProfileEdited({algo::BrushFalloff(m_falloff->currentData().toInt()), m_strength->value()});
    };
    connect(m_falloff, qOverload<int>(&QComboBox::currentIndexChanged), this, applyProfile);
    connect(m_strength, qOverload<double>(&QDoubleSpinBox::valueChanged), this, applyProfile);
    connect(m_brushMode, qOverload<int>(&QComboBox::currentIndexChanged), this, &PropertiesPanel::brushModeEdited);
    // One mirror for the brush and Fit Shape, shown in both groups; the plane is the project's.
    connect(m_mirror, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (index > 0)
            m_document->keys().setMirrorPlane(model::MirrorPlane(index));
        m_fit->mirrorBox()->setChecked(index > 0);
        emit brushMirrorEdited(index > 0);
    });
    connect(m_fit, &FitGroup::mirrorEdited, this, &PropertiesPanel::setMirrorOn);
    refreshMirror();
    connect(m_outlineBox, &OutlineSettingsBox::message, this, &PropertiesPanel::message);
    GestureTracker::track(m_sharpness, m_document);
    connect(m_sharpness, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double value) {
        if (!m_updating)
            m_document->look().setSharpness(value, GestureTracker::of(m_sharpness));
    });
    connect(m_unspecified, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (!m_updating)
            m_document->look().setUnspecifiedMode(model::UnspecifiedMode(m_unspecified->itemData(index).toInt()));
    });
    connect(m_time, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (!m_updating)
            m_document->look().setTimeInterpolation(model::TimeInterpolation(m_time->itemData(index).toInt()));
    });
    connect(m_preview, &QPushButton::toggled, this, [this](bool on) {
        if (m_updating || !m_viewport)
            return;
        // The preview changes the shape, never the camera: the drawing (and with it the frame
        // the camera fits) stays as it is.
        if (on)
            m_viewport->setTool(Viewport::Tool::Navigate);
        m_viewport->setPreview(on);
        refreshTools();
    });
    connect(m_document, &model::Document::changed, this, &PropertiesPanel::documentChanged);
    // Moved-vertex counts follow a brush stroke at once, then at most five times a second rather
    // than at every step (the last step's counts come when the stroke pauses or ends).
    m_summaryRefresh.setSingleShot(true);
    m_summaryRefresh.setInterval(200);
    connect(&m_summaryRefresh, &QTimer::timeout, this, [this] {
        if (m_summaryPending) {
            m_summaryPending = false;
            refresh();
        }
    });
    GestureTracker::track(m_opacity, m_document);
    refresh();
    refreshBlend();
    letRowsNarrow(this);
}

void PropertiesPanel::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    if (change.reset || change.has(Part::Mesh)) {
        // A radius of a few percent of the model is a useful first brush on any scale.
        if (m_document->hasMesh())
            emit brushRadiusEdited(defaultBrushRadius());
    }
    if (change.reset || change.has(Part::Blend))
        refreshBlend();
    if (change.reset || change.has(Part::Mesh) || change.has(Part::Keys))
        refreshMirror();
    const bool selectionTouched = change.touches(m_selection.id) || change.structure;
    if (change.reset || change.has(Part::Mesh)) {
        refresh();
    } else if ((change.has(Part::Drawings) || change.has(Part::Keys)) && selectionTouched) {
        if (change.offsetsOnly && !change.structure && m_summaryRefresh.isActive()) {
            m_summaryPending = true;
        } else {
            refresh();
            if (change.offsetsOnly)
                m_summaryRefresh.start();
        }
    }
}

void PropertiesPanel::setViewport(Viewport* viewport)
{
    m_viewport = viewport;
    if (!viewport)
        return;
    connect(viewport, &Viewport::toolChanged, this, &PropertiesPanel::refreshTools);
    // The outlines the viewport's outline mode shows: extracted once for both.
    m_outlineBox->setOutlineCache(viewport->drawingOverlay().outlineCache());
    m_fit->setOutlineCache(viewport->drawingOverlay().outlineCache());
    connect(viewport, &Viewport::cameraChanged, this, [this] {
        if (m_fov->hasFocus())
            return;
        m_updating = true;
        m_fov->setValue(m_viewport->camera().fovYDegrees);
        m_projection->setCurrentIndex(m_projection->findData(int(m_viewport->projection())));
        m_updating = false;
    });
    refreshTools();
}

void PropertiesPanel::setFitActions(QAction* fitCamera, QAction* fitShape)
{
    m_outlineBox->setFitCameraAction(fitCamera);
    m_fit->setActions(fitCamera, fitShape);
}

double PropertiesPanel::defaultBrushRadius() const
{
    // A radius of a few percent of the model is a useful first brush on any scale.
    if (!m_document->hasMesh())
        return 0.0;
    return 0.08 * algo::boundingBox(m_document->data().baseMesh->vertices).diagonal().norm();
}

void PropertiesPanel::showBrushRadius(double radius, double pixels)
{
    m_updating = true;
    m_radius->setValue(radius);
    m_pixelRadius->setValue(int(std::lround(pixels)));
    m_updating = false;
}

void PropertiesPanel::showMatching(int modelPoints, int drawingPoints, bool matching)
{
    m_modelPoints = modelPoints;
    m_drawingPoints = drawingPoints;
    m_matching = matching;
    refreshMatching();
}

void PropertiesPanel::showSolveResult(std::optional<double> rms, const QString& error)
{
    if (!rms) {
        emit message(error);
        QMessageBox::information(this, tr("Solve Camera"), error);
        return;
    }
    emit message(tr("Camera solved: the points are %1 drawing pixels off on average. Refine by hand if needed.")
                     .arg(*rms, 0, 'f', 1));
    m_lastSolveError = *rms;
    refreshMatching();
}

void PropertiesPanel::showSelection(ScenePanel::Selection selection)
{
    const ScenePanel::Selection previous = m_selection;
    m_selection = selection;
    // Leaving a drawing or key ends the tools that worked on it.
    if (m_viewport && !(previous == selection)) {
        if (m_viewport->tool() == Viewport::Tool::Align && selection.kind != ScenePanel::ItemKind::Drawing)
            m_viewport->setTool(Viewport::Tool::Navigate);
        // A selected drawing shows (in Preview too) until something else is selected; then the
        // one the artist asked for with its eye, or none. Brushing keeps its key's drawing.
        if (m_viewport->tool() != Viewport::Tool::Brush) {
            if (selection.kind == ScenePanel::ItemKind::Drawing)
                m_viewport->drawingOverlay().setDrawing(selection.id);
            else if (m_viewport->tool() != Viewport::Tool::Align)
                m_viewport->drawingOverlay().showAskedFor();
        }
    }
    refresh();
}

void PropertiesPanel::importDeformation()
{
    if (m_selection.kind != ScenePanel::ItemKind::Key)
        return;
    emit importDeformationRequested(m_selection.id); // the window reads the file as a job
}

void PropertiesPanel::refreshMatching()
{
    if (!m_viewport)
        return;
    const int models = m_modelPoints, drawings = m_drawingPoints;
    const int pairs = std::min(models, drawings);
    QString status
        = tr("%1 model points, %2 drawing points: %3 pairs (six or more needed)").arg(models).arg(drawings).arg(pairs);
    if (m_lastSolveError)
        status
            += QLatin1Char('\n') + tr("Last solve: %1 px reprojection error (RMS)").arg(*m_lastSolveError, 0, 'f', 1);
    m_matchStatus->setText(status);
    // The next click, in the status bar where the eyes are.
    if (m_matching) {
        if (models <= drawings)
            emit message(tr("Match Points: click a feature on the model (pair %1)").arg(models + 1));
        else
            emit message(tr("Match Points: Shift+click the same feature on the drawing (pair %1)").arg(models));
    }
    m_solve->setEnabled(pairs >= 6);
    m_clearPoints->setEnabled(models + drawings > 0);
}

void PropertiesPanel::refreshTools()
{
    m_updating = true;
    const bool aligning = m_viewport && m_viewport->tool() == Viewport::Tool::Align;
    const bool brushing = m_viewport && m_viewport->tool() == Viewport::Tool::Brush;
    m_align->setChecked(aligning && m_selection.kind == ScenePanel::ItemKind::Drawing);
    m_editKey->setChecked(
        brushing && m_selection.kind == ScenePanel::ItemKind::Key && m_viewport->displayedKey() == m_selection.id);
    m_preview->setChecked(m_viewport && m_viewport->isPreview());
    m_brushBox->setEnabled(brushing);
    m_fov->setEnabled(aligning);
    m_projection->setEnabled(aligning);
    m_match->setChecked(m_viewport && m_matching);
    m_updating = false;
    refreshMatching();
}

void PropertiesPanel::refresh()
{
    // A focused control about to be hidden (Create Key from Drawing hides the drawing's rows) hands
    // the keyboard to the next one, a spin box, where the viewport's keys (5, P, F) would type
    // into it: the keyboard goes back to the viewport instead (see the end).
    QPointer<QWidget> focused = QApplication::focusWidget();
    if (focused && !isAncestorOf(focused))
        focused = nullptr;
    m_updating = true;
    const auto& data = m_document->data();
    const QLocale locale;
    bool isDrawing = false, isKey = false;
    m_thumbnail->clear();
    m_thumbnail->setVisible(false);
    auto showThumbnail = [this](const QImage& image) {
        if (image.isNull())
            return;
        m_thumbnail->setPixmap(drawingThumbnail(image, QSize(220, 160)));
        m_thumbnail->setVisible(true);
    };

    if (m_selection.kind == ScenePanel::ItemKind::Drawing && data.drawing(m_selection.id)) {
        const auto& d = *data.drawing(m_selection.id);
        isDrawing = true;
        m_selectionBox->setTitle(tr("Reference drawing"));
        m_summary->setText(tr("%1 × %2 pixels, %3, %4")
                               .arg(d.image.width())
                               .arg(d.image.height())
                               .arg(d.imageFormat.toUpper())
                               .arg(d.aligned ? tr("camera aligned") : tr("camera not aligned yet")));
        showThumbnail(d.image);
        m_name->setText(d.name);
        m_opacity->setValue(int(std::lround(d.opacity * 100)));
        m_opacityValue->setText(QStringLiteral("%1 %").arg(m_opacity->value()));
        m_createKey->setEnabled(d.aligned && data.baseMesh);
    } else if (m_selection.kind == ScenePanel::ItemKind::Key && data.key(m_selection.id)) {
        const auto& k = *data.key(m_selection.id);
        isKey = true;
        m_selectionBox->setTitle(tr("Key viewpoint"));
        QStringList frames;
        for (const auto& [frame, offsets] : k.offsetsByFrame)
            frames << tr("frame %1: %n vertices moved", nullptr, int(offsets.indices.size())).arg(frame);
        m_summary->setText(tr("Direction (%1, %2, %3)\n%4")
                               .arg(locale.toString(k.direction.x(), 'f', 3), locale.toString(k.direction.y(), 'f', 3),
                                   locale.toString(k.direction.z(), 'f', 3),
                                   frames.isEmpty() ? tr("No deformation yet") : frames.join('\n')));
        m_name->setText(k.name);
        m_enabled->setChecked(k.enabled);
        m_linkedDrawing->clear();
        m_linkedDrawing->addItem(tr("(none)"), QVariant::fromValue<qulonglong>(0));
        for (const auto& d : data.drawings)
            m_linkedDrawing->addItem(d.name, QVariant::fromValue<qulonglong>(d.id));
        const model::ObjectId linked = k.drawingIds.empty() ? 0 : k.drawingIds.front();
        // The key's drawing, one click away from the Scene tree.
        if (const model::Drawing* d = data.drawing(linked))
            showThumbnail(d->image);
        m_linkedDrawing->setCurrentIndex(
            std::max(0, m_linkedDrawing->findData(QVariant::fromValue<qulonglong>(linked))));
    } else if (data.baseMesh) {
        const auto& mesh = *data.baseMesh;
        const auto box = algo::boundingBox(mesh.vertices);
        const Eigen::Vector3d size = box.sizes();
        m_selectionBox->setTitle(tr("Base model"));
        m_summary->setText(tr("%1\n%2 vertices, %3 triangles\nSize %4 × %5 × %6")
                               .arg(data.baseMeshName, locale.toString(qlonglong(mesh.vertexCount())),
                                   locale.toString(qlonglong(mesh.faceCount())), locale.toString(size.x(), 'g', 4),
                                   locale.toString(size.y(), 'g', 4), locale.toString(size.z(), 'g', 4)));
    } else {
        m_selectionBox->setTitle(tr("Selection"));
        m_summary->setText(
            tr("No base model. Import a mesh with File > Import Mesh, or drop a mesh file on the window."));
    }
    for (QWidget* w :
        std::initializer_list<QWidget*>{m_opacityRow, m_onTop, m_align, m_fov, m_projection, m_matchRow, m_createKey})
        m_form->setRowVisible(w, isDrawing);
    for (QWidget* w : std::initializer_list<QWidget*>{m_enabled, m_linkedDrawing, m_editKey, m_importDeformation})
        m_form->setRowVisible(w, isKey);
    m_form->setRowVisible(m_name, isDrawing || isKey);
    m_outlineBox->setVisible(isDrawing);
    m_outlineBox->setDrawing(isDrawing ? m_selection.id : 0);
    m_fit->setVisible(isKey);
    m_fit->setKey(isKey ? m_selection.id : 0);
    if (focused && !focused->isVisibleTo(this) && m_viewport)
        m_viewport->setFocus(Qt::OtherFocusReason);
    m_updating = false;
    refreshTools();
}

void PropertiesPanel::revealRow(QWidget* row)
{
    auto* scroll = findChild<QScrollArea*>();
    if (!scroll || !row->isVisibleTo(this))
        return;
    // The rows just shown or hidden lay out first (each layout asks its parent's in turn).
    for (int pass = 0; pass < 4; ++pass)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    // Vertically only: the panel follows the dock's width, and a wider row would shift it sideways.
    const int across = scroll->horizontalScrollBar()->value();
    scroll->ensureWidgetVisible(row, 10, 10);
    scroll->horizontalScrollBar()->setValue(across);
}

void PropertiesPanel::refreshMirror()
{
    const auto& data = m_document->data();
    const model::MirrorPlane detected
        = data.baseMesh ? model::detectMirrorPlane(*data.baseMesh) : model::MirrorPlane::Off;
    const QString names[] = {tr("Off"), tr("X"), tr("Y"), tr("Z")};
    for (int i = 0; i < 4; ++i)
        m_mirror->setItemText(i, i > 0 && i == int(detected) ? tr("%1 (detected)").arg(names[i]) : names[i]);
    // While mirroring, the choice shows the project's plane (an undo may have changed it).
    if (m_mirror->currentIndex() > 0 && m_mirror->currentIndex() != int(data.mirrorPlane)) {
        const QSignalBlocker block(m_mirror);
        m_mirror->setCurrentIndex(int(data.mirrorPlane));
        if (data.mirrorPlane == model::MirrorPlane::Off) {
            m_fit->mirrorBox()->setChecked(false);
            emit brushMirrorEdited(false);
        }
    }
}

void PropertiesPanel::setMirrorOn(bool on)
{
    if (on == (m_mirror->currentIndex() > 0))
        return;
    model::MirrorPlane plane = model::MirrorPlane::Off;
    if (on) {
        const auto& data = m_document->data();
        plane = data.mirrorPlane;
        if (plane == model::MirrorPlane::Off && data.baseMesh)
            plane = model::detectMirrorPlane(*data.baseMesh);
        if (plane == model::MirrorPlane::Off)
            plane = model::MirrorPlane::X;
    }
    m_mirror->setCurrentIndex(int(plane));
}

void PropertiesPanel::refreshBlend()
{
    m_updating = true;
    const auto& blend = m_document->data().blend;
    m_sharpness->setValue(blend.sharpness);
    m_unspecified->setCurrentIndex(m_unspecified->findData(int(blend.unspecified)));
    m_time->setCurrentIndex(m_time->findData(int(blend.time)));
    m_updating = false;
}

} // namespace celform::views
