// The properties dock: what is selected in the scene (model statistics; a drawing's image,
// overlay and alignment; a key's direction, drawing, deformation and the brush) and the
// project-wide blend settings. Edits go through the Document; a slider drag is one undo step.
// The brush and point-matching controls drive the viewport's tools, which panels do not know:
// the panel says what was edited (signals) and shows what the tools report (slots); the editor
// window connects both to the tools.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/model/document/document.h"
#include "celform/views/panels/scene_panel.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <optional>

#include <functional>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;

namespace celform::views {

class FitGroup;
class OutlineSettingsBox;
class Viewport;

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(model::Document* document, QWidget* parent = nullptr);
    /// The viewport whose tools (align, brush, preview) the panel drives.
    void setViewport(Viewport* viewport);

    // The buttons, for shortcuts in menus and for tests.
    [[nodiscard]] QPushButton* alignButton() const { return m_align; }
    [[nodiscard]] QPushButton* createKeyButton() const { return m_createKey; }
    [[nodiscard]] QPushButton* editKeyButton() const { return m_editKey; }
    [[nodiscard]] QPushButton* previewButton() const { return m_preview; }
    [[nodiscard]] QPushButton* matchPointsButton() const { return m_match; }
    [[nodiscard]] QPushButton* solveCameraButton() const { return m_solve; }
    /// A drawing's outline settings and a key's Fit to Drawing group.
    [[nodiscard]] OutlineSettingsBox* outlineSettings() const { return m_outlineBox; }
    [[nodiscard]] FitGroup* fitGroup() const { return m_fit; }
    /// The window's Fit Camera to Drawing and Fit Shape to Drawing, for the panel's buttons.
    void setFitActions(QAction* fitCamera, QAction* fitShape);

    /// 8% of the model's diagonal: a useful first brush on any scale (0 without a model).
    [[nodiscard]] double defaultBrushRadius() const;

public slots:
    void showSelection(celform::views::ScenePanel::Selection selection);
    /// The brushes' radius in world units and in pixels, as the tools have it now.
    void showBrushRadius(double radius, double pixels);
    /// The align tool's matched points and whether clicks place them.
    void showMatching(int modelPoints, int drawingPoints, bool matching);
    /// The outcome of Solve Camera: the RMS error in drawing pixels, or why it failed.
    void showSolveResult(std::optional<double> rms, const QString& error);

signals:
    /// A key was made from the selected drawing; the scene can select it.
    void keyCreated(celform::model::ObjectId key);
    /// A message for the status bar (refused edits, hints).
    void message(const QString& text);
    /// Import Deformation for a key: the window asks for the mesh, reads it as a job (JobRunner)
    /// and makes it the key's deformation.
    void importDeformationRequested(celform::model::ObjectId key);
    // The brush controls: the brushes' shared radius, and the falloff brush's own settings.
    void brushRadiusEdited(double radius);
    void brushPixelRadiusEdited(double pixels);
    void brushRadiusInPixelsEdited(bool pixels);
    void brushProfileEdited(const celform::algo::BrushProfile& profile);
    /// Move, Smooth or Relax, as 0, 1, 2.
    void brushModeEdited(int mode);
    void brushMirrorEdited(bool on);
    // Point matching (the align tool).
    void pointMatchingToggled(bool on);
    void solveCameraRequested();
    void clearMatchedPointsRequested();

private:
    void refresh();
    /// Scrolls the panel until row (a widget of it, shown) is in view.
    void revealRow(QWidget* row);
    void refreshBlend();
    /// The mirror choice: the detected plane marked, the project's plane shown while mirroring.
    void refreshMirror();
    /// Mirroring switched on (at the project's plane, else the detected one) or off.
    void setMirrorOn(bool on);
    /// One blend settings edit from a control (not while the panel itself updates them).
    void documentChanged(const model::ChangeSet& change);
    void refreshTools();
    void refreshMatching();
    void importDeformation();

    model::Document* m_document;
    QPointer<Viewport> m_viewport;
    ScenePanel::Selection m_selection;
    bool m_updating = false;

    QGroupBox* m_selectionBox;
    QFormLayout* m_form;
    QLabel* m_summary;
    QLabel* m_thumbnail;
    QLineEdit* m_name;
    QSlider* m_opacity;
    QLabel* m_opacityValue;
    QWidget* m_opacityRow;
    QCheckBox* m_onTop;
    QPushButton* m_align;
    QDoubleSpinBox* m_fov;
    QComboBox* m_projection;
    QPushButton* m_createKey;
    QWidget* m_matchRow;
    QPushButton* m_match;
    QPushButton* m_solve;
    QPushButton* m_clearPoints;
    QLabel* m_matchStatus;
    std::optional<double> m_lastSolveError;
    int m_modelPoints = 0, m_drawingPoints = 0; ///< the align tool's, as last reported
    bool m_matching = false; ///< RMS reprojection error of the last Solve Camera, pixels
    QCheckBox* m_enabled;
    QComboBox* m_linkedDrawing;
    QPushButton* m_editKey;
    QPushButton* m_importDeformation;
    OutlineSettingsBox* m_outlineBox;
    FitGroup* m_fit;

    QGroupBox* m_brushBox;
    QDoubleSpinBox* m_radius;
    QSpinBox* m_pixelRadius;
    QComboBox* m_radiusUnit;
    QComboBox* m_falloff;
    QDoubleSpinBox* m_strength;
    QComboBox* m_brushMode;
    QComboBox* m_mirror; ///< Off, X, Y, Z (index = model::MirrorPlane)

    QDoubleSpinBox* m_sharpness;
    QComboBox* m_unspecified;
    QComboBox* m_time;
    QPushButton* m_preview;
    QTimer m_summaryRefresh; ///< throttles refreshes during a brush stroke
    bool m_summaryPending = false;
};

} // namespace celform::views
