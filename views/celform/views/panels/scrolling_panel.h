// The body of the dock panels that grow taller than a dock: a frameless scroll area filling the
// panel, scrolling vertically only (the panel follows the dock's width).
#pragma once

#include <QFrame>
#include <QScrollArea>
#include <QVBoxLayout>
#include <QWidget>

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

} // namespace celform::views
