// Stereo and feature lines in the viewport, under Xvfb: the anaglyph is made of the two eye
// renders, disparity is zero at the convergence distance and crossed in front of it, lines
// follow silhouettes and stay off interiors, and frames are deterministic.
#include "celform/algorithms/stereo.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/line_overlay.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_display.h"

#include "test_support.h"

#include <QApplication>
#include <QtTest/QtTest>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

using celform::algo::StereoOutput;
using celform::algo::TriMesh;
using celform::model::Camera;
using celform::model::Document;
using celform::views::Viewport;

namespace {

/// A UV sphere of radius r at c (closed, consistent outward winding).
void appendSphere(std::vector<Eigen::Vector3f>& v, std::vector<std::array<int, 3>>& f, const Eigen::Vector3f& c,
    float r, int rings = 24, int segments = 48)
{
    const int base = int(v.size());
    const double pi = 3.14159265358979323846;
    v.push_back(c + Eigen::Vector3f(0, r, 0));
    for (int i = 1; i < rings; ++i) {
        const double theta = pi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2.0 * pi * j / segments;
            v.push_back(c
                + r
                    * Eigen::Vector3f(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                        float(-std::sin(theta) * std::sin(phi))));
        }
    }
    v.push_back(c + Eigen::Vector3f(0, -r, 0));
    const int south = int(v.size()) - 1;
    auto ring = [&](int i, int j) { return base + 1 + (i - 1) * segments + (j % segments); };
    for (int j = 0; j < segments; ++j)
        f.push_back({base, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            f.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            f.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    for (int j = 0; j < segments; ++j)
        f.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
}

std::shared_ptr<TriMesh> meshOf(const std::vector<Eigen::Vector3f>& v, const std::vector<std::array<int, 3>>& f)
{
    auto mesh = std::make_shared<TriMesh>();
    mesh->vertices.resize(Eigen::Index(v.size()), 3);
    for (size_t i = 0; i < v.size(); ++i)
        mesh->vertices.row(Eigen::Index(i)) = v[i].transpose();
    mesh->faces.resize(Eigen::Index(f.size()), 3);
    for (size_t i = 0; i < f.size(); ++i)
        mesh->faces.row(Eigen::Index(i)) << f[i][0], f[i][1], f[i][2];
    return mesh;
}

/// Centroid of the pixels where a channel is clearly darker than the background's channel.
std::optional<QPointF> darkCentroid(const QImage& image, int channel, int threshold, const QRect& area)
{
    const QImage img = image.convertToFormat(QImage::Format_RGBA8888);
    const int background = img.constScanLine(2)[4 * (img.width() - 3) + channel];
    double sx = 0, sy = 0;
    long long n = 0;
    for (int y = area.top(); y <= area.bottom(); ++y) {
        const uchar* row = img.constScanLine(y);
        for (int x = area.left(); x <= area.right(); ++x)
            if (background - row[4 * x + channel] > threshold) {
                sx += x + 0.5;
                sy += y + 0.5;
                ++n;
            }
    }
    if (n == 0)
        return std::nullopt;
    return QPointF(sx / double(n), sy / double(n));
}

int maxChannelDifference(const QImage& a, const QImage& b, int channel)
{
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888), y = b.convertToFormat(QImage::Format_RGBA8888);
    if (x.size() != y.size())
        return 255;
    int worst = 0;
    for (int r = 0; r < x.height(); ++r) {
        const uchar* px = x.constScanLine(r);
        const uchar* py = y.constScanLine(r);
        for (int c = 0; c < x.width(); ++c)
            worst = std::max(worst, std::abs(int(px[4 * c + channel]) - int(py[4 * c + channel])));
    }
    return worst;
}

} // namespace

class TestStereoViewport : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<Document> m_doc;
    std::unique_ptr<Viewport> m_view;
    Camera m_camera;
    double m_convergence = 5.0;

    QImage frame()
    {
        const int before = m_view->renderCount();
        m_view->update();
        if (!QTest::qWaitFor([&] { return m_view->renderCount() > before; }, 5000))
            qWarning("viewport did not repaint");
        return m_view->renderedImage();
    }

    void setLook(bool lines, double interocular, const Eigen::Vector3f& ink = Eigen::Vector3f(0.06f, 0.05f, 0.05f))
    {
        celform::model::Look look = m_doc->data().look;
        look.showLines = lines;
        look.lineStyle.color = ink;
        look.stereo.convergence = m_convergence;
        look.stereo.interocular = interocular;
        look.stereo.toeIn = false;
        look.stereo.swapEyes = false;
        m_doc->look().setLook(look);
    }

private slots:
    void initTestCase()
    {
        // Three spheres: a big one behind, a small one exactly at the convergence distance (on
        // the left) and a small one in front (on the right). The camera looks down -Z from z = 5.
        std::vector<Eigen::Vector3f> v;
        std::vector<std::array<int, 3>> f;
        appendSphere(v, f, Eigen::Vector3f(0.f, 0.f, -2.f), 0.8f); // depth 7
        appendSphere(v, f, Eigen::Vector3f(-0.9f, 0.5f, 0.f), 0.12f); // depth 5 = convergence
        appendSphere(v, f, Eigen::Vector3f(0.7f, -0.5f, 2.f), 0.15f); // depth 3: in front
        m_doc = std::make_unique<Document>();
        m_doc->setBaseMesh(meshOf(v, f), QStringLiteral("spheres"));
        m_view = std::make_unique<Viewport>(m_doc.get());
        m_view->resize(400, 300);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        m_camera.eye = Eigen::Vector3d(0, 0, 5);
        m_camera.target = Eigen::Vector3d(0, 0, 0);
        m_camera.up = Eigen::Vector3d(0, 1, 0);
        m_camera.fovYDegrees = 40.0;
        m_view->setCamera(m_camera);
        frame();
    }

    void anaglyphIsMadeOfTheEyes_data()
    {
        QTest::addColumn<bool>("lines");
        QTest::newRow("shading only") << false;
        QTest::newRow("with lines") << true;
    }

    void anaglyphIsMadeOfTheEyes()
    {
        QFETCH(bool, lines);
        setLook(lines, 0.3);
        m_view->setCamera(m_camera);
        m_view->display().setStereo(StereoOutput::Anaglyph);
        const QImage composed = frame();
        QCOMPARE(composed.size(), QSize(400, 300) * m_view->devicePixelRatio());
        m_view->display().setEyeOnly(celform::views::ViewportDisplay::Eye::Left);
        const QImage left = frame();
        m_view->display().setEyeOnly(celform::views::ViewportDisplay::Eye::Right);
        const QImage right = frame();
        m_view->display().setEyeOnly(celform::views::ViewportDisplay::Eye::Both);
        composed.save(QStringLiteral("/tmp/stereo_anaglyph%1.png").arg(lines ? "_lines" : ""));
        left.save(QStringLiteral("/tmp/stereo_left%1.png").arg(lines ? "_lines" : ""));
        right.save(QStringLiteral("/tmp/stereo_right%1.png").arg(lines ? "_lines" : ""));
        QVERIFY(left != right); // the eyes do differ
        QVERIFY2(maxChannelDifference(composed, left, 0) <= 2, "red is the left eye's");
        QVERIFY2(maxChannelDifference(composed, right, 1) <= 2, "green is the right eye's");
        QVERIFY2(maxChannelDifference(composed, right, 2) <= 2, "blue is the right eye's");
        // The CPU composition of the two eye images gives the same picture.
        const QImage cpu = celform::views::toSrgb(
            celform::algo::composeAnaglyph(celform::views::toLinear(left.convertToFormat(QImage::Format_RGBA8888)),
                celform::views::toLinear(right.convertToFormat(QImage::Format_RGBA8888))));
        for (int c = 0; c < 3; ++c)
            QVERIFY(maxChannelDifference(composed, cpu, c) <= 2);
        m_view->display().setStereo(StereoOutput::Off);
    }

    void disparity()
    {
        setLook(false, 0.3);
        m_view->setCamera(m_camera);
        m_view->display().setStereo(StereoOutput::Anaglyph);
        const QImage image = frame().convertToFormat(QImage::Format_RGBA8888);
        const int w = image.width(), h = image.height();
        // Red channel dark = the left eye sees a sphere there; cyan (green) = the right eye.
        // The convergence sphere sits at (-0.9, 0.5): upper left. The near one: lower right.
        // Projected centres (f = 412 px): (126, 109) radius 10 px and (296, 219) radius 21 px;
        // the big sphere is a disc of 47 px around (200, 150). The areas exclude it.
        QCOMPARE(QSize(w, h), QSize(400, 300));
        const QRect upperLeft(90, 70, 60, 65), lowerRight(250, 180, 150, 120);
        const auto zeroRed = darkCentroid(image, 0, 15, upperLeft), zeroCyan = darkCentroid(image, 1, 15, upperLeft);
        const auto nearRed = darkCentroid(image, 0, 15, lowerRight), nearCyan = darkCentroid(image, 1, 15, lowerRight);
        QVERIFY(zeroRed && zeroCyan && nearRed && nearCyan);
        qInfo("convergence sphere: red (%.2f, %.2f) cyan (%.2f, %.2f); near sphere: red (%.2f, %.2f) cyan (%.2f, %.2f)",
            zeroRed->x(), zeroRed->y(), zeroCyan->x(), zeroCyan->y(), nearRed->x(), nearRed->y(), nearCyan->x(),
            nearCyan->y());
        QVERIFY2(std::abs(zeroRed->x() - zeroCyan->x()) < 1.0, "zero disparity at the convergence distance");
        QVERIFY(std::abs(zeroRed->y() - zeroCyan->y()) < 1.0);
        // algo::stereoPair: x_right - x_left = 2 f b (1/C - 1/D) < 0 in front: crossed, the left
        // (red) image lies right of the right (cyan) one. Expected 2 f b (1/5 - 1/3) in pixels.
        const double focal = 0.5 * h / std::tan(0.5 * 40.0 * 3.14159265358979323846 / 180.0);
        const double expected = 2.0 * focal * 0.15 * (1.0 / 3.0 - 1.0 / 5.0);
        const double measured = nearRed->x() - nearCyan->x();
        qInfo("near sphere disparity %.2f px, expected %.2f px", measured, expected);
        QVERIFY2(measured > 0.0, "crossed disparity in front of the convergence plane");
        QVERIFY(std::abs(measured - expected) < 1.5);
        m_view->display().setStereo(StereoOutput::Off);
    }

    void linesFollowSilhouettes()
    {
        // Front view of the big sphere alone in the frame centre, mono.
        // Pure red ink: nothing in the clay shading is red, so every red pixel is a line.
        const Eigen::Vector3f red(1.f, 0.f, 0.f);
        setLook(true, 0.3, red);
        Camera c = m_camera;
        c.eye = Eigen::Vector3d(0, 0, 1.5);
        c.target = Eigen::Vector3d(0, 0, -2);
        m_view->setCamera(c);
        m_view->display().setStereo(StereoOutput::Off);
        const QImage with = frame().convertToFormat(QImage::Format_RGBA8888);
        with.save(QStringLiteral("/tmp/stereo_lines_mono.png"));
        setLook(false, 0.3, red);
        const QImage without = frame().convertToFormat(QImage::Format_RGBA8888);
        without.save(QStringLiteral("/tmp/stereo_nolines_mono.png"));
        const int w = with.width(), h = with.height();
        // The big sphere (radius 0.8 at distance 3.5) projects to a disc of this radius.
        const double focal = 0.5 * h / std::tan(0.5 * 40.0 * 3.14159265358979323846 / 180.0);
        const double d = 3.5, r = 0.8;
        const double radius = focal * r / std::sqrt(d * d - r * r);
        const double cx = 0.5 * w, cy = 0.5 * h;
        auto isInk = [](const uchar* p) { return p[0] > 150 && p[1] < 90 && p[2] < 90; };
        int silhouetteInk = 0, silhouetteSamples = 0, interiorInk = 0, offInk = 0;
        for (int k = 0; k < 360; ++k) {
            const double a = k * 3.14159265358979323846 / 180.0;
            // The darkest pixel within 2 px of the silhouette circle along this ray.
            bool found = false;
            for (double dr = -2.0; dr <= 2.0; dr += 0.5) {
                const int x = int(cx + (radius + dr) * std::cos(a)), y = int(cy + (radius + dr) * std::sin(a));
                if (x >= 0 && y >= 0 && x < w && y < h && isInk(with.constScanLine(y) + 4 * x))
                    found = true;
            }
            ++silhouetteSamples;
            silhouetteInk += found ? 1 : 0;
            // Interior ring, well inside: no line across the smooth interior.
            for (double f : {0.2, 0.5, 0.8}) {
                const int x = int(cx + f * radius * std::cos(a)), y = int(cy + f * radius * std::sin(a));
                interiorInk += isInk(with.constScanLine(y) + 4 * x) ? 1 : 0;
            }
        }
        for (int y = 0; y < h * 3 / 4; ++y) // the axes triad (red X arrow) sits bottom left
            for (int x = 0; x < w; ++x)
                offInk += isInk(without.constScanLine(y) + 4 * x) ? 1 : 0;
        qInfo("silhouette ink %d / %d, interior ink %d, ink with lines off %d", silhouetteInk, silhouetteSamples,
            interiorInk, offInk);
        QVERIFY(silhouetteInk > silhouetteSamples * 9 / 10);
        QCOMPARE(interiorInk, 0);
        QCOMPARE(offInk, 0);
        QVERIFY(m_view->lastFrameTimes().lines >= 0.0);
    }

    void stereoWithLinesAndOutputs_data()
    {
        QTest::addColumn<int>("output");
        QTest::newRow("anaglyph") << int(StereoOutput::Anaglyph);
        QTest::newRow("dubois") << int(StereoOutput::Dubois);
        QTest::newRow("halfcolor") << int(StereoOutput::HalfColor);
        QTest::newRow("sbs") << int(StereoOutput::SideBySide);
        QTest::newRow("tb") << int(StereoOutput::TopBottom);
    }

    void stereoWithLinesAndOutputs()
    {
        QFETCH(int, output);
        setLook(true, 0.3);
        m_view->setCamera(m_camera);
        m_view->display().setStereo(StereoOutput(output));
        const QImage a = frame();
        const QImage b = frame();
        QVERIFY2(a == b, "two frames of the same view are identical");
        QCOMPARE(a.size(), QSize(400, 300) * m_view->devicePixelRatio());
        a.save(QStringLiteral("/tmp/stereo_output_%1.png").arg(QString::fromLatin1(QTest::currentDataTag())));
        // The camera is back where it was after the eye renders.
        QVERIFY((m_view->camera().eye - m_camera.eye).norm() < 1e-9);
        m_view->display().setStereo(StereoOutput::Off);
    }

    /// Frame times on the armadillo (52k triangles), printed for comparison run to run.
    void armadilloFrameTimes()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_armadillo.off"));
        Document doc;
        doc.importBaseMesh(path);
        QVERIFY(doc.hasMesh());
        Viewport view(&doc);
        view.resize(800, 600);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        auto measure = [&](bool lines, StereoOutput output) {
            celform::model::Look look = doc.data().look;
            look.showLines = lines;
            doc.look().setLook(look);
            view.display().setStereo(output);
            view.renderedImage(); // warm up: topology, shaders
            double total = 0.0, lineTotal = 0.0;
            const int frames = 8;
            for (int i = 0; i < frames; ++i) {
                Camera c = view.camera();
                const Eigen::AngleAxisd turn(0.05, Eigen::Vector3d::UnitY());
                c.eye = view.pivot() + turn * (c.eye - view.pivot());
                c.target = view.pivot() + turn * (c.target - view.pivot());
                view.setCamera(c);
                view.renderedImage();
                total += view.lastFrameTimes().frame;
                lineTotal += view.lastFrameTimes().lines;
            }
            qInfo("armadillo 800x600, lines %s, stereo %d: %.1f ms per frame (lines %.1f ms)", lines ? "on" : "off",
                int(output), total / frames, lineTotal / frames);
        };
        measure(false, StereoOutput::Off);
        measure(true, StereoOutput::Off);
        measure(false, StereoOutput::Anaglyph);
        measure(true, StereoOutput::Anaglyph);
    }

    void cleanupTestCase()
    {
        m_view.reset();
        m_doc.reset();
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestStereoViewport test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_stereo_viewport.moc"
