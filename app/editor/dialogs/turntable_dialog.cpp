// The turntable settings dialog (turntable_dialog.h).
#include "editor/dialogs/turntable_dialog.h"

#include "celform/model/data/project_data.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace celform::app {

TurntableDialog::TurntableDialog(int startFrame, QWidget* parent)
    : QDialog(parent)
    , m_frames(new QSpinBox(this))
    , m_axis(new QComboBox(this))
    , m_elevation(new QDoubleSpinBox(this))
    , m_start(new QSpinBox(this))
    , m_angle(new QDoubleSpinBox(this))
{
    setObjectName(QStringLiteral("turntableDialog"));
    setWindowTitle(tr("Turntable"));
    m_frames->setObjectName(QStringLiteral("turntableFrames"));
    m_frames->setRange(2, model::kMaxFrame);
    m_frames->setToolTip(tr("Frames of one revolution; the scene's range becomes these frames"));
    m_axis->setObjectName(QStringLiteral("turntableAxis"));
    m_axis->addItem(tr("X"));
    m_axis->addItem(tr("Y (up)"));
    m_axis->addItem(tr("Z"));
    m_axis->setToolTip(tr("The axis the camera turns around, through the model's centre"));
    m_elevation->setObjectName(QStringLiteral("turntableElevation"));
    m_elevation->setRange(-89.0, 89.0);
    m_elevation->setSuffix(QStringLiteral(" °"));
    m_elevation->setToolTip(tr("How far the camera is raised above the plane normal to the axis"));
    m_start->setObjectName(QStringLiteral("turntableStart"));
    m_start->setRange(-model::kMaxFrame, model::kMaxFrame);
    m_start->setToolTip(tr("The frame the revolution starts at"));
    m_angle->setObjectName(QStringLiteral("turntableAngle"));
    m_angle->setRange(-360.0, 360.0);
    m_angle->setSuffix(QStringLiteral(" °"));
    m_angle->setToolTip(tr("Where on the circle the camera starts: 0 is the side the default view looks from"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Frames per revolution:"), m_frames);
    form->addRow(tr("Axis:"), m_axis);
    form->addRow(tr("Elevation:"), m_elevation);
    form->addRow(tr("Start frame:"), m_start);
    form->addRow(tr("Start angle:"), m_angle);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setToolTip(tr("Replace the camera path by the turntable (one undo step)"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
    model::Turntable defaults;
    defaults.startFrame = startFrame;
    setTurntable(defaults);
}

model::Turntable TurntableDialog::turntable() const
{
    model::Turntable t;
    t.frames = m_frames->value();
    t.axis = Eigen::Vector3d::Unit(m_axis->currentIndex());
    t.elevationDegrees = m_elevation->value();
    t.startFrame = m_start->value();
    t.startDegrees = m_angle->value();
    return t;
}

void TurntableDialog::setTurntable(const model::Turntable& t)
{
    m_frames->setValue(t.frames);
    Eigen::Index axis = 1;
    t.axis.cwiseAbs().maxCoeff(&axis);
    m_axis->setCurrentIndex(int(axis));
    m_elevation->setValue(t.elevationDegrees);
    m_start->setValue(t.startFrame);
    m_angle->setValue(t.startDegrees);
}

} // namespace celform::app
