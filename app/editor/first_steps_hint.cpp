#include "editor/first_steps_hint.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"

#include "celform/algorithms/tri_mesh.h"

#include <QApplication>
#include <QEvent>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace celform::app {

FirstStepsHint::FirstStepsHint(model::Document* document, views::Viewport* viewport)
    : QLabel(viewport)
    , m_document(document)
    , m_viewport(viewport)
{
    setObjectName(QStringLiteral("firstStepsHint"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setWordWrap(true);
    setStyleSheet(QStringLiteral("QLabel { background: rgba(20, 20, 20, 170); color: white; padding: 6px 10px; "
                                 "border-radius: 4px; }"));
    viewport->installEventFilter(this);
    // While a tool is on, its own banner says what to do.
    connect(viewport, &views::Viewport::toolChanged, this, [this] { refresh(); });
    // The model moves under the caption as the view changes: keep it clear of the model.
    connect(viewport, &views::Viewport::cameraChanged, this, [this] {
        if (isVisibleTo(parentWidget()))
            place();
    });
    connect(document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        if (change.reset) {
            const model::ProjectData& data = m_document->data();
            m_showcase = !data.keys.empty() && !data.look.cameraPath.empty();
            if (m_showcase)
                qApp->installEventFilter(this);
        }
        refresh();
    });
    connect(document->undoStack(), &QUndoStack::indexChanged, this, [this] { endShowcase(); });
    refresh();
}

QString FirstStepsHint::hintText() const
{
    const model::ProjectData& data = m_document->data();
    if (m_showcase && m_viewport->tool() == views::Viewport::Tool::Navigate)
        return tr("Press Space: the model changes shape with the view to match its drawings. Click a key in the "
                  "Scene panel to see its drawing.");
    if (!m_document->hasMesh())
        return tr("Start with a model: File ▸ New from Mesh (Ctrl+N), or open a project (Ctrl+O). "
                  "Help ▸ Getting Started walks through the rest.");
    if (data.drawings.empty())
        return tr("Import a drawing of the model sheet: File ▸ Import Drawing (Ctrl+Shift+I), or drop an image "
                  "here.");
    if (!data.keys.empty() || m_viewport->tool() != views::Viewport::Tool::Navigate)
        return {};
    const model::Drawing* selected = data.drawing(m_selectedDrawing);
    if (!selected)
        return tr("Select a drawing in the Scene panel and press Align to Drawing; then Create Key from Drawing.");
    if (!selected->aligned) {
        QString align = tr("Press Align to Drawing in the Properties panel and move the camera until the model "
                           "matches the drawing.");
        // Linux desktops move windows with Alt + drag by default: the Maya style's orbit never
        // reaches the viewport there (the Preferences say the same).
        if (m_viewport->navigation().style == views::NavigationStyle::Maya
            && !qEnvironmentVariableIsEmpty("XDG_CURRENT_DESKTOP"))
            align += QLatin1Char(' ')
                + tr("If Alt + drag moves the window instead of the view, choose Blender navigation in "
                     "Edit ▸ Preferences: it needs no Alt.");
        return align;
    }
    return tr("The camera matches the drawing: press Create Key from Drawing in the Properties panel.");
}

void FirstStepsHint::setSelectedDrawing(model::ObjectId drawing)
{
    m_selectedDrawing = drawing;
    refresh();
}

void FirstStepsHint::refresh()
{
    const QString text = hintText();
    setText(text);
    setVisible(!text.isEmpty());
    if (!text.isEmpty())
        place();
}

QRect FirstStepsHint::modelRect()
{
    if (!m_document->hasMesh())
        return {};
    // The box is the base model's: measured once per model, not at every step of an orbit.
    const std::shared_ptr<const algo::TriMesh>& mesh = m_document->data().baseMesh;
    if (m_boxOf.lock() != mesh) {
        m_box = algo::boundingBox(mesh->vertices);
        m_boxOf = mesh;
    }
    const Eigen::AlignedBox3d& box = m_box;
    QRectF rect;
    for (int corner = 0; corner < 8; ++corner) {
        const QPointF p = m_viewport->projectToWidget(box.corner(Eigen::AlignedBox3d::CornerType(corner)));
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            continue;
        rect = rect.isNull() ? QRectF(p, QSizeF(1.0, 1.0)) : rect.united(QRectF(p, QSizeF(1.0, 1.0)));
    }
    return rect.toAlignedRect();
}

void FirstStepsHint::place()
{
    const QWidget* viewport = parentWidget();
    // A caption, not a banner: a few lines of a readable measure.
    setMaximumWidth(std::clamp(viewport->width() - 24, 120, 560));
    adjustSize();
    // Bottom or top centre (the corners hold the orientation axes and the axis gizmo), whichever
    // covers less of the model.
    const int x = (viewport->width() - width()) / 2;
    const QRect bottom(QPoint(x, viewport->height() - height() - 12), size());
    const QRect top(QPoint(x, 12), size());
    const QRect model = modelRect();
    auto covered = [&](const QRect& r) {
        const QRect common = r.intersected(model);
        return common.isEmpty() ? 0 : common.width() * common.height();
    };
    move((covered(top) < covered(bottom) ? top : bottom).topLeft());
    raise();
}

void FirstStepsHint::endShowcase()
{
    if (!m_showcase)
        return;
    m_showcase = false;
    qApp->removeEventFilter(this);
    refresh();
}

bool FirstStepsHint::eventFilter(QObject* watched, QEvent* event)
{
    // The showcase's caption watches the whole application for the artist's first action (Space
    // is a window shortcut: its override event is the first the application sees).
    const QEvent::Type type = event->type();
    if (m_showcase && watched->isWidgetType() && window() == static_cast<QWidget*>(watched)->window()
        && (type == QEvent::MouseButtonPress || type == QEvent::KeyPress || type == QEvent::ShortcutOverride
            || type == QEvent::Wheel))
        endShowcase();
    // Before the window shows, the caption is not "visible" yet but its place still follows the
    // viewport's size (a --screenshot run placed it for the viewport's first, tiny size).
    if (watched == parentWidget() && (type == QEvent::Resize || type == QEvent::Show) && isVisibleTo(parentWidget()))
        place();
    return QLabel::eventFilter(watched, event);
}

} // namespace celform::app
