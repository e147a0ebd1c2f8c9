// Exporting the view-dependent model's animation for other tools: every frame
// of a range evaluated by FrameEvaluator through the shot's camera, as `celform eval` and the
// renderer see it, written as a glTF 2.0 scene (text or binary), a PC2 point cache, a sequence
// of OBJ meshes or a time-sampled USD layer (text). docs/export.md describes what each format holds.
#pragma once

#include "celform/algorithms/progress.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/output_file.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace celform::model {

struct SubdividedSurface;

enum class ExportFormat { Gltf, Glb, Pc2, ObjSequence, Usda };

/// The command line's names of the formats: gltf, glb, pc2, obj-seq, usda.
[[nodiscard]] QString exportFormatName(ExportFormat format);
[[nodiscard]] std::optional<ExportFormat> exportFormatFromName(const QString& name);
/// Every format, in the order of exportFormatName's list.
[[nodiscard]] std::vector<ExportFormat> exportFormats();

/// The aspect ratio of the camera framed for a project without a camera path or render camera:
/// the default render size's (1280 x 720), so an export sees what `celform eval` and
/// `celform render` see.
constexpr double kExportAspect = 1280.0 / 720.0;

struct ExportJob {
    ExportFormat format = ExportFormat::Pc2;
    int firstFrame = 0;
    int lastFrame = 0; ///< >= firstFrame
    /// The file; for an OBJ sequence a pattern: a run of # is the zero-padded frame number,
    /// without one "_FFFF" goes before the suffix (as a rendered sequence names its files).
    QString output;
    double aspect = kExportAspect;
    /// Loop subdivision level of the exported surface (0-3; PC2, OBJ sequences and USD). 0, the
    /// default, keeps the base model's vertices and their order.
    int subdivision = 0;
    /// USD only: the enabled keys as UsdSkelBlendShapes with their weights animated (as glTF's
    /// morph targets); the mesh's points then hold the shape without them (subdivision 0 only).
    bool blendShapes = false;

    [[nodiscard]] int frameCount() const { return lastFrame - firstFrame + 1; }
    /// The file frame f goes to (the output itself for a one-file format).
    [[nodiscard]] QString framePath(int frame) const;
};

/// The first problem of a job, empty when valid: a frame range within +-kMaxFrame, first <= last,
/// an output named.
[[nodiscard]] QString exportJobProblem(const ExportJob& job);

struct ExportResult {
    int frames = 0; ///< frames evaluated and written
    bool cancelled = false;
    /// Translated notes on what the format could not carry (a skinned base in glTF).
    QStringList warnings;
    QStringList files; ///< the files written
};

/// Exports a project's frames. source names the project in errors. progress counts the frames
/// as they are evaluated and is asked before each whether to stop: then the file being written
/// is dropped (a one-file format leaves no file; an OBJ sequence keeps the frames already
/// written). Throws IoError naming the project (no base model, keys that cannot be blended, a
/// bad job) or the file that could not be written.
ExportResult exportProject(
    const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress = nullptr);

namespace exporting {

/// The frames of a job as every format walks them: the evaluator prepared once, then each frame
/// evaluated through the camera at that frame (cameraAtFrame), progress reported, cancel asked.
class FrameWalk {
public:
    FrameWalk(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress);
    /// Evaluates the next frame; false when the range is done or the export was cancelled.
    bool next();
    [[nodiscard]] int frame() const { return m_frame; }
    [[nodiscard]] const Camera& camera() const { return m_camera; }
    [[nodiscard]] const FrameEvaluator& evaluator() const { return m_evaluator; }
    /// The frame's shape at the job's subdivision level (the evaluator's at level 0).
    [[nodiscard]] const algo::Positions& shape() const { return m_surface ? m_subdivided : m_evaluator.shape(); }
    /// The faces of shape() and its vertex count.
    [[nodiscard]] const algo::Faces& faces() const;
    /// The mesh at the job's subdivision level (the base model at level 0): faces, UVs.
    [[nodiscard]] const algo::TriMesh& mesh() const;
    [[nodiscard]] Eigen::Index vertexCount() const;
    [[nodiscard]] bool cancelled() const { return m_cancelled; }
    [[nodiscard]] int done() const { return m_done; }

private:
    const ProjectData& m_data;
    const ExportJob& m_job;
    algo::Progress* m_progress;
    FrameEvaluator m_evaluator;
    std::shared_ptr<const SubdividedSurface> m_surface; ///< null at level 0
    algo::Positions m_subdivided;
    Camera m_camera;
    int m_frame = 0;
    int m_done = 0;
    bool m_cancelled = false;
};

/// Ends a one-file format's atomic write: dropped when cancelled (no file left), else committed
/// (an IoError naming the file when that fails) and listed in result.
void finishFile(OutputFile& file, bool cancelled, ExportResult& result);

void writePc2(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result);
void writeObjSequence(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result);
void writeGltf(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result);
void writeUsda(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result);

} // namespace exporting

} // namespace celform::model
