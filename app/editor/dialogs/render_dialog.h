// File > Render Image and Render Sequence: the options of `celform render` (output, size, camera,
// frame or frame range, pass, stereo, style and lines for this render) as a dialog that describes
// a model::RenderJob. Problems show below the options and keep Render disabled; the options are
// remembered in QSettings. startRender (jobs/render_job.h) renders what the dialog describes.
#pragma once

#include "celform/model/render/render_job.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace celform::model {
class Document;
}
namespace celform::views {
class Viewport;
}

namespace celform::app {

class RenderDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { Image, Sequence };
    /// viewport gives the "current view" camera and its size; either may be null.
    RenderDialog(Kind kind, model::Document* document, views::Viewport* viewport, QWidget* parent = nullptr);

    [[nodiscard]] Kind kind() const { return m_kind; }
    /// The render the options describe now.
    [[nodiscard]] model::RenderJob job() const;
    [[nodiscard]] bool openWhenDone() const;
    /// Why the render cannot run as set (the first problem), empty when it can.
    [[nodiscard]] QString problem() const;

public slots:
    /// Asks before replacing existing files, remembers the options and closes with Accepted.
    void accept() override;

private:
    void buildForm();
    void fillCameras();
    void restoreOptions();
    void saveOptions() const;
    void updateState();
    void browse();
    [[nodiscard]] QString defaultOutput(const QString& folder, const QString& suffix) const;

    Kind m_kind;
    model::Document* m_document;
    views::Viewport* m_viewport;

    QLineEdit* m_output = nullptr;
    QComboBox* m_camera = nullptr;
    QSpinBox* m_frame = nullptr;
    QSpinBox* m_firstFrame = nullptr;
    QSpinBox* m_lastFrame = nullptr;
    QComboBox* m_sizePreset = nullptr;
    QSpinBox* m_width = nullptr;
    QSpinBox* m_height = nullptr;
    QComboBox* m_pass = nullptr;
    QComboBox* m_stereo = nullptr;
    QComboBox* m_style = nullptr;
    QComboBox* m_lines = nullptr;
    QCheckBox* m_svgTones = nullptr; ///< an .svg output's tone regions (`--svg-tones`)
    QCheckBox* m_open = nullptr;
    QLabel* m_files = nullptr;
    QLabel* m_problem = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

} // namespace celform::app
