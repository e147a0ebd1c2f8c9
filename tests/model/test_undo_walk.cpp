// Undo integrity under a long random walk: thousands of edits of every kind the
// Document offers, with gestures, brush strokes, undo, redo and saves mixed in. Each step is
// checked as it happens (a refused edit changes nothing, undo and redo land exactly on the states
// recorded for their index, changed() names every part that changed, a clean document equals its
// file), and at the end undoing everything gives the original project bit for bit and redoing
// everything gives the final one. Every saved file reopens equal to the document it came from.
//
// The walk is seeded: CELFORM_WALK_SEED picks the first of the three seeds run (the failure
// message names the seed to rerun); CELFORM_WALK_STEPS changes the number of steps per seed and
// CELFORM_WALK_VERBOSE=1 prints how often each operation ran, changed data or was refused.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <QBuffer>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <random>

using namespace celform;
using namespace celform::model;

namespace {

constexpr std::uint64_t kDefaultSeed = 20240614;
constexpr int kDefaultSteps = 10000;

using Rng = std::mt19937_64;

// Own distributions: std::uniform_*_distribution may differ between standard libraries, and a
// seed must replay the same walk everywhere.
double unit(Rng& r)
{
    return double(r() >> 11) * 0x1.0p-53;
}
double uniform(Rng& r, double a, double b)
{
    return a + (b - a) * unit(r);
}
float uniformF(Rng& r, double a, double b)
{
    return float(uniform(r, a, b));
}
int below(Rng& r, int n)
{
    return n <= 0 ? 0 : int(r() % std::uint64_t(n));
}
bool chance(Rng& r, double p)
{
    return unit(r) < p;
}
template <typename T> const T& pickFrom(Rng& r, const std::vector<T>& items)
{
    return items[std::size_t(below(r, int(items.size())))];
}

Eigen::Vector3d randomDirection(Rng& r)
{
    for (;;) {
        const Eigen::Vector3d v(uniform(r, -1, 1), uniform(r, -1, 1), uniform(r, -1, 1));
        if (v.norm() > 0.1 && v.norm() <= 1.0)
            return v.normalized();
    }
}

Eigen::Vector3f randomColor(Rng& r)
{
    return {uniformF(r, 0, 1), uniformF(r, 0, 1), uniformF(r, 0, 1)};
}

/// A camera around the unit-sized model; rarely an invalid one (eye on the target), which every
/// edit taking a camera must refuse or ignore.
Camera randomCamera(Rng& r, bool allowInvalid = true)
{
    Camera c;
    c.eye = randomDirection(r) * uniform(r, 2.5, 6.0);
    c.target = Eigen::Vector3d(uniform(r, -0.2, 0.2), uniform(r, -0.2, 0.2), uniform(r, -0.2, 0.2));
    c.up = chance(r, 0.7) ? Eigen::Vector3d(0, 1, 0) : randomDirection(r);
    c.projection = chance(r, 0.7) ? Projection::Perspective : Projection::Orthographic;
    c.fovYDegrees = uniform(r, 10, 80);
    c.orthoHeight = uniform(r, 0.5, 4);
    if (allowInvalid && chance(r, 0.05))
        c.target = c.eye;
    return c;
}

/// The walk's base model: an icosphere (symmetric across x = 0, so the X-mirror brush has twins)
/// with three materials and spherical UVs.
std::shared_ptr<const algo::TriMesh> walkMesh(int subdivisions, float scale = 1.f)
{
    auto sphere = test::icosphere(subdivisions);
    auto mesh = test::withSectorMaterials(*sphere, {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.3f, 0.9f}});
    mesh->vertices *= scale;
    mesh->uvs.resize(mesh->vertexCount(), 2);
    for (Eigen::Index v = 0; v < mesh->vertexCount(); ++v) {
        const Eigen::Vector3f p = sphere->vertices.row(v);
        mesh->uvs(v, 0) = std::atan2(p.z(), p.x()) / float(2 * M_PI) + 0.5f;
        mesh->uvs(v, 1) = std::asin(std::clamp(p.y(), -1.f, 1.f)) / float(M_PI) + 0.5f;
    }
    mesh->uvFaces = mesh->faces;
    return mesh;
}

QByteArray pngBytes(int w, int h, QColor color)
{
    QImage image(w, h, QImage::Format_RGBA8888);
    image.fill(color);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return bytes;
}

/// ProjectData::operator== member by member, but a shared mesh is equal without comparing its
/// arrays (most of the time per step otherwise); the final checks use operator== itself.
bool equalData(const ProjectData& a, const ProjectData& b, bool withPlayhead)
{
    const bool meshEqual = a.baseMesh == b.baseMesh || (a.baseMesh && b.baseMesh && *a.baseMesh == *b.baseMesh);
    return meshEqual && a.baseMeshName == b.baseMeshName && a.faceSets == b.faceSets && a.drawings == b.drawings
        && a.keys == b.keys && a.blend == b.blend && a.look == b.look && a.shadingOffsets == b.shadingOffsets
        && a.nextId == b.nextId && (!withPlayhead || a.currentFrame == b.currentFrame);
}

/// Equal stored data but for the playhead, which is not undoable.
bool sameData(const ProjectData& a, const ProjectData& b)
{
    return equalData(a, b, false);
}

/// The parts (Part bits) in which two projects differ.
std::uint32_t differingParts(const ProjectData& a, const ProjectData& b)
{
    std::uint32_t parts = 0;
    auto set = [&parts](Part p) { parts |= std::uint32_t(p); };
    const bool meshEqual = a.baseMesh == b.baseMesh || (a.baseMesh && b.baseMesh && *a.baseMesh == *b.baseMesh);
    if (!meshEqual || a.baseMeshName != b.baseMeshName)
        set(Part::Mesh);
    if (!(a.drawings == b.drawings))
        set(Part::Drawings);
    if (!(a.keys == b.keys))
        set(Part::Keys);
    if (a.blend != b.blend)
        set(Part::Blend);
    if (!(a.look.highlights == b.look.highlights))
        set(Part::Highlights);
    Look la = a.look, lb = b.look;
    la.highlights.clear();
    lb.highlights.clear();
    if (la != lb)
        set(Part::Look);
    if (!(a.faceSets == b.faceSets))
        set(Part::FaceSets);
    if (a.shadingOffsets != b.shadingOffsets)
        set(Part::ShadingOffsets);
    if (a.currentFrame != b.currentFrame)
        set(Part::Playhead);
    return parts;
}

/// What happened to one operation over a walk.
struct Tally {
    int runs = 0; ///< times tried
    int changed = 0; ///< times the data changed
    int refused = 0; ///< EditRefused or IoError (data checked unchanged)
    int empty = 0; ///< undo steps that changed nothing
    int merged = 0; ///< changes taken into the step on top instead of a new one
};

/// How a step is checked: an edit (or a brush stroke's begin, step, end) records the state at the
/// new undo index; undo and redo compare with the recorded states; the playhead changes nothing
/// else; a save changes nothing and must reopen equal.
enum class Kind { Edit, Undo, Redo, Playhead, Save, Stroke };

class Walk {
public:
    Walk(std::uint64_t seed, int steps)
        : m_seed(seed)
        , m_steps(steps)
        , m_rng(seed)
    {
        m_pngs = {pngBytes(8, 4, Qt::red), pngBytes(5, 9, Qt::darkGreen), pngBytes(3, 3, QColor(10, 20, 30, 128))};
        QObject::connect(
            &m_doc, &Document::changed, &m_doc, [this](const ChangeSet& c) { m_reported |= c.reset ? ~0u : c.parts; });
        defineOperations();
    }

    /// Runs the walk; false with failure() set on the first problem.
    bool run()
    {
        if (!m_dir.isValid())
            return fail(QStringLiteral("no temporary directory"));
        ProjectData start = newProject(walkMesh(2), QStringLiteral("icosphere.obj"));
        start.faceSets.push_back({"start patch", {0, 1, 2, 3, 10, 11}});
        m_doc.reset(std::move(start));
        // A few objects to start from, made by the document itself (then part of the original).
        m_doc.drawings().addDrawing(makeDrawing());
        m_doc.keys().createKey(QStringLiteral("front"), randomCamera(m_rng, false));
        m_doc.highlights().addHighlightLayer(QStringLiteral("shine"), 0);
        m_doc.reset(m_doc.data());
        m_original = m_doc.data();
        m_saved = m_original;
        m_states = {m_original};

        for (m_step = 0; m_step < m_steps; ++m_step)
            if (!step())
                return false;
        endStrokes();
        m_gesture.end();
        return finish();
    }

    [[nodiscard]] const QString& failure() const { return m_failure; }
    [[nodiscard]] const std::map<QString, Tally>& tallies() const { return m_tallies; }
    [[nodiscard]] int saves() const { return m_saves; }
    [[nodiscard]] int maxDepth() const { return m_maxDepth; }
    [[nodiscard]] int finalDepth() const { return m_finalDepth; }
    [[nodiscard]] int emptySteps() const { return m_emptySteps; }
    /// Brush steps by BrushMotion.
    [[nodiscard]] const std::array<int, 6>& motions() const { return m_motions; }

private:
    struct Operation {
        QString name;
        int weight;
        Kind kind;
        /// t picks the target (layer, key, name...), so that repeating an operation with the same
        /// target seed in a gesture edits the same thing; values come from the walk's generator.
        std::function<void(Rng& t)> run;
    };

    bool fail(const QString& message)
    {
        m_failure = QStringLiteral("seed %1, step %2 (%3): %4 (rerun with CELFORM_WALK_SEED=%1)")
                        .arg(m_seed)
                        .arg(m_step)
                        .arg(m_current.isEmpty() ? QStringLiteral("-") : m_current, message);
        return false;
    }

    QUndoStack* stack() const { return m_doc.undoStack(); }

    // --- choosing targets ------------------------------------------------------------------
    static constexpr ObjectId kBogusId = 987654;

    ObjectId anyDrawing(Rng& t) const
    {
        const auto& d = m_doc.data().drawings;
        return d.empty() || chance(t, 0.04) ? kBogusId : d[std::size_t(below(t, int(d.size())))].id;
    }
    ObjectId anyKey(Rng& t) const
    {
        const auto& k = m_doc.data().keys;
        return k.empty() || chance(t, 0.04) ? kBogusId : k[std::size_t(below(t, int(k.size())))].id;
    }
    ObjectId anyLayer(Rng& t) const
    {
        const auto& h = m_doc.data().look.highlights;
        return h.empty() || chance(t, 0.04) ? kBogusId : h[std::size_t(below(t, int(h.size())))].id;
    }
    QString anyFaceSet(Rng& t) const
    {
        const auto& s = m_doc.data().faceSets;
        if (s.empty() || chance(t, 0.15))
            return pickFrom(t, std::vector<QString>{QStringLiteral("ear"), QStringLiteral("鼻"), QStringLiteral("x")});
        return QString::fromStdString(s[std::size_t(below(t, int(s.size())))].name);
    }
    QString anyName(Rng& t) const
    {
        static const std::vector<QString> names{QStringLiteral("front"), QStringLiteral("side"),
            QStringLiteral("side 2"), QStringLiteral("three-quarter"), QStringLiteral("横顔"),
            QStringLiteral("  padded  "), QStringLiteral("shine"), QStringLiteral("ear"), QString(),
            QStringLiteral("   ")};
        return pickFrom(t, names);
    }
    static int anyFrame(Rng& t) { return pickFrom(t, std::vector<int>{0, 0, 5, 12, 24, -3}); }
    static double anyKeyFrame(Rng& t) { return pickFrom(t, std::vector<double>{0.0, 5.0, 12.5, 24.0, -3.0}); }
    std::uint32_t vertexCount() const
    {
        return m_doc.data().baseMesh ? std::uint32_t(m_doc.data().baseMesh->vertexCount()) : 0u;
    }
    int faceCount() const { return m_doc.data().baseMesh ? int(m_doc.data().baseMesh->faceCount()) : 0; }

    // --- making values -------------------------------------------------------------------------
    Drawing makeDrawing()
    {
        Drawing d;
        d.name = anyName(m_rng);
        d.imageFormat = QStringLiteral("png");
        d.imageData = pickFrom(m_rng, m_pngs);
        d.camera = randomCamera(m_rng, false);
        d.aligned = chance(m_rng, 0.5);
        d.opacity = uniform(m_rng, 0, 1);
        d.frame = anyFrame(m_rng);
        return d;
    }

    /// Valid sparse offsets: ascending indices below the vertex count, finite deltas.
    SparseOffsets randomOffsets(int maxCount)
    {
        SparseOffsets o;
        const std::uint32_t n = vertexCount();
        if (n == 0)
            return o;
        std::vector<std::uint32_t> picked;
        const int count = below(m_rng, maxCount + 1);
        for (int i = 0; i < count; ++i)
            picked.push_back(std::uint32_t(below(m_rng, int(n))));
        std::sort(picked.begin(), picked.end());
        picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
        for (std::uint32_t v : picked) {
            o.indices.push_back(v);
            o.deltas.emplace_back(uniformF(m_rng, -0.1, 0.1), uniformF(m_rng, -0.1, 0.1), uniformF(m_rng, -0.1, 0.1));
        }
        return o;
    }

    algo::ToonRamp randomRamp()
    {
        algo::ToonRamp ramp;
        const int tones = 2 + below(m_rng, 4);
        ramp.thresholds.clear();
        ramp.intensities.clear();
        for (int i = 0; i + 1 < tones; ++i)
            ramp.thresholds.push_back(uniformF(m_rng, -1, 1));
        std::sort(ramp.thresholds.begin(), ramp.thresholds.end());
        for (int i = 0; i < tones; ++i)
            ramp.intensities.push_back(uniformF(m_rng, 0, 1));
        if (chance(m_rng, 0.08))
            std::reverse(ramp.thresholds.begin(), ramp.thresholds.end()); // not ascending: invalid
        if (chance(m_rng, 0.04))
            ramp.intensities.pop_back(); // sizes do not match: invalid
        return ramp;
    }

    algo::GoochParams randomGooch()
    {
        algo::GoochParams g;
        g.preset = pickFrom(m_rng, std::vector<std::string>{"default", "auto", "white", "purple", "red", "custom"});
        g.ka = uniformF(m_rng, 0, 1);
        g.k1 = uniformF(m_rng, 0, 2);
        g.k2 = uniformF(m_rng, 0, 2);
        g.k3 = uniformF(m_rng, 0, 2);
        g.k4 = uniformF(m_rng, 0, 2);
        g.warm = randomColor(m_rng);
        g.cool = randomColor(m_rng);
        return g;
    }

    algo::HatchParams randomHatch()
    {
        return {uniformF(m_rng, 0.005, 0.1), uniformF(m_rng, -90, 90), uniformF(m_rng, 0.05, 0.95)};
    }

    algo::LineSettings randomLineSettings()
    {
        return {
            chance(m_rng, 0.5), chance(m_rng, 0.5), chance(m_rng, 0.5), chance(m_rng, 0.5), uniformF(m_rng, 5, 120)};
    }

    algo::LineStyle randomLineStyle()
    {
        algo::LineStyle s;
        s.color = randomColor(m_rng);
        s.outlineWidth = uniformF(m_rng, 0.5, 8);
        s.innerWidth = uniformF(m_rng, 0.5, 4);
        s.jitter = uniformF(m_rng, 0, 2);
        s.widthVariation = uniformF(m_rng, 0, 1);
        s.overshoot = uniformF(m_rng, 0, 5);
        s.seed = std::uint32_t(m_rng()); // any 32-bit seed
        return s;
    }

    StereoLook randomStereo()
    {
        StereoLook s;
        s.output = algo::StereoOutput(below(m_rng, 6));
        s.interocular = chance(m_rng, 0.3) ? 0.0 : uniform(m_rng, 0.01, 0.3);
        s.convergence = chance(m_rng, 0.3) ? 0.0 : uniform(m_rng, 1, 10);
        s.toeIn = chance(m_rng, 0.5);
        s.swapEyes = chance(m_rng, 0.5);
        if (chance(m_rng, 0.3))
            s.dubois.left(0, 1) = uniformF(m_rng, -0.5, 0.5);
        return s;
    }

    Light randomLight()
    {
        Light l;
        l.type = chance(m_rng, 0.7) ? LightType::Directional : LightType::Point;
        l.vector = chance(m_rng, 0.04) ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                       : Eigen::Vector3d(randomDirection(m_rng) * uniform(m_rng, 0.5, 5));
        return l;
    }

    Look randomLook()
    {
        Look l;
        l.style = ShadingStyle(below(m_rng, 4));
        for (int m = 0; m < 3; ++m)
            if (chance(m_rng, 0.3))
                l.materialStyles[m] = ShadingStyle(below(m_rng, 4));
        l.light = randomLight();
        l.backgroundColor = randomColor(m_rng);
        l.toon = randomRamp();
        l.toonEvaluation = algo::ToonEvaluation(below(m_rng, 3));
        l.subdivision = {below(m_rng, 4), below(m_rng, 4) - 1};
        l.gooch = randomGooch();
        l.hatch = randomHatch();
        l.showLines = chance(m_rng, 0.5);
        l.lines = randomLineSettings();
        l.lineStyle = randomLineStyle();
        l.stereo = randomStereo();
        if (chance(m_rng, 0.5))
            l.renderCamera = randomCamera(m_rng);
        HighlightTrack ignored; // setLook leaves the layers alone
        ignored.name = QStringLiteral("ignored");
        ignored.setKey(0, algo::HighlightLayer{});
        l.highlights.push_back(ignored);
        return l;
    }

    algo::HighlightOperation randomOperation()
    {
        using T = algo::HighlightOperationType;
        switch (below(m_rng, 5)) {
        case 0:
            return algo::HighlightOperation::translation(uniformF(m_rng, -0.5, 0.5), uniformF(m_rng, -0.5, 0.5));
        case 1:
            return algo::HighlightOperation::rotation(uniformF(m_rng, -180, 180));
        case 2:
            return algo::HighlightOperation::directionalScaling(uniformF(m_rng, 0, 1));
        case 3:
            return algo::HighlightOperation::split(uniformF(m_rng, 0, 0.5), uniformF(m_rng, 0, 0.5));
        default:
            return {T::Squaring, uniformF(m_rng, 0, 1), uniformF(m_rng, 1, 4)};
        }
    }

    /// A key layer: the layer's parameters with some changed, rarely out of the paper's range.
    algo::HighlightLayer randomLayer(algo::HighlightLayer layer)
    {
        if (chance(m_rng, 0.5))
            layer.shape.epsilon = uniformF(m_rng, 0.01, 0.3);
        if (chance(m_rng, 0.3))
            layer.color = randomColor(m_rng);
        if (chance(m_rng, 0.3))
            layer.offSpecularCut = uniformF(m_rng, -1, 1);
        for (auto& op : layer.shape.operations)
            if (chance(m_rng, 0.4)) {
                const algo::HighlightOperation fresh = randomOperation();
                if (fresh.type == op.type)
                    op = fresh;
            }
        if (chance(m_rng, 0.05))
            layer.shape.epsilon = chance(m_rng, 0.5) ? 0.f : 1.5f; // out of range: refused
        if (chance(m_rng, 0.03))
            layer.color.x() = -0.5f;
        return layer;
    }

    // --- the operations ------------------------------------------------------------------------
    void add(const QString& name, int weight, Kind kind, std::function<void(Rng&)> run)
    {
        m_operations.push_back({name, weight, kind, std::move(run)});
        m_totalWeight += weight;
    }

    void defineOperations()
    {
        Document& d = m_doc;
        Rng& r = m_rng;

        // Drawings.
        add("addDrawing", 4, Kind::Edit, [this, &d](Rng&) { d.drawings().addDrawing(makeDrawing()); });
        add("removeDrawing", 2, Kind::Edit, [this, &d](Rng& t) { d.drawings().removeDrawing(anyDrawing(t)); });
        add("renameDrawing", 3, Kind::Edit,
            [this, &d](Rng& t) { d.drawings().renameDrawing(anyDrawing(t), anyName(m_rng)); });
        add("setDrawingOpacity", 5, Kind::Edit, [this, &d, &r](Rng& t) {
            d.drawings().setDrawingOpacity(anyDrawing(t), uniform(r, -0.2, 1.2), m_gesture);
        });
        add("setDrawingCamera", 4, Kind::Edit,
            [this, &d, &r](Rng& t) { d.drawings().setDrawingCamera(anyDrawing(t), randomCamera(r), m_gesture); });

        // Keys.
        add("createKey", 5, Kind::Edit, [this, &d, &r](Rng& t) {
            std::vector<ObjectId> drawings;
            if (chance(r, 0.5))
                drawings.push_back(anyDrawing(t));
            // Now and then the camera of an existing key: a duplicate direction, refused.
            Camera camera = randomCamera(r);
            if (const KeyViewpoint* other = d.data().key(anyKey(t)); other && chance(r, 0.15))
                camera = other->camera;
            d.keys().createKey(anyName(t), camera, std::move(drawings), randomOffsets(6), anyFrame(t));
        });
        add("createKeyFromDrawing", 2, Kind::Edit,
            [this, &d](Rng& t) { d.keys().createKeyFromDrawing(anyDrawing(t)); });
        add("addKey", 1, Kind::Edit, [this, &d, &r](Rng& t) {
            KeyViewpoint key;
            key.name = anyName(t);
            key.direction = chance(r, 0.05) ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : randomDirection(r);
            key.camera = randomCamera(r, false);
            key.enabled = chance(r, 0.8);
            key.offsetsByFrame[anyFrame(t)] = randomOffsets(5);
            if (chance(r, 0.5))
                key.offsetsByFrame[anyFrame(t)] = randomOffsets(5);
            d.keys().addKey(std::move(key));
        });
        add("removeKey", 2, Kind::Edit, [this, &d](Rng& t) { d.keys().removeKey(anyKey(t)); });
        add("renameKey", 3, Kind::Edit, [this, &d](Rng& t) { d.keys().renameKey(anyKey(t), anyName(m_rng)); });
        add("setKeyEnabled", 3, Kind::Edit,
            [this, &d, &r](Rng& t) { d.keys().setKeyEnabled(anyKey(t), chance(r, 0.5)); });
        add("setKeyCamera", 3, Kind::Edit,
            [this, &d, &r](Rng& t) { d.keys().setKeyCamera(anyKey(t), randomCamera(r)); });
        add("linkKeyDrawing", 3, Kind::Edit,
            [this, &d, &r](Rng& t) { d.keys().linkKeyDrawing(anyKey(t), chance(r, 0.2) ? 0 : anyDrawing(t)); });
        add("setKeyDeformation", 5, Kind::Edit, [this, &d](Rng& t) {
            d.keys().setKeyDeformation(anyKey(t), anyFrame(t), randomOffsets(10), QStringLiteral("Set Offsets"));
        });
        add("importKeyDeformation", 1, Kind::Edit, [this, &d, &r](Rng& t) {
            // The key's shape at a frame with a few vertices moved, through a PLY file.
            const ObjectId id = anyKey(t);
            const int frame = anyFrame(t);
            const KeyViewpoint* key = d.data().key(id);
            if (!key || !d.data().baseMesh)
                return;
            algo::TriMesh shape = *d.data().baseMesh;
            shape.vertices = d.data().keyShape(*key, frame);
            for (const std::uint32_t v : randomOffsets(6).indices)
                shape.vertices.row(v) += Eigen::RowVector3f(uniformF(r, -0.1, 0.1), 0.f, uniformF(r, -0.1, 0.1));
            const QString path = m_dir.filePath(QStringLiteral("deformation.ply"));
            exportMesh(shape, path);
            d.keys().importKeyDeformation(id, importMesh(path), path, frame);
        });
        add("displaceKeyVertices", 8, Kind::Edit, [this, &d, &r](Rng& t) {
            const SparseOffsets step = randomOffsets(8);
            algo::Positions displacements(Eigen::Index(step.indices.size()), 3);
            for (std::size_t k = 0; k < step.indices.size(); ++k)
                displacements.row(Eigen::Index(k)) = step.deltas[k].transpose();
            std::vector<std::uint32_t> indices = step.indices;
            // Rarely a step the document must ignore: out of order, out of range, not finite.
            if (indices.size() > 1 && chance(r, 0.03))
                std::reverse(indices.begin(), indices.end());
            if (!indices.empty() && chance(r, 0.03))
                indices.back() = vertexCount() + 3;
            if (!indices.empty() && chance(r, 0.03))
                displacements(0, 0) = std::nanf("");
            d.keys().displaceKeyVertices(
                anyKey(t), anyFrame(t), indices, displacements, QStringLiteral("Displace"), m_gesture);
        });
        add("brushStroke", 8, Kind::Stroke, [this, &d, &r](Rng& t) {
            endStrokes();
            const ObjectId key = anyKey(t);
            const KeyViewpoint* k = d.data().key(key);
            const Camera camera = k && chance(r, 0.8) ? k->camera : randomCamera(r);
            const std::uint32_t picked = chance(r, 0.03) ? vertexCount() : std::uint32_t(below(r, int(vertexCount())));
            const double radius = chance(r, 0.03) ? -1.0 : uniform(r, 0.0, 0.9);
            m_stroke = d.keys().beginBrushStroke(
                key, anyFrame(t), picked, radius, camera, chance(r, 0.4) ? MirrorPlane::X : MirrorPlane::Off);
        });
        add("brushStep", 0, Kind::Stroke, [this, &d, &r](Rng&) {
            BrushStep step;
            step.motion = BrushMotion(below(r, 6));
            switch (step.motion) {
            case BrushMotion::Drag:
                step.a = uniform(r, -0.05, 0.05);
                step.b = uniform(r, -0.05, 0.05);
                break;
            case BrushMotion::Push:
                step.a = uniform(r, -0.05, 0.05);
                break;
            case BrushMotion::Rotate:
                step.a = uniform(r, -0.3, 0.3);
                break;
            case BrushMotion::Scale:
                step.a = uniform(r, 0.9, 1.1);
                break;
            case BrushMotion::Smooth:
            case BrushMotion::Relax:
                step.a = uniform(r, 0, 1);
                break;
            }
            m_motions[int(step.motion)] += 1;
            d.keys().applyBrushStroke(*m_stroke, step);
        });
        add("brushEnd", 0, Kind::Stroke, [this, &d](Rng&) {
            d.keys().endBrushStroke(*m_stroke);
            m_stroke.reset();
        });

        // Blend settings.
        add("setSharpness", 4, Kind::Edit, [this, &d, &r](Rng&) {
            d.look().setSharpness(chance(r, 0.05) ? -1.0
                    : chance(r, 0.03)             ? std::nan("")
                                                  : uniform(r, 0.1, 8),
                m_gesture);
        });
        add("setUnspecifiedMode", 2, Kind::Edit,
            [this, &d, &r](Rng&) { d.look().setUnspecifiedMode(UnspecifiedMode(below(r, 3)), m_gesture); });
        add("setTimeInterpolation", 2, Kind::Edit,
            [this, &d, &r](Rng&) { d.look().setTimeInterpolation(TimeInterpolation(below(r, 2)), m_gesture); });

        // The look, property by property.
        add("setShadingStyle", 3, Kind::Edit, [this, &d, &r](Rng& t) {
            d.look().setShadingStyle(ShadingStyle(below(r, 4)), below(t, 5) - 1, m_gesture);
        });
        add("setLight", 4, Kind::Edit, [this, &d](Rng&) { d.look().setLight(randomLight(), m_gesture); });
        add("setLightTrack", 2, Kind::Edit, [this, &d, &r](Rng&) {
            // issue 26: a light track of up to three keys (invalid lights are refused); with one,
            // setLight above keys the current frame.
            LightTrack track;
            for (int k = below(r, 4); k > 0; --k)
                track.setKey(below(r, 60) - 10, randomLight());
            d.look().setLightTrack(track, QStringLiteral("Set Light Track"));
        });
        add("setBackgroundColor", 2, Kind::Edit,
            [this, &d, &r](Rng&) { d.look().setBackgroundColor(randomColor(r), m_gesture); });
        add("setToonRamp", 2, Kind::Edit, [this, &d](Rng&) { d.look().setToonRamp(randomRamp(), m_gesture); });
        add("setToonEvaluation", 2, Kind::Edit,
            [this, &d, &r](Rng&) { d.look().setToonEvaluation(algo::ToonEvaluation(below(r, 3)), m_gesture); });
        add("setGooch", 2, Kind::Edit, [this, &d](Rng&) { d.look().setGooch(randomGooch(), m_gesture); });
        add("setHatch", 2, Kind::Edit, [this, &d](Rng&) { d.look().setHatch(randomHatch(), m_gesture); });
        add("setShowLines", 2, Kind::Edit, [this, &d, &r](Rng&) { d.look().setShowLines(chance(r, 0.5), m_gesture); });
        add("setLineSettings", 2, Kind::Edit,
            [this, &d](Rng&) { d.look().setLineSettings(randomLineSettings(), m_gesture); });
        add("setLineStyle", 2, Kind::Edit, [this, &d](Rng&) { d.look().setLineStyle(randomLineStyle(), m_gesture); });
        add("setStereo", 2, Kind::Edit, [this, &d](Rng&) { d.look().setStereo(randomStereo(), m_gesture); });
        add("setRenderCamera", 3, Kind::Edit, [this, &d, &r](Rng&) {
            d.look().setRenderCamera(
                chance(r, 0.2) ? std::optional<Camera>() : std::optional<Camera>(randomCamera(r)), m_gesture);
        });
        add("setSubdivision", 2, Kind::Edit, [this, &d, &r](Rng&) {
            // Now and then a level out of range, which is refused.
            d.look().setSubdivision({below(r, 5), below(r, 5) - 1}, m_gesture);
        });
        add("setLook", 2, Kind::Edit, [this, &d](Rng&) { d.look().setLook(randomLook()); });

        // Highlight layers.
        add("addHighlightLayer", 3, Kind::Edit,
            [this, &d](Rng& t) { d.highlights().addHighlightLayer(anyName(t), anyFrame(t)); });
        add("addHighlightPreset", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            d.highlights().addHighlightPreset(chance(r, 0.5) ? HighlightPreset::Window : HighlightPreset::Crescent,
                chance(r, 0.3) ? 0 : anyLayer(t), anyFrame(t));
        });
        add("removeHighlightLayer", 2, Kind::Edit,
            [this, &d](Rng& t) { d.highlights().removeHighlightLayer(anyLayer(t)); });
        add("renameHighlightLayer", 2, Kind::Edit,
            [this, &d](Rng& t) { d.highlights().renameHighlightLayer(anyLayer(t), anyName(m_rng)); });
        add("setHighlightKey", 6, Kind::Edit, [this, &d](Rng& t) {
            const ObjectId id = anyLayer(t);
            const double frame = anyKeyFrame(t);
            const HighlightTrack* track = d.data().highlight(id);
            d.highlights().setHighlightKey(
                id, frame, randomLayer(track ? track->layerAt(frame) : algo::HighlightLayer{}), m_gesture);
        });
        add("setHighlightKeys", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            const ObjectId id = anyLayer(t);
            const HighlightTrack* track = d.data().highlight(id);
            std::vector<algo::HighlightKey> keys;
            double frame = anyKeyFrame(t);
            const int count = below(r, 4); // 0 keys: refused
            for (int i = 0; i < count; ++i) {
                keys.push_back({frame, randomLayer(track ? track->layerAt(frame) : algo::HighlightLayer{})});
                frame += chance(r, 0.05) ? -1.0 : uniform(r, 0.5, 10);
            }
            d.highlights().setHighlightKeys(id, std::move(keys), QStringLiteral("Set Keys"), m_gesture);
        });
        add("removeHighlightKey", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            const ObjectId id = anyLayer(t);
            const HighlightTrack* track = d.data().highlight(id);
            d.highlights().removeHighlightKey(
                id, track && chance(r, 0.8) ? pickFrom(r, track->keys).frame : anyKeyFrame(t));
        });
        add("addHighlightOperation", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            d.highlights().addHighlightOperation(anyLayer(t), algo::HighlightOperationType(below(r, 5)));
        });
        add("moveHighlightOperation", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            d.highlights().moveHighlightOperation(anyLayer(t), below(r, 4), below(r, 5) - 2);
        });
        add("removeHighlightOperation", 1, Kind::Edit,
            [this, &d, &r](Rng& t) { d.highlights().removeHighlightOperation(anyLayer(t), below(r, 4) - 1); });
        add("highlightDrag", 6, Kind::Stroke, [this, &d](Rng& t) {
            endStrokes();
            m_highlightDrag = d.highlights().beginHighlightDrag(anyLayer(t), anyKeyFrame(t));
        });
        add("highlightDragStep", 0, Kind::Stroke, [this, &d, &r](Rng&) {
            const auto motion = HighlightMotion(below(r, 3));
            const double scale = motion == HighlightMotion::Rotate ? 100.0 : 0.3;
            d.highlights().applyHighlightDrag(
                *m_highlightDrag, {motion, uniform(r, -scale, scale), uniform(r, -0.2, 0.2)});
        });
        add("highlightDragEnd", 0, Kind::Stroke, [this, &d](Rng&) {
            d.highlights().endHighlightDrag(*m_highlightDrag);
            m_highlightDrag.reset();
        });
        add("setHighlightPatch", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            d.highlights().setHighlightPatch(anyLayer(t), chance(r, 0.2) ? QString() : anyFaceSet(t), m_gesture);
        });
        add("setHighlightGuide", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            d.highlights().setHighlightGuide(anyLayer(t),
                chance(r, 0.05) ? Eigen::Vector3f(Eigen::Vector3f::Zero())
                                : Eigen::Vector3f(randomDirection(r).cast<float>()),
                m_gesture);
        });
        add("setHighlightSmoothing", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            d.highlights().setHighlightSmoothing(anyLayer(t),
                chance(r, 0.05)       ? kMaxHighlightSmoothing + below(r, 3) - 1
                    : chance(r, 0.03) ? -1
                                      : below(r, 12),
                m_gesture);
        });
        add("setHighlightVisible", 2, Kind::Edit,
            [this, &d, &r](Rng& t) { d.highlights().setHighlightVisible(anyLayer(t), chance(r, 0.5)); });
        add("setHighlightCombinations", 2, Kind::Edit, [this, &d, &r](Rng& t) {
            const ObjectId id = anyLayer(t);
            std::vector<std::pair<algo::HighlightBoolean, QString>> combinations;
            const auto& layers = d.data().look.highlights;
            const int count = below(r, 3);
            for (int i = 0; i < count && !layers.empty(); ++i) {
                // Another layer mostly; itself or a missing name is refused.
                QString other = pickFrom(r, layers).name;
                if (chance(r, 0.05))
                    other = QStringLiteral("missing");
                combinations.emplace_back(
                    chance(r, 0.5) ? algo::HighlightBoolean::Union : algo::HighlightBoolean::Subtraction, other);
            }
            d.highlights().setHighlightCombinations(id, std::move(combinations), m_gesture);
        });

        // Face sets (highlight patches).
        auto randomFaces = [this, &r](int maxCount) {
            std::vector<std::int32_t> faces;
            const int count = below(r, maxCount + 1);
            for (int i = 0; i < count; ++i)
                faces.push_back(below(r, faceCount()));
            if (!faces.empty() && chance(r, 0.03))
                faces.back() = faceCount(); // out of range: refused
            return faces;
        };
        add("setFaceSet", 3, Kind::Edit, [this, &d, randomFaces](Rng& t) {
            d.faceSets().setFaceSet(chance(t, 0.05) ? QStringLiteral(" ") : anyFaceSet(t), randomFaces(20),
                QStringLiteral("Set Patch"), m_gesture);
        });
        add("faceSetStroke", 5, Kind::Stroke, [this, &d](Rng& t) {
            endStrokes();
            m_faceSetStroke = d.faceSets().beginFaceSetStroke(chance(t, 0.03) ? QStringLiteral(" ") : anyFaceSet(t));
        });
        add("faceSetDab", 0, Kind::Stroke, [this, &d, &r, randomFaces](Rng&) {
            d.faceSets().applyFaceSetStroke(*m_faceSetStroke, randomFaces(12), chance(r, 0.3));
        });
        add("faceSetStrokeEnd", 0, Kind::Stroke, [this, &d](Rng&) {
            d.faceSets().endFaceSetStroke(*m_faceSetStroke);
            m_faceSetStroke.reset();
        });
        add("removeFaceSet", 2, Kind::Edit, [this, &d](Rng& t) { d.faceSets().removeFaceSet(anyFaceSet(t)); });
        add("renameFaceSet", 2, Kind::Edit, [this, &d](Rng& t) {
            d.faceSets().renameFaceSet(anyFaceSet(t), chance(t, 0.5) ? anyName(m_rng) : anyFaceSet(m_rng));
        });
        add("newFaceSetForLayer", 2, Kind::Edit,
            [this, &d](Rng& t) { d.faceSets().newFaceSetForLayer(anyLayer(t), anyName(m_rng)); });

        // The base model: the same topology moved, fewer faces (patches go), more vertices, or
        // fewer vertices than the keys use (refused with IoError).
        add("setBaseMesh", 1, Kind::Edit, [&d, &r](Rng&) {
            switch (below(r, 4)) {
            case 0:
                d.setBaseMesh(walkMesh(2, uniformF(r, 0.8, 1.2)), QStringLiteral("scaled.obj"));
                break;
            case 1: {
                auto fewer = std::make_shared<algo::TriMesh>(*walkMesh(2));
                fewer->faces.conservativeResize(fewer->faceCount() - 20, 3);
                fewer->uvFaces.conservativeResize(fewer->faceCount(), 3);
                fewer->faceMaterials.resize(std::size_t(fewer->faceCount()));
                d.setBaseMesh(fewer, QStringLiteral("open.obj"));
                break;
            }
            case 2:
                d.setBaseMesh(walkMesh(3), QStringLiteral("finer.obj"));
                break;
            default:
                d.setBaseMesh(walkMesh(1), QStringLiteral("coarse.obj"));
                break;
            }
        });

        // The playhead, gestures, undo and redo, saves.
        add("setCurrentFrame", 4, Kind::Playhead, [&d, &r](Rng& t) {
            d.setCurrentFrame(chance(r, 0.02) ? (chance(r, 0.5) ? kMaxFrame : -kMaxFrame) : anyFrame(t));
        });
        add("beginGesture", 6, Kind::Edit, [this, &d](Rng&) { m_gesture = d.beginGesture(); });
        add("endGesture", 0, Kind::Edit, [this](Rng&) { m_gesture.end(); });
        add("undo", 14, Kind::Undo, [](Rng&) {});
        add("undoMany", 3, Kind::Undo, [](Rng&) {});
        add("redo", 7, Kind::Redo, [](Rng&) {});
        add("redoMany", 1, Kind::Redo, [](Rng&) {});
        add("saveCopy", 1, Kind::Save, [this, &r](Rng&) {
            // A copy (what autosave writes) leaves the clean state alone.
            const QString path = m_dir.filePath(QStringLiteral("copy.celform"));
            if (chance(r, 0.5))
                saveProject(m_doc.data(), path);
            else
                m_doc.saveCopy(path);
            m_lastSaved = path;
        });
        add("saveAs", 1, Kind::Save, [this](Rng&) {
            const QString path = m_dir.filePath(QStringLiteral("walk.celform"));
            m_doc.saveAs(path);
            m_lastSaved = path;
            m_saved = m_doc.data();
        });
    }

    /// Ends the open brush stroke, patch stroke and highlight drag.
    void endStrokes()
    {
        if (m_stroke)
            m_doc.keys().endBrushStroke(*m_stroke);
        if (m_faceSetStroke)
            m_doc.faceSets().endFaceSetStroke(*m_faceSetStroke);
        if (m_highlightDrag)
            m_doc.highlights().endHighlightDrag(*m_highlightDrag);
        m_stroke.reset();
        m_faceSetStroke.reset();
        m_highlightDrag.reset();
    }

    const Operation& byName(const QString& name) const
    {
        for (const Operation& op : m_operations)
            if (op.name == name)
                return op;
        Q_UNREACHABLE();
        return m_operations.front();
    }

    const Operation& choose(std::uint64_t& targetSeed)
    {
        targetSeed = m_rng();
        if (m_lastWasUndo && chance(m_rng, 0.35))
            return byName(chance(m_rng, 0.8) ? QStringLiteral("redo") : QStringLiteral("redoMany"));
        const QLatin1String open = m_stroke ? QLatin1String("brush")
            : m_faceSetStroke               ? QLatin1String("faceSet")
            : m_highlightDrag               ? QLatin1String("highlightDrag")
                                            : QLatin1String();
        if (!open.isEmpty()) {
            // While a brush (or the patch brush, or a highlight drag) is down: mostly its steps,
            // now and then anything else in between, a save among them (the clean state in the
            // middle of a stroke).
            static const std::map<QString, std::pair<QString, QString>> steps{
                {QStringLiteral("brush"), {QStringLiteral("brushStep"), QStringLiteral("brushEnd")}},
                {QStringLiteral("faceSet"), {QStringLiteral("faceSetDab"), QStringLiteral("faceSetStrokeEnd")}},
                {QStringLiteral("highlightDrag"),
                    {QStringLiteral("highlightDragStep"), QStringLiteral("highlightDragEnd")}}};
            const auto& [step, end] = steps.at(QString(open));
            const double x = unit(m_rng);
            if (x < 0.6)
                return byName(step);
            if (x < 0.75)
                return byName(end);
            if (x < 0.77)
                return byName(QStringLiteral("saveAs"));
        } else if (m_gesture.isOpen()) {
            // In a gesture: mostly the same edit on the same target again (a slider, a drag), so
            // steps merge; sometimes another edit; then the release.
            const double x = unit(m_rng);
            if (x < 0.12)
                return byName(QStringLiteral("endGesture"));
            if (x < 0.65 && m_lastEdit) {
                targetSeed = m_lastTarget;
                return *m_lastEdit;
            }
        }
        int pick = below(m_rng, m_totalWeight);
        for (const Operation& op : m_operations) {
            if (pick < op.weight) {
                if (op.name == QLatin1String("beginGesture") && m_gesture.isOpen())
                    return byName(QStringLiteral("endGesture"));
                // Keep the project small (the walk copies it at every step): past a few objects
                // of a kind, an addition becomes a removal.
                const ProjectData& d = m_doc.data();
                if ((op.name == QLatin1String("addDrawing") && d.drawings.size() >= 6))
                    return byName(QStringLiteral("removeDrawing"));
                if ((op.name == QLatin1String("createKey") || op.name == QLatin1String("addKey")
                        || op.name == QLatin1String("createKeyFromDrawing"))
                    && d.keys.size() >= 8)
                    return byName(QStringLiteral("removeKey"));
                if ((op.name == QLatin1String("addHighlightLayer") || op.name == QLatin1String("addHighlightPreset"))
                    && d.look.highlights.size() >= 8)
                    return byName(QStringLiteral("removeHighlightLayer"));
                if (op.name == QLatin1String("newFaceSetForLayer") && d.faceSets.size() >= 6)
                    return byName(QStringLiteral("removeFaceSet"));
                return op;
            }
            pick -= op.weight;
        }
        return m_operations.front();
    }

    bool undoOne()
    {
        if (!stack()->canUndo())
            return true;
        const int index = stack()->index();
        stack()->undo();
        if (stack()->index() != index - 1)
            return fail(QStringLiteral("undo did not step back"));
        if (!sameData(m_doc.data(), m_states[std::size_t(index - 1)]))
            return fail(QStringLiteral("undo to index %1 did not restore the data recorded there").arg(index - 1));
        return true;
    }

    bool redoOne()
    {
        if (!stack()->canRedo())
            return true;
        const int index = stack()->index();
        stack()->redo();
        if (stack()->index() != index + 1)
            return fail(QStringLiteral("redo did not step forward"));
        if (!sameData(m_doc.data(), m_states[std::size_t(index + 1)]))
            return fail(QStringLiteral("redo to index %1 did not restore the data recorded there").arg(index + 1));
        return true;
    }

    /// Reopens the file just saved and compares it with the document.
    bool checkReopen()
    {
        Document reopened;
        try {
            reopened.open(m_lastSaved);
        } catch (const IoError& e) {
            return fail(QStringLiteral("the saved file does not reopen: %1").arg(e.message()));
        }
        if (!(reopened.data() == m_doc.data())) {
            const std::uint32_t parts = differingParts(reopened.data(), m_doc.data());
            return fail(
                QStringLiteral("the reopened file differs from the document (parts 0x%1%2)")
                    .arg(parts, 0, 16)
                    .arg(reopened.data().nextId != m_doc.data().nextId ? QStringLiteral(", next id") : QString()));
        }
        if (reopened.isModified() || reopened.undoStack()->count() != 0)
            return fail(QStringLiteral("a reopened project starts with history or unsaved changes"));
        ++m_saves;
        return true;
    }

    bool step()
    {
        std::uint64_t targetSeed = 0;
        const Operation& op = choose(targetSeed);
        m_lastWasUndo = op.kind == Kind::Undo;
        m_current = op.name;
        Tally& tally = m_tallies[op.name];
        ++tally.runs;

        const ProjectData before = m_doc.data();
        const int index = stack()->index(), count = stack()->count();
        m_reported = 0;
        bool refused = false;
        Rng target(targetSeed);
        try {
            if (op.name == QLatin1String("undo") || op.name == QLatin1String("undoMany")) {
                const int n = op.name == QLatin1String("undo") ? 1 : 2 + below(m_rng, 9);
                for (int i = 0; i < n; ++i)
                    if (!undoOne())
                        return false;
            } else if (op.name == QLatin1String("redo") || op.name == QLatin1String("redoMany")) {
                const int n = op.name == QLatin1String("redo") ? 1 : 2 + below(m_rng, 9);
                for (int i = 0; i < n; ++i)
                    if (!redoOne())
                        return false;
            } else {
                op.run(target);
            }
        } catch (const EditRefused&) {
            refused = true;
        } catch (const IoError& e) {
            if (op.kind == Kind::Save)
                return fail(QStringLiteral("saving failed: %1").arg(e.message()));
            refused = true;
        }
        const ProjectData& after = m_doc.data();
        const std::uint32_t differing = differingParts(before, after);
        if (differing & ~m_reported)
            return fail(QStringLiteral("changed() did not report every part that changed (changed 0x%1, reported 0x%2)")
                            .arg(differing, 0, 16)
                            .arg(m_reported, 0, 16));

        if (refused) {
            ++tally.refused;
            if (!equalData(after, before, true))
                return fail(QStringLiteral("a refused edit changed the data"));
            if (stack()->index() != index || stack()->count() != count)
                return fail(QStringLiteral("a refused edit changed the undo history"));
            return checkClean();
        }
        const bool changed = !equalData(after, before, true);
        if (changed)
            ++tally.changed;

        switch (op.kind) {
        case Kind::Undo:
        case Kind::Redo:
            break; // checked step by step
        case Kind::Playhead:
            if (differing & ~std::uint32_t(Part::Playhead))
                return fail(QStringLiteral("moving the playhead changed more than the playhead"));
            if (stack()->index() != index || stack()->count() != count)
                return fail(QStringLiteral("moving the playhead made an undo step"));
            break;
        case Kind::Save:
            if (changed || stack()->index() != index || stack()->count() != count)
                return fail(QStringLiteral("saving changed the document or its history"));
            if (!checkReopen())
                return false;
            break;
        case Kind::Edit:
        case Kind::Stroke: {
            const bool historyMoved = stack()->index() != index || stack()->count() != count;
            if (!changed && !historyMoved)
                break; // a no-op (same value, missing target): nothing to record
            if (changed && stack()->index() != stack()->count())
                return fail(QStringLiteral("an edit left a redo branch behind"));
            if (!changed && stack()->index() > index) {
                ++m_emptySteps; // a step that changed nothing (reported, not an error)
                ++tally.empty;
            }
            const int now = stack()->index();
            if (changed && now == index && stack()->count() == count)
                ++tally.merged; // taken into the step on top (a gesture, a brush stroke)
            if (now < index && !sameData(after, m_states[std::size_t(now)]))
                return fail(QStringLiteral("a gesture that came back to its start does not match the state before"));
            m_states.resize(std::size_t(now));
            m_states.push_back(after);
            m_maxDepth = std::max(m_maxDepth, now);
            if (op.kind == Kind::Edit && changed) {
                m_lastEdit = &op;
                m_lastTarget = targetSeed;
            }
            break;
        }
        }
        if (m_states.size() != std::size_t(stack()->count()) + 1)
            return fail(QStringLiteral("the recorded states (%1) do not match the history (%2 steps)")
                            .arg(m_states.size())
                            .arg(stack()->count()));
        return checkClean();
    }

    /// A document that says it has no unsaved changes must hold what was saved last.
    bool checkClean()
    {
        if (stack()->cleanIndex() == stack()->index() && !sameData(m_doc.data(), m_saved))
            return fail(QStringLiteral("the document reports no unsaved changes but differs from its last save"));
        return true;
    }

    bool finish()
    {
        m_current = QStringLiteral("undo all");
        m_finalDepth = stack()->index();
        const ProjectData final = m_doc.data();
        while (stack()->canUndo())
            if (!undoOne())
                return false;
        m_doc.setCurrentFrame(m_original.currentFrame); // the playhead is not undoable
        if (!(m_doc.data() == m_original))
            return fail(QStringLiteral("undoing everything did not give the original project (parts 0x%1)")
                            .arg(differingParts(m_doc.data(), m_original), 0, 16));
        // Redoing up to where the walk ended gives its final project; when it ended after an
        // undo, the rest of the history redoes too.
        m_current = QStringLiteral("redo all");
        while (stack()->index() < m_finalDepth)
            if (!redoOne())
                return false;
        m_doc.setCurrentFrame(final.currentFrame);
        if (!(m_doc.data() == final))
            return fail(QStringLiteral("redoing everything did not give the final project (parts 0x%1)")
                            .arg(differingParts(m_doc.data(), final), 0, 16));
        while (stack()->canRedo())
            if (!redoOne())
                return false;
        // The final project survives a save and reopen too.
        m_lastSaved = m_dir.filePath(QStringLiteral("final.celform"));
        saveProject(m_doc.data(), m_lastSaved);
        return checkReopen();
    }

    std::uint64_t m_seed;
    int m_steps;
    Rng m_rng;
    QTemporaryDir m_dir;
    Document m_doc;
    std::vector<Operation> m_operations;
    int m_totalWeight = 0;
    std::vector<QByteArray> m_pngs;

    ProjectData m_original;
    ProjectData m_saved; ///< what the clean state holds
    std::vector<ProjectData> m_states; ///< the data at each undo index
    std::optional<BrushStroke> m_stroke;
    std::optional<FaceSetStroke> m_faceSetStroke;
    std::optional<HighlightDrag> m_highlightDrag;
    Gesture m_gesture; ///< the open gesture (slider drag, wheel burst) the edits are given
    const Operation* m_lastEdit = nullptr;
    std::uint64_t m_lastTarget = 0;
    QString m_lastSaved;
    std::uint32_t m_reported = 0;
    bool m_lastWasUndo = false;

    int m_step = 0;
    QString m_current;
    QString m_failure;
    std::map<QString, Tally> m_tallies;
    std::array<int, 6> m_motions{};
    int m_saves = 0;
    int m_maxDepth = 0;
    int m_finalDepth = 0;
    int m_emptySteps = 0;
};

std::uint64_t firstSeed()
{
    bool ok = false;
    const qulonglong seed = qEnvironmentVariable("CELFORM_WALK_SEED").toULongLong(&ok);
    return ok ? seed : kDefaultSeed;
}

} // namespace

class TestUndoWalk : public QObject {
    Q_OBJECT

private slots:
    // Two problems the walk found, pinned down on their own.

    void lineStyleSeedSurvivesTheFile()
    {
        // Any 32-bit seed the document takes must reopen (the reader once stopped at 2^31 - 1).
        QTemporaryDir dir;
        Document doc;
        doc.reset(newProject(walkMesh(1), QStringLiteral("sphere.obj")));
        algo::LineStyle style = doc.data().look.lineStyle;
        style.seed = 0xFFFFFFFFu;
        doc.look().setLineStyle(style);
        const QString path = dir.filePath(QStringLiteral("seed.celform"));
        doc.saveAs(path);
        Document reopened;
        QVERIFY_THROWS_NO_EXCEPTION(reopened.open(path));
        QCOMPARE(reopened.data().look.lineStyle.seed, 0xFFFFFFFFu);
        QVERIFY(reopened.data() == doc.data());
    }

    void saveInTheMiddleOfABrushStroke()
    {
        // The steps after a save are unsaved changes, and undo goes back to what was saved.
        QTemporaryDir dir;
        Document doc;
        doc.reset(newProject(walkMesh(2), QStringLiteral("sphere.obj")));
        Camera camera;
        camera.eye = Eigen::Vector3d(0, 0, 4);
        const ObjectId key = doc.keys().createKey(QStringLiteral("front"), camera);
        BrushStroke stroke = doc.keys().beginBrushStroke(key, 0, 0, 0.5, camera);
        doc.keys().applyBrushStroke(stroke, {BrushMotion::Drag, 0.05, 0.0});
        doc.saveAs(dir.filePath(QStringLiteral("stroke.celform")));
        const ProjectData saved = doc.data();
        doc.keys().applyBrushStroke(stroke, {BrushMotion::Drag, 0.05, 0.0});
        doc.keys().applyBrushStroke(stroke, {BrushMotion::Push, 0.02, 0.0});
        doc.keys().endBrushStroke(stroke);
        QVERIFY(!(doc.data() == saved));
        QVERIFY(doc.isModified());
        doc.undoStack()->undo();
        QVERIFY(!doc.isModified());
        QVERIFY(doc.data() == saved);
    }

    void walk_data()
    {
        QTest::addColumn<quint64>("seed");
        const std::uint64_t first = firstSeed();
        for (std::uint64_t s = first; s < first + 3; ++s)
            QTest::newRow(qPrintable(QStringLiteral("seed %1").arg(s))) << quint64(s);
    }

    void walk()
    {
        QFETCH(quint64, seed);
        bool ok = false;
        int steps = qEnvironmentVariableIntValue("CELFORM_WALK_STEPS", &ok);
        // Under the sanitizers (about 6x slower here) a third of the walk: the release build walks
        // it all, the sanitizers still see every kind of edit many times.
        if (!ok || steps <= 0)
            steps = celform::test::kAddressSanitizer ? kDefaultSteps / 3 : kDefaultSteps;
        QElapsedTimer timer;
        timer.start();
        Walk walk(seed, steps);
        const bool passed = walk.run();
        QVERIFY2(passed, qPrintable(walk.failure()));

        int changed = 0, refused = 0;
        for (const auto& [name, t] : walk.tallies()) {
            changed += t.changed;
            refused += t.refused;
        }
        qInfo("seed %llu: %d steps in %lld ms, %d changed the data, %d refused, %d saves reopened, history up to %d "
              "steps (%d at the end), %d empty steps",
            static_cast<unsigned long long>(seed), steps, static_cast<long long>(timer.elapsed()), changed, refused,
            walk.saves(), walk.maxDepth(), walk.finalDepth(), walk.emptySteps());
        if (qEnvironmentVariableIntValue("CELFORM_WALK_VERBOSE")) {
            for (const auto& [name, t] : walk.tallies())
                qInfo("  %-26s runs %5d  changed %5d  merged %4d  refused %4d  empty steps %d", qPrintable(name),
                    t.runs, t.changed, t.merged, t.refused, t.empty);
            const auto& m = walk.motions();
            qInfo("  brush motions: drag %d, push %d, rotate %d, scale %d, smooth %d", m[0], m[1], m[2], m[3], m[4]);
        }
    }
};

QTEST_GUILESS_MAIN(TestUndoWalk)
#include "test_undo_walk.moc"
