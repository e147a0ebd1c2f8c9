// Stereo review: keys are read by an event filter in front of the viewport, because the viewport
// keeps [ and ] (brush size) and F / Home for itself; the review's choices never touch the document.
#include "editor/review_window.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_display.h"

#include <QApplication>
#include <QKeyEvent>
#include <QLabel>
#include <QScreen>
#include <QVBoxLayout>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace celform::app {

namespace {

constexpr double kTurntableDegreesPerSecond = 20.0;
constexpr int kTurntableIntervalMs = 16;
constexpr double kPi = 3.14159265358979323846;

const char* const kOverlayStyle = "QLabel { background: rgba(20, 20, 24, 150); color: #f2f2f2; "
                                  "border-radius: 6px; padding: 6px 10px; }";

} // namespace

ReviewWindow::ReviewWindow(model::Document* document, const model::Camera& camera, QWidget* parent)
    : QWidget(parent, Qt::Window)
    , m_document(document)
{
    setWindowTitle(tr("Stereo Review"));
    setAttribute(Qt::WA_DeleteOnClose, false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_viewport = new views::Viewport(document, this);
    layout->addWidget(m_viewport);
    m_viewport->setCamera(camera);
    const algo::StereoOutput lookOutput = document ? document->data().look.stereo.output : algo::StereoOutput::Anaglyph;
    m_viewport->display().setStereo(lookOutput == algo::StereoOutput::Off ? algo::StereoOutput::Anaglyph : lookOutput);
    m_viewport->installEventFilter(this);
    setFocusProxy(m_viewport);

    m_status = new QLabel(m_viewport);
    m_status->setStyleSheet(QString::fromLatin1(kOverlayStyle));
    m_status->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_help = new QLabel(m_viewport);
    m_help->setStyleSheet(QString::fromLatin1(kOverlayStyle));
    m_help->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_help->setTextFormat(Qt::RichText);
    QString help = tr("<b>Stereo review</b>") + QStringLiteral("<table cellspacing='4'>");
    for (const KeyBinding& binding : keyBindings())
        help += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(QKeySequence(binding.key).toString(QKeySequence::NativeText).toHtmlEscaped(),
                        binding.description().toHtmlEscaped());
    m_help->setText(help + QStringLiteral("</table>"));
    m_help->adjustSize();
    m_help->hide();

    m_turntable.setInterval(kTurntableIntervalMs);
    connect(&m_turntable, &QTimer::timeout, this, &ReviewWindow::turntableStep);
    m_statusTimer.setInterval(500);
    connect(&m_statusTimer, &QTimer::timeout, this, &ReviewWindow::refreshStatus);
    m_statusTimer.start();
    m_fpsClock.start();
    m_fpsFrames = m_viewport->renderCount();
    refreshStatus();
}

ReviewWindow::~ReviewWindow() = default;

void ReviewWindow::showAs(const views::Viewport& editor)
{
    // What the editor shows: the view-dependent preview, or the key it displays, or the base.
    if (editor.isPreview())
        m_viewport->setPreview(true);
    else
        m_viewport->setDisplayedKey(editor.displayedKey());
    m_viewport->display().setShadingEnabled(true);
    refreshStatus();
}

void ReviewWindow::showReview()
{
    if (QScreen* screen = parentWidget() ? parentWidget()->screen() : QGuiApplication::primaryScreen())
        setGeometry(screen->geometry());
    showFullScreen();
    raise();
    activateWindow();
    m_viewport->setFocus(Qt::OtherFocusReason);
}

algo::StereoOutput ReviewWindow::nextOutput(algo::StereoOutput output)
{
    switch (output) {
    case algo::StereoOutput::Anaglyph:
        return algo::StereoOutput::Dubois;
    case algo::StereoOutput::Dubois:
        return algo::StereoOutput::HalfColor;
    case algo::StereoOutput::HalfColor:
        return algo::StereoOutput::SideBySide;
    case algo::StereoOutput::SideBySide:
        return algo::StereoOutput::TopBottom;
    case algo::StereoOutput::TopBottom:
        return algo::StereoOutput::Off;
    case algo::StereoOutput::Off:
        break;
    }
    return algo::StereoOutput::Anaglyph;
}

QString ReviewWindow::outputName(algo::StereoOutput output)
{
    switch (output) {
    case algo::StereoOutput::Anaglyph:
        return tr("Anaglyph");
    case algo::StereoOutput::Dubois:
        return tr("Dubois anaglyph");
    case algo::StereoOutput::HalfColor:
        return tr("Half-colour anaglyph");
    case algo::StereoOutput::SideBySide:
        return tr("Side by side");
    case algo::StereoOutput::TopBottom:
        return tr("Top-bottom");
    case algo::StereoOutput::Off:
        break;
    }
    return tr("Mono");
}

QString ReviewWindow::KeyBinding::description() const
{
    return QCoreApplication::translate("celform::app::ReviewWindow", text);
}

const std::vector<ReviewWindow::KeyBinding>& ReviewWindow::keyBindings()
{
    static const std::vector<KeyBinding> bindings = {
        {Command::Turntable, Qt::Key_Space, QT_TR_NOOP("turntable on / off")},
        {Command::PreviousKey, Qt::Key_Left, QT_TR_NOOP("previous key's camera")},
        {Command::NextKey, Qt::Key_Right, QT_TR_NOOP("next key's camera")},
        {Command::NextStereo, Qt::Key_S,
            QT_TR_NOOP("stereo: anaglyph, Dubois, half-colour, side by side, top-bottom, off")},
        {Command::Lines, Qt::Key_L, QT_TR_NOOP("lines on / off")},
        {Command::Preview, Qt::Key_P, QT_TR_NOOP("view-dependent preview on / off")},
        {Command::NarrowerEyes, Qt::Key_BracketLeft, QT_TR_NOOP("interocular distance -10%")},
        {Command::WiderEyes, Qt::Key_BracketRight, QT_TR_NOOP("interocular distance +10%")},
        {Command::Help, Qt::Key_H, QT_TR_NOOP("this help")},
        {Command::Close, Qt::Key_Escape, QT_TR_NOOP("close the review")},
    };
    return bindings;
}

bool ReviewWindow::isHelpShown() const
{
    return m_help->isVisible();
}

bool ReviewWindow::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_viewport && (event->type() == QEvent::KeyPress || event->type() == QEvent::ShortcutOverride)) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
            return QWidget::eventFilter(watched, event);
        if (event->type() == QEvent::ShortcutOverride) {
            // Claim the review's keys before any application shortcut sees them.
            for (const KeyBinding& binding : keyBindings())
                if (key->key() == binding.key) {
                    event->accept();
                    return true;
                }
            return QWidget::eventFilter(watched, event);
        }
        if (handleKey(key->key()))
            return true;
    }
    return QWidget::eventFilter(watched, event);
}

void ReviewWindow::keyPressEvent(QKeyEvent* event)
{
    if (!(event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) && handleKey(event->key())) {
        event->accept();
        return;
    }
    QWidget::keyPressEvent(event);
}

bool ReviewWindow::handleKey(int key)
{
    const auto& bindings = keyBindings();
    const auto binding
        = std::find_if(bindings.begin(), bindings.end(), [key](const KeyBinding& b) { return b.key == key; });
    if (binding == bindings.end())
        return false;
    switch (binding->command) {
    case Command::Close:
        close();
        return true;
    case Command::Turntable:
        setTurntable(!m_turntable.isActive());
        break;
    case Command::PreviousKey:
        stepKey(-1);
        break;
    case Command::NextKey:
        stepKey(1);
        break;
    case Command::NextStereo:
        m_viewport->display().setStereo(nextOutput(m_viewport->display().stereo()));
        break;
    case Command::Lines:
        m_viewport->display().setLinesOverride(!m_viewport->display().linesShown());
        break;
    case Command::Preview:
        m_viewport->setPreview(!m_viewport->isPreview());
        m_previewChosen = true;
        break;
    case Command::NarrowerEyes:
        scaleInterocular(1.0 / 1.1);
        break;
    case Command::WiderEyes:
        scaleInterocular(1.1);
        break;
    case Command::Help:
        m_help->setVisible(!m_help->isVisible());
        placeOverlays();
        break;
    }
    refreshStatus();
    return true;
}

void ReviewWindow::setTurntable(bool on)
{
    if (on) {
        m_turntableClock.start();
        m_turntable.start();
    } else {
        m_turntable.stop();
    }
}

void ReviewWindow::turntableStep()
{
    // Angle from elapsed time, so a slow frame (software GL, stereo at full screen) keeps the
    // speed and only lowers the frame rate.
    const double seconds = double(m_turntableClock.restart()) / 1000.0;
    const double angle = kTurntableDegreesPerSecond * std::min(seconds, 0.25) * kPi / 180.0;
    model::Camera camera = m_viewport->camera();
    const Eigen::Vector3d pivot = m_viewport->pivot();
    const Eigen::AngleAxisd turn(angle, Eigen::Vector3d::UnitY());
    camera.eye = pivot + turn * (camera.eye - pivot);
    camera.target = pivot + turn * (camera.target - pivot);
    camera.up = turn * camera.up;
    m_viewport->setCamera(camera);
}

void ReviewWindow::stepKey(int delta)
{
    if (!m_document)
        return;
    const auto& keys = m_document->data().keys;
    if (keys.empty()) {
        m_keyIndex = -1;
        return;
    }
    const int count = int(keys.size());
    m_keyIndex = m_keyIndex < 0 ? (delta > 0 ? 0 : count - 1) : ((m_keyIndex + delta) % count + count) % count;
    setTurntable(false);
    m_viewport->setCamera(keys[std::size_t(m_keyIndex)].camera);
    // At a key's camera the view-dependent shape is the key itself: show it, unless P chose.
    if (!m_previewChosen)
        m_viewport->setPreview(true);
}

void ReviewWindow::scaleInterocular(double factor)
{
    // The review's own settings: the current (possibly automatic) distance made explicit.
    model::StereoLook look = m_viewport->display().stereoLook();
    look.interocular = m_viewport->display().resolvedStereoSettings().interocular * factor;
    m_viewport->display().setStereoLook(look);
}

QString ReviewWindow::statusText() const
{
    const auto& keys = m_document ? m_document->data().keys : std::vector<model::KeyViewpoint>{};
    const QString key
        = m_keyIndex >= 0 && m_keyIndex < int(keys.size()) ? keys[std::size_t(m_keyIndex)].name : tr("free camera");
    QStringList parts;
    parts << outputName(m_viewport->display().stereo());
    parts << tr("Key: %1").arg(key);
    parts << tr("Interocular %1").arg(m_viewport->display().resolvedStereoSettings().interocular, 0, 'g', 3);
    // Frames are drawn on change only: an idle review shows the last frame's time, not "0 fps".
    if (m_fps > 0.0)
        parts << tr("%1 fps").arg(m_fps, 0, 'f', 1);
    else
        parts << tr("Idle (last frame %1 ms)").arg(m_viewport->lastFrameTimes().frame, 0, 'f', 0);
    if (m_turntable.isActive())
        parts << tr("Turntable");
    if (!m_viewport->display().linesShown())
        parts << tr("No lines");
    if (m_viewport->isPreview())
        parts << tr("Preview");
    parts << tr("H: help");
    return parts.join(QStringLiteral("  ·  "));
}

void ReviewWindow::refreshStatus()
{
    const qint64 elapsed = m_fpsClock.elapsed();
    if (elapsed >= 400) {
        const int frames = m_viewport->renderCount();
        m_fps = 1000.0 * double(frames - m_fpsFrames) / double(elapsed);
        m_fpsFrames = frames;
        m_fpsClock.restart();
    }
    m_status->setText(statusText());
    m_status->adjustSize();
    placeOverlays();
}

void ReviewWindow::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    placeOverlays();
}

void ReviewWindow::placeOverlays()
{
    const int margin = 12;
    m_status->move(margin, m_viewport->height() - m_status->height() - margin);
    m_status->raise();
    m_help->move(margin, margin);
    m_help->raise();
}

} // namespace celform::app
