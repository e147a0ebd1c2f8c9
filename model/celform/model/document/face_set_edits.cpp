// The named face sets (highlight patches): made, painted, renamed and removed by name. Layers on a
// set follow its renames and removal in the same undo step.
#include "celform/model/document/face_set_edits.h"

#include "celform/model/data/io_error.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/document/face_set_command.h"
#include "celform/model/document/face_values_command.h"

#include "celform/algorithms/tri_mesh.h"

#include <algorithm>
#include <iterator>

namespace celform::model {
namespace {

ChangeSet highlightChange(ObjectId id)
{
    return ChangeSet::of(Part::Highlights, id);
}

} // namespace

void FaceSetEdits::setFaceSet(
    const QString& name, std::vector<std::int32_t> faces, const QString& undoText, GestureId gesture)
{
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    refuseFaces(name, faces);
    const std::string wanted = name.toStdString();
    FaceSetCommand::Change change = FaceSetCommand::changeTo(data(), wanted, faces);
    if (!change.created && change.added.empty() && change.removed.empty())
        return;
    push(new FaceSetCommand(m_doc, undoText, wanted, std::move(change), gesture));
}

// --- the patch brush ----------------------------------------------------------------------------

FaceSetStroke FaceSetEdits::beginFaceSetStroke(const QString& target, MirrorPlane mirror)
{
    refuseFaces(target, {});
    FaceSetStroke stroke;
    stroke.target = target;
    stroke.name = target.toStdString();
    stroke.undoText = tr("Paint Patch “%1”").arg(target);
    prepareStroke(stroke, mirror);
    return stroke;
}

void FaceSetEdits::prepareStroke(FaceSetStroke& stroke, MirrorPlane mirror) const
{
    const algo::TriMesh& mesh = *data().baseMesh;
    stroke.mirrorPlane = mirrorGeometry(mesh, mirror);
    if (stroke.mirrorPlane) {
        algo::Positions centroids(mesh.faceCount(), 3);
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            centroids.row(f) = (mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1))
                                   + mesh.vertices.row(mesh.faces(f, 2)))
                / 3.f;
        stroke.centroids = algo::VertexGrid(centroids);
        // As the offset brush: a twin further than 5 % of the model's size is no twin.
        stroke.mirrorReach = 0.05 * algo::boundingBox(mesh.vertices).diagonal().norm();
    }
    stroke.gesture = m_doc->beginGesture();
}

void FaceSetEdits::collectDab(FaceSetStroke& stroke, const std::vector<std::int32_t>& faces) const
{
    stroke.dab.assign(faces.begin(), faces.end());
    stroke.twinMissing = false;
    if (stroke.mirrorPlane && !faces.empty()) {
        const algo::TriMesh& mesh = *data().baseMesh;
        std::size_t twins = 0;
        for (const std::int32_t f : faces) {
            if (f < 0 || f >= mesh.faceCount())
                continue; // refused by the caller, with nothing changed
            const Eigen::Vector3d centroid = (mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1))
                                                 + mesh.vertices.row(mesh.faces(f, 2)))
                                                 .transpose()
                                                 .cast<double>()
                / 3.0;
            const std::int64_t twin
                = stroke.centroids.nearest(algo::reflect(*stroke.mirrorPlane, centroid), stroke.mirrorReach);
            if (twin >= 0) {
                stroke.dab.push_back(std::int32_t(twin));
                ++twins;
            }
        }
        stroke.twinMissing = twins == 0;
    }
    std::sort(stroke.dab.begin(), stroke.dab.end());
    stroke.dab.erase(std::unique(stroke.dab.begin(), stroke.dab.end()), stroke.dab.end());
}

std::size_t FaceSetEdits::applyFaceSetStroke(FaceSetStroke& stroke, const std::vector<std::int32_t>& faces, bool erase)
{
    if (!stroke.active() || !data().baseMesh)
        return 0;
    collectDab(stroke, faces);
    if (stroke.mode == FaceSetStroke::Mode::Importance)
        return applyImportanceDab(stroke, erase);
    // Only what the dab changes: the faces it adds that the set lacks, or takes that it holds.
    const auto& sets = data().faceSets;
    const auto it
        = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == stroke.name; });
    const algo::FaceSet* set = it == sets.end() ? nullptr : &*it;
    static const std::vector<std::int32_t> none;
    const std::vector<std::int32_t>& before = set ? set->faces : none;
    stroke.changed.clear();
    if (erase)
        std::set_intersection(
            stroke.dab.begin(), stroke.dab.end(), before.begin(), before.end(), std::back_inserter(stroke.changed));
    else
        std::set_difference(
            stroke.dab.begin(), stroke.dab.end(), before.begin(), before.end(), std::back_inserter(stroke.changed));
    if (set && stroke.changed.empty())
        return 0;
    FaceSetCommand::Change change;
    change.created = set == nullptr;
    (erase ? change.removed : change.added) = stroke.changed; // the command keeps its own copy
    refuseFaces(stroke.target, change.added);
    push(new FaceSetCommand(m_doc, stroke.undoText, stroke.name, std::move(change), stroke.gesture));
    return stroke.changed.size();
}

void FaceSetEdits::endFaceSetStroke(FaceSetStroke& stroke)
{
    stroke.gesture.end();
}

// --- the artist's say over the depth analysis ---------------------------------------------------

FaceSetStroke FaceSetEdits::beginImportanceStroke(float value, float strength, MirrorPlane mirror)
{
    if (!data().baseMesh)
        throw EditRefused(tr("There is no base model to paint focal points on."));
    if (!(value >= 0.f && value <= 1.f))
        throw EditRefused(tr("The importance must be between 0 and 1."));
    if (!(strength > 0.f && strength <= 1.f))
        throw EditRefused(tr("The strength must be above 0 and at most 1."));
    FaceSetStroke stroke;
    stroke.mode = FaceSetStroke::Mode::Importance;
    stroke.value = value;
    stroke.strength = strength;
    stroke.undoText = tr("Paint Focal Points");
    stroke.touched.assign(std::size_t(data().baseMesh->faceCount()), 0);
    prepareStroke(stroke, mirror);
    return stroke;
}

std::size_t FaceSetEdits::applyImportanceDab(FaceSetStroke& stroke, bool erase)
{
    const std::int64_t faceCount = data().baseMesh->faceCount();
    if (!stroke.dab.empty() && (stroke.dab.front() < 0 || stroke.dab.back() >= faceCount))
        throw EditRefused(tr("The focal points name a face the base model does not have."));
    if (stroke.touched.size() != std::size_t(faceCount))
        stroke.touched.assign(std::size_t(faceCount), 0);
    const std::vector<float>& importance = data().faceImportance;
    const bool exists = std::int64_t(importance.size()) == faceCount;
    const float target = erase ? 1.f : stroke.value;
    FaceValuesCommand::Change change;
    change.existedBefore = exists;
    change.existsAfter = true;
    stroke.changed.clear();
    for (const std::int32_t f : stroke.dab) {
        if (stroke.touched[std::size_t(f)])
            continue; // once per stroke: a drag over the same faces does not pile up
        stroke.touched[std::size_t(f)] = 1;
        const float before = exists ? importance[std::size_t(f)] : 1.f;
        const float after = std::clamp(before + stroke.strength * (target - before), 0.f, 1.f);
        if (after == before)
            continue;
        change.indices.push_back(f);
        change.before.push_back(before);
        change.after.push_back(after);
        stroke.changed.push_back(f);
    }
    if (change.indices.empty())
        return 0;
    push(new FaceValuesCommand(m_doc, stroke.undoText, FaceLayer::Importance, std::move(change), stroke.gesture));
    return stroke.changed.size();
}

void FaceSetEdits::clearFaceImportance()
{
    const std::vector<float>& importance = data().faceImportance;
    if (importance.empty())
        return;
    FaceValuesCommand::Change change;
    change.existedBefore = true;
    change.existsAfter = false;
    for (std::size_t f = 0; f < importance.size(); ++f)
        if (importance[f] != 1.f) {
            change.indices.push_back(std::int32_t(f));
            change.before.push_back(importance[f]);
            change.after.push_back(1.f);
        }
    push(new FaceValuesCommand(m_doc, tr("Clear Focal Points"), FaceLayer::Importance, std::move(change), {}));
}

void FaceSetEdits::setSegmentOverrides(std::vector<std::int32_t> overrides, const QString& undoText)
{
    if (!data().baseMesh)
        throw EditRefused(tr("There is no base model to mark segments on."));
    const std::int64_t faceCount = data().baseMesh->faceCount();
    // The command stores labels as floats: whole numbers are exact up to 2^24.
    if (faceCount > (std::int64_t(1) << 24))
        throw EditRefused(tr("Segment overrides take models of at most 16,777,216 triangles."));
    const QString problem = segmentOverridesProblem(overrides, faceCount);
    if (!problem.isEmpty())
        throw EditRefused(tr("Segment overrides refused: %1.").arg(problem));
    // No label at all is no layer.
    if (std::all_of(overrides.begin(), overrides.end(), [](std::int32_t l) { return l == kNoSegmentOverride; }))
        overrides.clear();
    const std::vector<std::int32_t>& old = data().segmentOverrides;
    if (old == overrides)
        return;
    FaceValuesCommand::Change change;
    change.existedBefore = !old.empty();
    change.existsAfter = !overrides.empty();
    auto at = [](const std::vector<std::int32_t>& v, std::int64_t f) {
        return v.empty() ? kNoSegmentOverride : v[std::size_t(f)];
    };
    for (std::int64_t f = 0; f < faceCount; ++f)
        if (at(old, f) != at(overrides, f)) {
            change.indices.push_back(std::int32_t(f));
            change.before.push_back(float(at(old, f)));
            change.after.push_back(float(at(overrides, f)));
        }
    push(new FaceValuesCommand(m_doc, undoText, FaceLayer::SegmentOverrides, std::move(change), {}));
}

void FaceSetEdits::refuseFaces(const QString& name, const std::vector<std::int32_t>& faces) const
{
    if (!data().baseMesh)
        throw EditRefused(tr("There is no base model to make a patch on."));
    if (name.trimmed().isEmpty())
        throw EditRefused(tr("A patch needs a name."));
    if (!faces.empty() && (faces.front() < 0 || faces.back() >= data().baseMesh->faceCount()))
        throw EditRefused(tr("Patch “%1” names a face the base model does not have.").arg(name));
}

void FaceSetEdits::removeFaceSet(const QString& name)
{
    const std::string wanted = name.toStdString();
    std::vector<algo::FaceSet> sets = data().faceSets;
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end())
        return;
    sets.erase(it);
    auto* cmd = new CompositeCommand(m_doc, tr("Delete Patch “%1”").arg(name));
    // Layers go back to all faces before the set goes, so undo brings the set back first.
    for (const HighlightTrack& track : data().look.highlights)
        if (track.patch == name)
            new PropertyCommand<QString>(m_doc, {}, {Property::HighlightPatch, track.id},
                fieldOf(track.id, &HighlightTrack::patch), QString(), highlightChange(track.id), {}, cmd);
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = true;
    new PropertyCommand<std::vector<algo::FaceSet>>(
        m_doc, {}, {Property::FaceSets}, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change, {}, cmd);
    push(cmd);
}

void FaceSetEdits::renameFaceSet(const QString& name, const QString& newName)
{
    const QString trimmed = newName.trimmed();
    if (trimmed == name)
        return;
    if (trimmed.isEmpty())
        throw EditRefused(tr("A patch needs a name."));
    if (data().faceSet(trimmed))
        throw EditRefused(tr("There is already a patch named “%1”.").arg(trimmed));
    std::vector<algo::FaceSet> sets = data().faceSets;
    const std::string wanted = name.toStdString();
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    if (it == sets.end())
        return;
    it->name = trimmed.toStdString();
    auto* cmd = new CompositeCommand(m_doc, tr("Rename Patch “%1”").arg(name));
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = true;
    new PropertyCommand<std::vector<algo::FaceSet>>(
        m_doc, {}, {Property::FaceSets}, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change, {}, cmd);
    for (const HighlightTrack& track : data().look.highlights)
        if (track.patch == name)
            new PropertyCommand<QString>(m_doc, {}, {Property::HighlightPatch, track.id},
                fieldOf(track.id, &HighlightTrack::patch), trimmed, highlightChange(track.id), {}, cmd);
    push(cmd);
}

QString FaceSetEdits::newFaceSetForLayer(ObjectId layer, const QString& wanted)
{
    const HighlightTrack* track = data().highlight(layer);
    if (!track)
        throw EditRefused(tr("The highlight layer no longer exists."));
    if (!data().baseMesh)
        throw EditRefused(tr("There is no base model to make a patch on."));
    const QString name = uniqueFaceSetName(wanted);
    std::vector<algo::FaceSet> sets = data().faceSets;
    sets.push_back({name.toStdString(), {}});
    auto* cmd = new CompositeCommand(m_doc, tr("New Patch “%1”").arg(name));
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = true;
    new PropertyCommand<std::vector<algo::FaceSet>>(
        m_doc, {}, {Property::FaceSets}, [](ProjectData& d) { return &d.faceSets; }, std::move(sets), change, {}, cmd);
    new PropertyCommand<QString>(m_doc, {}, {Property::HighlightPatch, layer}, fieldOf(layer, &HighlightTrack::patch),
        name, highlightChange(track->id), {}, cmd);
    push(cmd);
    return name;
}

QString FaceSetEdits::uniqueFaceSetName(const QString& wanted) const
{
    return uniqueName(wanted, [this](const QString& n) { return data().faceSet(n) != nullptr; });
}

} // namespace celform::model
