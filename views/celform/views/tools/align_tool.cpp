// The align tool: camera commits after navigation settles, and the matched points with their
// markers over the viewport.
#include "celform/views/tools/align_tool.h"

#include "celform/algorithms/camera_solve.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/viewport/viewport.h"

#include <QLabel>
#include <QPainter>
#include <QWidget>

#include <algorithm>

namespace celform::views {
namespace {

/// Paints the matched points of the semi-automatic alignment over the viewport: model points
/// as red numbered dots, drawing points as blue numbered rings, a line between each pair.
class MatchMarkers : public QWidget {
public:
    MatchMarkers(Viewport* viewport, const AlignTool* tool)
        : QWidget(viewport)
        , m_viewport(viewport)
        , m_tool(tool)
    {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
    }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        QFont font = p.font();
        font.setBold(true);
        p.setFont(font);
        const auto& model = m_tool->matchedModelPoints();
        const auto& drawing = m_tool->matchedDrawingPoints();
        for (size_t i = 0; i < std::max(model.size(), drawing.size()); ++i) {
            const QString label = QString::number(i + 1);
            QPointF a, b;
            if (i < model.size())
                a = m_viewport->projectToWidget(model[i]);
            if (i < drawing.size())
                b = m_viewport->drawingOverlay().drawingToWidget(drawing[i]);
            if (i < model.size() && i < drawing.size()) {
                p.setPen(QPen(QColor(40, 40, 40, 160), 1, Qt::DashLine));
                p.drawLine(a, b);
            }
            if (i < model.size()) {
                p.setPen(QPen(Qt::white, 1.5));
                p.setBrush(QColor(220, 50, 40));
                p.drawEllipse(a, 5, 5);
                p.setPen(QColor(150, 20, 10));
                p.drawText(a + QPointF(7, -6), label);
            }
            if (i < drawing.size()) {
                p.setPen(QPen(QColor(30, 90, 220), 2.5));
                p.setBrush(Qt::NoBrush);
                p.drawEllipse(b, 6, 6);
                p.setPen(QColor(20, 60, 170));
                p.drawText(b + QPointF(8, 14), label);
            }
        }
    }

private:
    Viewport* m_viewport;
    const AlignTool* m_tool;
};

} // namespace

AlignTool::AlignTool(Viewport* viewport)
    : ViewportTool(viewport)
    , m_markers(new MatchMarkers(viewport, this))
    , m_banner(new QLabel(viewport))
{
    m_markers->hide();
    m_banner->setObjectName(QStringLiteral("alignBanner"));
    m_banner->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_banner->setStyleSheet(QStringLiteral("QLabel { background: rgba(30, 90, 200, 200); color: white; "
                                           "border-radius: 5px; padding: 4px 10px; }"));
    m_banner->hide();
    // The markers follow the camera whichever tool is on (points outlive the tool until cleared).
    connect(viewport, &Viewport::cameraChanged, m_markers, qOverload<>(&QWidget::update));
    // The pairs belong to the drawing they were placed on.
    connect(&viewport->drawingOverlay(), &DrawingOverlay::drawingChanged, this, [this] {
        if (!m_modelPoints.empty() || !m_drawingPoints.empty())
            clearMatchedPoints();
    });
    // An undo or redo of the drawing's camera moves the view at once, not when the mode restarts.
    if (model::Document* document = viewport->document())
        connect(document, &model::Document::changed, this, &AlignTool::documentChanged);
}

AlignTool::~AlignTool() = default;

void AlignTool::activate()
{
    model::Document* document = m_viewport->document();
    m_drawing = m_viewport->drawingOverlay().drawing();
    const model::Drawing* drawing = document && m_drawing ? document->data().drawing(m_drawing) : nullptr;
    if (!drawing) {
        m_drawing = 0;
        return;
    }
    // Start from the stored alignment, so refining it does not jump; nothing is stored until the
    // artist moves the camera.
    // Moving the view there is not the artist's move: it stores nothing (the previous mode's
    // camera is still in m_stored until the line below).
    if (drawing->aligned) {
        m_following = true;
        m_viewport->setCamera(drawing->camera);
        m_following = false;
    }
    m_stored = m_viewport->camera();
    m_banner->setText(tr("Aligning to “%1”: move the camera until the model matches the drawing "
                         "(Alt+drag, the wheel, Alt+Shift+drag rolls, add Ctrl to snap to 15°; numpad 1/3/7 "
                         "for the axis views; O: outline only). Esc finishes.")
                          .arg(drawing->name));
    placeBanner();
    m_banner->show();
    m_banner->raise();
}

void AlignTool::deactivate()
{
    commit();
    closeGesture();
    m_drawing = 0;
    m_banner->hide();
    if (m_matching)
        setPointMatching(false);
}

void AlignTool::placeBanner()
{
    // Clear of the axis gizmo in the top right corner.
    m_banner->setMaximumWidth(std::max(m_viewport->width() - 200, 100));
    m_banner->setWordWrap(true);
    m_banner->adjustSize();
    m_banner->move((m_viewport->width() - m_banner->width()) / 2, 8);
}

void AlignTool::commit()
{
    model::Document* document = m_viewport->document();
    // Only the drawing the mode was started on, and only a camera the artist changed (a resize
    // or another drawing's letterbox keeps the camera and stores nothing).
    if (!document || !m_drawing || m_following || m_viewport->drawingOverlay().drawing() != m_drawing)
        return;
    const model::Camera camera = m_viewport->camera();
    if (camera == m_stored)
        return;
    document->drawings().setDrawingCamera(m_drawing, camera, gesture());
    m_stored = camera;
}

void AlignTool::documentChanged(const model::ChangeSet& change)
{
    model::Document* document = m_viewport->document();
    if (!m_drawing || inGesture() || !change.has(model::Part::Drawings) || !change.touches(m_drawing))
        return;
    const model::Drawing* drawing = document->data().drawing(m_drawing);
    if (!drawing || !drawing->aligned || drawing->camera == m_stored)
        return;
    // The view's camera change stores nothing: it is the document's (and an edit pushed from an
    // undo or redo would break the history).
    m_following = true;
    m_viewport->setCamera(drawing->camera);
    m_following = false;
    m_stored = m_viewport->camera();
}

void AlignTool::cameraChanged()
{
    commit();
}

void AlignTool::navigationStarted()
{
    openGesture(); // the drag's or the wheel burst's camera edits merge into one undo step
}

void AlignTool::navigationEnded()
{
    commit();
    closeGesture();
}

bool AlignTool::press(const ToolEvent& event)
{
    if (!m_matching)
        return false;
    if (event.modifiers & Qt::ShiftModifier) {
        if (const auto pixel = m_viewport->drawingOverlay().widgetToDrawing(event.position))
            m_drawingPoints.push_back(*pixel);
        else
            emit message(tr("Shift+click inside the drawing to place its point."));
    } else if (const auto hit = m_viewport->pickSurface(event.position)) {
        // The picked surface point, not the nearest vertex: features rarely sit on one.
        m_modelPoints.push_back(hit->second);
    } else {
        emit message(tr("Click on the model to place a model point; Shift+click places the drawing point."));
    }
    m_markers->setVisible(true);
    markersChanged();
    return false; // a click, not a drag
}

void AlignTool::markersChanged()
{
    m_markers->update();
    emit matchedPointsChanged();
}

void AlignTool::setPointMatching(bool on)
{
    m_matching = on;
    m_markers->setVisible(on || !m_modelPoints.empty() || !m_drawingPoints.empty());
    m_markers->setGeometry(m_viewport->rect());
    m_markers->update();
    if (on)
        emit message(tr("Click a feature on the model, then Shift+click the same feature on the drawing; "
                        "six pairs or more, then Solve Camera."));
}

void AlignTool::clearMatchedPoints()
{
    m_modelPoints.clear();
    m_drawingPoints.clear();
    m_markers->setVisible(m_matching);
    markersChanged();
}

void AlignTool::removeLastMatchedPoint()
{
    if (m_drawingPoints.size() >= m_modelPoints.size() && !m_drawingPoints.empty())
        m_drawingPoints.pop_back();
    else if (!m_modelPoints.empty())
        m_modelPoints.pop_back();
    markersChanged();
}

void AlignTool::resized()
{
    m_markers->setGeometry(m_viewport->rect());
    if (m_banner->isVisible())
        placeBanner();
}

std::optional<double> AlignTool::solveFromMatchedPoints(QString* error)
{
    model::Document* document = m_viewport->document();
    const model::Drawing* drawing = (document && m_viewport->drawingOverlay().drawing())
        ? document->data().drawing(m_viewport->drawingOverlay().drawing())
        : nullptr;
    const size_t pairs = std::min(m_modelPoints.size(), m_drawingPoints.size());
    if (!drawing || drawing->image.isNull()) {
        if (error)
            *error = tr("Show a drawing to align first.");
        return std::nullopt;
    }
    if (pairs < 6) {
        if (error)
            *error = tr("%1 pairs of points so far; the camera needs at least six.").arg(pairs);
        return std::nullopt;
    }
    std::string message;
    const auto solved = algo::solveCamera(
        std::vector<Eigen::Vector3d>(m_modelPoints.begin(), m_modelPoints.begin() + std::ptrdiff_t(pairs)),
        std::vector<Eigen::Vector2d>(m_drawingPoints.begin(), m_drawingPoints.begin() + std::ptrdiff_t(pairs)),
        drawing->image.width(), drawing->image.height(), &message);
    if (!solved) {
        if (error)
            *error = tr("The camera could not be solved: %1").arg(QString::fromStdString(message));
        return std::nullopt;
    }
    model::Camera camera;
    camera.eye = solved->eye;
    camera.target = solved->target;
    camera.up = solved->up;
    camera.projection = model::Projection::Perspective;
    camera.fovYDegrees = solved->fovYDegrees;
    // One step: the solved camera, stored with the drawing (setCamera commits it while aligning).
    m_viewport->setCamera(camera);
    if (m_drawing != m_viewport->drawingOverlay().drawing())
        document->drawings().setDrawingCamera(m_viewport->drawingOverlay().drawing(), camera);
    m_markers->update();
    return solved->rmsPixelError;
}

} // namespace celform::views
