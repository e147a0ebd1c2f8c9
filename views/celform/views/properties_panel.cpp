// Properties of the selection and the blend settings, kept in sync with the document.
#include "celform/views/properties_panel.h"

#include "celform/algorithms/tri_mesh.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSlider>
#include <QVBoxLayout>

namespace celform::views {

PropertiesPanel::PropertiesPanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    auto* layout = new QVBoxLayout(this);

    m_selectionBox = new QGroupBox(tr("Selection"), this);
    auto* form = new QFormLayout(m_selectionBox);
    m_summary = new QLabel(m_selectionBox);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(m_summary);
    m_thumbnail = new QLabel(m_selectionBox);
    m_thumbnail->setAlignment(Qt::AlignCenter);
    form->addRow(m_thumbnail);
    m_name = new QLineEdit(m_selectionBox);
    m_name->setToolTip(tr("Name shown in the scene tree and used by the command line"));
    form->addRow(tr("&Name:"), m_name);

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
    form->addRow(tr("&Opacity:"), m_opacityRow);
    m_enabled = new QCheckBox(tr("&Enabled in the blend"), m_selectionBox);
    m_enabled->setToolTip(tr("A disabled key keeps its deformation but takes no part in the blend"));
    form->addRow(m_enabled);
    layout->addWidget(m_selectionBox);

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
    layout->addWidget(blendBox);
    layout->addStretch(1);

    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        if (m_updating)
            return;
        if (m_selection.kind == ScenePanel::ItemKind::Drawing)
            m_document->renameDrawing(m_selection.id, m_name->text());
        else if (m_selection.kind == ScenePanel::ItemKind::Key)
            m_document->renameKey(m_selection.id, m_name->text());
    });
    connect(m_opacity, &QSlider::valueChanged, this, [this](int value) {
        m_opacityValue->setText(QStringLiteral("%1 %").arg(value));
        if (!m_updating && m_selection.kind == ScenePanel::ItemKind::Drawing)
            m_document->setDrawingOpacity(m_selection.id, value / 100.0);
    });
    connect(m_enabled, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_updating && m_selection.kind == ScenePanel::ItemKind::Key)
            m_document->setKeyEnabled(m_selection.id, on);
    });
    connect(m_sharpness, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double value) {
        if (m_updating)
            return;
        auto blend = m_document->data().blend;
        blend.sharpness = value;
        m_document->setBlendSettings(blend);
    });
    connect(m_unspecified, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (m_updating)
            return;
        auto blend = m_document->data().blend;
        blend.unspecified = model::UnspecifiedMode(m_unspecified->itemData(index).toInt());
        m_document->setBlendSettings(blend);
    });
    for (auto signal : {&model::Document::meshChanged, &model::Document::drawingsChanged, &model::Document::keysChanged,
             &model::Document::documentReset})
        connect(m_document, signal, this, &PropertiesPanel::refresh);
    connect(m_document, &model::Document::blendChanged, this, &PropertiesPanel::refreshBlend);
    connect(m_document, &model::Document::documentReset, this, &PropertiesPanel::refreshBlend);
    refresh();
    refreshBlend();
}

void PropertiesPanel::showSelection(ScenePanel::Selection selection)
{
    m_selection = selection;
    refresh();
}

void PropertiesPanel::refresh()
{
    m_updating = true;
    const auto& data = m_document->data();
    const QLocale locale;
    bool nameVisible = false, opacityVisible = false, enabledVisible = false;
    m_thumbnail->clear();
    m_thumbnail->setVisible(false);

    if (m_selection.kind == ScenePanel::ItemKind::Drawing && data.drawing(m_selection.id)) {
        const auto& d = *data.drawing(m_selection.id);
        m_selectionBox->setTitle(tr("Reference drawing"));
        m_summary->setText(tr("%1 × %2 pixels, %3, %4")
                               .arg(d.image.width())
                               .arg(d.image.height())
                               .arg(d.imageFormat.toUpper())
                               .arg(d.aligned ? tr("camera aligned") : tr("camera not aligned yet")));
        if (!d.image.isNull()) {
            m_thumbnail->setPixmap(
                QPixmap::fromImage(d.image.scaled(220, 160, Qt::KeepAspectRatio, Qt::SmoothTransformation)));
            m_thumbnail->setVisible(true);
        }
        m_name->setText(d.name);
        m_opacity->setValue(int(std::lround(d.opacity * 100)));
        m_opacityValue->setText(QStringLiteral("%1 %").arg(m_opacity->value()));
        nameVisible = opacityVisible = true;
    } else if (m_selection.kind == ScenePanel::ItemKind::Key && data.key(m_selection.id)) {
        const auto& k = *data.key(m_selection.id);
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
        nameVisible = enabledVisible = true;
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
    m_name->setVisible(nameVisible);
    m_opacityRow->setVisible(opacityVisible);
    m_enabled->setVisible(enabledVisible);
    if (auto* form = qobject_cast<QFormLayout*>(m_selectionBox->layout())) {
        form->setRowVisible(m_name, nameVisible);
        form->setRowVisible(m_opacityRow, opacityVisible);
    }
    m_updating = false;
}

void PropertiesPanel::refreshBlend()
{
    m_updating = true;
    const auto& blend = m_document->data().blend;
    m_sharpness->setValue(blend.sharpness);
    m_unspecified->setCurrentIndex(m_unspecified->findData(int(blend.unspecified)));
    m_updating = false;
}

} // namespace celform::views
