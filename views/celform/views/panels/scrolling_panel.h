// The body of the dock panels that grow taller than a dock: a frameless scroll area filling the
// panel, scrolling vertically only (the panel follows the dock's width).
#pragma once

#include <QComboBox>
#include <QFormLayout>
#include <QFrame>
#include <QScrollArea>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>

namespace celform::views {

/// Fills panel with a vertical scroll area and returns the layout of its content widget (whose
/// parent widget is the one to parent the panel's group boxes to).
inline QVBoxLayout* scrollingPanelLayout(QWidget* panel)
{
    auto* outer = new QVBoxLayout(panel);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* content = new QWidget(scroll);
    auto* layout = new QVBoxLayout(content);
    scroll->setWidget(content);
    outer->addWidget(scroll);
    return layout;
}

/// Lets the panel's rows narrow to a 1366x768 screen's dock (about 300 px) instead of being cut
/// at its right edge (the scroll area never scrolls sideways): a form's field goes below its label
/// when the two do not fit side by side, and combo boxes stop asking for their longest item's
/// width. Call once the panel's rows are made.
inline void letRowsNarrow(QWidget* panel)
{
    for (QFormLayout* form : panel->findChildren<QFormLayout*>())
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    for (QComboBox* combo : panel->findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(std::max(combo->minimumContentsLength(), 12));
    }
}

} // namespace celform::views
