// A drawing's outline settings in the Properties panel: how Fit to Drawing reads the drawing's
// outline (the threshold of the ink, automatic by Otsu's method or set by hand, the radius that
// closes gaps in open line art, whether the inner lines stay), saved with the drawing, each change
// one undo step (a spin box drag one step); below them what the extraction found or why it failed,
// and Fit Camera to Drawing. The viewport's outline mode (O) shows the same outline.
#pragma once

#include "celform/model/data/object_id.h"

#include <QGroupBox>
#include <QPointer>
#include <QTimer>

#include <memory>

class QAction;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class OutlineCache;

class OutlineSettingsBox : public QGroupBox {
    Q_OBJECT
public:
    OutlineSettingsBox(model::Document* document, QWidget* parent = nullptr);
    /// The drawing shown (0: none).
    void setDrawing(model::ObjectId drawing);
    /// Where the outlines come from (the viewport's, so each is extracted once).
    void setOutlineCache(std::shared_ptr<OutlineCache> cache);
    /// The button's action: Fit Camera to Drawing (the window's).
    void setFitCameraAction(QAction* action);

    [[nodiscard]] QCheckBox* automaticBox() const { return m_automatic; }
    [[nodiscard]] QDoubleSpinBox* thresholdBox() const { return m_threshold; }
    [[nodiscard]] QDoubleSpinBox* closingBox() const { return m_closing; }
    [[nodiscard]] QCheckBox* innerLinesBox() const { return m_innerLines; }
    /// What the extraction found, or why it failed.
    [[nodiscard]] QString statusText() const;

signals:
    /// A refused edit, for the status bar.
    void message(const QString& text);

private:
    void refresh();
    void refreshStatus();
    void documentChanged(const model::ChangeSet& change);
    /// Stores the controls' values as the drawing's settings.
    void edit(const QObject* control);

    model::Document* m_document;
    std::shared_ptr<OutlineCache> m_cache;
    model::ObjectId m_drawing = 0;
    bool m_updating = false;
    QCheckBox* m_automatic;
    QDoubleSpinBox* m_threshold;
    QDoubleSpinBox* m_closing;
    QCheckBox* m_innerLines;
    QLabel* m_status;
    QToolButton* m_fitCamera;
    QTimer m_statusTimer; ///< the extraction waits for a pause in a spin box drag
};

} // namespace celform::views
