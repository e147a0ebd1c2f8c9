// The Look dock: shading style and its parameters, lines, key light, background and stereo
// settings of the document's Look. Each control sets one property through the document (a held
// spin-box arrow or key is one undo step; two controls are always two steps).
#pragma once

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/panels/gesture_tracker.h"

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
    /// Edits a copy of one property of the look and hands it to the document's setter for it,
    /// in the gesture of the control that sent the change (a spin box held down is one step); a
    /// refused value puts the controls back.
    /// The light shown: the light track's at the current frame, else the single light.
    [[nodiscard]] model::Light currentLight() const
    {
        return m_document->data().look.lightAt(m_document->data().currentFrame);
    }
    /// Changes the light shown (LookEdits::setLight keys it at the current frame on a track).
    template <typename Change> void editLight(Change&& change)
    {
        if (m_updating)
            return;
        model::Light light = currentLight();
        change(light);
        m_document->look().setLight(light, GestureTracker::of(sender()));
    }
    template <typename T, typename Change>
    void edit(T model::Look::*field, void (model::LookEdits::*set)(const T&, model::GestureId), Change&& change)
    {
        if (m_updating)
            return;
        T value = m_document->data().look.*field;
        change(value);
        try {
            (m_document->look().*set)(value, GestureTracker::of(sender()));
        } catch (const model::EditRefused&) {
            refresh();
        }
    }
    void refresh();
    void rebuildTones();
    void editDuboisMatrices();
    QDoubleSpinBox* makeSpin(double min, double max, double step, int decimals, const QString& tip);
    QToolButton* makeColorButton(const QString& tip, const std::function<Eigen::Vector3f(const model::Look&)>& get,
        const std::function<void(const Eigen::Vector3f&)>& set);

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
