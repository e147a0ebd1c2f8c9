// The properties dock: what is selected in the scene (model statistics, a drawing's image and
// overlay opacity, a key's direction) and the project-wide blend settings. Edits go through the
// Document; a slider drag is a single undo step.
#pragma once

#include "celform/model/document.h"
#include "celform/views/scene_panel.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QSlider;

namespace celform::views {

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(model::Document* document, QWidget* parent = nullptr);

public slots:
    void showSelection(celform::views::ScenePanel::Selection selection);

private:
    void refresh();
    void refreshBlend();

    model::Document* m_document;
    ScenePanel::Selection m_selection;
    bool m_updating = false;

    QGroupBox* m_selectionBox;
    QLabel* m_summary;
    QLabel* m_thumbnail;
    QLineEdit* m_name;
    QSlider* m_opacity;
    QLabel* m_opacityValue;
    QCheckBox* m_enabled;
    QWidget* m_opacityRow;

    QDoubleSpinBox* m_sharpness;
    QComboBox* m_unspecified;
};

} // namespace celform::views
