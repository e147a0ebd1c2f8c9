#include "editor/first_steps_hint.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"

#include <QEvent>

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
    connect(document, &model::Document::changed, this, [this](const model::ChangeSet&) { refresh(); });
    refresh();
}

QString FirstStepsHint::hintText() const
{
    const model::ProjectData& data = m_document->data();
    if (!m_document->hasMesh())
        return tr("Start with a model: File ▸ New from Mesh (Ctrl+N), or open a project (Ctrl+O). "
                  "Help ▸ Getting Started walks through the rest.");
    if (data.drawings.empty())
        return tr("Import a drawing of the model sheet: File ▸ Import Drawing (Ctrl+Shift+I), or drop an image "
                  "here.");
    if (data.keys.empty() && m_viewport->tool() == views::Viewport::Tool::Navigate)
        return tr("Select a drawing in the Scene panel and press Align to Drawing; then Create Key from Drawing.");
    return {};
}

void FirstStepsHint::refresh()
{
    const QString text = hintText();
    setText(text);
    setVisible(!text.isEmpty());
    if (!text.isEmpty())
        place();
}

void FirstStepsHint::place()
{
    const QWidget* viewport = parentWidget();
    setMaximumWidth(std::max(viewport->width() - 24, 120));
    adjustSize();
    // Bottom centre: the corners hold the orientation axes and the axis gizmo.
    move((viewport->width() - width()) / 2, viewport->height() - height() - 12);
    raise();
}

bool FirstStepsHint::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == parentWidget() && event->type() == QEvent::Resize && isVisible())
        place();
    return QLabel::eventFilter(watched, event);
}

} // namespace celform::app
