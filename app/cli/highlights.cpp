// `celform highlight` and `celform patch`: stylized highlight layers (Anjyo & Hiramitsu 2003) and
// the face sets they are drawn on, through the same document operations as the Highlights dock.
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"

#include <QJsonArray>

#include <set>

#include <algorithm>
#include <optional>

namespace celform::app {
namespace {

// Unqualified return types: lupdate misreads a qualified one as the context of Cli::tr() strings.
using Combinations = std::vector<std::pair<algo::HighlightBoolean, QString>>;
using Combination = std::pair<algo::HighlightBoolean, QString>;
using Operation = algo::HighlightOperation;
using FaceList = std::vector<std::int32_t>;
using FaceRanges = std::vector<std::pair<qlonglong, qlonglong>>;

/// "--op TYPE:V[,V]" (translate:A,B rotate:DEG scale:DELTA split:G1,G2 square:SIGMA,N).
Operation parseOperation(const QString& value)
{
    const int colon = int(value.indexOf(QLatin1Char(':')));
    const auto type = colon > 0 ? model::highlightOperationType(value.left(colon)) : std::nullopt;
    if (!type)
        throw UsageError{Cli::tr("--op takes translate:A,B, rotate:DEG, scale:DELTA, split:G1,G2 or square:SIGMA,N, "
                                 "not “%1”")
                             .arg(value)};
    algo::HighlightOperation op;
    op.type = *type;
    if (model::highlightOperationArity(*type) == 1) {
        op.a = float(parseFloat("op", value.mid(colon + 1)));
    } else {
        const Eigen::VectorXd v = parseFloats("op", value.mid(colon + 1), 2);
        op.a = float(v[0]);
        op.b = float(v[1]);
    }
    algo::HighlightLayer check;
    check.shape.operations = {op};
    const QString problem = model::highlightLayerProblem(check);
    if (!problem.isEmpty())
        throw UsageError{Cli::tr("--op “%1”: %2").arg(value, problem)};
    return op;
}

/// "--combine union:OTHER" or "--combine subtract:OTHER".
Combination parseCombination(const QString& value)
{
    const int colon = int(value.indexOf(QLatin1Char(':')));
    const QString mode = value.left(colon);
    if (colon < 0 || (mode != QLatin1String("union") && mode != QLatin1String("subtract"))
        || value.mid(colon + 1).isEmpty())
        throw UsageError{Cli::tr("--combine takes union:OTHER or subtract:OTHER, not “%1”").arg(value)};
    return {mode == QLatin1String("union") ? algo::HighlightBoolean::Union : algo::HighlightBoolean::Subtraction,
        value.mid(colon + 1)};
}

/// The project file's form of a track, with "all" spelled out for a track on every face.
QJsonObject listedTrackJson(const model::HighlightTrack& t)
{
    QJsonObject o = model::highlightTrackJson(t);
    if (t.patch.isEmpty())
        o.insert("patch", QStringLiteral("all"));
    return o;
}

/// What `highlight --add NAME` asks for, parsed before the project is opened.
struct LayerEdit {
    QString name;
    int frame = 0;
    std::optional<float> epsilon, cut;
    std::optional<Eigen::Vector3f> guide, color;
    std::optional<std::vector<algo::HighlightOperation>> operations;
    std::optional<Combinations> combinations;
    std::optional<int> smoothing;
    std::optional<bool> visible;
    std::optional<QString> patch; ///< empty: all faces

    /// The key at the frame: the given values over the layer as it is there.
    [[nodiscard]] algo::HighlightLayer keyOver(algo::HighlightLayer layer) const
    {
        if (epsilon)
            layer.shape.epsilon = *epsilon;
        if (cut)
            layer.offSpecularCut = *cut;
        if (color)
            layer.color = *color;
        if (operations)
            layer.shape.operations = *operations;
        return layer;
    }
};

LayerEdit parseLayerEdit(const Invocation& in)
{
    LayerEdit e;
    e.name = in.value("add");
    if (e.name.isEmpty())
        throw UsageError{Cli::tr("--add needs a layer name")};
    if (in.isSet("epsilon")) {
        e.epsilon = float(parseFloat("epsilon", in.value("epsilon")));
        if (!(*e.epsilon > 0.f && *e.epsilon <= 1.f))
            throw UsageError{Cli::tr("--epsilon must lie in (0, 1], not “%1”").arg(in.value("epsilon"))};
    }
    if (in.isSet("cut")) {
        e.cut = float(parseFloat("cut", in.value("cut")));
        if (!(*e.cut >= -1.f && *e.cut <= 1.f))
            throw UsageError{Cli::tr("--cut must lie in [-1, 1], not “%1”").arg(in.value("cut"))};
    }
    if (in.isSet("guide"))
        e.guide = parseFloatDirection("guide", in.value("guide"));
    if (in.isSet("color")) {
        e.color = parseFloats("color", in.value("color"), 3).cast<float>();
        if (e.color->minCoeff() < 0.f || e.color->maxCoeff() > 1.f)
            throw UsageError{Cli::tr("--color components must lie in [0, 1], not “%1”").arg(in.value("color"))};
    }
    if (in.isSet("op")) {
        e.operations.emplace();
        for (const QString& v : in.values("op"))
            e.operations->push_back(parseOperation(v));
    }
    if (in.isSet("combine")) {
        e.combinations.emplace();
        for (const QString& v : in.values("combine")) {
            e.combinations->push_back(parseCombination(v));
            if (e.combinations->back().second == e.name)
                throw UsageError{Cli::tr("--combine needs another layer than “%1” itself").arg(e.name)};
        }
    }
    if (in.isSet("smooth")) {
        e.smoothing = parseInt("smooth", in.value("smooth"));
        if (*e.smoothing < 0 || *e.smoothing > model::kMaxHighlightSmoothing)
            throw UsageError{Cli::tr("--smooth must lie in [0, %1], not “%2”")
                                 .arg(model::kMaxHighlightSmoothing)
                                 .arg(in.value("smooth"))};
    }
    if (in.isSet("visible"))
        e.visible = parseOnOff("visible", in.value("visible"));
    if (in.isSet("patch"))
        e.patch = in.value("patch") == QLatin1String("all") ? QString() : in.value("patch");
    e.frame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    return e;
}

/// Adds the layer, or with --frame sets a key of an existing one and its layer-wide values.
void applyLayerEdit(model::Document& doc, const QString& path, const LayerEdit& e, bool frameGiven)
{
    const model::ProjectData& data = doc.data();
    // Unknown references are bad input naming the file; the document checks them again.
    if (e.patch && !e.patch->isEmpty() && !data.faceSet(*e.patch))
        throw model::IoError(path, Cli::tr("has no face set named “%1”").arg(*e.patch));
    if (e.combinations)
        for (const auto& [mode, other] : *e.combinations)
            if (!data.highlightByName(other))
                throw model::IoError(path, Cli::tr("has no highlight layer named “%1”").arg(other));
    const model::HighlightTrack* existing = data.highlightByName(e.name);
    if (!existing) {
        model::HighlightTrack track;
        track.name = e.name;
        track.patch = e.patch.value_or(QString());
        track.guide = e.guide.value_or(track.guide);
        track.visible = e.visible.value_or(track.visible);
        track.smoothing = e.smoothing.value_or(track.smoothing);
        track.combineWith = e.combinations.value_or(Combinations{});
        track.keys.push_back({double(e.frame), e.keyOver(algo::HighlightLayer{})});
        doc.highlights().addHighlightLayers({std::move(track)}, model::Document::tr("Add Highlight Layer"));
        return;
    }
    if (!frameGiven)
        throw model::IoError(path,
            Cli::tr("already has a highlight layer named “%1”; give --frame F to set a keyframe of it").arg(e.name));
    const model::ObjectId id = existing->id;
    doc.highlights().setHighlightKey(id, e.frame, e.keyOver(existing->layerAt(e.frame)));
    if (e.patch)
        doc.highlights().setHighlightPatch(id, *e.patch);
    if (e.guide)
        doc.highlights().setHighlightGuide(id, *e.guide);
    if (e.smoothing)
        doc.highlights().setHighlightSmoothing(id, *e.smoothing);
    if (e.visible)
        doc.highlights().setHighlightVisible(id, *e.visible);
    if (e.combinations)
        doc.highlights().setHighlightCombinations(id, *e.combinations);
}

int runHighlight(const Invocation& in)
{
    // Every option is checked before the file is touched.
    const bool editing
        = in.countSet({"patch", "epsilon", "guide", "color", "cut", "op", "combine", "smooth", "visible", "frame"}) > 0;
    const int actions = in.countSet({"list", "add", "remove", "rename"});
    if (actions != 1 || (!in.isSet("add") && editing) || in.isSet("rename") != in.isSet("to"))
        throw UsageError{Cli::tr("give one of --list, --add NAME with its options, --remove NAME or --rename NAME --to "
                                 "NEW")};
    const QString path = in.argument(0);
    if (in.isSet("list")) {
        const model::ProjectData data = model::loadProject(path);
        QJsonArray layers;
        QString text;
        for (const model::HighlightTrack& t : data.look.highlights) {
            layers.append(listedTrackJson(t));
            text += Cli::tr("%1\tpatch %2\t%3 keyframes\n")
                        .arg(t.name, t.patch.isEmpty() ? QStringLiteral("all") : t.patch)
                        .arg(t.keys.size());
        }
        if (in.isSet("json"))
            printJson({{"layers", layers}});
        else
            printOut(text);
        return kExitOk;
    }
    if (in.isSet("remove") || in.isSet("rename")) {
        const QString name = in.value(in.isSet("remove") ? "remove" : "rename");
        auto doc = openProject(path);
        const model::HighlightTrack* track = doc->data().highlightByName(name);
        if (!track)
            throw model::IoError(path, Cli::tr("has no highlight layer named “%1”").arg(name));
        // The document carries other layers' combinations along.
        if (in.isSet("remove")) {
            doc->highlights().removeHighlightLayer(track->id);
        } else {
            const QString newName = in.value("to").trimmed();
            if (newName.isEmpty() || (newName != name && doc->data().highlightByName(newName)))
                throw UsageError{Cli::tr("--to needs a new name no other layer has, not “%1”").arg(in.value("to"))};
            doc->highlights().renameHighlightLayer(track->id, newName);
        }
        doc->saveAs(path);
        return kExitOk;
    }

    const LayerEdit edit = parseLayerEdit(in);
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    applyLayerEdit(*doc, path, edit, in.isSet("frame"));
    const model::HighlightTrack& track = *doc->data().highlightByName(edit.name);
    // Keys with different operation types do not interpolate: the earlier one holds.
    for (std::size_t k = 1; k < track.keys.size(); ++k)
        if (!algo::sameHighlightStructure(track.keys[k - 1].layer, track.keys[k].layer))
            printErr(Cli::tr("warning: %1: the keyframes %2 and %3 of “%4” have different operations; the earlier "
                             "one holds between them")
                         .arg(path)
                         .arg(track.keys[k - 1].frame)
                         .arg(track.keys[k].frame)
                         .arg(edit.name));
    const QJsonObject result = listedTrackJson(track);
    doc->saveAs(path);
    if (in.isSet("json"))
        printJson(result);
    return kExitOk;
}

/// The ranges of "A-B,C,..." (a usage error when malformed or naming no face at all: ",,," made
/// an empty patch). Checked before the project is opened; the face count after.
FaceRanges parseFaceRanges(const QString& text)
{
    FaceRanges ranges;
    const auto malformed
        = [&] { return UsageError{Cli::tr("--faces takes indices and ranges like 0-99,120, not “%1”").arg(text)}; };
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList ends = part.trimmed().split(QLatin1Char('-'));
        bool okA = false, okB = true;
        const qlonglong a = ends[0].toLongLong(&okA);
        const qlonglong b = ends.size() == 2 ? ends[1].toLongLong(&okB) : a;
        if (ends.size() > 2 || !okA || !okB || a < 0 || b < a)
            throw malformed();
        ranges.emplace_back(a, b);
    }
    if (ranges.empty())
        throw malformed();
    return ranges;
}

/// Face indices of ranges, each below faceCount (bad input naming the file when the mesh has no
/// such face).
FaceList expandFaceRanges(const FaceRanges& ranges, Eigen::Index faceCount, const QString& path)
{
    std::vector<std::int32_t> faces;
    for (const auto& [a, b] : ranges) {
        if (b >= faceCount)
            throw model::IoError(path, Cli::tr("has %1 faces; face %2 does not exist").arg(faceCount).arg(b));
        for (qlonglong f = a; f <= b; ++f)
            faces.push_back(std::int32_t(f));
    }
    return faces;
}

/// The faces of --faces, --material and --sphere, united.
FaceList selectFaces(const Invocation& in, const algo::TriMesh& mesh, const std::vector<FaceRanges>& faceRanges,
    const std::vector<Eigen::Vector4d>& spheres, const QString& path)
{
    std::vector<std::int32_t> selected;
    for (const FaceRanges& ranges : faceRanges) {
        const auto faces = expandFaceRanges(ranges, mesh.faceCount(), path);
        selected.insert(selected.end(), faces.begin(), faces.end());
    }
    for (const QString& name : in.values("material")) {
        const auto it = std::find_if(mesh.materials.begin(), mesh.materials.end(),
            [&](const algo::Material& m) { return QString::fromStdString(m.name) == name; });
        if (it == mesh.materials.end())
            throw model::IoError(path, Cli::tr("has no material named “%1”").arg(name));
        const auto index = std::int32_t(it - mesh.materials.begin());
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            if ((mesh.faceMaterials.empty() ? 0 : mesh.faceMaterials[std::size_t(f)]) == index)
                selected.push_back(std::int32_t(f));
    }
    for (const Eigen::Vector4d& s : spheres) {
        const Eigen::Vector3f centre = s.head<3>().cast<float>();
        const float r2 = float(s[3] * s[3]);
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            for (int k = 0; k < 3; ++k)
                if ((mesh.vertices.row(mesh.faces(f, k)).transpose() - centre).squaredNorm() <= r2) {
                    selected.push_back(std::int32_t(f));
                    break;
                }
    }
    return selected;
}

QJsonObject patchJson(const algo::FaceSet& set)
{
    return {{"name", QString::fromStdString(set.name)}, {"face_count", double(set.faces.size())}};
}

/// A mirrored stroke of one dab whose faces have no twins says so.
void warnIfNoTwins(const model::FaceSetStroke& stroke, model::MirrorPlane mirror)
{
    if (stroke.twinMissing)
        printErr(Cli::tr("warning: the selected faces have no mirror twins across the %1 plane; only their side was "
                         "painted")
                     .arg(model::mirrorPlaneName(mirror)));
}

/// `patch --importance V [--strength S]` and `--clear-importance`: focal points painted as one
/// stroke of the patch brush's importance mode (the editor's, one undo step).
int runImportance(const Invocation& in, const std::vector<Eigen::Vector4d>& spheres,
    const std::vector<FaceRanges>& faceRanges, const std::optional<model::MirrorPlane>& mirrorChoice)
{
    const QString path = in.argument(0);
    float value = 1.f, strength = 1.f;
    if (in.isSet("importance")) {
        value = float(parseNumber("importance", in.value("importance")));
        if (!(value >= 0.f && value <= 1.f))
            throw UsageError{Cli::tr("--importance takes a value in [0, 1], not “%1”").arg(in.value("importance"))};
    }
    if (in.isSet("strength")) {
        strength = float(parseNumber("strength", in.value("strength")));
        if (!(strength > 0.f && strength <= 1.f))
            throw UsageError{Cli::tr("--strength takes a value in (0, 1], not “%1”").arg(in.value("strength"))};
    }
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    std::size_t changed = 0;
    if (in.isSet("clear-importance")) {
        doc->faceSets().clearFaceImportance();
    } else {
        const auto selected = selectFaces(in, *doc->data().baseMesh, faceRanges, spheres, path);
        const model::MirrorPlane mirror = mirrorChoice.value_or(doc->data().mirrorPlane);
        model::FaceSetStroke stroke = doc->faceSets().beginImportanceStroke(value, strength, mirror);
        changed = doc->faceSets().applyFaceSetStroke(stroke, selected, false);
        doc->faceSets().endFaceSetStroke(stroke);
        warnIfNoTwins(stroke, mirror);
    }
    doc->saveAs(path);
    if (in.isSet("json")) {
        QJsonObject json = faceImportanceJson(doc->data());
        json.insert("faces_changed", double(changed));
        printJson(json);
    }
    return kExitOk;
}

int runPatch(const Invocation& in)
{
    const int actions = in.countSet({"list", "add", "subtract", "remove", "importance", "clear-importance"});
    const bool selecting = in.countSet({"sphere", "faces", "material"}) > 0;
    if (actions != 1 || ((in.isSet("list") || in.isSet("remove") || in.isSet("clear-importance")) && selecting)
        || ((in.isSet("add") || in.isSet("subtract") || in.isSet("importance")) && !selecting))
        throw UsageError{Cli::tr("give one of --list, --add NAME, --subtract NAME or --importance V with a selection, "
                                 "or --remove NAME or --clear-importance")};
    if (in.isSet("strength") && !in.isSet("importance"))
        throw UsageError{Cli::tr("--strength goes with --importance")};
    const QString path = in.argument(0);
    std::vector<Eigen::Vector4d> spheres;
    for (const QString& text : in.values("sphere")) {
        // Float coordinates, as the mesh's; the radius is squared, so it must stay well inside them.
        const Eigen::VectorXd s = parseFloats("sphere", text, 4);
        if (!(s[3] > 0.0) || !std::isfinite(float(s[3] * s[3])))
            throw UsageError{Cli::tr("--sphere needs a positive radius, not “%1”").arg(text)};
        spheres.emplace_back(s);
    }
    std::vector<FaceRanges> faceRanges;
    for (const QString& text : in.values("faces"))
        faceRanges.push_back(parseFaceRanges(text));
    const std::optional<model::MirrorPlane> mirrorChoice
        = parseMirror("mirror", in.isSet("mirror") ? in.value("mirror") : QStringLiteral("off"));
    if (in.isSet("importance") || in.isSet("clear-importance"))
        return runImportance(in, spheres, faceRanges, mirrorChoice);
    const QString name = in.value(in.isSet("add") ? "add" : in.isSet("subtract") ? "subtract" : "remove");
    if (!in.isSet("list") && name.trimmed().isEmpty())
        throw UsageError{Cli::tr("a patch needs a name")};
    if (in.isSet("list")) {
        const model::ProjectData data = model::loadProject(path);
        QJsonArray patches;
        QString text;
        for (const auto& set : data.faceSets) {
            patches.append(patchJson(set));
            text += Cli::tr("%1\t%2 faces\n").arg(QString::fromStdString(set.name)).arg(set.faces.size());
        }
        if (in.isSet("json"))
            printJson({{"patches", patches}});
        else
            printOut(text);
        return kExitOk;
    }
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    if ((in.isSet("remove") || in.isSet("subtract")) && !doc->data().faceSet(name))
        throw model::IoError(path, Cli::tr("has no patch named “%1”").arg(name));
    if (in.isSet("remove")) {
        doc->faceSets().removeFaceSet(name); // its layers go back to all faces in the same step
    } else {
        const auto selected = selectFaces(in, *doc->data().baseMesh, faceRanges, spheres, path);
        // One dab of the patch brush: the same edit, and undo text, as a drag in the editor.
        const model::MirrorPlane mirror = mirrorChoice.value_or(doc->data().mirrorPlane);
        model::FaceSetStroke stroke = doc->faceSets().beginFaceSetStroke(name, mirror);
        doc->faceSets().applyFaceSetStroke(stroke, selected, in.isSet("subtract"));
        doc->faceSets().endFaceSetStroke(stroke);
        warnIfNoTwins(stroke, mirror);
    }
    doc->saveAs(path);
    if (in.isSet("json") && !in.isSet("remove"))
        printJson(patchJson(*doc->data().faceSet(name)));
    return kExitOk;
}

} // namespace

QJsonObject faceImportanceJson(const model::ProjectData& data)
{
    std::int64_t below = 0;
    double sum = 0.0;
    for (const float v : data.faceImportance) {
        below += v < 1.f ? 1 : 0;
        sum += double(v);
    }
    const double faces = data.baseMesh ? double(data.baseMesh->faceCount()) : 0.0;
    const double mean = data.faceImportance.empty() || faces == 0.0 ? 1.0 : sum / faces;
    return {{"painted", !data.faceImportance.empty()}, {"faces_below_1", double(below)}, {"mean", mean}};
}

QJsonObject segmentOverridesJson(const model::ProjectData& data)
{
    std::int64_t faces = 0;
    std::set<std::int32_t> groups;
    for (const std::int32_t label : data.segmentOverrides)
        if (label >= 0) {
            ++faces;
            groups.insert(label);
        }
    return {{"groups", double(groups.size())}, {"faces", double(faces)}};
}

std::vector<SubCommand> highlightCommands()
{
    return {
        {"highlight",
            {"celform highlight P --list [--json]",
                "celform highlight P --add NAME [--patch FACESET|all] [--epsilon E] [--guide X,Y,Z] [--color R,G,B] "
                "[--cut C] [--op translate:A,B|rotate:DEG|scale:DELTA|split:G1,G2|square:SIGMA,N]... "
                "[--combine union|subtract:OTHER]... [--smooth N] [--visible on|off] [--frame F] [--json]",
                "celform highlight P (--remove NAME | --rename NAME --to NEW)"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Adds, keys and lists stylized highlight layers."),
            {{"P", kProjectArgument}},
            {{"list", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "List the highlight layers.")},
                {"add", "NAME",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Add a layer, or with --frame key an existing one.")},
                {"patch", "FACESET",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Face set the highlight may appear on (all: every face).")},
                {"epsilon", "E", QT_TRANSLATE_NOOP("celform::app::Cli", "Size of the area, in (0, 1] (default 0.05).")},
                {"guide", "X,Y,Z",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Direction of the u axis on models without UVs (default 0,1,0).")},
                {"color", "R,G,B",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Linear RGB colour in [0, 1] (default 1,1,1).")},
                {"cut", "C",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Off-specular cut: no highlight where N.L <= C (default -1: off).")},
                {"op", "TYPE:VALUES",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Operation, in order (repeatable): translate:A,B rotate:DEG scale:DELTA split:G1,G2 "
                        "square:SIGMA,N.")},
                {"combine", "MODE:OTHER",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Unite with or subtract another layer's area (repeatable).")},
                {"smooth", "N",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Rounds of normal smoothing over the patch for this layer (default 0: the surface's "
                        "normals).")},
                {"visible", "on|off",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Draw the layer (on) or use it only in combinations (off).")},
                {"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame of the keyframe (default 0).")},
                {"json", nullptr, kJsonOption},
                {"remove", "NAME",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Remove a layer and its use in other layers' combinations.")},
                {"rename", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "Rename a layer (with --to).")},
                {"to", "NEW", QT_TRANSLATE_NOOP("celform::app::Cli", "The new name of --rename.")}},
            runHighlight},
        {"patch",
            {"celform patch P --list [--json]",
                "celform patch P (--add NAME | --subtract NAME) [--sphere X,Y,Z,R]... [--faces A-B,C]... "
                "[--material M]... [--mirror auto|x|y|z|off] [--json]",
                "celform patch P --remove NAME",
                "celform patch P --importance V [--strength S] [--sphere X,Y,Z,R]... [--faces A-B,C]... "
                "[--material M]... [--mirror auto|x|y|z|off] [--json]",
                "celform patch P --clear-importance [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Makes, lists and removes patches: named face sets that highlight layers are limited to; paints the "
                "faces' importance (focal points) that the light optimisation weighs segments by."),
            {{"P", kProjectArgument}},
            {{"list", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "List the patches.")},
                {"add", "NAME",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Add the selected faces to a patch (made when missing).")},
                {"subtract", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "Take the selected faces out of a patch.")},
                {"remove", "NAME",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Delete a patch; its highlight layers go back to all faces.")},
                {"importance", "V",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Paint the selected faces' importance towards V in [0, 1] (default of every face: 1); a "
                        "segment's weight in the light optimisation is multiplied by its faces' mean importance.")},
                {"strength", "S",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "With --importance: the share of the way to V the faces go, in (0, 1] (default 1).")},
                {"clear-importance", nullptr,
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Every face's importance back to 1.")},
                {"sphere", "X,Y,Z,R",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Select the faces with a corner inside a sphere (repeatable).")},
                {"faces", "A-B,C", QT_TRANSLATE_NOOP("celform::app::Cli", "Select faces by index (repeatable).")},
                {"material", "M", QT_TRANSLATE_NOOP("celform::app::Cli", "Select a material's faces (repeatable).")},
                {"mirror", "auto|x|y|z|off",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Also paint the faces' mirror twins across this plane (auto: the project's; default off).")},
                {"json", nullptr, kJsonOption}},
            runPatch},
    };
}

} // namespace celform::app
