// FaceValuesCommand: a per-face layer changed sparsely.
#include "celform/model/document/face_values_command.h"

#include "celform/model/document/sparse_change.h"

#include "celform/algorithms/tri_mesh.h"

namespace celform::model {
namespace {

template <typename T>
void applyTo(std::vector<T>& layer, T fill, std::size_t faces, bool exists, const std::vector<std::int32_t>& which,
    const std::vector<float>& values)
{
    if (!exists) {
        layer.clear();
        return;
    }
    if (layer.size() != faces)
        layer.assign(faces, fill);
    for (std::size_t k = 0; k < which.size(); ++k)
        if (which[k] >= 0 && std::size_t(which[k]) < layer.size())
            layer[std::size_t(which[k])] = T(values[k]);
}

} // namespace

FaceValuesCommand::FaceValuesCommand(
    Document* doc, const QString& text, FaceLayer layer, Change change, GestureId gesture)
    : DocumentCommand(doc, text)
    , m_layer(layer)
    , m_change(std::move(change))
    , m_gesture(gesture)
{ }

void FaceValuesCommand::apply(bool forward)
{
    ProjectData& data = mutableData();
    const std::size_t faces = data.baseMesh ? std::size_t(data.baseMesh->faceCount()) : 0;
    const bool exists = forward ? m_change.existsAfter : m_change.existedBefore;
    const std::vector<float>& values = forward ? m_change.after : m_change.before;
    if (m_layer == FaceLayer::Importance)
        applyTo(data.faceImportance, 1.f, faces, exists, m_change.indices, values);
    else
        applyTo(data.segmentOverrides, kNoSegmentOverride, faces, exists, m_change.indices, values);
    noteChange(ChangeSet::of(Part::FaceValues));
}

bool FaceValuesCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const FaceValuesCommand*>(other);
    if (!o || o->m_gesture != m_gesture || o->m_layer != m_layer)
        return false;
    m_change = mergedSparseChange(m_change, o->m_change);
    return true;
}

} // namespace celform::model
