// The window-modal progress dialog every long job of the editor shows (JobRunner, jobs/): a
// Cancel button, a range of steps, kept open until the runner closes it.
#pragma once

#include <QString>

class QProgressDialog;
class QWidget;

namespace celform::app {

/// A window-modal progress dialog on parent, titled title, with label and steps 0..maximum, at
/// 0. It shows itself after minimumDurationMs (0: at once), never closes or resets by itself, and
/// its Cancel button emits canceled(). The caller owns it (delete or deleteLater when done).
[[nodiscard]] QProgressDialog* makeProgressDialog(QWidget* parent, const QString& objectName, const QString& title,
    const QString& label, int maximum, int minimumDurationMs = 0);

} // namespace celform::app
