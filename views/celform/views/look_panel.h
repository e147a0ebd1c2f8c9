// The Look dock: shading style and its parameters, lines, key light, background and stereo
// settings of the document's Look. Each change is a Document::setLook (a slider or spin-box drag
// merges into one undo step).
#pragma once

#include "celform/model/document.h"

#include <QWidget>

#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QSpinBox;
class QToolButton;

namespace celform::views {

class LookPanel : public QWidget {
    Q_OBJECT
public:
    explicit LookPanel(model::Document* document, QWidget* parent = nullptr);

    [[nodiscard]] QComboBox* styleBox() const { return m_style; }

private:
    /// Applies an edit to a copy of the current look and pushes it.
    void edit(const std::function<void(model::Look&)>& change);
    void refresh();
    void rebuildTones();
    void editDuboisMatrices();
    QDoubleSpinBox* makeSpin(double min, double max, double step, int decimals, const QString& tip);
    QToolButton* makeColorButton(const QString& tip, const std::function<Eigen::Vector3f(const model::Look&)>& get,
        const std::function<void(model::Look&, const Eigen::Vector3f&)>& set);

    model::Document* m_document;
    bool m_updating = false;
    std::vector<std::function<void()>> m_refreshers; ///< each control's update from the look

    QComboBox* m_style;
    QComboBox* m_material; ///< which material the style applies to (-1: all)
    QGroupBox* m_toonBox;
    QFormLayout* m_toneForm;
    QSpinBox* m_toneCount;
    std::vector<QDoubleSpinBox*> m_thresholds;
    std::vector<QDoubleSpinBox*> m_intensities;
    QGroupBox* m_goochBox;
    QGroupBox* m_hatchBox;
};

} // namespace celform::views
