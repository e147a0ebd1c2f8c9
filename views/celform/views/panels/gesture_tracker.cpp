// Event filtering for GestureTracker: presses, key repeats and wheel bursts.
#include "celform/views/panels/gesture_tracker.h"

#include "celform/model/document/document.h"

#include <QAbstractSlider>
#include <QEvent>
#include <QKeyEvent>
#include <QWidget>

namespace celform::views {
namespace {

/// Wheel ticks closer together than this belong to one gesture.
constexpr int kWheelPauseMilliseconds = 400;

} // namespace

GestureTracker* GestureTracker::track(QWidget* control, model::Document* document)
{
    return new GestureTracker(control, document);
}

model::GestureId GestureTracker::of(const QObject* control)
{
    const auto* tracker
        = control ? control->findChild<GestureTracker*>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
    return tracker ? tracker->m_gesture.id() : model::GestureId{};
}

GestureTracker::GestureTracker(QWidget* control, model::Document* document)
    : QObject(control)
    , m_document(document)
{
    // The spin box's line edit takes the keys: watch it too.
    control->installEventFilter(this);
    for (QWidget* child : control->findChildren<QWidget*>())
        child->installEventFilter(this);
    // A slider's handle drag starts and ends with the press, wherever the release happens.
    if (auto* slider = qobject_cast<QAbstractSlider*>(control)) {
        connect(slider, &QAbstractSlider::sliderPressed, this, &GestureTracker::begin);
        connect(slider, &QAbstractSlider::sliderReleased, this, &GestureTracker::end);
    }
    m_wheelEnd.setSingleShot(true);
    m_wheelEnd.setInterval(kWheelPauseMilliseconds);
    connect(&m_wheelEnd, &QTimer::timeout, this, &GestureTracker::end);
}

void GestureTracker::begin()
{
    end();
    m_gesture = m_document->beginGesture();
}

void GestureTracker::end()
{
    m_wheelEnd.stop();
    m_gesture.end();
}

bool GestureTracker::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick:
        begin();
        break;
    case QEvent::MouseButtonRelease:
    case QEvent::FocusOut:
    case QEvent::Hide:
        end();
        break;
    case QEvent::KeyPress:
        // An auto-repeated key continues the gesture its first press began.
        if (!static_cast<QKeyEvent*>(event)->isAutoRepeat() || !m_gesture.isOpen())
            begin();
        break;
    case QEvent::KeyRelease:
        if (!static_cast<QKeyEvent*>(event)->isAutoRepeat())
            end();
        break;
    case QEvent::Wheel:
        if (!m_gesture.isOpen())
            begin();
        m_wheelEnd.start();
        break;
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace celform::views
