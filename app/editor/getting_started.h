// Help > Getting Started: the illustrated guide of docs/getting-started.md, built into the
// program, in a window of its own.
#pragma once

class QDialog;
class QWidget;

namespace celform::app {

/// Opens (or raises) the guide; the dialog deletes itself when closed.
QDialog* showGettingStarted(QWidget* parent);

} // namespace celform::app
