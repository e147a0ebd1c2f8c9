// Stereo review for supervisors: a full-screen viewport on the open document showing the look in
// stereo, with a turntable, the keys' cameras one key press away, and a small status overlay.
#pragma once

#include "celform/algorithms/stereo.h"
#include "celform/model/data/camera.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <vector>

class QLabel;

namespace celform::model {
class Document;
}
namespace celform::views {
class Viewport;
}

namespace celform::app {

class ReviewWindow : public QWidget {
    Q_OBJECT
public:
    /// A review of document starting from camera. Show it with showReview().
    ReviewWindow(model::Document* document, const model::Camera& camera, QWidget* parent = nullptr);
    ~ReviewWindow() override;
    /// Shows what an editor viewport shows: its preview state or its displayed key.
    void showAs(const views::Viewport& editor);

    /// Full screen on the screen of the parent (or the primary one), focused.
    void showReview();

    [[nodiscard]] views::Viewport* viewport() const { return m_viewport; }
    [[nodiscard]] bool isTurntable() const { return m_turntable.isActive(); }
    /// Index into the document's keys of the key whose camera is shown, or -1.
    [[nodiscard]] int keyIndex() const { return m_keyIndex; }
    [[nodiscard]] QString statusText() const;
    [[nodiscard]] bool isHelpShown() const;

    /// What the review's keys do. One table (keyBindings()) drives the keys, the help overlay and
    /// Help > Keyboard Shortcuts.
    enum class Command {
        Close,
        Turntable,
        PreviousKey,
        NextKey,
        NextStereo,
        Lines,
        Preview,
        NarrowerEyes,
        WiderEyes,
        Help
    };
    struct KeyBinding {
        Command command;
        Qt::Key key; ///< pressed without Ctrl, Alt or Meta
        const char* text; ///< untranslated (context celform::app::ReviewWindow): see description()
        [[nodiscard]] QString description() const;
    };
    [[nodiscard]] static const std::vector<KeyBinding>& keyBindings();

    /// The order S steps through.
    static algo::StereoOutput nextOutput(algo::StereoOutput output);
    static QString outputName(algo::StereoOutput output);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    /// Handles a review key; false for keys the viewport may have.
    bool handleKey(int key);
    void setTurntable(bool on);
    void turntableStep();
    void stepKey(int delta);
    void scaleInterocular(double factor);
    void refreshStatus();
    void placeOverlays();

    model::Document* m_document;
    views::Viewport* m_viewport = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_help = nullptr;
    QTimer m_turntable;
    QElapsedTimer m_turntableClock;
    QTimer m_statusTimer;
    QElapsedTimer m_fpsClock;
    int m_fpsFrames = 0;
    double m_fps = 0.0;
    int m_keyIndex = -1;
    bool m_previewChosen = false; ///< P was pressed: the arrows keep the preview as it is
};

} // namespace celform::app
