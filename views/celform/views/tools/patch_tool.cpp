// Dabs of the patch brush go to Document::paintFaceSet inside one gesture.
#include "celform/views/tools/patch_tool.h"

#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/views/viewport.h"

#include <QCoreApplication>

namespace celform::views {
namespace {

struct Patch {
    Q_DECLARE_TR_FUNCTIONS(celform::views::PatchTool)
};

} // namespace

void PatchTool::activate()
{
    emit m_viewport->message(
        Patch::tr("Paint the patch “%1”: drag adds faces, Ctrl+drag removes them, [ and ] change the radius.")
            .arg(m_viewport->patchTarget()));
}

bool PatchTool::press(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !document->hasMesh())
        return false;
    m_gesture = document->beginGesture();
    paint(event);
    return true;
}

void PatchTool::move(const ToolEvent& event)
{
    paint(event);
}

void PatchTool::paint(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || m_gesture == 0)
        return;
    const QString target = m_viewport->patchTarget();
    if (target.trimmed().isEmpty()) {
        emit m_viewport->message(Patch::tr("Choose or create a patch in the Highlights dock first."));
        return;
    }
    const std::vector<std::int32_t> dab = m_viewport->facesUnderBrush(event.position);
    if (dab.empty())
        return;
    try {
        document->paintFaceSet(target, dab, event.modifiers & Qt::ControlModifier);
    } catch (const model::EditRefused& e) {
        emit m_viewport->message(e.message());
    }
}

void PatchTool::finish()
{
    model::Document* document = m_viewport->document();
    if (document && m_gesture != 0 && document->currentGesture() == m_gesture)
        document->endGesture();
    m_gesture = 0;
}

void PatchTool::release(const ToolEvent&)
{
    finish();
}

void PatchTool::cancel()
{
    finish();
}

} // namespace celform::views
