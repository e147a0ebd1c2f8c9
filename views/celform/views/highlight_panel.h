// The Highlights dock: stylized highlight layers of the document's Look (Anjyo & Hiramitsu 2003,
// "Making highlight animation"): the layer list, the selected layer's parameters at the current
// frame (interpolated between keys), its operations and combinations, and a small timeline with
// the layer's keys. Editing a keyed parameter writes the key at the current frame; every change is
// a Document::setLook (a spin-box drag is one undo step). The current frame is panel state.
#pragma once

#include "celform/model/document.h"

#include <QWidget>

#include <functional>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;
class QToolButton;
class QVBoxLayout;

namespace celform::views {

class Viewport;

/// Frames 0..N with the selected layer's key marks and a draggable current-frame cursor.
class HighlightTimeline : public QWidget {
    Q_OBJECT
public:
    explicit HighlightTimeline(QWidget* parent = nullptr);

    void setFrameCount(int last); ///< the last frame N
    void setKeys(std::vector<double> frames);
    void setFrame(int frame);
    [[nodiscard]] int frame() const { return m_frame; }
    [[nodiscard]] int lastFrame() const { return m_last; }
    /// Horizontal widget coordinate of a frame's centre (tests, hit testing).
    [[nodiscard]] int xForFrame(int frame) const;
    [[nodiscard]] QSize sizeHint() const override { return {240, 40}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {80, 36}; }

signals:
    void frameScrubbed(int frame);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    [[nodiscard]] int frameAt(double x) const;
    int m_last = 48;
    int m_frame = 0;
    std::vector<double> m_keys;
};

class HighlightPanel : public QWidget {
    Q_OBJECT
public:
    explicit HighlightPanel(model::Document* document, QWidget* parent = nullptr);

    /// The viewport that follows the current frame (may be null).
    /// The viewport also receives drags on the model in its Highlight tool ("Edit in Viewport").
    void setViewport(Viewport* viewport);
    [[nodiscard]] int currentFrame() const { return m_frame; }
    void setCurrentFrame(int frame);
    /// Index of the selected layer in Look::highlights, -1 when none.
    [[nodiscard]] int selectedLayer() const;
    void selectLayer(int index);
    [[nodiscard]] HighlightTimeline* timeline() const { return m_timeline; }

signals:
    void frameChanged(int frame);

private:
    /// Applies an edit to a copy of the look and pushes it when valid. Edits with the same
    /// non-empty mergeKey in a row (a spin-box drag) are one undo step; others are one each.
    void edit(const QString& undoText, const std::function<void(model::Look&)>& change, const QString& mergeKey = {});
    /// Edits the selected track (no-op without one).
    void editTrack(const QString& undoText, const std::function<void(model::HighlightTrack&)>& change,
        const QString& mergeKey = {});
    /// Edits the selected track's layer at the current frame and writes it as the key there.
    void editKey(const QString& undoText, const std::function<void(algo::HighlightLayer&)>& change,
        const QString& mergeKey = {});
    /// Applies a structural change of the operations to every key of the selected track.
    void editOperations(
        const QString& undoText, const std::function<void(std::vector<algo::HighlightOperation>&)>& change);
    [[nodiscard]] const model::HighlightTrack* track() const;
    [[nodiscard]] std::vector<QString> faceSetNames() const;
    QDoubleSpinBox* makeSpin(double min, double max, double step, int decimals, const QString& tip);
    void refresh();
    void rebuildOperations(const algo::HighlightLayer& layer);
    void rebuildCombinations(const model::HighlightTrack& t);
    void jumpToKey(int direction);
    enum class Preset { Window, Crescent };
    /// Adds the layers of a preset after the others (one undo step) and selects the visible one.
    void addPreset(Preset preset);
    /// Makes an empty face set named after the selected layer and puts the layer on it (one undo step).
    void newPatchForLayer();
    /// Viewport drags (Tool::Highlight): plain translates the highlight along the tangent frame at
    /// the picked point as seen on screen, Shift rotates, Ctrl scales; one undo step per drag.
    void beginViewportDrag(const QPointF& position);
    void viewportDrag(const QPointF& delta, Qt::KeyboardModifiers modifiers);

    model::Document* m_document;
    Viewport* m_viewport = nullptr;
    bool m_updating = false;
    int m_frame = 0;
    QString m_lastMergeKey;
    int m_lastUndoIndex = -1;
    int m_dragCount = 0;
    QPointF m_dragDu, m_dragDv; ///< screen directions (unit) of du, dv at the picked point
    double m_dragUnitsPerPixel = 0.005; ///< translation parameter per pixel of drag
    QPushButton* m_editInViewport;

    QListWidget* m_layers;
    QPushButton* m_addLayer;
    QToolButton* m_addPreset;
    QPushButton* m_removeLayer;
    HighlightTimeline* m_timeline;
    QSpinBox* m_frameSpin;
    QSpinBox* m_lastFrame;
    QToolButton* m_previousKey;
    QToolButton* m_nextKey;
    QPushButton* m_key;
    QPushButton* m_deleteKey;
    QGroupBox* m_parameters;
    QToolButton* m_color;
    QDoubleSpinBox* m_epsilon;
    QDoubleSpinBox* m_cut;
    QComboBox* m_patch;
    QToolButton* m_paintPatch;
    QAction* m_newPatch;
    QAction* m_renamePatch;
    QAction* m_deletePatch;
    QDoubleSpinBox* m_guide[3];
    QSpinBox* m_smoothing;
    QGroupBox* m_operationsBox;
    QVBoxLayout* m_operationRows;
    QToolButton* m_addOperation;
    std::vector<algo::HighlightOperationType> m_operationTypes; ///< the rows' types, to rebuild on change
    std::vector<std::pair<QDoubleSpinBox*, QDoubleSpinBox*>> m_operationSpins;
    QGroupBox* m_combinationsBox;
    QVBoxLayout* m_combinationRows;
    QPushButton* m_addCombination;
    QLabel* m_viewportLimit;
};

} // namespace celform::views
