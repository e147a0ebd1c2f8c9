// File > Export…: the format, the frame range (the project's by default), for USD the keys as
// blend shapes, and the file; the export itself runs as a job of the JobRunner (jobs/export_job.h).
#pragma once

#include "celform/model/export/export.h"

#include <QDialog>
#include <QObject>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace celform::model {
class Document;
}

namespace celform::app {

class MainWindow;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    ExportDialog(const model::Document* document, QWidget* parent = nullptr);

    /// The job the fields describe (valid once accepted).
    [[nodiscard]] model::ExportJob job() const;

    [[nodiscard]] QComboBox* formatBox() const { return m_format; }
    [[nodiscard]] QSpinBox* firstFrameBox() const { return m_first; }
    [[nodiscard]] QSpinBox* lastFrameBox() const { return m_last; }
    [[nodiscard]] QLineEdit* fileEdit() const { return m_file; }
    /// USD only (enabled for it): the keys as blend shapes (celform export --blend-shapes).
    [[nodiscard]] QCheckBox* blendShapesBox() const { return m_blendShapes; }

    void accept() override;

private:
    void browse();
    void formatChanged();

    QComboBox* m_format;
    QSpinBox* m_first;
    QSpinBox* m_last;
    QLineEdit* m_file;
    QCheckBox* m_blendShapes;
};

/// Adds File > Export… (Ctrl+Shift+E) before the window's Quit, enabled with a base model.
void installExportAction(MainWindow* window);

} // namespace celform::app
