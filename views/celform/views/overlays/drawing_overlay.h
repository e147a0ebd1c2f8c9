// The reference drawing fixed in the viewport (paper 1, section 3.1.1): which drawing, over the
// model (with its opacity) or under it as a backdrop, or only its outline in magenta for checking
// that contours meet: the outline Fit to Drawing aims at, extracted with the drawing's saved
// settings (a banner says why when there is none); its height fills the view, so a camera aligned
// here matches the drawing. The viewport draws what this says and follows its signals.
#pragma once

#include "celform/model/data/object_id.h"

#include <QImage>
#include <QObject>
#include <QPointF>
#include <QString>

#include <Eigen/Core>

#include <memory>
#include <optional>

class QLabel;
class QWidget;

namespace celform::algo {
struct Outline;
}

namespace celform::model {
class Document;
struct Drawing;
} // namespace celform::model

namespace celform::views {

class OutlineCache;

class DrawingOverlay : public QObject {
    Q_OBJECT
public:
    /// view: the widget the drawing fills (its size places the drawing).
    DrawingOverlay(model::Document* document, QWidget* view);

    /// The drawing shown (0: none).
    void setDrawing(model::ObjectId drawing);
    [[nodiscard]] model::ObjectId drawing() const { return m_drawing; }
    /// The drawing the artist asked to see (the eye in the Scene panel, the D key), 0 for none: it
    /// stays shown whatever is selected. Only aligning or brushing a key shows a drawing of itself,
    /// and selecting one shows it until something else is selected. A view state like the camera,
    /// so not saved with the project nor an undoable edit. One at a time, as one is shown.
    [[nodiscard]] model::ObjectId askedFor() const { return m_asked; }
    /// The eye: drawing shown is hidden (and no longer asked for); hidden, it is shown and asked for.
    void toggleShown(model::ObjectId drawing);
    /// Back to what the artist asked for: the drawing asked for, or none (leaving a selection,
    /// Navigate Only).
    void showAskedFor() { setDrawing(m_asked); }
    /// Over the model (with the drawing's opacity) or under it, as a backdrop.
    void setOnTop(bool onTop);
    [[nodiscard]] bool onTop() const { return m_onTop; }
    /// Only the drawing's outline, in magenta, for checking contours meet: the outline Fit to
    /// Drawing reads (model::drawingOutline); the drawing's lines in orange when it has none.
    void setOutline(bool on);
    [[nodiscard]] bool outline() const { return m_outline; }
    /// Why the drawing shown has no outline (model::outlineProblem), empty when it has one or the
    /// outline mode is off; the banner over the viewport shows it.
    [[nodiscard]] QString outlineProblem() const { return m_problem; }
    /// The drawings' extracted outlines, shared with whoever measures against them.
    [[nodiscard]] const std::shared_ptr<OutlineCache>& outlineCache() const { return m_outlines; }

    /// Widget position (logical pixels) to drawing pixels and back, for the drawing shown.
    [[nodiscard]] std::optional<Eigen::Vector2d> widgetToDrawing(const QPointF& position) const;
    [[nodiscard]] QPointF drawingToWidget(const Eigen::Vector2d& pixel) const;

    // --- for the viewport that draws it -----------------------------------------------------
    /// The drawing shown, or null; one the document no longer has is forgotten (no signal).
    const model::Drawing* resolve();
    /// The image to draw (the drawing's, or its outline), null for none; after resolve().
    [[nodiscard]] const QImage* image();
    [[nodiscard]] bool drawnOnTop() const { return m_onTop || m_outline; }
    /// The outline is drawn at full strength: it is thin.
    [[nodiscard]] double opacity() const;
    /// How much the camera's frame is enlarged so that the drawing's frame fits in the view.
    [[nodiscard]] double frameScale() const;
    /// Forgets the drawing without signals (a new document: the viewport redraws everything).
    void forget() { m_drawing = 0; }

signals:
    /// The drawing shown is about to change: aligning to the old one ends (and stores) first.
    void drawingAboutToChange();
    /// The drawing shown changed.
    void drawingChanged();
    /// What is drawn changed (the drawing, on top, outline).
    void changed();
    /// The outline mode's problem changed (empty: none now).
    void outlineProblemChanged(const QString& problem);

private:
    [[nodiscard]] const model::Drawing* current() const;
    void setProblem(const QString& problem);
    void placeBanner();
    bool eventFilter(QObject* watched, QEvent* event) override;

    model::Document* m_document;
    QWidget* m_view;
    model::ObjectId m_drawing = 0;
    model::ObjectId m_asked = 0;
    bool m_onTop = true;
    bool m_outline = false;
    std::shared_ptr<OutlineCache> m_outlines;
    QImage m_outlineImage; ///< the drawing's outline, made when first shown
    std::shared_ptr<const algo::Outline> m_outlineSource; ///< the outline m_outlineImage was drawn from
    qint64 m_edgesSource = 0; ///< cacheKey of the image m_outlineImage's lines were found in
    QString m_problem;
    QLabel* m_banner; ///< the problem, over the bottom of the viewport
};

} // namespace celform::views
