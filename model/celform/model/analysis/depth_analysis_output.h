// The depth analysis as pictures and files: the segment, curvature and depth-error pictures the
// editor overlays and `celform render --pass` writes, and the EXR of `celform analyze --out`.
#pragma once

#include "celform/algorithms/curvature.h"
#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/image.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace celform::model {

struct FrameAnalysis;

enum class AnalysisPicture {
    Segments, ///< one colour per segment (thesis figures 5.1-5.7)
    Curvature, ///< Gaussian curvature, orange positive, blue negative (figure 4.5)
    DepthError, ///< perceived - actual depth: blue perceived farther, orange nearer (figure 4.17)
};

/// "segments", "curvature", "depth-error": the render passes of the analysis.
QStringList analysisPassNames();
std::optional<AnalysisPicture> analysisPictureFromName(const QString& name);

/// The colour of segment id (linear RGB): hues spread by the golden angle, so neighbours differ.
Eigen::Vector3f segmentColor(int id);

/// A picture of the analysis, width x height. For 8-bit files and overlays: colours over
/// transparent pixels (alpha 0) off the model and, for segments, on dropped pixels; the diverging
/// pictures are light grey at zero and saturate at *scale (returned when not null): for curvature
/// the shape's (DepthAnalysis::curvatureScale), for the depth error the 98th percentile of |error|
/// over the model's pixels. For float files (forFloatFile): the raw values in R, G and B
/// (segment ids, -1 where transparent; curvature; depth error), alpha 1 on the model.
algo::ImageRGBA analysisImage(
    const algo::DepthAnalysis& analysis, AnalysisPicture picture, bool forFloatFile, float* scale = nullptr);

/// Writes the picture and the analysis buffers as one EXR: R G B A (the picture analysed),
/// curvature.K, segment.ID (-1 transparent), depth.Z (0 off the model), depth_error.Z, feature.Y.
/// Throws IoError naming the file.
void writeAnalysisExr(const FrameAnalysis& frame, const QString& path);

/// Writes shape with its faces as a binary PLY whose vertices carry, besides x y z, the float
/// properties k1 and k2 (principal curvatures, k1 >= k2), K (k1 k2) and K_smooth (K averaged over
/// the one-ring by Voronoi area, what the segments use). Atomic; throws IoError naming the file.
void writeCurvaturePly(
    const algo::Positions& shape, const algo::Faces& faces, const algo::Curvatures& curvature, const QString& path);

} // namespace celform::model
