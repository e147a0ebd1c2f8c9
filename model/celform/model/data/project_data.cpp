// Look-ups and comparison of the project data.
#include "celform/model/data/project_data.h"

#include "celform/algorithms/blend.h"
#include "celform/algorithms/sorted_merge.h"
#include "celform/algorithms/subdivision.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace celform::model {
namespace {

// Gives lupdate the context "celform::model::Highlights" for the validation messages below.
struct Highlights {
    Q_DECLARE_TR_FUNCTIONS(celform::model::Highlights)
};

bool inRange(float v, float lo, float hi)
{
    return std::isfinite(v) && v >= lo && v <= hi;
}

template <typename Vec> auto* findById(Vec& items, ObjectId id)
{
    auto it = std::find_if(items.begin(), items.end(), [id](const auto& x) { return x.id == id; });
    return it == items.end() ? nullptr : &*it;
}
template <typename Vec> auto* findByName(Vec& items, const QString& name)
{
    auto it = std::find_if(items.begin(), items.end(), [&name](const auto& x) { return x.name == name; });
    return it == items.end() ? nullptr : &*it;
}
} // namespace

const Drawing* ProjectData::drawing(ObjectId id) const
{
    return findById(drawings, id);
}
Drawing* ProjectData::drawing(ObjectId id)
{
    return findById(drawings, id);
}
const KeyViewpoint* ProjectData::key(ObjectId id) const
{
    return findById(keys, id);
}
KeyViewpoint* ProjectData::key(ObjectId id)
{
    return findById(keys, id);
}
const KeyViewpoint* ProjectData::keyByName(const QString& name) const
{
    return findByName(keys, name);
}
const Drawing* ProjectData::drawingByName(const QString& name) const
{
    return findByName(drawings, name);
}
const HighlightTrack* ProjectData::highlight(ObjectId id) const
{
    return findById(look.highlights, id);
}
HighlightTrack* ProjectData::highlight(ObjectId id)
{
    return findById(look.highlights, id);
}
const HighlightTrack* ProjectData::highlightByName(const QString& name) const
{
    return findByName(look.highlights, name);
}

Eigen::Vector3f SparseOffsets::at(std::uint32_t index) const
{
    const auto it = std::lower_bound(indices.begin(), indices.end(), index);
    if (it == indices.end() || *it != index)
        return Eigen::Vector3f::Zero();
    return deltas[std::size_t(it - indices.begin())];
}

void SparseOffsets::assign(const std::vector<std::uint32_t>& changed, const std::vector<Eigen::Vector3f>& values,
    const std::vector<char>& present)
{
    // Only values of vertices already stored (a brush stroke's later steps): write them in place,
    // O(m log n) and no allocation.
    const bool inPlace = std::all_of(present.begin(), present.end(), [](char p) { return p != 0; })
        && std::all_of(changed.begin(), changed.end(),
            [this](std::uint32_t v) { return std::binary_search(indices.begin(), indices.end(), v); });
    if (inPlace) {
        auto from = indices.begin();
        for (std::size_t j = 0; j < changed.size(); ++j) {
            from = std::lower_bound(from, indices.end(), changed[j]);
            deltas[std::size_t(from - indices.begin())] = values[j];
        }
        return;
    }
    // One merge pass of two ascending lists: O(n + m), no per-vertex insertion into the middle.
    std::vector<std::uint32_t> mergedIndices;
    std::vector<Eigen::Vector3f> mergedDeltas;
    mergedIndices.reserve(indices.size() + changed.size());
    mergedDeltas.reserve(indices.size() + changed.size());
    auto fromChange = [&](std::size_t k) {
        if (present[k]) { // else removed by the change
            mergedIndices.push_back(changed[k]);
            mergedDeltas.push_back(values[k]);
        }
    };
    algo::mergeAscending(
        indices, changed,
        [&](std::size_t k) {
            mergedIndices.push_back(indices[k]);
            mergedDeltas.push_back(deltas[k]);
        },
        fromChange, [&](std::size_t, std::size_t k) { fromChange(k); });
    indices = std::move(mergedIndices);
    deltas = std::move(mergedDeltas);
}

SparseOffsets SparseOffsets::difference(const algo::Positions& shape, const algo::Positions& base)
{
    SparseOffsets result;
    for (Eigen::Index v = 0; v < std::min(shape.rows(), base.rows()); ++v) {
        const Eigen::Vector3f d = shape.row(v) - base.row(v);
        if (d != Eigen::Vector3f::Zero()) {
            result.indices.push_back(std::uint32_t(v));
            result.deltas.push_back(d);
        }
    }
    return result;
}

ProjectData::FrameOffsets ProjectData::offsetsAt(const KeyViewpoint& key, int frame, TimeInterpolation time)
{
    FrameOffsets result;
    offsetsAt(key, frame, time, result);
    return result;
}

void ProjectData::offsetsAt(const KeyViewpoint& key, int frame, TimeInterpolation time, FrameOffsets& result)
{
    result.stored = nullptr;
    result.interpolated.indices.clear();
    result.interpolated.deltas.clear();
    if (key.offsetsByFrame.empty())
        return;
    if (key.offsetsByFrame.size() == 1) {
        result.stored = &key.offsetsByFrame.begin()->second;
        return;
    }
    std::vector<double> knots;
    std::vector<const SparseOffsets*> values;
    knots.reserve(key.offsetsByFrame.size());
    values.reserve(key.offsetsByFrame.size());
    for (const auto& [f, offsets] : key.offsetsByFrame) {
        knots.push_back(double(f));
        values.push_back(&offsets);
    }
    const std::vector<double> weights
        = algo::splineWeights(knots, double(frame), time == TimeInterpolation::PeriodicSpline);
    const auto single = std::find(weights.begin(), weights.end(), 1.0);
    if (single != weights.end()
        && std::count_if(weights.begin(), weights.end(), [](double w) { return w != 0.0; }) == 1) {
        result.stored = values[std::size_t(single - weights.begin())];
        return;
    }
    // The weighted sum of the keyed frames' sparse offsets: a merge of their ascending index
    // lists. A vertex's terms are summed in keyed-frame order, the first one assigned.
    struct Head {
        const SparseOffsets* offsets;
        float weight;
        std::size_t at;
    };
    std::vector<Head> heads;
    heads.reserve(values.size());
    std::size_t total = 0;
    for (std::size_t k = 0; k < values.size(); ++k)
        if (weights[k] != 0.0 && !values[k]->indices.empty()) {
            heads.push_back({values[k], float(weights[k]), 0});
            total = std::max(total, values[k]->indices.size());
        }
    SparseOffsets& out = result.interpolated;
    out.indices.reserve(total);
    out.deltas.reserve(total);
    constexpr std::uint32_t kDone = std::numeric_limits<std::uint32_t>::max();
    for (;;) {
        std::uint32_t next = kDone;
        for (const Head& h : heads)
            if (h.at < h.offsets->indices.size())
                next = std::min(next, h.offsets->indices[h.at]);
        if (next == kDone)
            break;
        bool first = true;
        for (Head& h : heads) {
            if (h.at >= h.offsets->indices.size() || h.offsets->indices[h.at] != next)
                continue;
            const Eigen::Vector3f term = h.weight * h.offsets->deltas[h.at++];
            if (first) {
                out.indices.push_back(next);
                out.deltas.push_back(term);
                first = false;
            } else {
                out.deltas.back() += term;
            }
        }
    }
}

QString subdivisionProblem(const SubdivisionLook& s)
{
    const int subdivision = s.level, viewportSubdivision = s.viewportLevel;
    if (subdivision < 0 || subdivision > algo::kMaxSubdivisionLevel)
        return QCoreApplication::translate("Look", "the subdivision level must be 0 to %1, not %2")
            .arg(algo::kMaxSubdivisionLevel)
            .arg(subdivision);
    if (viewportSubdivision < -1 || viewportSubdivision > algo::kMaxSubdivisionLevel)
        return QCoreApplication::translate(
            "Look", "the viewport's subdivision level must be -1 (the render level) or 0 to %1, not %2")
            .arg(algo::kMaxSubdivisionLevel)
            .arg(viewportSubdivision);
    return {};
}

QString faceImportanceProblem(const std::vector<float>& importance, std::int64_t faceCount)
{
    if (importance.empty())
        return {};
    if (std::int64_t(importance.size()) != faceCount)
        return QCoreApplication::translate("ProjectData", "the face importance has %1 values for %2 faces")
            .arg(importance.size())
            .arg(faceCount);
    for (const float v : importance)
        if (!(v >= 0.f && v <= 1.f))
            return QCoreApplication::translate("ProjectData", "a face importance lies outside 0 to 1");
    return {};
}

QString segmentOverridesProblem(const std::vector<std::int32_t>& overrides, std::int64_t faceCount)
{
    if (overrides.empty())
        return {};
    if (std::int64_t(overrides.size()) != faceCount)
        return QCoreApplication::translate("ProjectData", "the segment overrides have %1 labels for %2 faces")
            .arg(overrides.size())
            .arg(faceCount);
    for (const std::int32_t label : overrides)
        if (label < kNoSegmentOverride || label >= faceCount)
            return QCoreApplication::translate("ProjectData", "a segment override label is out of range");
    return {};
}

QString sceneTimeProblem(const SceneTime& time)
{
    if (!std::isfinite(time.fps) || time.fps <= 0.0 || time.fps > kMaxFps)
        return QCoreApplication::translate("SceneTime", "frames per second must lie in (0, %1], not %2")
            .arg(kMaxFps)
            .arg(time.fps);
    if (std::abs(time.firstFrame) > kMaxFrame || std::abs(time.lastFrame) > kMaxFrame)
        return QCoreApplication::translate("SceneTime", "the frame range must lie within ±%1").arg(kMaxFrame);
    if (time.lastFrame < time.firstFrame)
        return QCoreApplication::translate("SceneTime", "the frame range ends (%1) before it starts (%2)")
            .arg(time.lastFrame)
            .arg(time.firstFrame);
    return {};
}

QString DrawingOutline::problem() const
{
    if (!std::isfinite(threshold) || threshold > 1.0)
        return QCoreApplication::translate(
            "DrawingOutline", "the outline threshold must lie in 0 to 1 (or be negative for automatic), not %1")
            .arg(threshold);
    if (!std::isfinite(closingRadius) || closingRadius < 0.0 || closingRadius > kMaxClosingRadius)
        return QCoreApplication::translate("DrawingOutline", "the closing radius must lie in 0 to %1 pixels, not %2")
            .arg(kMaxClosingRadius)
            .arg(closingRadius);
    if (minComponentPixels < 0)
        return QCoreApplication::translate("DrawingOutline", "the smallest figure kept must not be negative, not %1")
            .arg(minComponentPixels);
    return {};
}

const algo::Positions& ProjectData::basePositions(int frame, algo::Positions& scratch) const
{
    Q_ASSERT(baseMesh);
    if (!animated())
        return baseMesh->vertices;
    baseAnimation->evaluate(baseMesh->vertices, frame, scratch);
    return scratch;
}

Eigen::Vector3f ProjectData::baseVertex(int frame, Eigen::Index vertex) const
{
    Q_ASSERT(baseMesh);
    if (!animated())
        return baseMesh->vertices.row(vertex).transpose();
    return baseAnimation->evaluateVertex(baseMesh->vertices, frame, vertex);
}

Eigen::Vector3d ProjectData::baseCentre(int frame) const
{
    if (!baseMesh)
        return Eigen::Vector3d::Zero();
    if (!animated())
        return baseMesh->centre();
    algo::Positions scratch;
    return algo::centroid(basePositions(frame, scratch));
}

algo::Positions ProjectData::keyShape(const KeyViewpoint& key, int frame) const
{
    Q_ASSERT(baseMesh);
    algo::Positions scratch;
    algo::Positions shape = basePositions(frame, scratch);
    const FrameOffsets offsets = offsetsAt(key, frame, blend.time);
    if (const SparseOffsets* o = offsets.get())
        for (std::size_t i = 0; i < o->indices.size(); ++i)
            shape.row(o->indices[i]) += o->deltas[i].transpose();
    return shape;
}

std::vector<double> ProjectData::keyFrameWeights(const KeyViewpoint& key, int frame) const
{
    if (key.offsetsByFrame.size() == 1)
        return {1.0};
    std::vector<double> knots;
    knots.reserve(key.offsetsByFrame.size());
    for (const auto& entry : key.offsetsByFrame)
        knots.push_back(double(entry.first));
    if (knots.empty())
        return {};
    return algo::splineWeights(knots, double(frame), blend.time == TimeInterpolation::PeriodicSpline);
}

void ProjectData::updateKeyShape(
    const KeyViewpoint& key, int frame, const std::vector<std::uint32_t>& vertices, algo::Positions& shape) const
{
    Q_ASSERT(baseMesh && shape.rows() == baseMesh->vertices.rows());
    const std::vector<double> weights = keyFrameWeights(key, frame);
    for (const std::uint32_t v : vertices) {
        // Summed as offsetsAt() sums (keyed frames in order, weight times offset), then added to
        // the base as keyShape() adds it: the same floats as a full recomputation.
        Eigen::Vector3f offset = Eigen::Vector3f::Zero();
        std::size_t k = 0;
        for (const auto& entry : key.offsetsByFrame) {
            const double w = weights[k++];
            if (w != 0.0)
                offset += float(w) * entry.second.at(v);
        }
        shape.row(v) = baseVertex(frame, Eigen::Index(v)).transpose() + offset.transpose();
    }
}

ProjectData newProject(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName)
{
    ProjectData data;
    if (mesh) {
        // Strokes about 1.5% of the model apart read as hatching at any model scale.
        const double diagonal = algo::boundingBox(mesh->vertices).diagonal().norm();
        if (diagonal > 0 && std::isfinite(diagonal))
            data.look.hatch.spacing = float(0.015 * diagonal);
    }
    if (mesh)
        data.mirrorPlane = detectMirrorPlane(*mesh);
    data.baseMesh = std::move(mesh);
    data.baseMeshName = meshName;
    return data;
}

bool ProjectData::operator==(const ProjectData& o) const
{
    const bool meshEqual = (!baseMesh && !o.baseMesh) || (baseMesh && o.baseMesh && *baseMesh == *o.baseMesh);
    const bool animationEqual = animated() == o.animated() && (!animated() || *baseAnimation == *o.baseAnimation);
    return meshEqual && baseMeshName == o.baseMeshName && faceSets == o.faceSets && drawings == o.drawings
        && keys == o.keys && blend == o.blend && look == o.look && shadingOffsets == o.shadingOffsets
        && faceImportance == o.faceImportance && segmentOverrides == o.segmentOverrides && mirrorPlane == o.mirrorPlane
        && nextId == o.nextId && currentFrame == o.currentFrame && time == o.time && animationEqual;
}

const algo::FaceSet* ProjectData::faceSet(const QString& name) const
{
    const std::string wanted = name.toStdString();
    const auto it
        = std::find_if(faceSets.begin(), faceSets.end(), [&](const algo::FaceSet& s) { return s.name == wanted; });
    return it == faceSets.end() ? nullptr : &*it;
}

std::vector<QString> ProjectData::faceSetNames() const
{
    std::vector<QString> names;
    names.reserve(faceSets.size());
    for (const auto& set : faceSets)
        names.push_back(QString::fromStdString(set.name));
    return names;
}

algo::HighlightLayer HighlightTrack::layerAt(double frame) const
{
    return algo::interpolateHighlightKeys(keys, frame).value_or(algo::HighlightLayer{});
}

void HighlightTrack::setKey(double frame, const algo::HighlightLayer& layer)
{
    auto it = std::lower_bound(
        keys.begin(), keys.end(), frame, [](const algo::HighlightKey& k, double f) { return k.frame < f; });
    if (it != keys.end() && it->frame == frame)
        it->layer = layer;
    else
        keys.insert(it, algo::HighlightKey{frame, layer});
}

Eigen::Vector2d HighlightTrack::translationAt(double frame) const
{
    using T = algo::HighlightOperationType;
    const algo::HighlightLayer layer = layerAt(frame);
    double degrees = 0.0;
    for (const algo::HighlightOperation& op : layer.shape.operations) {
        if (op.type == T::Rotation)
            degrees += op.a;
        if (op.type != T::Translation)
            continue;
        // The stored values are in the frame the earlier rotations left: turn them back.
        const double r = degrees * 3.14159265358979323846 / 180.0, c = std::cos(r), s = std::sin(r);
        return {c * op.a - s * op.b, s * op.a + c * op.b};
    }
    return Eigen::Vector2d::Zero();
}

QString highlightOperationName(algo::HighlightOperationType type)
{
    switch (type) {
    case algo::HighlightOperationType::Translation:
        return QStringLiteral("translate");
    case algo::HighlightOperationType::Rotation:
        return QStringLiteral("rotate");
    case algo::HighlightOperationType::DirectionalScaling:
        return QStringLiteral("scale");
    case algo::HighlightOperationType::Split:
        return QStringLiteral("split");
    case algo::HighlightOperationType::Squaring:
        return QStringLiteral("square");
    }
    return {};
}

std::optional<algo::HighlightOperationType> highlightOperationType(const QString& name)
{
    for (auto type : {algo::HighlightOperationType::Translation, algo::HighlightOperationType::Rotation,
             algo::HighlightOperationType::DirectionalScaling, algo::HighlightOperationType::Split,
             algo::HighlightOperationType::Squaring})
        if (highlightOperationName(type) == name)
            return type;
    return std::nullopt;
}

int highlightOperationArity(algo::HighlightOperationType type)
{
    return type == algo::HighlightOperationType::Rotation || type == algo::HighlightOperationType::DirectionalScaling
        ? 1
        : 2;
}

QString highlightLayerProblem(const algo::HighlightLayer& layer)
{
    if (!inRange(layer.shape.epsilon, 0.f, 1.f) || layer.shape.epsilon == 0.f)
        return Highlights::tr("epsilon must lie in (0, 1]");
    for (int c = 0; c < 3; ++c)
        if (!inRange(layer.color[c], 0.f, 1.f))
            return Highlights::tr("colour components must lie in [0, 1]");
    if (!inRange(layer.offSpecularCut, -1.f, 1.f))
        return Highlights::tr("the off-specular cut must lie in [-1, 1]");
    for (const algo::HighlightOperation& op : layer.shape.operations) {
        const float big = std::numeric_limits<float>::max();
        bool ok = true;
        switch (op.type) {
        case algo::HighlightOperationType::Translation:
            ok = inRange(op.a, -big, big) && inRange(op.b, -big, big);
            break;
        case algo::HighlightOperationType::Rotation:
            ok = inRange(op.a, -big, big) && op.b == 0.f;
            break;
        case algo::HighlightOperationType::DirectionalScaling:
            ok = inRange(op.a, 0.f, 1.f) && op.b == 0.f;
            break;
        case algo::HighlightOperationType::Split:
            ok = inRange(op.a, 0.f, big) && inRange(op.b, 0.f, big);
            break;
        case algo::HighlightOperationType::Squaring:
            ok = inRange(op.a, 0.f, 1.f) && inRange(op.b, 1.f, big);
            break;
        }
        if (!ok)
            return Highlights::tr("the parameters of a %1 operation are out of range")
                .arg(highlightOperationName(op.type));
    }
    if (!layer.combinations.empty())
        return Highlights::tr("combinations belong to the track, not to its keys");
    return {};
}

QString highlightTracksProblem(const std::vector<HighlightTrack>& tracks, const std::vector<QString>& faceSetNames)
{
    std::set<QString> names;
    for (const HighlightTrack& t : tracks) {
        if (t.name.isEmpty())
            return Highlights::tr("a highlight layer has no name");
        if (!names.insert(t.name).second)
            return Highlights::tr("two highlight layers are named “%1”").arg(t.name);
    }
    for (const HighlightTrack& t : tracks) {
        if (!t.patch.isEmpty() && std::find(faceSetNames.begin(), faceSetNames.end(), t.patch) == faceSetNames.end())
            return Highlights::tr("highlight layer “%1” uses the unknown face set “%2”").arg(t.name, t.patch);
        if (!t.guide.allFinite() || t.guide.norm() == 0.f)
            return Highlights::tr("highlight layer “%1” has a zero guide direction").arg(t.name);
        if (t.smoothing < 0 || t.smoothing > kMaxHighlightSmoothing)
            return Highlights::tr("highlight layer “%1” has normal smoothing outside [0, %2]")
                .arg(t.name)
                .arg(kMaxHighlightSmoothing);
        if (t.keys.empty())
            return Highlights::tr("highlight layer “%1” has no keyframe").arg(t.name);
        for (std::size_t i = 0; i < t.keys.size(); ++i) {
            if (!std::isfinite(t.keys[i].frame) || (i > 0 && !(t.keys[i].frame > t.keys[i - 1].frame)))
                return Highlights::tr("highlight layer “%1” has keyframes out of order").arg(t.name);
            const QString problem = highlightLayerProblem(t.keys[i].layer);
            if (!problem.isEmpty())
                return Highlights::tr("highlight layer “%1”: %2").arg(t.name, problem);
        }
        for (const auto& [mode, other] : t.combineWith)
            if (other == t.name || names.count(other) == 0)
                return Highlights::tr("highlight layer “%1” combines with “%2”, which is not another layer")
                    .arg(t.name, other);
    }
    return {};
}

} // namespace celform::model
