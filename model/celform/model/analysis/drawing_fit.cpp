// Fit to Drawing on the project's data: the model's pieces gathered for the fits of the algorithms
// layer and their results turned back into document cameras and displacements.
#include "celform/model/analysis/drawing_fit.h"

#include "celform/algorithms/fit_camera.h"
#include "celform/algorithms/fit_shape.h"
#include "celform/model/data/io_error.h"
#include "celform/model/render/render_output.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cstring>

namespace celform::model {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("celform::model::DrawingFit", text);
}

Camera documentCamera(const algo::RasterCamera& r)
{
    Camera c;
    c.eye = r.eye;
    c.target = r.target;
    c.up = r.up;
    c.projection = r.orthographic ? Projection::Orthographic : Projection::Perspective;
    c.fovYDegrees = r.fovYDegrees;
    c.orthoHeight = r.orthoHeight;
    return c;
}

/// The outline of the drawing, or the sentence why there is none.
algo::Outline checkedOutline(const Drawing& drawing, QString& error)
{
    algo::Outline outline = drawingOutline(drawing);
    error = outlineProblem(drawing, outline);
    return outline;
}

/// The vertices of a face set's faces, ascending.
std::vector<std::int32_t> faceSetVertices(const algo::TriMesh& mesh, const algo::FaceSet& set)
{
    std::vector<char> used(std::size_t(mesh.vertexCount()), 0);
    for (std::int32_t f : set.faces)
        for (int c = 0; c < 3; ++c)
            used[std::size_t(mesh.faces(f, c))] = 1;
    std::vector<std::int32_t> vertices;
    for (std::size_t v = 0; v < used.size(); ++v)
        if (used[v])
            vertices.push_back(std::int32_t(v));
    return vertices;
}

} // namespace

algo::DrawingImage drawingPixels(const QImage& image)
{
    algo::DrawingImage out;
    if (image.isNull())
        return out;
    const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
    out.width = rgba.width();
    out.height = rgba.height();
    out.channels = 4;
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * 4);
    const std::size_t rowBytes = std::size_t(out.width) * 4;
    for (int y = 0; y < out.height; ++y)
        std::memcpy(out.pixels.data() + std::size_t(y) * rowBytes, rgba.constScanLine(y), rowBytes);
    return out;
}

algo::OutlineSettings outlineSettings(const DrawingOutline& outline)
{
    algo::OutlineSettings s;
    s.threshold = outline.threshold;
    s.closingRadius = outline.closingRadius;
    s.fillHoles = !outline.innerLines;
    s.minComponentPixels = outline.minComponentPixels;
    return s;
}

algo::Outline drawingOutline(const Drawing& drawing)
{
    return algo::extractOutline(drawingPixels(drawing.image), outlineSettings(drawing.outline));
}

QImage outlineImage(const algo::Outline& outline, const QColor& colour, double penWidth)
{
    if (!outline.ok() || outline.width <= 0 || outline.height <= 0)
        return {};
    QPainterPath path;
    path.setFillRule(Qt::OddEvenFill);
    for (const auto& contour : outline.contours) {
        if (contour.empty())
            continue;
        path.moveTo(contour.front().x(), contour.front().y());
        for (std::size_t i = 1; i < contour.size(); ++i)
            path.lineTo(contour[i].x(), contour[i].y());
        path.closeSubpath();
    }
    QImage image(outline.width, outline.height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QColor tint = colour;
    tint.setAlpha(60);
    painter.fillPath(path, tint);
    painter.strokePath(path, QPen(colour, penWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    return image;
}

QString outlineProblem(const Drawing& drawing, const algo::Outline& outline)
{
    switch (outline.error) {
    case algo::OutlineError::None:
        return {};
    case algo::OutlineError::EmptyImage:
        return tr("The drawing “%1” has no image to read an outline from.").arg(drawing.name);
    case algo::OutlineError::NothingFound:
        return tr("The drawing “%1” is all one tone: no figure stands out from the paper. Set the outline "
                  "threshold by hand.")
            .arg(drawing.name);
    case algo::OutlineError::NoClosedOutline:
        return tr("The drawing “%1” has no closed outline: its lines never enclose the figure. Raise the "
                  "closing radius to bridge the gaps.")
            .arg(drawing.name);
    case algo::OutlineError::TouchesBorder:
        return tr("The figure in the drawing “%1” touches the image border, so its outline is cut off by the "
                  "frame. Use a drawing with paper around the character.")
            .arg(drawing.name);
    }
    return {};
}

const Drawing& fitDrawing(const ProjectData& data, const KeyViewpoint& key, ObjectId drawingId)
{
    if (drawingId == 0) {
        for (ObjectId id : key.drawingIds)
            if (const Drawing* d = data.drawing(id))
                return *d;
        throw EditRefused(
            tr("The key “%1” is not linked to a drawing. Link it to the drawing to fit first.").arg(key.name));
    }
    const Drawing* drawing = data.drawing(drawingId);
    if (!drawing)
        throw EditRefused(tr("The drawing to fit no longer exists."));
    if (std::find(key.drawingIds.begin(), key.drawingIds.end(), drawingId) == key.drawingIds.end())
        throw EditRefused(tr("The key “%1” is not linked to the drawing “%2”.").arg(key.name, drawing->name));
    return *drawing;
}

CameraFit fitCameraToDrawing(const ProjectData& data, ObjectId drawingId, ObjectId keyId, algo::Progress* progress)
{
    CameraFit result;
    const Drawing* drawing = data.drawing(drawingId);
    const KeyViewpoint* key = keyId ? data.key(keyId) : nullptr;
    if (!data.baseMesh || !drawing || (keyId && !key)) {
        result.error = tr("Fit Camera to Drawing needs a base model and a drawing.");
        return result;
    }
    result.before = drawing->aligned || !key ? drawing->camera : key->camera;
    result.after = result.before;
    const algo::Outline outline = checkedOutline(*drawing, result.error);
    if (!result.error.isEmpty())
        return result;

    algo::Positions scratch;
    const algo::Positions shape
        = key ? data.keyShape(*key, drawing->frame) : data.basePositions(drawing->frame, scratch);
    const algo::TriMesh& mesh = *data.baseMesh;
    const algo::RasterCamera start = rasterCamera(result.before, outline.width, outline.height);
    const algo::FitCameraResult fit
        = algo::fitCamera(shape, mesh.faces, mesh.edgeTopology(), start, outline, {}, progress);
    result.cancelled = fit.cancelled;
    result.ok = fit.ok;
    result.metricsBefore = fit.before;
    result.metricsAfter = fit.after;
    result.iterations = fit.iterations;
    if (fit.ok)
        result.after = documentCamera(fit.camera);
    else if (!fit.cancelled)
        result.error = tr("The camera could not be fitted to the drawing “%1”: %2")
                           .arg(drawing->name, QString::fromStdString(fit.error));
    return result;
}

ShapeFit fitShapeToDrawing(const ProjectData& data, ObjectId keyId, ObjectId drawingId, const ShapeFitRequest& request,
    algo::Progress* progress)
{
    ShapeFit result;
    const KeyViewpoint* key = data.key(keyId);
    if (!data.baseMesh || !key) {
        result.error = tr("Fit Shape to Drawing needs a base model and a key.");
        return result;
    }
    const Drawing* drawing = nullptr;
    try {
        drawing = &fitDrawing(data, *key, drawingId);
    } catch (const EditRefused& e) {
        result.error = e.message();
        return result;
    }
    result.frame = drawing->frame;
    const algo::Outline outline = checkedOutline(*drawing, result.error);
    if (!result.error.isEmpty())
        return result;
    const algo::TriMesh& mesh = *data.baseMesh;

    algo::FitShapeOptions options;
    if (!request.regionFaceSet.isEmpty()) {
        const algo::FaceSet* region = data.faceSet(request.regionFaceSet);
        if (!region || region->faces.empty()) {
            result.error = tr("There is no painted face set “%1” to fit within.").arg(request.regionFaceSet);
            return result;
        }
        options.regionFaces = region->faces;
    }
    if (!request.pinFaceSet.isEmpty()) {
        const algo::FaceSet* pins = data.faceSet(request.pinFaceSet);
        if (!pins) {
            result.error = tr("There is no painted face set “%1” to pin.").arg(request.pinFaceSet);
            return result;
        }
        options.pinnedVertices = faceSetVertices(mesh, *pins);
    }
    if (const int axis = mirrorAxis(data.mirrorPlane); request.mirror && axis >= 0) {
        options.mirror = mesh.mirrorTwins(axis);
        options.mirrorNormal = Eigen::Vector3d::Unit(axis);
    }
    if (!(request.strength >= 0.0 && request.strength <= 1.0)) {
        result.error = tr("The strength of a fit must lie in 0 to 1.");
        return result;
    }
    options.strength = request.strength;
    options.maxRounds = std::max(1, request.maxRounds);

    const algo::Positions shape = data.keyShape(*key, drawing->frame);
    const algo::RasterCamera camera = rasterCamera(key->camera, outline.width, outline.height);
    algo::FitShapeResult fit
        = algo::fitShape(shape, mesh.faces, mesh.edgeTopology(), camera, outline, options, progress);
    result.ok = fit.ok;
    result.cancelled = fit.cancelled;
    result.metricsBefore = fit.before;
    result.metricsAfter = fit.after;
    result.rounds = fit.rounds;
    if (fit.ok) {
        result.indices = std::move(fit.indices);
        result.displacements = std::move(fit.displacements);
    } else if (!fit.cancelled) {
        result.error = tr("The key “%1” could not be fitted to the drawing “%2”: %3")
                           .arg(key->name, drawing->name, QString::fromStdString(fit.error));
    }
    return result;
}

algo::FitMetrics keyFitMetrics(const ProjectData& data, const KeyViewpoint& key, const Drawing& drawing,
    const algo::Outline& outline, algo::FitScratch* scratch)
{
    if (!data.baseMesh || !outline.ok())
        return {};
    const algo::Positions shape = data.keyShape(key, drawing.frame);
    return algo::measureFit(
        shape, data.baseMesh->faces, rasterCamera(key.camera, outline.width, outline.height), outline, {}, scratch);
}

} // namespace celform::model
