// Writing rendered frames: one pass or the beauty as PNG/TIFF/JPEG (8-bit sRGB) or EXR (linear
// float), and every pass as named channels of one EXR, through OpenImageIO.
#pragma once

#include "celform/algorithms/render.h"
#include "celform/algorithms/stereo.h"
#include "celform/model/data/project_data.h"

#include <QString>
#include <QStringList>

#include <string>
#include <vector>

namespace celform::model {

/// The renderer's view of the document's look (styles per material, light, tones, lines) at a
/// frame (the light track's light there, Look::lightAt). look may override the document's (a
/// render with --style or --light). shadingOffsets: the offsets in effect at the view and frame
/// (shading_layers.h, effectiveShadingOffsets; kept by the caller, empty for none); null means the
/// base layer alone.
algo::RenderLook renderLookFor(
    const ProjectData& data, const Look& look, const std::vector<float>* shadingOffsets, int frame);
/// The same at the document's current frame.
inline algo::RenderLook renderLookFor(
    const ProjectData& data, const Look& look, const std::vector<float>* shadingOffsets = nullptr)
{
    return renderLookFor(data, look, shadingOffsets, data.currentFrame);
}

/// The look's visible highlight tracks resolved at a frame for the renderer: keys interpolated,
/// combinations by name replaced by the other tracks' shapes at the same frame, patch face
/// masks (all faces for an empty patch), each track's smoothed normals over its patch when it asks
/// for smoothing, and per-vertex tangent frames of the shape (#V by 3) from the base model's UVs
/// when it has them, else from each track's guide over its patch (against the smoothed normals
/// where there are some). With a cache and the shape's generation (algo::Shape; 0: unknown, nothing
/// cached), the per-vertex geometry of a track whose shape, patch, guide and smoothing are
/// unchanged is reused (parameter edits, scrubbing a still shape) without looking at the positions.
std::vector<algo::RenderHighlight> renderHighlightsFor(const ProjectData& data, const Look& look,
    const algo::Positions& shape, int frame, algo::RenderCache* cache = nullptr, std::uint64_t shapeGeneration = 0);

/// The raster camera of a document camera for an image size.
algo::RasterCamera rasterCamera(const Camera& camera, int width, int height);

/// The stereo settings with "auto" distances resolved: convergence at the centroid's depth, eyes
/// a thirtieth of it apart.
algo::StereoSettings resolvedStereo(const StereoLook& stereo, const Camera& camera, const Eigen::Vector3d& centroid);

/// The passes of each eye of a frame of the shape: mono, the camera's alone; in stereo the left
/// and right eyes (their lines from the centre eye, paper 3, section 4.2.2), after the centre
/// camera's passes when withCentre. Arguments as renderShape's.
std::vector<algo::RenderPasses> renderEyes(const ProjectData& data, const Look& look, const algo::Positions& shape,
    int frame, const Camera& camera, int width, int height, algo::StereoOutput stereo, algo::RenderCache& cache,
    std::uint64_t shapeGeneration = 0, const std::vector<float>* shadingOffsets = nullptr, bool withCentre = false,
    const algo::Positions* vertexNormals = nullptr);

/// Renders a frame of the shape, mono or as a stereo composition (lines from the centre eye,
/// paper 3, section 4.2.2). For stereo only the beauty pass is composed; the other passes are
/// the centre eye's. frame selects the highlight keys; shapeGeneration as in renderHighlightsFor;
/// shadingOffsets as in renderLookFor; vertexNormals: the shape's normals to shade with (a
/// subdivided surface's limit normals), null for the faces' area-weighted ones.
algo::RenderPasses renderShape(const ProjectData& data, const Look& look, const algo::Positions& shape, int frame,
    const Camera& camera, int width, int height, algo::StereoOutput stereo, algo::RenderCache& cache,
    std::uint64_t shapeGeneration = 0, const std::vector<float>* shadingOffsets = nullptr,
    const algo::Positions* vertexNormals = nullptr);

/// The same into passes, whose buffers are reused when they have the size already (a sequence's
/// frames, issue 29). dataPasses false: the beauty, lines and strokes alone (algo::RenderLook).
void renderShape(const ProjectData& data, const Look& look, const algo::Positions& shape, int frame,
    const Camera& camera, int width, int height, algo::StereoOutput stereo, algo::RenderCache& cache,
    algo::RenderPasses& passes, std::uint64_t shapeGeneration = 0, const std::vector<float>* shadingOffsets = nullptr,
    const algo::Positions* vertexNormals = nullptr, bool dataPasses = true);

/// The pass names of `celform render --pass`.
QStringList renderPassNames();

/// A single pass as an image: beauty as is, scalar passes as grey, normals as 0.5 * n + 0.5 for
/// 8-bit files (raw in EXR), depth normalised to [0, 1] over the model for 8-bit files (raw in
/// EXR, 0 off the model), ids as distinct colours (raw in EXR). Throws IoError for a bad name.
algo::ImageRGBA passImage(const algo::RenderPasses& passes, const QString& pass, bool forFloatFile);
/// The same into image, whose storage is reused.
void passImage(const algo::RenderPasses& passes, const QString& pass, bool forFloatFile, algo::ImageRGBA& image);

/// An 8-bit image made ready for its file (encodeChannels): the values with their channel names,
/// apart from the buffers they came from, so that another thread can write it while the next
/// frame renders. Its buffers are reused from frame to frame.
struct EncodedFrame {
    int width = 0;
    int height = 0;
    std::vector<std::string> names;
    std::vector<unsigned char> bytes;
};

/// Checks path's suffix (png, tif, tiff, jpg, jpeg; else IoError naming it, an .exr too) and
/// quantises count interleaved floats of the named channels to 8 bits into out (sRGB-encoded
/// colour channels when encodeSrgb).
void encodeChannels(const QString& path, int width, int height, const std::vector<std::string>& names,
    const float* data, std::size_t count, bool encodeSrgb, EncodedFrame& out);

/// Writes an encoded image to path atomically (a temporary file beside it, closed, then renamed;
/// not synced to the disk). Throws IoError naming path.
void writeEncoded(const EncodedFrame& image, const QString& path);

/// Writes count interleaved floats of the named channels to path by its suffix, atomically: an EXR
/// straight from data, an 8-bit file through encodeChannels into scratch (whose buffers a
/// sequence reuses; null: made here) and writeEncoded. Throws IoError naming path.
void writeChannelsFile(const QString& path, int width, int height, const std::vector<std::string>& names,
    const float* data, std::size_t count, bool encodeSrgb, EncodedFrame* scratch = nullptr);

/// Writes an image by suffix (png, tif, tiff, jpg, jpeg, exr), atomically (temporary file beside
/// it, then a rename). Throws IoError naming the file.
void writeImage(const algo::ImageRGBA& image, const QString& path);

/// Writes width x height pixels of the named channels (interleaved floats) by suffix, atomically;
/// 8-bit formats take values in [0, 1], sRGB-encoded in the colour channels when encodeSrgb.
/// Throws IoError naming the file.
void writeImageChannels(const QString& path, int width, int height, const std::vector<std::string>& names,
    const std::vector<float>& data, bool encodeSrgb);

/// Why the file at path is not a whole image that can be read (empty, truncated, damaged), empty
/// when it is: `render --skip-existing` skips only such frames, and renders a frame cut short by an
/// earlier run (a full disk, a killed node) again. Decodes the file in this process.
QString incompleteImageProblem(const QString& path);

/// Writes every pass into one EXR with named channels: R G B A (beauty), lines.Y, tone.Y,
/// highlights.Y, depth.Z, normal.X normal.Y normal.Z, id.ID, read straight from passes (no copy of
/// them is made). Throws IoError.
void writePassesExr(const algo::RenderPasses& passes, const QString& path);

} // namespace celform::model
