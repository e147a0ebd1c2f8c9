// Issue 25's picture figures ("## Figures"): the default look (toon with lines) at 1280x960, a
// directional light at (0.5, 0.8, 0.6), seen from (0.3, 0.2, 1), on the elephant sample and the
// shared coarse meshes, rendered through `celform render`'s own path (model::renderFrames, every
// pass into an EXR read back here) at render subdivision level 2, against the smooth surface: the
// same model subdivided three times by Loop's rule and rendered as a plain mesh (that surface as
// the base model, level 0). Level 0 (the control mesh) is measured and printed beside it, so that
// the before and after stay on record. The before/after pictures of docs/lines.md are written
// from the same renders (as test_getting_started writes the guide's screenshots), so they never
// show a renderer that is gone.
#include "test_support.h"

#include "celform/model/data/framed_camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"
#include "celform/model/render/subdivided_surface.h"

#include <OpenImageIO/imageio.h>

#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <map>

using namespace celform;

namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 960;
/// "Away from the silhouette": every pixel within this many pixels (a disc) is covered in both
/// pictures compared, the test's and the reference's.
constexpr int kAway = 3;
/// Line coverage that counts as ink: a quarter, so that faint tapered dashes count too (as in
/// test_render_output).
constexpr float kInk = 0.25f;
/// A dash is short when the diagonal of its bounding box is under this many pixels.
constexpr double kShortDash = 30.0;
/// Meshes above this many triangles are not coarse (cgal_bunny00 has 75k): they are left out.
constexpr Eigen::Index kCoarseTriangles = 20000;

/// The passes of a rendered frame, as the all-pass EXR of `celform render` holds them.
struct Frame {
    int width = 0, height = 0;
    std::vector<float> rgba; ///< the beauty, linear, 4 floats a pixel
    std::vector<float> lines, tone;
    std::vector<char> covered; ///< the id pass is a face
};

Frame readFrame(const QString& path)
{
    Frame frame;
    auto in = OIIO::ImageInput::open(path.toStdString());
    if (!in)
        return frame;
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return frame;
    auto channel = [&](const char* name) {
        for (int c = 0; c < channels; ++c)
            if (spec.channelnames[std::size_t(c)] == name)
                return c;
        return -1;
    };
    const int r = channel("R"), lines = channel("lines.Y"), tone = channel("tone.Y"), id = channel("id.ID");
    if (r < 0 || lines < 0 || tone < 0 || id < 0 || channel("A") != r + 3)
        return frame;
    frame.width = spec.width;
    frame.height = spec.height;
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height);
    frame.rgba.resize(count * 4);
    frame.lines.resize(count);
    frame.tone.resize(count);
    frame.covered.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = pixels.data() + i * std::size_t(channels);
        std::copy(p + r, p + r + 4, frame.rgba.begin() + std::ptrdiff_t(i * 4));
        frame.lines[i] = p[lines];
        frame.tone[i] = p[tone];
        frame.covered[i] = p[id] >= 0.f;
    }
    return frame;
}

Eigen::Vector3d figureView()
{
    return Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
}

/// Renders frame 0 of data through renderFrames (`celform render --size 1280x960 --light
/// directional:0.5,0.8,0.6 --subdivision level --style toon --lines on`, the camera given) into an
/// EXR of every pass in folder, and reads it back.
Frame renderThroughJob(
    const model::ProjectData& data, const model::Camera& camera, int level, const QString& folder, const QString& name)
{
    model::RenderJob job;
    job.camera = camera;
    job.size = QSize(kWidth, kHeight);
    job.light = model::Light{model::LightType::Directional, Eigen::Vector3d(0.5, 0.8, 0.6).normalized()};
    job.subdivision = level;
    job.style = model::ShadingStyle::Toon;
    job.lines = true;
    job.output = folder + QLatin1Char('/') + name + QStringLiteral(".exr");
    if (model::renderFrames(data, name, job) != 1)
        return {};
    return readFrame(job.output);
}

/// The smooth surface of data's base model with the control shape given (its rest pose, or a
/// deformed frame): Loop level 3 as a project of its own whose base model it is (level 0), with
/// data's look, face sets and shading offsets carried to it.
model::ProjectData smoothReference(const model::ProjectData& data, const algo::Positions& control)
{
    const auto surface = model::subdividedSurface(data, 3);
    model::ProjectData reference = surface->display;
    auto mesh = std::make_shared<algo::TriMesh>(*surface->display.baseMesh);
    surface->apply(control, mesh->vertices);
    reference.baseMesh = mesh;
    reference.look.subdivision = {};
    return reference;
}

/// Covered in both masks at every pixel of the disc of radius kAway around it (outside the image
/// counts as uncovered).
std::vector<char> awayFromSilhouettes(const Frame& a, const Frame& b)
{
    std::vector<char> both(a.covered.size());
    for (std::size_t i = 0; i < both.size(); ++i)
        both[i] = a.covered[i] && b.covered[i];
    std::vector<char> inner(both.size(), 0);
    for (int y = kAway; y < a.height - kAway; ++y)
        for (int x = kAway; x < a.width - kAway; ++x) {
            bool all = true;
            for (int dy = -kAway; dy <= kAway && all; ++dy)
                for (int dx = -kAway; dx <= kAway && all; ++dx)
                    if (dx * dx + dy * dy <= kAway * kAway)
                        all = both[std::size_t((y + dy) * a.width + x + dx)] != 0;
            inner[std::size_t(y * a.width + x)] = all;
        }
    return inner;
}

/// The bounding-box diagonals of the pieces of line ink (lines pass above kInk), 8-connected.
std::vector<double> inkPieceDiagonals(const Frame& f)
{
    std::vector<int> label(f.lines.size(), -1);
    std::vector<double> diagonals;
    std::vector<int> queue;
    for (int seed = 0; seed < int(f.lines.size()); ++seed) {
        if (label[std::size_t(seed)] >= 0 || f.lines[std::size_t(seed)] <= kInk)
            continue;
        const int id = int(diagonals.size());
        Eigen::AlignedBox2i box;
        queue.clear();
        queue.push_back(seed);
        label[std::size_t(seed)] = id;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const Eigen::Vector2i p(queue[head] % f.width, queue[head] / f.width);
            box.extend(p);
            for (int n = 0; n < 9; ++n) {
                const Eigen::Vector2i q = p + Eigen::Vector2i(n % 3 - 1, n / 3 - 1);
                if (q.x() < 0 || q.y() < 0 || q.x() >= f.width || q.y() >= f.height)
                    continue;
                const int j = q.y() * f.width + q.x();
                if (label[std::size_t(j)] < 0 && f.lines[std::size_t(j)] > kInk) {
                    label[std::size_t(j)] = id;
                    queue.push_back(j);
                }
            }
        }
        diagonals.push_back((box.sizes() + Eigen::Vector2i::Ones()).cast<double>().norm());
    }
    return diagonals;
}

/// The figures of a picture against the smooth surface's.
struct Figures {
    double toneDiffPercent = 0; ///< of the pixels away from both silhouettes, dark in one picture only
    int innerPixels = 0;
    int shortDashes = 0; ///< ink pieces whose bounding-box diagonal is under kShortDash
    int referenceShortDashes = 0;
    double iou = 0; ///< coverage
};

Figures compare(const Frame& test, const Frame& reference, const algo::ToonRamp& ramp)
{
    Figures out;
    // Dark: below the middle of the two darkest tones (the anti-aliased tone pass blends them
    // along a boundary; the middle is where the boundary lies).
    const float dark = ramp.intensities.size() >= 2 ? 0.5f * (ramp.intensities[0] + ramp.intensities[1]) : 0.5f;
    const std::vector<char> inner = awayFromSilhouettes(test, reference);
    int differ = 0, both = 0, either = 0;
    for (std::size_t i = 0; i < inner.size(); ++i) {
        both += test.covered[i] && reference.covered[i];
        either += test.covered[i] || reference.covered[i];
        if (!inner[i])
            continue;
        ++out.innerPixels;
        differ += (test.tone[i] < dark) != (reference.tone[i] < dark);
    }
    out.toneDiffPercent = 100.0 * differ / std::max(1, out.innerPixels);
    out.iou = double(both) / std::max(1, either);
    for (const double d : inkPieceDiagonals(test))
        out.shortDashes += d < kShortDash;
    for (const double d : inkPieceDiagonals(reference))
        out.referenceShortDashes += d < kShortDash;
    return out;
}

QString describe(const Figures& f)
{
    return QStringLiteral("dark tone differs on %1 % of %2 inner pixels, %3 dashes under 30 px (reference %4), "
                          "silhouette IoU %5")
        .arg(f.toneDiffPercent, 0, 'f', 2)
        .arg(f.innerPixels)
        .arg(f.shortDashes)
        .arg(f.referenceShortDashes)
        .arg(f.iou, 0, 'f', 4);
}

/// A mesh of the figures: the elephant sample, or a shared mesh in a new project (default look).
model::ProjectData loadModel(const QString& name)
{
    if (name == QLatin1String("elephant-plain"))
        return model::loadProject(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"));
    const QString path = test::sharedDataPath(QStringLiteral("meshes/") + name + QStringLiteral(".off"));
    if (path.isEmpty())
        return {};
    return model::newProject(std::make_shared<const algo::TriMesh>(model::importMesh(path).mesh), name);
}

/// The control shape of frame 0 seen from camera (the blend of the keys there and their offsets,
/// as renderFrames evaluates it before subdividing).
algo::Positions frameShape(const model::ProjectData& data, const model::Camera& camera)
{
    model::FrameEvaluator evaluator;
    evaluator.prepare(data);
    evaluator.evaluate(data, 0, camera.eye);
    return evaluator.shape();
}

/// A key seen from the figures' view whose offsets are a brush stroke: the point of the model
/// highest on the screen pushed up the screen by 6 % of the model's size, with a smooth falloff
/// ((1 - (d/r)^2)^2, as a sculpting brush) over a radius of 12 %. The silhouette there moves
/// out, so the deformation shows in the coverage.
model::KeyViewpoint brushedKey(const model::ProjectData& data, const model::Camera& camera)
{
    const algo::Positions& v = data.baseMesh->vertices;
    const Eigen::Vector3f forward = (camera.target - camera.eye).normalized().cast<float>();
    Eigen::Vector3f up = camera.up.cast<float>();
    up = (up - up.dot(forward) * forward).normalized();
    const float size = (v.colwise().maxCoeff() - v.colwise().minCoeff()).norm();
    Eigen::Index top = 0;
    (v * up).maxCoeff(&top);
    const Eigen::Vector3f centre = v.row(top);
    const float radius = 0.12f * size;
    model::KeyViewpoint key;
    key.id = 1;
    key.name = QStringLiteral("brushed");
    key.direction = figureView();
    key.camera = camera;
    model::SparseOffsets& offsets = key.offsetsByFrame[0];
    for (Eigen::Index i = 0; i < v.rows(); ++i) {
        const float d = (Eigen::Vector3f(v.row(i)) - centre).norm() / radius;
        if (d >= 1.f)
            continue;
        const float w = (1.f - d * d) * (1.f - d * d);
        offsets.indices.push_back(std::uint32_t(i));
        offsets.deltas.push_back(0.06f * size * w * up);
    }
    return key;
}

/// A picture's pixels as `celform render` writes them to a PNG (sRGB, 8 bits).
QImage pngPixels(const Frame& f)
{
    model::EncodedFrame encoded;
    model::encodeChannels(
        QStringLiteral("x.png"), f.width, f.height, {"R", "G", "B", "A"}, f.rgba.data(), f.rgba.size(), true, encoded);
    QImage image(f.width, f.height, QImage::Format_RGBA8888);
    for (int y = 0; y < f.height; ++y)
        std::copy_n(encoded.bytes.data() + std::size_t(y) * std::size_t(f.width) * 4, std::size_t(f.width) * 4,
            image.scanLine(y));
    return image;
}

/// The crop of the before/after pictures: a square of side fraction of the coverage's bounding
/// box height, centred at (cx, cy) in fractions of that box.
QRect cropOf(const Frame& f, double cx, double cy, double side)
{
    int x0 = f.width, y0 = f.height, x1 = -1, y1 = -1;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.covered[std::size_t(y * f.width + x)]) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
    const int s = std::min({int(side * (y1 - y0 + 1)), f.width, f.height});
    const int left = std::clamp(int(x0 + cx * (x1 - x0 + 1)) - s / 2, 0, f.width - s);
    const int top = std::clamp(int(y0 + cy * (y1 - y0 + 1)) - s / 2, 0, f.height - s);
    return {left, top, s, s};
}

/// Level 0 on the left, level 2 on the right, the same crop of each (the beauty is opaque, the
/// look's background around the model), a white gap between them.
QImage sideBySide(const Frame& before, const Frame& after, const QRect& crop)
{
    constexpr int gap = 8;
    QImage out(crop.width() * 2 + gap, crop.height(), QImage::Format_RGB888);
    out.fill(Qt::white);
    QPainter painter(&out);
    painter.drawImage(QPoint(0, 0), pngPixels(before), crop);
    painter.drawImage(QPoint(crop.width() + gap, 0), pngPixels(after), crop);
    painter.end();
    return out;
}

} // namespace

class TestToonFigures : public QObject {
    Q_OBJECT

    QTemporaryDir m_folder;
    /// Renders of the figures, kept for the pictures: (mesh, level) -> frame.
    std::map<std::pair<QString, int>, Frame> m_renders;

    const QString m_docs = QStringLiteral(CELFORM_SOURCE_DIR "/docs");

    static model::Camera cameraOf(const model::ProjectData& data)
    {
        return model::cameraFromView(data, figureView(), double(kWidth) / kHeight);
    }

    /// The (kept) render of a model at a level.
    const Frame& renderOf(const QString& name, const model::ProjectData& data, int level)
    {
        Frame& f = m_renders[{name, level}];
        if (f.width == 0)
            f = renderThroughJob(data, cameraOf(data), level, m_folder.path(), name + QString::number(level));
        return f;
    }

private slots:
    void figuresAtLevel2_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("elephant sample") << QStringLiteral("elephant-plain");
        QTest::newRow("cgal_elephant") << QStringLiteral("cgal_elephant");
        QTest::newRow("npm_bunny") << QStringLiteral("npm_bunny");
        QTest::newRow("cgal_fandisk") << QStringLiteral("cgal_fandisk");
        QTest::newRow("cgal_bunny00") << QStringLiteral("cgal_bunny00");
    }

    void figuresAtLevel2()
    {
        QFETCH(QString, name);
        QVERIFY(m_folder.isValid());
        const model::ProjectData data = loadModel(name);
        if (!data.baseMesh)
            QSKIP(qPrintable(QStringLiteral("shared test data not found: ../shared/data/meshes/") + name));
        if (data.baseMesh->faceCount() > kCoarseTriangles)
            QSKIP(qPrintable(
                QStringLiteral("%1 has %2 triangles: not a coarse mesh").arg(name).arg(data.baseMesh->faceCount())));
        QElapsedTimer timer;
        timer.start();
        const model::Camera camera = cameraOf(data);
        const Frame& level0 = renderOf(name, data, 0);
        const Frame& level2 = renderOf(name, data, 2);
        const Frame smooth = renderThroughJob(
            smoothReference(data, frameShape(data, camera)), camera, 0, m_folder.path(), name + "-l3");
        QVERIFY(level0.width == kWidth && level2.width == kWidth && smooth.width == kWidth);
        const algo::ToonRamp& ramp = data.look.toon;
        const Figures before = compare(level0, smooth, ramp), after = compare(level2, smooth, ramp);
        qInfo("%s (%lld triangles) level 0: %s", qPrintable(name), qlonglong(data.baseMesh->faceCount()),
            qPrintable(describe(before)));
        qInfo("%s level 2: %s (%lld ms)", qPrintable(name), qPrintable(describe(after)), qlonglong(timer.elapsed()));
        QVERIFY2(after.toneDiffPercent <= 0.8, qPrintable(describe(after)));
        QVERIFY2(after.shortDashes <= 3, qPrintable(describe(after)));
        QVERIFY2(after.iou >= 0.97, qPrintable(describe(after)));
    }

    void keyDeformationShowsThrough()
    {
        // A brushed key on the elephant sample, seen from its own view: level 2 of the deformed
        // frame against level 3 of the deformed control shape, and against the undeformed level 2.
        QVERIFY(m_folder.isValid());
        const QString name = QStringLiteral("elephant-plain");
        model::ProjectData data = loadModel(name);
        const model::Camera camera = cameraOf(data);
        const Frame& plain = renderOf(name, data, 2);
        data.keys.push_back(brushedKey(data, camera));
        const algo::Positions deformed = frameShape(data, camera);
        const algo::Positions& rest = data.baseMesh->vertices;
        const float moved = (deformed - rest).rowwise().norm().maxCoeff();
        QVERIFY(moved > 0.05f * (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm()); // the whole key
        const Frame level2 = renderThroughJob(data, camera, 2, m_folder.path(), name + "-deformed2");
        const Frame smooth
            = renderThroughJob(smoothReference(data, deformed), camera, 0, m_folder.path(), name + "-deformed3");
        QVERIFY(level2.width == kWidth && smooth.width == kWidth);
        const Figures f = compare(level2, smooth, data.look.toon);
        // The pixels the brush adds to (or takes from) the level-2 silhouette, and how many of
        // them the deformed smooth surface agrees on.
        int changed = 0, agree = 0;
        for (std::size_t i = 0; i < plain.covered.size(); ++i)
            if (plain.covered[i] != level2.covered[i]) {
                ++changed;
                agree += level2.covered[i] == smooth.covered[i];
            }
        qInfo("brushed elephant (largest offset %.4f) level 2: %s; %d pixels of coverage changed by the key, "
              "%d of them as on the deformed smooth surface",
            double(moved), qPrintable(describe(f)), changed, agree);
        QVERIFY2(f.iou >= 0.97, qPrintable(describe(f)));
        QVERIFY2(f.toneDiffPercent <= 0.8, qPrintable(describe(f)));
        QVERIFY(changed >= 500);
        QVERIFY(agree >= 0.9 * changed);
    }

    void beforeAfterPictures()
    {
        // Level 0 and level 2 side by side, a close-up of the same crop: written into docs/images
        // on every run, then the docs must show exactly these pictures.
        QVERIFY(m_folder.isValid());
        struct Picture {
            const char* mesh;
            const char* file;
            double cx, cy, side; // crop (cropOf)
        };
        const Picture pictures[] = {
            {"elephant-plain", "toon-before-after-elephant.png", 0.59, 0.34, 0.72}, // the head and trunk
            {"npm_bunny", "toon-before-after-bunny.png", 0.4, 0.45, 0.8}, // the head, ears and haunch
            {"cgal_armadillo", "toon-before-after-armadillo.png", 0.41, 0.33, 0.75}, // the back and arms
        };
        QStringList made;
        for (const Picture& p : pictures) {
            const QString name = QString::fromLatin1(p.mesh);
            const model::ProjectData data = loadModel(name);
            if (!data.baseMesh) {
                qInfo("%s: shared mesh absent, picture not written", p.mesh);
                continue;
            }
            const Frame& before = renderOf(name, data, 0);
            const Frame& after = renderOf(name, data, 2);
            QVERIFY(before.width == kWidth && after.width == kWidth);
            auto shortDashes = [](const Frame& f) {
                const std::vector<double> d = inkPieceDiagonals(f);
                return std::count_if(d.begin(), d.end(), [](double x) { return x < kShortDash; });
            };
            qInfo("%s (%lld triangles): %d dashes under 30 px at level 0, %d at level 2", p.mesh,
                qlonglong(data.baseMesh->faceCount()), int(shortDashes(before)), int(shortDashes(after)));
            const QImage picture = sideBySide(before, after, cropOf(after, p.cx, p.cy, p.side));
            const QString path = m_docs + QStringLiteral("/images/") + QString::fromLatin1(p.file);
            QVERIFY(picture.save(path));
            made << QString::fromLatin1(p.file);
        }
        if (made.size() < 3)
            QSKIP("shared meshes absent: only the elephant's picture was written");
        // docs/lines.md shows each of these pictures, and no other toon-* picture.
        QFile doc(m_docs + QStringLiteral("/lines.md"));
        QVERIFY(doc.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString shown = QString::fromUtf8(doc.readAll());
        for (const QString& file : made)
            QVERIFY2(shown.contains(QStringLiteral("](images/%1)").arg(file)), qPrintable(file));
        QCOMPARE(int(shown.count(QStringLiteral("](images/toon-"))), int(made.size()));
    }
};

QTEST_GUILESS_MAIN(TestToonFigures)
#include "test_toon_figures.moc"
