// The Highlights dock: stylized highlight layers of the document (Anjyo & Hiramitsu 2003, "Making
// highlight animation"): the layer list, the selected layer's parameters at the playhead
// (interpolated between keys), its operations and combinations, and a timeline with the layer's
// keys. Editing a keyed parameter writes the key at the playhead; every change is one document
// operation on the layer's id (a held spin-box arrow or key is one undo step).
#pragma once

#include "celform/model/document/document.h"

#include <QColor>
#include <QWidget>

#include <vector>

class QAction;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QListWidget;
class QComboBox;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace celform::views {

class FrameTimeline;
class HighlightCombinationsBox;
class HighlightOperationsBox;
class Viewport;

class HighlightPanel : public QWidget {
    Q_OBJECT
public:
    explicit HighlightPanel(model::Document* document, QWidget* parent = nullptr);

    /// The viewport whose Patch and Highlight tools the dock drives (may be null).
    void setViewport(Viewport* viewport);
    /// The document's playhead (the dock has no frame of its own).
    [[nodiscard]] int currentFrame() const { return m_document->currentFrame(); }
    /// Moves the document's playhead, clamped to the timeline's frames.
    void setCurrentFrame(int frame);
    /// Index of the selected layer in the look's highlights, -1 when none.
    [[nodiscard]] int selectedLayer() const;
    /// Id of the selected layer, 0 when none.
    [[nodiscard]] model::ObjectId selectedLayerId() const;
    void selectLayer(int index);
    [[nodiscard]] FrameTimeline* timeline() const { return m_timeline; }

signals:
    // What the viewport's tools edit (panels do not know tools: the editor window connects them).
    /// The highlight layer the viewport's highlight drag moves (0: none).
    void highlightTargetChosen(celform::model::ObjectId layer);
    /// The face set the viewport's patch brush paints into.
    void patchTargetChosen(const QString& faceSet);
    /// The patch brush paints the mirror image too (the Mirror button by Paint).
    void patchMirrorToggled(bool on);

private:
    void documentChanged(const model::ChangeSet& change);
    /// The frame spin box and the key strip follow the scene's frame range.
    void syncFrameRange();
    /// Edits the selected layer's key at the playhead through HighlightEdits::setHighlightKey.
    void editKey(const std::function<void(algo::HighlightLayer&)>& change, model::GestureId gesture = {});
    /// Runs a document operation; a refused edit puts the controls back.
    void run(const std::function<void()>& operation);
    [[nodiscard]] const model::HighlightTrack* track() const;
    QDoubleSpinBox* makeSpin(double min, double max, double step, int decimals, const QString& tip);
    void refresh();
    void jumpToKey(int direction);
    /// Adds the layers of a preset after the others (one undo step) and selects the visible one.
    void addPreset(model::HighlightPreset preset);
    /// Makes an empty face set named after the selected layer and puts the layer on it (one undo step).
    void newPatchForLayer();

    model::Document* m_document;
    Viewport* m_viewport = nullptr;
    bool m_updating = false;

    QListWidget* m_layers;
    QPushButton* m_addLayer;
    QToolButton* m_addPreset;
    QPushButton* m_removeLayer;
    FrameTimeline* m_timeline;
    QSpinBox* m_frameSpin;
    QSpinBox* m_lastFrame;
    QToolButton* m_previousKey;
    QToolButton* m_nextKey;
    QPushButton* m_key;
    QPushButton* m_deleteKey;
    QGroupBox* m_parameters;
    QToolButton* m_color;
    QColor m_swatchColour; ///< the colour m_color's icon shows
    QDoubleSpinBox* m_epsilon;
    QDoubleSpinBox* m_cut;
    QComboBox* m_patch;
    QToolButton* m_paintPatch;
    QAction* m_newPatch;
    QAction* m_renamePatch;
    QAction* m_deletePatch;
    QDoubleSpinBox* m_guide[3];
    QSpinBox* m_smoothing;
    QPushButton* m_editInViewport;
    HighlightOperationsBox* m_operations;
    HighlightCombinationsBox* m_combinations;
    QLabel* m_viewportLimit;
};

} // namespace celform::views
