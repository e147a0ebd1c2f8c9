// The gesture bookkeeping every drag tool shares.
#include "celform/views/tools/viewport_tool.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"

namespace celform::views {

bool ViewportTool::openGesture()
{
    model::Document* document = m_viewport->document();
    if (!document)
        return false;
    m_gesture = document->beginGesture();
    return true;
}

void ViewportTool::closeGesture()
{
    m_gesture.end();
}

} // namespace celform::views
