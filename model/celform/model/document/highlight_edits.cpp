// Stylized highlight layers (Anjyo & Hiramitsu 2003, "Making highlight animation") and the face
// sets they are drawn on, edited by layer id; combinations name other layers, so renames and
// removals carry their references along in the same undo step.
#include "celform/model/document/highlight_edits.h"

#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace celform::model {
namespace {

ChangeSet highlightChange(ObjectId id, bool structure = false)
{
    ChangeSet c = ChangeSet::of(Part::Highlights, id);
    c.structure = structure;
    return c;
}

using Combinations = std::vector<std::pair<algo::HighlightBoolean, QString>>;

std::function<std::vector<HighlightTrack>&(ProjectData&)> tracksOf()
{
    return [](ProjectData& d) -> std::vector<HighlightTrack>& { return d.look.highlights; };
}

/// The undo text of a key edit, after what changed in it.
QString keyEditText(const algo::HighlightLayer& before, const algo::HighlightLayer& after)
{
    if (before.shape.epsilon != after.shape.epsilon && before.shape.operations == after.shape.operations)
        return Document::tr("Change Highlight Size");
    if (before.color != after.color)
        return Document::tr("Change Highlight Colour");
    if (before.offSpecularCut != after.offSpecularCut)
        return Document::tr("Change Off-Specular Cut");
    if (before.shape.operations != after.shape.operations)
        return Document::tr("Change Highlight Operation");
    return Document::tr("Key Highlight");
}

} // namespace

const HighlightTrack& HighlightEdits::highlightOrThrow(ObjectId id) const
{
    const HighlightTrack* t = data().highlight(id);
    if (!t)
        throw EditRefused(tr("The highlight layer no longer exists."));
    return *t;
}

void HighlightEdits::refuseInvalidTracks(const std::vector<HighlightTrack>& tracks) const
{
    const QString problem = highlightTracksProblem(tracks, data().faceSetNames());
    if (!problem.isEmpty())
        throw EditRefused(problem);
}

// --- layers -------------------------------------------------------------------------------------

std::vector<ObjectId> HighlightEdits::addHighlightLayers(std::vector<HighlightTrack> tracks, const QString& undoText)
{
    std::vector<HighlightTrack> all = data().look.highlights;
    all.insert(all.end(), tracks.begin(), tracks.end());
    refuseInvalidTracks(all);
    std::vector<ObjectId> ids;
    auto* cmd = new CompositeCommand(m_doc, undoText);
    ObjectId next = data().nextId;
    for (HighlightTrack& track : tracks) {
        track.id = next++;
        ids.push_back(track.id);
    }
    new NextIdCommand(m_doc, next, cmd);
    std::size_t index = data().look.highlights.size();
    for (HighlightTrack& track : tracks)
        new InsertRemoveCommand<HighlightTrack>(
            m_doc, {}, tracksOf(), std::move(track), index++, false, Part::Highlights, cmd);
    push(cmd);
    return ids;
}

ObjectId HighlightEdits::addHighlightLayer(const QString& name, int frame)
{
    HighlightTrack track;
    track.name = uniqueHighlightName(name);
    track.setKey(frame, algo::HighlightLayer{});
    return addHighlightLayers({std::move(track)}, tr("Add Highlight Layer")).front();
}

std::vector<ObjectId> HighlightEdits::addHighlightPreset(HighlightPreset preset, ObjectId baseId, int frame)
{
    const HighlightTrack* base = data().highlight(baseId);
    std::vector<HighlightTrack> layers = highlightPresetLayers(preset, base ? *base : HighlightTrack{}, frame);
    // Unique names, the combinations following the renamed operands.
    std::vector<QString> taken;
    for (const auto& t : data().look.highlights)
        taken.push_back(t.name);
    for (HighlightTrack& layer : layers) {
        QString name = layer.name;
        for (int n = 2; std::find(taken.begin(), taken.end(), name) != taken.end(); ++n)
            name = QStringLiteral("%1 %2").arg(layer.name).arg(n);
        taken.push_back(name);
        for (HighlightTrack& other : layers)
            for (auto& c : other.combineWith)
                if (c.second == layer.name)
                    c.second = name;
        layer.name = name;
    }
    return addHighlightLayers(std::move(layers),
        preset == HighlightPreset::Window ? tr("Add Window Highlight") : tr("Add Crescent Highlight"));
}

void HighlightEdits::addHighlightOperation(ObjectId id, algo::HighlightOperationType type)
{
    std::vector<algo::HighlightKey> keys = highlightOrThrow(id).keys;
    for (auto& k : keys)
        k.layer.shape.operations.push_back(neutralHighlightOperation(type));
    setHighlightKeys(id, std::move(keys), tr("Add Highlight Operation"));
}

void HighlightEdits::moveHighlightOperation(ObjectId id, int index, int delta)
{
    std::vector<algo::HighlightKey> keys = highlightOrThrow(id).keys;
    for (auto& k : keys) {
        auto& ops = k.layer.shape.operations;
        const int to = index + delta;
        if (index < 0 || to < 0 || index >= int(ops.size()) || to >= int(ops.size()))
            return;
        const algo::HighlightOperation moved = ops[std::size_t(index)];
        ops.erase(ops.begin() + index);
        ops.insert(ops.begin() + to, moved);
    }
    setHighlightKeys(id, std::move(keys), tr("Move Highlight Operation"));
}

void HighlightEdits::removeHighlightOperation(ObjectId id, int index)
{
    std::vector<algo::HighlightKey> keys = highlightOrThrow(id).keys;
    for (auto& k : keys) {
        auto& ops = k.layer.shape.operations;
        if (index < 0 || index >= int(ops.size()))
            return;
        ops.erase(ops.begin() + index);
    }
    setHighlightKeys(id, std::move(keys), tr("Remove Highlight Operation"));
}

void HighlightEdits::removeHighlightLayer(ObjectId id)
{
    const HighlightTrack* track = data().highlight(id);
    if (!track)
        return;
    auto* cmd = new CompositeCommand(m_doc, tr("Remove Highlight Layer “%1”").arg(track->name));
    // Other layers stop combining with it first, so undo restores them after the layer is back.
    for (const HighlightTrack& other : data().look.highlights) {
        Combinations kept;
        std::copy_if(other.combineWith.begin(), other.combineWith.end(), std::back_inserter(kept),
            [&](const auto& c) { return c.second != track->name; });
        if (kept.size() != other.combineWith.size())
            new PropertyCommand<Combinations>(m_doc, {}, {Property::HighlightCombinations, other.id},
                fieldOf(other.id, &HighlightTrack::combineWith), std::move(kept), highlightChange(other.id), {}, cmd);
    }
    const auto index = std::size_t(track - data().look.highlights.data());
    new InsertRemoveCommand<HighlightTrack>(m_doc, {}, tracksOf(), *track, index, true, Part::Highlights, cmd);
    push(cmd);
}

void HighlightEdits::renameHighlightLayer(ObjectId id, const QString& name)
{
    const HighlightTrack& track = highlightOrThrow(id);
    const QString wanted = name.trimmed();
    if (wanted == track.name)
        return;
    if (wanted.isEmpty())
        throw EditRefused(tr("A highlight layer needs a name."));
    if (data().highlightByName(wanted))
        throw EditRefused(tr("There is already a highlight layer named “%1”.").arg(wanted));
    auto* cmd = new CompositeCommand(m_doc, tr("Rename Highlight Layer “%1”").arg(track.name));
    new PropertyCommand<QString>(m_doc, {}, {Property::HighlightName, id}, fieldOf(id, &HighlightTrack::name), wanted,
        highlightChange(id, true), {}, cmd);
    for (const HighlightTrack& other : data().look.highlights) {
        Combinations renamed = other.combineWith;
        bool touched = false;
        for (auto& c : renamed)
            if (c.second == track.name) {
                c.second = wanted;
                touched = true;
            }
        if (touched)
            new PropertyCommand<Combinations>(m_doc, {}, {Property::HighlightCombinations, other.id},
                fieldOf(other.id, &HighlightTrack::combineWith), std::move(renamed), highlightChange(other.id), {},
                cmd);
    }
    push(cmd);
}

void HighlightEdits::setHighlightKey(ObjectId id, double frame, const algo::HighlightLayer& layer, GestureId gesture)
{
    const HighlightTrack& track = highlightOrThrow(id);
    const QString problem = highlightLayerProblem(layer);
    if (!problem.isEmpty())
        throw EditRefused(tr("Highlight layer “%1”: %2").arg(track.name, problem));
    const algo::HighlightLayer before = track.layerAt(frame);
    HighlightTrack edited = track;
    edited.setKey(frame, layer);
    if (edited.keys == track.keys)
        return;
    setHighlightKeys(id, std::move(edited.keys), keyEditText(before, layer), gesture);
}

void HighlightEdits::setHighlightKeys(
    ObjectId id, std::vector<algo::HighlightKey> keys, const QString& undoText, GestureId gesture)
{
    const HighlightTrack& track = highlightOrThrow(id);
    std::vector<HighlightTrack> tracks = data().look.highlights;
    const auto index = std::size_t(&track - data().look.highlights.data());
    tracks[index].keys = keys;
    if (tracks[index] == track)
        return;
    refuseInvalidTracks(tracks);
    // One property for all keys: a viewport drag that first adds an operation to every key and
    // then keeps changing one key stays one undo step.
    ChangeSet change = highlightChange(id);
    for (const auto& k : keys)
        change.frames.push_back(int(std::floor(k.frame)));
    std::sort(change.frames.begin(), change.frames.end());
    change.frames.erase(std::unique(change.frames.begin(), change.frames.end()), change.frames.end());
    push(new PropertyCommand<std::vector<algo::HighlightKey>>(m_doc, undoText, {Property::HighlightKeys, id},
        fieldOf(id, &HighlightTrack::keys), std::move(keys), std::move(change), gesture));
}

void HighlightEdits::removeHighlightKey(ObjectId id, double frame)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.keys.size() < 2)
        return;
    std::vector<algo::HighlightKey> keys;
    std::copy_if(track.keys.begin(), track.keys.end(), std::back_inserter(keys),
        [frame](const algo::HighlightKey& k) { return k.frame != frame; });
    if (keys.size() == track.keys.size())
        return;
    setHighlightKeys(id, std::move(keys), tr("Delete Highlight Key"));
}

// --- direct manipulation in the viewport ----------------------------------------------------------

HighlightDrag HighlightEdits::beginHighlightDrag(ObjectId id, double frame)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (!std::isfinite(frame))
        throw EditRefused(tr("A highlight is keyed at a finite frame."));
    HighlightDrag drag;
    drag.layer = id;
    drag.frame = frame;
    drag.startTranslation = track.translationAt(frame);
    drag.gesture = m_doc->beginGesture();
    return drag;
}

void HighlightEdits::applyHighlightDrag(HighlightDrag& drag, const HighlightDragStep& step)
{
    using T = algo::HighlightOperationType;
    const HighlightTrack* found = data().highlight(drag.layer);
    if (!drag.active() || !found || !std::isfinite(step.a) || !std::isfinite(step.b))
        return; // ended, or the layer went (an undo during the drag)
    const HighlightTrack& track = *found;
    const T type = step.motion == HighlightMotion::Rotate ? T::Rotation
        : step.motion == HighlightMotion::Scale           ? T::DirectionalScaling
                                                          : T::Translation;
    double a = step.a, b = step.b;
    if (step.motion == HighlightMotion::Move) {
        // The translation the step wants, less the one the layer has now.
        const Eigen::Vector2d now = track.translationAt(drag.frame);
        a = drag.startTranslation.x() + step.a - now.x();
        b = drag.startTranslation.y() + step.b - now.y();
    }
    auto firstOf = [type](const std::vector<algo::HighlightOperation>& ops) {
        return std::size_t(
            std::find_if(ops.begin(), ops.end(), [type](const auto& op) { return op.type == type; }) - ops.begin());
    };
    drag.keys = track.keys;
    for (auto& k : drag.keys) {
        auto& ops = k.layer.shape.operations;
        if (firstOf(ops) == ops.size())
            ops.insert(type == T::DirectionalScaling ? ops.end() : ops.begin(), neutralHighlightOperation(type));
    }
    HighlightTrack edited;
    edited.keys = std::move(drag.keys);
    algo::HighlightLayer atFrame = edited.layerAt(drag.frame);
    auto& ops = atFrame.shape.operations;
    const std::size_t index = firstOf(ops);
    if (index == ops.size())
        return; // cannot happen: every key has one now
    algo::HighlightOperation& op = ops[index];
    if (type == T::Rotation) {
        op.a = float(std::clamp(op.a + a, -360.0, 360.0));
    } else if (type == T::DirectionalScaling) {
        op.a = float(std::clamp(op.a + a, 0.0, 1.0));
    } else {
        // Paper 2, "translation": H + alpha du + beta dv in the frame the earlier rotations left.
        double degrees = 0.0;
        for (std::size_t i = 0; i < index; ++i)
            if (ops[i].type == T::Rotation)
                degrees += ops[i].a;
        const double radians = degrees * 3.14159265358979323846 / 180.0;
        const double c = std::cos(radians), s = std::sin(radians);
        op.a += float(c * a + s * b);
        op.b += float(-s * a + c * b);
    }
    if (!std::isfinite(op.a) || !std::isfinite(op.b))
        return;
    edited.setKey(drag.frame, atFrame);
    drag.keys = std::move(edited.keys);
    setHighlightKeys(drag.layer, drag.keys,
        type == T::Rotation                 ? tr("Rotate Highlight")
            : type == T::DirectionalScaling ? tr("Scale Highlight")
                                            : tr("Move Highlight"),
        drag.gesture);
}

void HighlightEdits::endHighlightDrag(HighlightDrag& drag)
{
    drag.gesture.end();
}

void HighlightEdits::setHighlightPatch(ObjectId id, const QString& patch, GestureId gesture)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.patch == patch)
        return;
    if (!patch.isEmpty() && !data().faceSet(patch))
        throw EditRefused(tr("There is no patch named “%1”.").arg(patch));
    push(new PropertyCommand<QString>(m_doc, tr("Change Highlight Patch"), {Property::HighlightPatch, id},
        fieldOf(id, &HighlightTrack::patch), patch, highlightChange(id), gesture));
}

void HighlightEdits::setHighlightGuide(ObjectId id, const Eigen::Vector3f& guide, GestureId gesture)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.guide == guide)
        return;
    if (!guide.allFinite() || guide.norm() == 0.f)
        throw EditRefused(tr("A highlight's guide needs a direction (not zero)."));
    push(new PropertyCommand<Eigen::Vector3f>(m_doc, tr("Change Highlight Guide"), {Property::HighlightGuide, id},
        fieldOf(id, &HighlightTrack::guide), guide, highlightChange(id), gesture));
}

void HighlightEdits::setHighlightSmoothing(ObjectId id, int rounds, GestureId gesture)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.smoothing == rounds)
        return;
    if (rounds < 0 || rounds > kMaxHighlightSmoothing)
        throw EditRefused(tr("Normal smoothing takes 0 to %1 rounds.").arg(kMaxHighlightSmoothing));
    push(new PropertyCommand<int>(m_doc, tr("Change Highlight Smoothing"), {Property::HighlightSmoothing, id},
        fieldOf(id, &HighlightTrack::smoothing), rounds, highlightChange(id), gesture));
}

void HighlightEdits::setHighlightVisible(ObjectId id, bool visible)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.visible == visible)
        return;
    push(new PropertyCommand<bool>(m_doc, visible ? tr("Show Highlight Layer") : tr("Hide Highlight Layer"),
        {Property::HighlightVisible, id}, fieldOf(id, &HighlightTrack::visible), visible, highlightChange(id, true),
        {}));
}

void HighlightEdits::setHighlightCombinations(ObjectId id, Combinations combinations, GestureId gesture)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.combineWith == combinations)
        return;
    std::vector<HighlightTrack> tracks = data().look.highlights;
    tracks[std::size_t(&track - data().look.highlights.data())].combineWith = combinations;
    refuseInvalidTracks(tracks);
    push(new PropertyCommand<Combinations>(m_doc, tr("Change Highlight Combinations"),
        {Property::HighlightCombinations, id}, fieldOf(id, &HighlightTrack::combineWith), std::move(combinations),
        highlightChange(id), gesture));
}

QString HighlightEdits::uniqueHighlightName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return data().highlightByName(n) != nullptr; });
}

} // namespace celform::model
