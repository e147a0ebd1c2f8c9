// A drawing's outline settings (outline_settings_box.h).
#include "celform/views/panels/outline_settings_box.h"

#include "celform/model/analysis/drawing_fit.h"
#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/outline_cache.h"
#include "celform/views/panels/gesture_tracker.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace celform::views {

OutlineSettingsBox::OutlineSettingsBox(model::Document* document, QWidget* parent)
    : QGroupBox(tr("Outline for Fit to Drawing"), parent)
    , m_document(document)
    , m_cache(std::make_shared<OutlineCache>())
{
    setObjectName(QStringLiteral("outlineSettingsBox"));
    auto* form = new QFormLayout(this);
    auto* thresholdRow = new QWidget(this);
    auto* thresholdLayout = new QHBoxLayout(thresholdRow);
    thresholdLayout->setContentsMargins(0, 0, 0, 0);
    m_automatic = new QCheckBox(tr("A&utomatic"), thresholdRow);
    m_automatic->setObjectName(QStringLiteral("outlineAutomatic"));
    m_automatic->setToolTip(tr("Choose the threshold from the drawing's histogram (Otsu's method); off: set it "
                               "by hand"));
    m_threshold = new QDoubleSpinBox(thresholdRow);
    m_threshold->setObjectName(QStringLiteral("outlineThreshold"));
    m_threshold->setRange(0.0, 1.0);
    m_threshold->setSingleStep(0.02);
    m_threshold->setDecimals(3); // Otsu's threshold of black-on-white line art is a few thousandths
    m_threshold->setToolTip(tr("Ink is where the drawing is darker than this (0 black, 1 white); a drawing with "
                               "transparency uses its alpha instead"));
    thresholdLayout->addWidget(m_automatic);
    thresholdLayout->addWidget(m_threshold, 1);
    form->addRow(tr("&Threshold:"), thresholdRow);
    m_closing = new QDoubleSpinBox(this);
    m_closing->setObjectName(QStringLiteral("outlineClosing"));
    m_closing->setRange(0.0, model::DrawingOutline::kMaxClosingRadius);
    m_closing->setSingleStep(1.0);
    m_closing->setDecimals(1);
    m_closing->setSuffix(tr(" px"));
    m_closing->setToolTip(tr("Radius in drawing pixels that closes gaps in open line art: gaps up to about twice "
                             "this wide are bridged. 0 closes nothing"));
    form->addRow(tr("C&losing radius:"), m_closing);
    m_innerLines = new QCheckBox(tr("&Inner lines"), this);
    m_innerLines->setObjectName(QStringLiteral("outlineInnerLines"));
    m_innerLines->setToolTip(tr("Keep the shapes the drawing's inner lines enclose as holes (off: the outer "
                                "outline alone, the figure filled)"));
    form->addRow(m_innerLines);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("outlineStatus"));
    m_status->setWordWrap(true);
    form->addRow(m_status);
    m_fitCamera = new QToolButton(this);
    m_fitCamera->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_fitCamera->hide(); // until the window gives it its action
    form->addRow(m_fitCamera);

    GestureTracker::track(m_threshold, m_document);
    GestureTracker::track(m_closing, m_document);
    connect(m_automatic, &QCheckBox::toggled, this, [this] { edit(m_automatic); });
    connect(m_threshold, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] { edit(m_threshold); });
    connect(m_closing, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] { edit(m_closing); });
    connect(m_innerLines, &QCheckBox::toggled, this, [this] { edit(m_innerLines); });
    connect(m_document, &model::Document::changed, this, &OutlineSettingsBox::documentChanged);
    m_statusTimer.setSingleShot(true);
    m_statusTimer.setInterval(150);
    connect(&m_statusTimer, &QTimer::timeout, this, &OutlineSettingsBox::refreshStatus);
}

void OutlineSettingsBox::setDrawing(model::ObjectId drawing)
{
    m_drawing = drawing;
    refresh();
}

void OutlineSettingsBox::setOutlineCache(std::shared_ptr<OutlineCache> cache)
{
    m_cache = std::move(cache);
    refreshStatus();
}

void OutlineSettingsBox::setFitCameraAction(QAction* action)
{
    m_fitCamera->setDefaultAction(action);
    m_fitCamera->setVisible(action != nullptr);
}

QString OutlineSettingsBox::statusText() const
{
    return m_status->text();
}

void OutlineSettingsBox::documentChanged(const model::ChangeSet& change)
{
    if (change.reset || (change.has(model::Part::Drawings) && (change.structure || change.touches(m_drawing))))
        refresh();
}

void OutlineSettingsBox::refresh()
{
    const model::Drawing* drawing = m_drawing ? m_document->data().drawing(m_drawing) : nullptr;
    if (!drawing)
        return;
    m_updating = true;
    const model::DrawingOutline& o = drawing->outline;
    m_automatic->setChecked(o.threshold < 0.0);
    m_threshold->setEnabled(o.threshold >= 0.0);
    if (o.threshold >= 0.0)
        m_threshold->setValue(o.threshold);
    m_closing->setValue(o.closingRadius);
    m_innerLines->setChecked(o.innerLines);
    m_updating = false;
    // A spin box drag extracts once it pauses; anything else at once.
    if (GestureTracker::of(m_threshold) || GestureTracker::of(m_closing))
        m_statusTimer.start();
    else
        refreshStatus();
}

void OutlineSettingsBox::refreshStatus()
{
    const model::Drawing* drawing = m_drawing ? m_document->data().drawing(m_drawing) : nullptr;
    if (!drawing || !m_cache || isHidden()) {
        m_status->clear();
        return;
    }
    const std::shared_ptr<const algo::Outline> outline = m_cache->outline(*drawing);
    if (const QString problem = model::outlineProblem(*drawing, *outline); !problem.isEmpty()) {
        m_status->setStyleSheet(QStringLiteral("color: #c0392b;"));
        m_status->setText(problem);
        return;
    }
    m_status->setStyleSheet({});
    const QString how = outline->usedAlpha ? tr("read from the drawing's transparency")
                                           : tr("threshold %1").arg(outline->thresholdUsed, 0, 'f', 3);
    m_status->setText(
        tr("Outline found (%1): %n contour(s). O shows it in the viewport.", nullptr, int(outline->contours.size()))
            .arg(how));
    // The automatic threshold's value, as a start for setting it by hand.
    if (drawing->outline.threshold < 0.0 && outline->thresholdUsed >= 0.0) {
        m_updating = true;
        m_threshold->setValue(outline->thresholdUsed);
        m_updating = false;
    }
}

void OutlineSettingsBox::edit(const QObject* control)
{
    const model::Drawing* drawing = m_drawing ? m_document->data().drawing(m_drawing) : nullptr;
    if (m_updating || !drawing)
        return;
    model::DrawingOutline outline = drawing->outline;
    outline.threshold = m_automatic->isChecked() ? -1.0 : m_threshold->value();
    outline.closingRadius = m_closing->value();
    outline.innerLines = m_innerLines->isChecked();
    try {
        m_document->drawings().setDrawingOutline(m_drawing, outline, GestureTracker::of(control));
    } catch (const model::EditRefused& e) {
        emit message(e.message());
        refresh();
    }
}

} // namespace celform::views
