// Stylized highlight layers (Anjyo & Hiramitsu 2003, "Making highlight animation") and the face
// sets they are drawn on, edited by layer id; combinations name other layers, so renames and
// removals carry their references along in the same undo step.
#include "celform/model/document/document.h"

#include "celform/model/document/document_commands.h"
#include "celform/model/data/io_error.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace celform::model {
namespace {

QString idTarget(ObjectId id)
{
    return QString::number(id);
}

/// Locates a highlight layer's member by id.
template <typename T> std::function<T*(ProjectData&)> trackField(ObjectId id, T HighlightTrack::*member)
{
    return [id, member](ProjectData& d) -> T* {
        HighlightTrack* t = d.highlight(id);
        return t ? &(t->*member) : nullptr;
    };
}

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

const HighlightTrack& Document::highlightOrThrow(ObjectId id) const
{
    const HighlightTrack* t = m_data.highlight(id);
    if (!t)
        throw EditRefused(tr("The highlight layer no longer exists."));
    return *t;
}

void Document::refuseInvalidTracks(const std::vector<HighlightTrack>& tracks) const
{
    const QString problem = highlightTracksProblem(tracks, m_data.faceSetNames());
    if (!problem.isEmpty())
        throw EditRefused(problem);
}

// --- layers -------------------------------------------------------------------------------------

std::vector<ObjectId> Document::addHighlightLayers(std::vector<HighlightTrack> tracks, const QString& undoText)
{
    std::vector<HighlightTrack> all = m_data.look.highlights;
    all.insert(all.end(), tracks.begin(), tracks.end());
    refuseInvalidTracks(all);
    std::vector<ObjectId> ids;
    auto* cmd = new CompositeCommand(this, undoText);
    ObjectId next = m_data.nextId;
    for (HighlightTrack& track : tracks) {
        track.id = next++;
        ids.push_back(track.id);
    }
    new NextIdCommand(this, next, cmd);
    std::size_t index = m_data.look.highlights.size();
    for (HighlightTrack& track : tracks)
        new InsertRemoveCommand<HighlightTrack>(
            this, {}, tracksOf(), std::move(track), index++, false, Part::Highlights, cmd);
    push(cmd);
    return ids;
}

ObjectId Document::addHighlightLayer(const QString& name, int frame)
{
    HighlightTrack track;
    track.name = uniqueHighlightName(name);
    track.setKey(frame, algo::HighlightLayer{});
    return addHighlightLayers({std::move(track)}, tr("Add Highlight Layer")).front();
}

std::vector<ObjectId> Document::addHighlightPreset(HighlightPreset preset, ObjectId baseId, int frame)
{
    const HighlightTrack* base = m_data.highlight(baseId);
    std::vector<HighlightTrack> layers = highlightPresetLayers(preset, base ? *base : HighlightTrack{}, frame);
    // Unique names, the combinations following the renamed operands.
    std::vector<QString> taken;
    for (const auto& t : m_data.look.highlights)
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

void Document::addHighlightOperation(ObjectId id, algo::HighlightOperationType type)
{
    std::vector<algo::HighlightKey> keys = highlightOrThrow(id).keys;
    for (auto& k : keys)
        k.layer.shape.operations.push_back(neutralHighlightOperation(type));
    setHighlightKeys(id, std::move(keys), tr("Add Highlight Operation"));
}

void Document::moveHighlightOperation(ObjectId id, int index, int delta)
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

void Document::removeHighlightOperation(ObjectId id, int index)
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

void Document::removeHighlightLayer(ObjectId id)
{
    const HighlightTrack* track = m_data.highlight(id);
    if (!track)
        return;
    auto* cmd = new CompositeCommand(this, tr("Remove Highlight Layer “%1”").arg(track->name));
    // Other layers stop combining with it first, so undo restores them after the layer is back.
    for (const HighlightTrack& other : m_data.look.highlights) {
        Combinations kept;
        std::copy_if(other.combineWith.begin(), other.combineWith.end(), std::back_inserter(kept),
            [&](const auto& c) { return c.second != track->name; });
        if (kept.size() != other.combineWith.size())
            new PropertyCommand<Combinations>(this, {}, Property::HighlightCombinations, idTarget(other.id),
                trackField(other.id, &HighlightTrack::combineWith), std::move(kept), highlightChange(other.id), 0, cmd);
    }
    const auto index = std::size_t(track - m_data.look.highlights.data());
    new InsertRemoveCommand<HighlightTrack>(this, {}, tracksOf(), *track, index, true, Part::Highlights, cmd);
    push(cmd);
}

void Document::renameHighlightLayer(ObjectId id, const QString& name)
{
    const HighlightTrack& track = highlightOrThrow(id);
    const QString wanted = name.trimmed();
    if (wanted == track.name)
        return;
    if (wanted.isEmpty())
        throw EditRefused(tr("A highlight layer needs a name."));
    if (m_data.highlightByName(wanted))
        throw EditRefused(tr("There is already a highlight layer named “%1”.").arg(wanted));
    auto* cmd = new CompositeCommand(this, tr("Rename Highlight Layer “%1”").arg(track.name));
    new PropertyCommand<QString>(this, {}, Property::HighlightName, idTarget(id), trackField(id, &HighlightTrack::name),
        wanted, highlightChange(id, true), 0, cmd);
    for (const HighlightTrack& other : m_data.look.highlights) {
        Combinations renamed = other.combineWith;
        bool touched = false;
        for (auto& c : renamed)
            if (c.second == track.name) {
                c.second = wanted;
                touched = true;
            }
        if (touched)
            new PropertyCommand<Combinations>(this, {}, Property::HighlightCombinations, idTarget(other.id),
                trackField(other.id, &HighlightTrack::combineWith), std::move(renamed), highlightChange(other.id), 0,
                cmd);
    }
    push(cmd);
}

void Document::setHighlightKey(ObjectId id, double frame, const algo::HighlightLayer& layer)
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
    setHighlightKeys(id, std::move(edited.keys), keyEditText(before, layer));
}

void Document::setHighlightKeys(ObjectId id, std::vector<algo::HighlightKey> keys, const QString& undoText)
{
    const HighlightTrack& track = highlightOrThrow(id);
    std::vector<HighlightTrack> tracks = m_data.look.highlights;
    const auto index = std::size_t(&track - m_data.look.highlights.data());
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
    push(new PropertyCommand<std::vector<algo::HighlightKey>>(this, undoText, Property::HighlightKeys, idTarget(id),
        trackField(id, &HighlightTrack::keys), std::move(keys), std::move(change), m_gesture));
}

void Document::removeHighlightKey(ObjectId id, double frame)
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

void Document::nudgeHighlight(ObjectId id, double frame, algo::HighlightOperationType type, double a, double b)
{
    using T = algo::HighlightOperationType;
    const HighlightTrack& track = highlightOrThrow(id);
    if (type != T::Translation && type != T::Rotation && type != T::DirectionalScaling)
        return;
    auto firstOf = [type](const std::vector<algo::HighlightOperation>& ops) {
        return std::size_t(
            std::find_if(ops.begin(), ops.end(), [type](const auto& op) { return op.type == type; }) - ops.begin());
    };
    HighlightTrack edited = track;
    for (auto& k : edited.keys) {
        auto& ops = k.layer.shape.operations;
        if (firstOf(ops) == ops.size())
            ops.insert(type == T::DirectionalScaling ? ops.end() : ops.begin(), neutralHighlightOperation(type));
    }
    algo::HighlightLayer layer = edited.layerAt(frame);
    auto& ops = layer.shape.operations;
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
    edited.setKey(frame, layer);
    setHighlightKeys(id, std::move(edited.keys),
        type == T::Rotation                 ? tr("Rotate Highlight")
            : type == T::DirectionalScaling ? tr("Scale Highlight")
                                            : tr("Move Highlight"));
}

void Document::setHighlightTranslation(ObjectId id, double frame, double alpha, double beta)
{
    const Eigen::Vector2d now = highlightOrThrow(id).translationAt(frame);
    if (!std::isfinite(alpha) || !std::isfinite(beta))
        return;
    nudgeHighlight(id, frame, algo::HighlightOperationType::Translation, alpha - now.x(), beta - now.y());
}

void Document::setHighlightPatch(ObjectId id, const QString& patch)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.patch == patch)
        return;
    if (!patch.isEmpty() && !m_data.faceSet(patch))
        throw EditRefused(tr("There is no patch named “%1”.").arg(patch));
    push(new PropertyCommand<QString>(this, tr("Change Highlight Patch"), Property::HighlightPatch, idTarget(id),
        trackField(id, &HighlightTrack::patch), patch, highlightChange(id), m_gesture));
}

void Document::setHighlightGuide(ObjectId id, const Eigen::Vector3f& guide)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.guide == guide)
        return;
    if (!guide.allFinite() || guide.norm() == 0.f)
        throw EditRefused(tr("A highlight's guide needs a direction (not zero)."));
    push(new PropertyCommand<Eigen::Vector3f>(this, tr("Change Highlight Guide"), Property::HighlightGuide,
        idTarget(id), trackField(id, &HighlightTrack::guide), guide, highlightChange(id), m_gesture));
}

void Document::setHighlightSmoothing(ObjectId id, int rounds)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.smoothing == rounds)
        return;
    if (rounds < 0 || rounds > kMaxHighlightSmoothing)
        throw EditRefused(tr("Normal smoothing takes 0 to %1 rounds.").arg(kMaxHighlightSmoothing));
    push(new PropertyCommand<int>(this, tr("Change Highlight Smoothing"), Property::HighlightSmoothing, idTarget(id),
        trackField(id, &HighlightTrack::smoothing), rounds, highlightChange(id), m_gesture));
}

void Document::setHighlightVisible(ObjectId id, bool visible)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.visible == visible)
        return;
    push(new PropertyCommand<bool>(this, visible ? tr("Show Highlight Layer") : tr("Hide Highlight Layer"),
        Property::HighlightVisible, idTarget(id), trackField(id, &HighlightTrack::visible), visible,
        highlightChange(id, true), 0));
}

void Document::setHighlightCombinations(ObjectId id, Combinations combinations)
{
    const HighlightTrack& track = highlightOrThrow(id);
    if (track.combineWith == combinations)
        return;
    std::vector<HighlightTrack> tracks = m_data.look.highlights;
    tracks[std::size_t(&track - m_data.look.highlights.data())].combineWith = combinations;
    refuseInvalidTracks(tracks);
    push(new PropertyCommand<Combinations>(this, tr("Change Highlight Combinations"), Property::HighlightCombinations,
        idTarget(id), trackField(id, &HighlightTrack::combineWith), std::move(combinations), highlightChange(id),
        m_gesture));
}

// --- face sets ------------------------------------------------------------------------------------

void Document::setFaceSet(const QString& name, std::vector<std::int32_t> faces, const QString& undoText)
{
    if (!m_data.baseMesh)
        throw EditRefused(tr("There is no base model to make a patch on."));
    if (name.trimmed().isEmpty())
        throw EditRefused(tr("A patch needs a name."));
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    if (!faces.empty() && (faces.front() < 0 || faces.back() >= m_data.baseMesh->faceCount()))
        throw EditRefused(tr("Patch “%1” names a face the base model does not have.").arg(name));
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    const std::string wanted = name.toStdString();
    auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    const bool created = it == sets.end();
    if (created) {
        sets.push_back({wanted, std::move(faces)});
    } else {
        if (it->faces == faces)
            return;
        it->faces = std::move(faces);
    }
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = created;
    push(new PropertyCommand<std::vector<algo::FaceSet>>(
        this, undoText, Property::FaceSets, name, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change,
        m_gesture));
}

void Document::paintFaceSet(const QString& name, const std::vector<std::int32_t>& faces, bool subtract)
{
    const algo::FaceSet* set = m_data.faceSet(name);
    std::vector<std::int32_t> dab = faces;
    std::sort(dab.begin(), dab.end());
    dab.erase(std::unique(dab.begin(), dab.end()), dab.end());
    const std::vector<std::int32_t> none;
    const std::vector<std::int32_t>& before = set ? set->faces : none;
    std::vector<std::int32_t> after;
    after.reserve(before.size() + dab.size());
    if (subtract)
        std::set_difference(before.begin(), before.end(), dab.begin(), dab.end(), std::back_inserter(after));
    else
        std::set_union(before.begin(), before.end(), dab.begin(), dab.end(), std::back_inserter(after));
    if (set && after == before)
        return;
    setFaceSet(name, std::move(after), tr("Paint Patch “%1”").arg(name));
}

void Document::removeFaceSet(const QString& name)
{
    const std::string wanted = name.toStdString();
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end())
        return;
    sets.erase(it);
    auto* cmd = new CompositeCommand(this, tr("Delete Patch “%1”").arg(name));
    // Layers go back to all faces before the set goes, so undo brings the set back first.
    for (const HighlightTrack& track : m_data.look.highlights)
        if (track.patch == name)
            new PropertyCommand<QString>(this, {}, Property::HighlightPatch, idTarget(track.id),
                trackField(track.id, &HighlightTrack::patch), QString(), highlightChange(track.id), 0, cmd);
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = true;
    new PropertyCommand<std::vector<algo::FaceSet>>(
        this, {}, Property::FaceSets, name, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change, 0,
        cmd);
    push(cmd);
}

void Document::renameFaceSet(const QString& name, const QString& newName)
{
    const QString trimmed = newName.trimmed();
    if (trimmed == name)
        return;
    if (trimmed.isEmpty())
        throw EditRefused(tr("A patch needs a name."));
    if (m_data.faceSet(trimmed))
        throw EditRefused(tr("There is already a patch named “%1”.").arg(trimmed));
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    const std::string wanted = name.toStdString();
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end())
        return;
    it->name = trimmed.toStdString();
    auto* cmd = new CompositeCommand(this, tr("Rename Patch “%1”").arg(name));
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = true;
    new PropertyCommand<std::vector<algo::FaceSet>>(
        this, {}, Property::FaceSets, name, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change, 0,
        cmd);
    for (const HighlightTrack& track : m_data.look.highlights)
        if (track.patch == name)
            new PropertyCommand<QString>(this, {}, Property::HighlightPatch, idTarget(track.id),
                trackField(track.id, &HighlightTrack::patch), trimmed, highlightChange(track.id), 0, cmd);
    push(cmd);
}

QString Document::newFaceSetForLayer(ObjectId layer, const QString& wanted)
{
    const HighlightTrack& track = highlightOrThrow(layer);
    if (!m_data.baseMesh)
        throw EditRefused(tr("There is no base model to make a patch on."));
    const QString name = uniqueFaceSetName(wanted);
    std::vector<algo::FaceSet> sets = m_data.faceSets;
    sets.push_back({name.toStdString(), {}});
    auto* cmd = new CompositeCommand(this, tr("New Patch “%1”").arg(name));
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = true;
    new PropertyCommand<std::vector<algo::FaceSet>>(
        this, {}, Property::FaceSets, name, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change, 0,
        cmd);
    new PropertyCommand<QString>(this, {}, Property::HighlightPatch, idTarget(layer),
        trackField(layer, &HighlightTrack::patch), name, highlightChange(track.id), 0, cmd);
    push(cmd);
    return name;
}

} // namespace celform::model
