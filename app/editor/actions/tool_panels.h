// The docks' controls for the viewport's tools: the Properties dock's brush and point-matching
// controls, the Highlights dock's patch and highlight targets, the Depth dock's offset target.
// Panels do not know tools (they edit the document); this connects each control to the tool that
// owns the setting, and what the tools report back to the controls.
#pragma once

namespace celform::views {
class DepthPanel;
class HighlightPanel;
class PropertiesPanel;
class Viewport;
} // namespace celform::views

namespace celform::app {

/// Call before the panels' setViewport(), so their first targets reach the tools.
void connectToolPanels(views::Viewport& viewport, views::PropertiesPanel& properties, views::HighlightPanel& highlights,
    views::DepthPanel& depth);

} // namespace celform::app
