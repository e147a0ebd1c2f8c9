// USD export in its text form, .usda (export.h, docs/export.md): the evaluated shape as a
// UsdGeomMesh whose points and normals are time-sampled at every frame, the shot camera as a
// UsdGeomCamera with a time-sampled transform and lens, and on request the enabled keys as
// UsdSkelBlendShapes with their weights animated by a SkelAnimation (as the glTF export's morph
// targets). Written by hand (USD's text grammar; Pixar's "USD File Formats"), streamed frame by
// frame: the points of a frame are formatted into one reused buffer and written. One attribute's
// samples must be one block, so the normals take a second walk over the frames (evaluating a
// frame again costs little next to formatting and writing it), and no buffer holds the whole
// shot. Atomic, as every one-file format.
#include "celform/model/export/export.h"
#include "celform/model/io/output_file.h"
#include "celform/model/export/usda_text.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <set>

namespace celform::model::exporting {

std::string usdIdentifier(std::string_view name)
{
    std::string id;
    id.reserve(name.size() + 1);
    for (const char c : name) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        id.push_back(ok ? c : '_');
    }
    if (id.empty() || (id[0] >= '0' && id[0] <= '9'))
        id.insert(id.begin(), '_');
    return id;
}

UsdaText& UsdaText::quoted(std::string_view s)
{
    *this << '"';
    for (const char c : s) {
        if (c == '"' || c == '\\')
            *this << '\\' << c;
        else if (c == '\n')
            text("\\n");
        else if (static_cast<unsigned char>(c) < 0x20)
            *this << ' ';
        else
            *this << c;
    }
    return *this << '"';
}

namespace {

QString text(const char* s)
{
    return QCoreApplication::translate("celform::model::Export", s);
}

/// Appends the text (an IoError naming the file and the system's reason when it fails).
void write(OutputFile& file, const UsdaText& t)
{
    file.write(t.data(), qint64(t.size()));
}

/// One frame of the camera as UsdGeomCamera holds it.
struct CameraSample {
    int frame = 0;
    Projection projection = Projection::Perspective;
    double transform[16] = {}; ///< row-major, USD's row vectors: the axes, then the eye
    float focalLength = 0, horizontalAperture = 0, verticalAperture = 0, nearClip = 0, farClip = 0;
};

/// Horizontal aperture of the exported camera, in tenths of a scene unit (USD's "millimetres"):
/// a 36 mm film back, so focal lengths read as on a full-frame camera.
constexpr double kFilmWidth = 36.0;

CameraSample cameraSample(const Camera& camera, int frame, double aspect, double modelSize)
{
    CameraSample s;
    s.frame = frame;
    s.projection = camera.projection;
    // UsdGeomCamera looks down its -Z with +Y up (UsdGeomCamera's schema documentation).
    const Eigen::Vector3d axes[4] = {camera.right(), camera.trueUp(), -camera.forward(), camera.eye};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            s.transform[r * 4 + c] = c < 3 ? axes[r][c] : (r == 3 ? 1.0 : 0.0);
    if (camera.projection == Projection::Perspective) {
        s.horizontalAperture = float(kFilmWidth);
        s.verticalAperture = float(kFilmWidth / aspect);
        // The vertical field of view fovY spans the vertical aperture at the focal length.
        s.focalLength = float(kFilmWidth / aspect / (2.0 * std::tan(camera.fovYDegrees * M_PI / 360.0)));
    } else {
        // An orthographic camera's apertures are the view's size, in tenths of a scene unit.
        s.verticalAperture = float(camera.orthoHeight * 10.0);
        s.horizontalAperture = float(camera.orthoHeight * aspect * 10.0);
        s.focalLength = 50.0f;
    }
    // The clipping range of the glTF export's camera: far beyond the model, near a small part of it.
    const double far = std::max(1e-3, ((camera.eye - camera.target).norm() + modelSize) * 10.0);
    s.farClip = float(far);
    s.nearClip = camera.projection == Projection::Perspective ? float(std::max(1e-6, far * 1e-5)) : 0.0f;
    return s;
}

/// A blend shape: a key's offsets at the playhead (as the glTF export's morph targets).
struct BlendShapeKey {
    ObjectId key = 0;
    std::string name; ///< its prim's name and its token in skel:blendShapes
    ProjectData::FrameOffsets offsets;
};

std::vector<BlendShapeKey> blendShapeKeys(const ProjectData& data)
{
    std::vector<BlendShapeKey> keys;
    std::set<std::string> taken;
    for (const KeyViewpoint& key : data.keys) {
        if (!key.enabled)
            continue;
        BlendShapeKey k;
        k.key = key.id;
        k.name = usdIdentifier(key.name.toStdString());
        for (int n = 2; taken.count(k.name); ++n)
            k.name = usdIdentifier(key.name.toStdString()) + "_" + std::to_string(n);
        taken.insert(k.name);
        k.offsets = ProjectData::offsetsAt(key, data.currentFrame, data.blend.time);
        keys.push_back(std::move(k));
    }
    return keys;
}

/// Writes the stage's metadata and the mesh's attributes that do not change.
void writeHeader(UsdaText& t, const ProjectData& data, const ExportJob& job, const algo::TriMesh& mesh,
    const std::string& meshName, const std::vector<BlendShapeKey>& shapes)
{
    const double fps = data.time.fps;
    t << "#usda 1.0\n(\n    defaultPrim = \"celform\"\n    doc = \"Celform export\"\n";
    t << "    endTimeCode = " << job.lastFrame << "\n    framesPerSecond = " << fps << '\n';
    t << "    metersPerUnit = 1\n    startTimeCode = " << job.firstFrame << "\n    timeCodesPerSecond = " << fps
      << "\n    upAxis = \"Y\"\n)\n\n";
    t << "def Xform \"celform\"\n{\n";
    const bool skel = !shapes.empty();
    const std::string indent = skel ? "        " : "    ";
    if (skel)
        t << "    def SkelRoot \"model\"\n    {\n";
    t << indent << "def Mesh " << '"' << meshName << '"';
    if (skel)
        t << " (\n" << indent << "    prepend apiSchemas = [\"SkelBindingAPI\"]\n" << indent << ')';
    t << '\n' << indent << "{\n";
    const std::string in = indent + "    ";
    t << in << "uniform bool doubleSided = 0\n";
    t << in << "int[] faceVertexCounts = [";
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
        t << (f > 0 ? ", 3" : "3");
    t << "]\n";
    t << in << "int[] faceVertexIndices = ";
    t.list(mesh.faces.data(), std::size_t(mesh.faces.size()));
    t << '\n' << in << "uniform token orientation = \"rightHanded\"\n";
    if (mesh.hasUvs()) {
        // USD's texture origin is the image's bottom left, as in OBJ: the coordinates as they are.
        t << in << "texCoord2f[] primvars:st = ";
        t.tuples(mesh.uvs.data(), std::size_t(mesh.uvs.rows()), 2);
        t << " (\n" << in << "    interpolation = \"faceVarying\"\n" << in << ")\n";
        t << in << "int[] primvars:st:indices = ";
        t.list(mesh.uvFaces.data(), std::size_t(mesh.uvFaces.size()));
        t << '\n';
    }
    if (skel) {
        const std::string prefix = "</celform/model/" + meshName + "/";
        t << in << "uniform token[] skel:blendShapes = [";
        for (std::size_t k = 0; k < shapes.size(); ++k)
            t << (k > 0 ? ", " : "") << '"' << shapes[k].name << '"';
        t << "]\n" << in << "rel skel:blendShapeTargets = [";
        for (std::size_t k = 0; k < shapes.size(); ++k)
            t << (k > 0 ? ", " : "") << prefix << shapes[k].name << '>';
        t << "]\n" << in << "rel skel:skeleton = </celform/model/skeleton>\n";
    }
    // The Loop-subdivided surface is already in the points: the mesh is drawn as it is.
    t << in << "uniform token subdivisionScheme = \"none\"\n";
}

/// The blend shapes (the mesh's children) and the skeleton with the animation of their weights.
void writeBlendShapes(UsdaText& t, const std::vector<BlendShapeKey>& shapes, const std::vector<CameraSample>& frames,
    const std::vector<float>& weights)
{
    for (const BlendShapeKey& k : shapes) {
        const SparseOffsets& sparse = *k.offsets.get();
        t << "\n            def BlendShape \"" << k.name << "\"\n            {\n";
        t << "                uniform vector3f[] offsets = ";
        t.tuples(sparse.deltas.empty() ? nullptr : sparse.deltas[0].data(), sparse.deltas.size(), 3);
        t << "\n                uniform int[] pointIndices = ";
        t.list(sparse.indices.data(), sparse.indices.size());
        t << "\n            }\n";
    }
    t << "        }\n\n";
    // A skeleton without joints: UsdSkel's binding for meshes animated by blend shapes alone.
    t << "        def Skeleton \"skeleton\" (\n            prepend apiSchemas = [\"SkelBindingAPI\"]\n        )\n"
         "        {\n            uniform matrix4d[] bindTransforms = []\n            uniform token[] joints = []\n"
         "            uniform matrix4d[] restTransforms = []\n"
         "            rel skel:animationSource = </celform/model/skeleton/weights>\n\n"
         "            def SkelAnimation \"weights\"\n            {\n";
    t << "                uniform token[] blendShapes = [";
    for (std::size_t k = 0; k < shapes.size(); ++k)
        t << (k > 0 ? ", " : "") << '"' << shapes[k].name << '"';
    t << "]\n                float[] blendShapeWeights.timeSamples = {\n";
    for (std::size_t f = 0; f < frames.size(); ++f) {
        t << "                    " << frames[f].frame << ": ";
        t.list(weights.data() + f * shapes.size(), shapes.size());
        t << ",\n";
    }
    t << "                }\n                uniform token[] joints = []\n            }\n        }\n    }\n";
}

void writeCamera(UsdaText& t, const std::vector<CameraSample>& frames, Projection projection)
{
    t << "\n    def Camera \"camera\"\n    {\n";
    auto samples = [&](const char* declaration, auto value) {
        t << "        " << declaration << ".timeSamples = {\n";
        for (const CameraSample& s : frames) {
            t << "            " << s.frame << ": ";
            value(s);
            t << ",\n";
        }
        t << "        }\n";
    };
    samples("float2 clippingRange", [&](const CameraSample& s) {
        const float range[2] = {s.nearClip, s.farClip};
        t.tuple(range, 2);
    });
    samples("float focalLength", [&](const CameraSample& s) { t << s.focalLength; });
    samples("float horizontalAperture", [&](const CameraSample& s) { t << s.horizontalAperture; });
    t << "        token projection = \"" << (projection == Projection::Perspective ? "perspective" : "orthographic")
      << "\"\n";
    samples("float verticalAperture", [&](const CameraSample& s) { t << s.verticalAperture; });
    samples("matrix4d xformOp:transform", [&](const CameraSample& s) {
        t << '(';
        for (int r = 0; r < 4; ++r) {
            t << (r > 0 ? ", " : "");
            t.tuple(s.transform + r * 4, 4);
        }
        t << ')';
    });
    t << "        uniform token[] xformOpOrder = [\"xformOp:transform\"]\n    }\n}\n";
}

} // namespace

void writeUsda(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result)
{
    // Two walks over the frames, the points and then the normals: one progress bar for both.
    algo::ProgressPart pointsPart(progress, 0, 2 * std::int64_t(job.frameCount()));
    algo::ProgressPart normalsPart(progress, job.frameCount(), 2 * std::int64_t(job.frameCount()));
    FrameWalk walk(data, source, job, progress ? &pointsPart : nullptr);
    const algo::TriMesh& mesh = walk.mesh();
    const std::string meshName = usdIdentifier(
        data.baseMeshName.isEmpty() ? "base" : QFileInfo(data.baseMeshName).completeBaseName().toStdString());
    const std::vector<BlendShapeKey> shapes = job.blendShapes ? blendShapeKeys(data) : std::vector<BlendShapeKey>{};
    if (job.blendShapes && shapes.empty())
        result.warnings << text("the project has no enabled keys: no blend shapes written");
    const std::string in = shapes.empty() ? "        " : "            ";

    OutputFile file(job.output); // whole or not at all; every write checked (issue 27)

    UsdaText t;
    writeHeader(t, data, job, mesh, meshName, shapes);
    t << in << "point3f[] points.timeSamples = {\n";
    write(file, t);

    // Every frame: its points (less the blend shapes' share when they are written) to the file,
    // its camera and weights and extent kept (a few numbers).
    const double modelSize = algo::boundingBox(mesh.vertices).diagonal().norm();
    std::vector<CameraSample> cameras;
    std::vector<float> weights, extents;
    cameras.reserve(std::size_t(job.frameCount()));
    weights.reserve(std::size_t(job.frameCount()) * shapes.size());
    extents.reserve(std::size_t(job.frameCount()) * 6);
    algo::Positions points, normals;
    while (walk.next()) {
        cameras.push_back(cameraSample(walk.camera(), walk.frame(), job.aspect, modelSize));
        const algo::Positions* shape = &walk.shape();
        if (!shapes.empty()) {
            points = walk.shape();
            const std::size_t row = weights.size();
            weights.resize(row + shapes.size(), 0.0f);
            for (const KeyShare& share : walk.evaluator().blend().shares)
                for (std::size_t k = 0; k < shapes.size(); ++k)
                    if (shapes[k].key == share.key)
                        weights[row + k] = float(share.weight);
            // points + sum of weight x offsets is the evaluated shape, whatever the keys do at
            // other frames (UsdSkel adds the blend shapes to the points, UsdSkel's BlendShape).
            for (std::size_t k = 0; k < shapes.size(); ++k) {
                const SparseOffsets& sparse = *shapes[k].offsets.get();
                for (std::size_t i = 0; i < sparse.indices.size(); ++i)
                    points.row(Eigen::Index(sparse.indices[i])) -= weights[row + k] * sparse.deltas[i].transpose();
            }
            shape = &points;
        }
        // The extent bounds what is drawn: the whole shape, blend shapes applied.
        if (walk.shape().rows() > 0) {
            const Eigen::AlignedBox3f box(
                walk.shape().colwise().minCoeff().transpose(), walk.shape().colwise().maxCoeff().transpose());
            extents.insert(extents.end(),
                {box.min().x(), box.min().y(), box.min().z(), box.max().x(), box.max().y(), box.max().z()});
        } else
            extents.insert(extents.end(), 6, 0.0f);

        t.clear();
        t << in << "    " << walk.frame() << ": ";
        t.tuples(shape->data(), std::size_t(shape->rows()), 3);
        t << ",\n";
        write(file, t);
        ++result.frames;
    }
    if (walk.cancelled()) {
        finishFile(file, true, result);
        return;
    }

    // The second walk: the normals of the whole shape at every frame.
    t.clear();
    t << in << "}\n" << in << "normal3f[] normals.timeSamples = {\n";
    write(file, t);
    FrameWalk again(data, source, job, progress ? &normalsPart : nullptr);
    while (again.next()) {
        algo::vertexNormals(again.shape(), again.faces(), normals); // storage kept from frame to frame
        t.clear();
        t << in << "    " << again.frame() << ": ";
        t.tuples(normals.data(), std::size_t(normals.rows()), 3);
        t << ",\n";
        write(file, t);
    }
    if (again.cancelled()) {
        finishFile(file, true, result);
        return;
    }
    t.clear();
    t << in << "}\n" << in << "float3[] extent.timeSamples = {\n";
    for (std::size_t f = 0; f < cameras.size(); ++f) {
        t << in << "    " << cameras[f].frame << ": ";
        t.tuples(extents.data() + f * 6, 2, 3);
        t << ",\n";
    }
    t << in << "}\n";
    if (shapes.empty())
        t << "    }\n";
    else
        writeBlendShapes(t, shapes, cameras, weights);
    const Projection projection = cameras.empty() ? Projection::Perspective : cameras.front().projection;
    if (std::any_of(cameras.begin(), cameras.end(), [&](const CameraSample& s) { return s.projection != projection; }))
        result.warnings << text("the camera path changes between perspective and orthographic: the USD camera "
                                "keeps the first frame's projection");
    writeCamera(t, cameras, projection);
    write(file, t);
    finishFile(file, false, result);
}

} // namespace celform::model::exporting
