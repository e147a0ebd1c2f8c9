// The reference drawings' edits: each one undo step, by drawing id.
#include "celform/model/document/drawing_edits.h"

#include "celform/model/data/io_error.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/io/image_io.h"

#include <algorithm>
#include <cmath>

namespace celform::model {

ObjectId DrawingEdits::addDrawing(Drawing drawing)
{
    drawing.id = data().nextId;
    drawing.name = uniqueDrawingName(drawing.name);
    const ObjectId id = drawing.id;
    auto* cmd = new CompositeCommand(m_doc, tr("Add Drawing “%1”").arg(drawing.name));
    new NextIdCommand(m_doc, id + 1, cmd);
    new InsertRemoveCommand<Drawing>(
        m_doc, {}, [](ProjectData& d) -> std::vector<Drawing>& { return d.drawings; }, std::move(drawing),
        data().drawings.size(), false, Part::Drawings, cmd);
    push(cmd);
    return id;
}

ObjectId DrawingEdits::importDrawing(const QString& path)
{
    return addDrawing(model::importDrawing(path));
}

void DrawingEdits::removeDrawing(ObjectId id)
{
    const Drawing* drawing = data().drawing(id);
    if (!drawing)
        return;
    auto* cmd = new CompositeCommand(m_doc, tr("Remove Drawing “%1”").arg(drawing->name));
    // Unlink the drawing from keys first, so undo relinks them after the drawing is back.
    for (const auto& key : data().keys) {
        std::vector<ObjectId> ids = key.drawingIds;
        const auto newEnd = std::remove(ids.begin(), ids.end(), id);
        if (newEnd == ids.end())
            continue;
        ids.erase(newEnd, ids.end());
        new PropertyCommand<std::vector<ObjectId>>(m_doc, {}, {Property::KeyDrawings, key.id},
            fieldOf(key.id, &KeyViewpoint::drawingIds), std::move(ids), structuralChange(Part::Keys, key.id), {}, cmd);
    }
    const auto index = std::size_t(drawing - data().drawings.data());
    new InsertRemoveCommand<Drawing>(
        m_doc, {}, [](ProjectData& d) -> std::vector<Drawing>& { return d.drawings; }, *drawing, index, true,
        Part::Drawings, cmd);
    push(cmd);
}

void DrawingEdits::renameDrawing(ObjectId id, const QString& name)
{
    const Drawing* drawing = data().drawing(id);
    if (!drawing || drawing->name == name.trimmed() || name.trimmed().isEmpty())
        return;
    const QString unique = uniqueDrawingName(name);
    push(new PropertyCommand<QString>(m_doc, tr("Rename Drawing to “%1”").arg(unique), {Property::DrawingName, id},
        fieldOf(id, &Drawing::name), unique, structuralChange(Part::Drawings, id), {}));
}

void DrawingEdits::setDrawingOpacity(ObjectId id, double opacity, GestureId gesture)
{
    const Drawing* drawing = data().drawing(id);
    opacity = std::clamp(opacity, 0.0, 1.0);
    if (!drawing || drawing->opacity == opacity || !std::isfinite(opacity))
        return;
    push(new PropertyCommand<double>(m_doc, tr("Set Drawing Opacity"), {Property::DrawingOpacity, id},
        fieldOf(id, &Drawing::opacity), opacity, ChangeSet::of(Part::Drawings, id), gesture));
}

void DrawingEdits::setDrawingCamera(ObjectId id, const Camera& camera, GestureId gesture)
{
    const Drawing* drawing = data().drawing(id);
    if (!drawing || !camera.isValid() || (drawing->aligned && drawing->camera == camera))
        return;
    push(newDrawingCameraCommand(m_doc, tr("Align Drawing “%1”").arg(drawing->name), id, camera, gesture));
}

void DrawingEdits::setDrawingOutline(ObjectId id, const DrawingOutline& outline, GestureId gesture)
{
    const Drawing* drawing = data().drawing(id);
    if (!drawing || drawing->outline == outline)
        return;
    if (const QString problem = outline.problem(); !problem.isEmpty())
        throw EditRefused(problem);
    push(new PropertyCommand<DrawingOutline>(m_doc, tr("Set Outline of “%1”").arg(drawing->name),
        {Property::DrawingOutline, id}, fieldOf(id, &Drawing::outline), outline, ChangeSet::of(Part::Drawings, id),
        gesture));
}

QUndoCommand* newDrawingCameraCommand(
    Document* doc, const QString& text, ObjectId id, const Camera& camera, GestureId gesture, QUndoCommand* parent)
{
    // The camera and the "aligned" flag are one value: a navigation gesture is one step, and its
    // undo gives back an unaligned drawing where there was one.
    using Aligned = std::pair<Camera, bool>;
    return new PropertyCommand<Aligned>(
        doc, text, {Property::DrawingCamera, id},
        [id](const ProjectData& d) -> std::optional<Aligned> {
            const Drawing* x = d.drawing(id);
            return x ? std::optional<Aligned>(Aligned{x->camera, x->aligned}) : std::nullopt;
        },
        [id](ProjectData& d, const Aligned& value) {
            if (Drawing* x = d.drawing(id)) {
                x->camera = value.first;
                x->aligned = value.second;
            }
        },
        Aligned{camera, true}, ChangeSet::of(Part::Drawings, id), gesture, parent);
}

QString DrawingEdits::uniqueDrawingName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return data().drawingByName(n) != nullptr; });
}

} // namespace celform::model
