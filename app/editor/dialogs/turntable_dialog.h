// Camera ▸ Turntable…: the settings of a turntable camera path (model::Turntable) — frames per
// revolution, axis, elevation, start frame and angle. The caller applies them through
// AnimationEdits::makeTurntable.
#pragma once

#include "celform/model/data/camera_path.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace celform::app {

class TurntableDialog : public QDialog {
    Q_OBJECT
public:
    /// Starts from defaults, starting at startFrame.
    explicit TurntableDialog(int startFrame, QWidget* parent = nullptr);

    [[nodiscard]] model::Turntable turntable() const;
    void setTurntable(const model::Turntable& turntable);

private:
    QSpinBox* m_frames;
    QComboBox* m_axis;
    QDoubleSpinBox* m_elevation;
    QSpinBox* m_start;
    QDoubleSpinBox* m_angle;
};

} // namespace celform::app
