// Fit to Drawing on the project's data: a drawing's outline read with the settings saved with it,
// and the key camera and the key's shape fitted to it (algorithms/fit_camera.h, fit_shape.h; paper
// 1, section 3.1 and its first future work, "semi-automatic alignment and deformation based on
// feature correspondence"). These are long solves run off the GUI thread: each returns a result
// that the document applies as one undo step (KeyEdits::applyFittedCamera, applyFittedShape), so
// the editor, the command line and the tests share one path.
#pragma once

#include "celform/algorithms/fit_metrics.h"
#include "celform/algorithms/outline.h"
#include "celform/algorithms/progress.h"
#include "celform/model/data/project_data.h"

#include <QColor>
#include <QImage>
#include <QString>

#include <cstdint>
#include <vector>

namespace celform::model {

/// A decoded drawing as the outline extraction reads it: 8-bit RGBA, not premultiplied.
algo::DrawingImage drawingPixels(const QImage& image);

/// The extraction settings of a drawing's saved outline settings.
algo::OutlineSettings outlineSettings(const DrawingOutline& outline);

/// The drawing's outline with its saved settings; error EmptyImage when its image is not decoded.
algo::Outline drawingOutline(const Drawing& drawing);

/// The outline as the artist checks it: the filled figure tinted, its contours (holes included)
/// stroked in colour penWidth drawing pixels wide, on a transparent image of the drawing's size
/// (ARGB32 premultiplied); null when the outline failed. The editor's outline mode and `celform
/// outline` show this.
QImage outlineImage(const algo::Outline& outline, const QColor& colour, double penWidth);

/// Why the outline of a drawing failed, as a sentence naming the drawing (translated); empty when
/// the outline is sound.
QString outlineProblem(const Drawing& drawing, const algo::Outline& outline);

/// The key and drawing a fit works on: the key's linked drawing given by id (0: its first link).
/// Throws EditRefused with a sentence naming the problem (no such key, no linked drawing, a
/// drawing that is not the key's).
const Drawing& fitDrawing(const ProjectData& data, const KeyViewpoint& key, ObjectId drawingId);

struct CameraFit {
    bool ok = false;
    bool cancelled = false;
    QString error; ///< translated, when neither ok nor cancelled
    Camera before; ///< the camera the fit started from
    Camera after; ///< the fitted camera (before when not ok)
    algo::FitMetrics metricsBefore; ///< full-resolution figures against the outline
    algo::FitMetrics metricsAfter;
    int iterations = 0;
};

/// Fit Camera to Drawing: starting from the drawing's aligned camera (else the key's), the
/// rotation, position and field of view (orthographic: height) for which the model's silhouette
/// meets the drawing's outline. The model is the key's shape at the drawing's frame when keyId is
/// not 0, else the (animated) base there. Apply with KeyEdits::applyFittedCamera.
CameraFit fitCameraToDrawing(
    const ProjectData& data, ObjectId drawingId, ObjectId keyId, algo::Progress* progress = nullptr);

/// What Fit Shape to Drawing may change.
struct ShapeFitRequest {
    QString regionFaceSet; ///< the faces that may move; empty: the whole model
    QString pinFaceSet; ///< the vertices of these faces stay fixed; empty: none
    bool mirror = false; ///< the brush's mirror, across the project's plane (ProjectData::mirrorPlane)
    double strength = 1.0; ///< in [0, 1]
    int maxRounds = 10;
};

struct ShapeFit {
    bool ok = false;
    bool cancelled = false;
    QString error; ///< translated, when neither ok nor cancelled
    int frame = 0; ///< the drawing's frame: where the deformation goes
    /// Displacements of the key's shape at frame: the vertices that move (ascending) and their
    /// offsets (#indices by 3), for KeyEdits::applyFittedShape.
    std::vector<std::uint32_t> indices;
    algo::Positions displacements;
    algo::FitMetrics metricsBefore;
    algo::FitMetrics metricsAfter;
    int rounds = 0;
};

/// Fit Shape to Drawing: the key's shape at the drawing's frame deformed, seen from the key's
/// camera, until its silhouette meets the drawing's outline.
ShapeFit fitShapeToDrawing(const ProjectData& data, ObjectId keyId, ObjectId drawingId,
    const ShapeFitRequest& request = {}, algo::Progress* progress = nullptr);

/// The key's figures against a drawing's outline (already extracted): its shape at the drawing's
/// frame, seen from the key's camera, the control mesh's silhouette. For the live panel: keep the
/// scratch between calls.
algo::FitMetrics keyFitMetrics(const ProjectData& data, const KeyViewpoint& key, const Drawing& drawing,
    const algo::Outline& outline, algo::FitScratch* scratch = nullptr);

} // namespace celform::model
