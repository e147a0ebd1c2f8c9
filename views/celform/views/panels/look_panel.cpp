// Look controls bound to the document: a list of refreshers keeps every control in step with the
// look after undo, redo or a change from the command line or the viewport.
#include "celform/views/panels/look_panel.h"

#include "celform/views/panels/scrolling_panel.h"

#include "celform/views/panels/color_swatch.h"
#include "celform/views/panels/gesture_tracker.h"
#include "celform/model/data/io_error.h"

#include "celform/algorithms/stroke_refine.h"
#include "celform/algorithms/subdivision.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QPushButton>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace celform::views {
namespace {

void paintSwatch(QToolButton* button, const Eigen::Vector3f& color)
{
    QPixmap swatch(28, 16);
    swatch.fill(toQColor(color));
    button->setIcon(QIcon(swatch));
}

} // namespace

LookPanel::LookPanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    QVBoxLayout* layout = scrollingPanelLayout(this);
    QWidget* content = layout->parentWidget();

    // --- shading -------------------------------------------------------------------------------
    auto* shadingBox = new QGroupBox(tr("Shading"), content);
    auto* shadingForm = new QFormLayout(shadingBox);
    m_style = new QComboBox(shadingBox);
    m_style->addItem(tr("Toon"), int(model::ShadingStyle::Toon));
    m_style->addItem(tr("Gooch warm/cool"), int(model::ShadingStyle::Gooch));
    m_style->addItem(tr("Comic hatching"), int(model::ShadingStyle::Comic));
    m_style->addItem(tr("Lambert"), int(model::ShadingStyle::Lambert));
    m_style->setToolTip(tr("Toon: flat tones; Gooch: warm and cool lights; Comic: shadows drawn as strokes; "
                           "Lambert: plain diffuse shading for modelling"));
    shadingForm->addRow(tr("&Style:"), m_style);
    m_material = new QComboBox(shadingBox);
    m_material->setToolTip(tr("The style applies to every material, or to one material only"));
    shadingForm->addRow(tr("&Applies to:"), m_material);
    connect(m_style, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        const auto style = model::ShadingStyle(m_style->itemData(index).toInt());
        const int material = m_material->currentData().toInt();
        if (!m_updating)
            m_document->look().setShadingStyle(style, material);
    });
    connect(m_material, qOverload<int>(&QComboBox::activated), this, [this](int) { refresh(); });
    m_refreshers.push_back([this] {
        // Materials of the base model; a mesh without materials has the one default material.
        const int previous = m_material->currentData().isValid() ? m_material->currentData().toInt() : -1;
        m_material->clear();
        m_material->addItem(tr("All materials"), -1);
        if (const auto& mesh = m_document->data().baseMesh)
            for (size_t m = 0; m < mesh->materials.size(); ++m)
                m_material->addItem(QString::fromStdString(mesh->materials[m].name), int(m));
        m_material->setCurrentIndex(std::max(0, m_material->findData(previous)));
        m_material->setEnabled(m_material->count() > 2);
        const int material = m_material->currentData().toInt();
        const auto& look = m_document->data().look;
        m_style->setCurrentIndex(m_style->findData(int(material < 0 ? look.style : look.styleOf(material))));
    });

    auto* lightType = new QComboBox(shadingBox);
    lightType->addItem(tr("Directional"), int(model::LightType::Directional));
    lightType->addItem(tr("Point"), int(model::LightType::Point));
    lightType->setToolTip(tr("Directional: the vector points from the model towards the light. Point: the light's "
                             "position in model space."));
    shadingForm->addRow(tr("&Light:"), lightType);
    connect(lightType, qOverload<int>(&QComboBox::activated), this, [this, lightType](int index) {
        const auto type = model::LightType(lightType->itemData(index).toInt());
        editLight([type](model::Light& l) {
            if (l.type == type)
                return;
            l.type = type;
            if (type == model::LightType::Directional && l.vector.norm() > 0)
                l.vector.normalize();
        });
    });
    m_refreshers.push_back(
        [this, lightType] { lightType->setCurrentIndex(lightType->findData(int(currentLight().type))); });
    auto* lightRow = new QWidget(shadingBox);
    auto* lightLayout = new QHBoxLayout(lightRow);
    lightLayout->setContentsMargins(0, 0, 0, 0);
    for (int axis = 0; axis < 3; ++axis) {
        QDoubleSpinBox* spin = makeSpin(-1e4, 1e4, 0.05, 3, tr("Light vector (x, y, z)"));
        // Room for "-0.000" and the arrows: in a narrow dock the row goes below its label
        // (letRowsNarrow) rather than cutting the values to "0.40(".
        spin->setMinimumWidth(spin->fontMetrics().horizontalAdvance(QStringLiteral("-0.000")) + 28);
        spin->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        lightLayout->addWidget(spin);
        connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            [this, axis](double v) { editLight([axis, v](model::Light& l) { l.vector[axis] = v; }); });
        m_refreshers.push_back([this, spin, axis] { spin->setValue(currentLight().vector[axis]); });
    }
    shadingForm->addRow(tr("Light &vector:"), lightRow);
    shadingForm->addRow(tr("&Background:"),
        makeColorButton(
            tr("Colour behind the model"), [](const model::Look& l) { return l.backgroundColor; },
            [this](const Eigen::Vector3f& c) { m_document->look().setBackgroundColor(c); }));
    layout->addWidget(shadingBox);

    // --- smooth surface (issue 25) --------------------------------------------------------------
    auto* surfaceBox = new QGroupBox(tr("Smooth surface"), content);
    surfaceBox->setToolTip(tr("Loop subdivision of the base model: tones and lines are drawn on a smooth "
                              "surface instead of the facets of a coarse mesh"));
    auto* surfaceForm = new QFormLayout(surfaceBox);
    auto* renderLevel = new QSpinBox(surfaceBox);
    renderLevel->setObjectName(QStringLiteral("renderSubdivision"));
    renderLevel->setRange(0, algo::kMaxSubdivisionLevel);
    renderLevel->setToolTip(tr("Subdivision level of renders and of the depth analysis: 0 is the control mesh, "
                               "each level has four times the triangles of the one before"));
    surfaceForm->addRow(tr("&Render level:"), renderLevel);
    connect(renderLevel, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        edit(&model::Look::subdivision, &model::LookEdits::setSubdivision,
            [v](model::SubdivisionLook& s) { s.level = v; });
    });
    auto* viewportLevel = new QSpinBox(surfaceBox);
    viewportLevel->setObjectName(QStringLiteral("viewportSubdivision"));
    viewportLevel->setRange(-1, algo::kMaxSubdivisionLevel);
    viewportLevel->setSpecialValueText(tr("Same as render"));
    viewportLevel->setToolTip(tr("Subdivision level the viewport shows: the render level by default, so that the "
                                 "viewport shows what renders show; a lower level is faster to draw (never above "
                                 "the render level). Keys 1 and 3 switch between the control mesh and this level"));
    surfaceForm->addRow(tr("&Viewport level:"), viewportLevel);
    connect(viewportLevel, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        edit(&model::Look::subdivision, &model::LookEdits::setSubdivision,
            [v](model::SubdivisionLook& s) { s.viewportLevel = v; });
    });
    m_refreshers.push_back([this, renderLevel, viewportLevel] {
        const model::SubdivisionLook& s = m_document->data().look.subdivision;
        renderLevel->setValue(s.level);
        viewportLevel->setValue(s.viewportLevel);
    });
    layout->addWidget(surfaceBox);

    // --- toon tones ----------------------------------------------------------------------------
    m_toonBox = new QGroupBox(tr("Toon tones"), content);
    m_toneForm = new QFormLayout(m_toonBox);
    auto* evaluation = new QComboBox(m_toonBox);
    evaluation->addItem(tr("Per pixel"), int(algo::ToonEvaluation::PerPixel));
    evaluation->addItem(tr("Per vertex (32-entry table)"), int(algo::ToonEvaluation::PerVertexLut));
    evaluation->addItem(tr("Per face"), int(algo::ToonEvaluation::PerFace));
    evaluation->setToolTip(tr("Where N·L is evaluated: per pixel gives crisp tone boundaries; per vertex through a "
                              "32-entry table interpolates across triangles (the comic renderer's way); per face "
                              "shows each triangle's tone"));
    m_toneForm->addRow(tr("&Evaluation:"), evaluation);
    connect(evaluation, qOverload<int>(&QComboBox::activated), this, [this, evaluation](int index) {
        if (!m_updating)
            m_document->look().setToonEvaluation(algo::ToonEvaluation(evaluation->itemData(index).toInt()));
    });
    m_refreshers.push_back([this, evaluation] {
        evaluation->setCurrentIndex(evaluation->findData(int(m_document->data().look.toonEvaluation)));
    });
    m_toneCount = new QSpinBox(m_toonBox);
    m_toneCount->setRange(2, 8);
    m_toneCount->setToolTip(tr("Number of flat tones"));
    m_toneForm->addRow(tr("&Tones:"), m_toneCount);
    connect(m_toneCount, qOverload<int>(&QSpinBox::valueChanged), this, [this](int count) {
        if (m_updating)
            return;
        edit(&model::Look::toon, &model::LookEdits::setToonRamp, [count](algo::ToonRamp& toon) {
            // Evenly spaced thresholds over N.L in [-0.2, 0.8] and intensities from 0.25 to 0.95:
            // a sensible start that the artist then shapes tone by tone.
            toon.thresholds.clear();
            toon.intensities.clear();
            for (int i = 0; i < count; ++i) {
                toon.intensities.push_back(
                    count == 2 ? (i == 0 ? 0.25f : 0.75f) : 0.25f + 0.7f * float(i) / float(count - 1));
                if (i > 0)
                    toon.thresholds.push_back(count == 2 ? 0.5f : -0.2f + float(i) / float(count - 1));
            }
        });
    });
    layout->addWidget(m_toonBox);

    // --- Gooch ------------------------------------------------------------------------------------
    m_goochBox = new QGroupBox(tr("Gooch warm/cool"), content);
    auto* goochForm = new QFormLayout(m_goochBox);
    auto* preset = new QComboBox(m_goochBox);
    for (const char* name : {"auto", "default", "white", "purple", "red"})
        preset->addItem(QString::fromLatin1(name), QString::fromLatin1(name));
    preset->setItemText(0, tr("By material hue (automatic)"));
    preset->setItemText(1, tr("Default"));
    preset->setItemText(2, tr("White (no warm light)"));
    preset->setItemText(3, tr("Purple (stronger cool)"));
    preset->setItemText(4, tr("Red (more cool, less warm)"));
    preset->setToolTip(tr("The hue-adaptive rules of View-Dependent Geometry, section 3.2.4, as starting points"));
    goochForm->addRow(tr("&Preset:"), preset);
    connect(preset, qOverload<int>(&QComboBox::activated), this, [this, preset](int index) {
        const std::string name = preset->itemData(index).toString().toStdString();
        edit(&model::Look::gooch, &model::LookEdits::setGooch, [name](algo::GoochParams& g) {
            const algo::GoochParams p = name == "auto" ? model::autoGooch() : algo::goochPreset(name);
            g.preset = p.preset;
            g.ka = p.ka;
            g.k1 = p.k1;
            g.k2 = p.k2;
            g.k3 = p.k3;
            g.k4 = p.k4;
        });
    });
    m_refreshers.push_back([this, preset] {
        preset->setCurrentIndex(
            std::max(0, preset->findData(QString::fromStdString(m_document->data().look.gooch.preset))));
    });
    const std::pair<const char*, float algo::GoochParams::*> coefficients[]
        = {{"ka", &algo::GoochParams::ka}, {"k1", &algo::GoochParams::k1}, {"k2", &algo::GoochParams::k2},
            {"k3", &algo::GoochParams::k3}, {"k4", &algo::GoochParams::k4}};
    for (const auto& [name, member] : coefficients) {
        QDoubleSpinBox* spin = makeSpin(
            -4.0, 4.0, 0.05, 2, tr("C = ka·Cbase + (l1·n)(Cwarm − Cbase·k1)·k2 + (l2·n)(Ccool − Cbase·k3)·k4"));
        goochForm->addRow(QString::fromLatin1(name) + QLatin1Char(':'), spin);
        const auto m = member;
        connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, m](double v) {
            edit(&model::Look::gooch, &model::LookEdits::setGooch, [m, v](algo::GoochParams& g) { g.*m = float(v); });
        });
        m_refreshers.push_back([this, spin, m] { spin->setValue(m_document->data().look.gooch.*m); });
    }
    goochForm->addRow(tr("&Warm:"),
        makeColorButton(
            tr("Warm light colour"), [](const model::Look& l) { return l.gooch.warm; },
            [this](const Eigen::Vector3f& c) {
                edit(&model::Look::gooch, &model::LookEdits::setGooch, [c](algo::GoochParams& g) { g.warm = c; });
            }));
    goochForm->addRow(tr("&Cool:"),
        makeColorButton(
            tr("Cool light colour"), [](const model::Look& l) { return l.gooch.cool; },
            [this](const Eigen::Vector3f& c) {
                edit(&model::Look::gooch, &model::LookEdits::setGooch, [c](algo::GoochParams& g) { g.cool = c; });
            }));
    layout->addWidget(m_goochBox);

    // --- hatching -----------------------------------------------------------------------------------
    m_hatchBox = new QGroupBox(tr("Comic hatching"), content);
    auto* hatchForm = new QFormLayout(m_hatchBox);
    const std::tuple<QString, float algo::HatchParams::*, double, double, double, int, QString> hatchControls[]
        = {{tr("S&pacing:"), &algo::HatchParams::spacing, 1e-5, 1e4, 0.005, 4,
               tr("Distance between strokes, model units")},
            {tr("&Angle:"), &algo::HatchParams::angleDegrees, -180, 180, 5, 1, tr("Stroke direction, degrees")},
            {tr("W&idth:"), &algo::HatchParams::width, 0.05, 0.95, 0.05, 2,
                tr("Stroke width as a fraction of the spacing")}};
    for (const auto& [label, member, lo, hi, step, decimals, tip] : hatchControls) {
        QDoubleSpinBox* spin = makeSpin(lo, hi, step, decimals, tip);
        hatchForm->addRow(label, spin);
        const auto m = member;
        connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, m](double v) {
            edit(&model::Look::hatch, &model::LookEdits::setHatch, [m, v](algo::HatchParams& h) { h.*m = float(v); });
        });
        m_refreshers.push_back([this, spin, m] { spin->setValue(m_document->data().look.hatch.*m); });
    }
    layout->addWidget(m_hatchBox);

    // --- lines ----------------------------------------------------------------------------------------
    auto* linesBox = new QGroupBox(tr("Lines"), content);
    linesBox->setCheckable(true);
    linesBox->setToolTip(tr("Silhouettes, creases, borders, material boundaries and apparent ridges"));
    auto* linesForm = new QFormLayout(linesBox);
    connect(linesBox, &QGroupBox::toggled, this, [this](bool on) {
        if (!m_updating)
            m_document->look().setShowLines(on);
    });
    m_refreshers.push_back([this, linesBox] { linesBox->setChecked(m_document->data().look.showLines); });
    const std::pair<QString, bool algo::LineSettings::*> kinds[]
        = {{tr("Silhouettes"), &algo::LineSettings::silhouettes}, {tr("Creases"), &algo::LineSettings::creases},
            {tr("Borders (open edges)"), &algo::LineSettings::borders},
            {tr("Material boundaries"), &algo::LineSettings::materialBoundaries}};
    for (const auto& [label, member] : kinds) {
        auto* check = new QCheckBox(label, linesBox);
        linesForm->addRow(check);
        const auto m = member;
        connect(check, &QCheckBox::toggled, this, [this, m](bool on) {
            edit(
                &model::Look::lines, &model::LookEdits::setLineSettings, [m, on](algo::LineSettings& s) { s.*m = on; });
        });
        m_refreshers.push_back([this, check, m] { check->setChecked(m_document->data().look.lines.*m); });
    }
    QDoubleSpinBox* crease
        = makeSpin(1, 179, 1, 0, tr("A crease is drawn where the faces meet at more than this angle"));
    crease->setSuffix(QStringLiteral("°"));
    linesForm->addRow(tr("Crease &angle:"), crease);
    connect(crease, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::lines, &model::LookEdits::setLineSettings,
            [v](algo::LineSettings& s) { s.creaseAngleDegrees = float(v); });
    });
    m_refreshers.push_back([this, crease] { crease->setValue(m_document->data().look.lines.creaseAngleDegrees); });
    QDoubleSpinBox* creaseLow = makeSpin(0, 179, 1, 0,
        tr("Hysteresis: an edge above this angle continues a crease that is already above the crease angle, "
           "so creases on a coarse surface do not break into dashes. At or above the crease angle: off"));
    creaseLow->setSuffix(QStringLiteral("°"));
    linesForm->addRow(tr("Crease continues abo&ve:"), creaseLow);
    connect(creaseLow, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::lines, &model::LookEdits::setLineSettings,
            [v](algo::LineSettings& s) { s.creaseLowAngleDegrees = float(v); });
    });
    m_refreshers.push_back(
        [this, creaseLow] { creaseLow->setValue(m_document->data().look.lines.creaseLowAngleDegrees); });
    // Apparent ridges (paper 3, section 4.2): view-dependent lines, off by default.
    auto* ridges = new QCheckBox(tr("Apparent ridges"), linesBox);
    ridges->setToolTip(tr("Lines where the surface, as seen from the camera, bends most sharply (Judd et al. "
                          "2007): folds and bulges that are neither silhouettes nor creases. Drawn with the inner "
                          "width; they help depth perception in stereo"));
    linesForm->addRow(ridges);
    connect(ridges, &QCheckBox::toggled, this, [this](bool on) {
        edit(&model::Look::lines, &model::LookEdits::setLineSettings, [on](algo::LineSettings& s) { s.ridges = on; });
    });
    m_refreshers.push_back([this, ridges] { ridges->setChecked(m_document->data().look.lines.ridges); });
    QDoubleSpinBox* ridgeThreshold = makeSpin(0, 10, 0.05, 2,
        tr("Apparent ridges are drawn where the view-dependent curvature times the median edge length exceeds "
           "this: lower draws more (and noisier) lines, higher only the sharpest folds"));
    linesForm->addRow(tr("Ridge &threshold:"), ridgeThreshold);
    connect(ridgeThreshold, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::lines, &model::LookEdits::setLineSettings,
            [v](algo::LineSettings& s) { s.ridgeThreshold = float(v); });
    });
    m_refreshers.push_back([this, ridgeThreshold] {
        ridgeThreshold->setValue(m_document->data().look.lines.ridgeThreshold);
        ridgeThreshold->setEnabled(m_document->data().look.lines.ridges);
    });
    // Paper 3, figures 4.8 and 4.11: raw ridges, or joined into smoothed snakes.
    auto* ridgeSnakes = new QCheckBox(tr("Join ridges into smooth strokes"), linesBox);
    ridgeSnakes->setObjectName(QStringLiteral("ridgeSnakes"));
    ridgeSnakes->setToolTip(tr("Joins the ridge pieces into strokes, smooths them and drops short ones (the "
                               "thesis's snakes). Off shows the ridges as extracted, piece by piece"));
    linesForm->addRow(ridgeSnakes);
    connect(ridgeSnakes, &QCheckBox::toggled, this, [this](bool on) {
        edit(&model::Look::lines, &model::LookEdits::setLineSettings,
            [on](algo::LineSettings& s) { s.ridgeSnakes = on; });
    });
    m_refreshers.push_back([this, ridgeSnakes] {
        ridgeSnakes->setChecked(m_document->data().look.lines.ridgeSnakes);
        ridgeSnakes->setEnabled(m_document->data().look.lines.ridges);
    });
    // Paper 3, section 4.4: the threshold as a function of the stereo depth error.
    QDoubleSpinBox* ridgeDepth = makeSpin(0, 100, 0.5, 1,
        tr("Lowers the ridge threshold where the stereo depth error of the picture is high, so that more "
           "lines give the eyes something to match there (0: one threshold everywhere). Renders and the depth "
           "analysis apply it; the viewport shows the plain threshold"));
    ridgeDepth->setObjectName(QStringLiteral("ridgeDepthStrength"));
    linesForm->addRow(tr("Ridges from &depth error:"), ridgeDepth);
    connect(ridgeDepth, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::lines, &model::LookEdits::setLineSettings,
            [v](algo::LineSettings& s) { s.ridgeDepthStrength = float(v); });
    });
    m_refreshers.push_back([this, ridgeDepth] {
        ridgeDepth->setValue(m_document->data().look.lines.ridgeDepthStrength);
        ridgeDepth->setEnabled(m_document->data().look.lines.ridges);
    });
    linesForm->addRow(tr("C&olour:"),
        makeColorButton(
            tr("Line colour"), [](const model::Look& l) { return l.lineStyle.color; },
            [this](const Eigen::Vector3f& c) {
                edit(
                    &model::Look::lineStyle, &model::LookEdits::setLineStyle, [c](algo::LineStyle& s) { s.color = c; });
            }));
    const std::tuple<QString, float algo::LineStyle::*, double, double, double, QString> styleControls[] = {
        {tr("O&utline width:"), &algo::LineStyle::outlineWidth, 0, 50, 0.25, tr("Silhouettes and borders, pixels")},
        {tr("&Inner width:"), &algo::LineStyle::innerWidth, 0, 50, 0.25, tr("Creases and material boundaries, pixels")},
        {tr("&Jitter:"), &algo::LineStyle::jitter, 0, 20, 0.25, tr("Hand-drawn jagged offset, pixels")},
        {tr("Width &variation:"), &algo::LineStyle::widthVariation, 0, 1, 0.05,
            tr("Relative change of width along strokes")},
        {tr("O&vershoot:"), &algo::LineStyle::overshoot, 0, 50, 0.5, tr("Extension of stroke ends, pixels")},
        {tr("&Gap joining:"), &algo::LineStyle::joinGap, 0, 20, 0.5,
            tr("Stroke ends at most this far apart are joined into one stroke, pixels")},
        {tr("Ta&per:"), &algo::LineStyle::taper, 0, 200, 1,
            tr("Length over which strokes thin towards their ends, as a brush lifted off the paper, pixels "
               "(0: no taper)")},
        {tr("&Reduction:"), &algo::LineStyle::reduction, 0, 1, 0.05,
            tr("How much thinner the farthest line is than the nearest, as a fraction of its width (Pencil+'s "
               "reduction by distance)")}};
    for (const auto& [label, member, lo, hi, step, tip] : styleControls) {
        QDoubleSpinBox* spin = makeSpin(lo, hi, step, 2, tip);
        linesForm->addRow(label, spin);
        const auto m = member;
        connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, m](double v) {
            edit(&model::Look::lineStyle, &model::LookEdits::setLineStyle,
                [m, v](algo::LineStyle& s) { s.*m = float(v); });
        });
        m_refreshers.push_back([this, spin, m] { spin->setValue(m_document->data().look.lineStyle.*m); });
    }
    auto* smoothing = new QSpinBox(linesBox);
    smoothing->setRange(0, algo::kMaxSmoothing);
    smoothing->setToolTip(tr("Rounds of Chaikin smoothing of the projected strokes (corners stay sharp)"));
    linesForm->addRow(tr("S&moothing:"), smoothing);
    connect(smoothing, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        edit(&model::Look::lineStyle, &model::LookEdits::setLineStyle, [v](algo::LineStyle& s) { s.smoothing = v; });
    });
    m_refreshers.push_back([this, smoothing] { smoothing->setValue(m_document->data().look.lineStyle.smoothing); });
    QDoubleSpinBox* minLength = makeSpin(
        0, 20, 0.1, 1, tr("Strokes shorter than this, as a percentage of the picture's height, are dropped"));
    minLength->setSuffix(QStringLiteral(" %"));
    linesForm->addRow(tr("Minimum &length:"), minLength);
    connect(minLength, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::lineStyle, &model::LookEdits::setLineStyle,
            [v](algo::LineStyle& s) { s.minLength = float(v / 100.0); });
    });
    m_refreshers.push_back(
        [this, minLength] { minLength->setValue(100.0 * double(m_document->data().look.lineStyle.minLength)); });
    layout->addWidget(linesBox);

    // --- stereo ---------------------------------------------------------------------------------------
    auto* stereoBox = new QGroupBox(tr("Stereo"), content);
    auto* stereoForm = new QFormLayout(stereoBox);
    auto* output = new QComboBox(stereoBox);
    const std::pair<QString, algo::StereoOutput> outputs[] = {{tr("Red/cyan anaglyph"), algo::StereoOutput::Anaglyph},
        {tr("Dubois red/cyan"), algo::StereoOutput::Dubois},
        {tr("Half-colour anaglyph"), algo::StereoOutput::HalfColor},
        {tr("Side by side"), algo::StereoOutput::SideBySide}, {tr("Top and bottom"), algo::StereoOutput::TopBottom}};
    for (const auto& [label, value] : outputs)
        output->addItem(label, int(value));
    output->setToolTip(tr("How the two eyes are combined in the stereo review and stereo renders"));
    stereoForm->addRow(tr("&Output:"), output);
    connect(output, qOverload<int>(&QComboBox::activated), this, [this, output](int index) {
        const auto o = algo::StereoOutput(output->itemData(index).toInt());
        edit(&model::Look::stereo, &model::LookEdits::setStereo, [o](model::StereoLook& st) { st.output = o; });
    });
    m_refreshers.push_back([this, output] {
        output->setCurrentIndex(std::max(0, output->findData(int(m_document->data().look.stereo.output))));
    });
    QDoubleSpinBox* interocular = makeSpin(0, 1e4, 0.005, 4,
        tr("Distance between the eyes, model units; 0 = automatic "
           "(a thirtieth of the convergence distance)"));
    interocular->setSpecialValueText(tr("Automatic"));
    stereoForm->addRow(tr("&Interocular:"), interocular);
    connect(interocular, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::stereo, &model::LookEdits::setStereo, [v](model::StereoLook& st) { st.interocular = v; });
    });
    m_refreshers.push_back([this, interocular] { interocular->setValue(m_document->data().look.stereo.interocular); });
    QDoubleSpinBox* convergence = makeSpin(0, 1e6, 0.05, 3,
        tr("Distance of the zero-parallax plane from the camera; "
           "0 = automatic (the model's centre)"));
    convergence->setSpecialValueText(tr("Automatic"));
    stereoForm->addRow(tr("&Convergence:"), convergence);
    connect(convergence, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        edit(&model::Look::stereo, &model::LookEdits::setStereo, [v](model::StereoLook& st) { st.convergence = v; });
    });
    m_refreshers.push_back([this, convergence] { convergence->setValue(m_document->data().look.stereo.convergence); });
    auto* toeIn = new QCheckBox(tr("&Toe-in (instead of off-axis)"), stereoBox);
    toeIn->setToolTip(tr("Rotate the eyes towards the convergence point; off-axis (the default) avoids the keystone "
                         "distortion of toe-in"));
    stereoForm->addRow(toeIn);
    connect(toeIn, &QCheckBox::toggled, this, [this](bool on) {
        edit(&model::Look::stereo, &model::LookEdits::setStereo, [on](model::StereoLook& st) { st.toeIn = on; });
    });
    m_refreshers.push_back([this, toeIn] { toeIn->setChecked(m_document->data().look.stereo.toeIn); });
    auto* swap = new QCheckBox(tr("S&wap eyes"), stereoBox);
    stereoForm->addRow(swap);
    connect(swap, &QCheckBox::toggled, this, [this](bool on) {
        edit(&model::Look::stereo, &model::LookEdits::setStereo, [on](model::StereoLook& st) { st.swapEyes = on; });
    });
    m_refreshers.push_back([this, swap] { swap->setChecked(m_document->data().look.stereo.swapEyes); });
    auto* dubois = new QPushButton(tr("&Dubois Matrices…"), stereoBox);
    dubois->setToolTip(tr("The 3 × 3 matrices mapping each eye's linear RGB to the anaglyph (Dubois "
                          "least-squares red/cyan by default); tune them to a display and glasses"));
    stereoForm->addRow(dubois);
    connect(dubois, &QPushButton::clicked, this, &LookPanel::editDuboisMatrices);
    layout->addWidget(stereoBox);
    layout->addStretch(1);

    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        // With a light track the light shown is the one at the playhead.
        if (change.has(model::Part::Look) || change.has(model::Part::Mesh)
            || (change.has(model::Part::Playhead) && !m_document->data().look.lightTrack.empty()))
            refresh();
    });
    refresh();
    letRowsNarrow(this);
}

QDoubleSpinBox* LookPanel::makeSpin(double min, double max, double step, int decimals, const QString& tip)
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

QToolButton* LookPanel::makeColorButton(const QString& tip,
    const std::function<Eigen::Vector3f(const model::Look&)>& get,
    const std::function<void(const Eigen::Vector3f&)>& set)
{
    auto* button = new QToolButton(this);
    button->setToolTip(tip);
    button->setIconSize(QSize(28, 16));
    connect(button, &QToolButton::clicked, this, [this, get, set, tip] {
        const QColor chosen = QColorDialog::getColor(toQColor(get(m_document->data().look)), this, tip);
        if (chosen.isValid())
            set(fromQColor(chosen));
    });
    m_refreshers.push_back([this, button, get] { paintSwatch(button, get(m_document->data().look)); });
    return button;
}

void LookPanel::editDuboisMatrices()
{
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Dubois Matrices"));
    auto* layout = new QVBoxLayout(&dialog);
    const algo::DuboisMatrices current = m_document->data().look.stereo.dubois;
    QDoubleSpinBox* cells[2][3][3];
    const QString titles[2] = {tr("Left eye"), tr("Right eye")};
    const Eigen::Matrix3f* matrices[2] = {&current.left, &current.right};
    for (int eye = 0; eye < 2; ++eye) {
        auto* box = new QGroupBox(titles[eye], &dialog);
        auto* grid = new QGridLayout(box);
        const QString channels[3] = {tr("R out"), tr("G out"), tr("B out")};
        for (int r = 0; r < 3; ++r) {
            grid->addWidget(new QLabel(channels[r], box), r, 0);
            for (int c = 0; c < 3; ++c) {
                auto* spin = new QDoubleSpinBox(box);
                spin->setRange(-4.0, 4.0);
                spin->setDecimals(3);
                spin->setSingleStep(0.01);
                spin->setValue((*matrices[eye])(r, c));
                grid->addWidget(spin, r, c + 1);
                cells[eye][r][c] = spin;
            }
        }
        layout->addWidget(box);
    }
    auto* buttons = new QDialogButtonBox(
        QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::RestoreDefaults, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, &dialog, [&cells] {
        const algo::DuboisMatrices defaults = algo::DuboisMatrices::redCyan();
        const Eigen::Matrix3f* m[2] = {&defaults.left, &defaults.right};
        for (int eye = 0; eye < 2; ++eye)
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    cells[eye][r][c]->setValue((*m[eye])(r, c));
    });
    layout->addWidget(buttons);
    if (dialog.exec() != QDialog::Accepted)
        return;
    edit(&model::Look::stereo, &model::LookEdits::setStereo, [&cells](model::StereoLook& st) {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                st.dubois.left(r, c) = float(cells[0][r][c]->value());
                st.dubois.right(r, c) = float(cells[1][r][c]->value());
            }
    });
}

void LookPanel::rebuildTones()
{
    const auto& toon = m_document->data().look.toon;
    const int count = int(toon.intensities.size());
    // Rows after "Evaluation" and "Tones" are the per-tone controls.
    while (m_toneForm->rowCount() > 2)
        m_toneForm->removeRow(2);
    m_thresholds.clear();
    m_intensities.clear();
    for (int i = count - 1; i >= 0; --i) {
        auto* row = new QWidget(m_toonBox);
        auto* h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        QDoubleSpinBox* intensity = makeSpin(0, 2, 0.05, 2, tr("Brightness of this tone (multiplies the base colour)"));
        intensity->setValue(toon.intensities[std::size_t(i)]);
        h->addWidget(intensity);
        connect(intensity, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, i](double v) {
            edit(&model::Look::toon, &model::LookEdits::setToonRamp,
                [i, v](algo::ToonRamp& ramp) { ramp.intensities[std::size_t(i)] = float(v); });
        });
        if (i > 0) {
            h->addWidget(new QLabel(tr("from N·L"), row));
            QDoubleSpinBox* threshold
                = makeSpin(-1.5, 1.5, 0.05, 2, tr("The tone starts where N·L + offset reaches this value"));
            threshold->setValue(toon.thresholds[std::size_t(i - 1)]);
            h->addWidget(threshold);
            connect(threshold, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, i](double v) {
                edit(&model::Look::toon, &model::LookEdits::setToonRamp,
                    [i, v](algo::ToonRamp& ramp) { ramp.thresholds[std::size_t(i - 1)] = float(v); });
            });
            m_thresholds.push_back(threshold);
        }
        m_intensities.push_back(intensity);
        m_toneForm->addRow(i == count - 1 ? tr("Brightest:")
                : i == 0                  ? tr("Darkest:")
                                          : tr("Tone %1:").arg(i + 1),
            row);
    }
}

void LookPanel::refresh()
{
    m_updating = true;
    for (const auto& refresher : m_refreshers) {
        refresher();
    }
    const auto& look = m_document->data().look;
    m_toneCount->setValue(int(look.toon.intensities.size()));
    if (m_intensities.size() != look.toon.intensities.size()) {
        rebuildTones(); // only when the count changed: a row's own spin box may be emitting now
    } else {
        // Rows run brightest first.
        const std::size_t n = look.toon.intensities.size();
        for (std::size_t k = 0; k < n; ++k) {
            const QSignalBlocker block(m_intensities[k]);
            m_intensities[k]->setValue(look.toon.intensities[n - 1 - k]);
        }
        for (std::size_t k = 0; k < m_thresholds.size(); ++k) {
            const QSignalBlocker block(m_thresholds[k]);
            m_thresholds[k]->setValue(look.toon.thresholds[n - 2 - k]);
        }
    }
    const bool toonLike = look.style == model::ShadingStyle::Toon || look.style == model::ShadingStyle::Comic;
    m_toonBox->setVisible(toonLike);
    m_goochBox->setVisible(look.style == model::ShadingStyle::Gooch);
    m_hatchBox->setVisible(look.style == model::ShadingStyle::Comic);
    m_updating = false;
}

} // namespace celform::views
