// The key's "Fit to Drawing" group in the Properties panel: how well the key meets its drawing,
// live (the silhouette IoU and the chamfer distance in drawing pixels, measured on the control
// mesh's silhouette through the key's camera at the drawing's frame; DESIGN.md, "Drawings and
// cameras"), the Fit Camera and Fit Shape buttons (the window's actions), and what Fit Shape may
// change: a region of painted faces, pinned faces, the mirror (the brush's) and the strength.
#pragma once

#include "celform/algorithms/fit_metrics.h"
#include "celform/model/analysis/drawing_fit.h"

#include <QGroupBox>
#include <QTimer>

#include <memory>
#include <optional>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class OutlineCache;

class FitGroup : public QGroupBox {
    Q_OBJECT
public:
    FitGroup(model::Document* document, QWidget* parent = nullptr);
    /// The key shown (0: none).
    void setKey(model::ObjectId key);
    /// Where the drawings' outlines come from (the viewport's, so each is extracted once).
    void setOutlineCache(std::shared_ptr<OutlineCache> cache);
    /// The buttons' actions: Fit Camera to Drawing and Fit Shape to Drawing (the window's).
    void setActions(QAction* fitCamera, QAction* fitShape);

    /// What Fit Shape to Drawing may change, as the controls say.
    [[nodiscard]] model::ShapeFitRequest shapeRequest() const;
    [[nodiscard]] QCheckBox* mirrorBox() const { return m_mirror; }
    [[nodiscard]] QComboBox* regionBox() const { return m_region; }
    [[nodiscard]] QComboBox* pinBox() const { return m_pins; }
    [[nodiscard]] QDoubleSpinBox* strengthBox() const { return m_strength; }
    /// The last figures (none when the key has no drawing or its outline failed).
    [[nodiscard]] const std::optional<algo::FitMetrics>& metrics() const { return m_metrics; }
    /// How long the last measurement took, milliseconds.
    [[nodiscard]] double measureMilliseconds() const { return m_milliseconds; }
    [[nodiscard]] QString figuresText() const;

signals:
    /// The mirror was switched here (the brush's setting: the panel keeps both in step).
    void mirrorEdited(bool on);
    /// New figures are shown.
    void measured();

private:
    void documentChanged(const model::ChangeSet& change);
    void refreshFaceSets();
    void measure();

    model::Document* m_document;
    std::shared_ptr<OutlineCache> m_cache;
    model::ObjectId m_key = 0;
    model::ObjectId m_drawing = 0; ///< the key's drawing when last measured
    QLabel* m_figures;
    QToolButton* m_fitCamera;
    QToolButton* m_fitShape;
    QComboBox* m_region;
    QComboBox* m_pins;
    QDoubleSpinBox* m_strength;
    QCheckBox* m_mirror;
    QTimer m_measureTimer; ///< coalesces the edits of a stroke or a drag into one measurement
    algo::FitScratch m_scratch; ///< kept between measurements: a megapixel drawing's transforms
    std::optional<algo::FitMetrics> m_metrics;
    double m_milliseconds = 0.0;
};

} // namespace celform::views
