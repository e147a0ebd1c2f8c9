// Everything a Celform project holds, as plain values (DESIGN.md, "The document"). The Document
// owns one ProjectData and changes it only through undo commands; file I/O reads and writes it.
#pragma once

#include "celform/algorithms/base_animation.h"
#include "celform/algorithms/highlights.h"
#include "celform/algorithms/lines.h"
#include "celform/algorithms/shading.h"
#include "celform/algorithms/stereo.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/camera.h"
#include "celform/model/data/camera_path.h"
#include "celform/model/data/light_track.h"
#include "celform/model/data/mirror_plane.h"
#include "celform/model/data/object_id.h"

#include <QByteArray>
#include <QImage>
#include <QString>

#include <cstdint>
#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace celform::model {

/// Sparse per-vertex offsets from the base model (paper 1, section 3.1.2: deformations touch
/// few vertices). indices are strictly increasing.
struct SparseOffsets {
    std::vector<std::uint32_t> indices;
    std::vector<Eigen::Vector3f> deltas;
    bool operator==(const SparseOffsets& o) const { return indices == o.indices && deltas == o.deltas; }

    /// The offset of a vertex, zero when it has none.
    [[nodiscard]] Eigen::Vector3f at(std::uint32_t index) const;
    /// Sets the offsets of the given vertices (indices ascending); present[i] == false removes
    /// vertex i's entry instead. Keeps indices ascending.
    void assign(const std::vector<std::uint32_t>& changed, const std::vector<Eigen::Vector3f>& values,
        const std::vector<char>& present);
    /// Offsets of the keyed shape from the base: every vertex whose position differs.
    static SparseOffsets difference(const algo::Positions& shape, const algo::Positions& base);
};

/// How a drawing's outline is extracted for Fit to Drawing (algo::OutlineSettings, the parts the
/// artist sets and the project saves with the drawing).
struct DrawingOutline {
    /// Ink where the luminance (0 black .. 1 white) is below this; negative: Otsu's threshold.
    double threshold = -1.0;
    /// Radius in pixels of the disc closing gaps of open line art (0 .. kMaxClosingRadius).
    double closingRadius = 2.0;
    /// Keep the drawing's inner lines: the holes the ink encloses stay open (off fills them and
    /// the outer outline alone remains).
    bool innerLines = false;
    /// 0: the largest figure only; > 0: every figure of at least this many pixels as well.
    int minComponentPixels = 0;

    static constexpr double kMaxClosingRadius = 64.0;
    bool operator==(const DrawingOutline& o) const
    {
        return threshold == o.threshold && closingRadius == o.closingRadius && innerLines == o.innerLines
            && minComponentPixels == o.minComponentPixels;
    }
    bool operator!=(const DrawingOutline& o) const { return !(*this == o); }
    /// The first problem of the values (a threshold above 1, a closing radius out of range, a
    /// negative size), empty when valid.
    [[nodiscard]] QString problem() const;
};

struct Drawing {
    ObjectId id = 0;
    QString name;
    QByteArray imageData; ///< the original file's bytes, embedded in the project
    QString imageFormat; ///< lower-case suffix of the original file: png, jpg, tif, exr, psd, svg
    QImage image; ///< decoded for display; not saved (rebuilt from imageData on load)
    Camera camera; ///< the camera aligned to the drawing
    bool aligned = false; ///< whether camera has been set by the artist
    double opacity = 0.5; ///< overlay opacity in the viewport
    int frame = 0;
    DrawingOutline outline; ///< how Fit to Drawing reads the drawing's outline

    /// Equality of the stored data (the decoded image is derived and not compared).
    bool operator==(const Drawing& o) const
    {
        return id == o.id && name == o.name && imageData == o.imageData && imageFormat == o.imageFormat
            && camera == o.camera && aligned == o.aligned && opacity == o.opacity && frame == o.frame
            && outline == o.outline;
    }
};

struct KeyViewpoint {
    ObjectId id = 0;
    QString name;
    Eigen::Vector3d direction{0.0, 0.0, 1.0}; ///< unit, from the base centroid towards the eye
    Camera camera;
    std::vector<ObjectId> drawingIds;
    std::map<int, SparseOffsets> offsetsByFrame; ///< key deformation per frame
    /// The key's layer of shading offsets (paper 3, eq. 4.3) per keyed frame, dense per vertex:
    /// added to the base layer with the key's blend weight (shading_layers.h).
    std::map<int, std::vector<float>> shadingOffsetsByFrame;
    bool enabled = true;

    bool operator==(const KeyViewpoint& o) const
    {
        return id == o.id && name == o.name && direction == o.direction && camera == o.camera
            && drawingIds == o.drawingIds && offsetsByFrame == o.offsetsByFrame
            && shadingOffsetsByFrame == o.shadingOffsetsByFrame && enabled == o.enabled;
    }
};

/// Paper 1, section 3.3: how views outside the hull of the key directions are filled.
enum class UnspecifiedMode { Dummy, Cosine, Cosine2 };
/// Paper 1, section 4.2: interpolation of key deformations over time.
enum class TimeInterpolation { NaturalSpline, PeriodicSpline };

/// The largest blend sharpness alpha a project holds: beyond it w^alpha underflows for weights
/// well inside a facet, and the blend is a switch between keys anyway.
constexpr double kMaxSharpness = 100.0;

struct BlendSettings {
    double sharpness = 1.0; ///< alpha of paper 1, section 3.2.2
    UnspecifiedMode unspecified = UnspecifiedMode::Dummy;
    TimeInterpolation time = TimeInterpolation::NaturalSpline;
    bool operator==(const BlendSettings& o) const
    {
        return sharpness == o.sharpness && unspecified == o.unspecified && time == o.time;
    }
    bool operator!=(const BlendSettings& o) const { return !(*this == o); }
};

enum class ShadingStyle { Lambert, Toon, Gooch, Comic };
/// Stereo settings of the look (paper 3, section 3.1). Distances of zero or less mean "auto":
/// convergence at the model's centre, interocular a thirtieth of the convergence distance.
struct StereoLook {
    algo::StereoOutput output = algo::StereoOutput::Anaglyph; ///< used when a preview asks for stereo
    double interocular = 0.0;
    double convergence = 0.0;
    bool toeIn = false;
    bool swapEyes = false;
    algo::DuboisMatrices dubois = algo::DuboisMatrices::redCyan();
    bool operator==(const StereoLook& o) const
    {
        return output == o.output && interocular == o.interocular && convergence == o.convergence && toeIn == o.toeIn
            && swapEyes == o.swapEyes && dubois.left == o.dubois.left && dubois.right == o.dubois.right;
    }
};

/// Gooch coefficients chosen per material by the paper's hue rules (preset name "auto").
inline algo::GoochParams autoGooch()
{
    algo::GoochParams g;
    g.preset = "auto";
    return g;
}

/// The largest frame number (either sign) a project, the playhead and the command line accept:
/// about 3.8 days at 24 frames per second, far from integer overflow in frame arithmetic.
constexpr int kMaxFrame = 8'000'000;

/// The most rounds of normal smoothing a highlight track may ask for.
constexpr int kMaxHighlightSmoothing = 1000;

/// One stylized highlight layer over time (Anjyo & Hiramitsu 2003, "Making highlight animation").
/// The keys' layers hold colour, shape and off-specular cut; their names and combinations are
/// unused: the track's name identifies it, and combineWith names other tracks whose shape at the
/// same frame is united with or subtracted from this one (resolved when rendering, so editing the
/// other track changes this one too).
struct HighlightTrack {
    ObjectId id = 0; ///< stable id, given by the document (0 until added)
    QString name; ///< unique among the look's tracks, not empty
    QString patch; ///< name of a face set of the base model; empty = all faces
    Eigen::Vector3f guide{0.0f, 1.0f, 0.0f}; ///< stroke direction for tangent frames without UVs
    bool visible = true; ///< false: drawn only as an operand of other tracks' combinations
    /// Rounds of normal smoothing over the patch (algo::smoothPatchNormals), in
    /// [0, kMaxHighlightSmoothing]; 0 = the surface's normals. Not keyed.
    int smoothing = 0;
    std::vector<std::pair<algo::HighlightBoolean, QString>> combineWith; ///< left to right
    std::vector<algo::HighlightKey> keys; ///< at least one, frames strictly increasing

    /// The key layer at a frame (interpolated, held outside the keys), combinations not resolved.
    [[nodiscard]] algo::HighlightLayer layerAt(double frame) const;
    /// Sets (replaces or inserts) the key at frame, keeping keys sorted.
    void setKey(double frame, const algo::HighlightLayer& layer);
    /// The translation (alpha, beta) of the layer at a frame along du and dv as they are before
    /// its operations (rotations earlier in the list turn the frame the stored values are in);
    /// zero without a translation.
    [[nodiscard]] Eigen::Vector2d translationAt(double frame) const;
    bool operator==(const HighlightTrack& o) const
    {
        return id == o.id && name == o.name && patch == o.patch && guide == o.guide && visible == o.visible
            && smoothing == o.smoothing && combineWith == o.combineWith && keys == o.keys;
    }
};

/// The first problem of a key's parameters, empty when valid: epsilon in (0, 1], colour
/// components in [0, 1], off-specular cut in [-1, 1], and each operation's parameters in the
/// paper's range (scaling delta and squaring sigma in [0, 1], split gammas >= 0, squaring n >= 1).
[[nodiscard]] QString highlightLayerProblem(const algo::HighlightLayer& layer);

/// The first problem of a look's highlight tracks, empty when valid: names unique and not empty,
/// at least one key per track with strictly increasing frames, valid keys, a non-zero guide,
/// smoothing in [0, kMaxHighlightSmoothing], combinations naming another existing track.
/// faceSetNames: the base model's face sets (a patch must name one of them).
[[nodiscard]] QString highlightTracksProblem(
    const std::vector<HighlightTrack>& tracks, const std::vector<QString>& faceSetNames);

/// Stable names of the operation types (file format and command line): translate, rotate,
/// scale, split, square; and the number of parameters each takes.
[[nodiscard]] QString highlightOperationName(algo::HighlightOperationType type);
[[nodiscard]] std::optional<algo::HighlightOperationType> highlightOperationType(const QString& name);
[[nodiscard]] int highlightOperationArity(algo::HighlightOperationType type);

/// The cartoon look (DESIGN.md, "Look"): shading style and parameters, lines, key light, stereo.
/// Loop subdivision of the displayed and rendered surface (issue 25; algo/subdivision.h).
struct SubdivisionLook {
    /// 0 (the control mesh) to algo::kMaxSubdivisionLevel: what `celform render`, the depth
    /// analysis and, by default, the viewport use.
    int level = 0;
    /// The viewport's level: -1 follows level; otherwise a lower level as a speed setting.
    int viewportLevel = -1;
    /// The level the viewport shows: viewportLevel when set, never above level.
    [[nodiscard]] int viewport() const { return viewportLevel < 0 ? level : std::min(viewportLevel, level); }
    bool operator==(const SubdivisionLook& o) const { return level == o.level && viewportLevel == o.viewportLevel; }
    bool operator!=(const SubdivisionLook& o) const { return !(*this == o); }
};

struct Look {
    ShadingStyle style = ShadingStyle::Toon;
    /// Per-material style (material index -> style); materials not listed use style.
    std::map<int, ShadingStyle> materialStyles;
    Light light; ///< the key light when lightTrack has no keys
    /// The shot's light over time (issue 26): when it has keys, the light at every frame, and
    /// light is not used (lightAt).
    LightTrack lightTrack;
    Eigen::Vector3f backgroundColor{0.93f, 0.93f, 0.91f};
    algo::ToonRamp toon;
    algo::ToonEvaluation toonEvaluation = algo::ToonEvaluation::PerPixel;
    algo::GoochParams gooch = autoGooch();
    algo::HatchParams hatch;
    bool showLines = true;
    algo::LineSettings lines;
    algo::LineStyle lineStyle;
    StereoLook stereo;
    SubdivisionLook subdivision;
    std::vector<HighlightTrack> highlights; ///< drawn in order, later over earlier
    /// The shot's camera: `celform render` looks through it unless told otherwise; none means a
    /// framed default view. Set from the editor's view (View menu) or `celform set --render-view`.
    std::optional<Camera> renderCamera;
    /// The shot's camera over time (camera_path.h); when it has keys, it is the render camera at
    /// every frame and renderCamera is not used.
    CameraPath cameraPath;

    /// The light at a frame: the light track's there, else the single light.
    [[nodiscard]] Light lightAt(double frame) const { return lightTrack.at(frame, light); }
    [[nodiscard]] ShadingStyle styleOf(int material) const
    {
        const auto it = materialStyles.find(material);
        return it == materialStyles.end() ? style : it->second;
    }
    bool operator==(const Look& o) const
    {
        return style == o.style && materialStyles == o.materialStyles && light == o.light && lightTrack == o.lightTrack
            && backgroundColor == o.backgroundColor && toon == o.toon && toonEvaluation == o.toonEvaluation
            && gooch == o.gooch && hatch == o.hatch && showLines == o.showLines && lines == o.lines
            && lineStyle == o.lineStyle && stereo == o.stereo && subdivision == o.subdivision
            && highlights == o.highlights && renderCamera == o.renderCamera && cameraPath == o.cameraPath;
    }
    bool operator!=(const Look& o) const { return !(*this == o); }
};

/// The first problem of subdivision levels (render 0-3; viewport -1 or 0-3), empty when valid.
[[nodiscard]] QString subdivisionProblem(const SubdivisionLook& subdivision);

/// The scene's time: frames per second and the frame range the timeline plays and a
/// sequence render or export covers by default. Frame F is at time F / fps.
struct SceneTime {
    double fps = 24.0; ///< in (0, kMaxFps]
    int firstFrame = 0;
    int lastFrame = 47; ///< >= firstFrame
    bool operator==(const SceneTime& o) const
    {
        return fps == o.fps && firstFrame == o.firstFrame && lastFrame == o.lastFrame;
    }
    bool operator!=(const SceneTime& o) const { return !(*this == o); }
};

/// The highest frame rate a project accepts.
constexpr double kMaxFps = 1000.0;

/// The first problem of a scene time, empty when valid.
[[nodiscard]] QString sceneTimeProblem(const SceneTime& time);

/// A face that keeps the segment the analysis finds for it (ProjectData::segmentOverrides).
constexpr std::int32_t kNoSegmentOverride = -1;

/// The first problem of per-face importance values for a model of faceCount faces (empty vector:
/// none painted), empty when they are sound.
[[nodiscard]] QString faceImportanceProblem(const std::vector<float>& importance, std::int64_t faceCount);
/// The same for segment overrides (labels at least 0, or kNoSegmentOverride).
[[nodiscard]] QString segmentOverridesProblem(const std::vector<std::int32_t>& overrides, std::int64_t faceCount);

struct ProjectData {
    std::shared_ptr<const algo::TriMesh> baseMesh; ///< shared, immutable: edits replace it whole
    /// The animated base (paper 1, section 4.1): null for a still base model. Same topology and
    /// vertex order as baseMesh, whose vertices are the rest pose it moves.
    std::shared_ptr<const algo::BaseAnimation> baseAnimation;
    QString baseMeshName; ///< file name the base model came from
    /// Named face sets of the base model: the highlight patches (paper 2 works patch by patch).
    /// Faces ascending without repeats, each below the base model's face count; names unique.
    std::vector<algo::FaceSet> faceSets;
    std::vector<Drawing> drawings;
    std::vector<KeyViewpoint> keys;
    BlendSettings blend;
    Look look;
    /// Per-vertex shading offsets O_v added to N.L before the toon tones (paper 3, equation 4.3);
    /// empty means all zero. The base layer: every view and frame; keys add their own layers
    /// (KeyViewpoint::shadingOffsetsByFrame, combined by shading_layers.h).
    std::vector<float> shadingOffsets;
    /// The artist's say over the depth analysis (paper 3, 6.2; issue 26), both per face of the
    /// base model, empty when never painted:
    /// - faceImportance: how much each face matters to the light optimisation, in [0, 1] (empty:
    ///   all 1). A segment's weight is multiplied by the mean importance of its faces (focal points).
    /// - segmentOverrides: a label per face, or kNoSegmentOverride. Faces with the same label form
    ///   one segment of the analysis, whatever their curvature and depth (the segment brush's
    ///   merges and splits); faces without one are segmented as the thesis does.
    std::vector<float> faceImportance;
    std::vector<std::int32_t> segmentOverrides;
    /// The plane the brushes mirror across when their mirror is on: detected when the model is
    /// imported (newProject), saved with the project.
    MirrorPlane mirrorPlane = MirrorPlane::X;
    ObjectId nextId = 1;
    /// The playhead (DESIGN.md, "The document"): the frame every view shows. Saved with the
    /// project, not undoable.
    int currentFrame = 0;
    /// Frames per second and the frame range.
    SceneTime time;

    /// The base model's vertices at a frame: baseMesh's own when the base is still (no copy,
    /// scratch untouched), else the animation evaluated into scratch. Needs a base mesh.
    [[nodiscard]] const algo::Positions& basePositions(int frame, algo::Positions& scratch) const;
    /// One vertex of the base at a frame (cheap: for brushes that touch few vertices).
    [[nodiscard]] Eigen::Vector3f baseVertex(int frame, Eigen::Index vertex) const;
    /// Mean of the base's vertex positions at a frame (DESIGN.md, "View direction").
    [[nodiscard]] Eigen::Vector3d baseCentre(int frame) const;
    [[nodiscard]] bool animated() const { return baseAnimation && !baseAnimation->empty(); }

    [[nodiscard]] const Drawing* drawing(ObjectId id) const;
    [[nodiscard]] Drawing* drawing(ObjectId id);
    [[nodiscard]] const KeyViewpoint* key(ObjectId id) const;
    [[nodiscard]] KeyViewpoint* key(ObjectId id);
    [[nodiscard]] const KeyViewpoint* keyByName(const QString& name) const;
    [[nodiscard]] const Drawing* drawingByName(const QString& name) const;
    [[nodiscard]] const HighlightTrack* highlight(ObjectId id) const;
    [[nodiscard]] HighlightTrack* highlight(ObjectId id);
    [[nodiscard]] const HighlightTrack* highlightByName(const QString& name) const;
    [[nodiscard]] const algo::FaceSet* faceSet(const QString& name) const;
    [[nodiscard]] std::vector<QString> faceSetNames() const;

    /// A key's offsets at a frame (paper 1, section 4.2; DESIGN.md, "Time"): a keyed frame's own
    /// offsets; between and around keyed frames, every vertex's offset interpolated over the keyed
    /// frames by algo::splineWeights (natural cubic, held outside the keyed range, or periodic for
    /// looping cycles), a vertex missing from a keyed frame counting as zero there.
    struct FrameOffsets {
        const SparseOffsets* stored = nullptr; ///< a keyed frame's own offsets (not copied)
        SparseOffsets interpolated; ///< otherwise
        [[nodiscard]] const SparseOffsets* get() const { return stored ? stored : &interpolated; }
    };
    [[nodiscard]] static FrameOffsets offsetsAt(const KeyViewpoint& key, int frame, TimeInterpolation time);
    /// The same into out, reusing its storage (no allocation once it has grown).
    static void offsetsAt(const KeyViewpoint& key, int frame, TimeInterpolation time, FrameOffsets& out);
    /// Base model plus a key's offsets at a frame (#V by 3), with the project's time
    /// interpolation. Needs a base mesh.
    [[nodiscard]] algo::Positions keyShape(const KeyViewpoint& key, int frame) const;
    /// Recomputes only the given rows (ascending) of a key's shape at a frame, as keyShape()
    /// computes them: after a change of those vertices' offsets, O(k log n) instead of O(#V).
    void updateKeyShape(
        const KeyViewpoint& key, int frame, const std::vector<std::uint32_t>& vertices, algo::Positions& shape) const;
    /// The weights of a key's keyed frames at a frame (paper 1, section 4.2), in keyed-frame
    /// order: the interpolated offset of a vertex is the weighted sum of its keyed offsets.
    [[nodiscard]] std::vector<double> keyFrameWeights(const KeyViewpoint& key, int frame) const;

    /// Equal stored data, mesh compared by value (used by tests and the save/load round trip).
    bool operator==(const ProjectData& o) const;
};

/// A new project on a base model, with the look's lengths (hatch spacing) scaled to the model.
ProjectData newProject(std::shared_ptr<const algo::TriMesh> mesh, const QString& meshName);

} // namespace celform::model
