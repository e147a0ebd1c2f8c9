// The Depth dock (depth_panel.h).
#include "celform/views/panels/depth_panel.h"

#include "celform/views/panels/depth_chart.h"
#include "celform/views/overlays/shot_depth_runner.h"

#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/document/document.h"
#include "celform/views/panels/color_swatch.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/scrolling_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QRadioButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

QIcon swatch(const Eigen::Vector3f& linear)
{
    QPixmap pixmap(12, 12);
    pixmap.fill(toQColor(linear));
    QPainter painter(&pixmap);
    painter.setPen(QColor(60, 60, 60));
    painter.drawRect(0, 0, 11, 11);
    return QIcon(pixmap);
}

} // namespace

DepthPanel::DepthPanel(model::Document* document, Viewport* viewport, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_runner(new DepthAnalysisRunner(document, viewport, this))
    , m_overlay(new DepthOverlay(viewport, m_runner))
{
    setObjectName(QStringLiteral("depthPanel"));
    // Scrolls rather than growing the dock column taller than a 1366x768 screen.
    QVBoxLayout* layout = scrollingPanelLayout(this);
    QWidget* body = layout->parentWidget();

    // The overlays, one at a time, as the thesis shows them.
    auto* overlayBox = new QGroupBox(tr("Overlay"), body);
    auto* overlayLayout = new QVBoxLayout(overlayBox);
    m_kinds = new QButtonGroup(this);
    const std::tuple<DepthOverlay::Kind, QString, QString, const char*> kinds[] = {
        {DepthOverlay::Kind::None, tr("None"), tr("Show the picture without an overlay"), "depthOverlayNone"},
        {DepthOverlay::Kind::Segments, tr("Segments"),
            tr("Parts of salient shape: neighbouring pixels with the same sign of Gaussian curvature and close "
               "depths, one colour each (segments under the minimum size are left out)"),
            "depthOverlaySegments"},
        {DepthOverlay::Kind::Curvature, tr("Gaussian curvature"),
            tr("Orange where the surface is dome-like (K > 0), blue where it is saddle-like (K < 0)"),
            "depthOverlayCurvature"},
        {DepthOverlay::Kind::DepthError, tr("Depth error"),
            tr("How far the depth a viewer perceives (that of the nearest colour edge) is from the real depth: "
               "blue where the surface is seen farther than it is, orange where it is seen nearer"),
            "depthOverlayError"},
    };
    for (const auto& [kind, text, tip, name] : kinds) {
        auto* button = new QRadioButton(text, overlayBox);
        button->setObjectName(QLatin1String(name));
        button->setToolTip(tip);
        m_kinds->addButton(button, int(kind));
        overlayLayout->addWidget(button);
    }
    m_kinds->button(int(DepthOverlay::Kind::None))->setChecked(true);
    connect(m_kinds, &QButtonGroup::idClicked, this, [this](int id) { setOverlayKind(DepthOverlay::Kind(id)); });
    auto* opacityRow = new QHBoxLayout;
    opacityRow->addWidget(new QLabel(tr("Opacity"), overlayBox));
    m_opacity = new QSlider(Qt::Horizontal, overlayBox);
    m_opacity->setObjectName(QStringLiteral("depthOverlayOpacity"));
    m_opacity->setRange(0, 100);
    m_opacity->setValue(80);
    m_opacity->setToolTip(tr("How much the overlay covers the model"));
    connect(m_opacity, &QSlider::valueChanged, this, [this](int v) { m_overlay->setOpacity(v / 100.0); });
    opacityRow->addWidget(m_opacity);
    overlayLayout->addLayout(opacityRow);
    layout->addWidget(overlayBox);

    // The figure of merit (thesis 4.4.1): one number, live.
    m_mse = new QLabel(body);
    m_mse->setObjectName(QStringLiteral("depthErrorLabel"));
    QFont big = m_mse->font();
    big.setPointSizeF(big.pointSizeF() * 1.5);
    big.setBold(true);
    m_mse->setFont(big);
    m_mse->setWordWrap(true); // a narrow dock wraps it instead of clipping the panel
    m_mse->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_mse->setToolTip(tr("Mean squared difference between perceived and real depth over the model's pixels "
                         "(model units squared): lower reads better in stereo"));
    layout->addWidget(m_mse);
    m_details = new QLabel(body);
    m_details->setWordWrap(true);
    layout->addWidget(m_details);
    m_status = new QLabel(body);
    m_status->setObjectName(QStringLiteral("depthStatus"));
    layout->addWidget(m_status);

    // The depth error along the shot (issue 26): every frame of the scene's range through the shot
    // camera, analysed on a thread of its own when asked, kept until the document changes.
    auto* shotBox = new QGroupBox(tr("Along the Shot"), body);
    auto* shotLayout = new QVBoxLayout(shotBox);
    m_chart = new DepthChart(document, shotBox);
    shotLayout->addWidget(m_chart);
    auto* shotRow = new QHBoxLayout;
    m_chartButton = new QToolButton(shotBox);
    m_chartButton->setObjectName(QStringLiteral("chartShotButton"));
    m_chartButton->setText(tr("Chart Shot"));
    m_chartButton->setToolTip(tr("Analyse every frame of the scene's range through the shot camera at the "
                                 "analysis size and chart the depth error"));
    m_chartCancel = new QToolButton(shotBox);
    m_chartCancel->setObjectName(QStringLiteral("chartShotCancel"));
    m_chartCancel->setText(tr("Cancel"));
    m_chartCancel->setEnabled(false);
    m_chartStatus = new QLabel(shotBox);
    m_chartStatus->setObjectName(QStringLiteral("chartShotStatus"));
    m_chartStatus->setWordWrap(true);
    shotRow->addWidget(m_chartButton);
    shotRow->addWidget(m_chartCancel);
    shotRow->addWidget(m_chartStatus, 1);
    shotLayout->addLayout(shotRow);
    layout->addWidget(shotBox);
    m_shotRunner = new ShotDepthRunner(document, this);
    connect(m_chartButton, &QToolButton::clicked, this, &DepthPanel::chartShot);
    connect(m_chartCancel, &QToolButton::clicked, m_shotRunner, &ShotDepthRunner::cancel);
    connect(m_shotRunner, &ShotDepthRunner::progressed, this,
        [this](int done, int total) { m_chartStatus->setText(tr("Analysing frame %1 of %2…").arg(done).arg(total)); });
    connect(m_shotRunner, &ShotDepthRunner::finished, this, [this](bool completed, const QString& error) {
        m_chartCancel->setEnabled(false);
        m_chartButton->setEnabled(true);
        if (completed) {
            m_chart->setSamples(m_shotRunner->samples());
            double sum = 0.0;
            for (const ShotDepthSample& s : m_shotRunner->samples())
                sum += s.mse;
            const auto n = m_shotRunner->samples().size();
            m_chartStatus->setText(
                tr("%n frame(s), mean MSE %1", nullptr, int(n)).arg(n ? sum / double(n) : 0.0, 0, 'g', 4));
        } else {
            m_chartStatus->setText(error.isEmpty() ? tr("Cancelled") : error);
        }
    });
    connect(m_shotRunner, &ShotDepthRunner::staled, this, [this] {
        m_chart->setStale(true);
        m_chartStatus->setText(tr("Changed since charted: Chart Shot again"));
    });
    connect(document, &model::Document::changed, this, [this, document](const model::ChangeSet& change) {
        if (change.reset || change.has(model::Part::SceneTime))
            m_chart->setRange(document->data().time.firstFrame, document->data().time.lastFrame);
    });
    m_chart->setRange(document->data().time.firstFrame, document->data().time.lastFrame);

    // Optimise Light for Stereo (thesis 4.1, 5.0.2-5.0.3): the method and how segments count.
    auto* lightBox = new QGroupBox(tr("Light for Stereo"), body);
    auto* lightForm = new QFormLayout(lightBox);
    lightForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_method = new QComboBox(lightBox);
    m_method->setObjectName(QStringLiteral("lightMethod"));
    m_method->addItem(tr("Gradient"), int(algo::LightMethod::Gradient));
    m_method->addItem(tr("Annealing"), int(algo::LightMethod::Annealing));
    m_method->addItem(tr("Random"), int(algo::LightMethod::Random));
    m_method->setToolTip(tr("Gradient moves the light from where you put it along the shading's derivative "
                            "(predictable); annealing tries shrinking random moves; random tries independent "
                            "lights and keeps the best"));
    lightForm->addRow(tr("Method"), m_method);
    m_weight = new QComboBox(lightBox);
    m_weight->setObjectName(QStringLiteral("lightWeight"));
    m_weight->addItem(tr("Every segment alike"), int(algo::SegmentWeight::Constant));
    m_weight->addItem(tr("By segment size"), int(algo::SegmentWeight::Area));
    m_weight->setToolTip(tr("Alike: small features such as dents count as much as the body (thesis figure 5.9); "
                            "by size: large parts count more"));
    lightForm->addRow(tr("Segments count"), m_weight);
    m_optimise = new QToolButton(lightBox);
    m_optimise->setObjectName(QStringLiteral("optimiseLightButton"));
    m_optimise->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_optimise->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    lightForm->addRow(m_optimise);
    layout->addWidget(lightBox);
    {
        QSettings stored;
        m_method->setCurrentIndex(std::clamp(stored.value(QStringLiteral("depth/lightMethod"), 0).toInt(), 0, 2));
        m_weight->setCurrentIndex(std::clamp(stored.value(QStringLiteral("depth/lightWeight"), 0).toInt(), 0, 1));
    }
    connect(m_method, qOverload<int>(&QComboBox::currentIndexChanged), this,
        [](int index) { QSettings().setValue(QStringLiteral("depth/lightMethod"), index); });
    connect(m_weight, qOverload<int>(&QComboBox::currentIndexChanged), this,
        [](int index) { QSettings().setValue(QStringLiteral("depth/lightWeight"), index); });

    // The segments and their bright/dark ratios against the window (thesis 4.1.3, 5.0.3).
    m_table = new QTableWidget(0, 5, body);
    m_table->setObjectName(QStringLiteral("segmentTable"));
    m_table->setHorizontalHeaderLabels({tr("Segment"), tr("Pixels"), tr("Ratio"), tr("In window"), tr("Importance")});
    m_table->horizontalHeaderItem(4)->setToolTip(
        tr("The mean importance of the segment's faces (focal points, Look > Focal Points): its weight in the light "
           "optimisation is multiplied by it"));
    // The columns share the dock's width (no horizontal scrolling in a narrow dock).
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setMinimumSectionSize(40);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setMinimumHeight(120);
    m_table->setToolTip(tr("Each segment's share of pixels shaded bright (N·L plus offset above the toon "
                           "threshold); the shading line reads best when it is inside the window"));
    layout->addWidget(m_table, 1);

    // Where the offset brush and the automatic offsets write (paper 3, section 4.3): the base
    // layer, or a key's layer at the playhead (Edit > Shading Offsets).
    m_offsetTarget = new QLabel(body);
    m_offsetTarget->setObjectName(QStringLiteral("offsetTargetLabel"));
    m_offsetTarget->setWordWrap(true);
    m_offsetTarget->setToolTip(tr("The layer of shading offsets the offset brush (Shift+O) and Edit > Shading "
                                  "Offsets > Automatic Shading Offsets write into"));
    layout->addWidget(m_offsetTarget);

    auto* settingsBox = new QGroupBox(tr("Analysis"), body);
    auto* form = new QFormLayout(settingsBox);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows); // narrow docks put a field under its label
    m_window = new QComboBox(settingsBox);
    m_window->setObjectName(QStringLiteral("ratioWindow"));
    m_window->addItem(tr("Lenient (0.20–0.80)"));
    m_window->addItem(tr("Medium (0.35–0.65)"));
    m_window->addItem(tr("Strict (0.50)"));
    m_window->addItem(tr("Custom"));
    m_window->setCurrentIndex(1);
    m_window->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_window->setMinimumContentsLength(8);
    m_window->setToolTip(tr("The bright/dark ratios a segment should have (thesis 5.0.3)"));
    form->addRow(tr("Ratio window"), m_window);
    auto* range = new QHBoxLayout;
    m_low = new QDoubleSpinBox(settingsBox);
    m_high = new QDoubleSpinBox(settingsBox);
    for (QDoubleSpinBox* spin : {m_low, m_high}) {
        spin->setRange(0.0, 1.0);
        spin->setSingleStep(0.05);
        spin->setDecimals(2);
        range->addWidget(spin);
    }
    m_low->setValue(0.35);
    m_high->setValue(0.65);
    m_low->setToolTip(tr("Lowest acceptable bright ratio"));
    m_high->setToolTip(tr("Highest acceptable bright ratio"));
    form->addRow(tr("From, to"), range);
    m_depthThreshold = new QDoubleSpinBox(settingsBox);
    m_depthThreshold->setObjectName(QStringLiteral("depthThreshold"));
    m_depthThreshold->setRange(0.1, 50.0);
    m_depthThreshold->setDecimals(1);
    m_depthThreshold->setSingleStep(0.5);
    m_depthThreshold->setSuffix(tr(" % of size"));
    m_depthThreshold->setValue(2.0);
    m_depthThreshold->setToolTip(tr("Neighbouring pixels whose depths differ by this share of the model's "
                                    "bounding-box diagonal or more belong to different segments"));
    form->addRow(tr("Depth step"), m_depthThreshold);
    m_minPixels = new QSpinBox(settingsBox);
    m_minPixels->setObjectName(QStringLiteral("minSegmentPixels"));
    m_minPixels->setRange(1, 100000);
    m_minPixels->setValue(algo::kMinSegmentPixels);
    m_minPixels->setSuffix(tr(" px"));
    m_minPixels->setToolTip(tr("Smaller segments are dropped as noise (the thesis uses 64 pixels)"));
    form->addRow(tr("Smallest segment"), m_minPixels);
    layout->addWidget(settingsBox);

    QSettings settings;
    m_window->setCurrentIndex(settings.value(QStringLiteral("depth/window"), 1).toInt());
    m_low->setValue(settings.value(QStringLiteral("depth/low"), 0.35).toDouble());
    m_high->setValue(settings.value(QStringLiteral("depth/high"), 0.65).toDouble());
    m_depthThreshold->setValue(settings.value(QStringLiteral("depth/threshold"), 2.0).toDouble());
    m_minPixels->setValue(settings.value(QStringLiteral("depth/minPixels"), algo::kMinSegmentPixels).toInt());
    auto presetChanged = [this](int index) {
        const double presets[][2] = {{0.2, 0.8}, {0.35, 0.65}, {0.5, 0.5}};
        if (index >= 0 && index < 3) {
            const QSignalBlocker a(m_low), b(m_high);
            m_low->setValue(presets[index][0]);
            m_high->setValue(presets[index][1]);
        }
        m_low->setEnabled(index == 3);
        m_high->setEnabled(index == 3);
        applySettings();
    };
    connect(m_window, qOverload<int>(&QComboBox::currentIndexChanged), this, presetChanged);
    presetChanged(m_window->currentIndex());
    for (QDoubleSpinBox* spin : {m_low, m_high, m_depthThreshold})
        connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] { applySettings(); });
    connect(m_minPixels, qOverload<int>(&QSpinBox::valueChanged), this, [this] { applySettings(); });

    connect(m_runner, &DepthAnalysisRunner::analysed, this, &DepthPanel::showResult);
    connect(m_runner, &DepthAnalysisRunner::busyChanged, this, &DepthPanel::showBusy);
    m_mse->setText(tr("Depth error: —"));
    letRowsNarrow(this);
}

void DepthPanel::showOffsetTarget(const QString& target)
{
    m_offsetTarget->setText(tr("Shading offsets go into the %1.").arg(target));
}

void DepthPanel::setOverlayKind(DepthOverlay::Kind kind)
{
    if (QAbstractButton* button = m_kinds->button(int(kind)))
        button->setChecked(true);
    const bool changed = m_overlay->kind() != kind;
    m_overlay->setKind(kind);
    updateActivity();
    if (changed)
        emit overlayKindChanged(kind);
}

void DepthPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_shown = true;
    updateActivity();
}

void DepthPanel::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    m_shown = false;
    updateActivity();
}

void DepthPanel::updateActivity()
{
    m_runner->setActive(m_shown || m_overlay->kind() != DepthOverlay::Kind::None);
}

void DepthPanel::applySettings()
{
    model::AnalysisSettings s;
    s.window = {float(std::min(m_low->value(), m_high->value())), float(std::max(m_low->value(), m_high->value()))};
    s.depthThreshold = m_depthThreshold->value() / 100.0;
    s.minSegmentPixels = m_minPixels->value();
    QSettings settings;
    settings.setValue(QStringLiteral("depth/window"), m_window->currentIndex());
    settings.setValue(QStringLiteral("depth/low"), m_low->value());
    settings.setValue(QStringLiteral("depth/high"), m_high->value());
    settings.setValue(QStringLiteral("depth/threshold"), m_depthThreshold->value());
    settings.setValue(QStringLiteral("depth/minPixels"), m_minPixels->value());
    m_runner->setSettings(s);
}

void DepthPanel::setOptimiseLightAction(QAction* action)
{
    m_optimise->setDefaultAction(action);
}

algo::LightOptimisationSettings DepthPanel::lightSettings() const
{
    algo::LightOptimisationSettings s;
    s.method = algo::LightMethod(m_method->currentData().toInt());
    s.weight = algo::SegmentWeight(m_weight->currentData().toInt());
    return s;
}

void DepthPanel::showBusy(bool busy)
{
    m_status->setText(busy ? tr("Analysing…") : QString());
}

void DepthPanel::showResult()
{
    const auto result = m_runner->result();
    if (!result)
        return;
    if (!result->error.isEmpty()) {
        m_mse->setText(tr("Depth error: —"));
        m_details->setText(result->error);
        m_table->setRowCount(0);
        return;
    }
    m_mse->setText(tr("Depth error MSE: %1").arg(result->meanSquaredError, 0, 'g', 4));
    const int inside = algo::segmentsInWindow(result->segmentStats);
    m_details->setText(
        tr("RMSE %1 model units · %2 of %3 segments inside the window · features on %4% of %5 model pixels · "
           "%6 x %7 px in %8 ms")
            .arg(std::sqrt(result->meanSquaredError), 0, 'g', 3)
            .arg(inside)
            .arg(result->segmentStats.size())
            .arg(result->modelPixels > 0 ? 100.0 * double(result->featurePixels) / double(result->modelPixels) : 0.0, 0,
                'f', 1)
            .arg(result->modelPixels)
            .arg(result->width)
            .arg(result->height)
            .arg(result->milliseconds, 0, 'f', 0));
    m_table->setRowCount(int(result->segmentStats.size()));
    for (int row = 0; row < int(result->segmentStats.size()); ++row) {
        const algo::SegmentStats& s = result->segmentStats[std::size_t(row)];
        auto item = [&](int column, const QString& text) {
            QTableWidgetItem* cell = m_table->item(row, column);
            if (!cell) {
                cell = new QTableWidgetItem;
                m_table->setItem(row, column, cell);
            }
            cell->setText(text);
            return cell;
        };
        QTableWidgetItem* id = item(0, QString::number(row));
        id->setIcon(swatch(model::segmentColor(row)));
        id->setToolTip(s.meanCurvature > 0.f ? tr("Dome-like (K > 0)") : tr("Saddle-like (K < 0)"));
        item(1, QString::number(s.pixels))->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        item(2, QString::number(double(s.ratio), 'f', 2))->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        QTableWidgetItem* in = item(3, s.inWindow ? tr("Yes") : tr("No"));
        in->setForeground(s.inWindow ? QColor(20, 130, 40) : QColor(190, 40, 30));
        item(4, QString::number(double(s.importance), 'f', 2))->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
}

void DepthPanel::chartShot()
{
    // The analysis size and settings of the live analysis, over the scene's whole range.
    const model::SceneTime& time = m_document->data().time;
    m_chartButton->setEnabled(false);
    m_chartCancel->setEnabled(true);
    m_chartStatus->setText(tr("Analysing the shot…"));
    m_shotRunner->start(time.firstFrame, time.lastFrame, 1, m_runner->analysisSize(), m_runner->settings());
}

} // namespace celform::views
