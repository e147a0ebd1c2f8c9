// The Timeline dock's panel (timeline_panel.h).
#include "celform/views/timeline/timeline_panel.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/timeline/playback.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace celform::views {
namespace {

QToolButton* transportButton(QWidget* parent, QStyle::StandardPixmap icon, const QString& name, const QString& tip)
{
    auto* button = new QToolButton(parent);
    button->setObjectName(name);
    button->setIcon(parent->style()->standardIcon(icon));
    button->setToolTip(tip);
    button->setAutoRaise(true);
    return button;
}

} // namespace

TimelinePanel::TimelinePanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_playback(new Playback(document, this))
    , m_ruler(new TimelineRuler(document, this))
    , m_first(new QSpinBox(this))
    , m_last(new QSpinBox(this))
    , m_fps(new QDoubleSpinBox(this))
    , m_current(new QSpinBox(this))
{
    setObjectName(QStringLiteral("timelinePanel"));
    auto* start = transportButton(this, QStyle::SP_MediaSkipBackward, QStringLiteral("timelineStart"),
        tr("Go to the first frame of the range (Shift+Left)"));
    auto* previousKey = transportButton(this, QStyle::SP_MediaSeekBackward, QStringLiteral("timelinePreviousKey"),
        tr("Go to the previous keyed frame of any kind (Down)"));
    m_play = transportButton(this, QStyle::SP_MediaPlay, QStringLiteral("timelinePlay"),
        tr("Play or pause at the scene's frame rate (Space)"));
    m_play->setCheckable(true);
    auto* nextKey = transportButton(this, QStyle::SP_MediaSeekForward, QStringLiteral("timelineNextKey"),
        tr("Go to the next keyed frame of any kind (Up)"));
    auto* end = transportButton(this, QStyle::SP_MediaSkipForward, QStringLiteral("timelineEnd"),
        tr("Go to the last frame of the range (Shift+Right)"));
    m_loop = transportButton(this, QStyle::SP_BrowserReload, QStringLiteral("timelineLoop"),
        tr("Loop: after the last frame play the first again"));
    m_loop->setCheckable(true);
    m_loop->setChecked(m_playback->isLooping());

    m_current->setObjectName(QStringLiteral("timelineCurrentFrame"));
    m_current->setRange(-model::kMaxFrame, model::kMaxFrame);
    m_current->setKeyboardTracking(false);
    m_current->setToolTip(tr("The current frame: every view shows the project at this frame"));
    m_first->setObjectName(QStringLiteral("timelineFirstFrame"));
    m_first->setKeyboardTracking(false);
    m_first->setToolTip(tr("First frame of the scene's range (playback and rendered sequences)"));
    m_last->setObjectName(QStringLiteral("timelineLastFrame"));
    m_last->setKeyboardTracking(false);
    m_last->setToolTip(tr("Last frame of the scene's range"));
    m_fps->setObjectName(QStringLiteral("timelineFps"));
    m_fps->setKeyboardTracking(false);
    m_fps->setRange(1.0, model::kMaxFps);
    m_fps->setDecimals(3);
    m_fps->setSuffix(tr(" fps"));
    m_fps->setToolTip(tr("Frames per second of the scene (playback, exports)"));
    m_achieved = new QLabel(this);
    m_achieved->setObjectName(QStringLiteral("timelineAchievedFps"));
    m_achieved->setToolTip(tr("Frames drawn per second while playing; below the scene's rate, frames are dropped"));
    m_achieved->setMinimumWidth(m_achieved->fontMetrics().horizontalAdvance(tr("Playing: 000.0 fps")));
    auto* legend = new QLabel(this);
    legend->setObjectName(QStringLiteral("timelineLegend"));
    legend->setTextFormat(Qt::RichText);
    legend->setText(
        QStringLiteral("<span style='color:%1'>▼</span> %2 &nbsp;<span style='color:%3'>■</span> %4 "
                       "&nbsp;<span style='color:%5'>◆</span> %6 &nbsp;<span style='color:%7'>●</span> %8")
            .arg(markColor(TimelineMarkKind::Camera).name(), tr("camera"), markColor(TimelineMarkKind::Light).name(),
                tr("light"), markColor(TimelineMarkKind::Deformation).name(), tr("deformation"),
                markColor(TimelineMarkKind::Highlight).name(), tr("highlight")));
    legend->setToolTip(tr("Key marks on the ruler, top to bottom: camera keys, light keys, key deformations and "
                          "highlight keys"));

    auto* controls = new QHBoxLayout;
    controls->setContentsMargins(0, 0, 0, 0);
    for (QWidget* w : std::initializer_list<QWidget*>{start, previousKey, m_play, nextKey, end, m_loop})
        controls->addWidget(w);
    controls->addSpacing(8);
    controls->addWidget(new QLabel(tr("Frame"), this));
    controls->addWidget(m_current);
    controls->addSpacing(8);
    controls->addWidget(new QLabel(tr("Range"), this));
    controls->addWidget(m_first);
    controls->addWidget(new QLabel(QStringLiteral("–"), this));
    controls->addWidget(m_last);
    controls->addWidget(m_fps);
    controls->addSpacing(8);
    controls->addWidget(m_achieved);
    controls->addStretch(1);
    controls->addWidget(legend);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(2);
    layout->addLayout(controls);
    layout->addWidget(m_ruler);

    connect(start, &QToolButton::clicked, this, &TimelinePanel::jumpToStart);
    connect(end, &QToolButton::clicked, this, &TimelinePanel::jumpToEnd);
    connect(previousKey, &QToolButton::clicked, this, [this] { jumpToKey(-1); });
    connect(nextKey, &QToolButton::clicked, this, [this] { jumpToKey(1); });
    connect(m_play, &QToolButton::clicked, m_playback, &Playback::toggle);
    connect(m_loop, &QToolButton::toggled, m_playback, &Playback::setLooping);
    connect(m_playback, &Playback::loopingChanged, m_loop, &QToolButton::setChecked);
    connect(m_playback, &Playback::playingChanged, this, [this](bool playing) {
        const QSignalBlocker block(m_play);
        m_play->setChecked(playing);
        m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        m_achieved->setText(playing ? tr("Playing…") : QString());
    });
    connect(m_playback, &Playback::achievedFpsChanged, this, [this](double fps) {
        if (m_playback->isPlaying())
            m_achieved->setText(tr("Playing: %1 fps").arg(fps, 0, 'f', 1));
    });
    connect(m_current, qOverload<int>(&QSpinBox::valueChanged), this, [this](int frame) {
        if (!m_refreshing)
            m_document->setCurrentFrame(frame);
    });
    for (QSpinBox* box : {m_first, m_last})
        connect(box, qOverload<int>(&QSpinBox::valueChanged), this, [this] { applySceneTime(); });
    connect(m_fps, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] { applySceneTime(); });
    connect(m_document, &model::Document::changed, this, &TimelinePanel::documentChanged);
    refreshTime();
    refreshMarks();
}

QString TimelinePanel::fpsReadout() const
{
    return m_achieved->text();
}

void TimelinePanel::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    if (change.reset || change.has(Part::SceneTime) || change.has(Part::Playhead))
        refreshTime();
    if (change.reset || change.has(Part::CameraPath) || change.has(Part::Highlights) || change.has(Part::Look)
        || (change.has(Part::Keys) && !change.offsetsOnly))
        refreshMarks();
    if (change.reset)
        setEnabled(m_document->hasMesh());
}

void TimelinePanel::refreshTime()
{
    m_refreshing = true;
    const model::SceneTime& time = m_document->data().time;
    const QSignalBlocker b1(m_first), b2(m_last), b3(m_fps), b4(m_current);
    // Only what differs: this runs on every played frame, and a spin box's setRange asks the
    // window to lay out again (a new size hint), which repaints the whole dock.
    // Each end bounds the other, so the boxes never offer a range the document refuses.
    if (m_first->maximum() != time.lastFrame)
        m_first->setRange(-model::kMaxFrame, time.lastFrame);
    if (m_last->minimum() != time.firstFrame)
        m_last->setRange(time.firstFrame, model::kMaxFrame);
    if (m_first->value() != time.firstFrame)
        m_first->setValue(time.firstFrame);
    if (m_last->value() != time.lastFrame)
        m_last->setValue(time.lastFrame);
    if (m_fps->value() != time.fps)
        m_fps->setValue(time.fps);
    m_current->setValue(m_document->currentFrame());
    m_ruler->setRange(time.firstFrame, time.lastFrame);
    m_refreshing = false;
}

void TimelinePanel::refreshMarks()
{
    m_ruler->setMarks(timelineMarks(m_document->data()));
}

void TimelinePanel::applySceneTime()
{
    if (m_refreshing)
        return;
    model::SceneTime time = m_document->data().time;
    time.firstFrame = m_first->value();
    time.lastFrame = m_last->value();
    time.fps = m_fps->value();
    try {
        m_document->animation().setSceneTime(time);
    } catch (const model::EditRefused&) {
        refreshTime(); // back to what the document holds
    }
}

void TimelinePanel::setFrame(int frame)
{
    m_document->setCurrentFrame(frame);
}

void TimelinePanel::jumpToStart()
{
    setFrame(m_document->data().time.firstFrame);
}

void TimelinePanel::jumpToEnd()
{
    setFrame(m_document->data().time.lastFrame);
}

void TimelinePanel::stepFrame(int delta)
{
    const model::SceneTime& time = m_document->data().time;
    int frame = m_document->currentFrame() + delta;
    if (frame > time.lastFrame)
        frame = m_playback->isLooping() ? time.firstFrame : time.lastFrame;
    else if (frame < time.firstFrame)
        frame = m_playback->isLooping() ? time.lastFrame : time.firstFrame;
    setFrame(frame);
}

void TimelinePanel::jumpToKey(int direction)
{
    // Over the union of every kind's keyed frames, inside the range or not.
    const std::vector<int> frames = markFrames(m_ruler->marks());
    const int current = m_document->currentFrame();
    if (direction > 0) {
        const auto it = std::upper_bound(frames.begin(), frames.end(), current);
        if (it != frames.end())
            setFrame(*it);
    } else {
        const auto it = std::lower_bound(frames.begin(), frames.end(), current);
        if (it != frames.begin())
            setFrame(*std::prev(it));
    }
}

} // namespace celform::views
