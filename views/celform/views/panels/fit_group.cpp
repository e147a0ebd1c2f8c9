// The key's Fit to Drawing group (fit_group.h).
#include "celform/views/panels/fit_group.h"

#include "celform/model/document/document.h"
#include "celform/views/overlays/outline_cache.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QVBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QToolButton>

namespace celform::views {

FitGroup::FitGroup(model::Document* document, QWidget* parent)
    : QGroupBox(tr("Fit to Drawing"), parent)
    , m_document(document)
    , m_cache(std::make_shared<OutlineCache>())
{
    setObjectName(QStringLiteral("fitGroup"));
    auto* form = new QFormLayout(this);
    m_figures = new QLabel(this);
    m_figures->setObjectName(QStringLiteral("fitFigures"));
    m_figures->setWordWrap(true);
    m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_figures->setToolTip(tr("How well the key meets its drawing's outline, seen through the key's camera at the "
                             "drawing's frame: the overlap of the two filled shapes (IoU, 1 is a perfect match) and "
                             "the mean distance between their outlines in drawing pixels. Measured on the control "
                             "mesh's silhouette"));
    form->addRow(m_figures);
    auto* buttons = new QWidget(this);
    // One above the other: side by side their names would widen the dock.
    auto* buttonLayout = new QVBoxLayout(buttons);
    buttonLayout->setContentsMargins(0, 0, 0, 0);
    m_fitCamera = new QToolButton(buttons);
    m_fitShape = new QToolButton(buttons);
    for (QToolButton* b : {m_fitCamera, m_fitShape}) {
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        buttonLayout->addWidget(b);
    }
    buttons->hide(); // until the window gives the buttons their actions
    form->addRow(buttons);

    m_region = new QComboBox(this);
    m_region->setObjectName(QStringLiteral("fitRegion"));
    m_region->setToolTip(tr("The faces Fit Shape may move: the whole model, or a painted face set"));
    form->addRow(tr("&Region:"), m_region);
    m_pins = new QComboBox(this);
    m_pins->setObjectName(QStringLiteral("fitPins"));
    m_pins->setToolTip(tr("A painted face set whose vertices stay where they are"));
    form->addRow(tr("&Pinned:"), m_pins);
    m_strength = new QDoubleSpinBox(this);
    m_strength->setObjectName(QStringLiteral("fitStrength"));
    m_strength->setRange(0.0, 1.0);
    m_strength->setSingleStep(0.05);
    m_strength->setDecimals(2);
    m_strength->setValue(1.0);
    m_strength->setToolTip(tr("How much of the fitted deformation Fit Shape applies: 1 all of it, 0.5 half way"));
    form->addRow(tr("&Strength:"), m_strength);
    m_mirror = new QCheckBox(tr("&Mirror (the brush's)"), this);
    m_mirror->setObjectName(QStringLiteral("fitMirror"));
    m_mirror->setToolTip(tr("Keep the fitted shape symmetric across the brush's mirror plane: one setting for "
                            "both"));
    form->addRow(m_mirror);
    connect(m_mirror, &QCheckBox::toggled, this, &FitGroup::mirrorEdited);

    // Edits come in bursts (a brush stroke, a spin box drag): measure once they pause.
    m_measureTimer.setSingleShot(true);
    m_measureTimer.setInterval(80);
    connect(&m_measureTimer, &QTimer::timeout, this, &FitGroup::measure);
    connect(m_document, &model::Document::changed, this, &FitGroup::documentChanged);
    refreshFaceSets();
}

void FitGroup::setKey(model::ObjectId key)
{
    if (key == m_key)
        return;
    m_key = key;
    m_metrics.reset();
    m_figures->clear();
    if (key)
        m_measureTimer.start();
}

void FitGroup::setOutlineCache(std::shared_ptr<OutlineCache> cache)
{
    m_cache = std::move(cache);
    if (m_key)
        m_measureTimer.start();
}

void FitGroup::setActions(QAction* fitCamera, QAction* fitShape)
{
    m_fitCamera->setDefaultAction(fitCamera);
    m_fitShape->setDefaultAction(fitShape);
    m_fitCamera->parentWidget()->setVisible(fitCamera || fitShape);
}

model::ShapeFitRequest FitGroup::shapeRequest() const
{
    model::ShapeFitRequest request;
    request.regionFaceSet = m_region->currentData().toString();
    request.pinFaceSet = m_pins->currentData().toString();
    request.mirror = m_mirror->isChecked();
    request.strength = m_strength->value();
    return request;
}

QString FitGroup::figuresText() const
{
    return m_figures->text();
}

void FitGroup::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    if (change.reset || change.has(Part::FaceSets))
        refreshFaceSets();
    if (!m_key)
        return;
    // The key's shape or camera, its drawing's outline settings or image, the model, a new link.
    const bool keyTouched = change.has(Part::Keys) && (change.touches(m_key) || change.structure);
    const bool drawingTouched = change.has(Part::Drawings) && (change.touches(m_drawing) || change.structure);
    // At most one measurement per interval while a stroke goes on, and one after its last step.
    if ((change.reset || change.has(Part::Mesh) || keyTouched || drawingTouched) && !m_measureTimer.isActive())
        m_measureTimer.start();
}

void FitGroup::refreshFaceSets()
{
    const QString region = m_region->currentData().toString();
    const QString pins = m_pins->currentData().toString();
    m_region->clear();
    m_pins->clear();
    m_region->addItem(tr("Whole model"), QString());
    m_pins->addItem(tr("None"), QString());
    for (const algo::FaceSet& set : m_document->data().faceSets) {
        const QString name = QString::fromStdString(set.name);
        m_region->addItem(name, name);
        m_pins->addItem(name, name);
    }
    m_region->setCurrentIndex(std::max(0, m_region->findData(region)));
    m_pins->setCurrentIndex(std::max(0, m_pins->findData(pins)));
}

void FitGroup::measure()
{
    const model::ProjectData& data = m_document->data();
    const model::KeyViewpoint* key = m_key ? data.key(m_key) : nullptr;
    m_metrics.reset();
    m_drawing = 0;
    if (!key || !data.baseMesh) {
        m_figures->clear();
        emit measured();
        return;
    }
    const model::Drawing* drawing = nullptr;
    for (model::ObjectId id : key->drawingIds)
        if ((drawing = data.drawing(id)))
            break;
    if (!drawing) {
        m_figures->setText(tr("Link the key to a drawing to measure how well it meets it."));
        emit measured();
        return;
    }
    m_drawing = drawing->id;
    const std::shared_ptr<const algo::Outline> outline = m_cache->outline(*drawing);
    if (const QString problem = model::outlineProblem(*drawing, *outline); !problem.isEmpty()) {
        m_figures->setText(problem);
        emit measured();
        return;
    }
    QElapsedTimer clock;
    clock.start();
    const algo::FitMetrics metrics = model::keyFitMetrics(data, *key, *drawing, *outline, &m_scratch);
    m_milliseconds = double(clock.nsecsElapsed()) / 1e6;
    m_metrics = metrics;
    const QLocale locale;
    if (!metrics.valid)
        m_figures->setText(tr("Against “%1”: the model is not in the key's view.").arg(drawing->name));
    else
        m_figures->setText(
            tr("Against “%1”:\nsilhouette IoU %2\nchamfer distance %3 px")
                .arg(drawing->name, locale.toString(metrics.iou, 'f', 3), locale.toString(metrics.chamferPx, 'f', 2)));
    emit measured();
}

} // namespace celform::views
