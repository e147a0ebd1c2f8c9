// Stereo previews (paper 3, sections 3.1 and 4.5.2): zero disparity at the convergence plane,
// crossed disparity in front of it and uncrossed behind, toe-in aim, swapped eyes, the
// anaglyph / Dubois / half-colour / side-by-side / top-bottom compositions, and the sRGB curves.
#include "test_support.h"

#include "celform/algorithms/stereo.h"

#include <cmath>

using namespace celform::algo;

Q_DECLARE_METATYPE(Eigen::Vector3f)

namespace {

RasterCamera centreCamera(bool ortho, double shift)
{
    RasterCamera c;
    c.eye = Eigen::Vector3d(0.4, 1.2, 3.0);
    c.target = Eigen::Vector3d(0.0, 0.3, -0.5);
    c.up = Eigen::Vector3d(0.05, 1.0, 0.0);
    c.orthographic = ortho;
    c.fovYDegrees = 35;
    c.orthoHeight = 2.5;
    c.width = 800;
    c.height = 600;
    c.horizontalShift = shift;
    return c;
}

ImageRGBA filled(int w, int h, const Eigen::Vector4f& c)
{
    return ImageRGBA(w, h, c);
}

Eigen::Vector4f pixel(const ImageRGBA& image, int x, int y)
{
    const float* p = image.at(x, y);
    return {p[0], p[1], p[2], p[3]};
}

} // namespace

class TestStereo : public QObject {
    Q_OBJECT

private slots:
    void disparitySigns_data()
    {
        QTest::addColumn<bool>("ortho");
        QTest::addColumn<bool>("toeIn");
        QTest::addColumn<double>("shift");
        QTest::newRow("perspective off-axis") << false << false << 0.0;
        QTest::newRow("perspective off-axis, shifted centre") << false << false << 0.03;
        QTest::newRow("perspective toe-in") << false << true << 0.0;
        QTest::newRow("orthographic") << true << false << 0.0;
        QTest::newRow("orthographic toe-in") << true << true << 0.0;
    }
    /// Documented convention: x_right - x_left is zero at the convergence distance, negative
    /// (crossed, x_left > x_right) for nearer points, positive (uncrossed) for farther ones.
    void disparitySigns()
    {
        QFETCH(bool, ortho);
        QFETCH(bool, toeIn);
        QFETCH(double, shift);
        const RasterCamera centre = centreCamera(ortho, shift);
        StereoSettings s;
        s.interocular = 0.2;
        s.convergence = 2.5;
        s.toeIn = toeIn;
        const auto [left, right] = stereoPair(centre, s);
        const Eigen::Vector3d f = centre.forward();
        // Structured bindings are captured through references: C++17 (and Clang 14) cannot capture them.
        const auto disparity
            = [&l = left, &r = right](const Eigen::Vector3d& p) { return r.project(p).x() - l.project(p).x(); };
        const Eigen::Vector3d onAxis = centre.eye + s.convergence * f;
        QVERIFY2(std::abs(disparity(onAxis)) < 1e-9, qPrintable(QString::number(disparity(onAxis))));
        QVERIFY(std::abs(left.project(onAxis).y() - right.project(onAxis).y()) < 1e-9);
        // Still where the centre camera sees it.
        QVERIFY(
            std::abs(0.5 * (left.project(onAxis).x() + right.project(onAxis).x()) - centre.project(onAxis).x()) < 1e-6);
        double previous = -1e300;
        for (double depth : {0.5, 1.0, 2.0, 2.4, 2.6, 4.0, 10.0, 100.0}) {
            const double d = disparity(centre.eye + depth * f);
            if (depth < s.convergence)
                QVERIFY2(d < 0, "crossed disparity in front of the convergence plane");
            else
                QVERIFY2(d > 0, "uncrossed disparity behind the convergence plane");
            QVERIFY(d > previous); // grows with depth
            previous = d;
        }
        if (!ortho && !toeIn) {
            // Off-axis: the whole convergence plane has zero disparity, and the closed form holds.
            const Eigen::Vector3d offAxis = onAxis + 0.4 * centre.right() - 0.3 * centre.trueUp();
            QVERIFY(std::abs(disparity(offAxis)) < 1e-9);
            const double focal = 0.5 * centre.height / std::tan(0.5 * centre.fovYDegrees * M_PI / 180.0);
            const double depth = 1.3;
            const double expected = 2 * focal * 0.1 * (1 / s.convergence - 1 / depth);
            QVERIFY(std::abs(disparity(centre.eye + depth * f + 0.2 * centre.right()) - expected) < 1e-9);
            QVERIFY((left.eye - (centre.eye - 0.1 * centre.right())).norm() < 1e-12);
            QVERIFY((right.eye - (centre.eye + 0.1 * centre.right())).norm() < 1e-12);
            QVERIFY((left.forward() - f).norm() < 1e-12 && (right.forward() - f).norm() < 1e-12);
            QVERIFY(left.horizontalShift < shift && right.horizontalShift > shift);
            // Off-axis keeps vertical disparity at zero everywhere.
            QVERIFY(std::abs(left.project(offAxis + f).y() - right.project(offAxis + f).y()) < 1e-9);
        }
    }

    void toeInLooksAtConvergencePoint()
    {
        const RasterCamera centre = centreCamera(false, 0.0);
        StereoSettings s;
        s.interocular = 0.1;
        s.convergence = 3.0;
        s.toeIn = true;
        const auto [left, right] = stereoPair(centre, s);
        const Eigen::Vector3d point = centre.eye + s.convergence * centre.forward();
        QVERIFY((left.eye - (centre.eye - 0.05 * centre.right())).norm() < 1e-12);
        QVERIFY((right.eye - (centre.eye + 0.05 * centre.right())).norm() < 1e-12);
        QVERIFY((left.forward() - (point - left.eye).normalized()).norm() < 1e-12);
        QVERIFY((right.forward() - (point - right.eye).normalized()).norm() < 1e-12);
        QCOMPARE(left.horizontalShift, 0.0);
        const Eigen::Vector3d pl = left.project(point), pr = right.project(point);
        QVERIFY(std::abs(pl.x() - 400) < 1e-9 && std::abs(pl.y() - 300) < 1e-9);
        QVERIFY(std::abs(pr.x() - 400) < 1e-9 && std::abs(pr.y() - 300) < 1e-9);
    }

    void swapEyes()
    {
        const RasterCamera centre = centreCamera(false, 0.0);
        StereoSettings s;
        const auto [left, right] = stereoPair(centre, s);
        s.swapEyes = true;
        const auto [first, second] = stereoPair(centre, s);
        QCOMPARE(first.eye, right.eye);
        QCOMPARE(second.eye, left.eye);
        QCOMPARE(first.horizontalShift, right.horizontalShift);
        QCOMPARE(second.horizontalShift, left.horizontalShift);
        QVERIFY(first.horizontalShift > second.horizontalShift);
    }

    void anaglyphChannels()
    {
        const ImageRGBA red = filled(3, 2, {1, 0, 0, 1});
        const ImageRGBA cyan = filled(3, 2, {0, 1, 1, 1});
        QCOMPARE(pixel(composeAnaglyph(red, cyan), 1, 1), Eigen::Vector4f(1, 1, 1, 1));
        QCOMPARE(pixel(composeAnaglyph(cyan, red), 2, 0), Eigen::Vector4f(0, 0, 0, 1));
        const ImageRGBA l = filled(3, 2, {0.2f, 0.4f, 0.6f, 0.25f});
        const ImageRGBA r = filled(3, 2, {0.7f, 0.8f, 0.9f, 0.5f});
        const ImageRGBA a = composeAnaglyph(l, r);
        QCOMPARE(a.width, 3);
        QCOMPARE(a.height, 2);
        QCOMPARE(pixel(a, 0, 1), Eigen::Vector4f(0.2f, 0.8f, 0.9f, 0.5f));
    }

    void dubois_data()
    {
        QTest::addColumn<Eigen::Vector3f>("left");
        QTest::addColumn<Eigen::Vector3f>("right");
        QTest::addColumn<Eigen::Vector3f>("expected");
        QTest::newRow("left red") << Eigen::Vector3f(1, 0, 0) << Eigen::Vector3f(0, 0, 0)
                                  << Eigen::Vector3f(0.437f, 0.f, 0.f);
        QTest::newRow("right green") << Eigen::Vector3f(0, 0, 0) << Eigen::Vector3f(0, 1, 0)
                                     << Eigen::Vector3f(0.f, 0.761f, 0.f);
        QTest::newRow("right blue clamps")
            << Eigen::Vector3f(0, 0, 0) << Eigen::Vector3f(0, 0, 1) << Eigen::Vector3f(0.f, 0.009f, 1.f);
        QTest::newRow("grey both") << Eigen::Vector3f(0.5f, 0.5f, 0.5f) << Eigen::Vector3f(0.5f, 0.5f, 0.5f)
                                   << Eigen::Vector3f(0.5f, 0.4995f, 0.5f);
    }
    void dubois()
    {
        QFETCH(Eigen::Vector3f, left);
        QFETCH(Eigen::Vector3f, right);
        QFETCH(Eigen::Vector3f, expected);
        const ImageRGBA out = composeDubois(
            filled(2, 2, {left[0], left[1], left[2], 1}), filled(2, 2, {right[0], right[1], right[2], 1}));
        const Eigen::Vector4f p = pixel(out, 1, 0);
        QVERIFY2((p.head<3>() - expected).cwiseAbs().maxCoeff() < 1e-6f,
            qPrintable(QStringLiteral("%1 %2 %3").arg(p[0]).arg(p[1]).arg(p[2])));
        QCOMPARE(p[3], 1.f);
    }

    void halfColor()
    {
        const ImageRGBA out
            = composeHalfColor(filled(2, 1, {0.2f, 0.4f, 0.6f, 1}), filled(2, 1, {0.7f, 0.8f, 0.9f, 1}));
        const Eigen::Vector4f p = pixel(out, 1, 0);
        QVERIFY(std::abs(p[0] - (0.2126f * 0.2f + 0.7152f * 0.4f + 0.0722f * 0.6f)) < 1e-6f);
        QVERIFY(std::abs(p[0] - 0.37192f) < 1e-6f);
        QCOMPARE(p[1], 0.8f);
        QCOMPARE(p[2], 0.9f);
    }

    void sideBySideAndTopBottom()
    {
        ImageRGBA l(3, 2), r(3, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                l.at(x, y)[0] = float(10 * y + x);
                r.at(x, y)[0] = float(100 + 10 * y + x);
            }
        const ImageRGBA sbs = composeSideBySide(l, r);
        QCOMPARE(sbs.width, 6);
        QCOMPARE(sbs.height, 2);
        QCOMPARE(sbs.pixels.size(), std::size_t(6 * 2 * 4));
        QCOMPARE(sbs.at(1, 1)[0], 11.f);
        QCOMPARE(sbs.at(4, 1)[0], 111.f);
        QCOMPARE(sbs.at(3, 0)[0], 100.f);
        const ImageRGBA tb = composeTopBottom(l, r);
        QCOMPARE(tb.width, 3);
        QCOMPARE(tb.height, 4);
        QCOMPARE(tb.at(2, 1)[0], 12.f);
        QCOMPARE(tb.at(2, 2)[0], 102.f);
        QCOMPARE(tb.at(0, 3)[0], 110.f);
    }

    void mismatchedSizesGiveEmptyImages()
    {
        const ImageRGBA a(4, 3), b(3, 4);
        QVERIFY(composeAnaglyph(a, b).pixels.empty());
        QVERIFY(composeDubois(a, b).pixels.empty());
        QVERIFY(composeHalfColor(a, b).pixels.empty());
        QVERIFY(composeSideBySide(a, b).pixels.empty());
        QCOMPARE(composeTopBottom(a, b).width, 0);
    }

    void srgbCurves()
    {
        QVERIFY(std::abs(double(linearToSrgb(0.5f)) - 0.7353569830524495) < 1e-7);
        QVERIFY(std::abs(double(srgbToLinear(0.5f)) - 0.21404114048223255) < 1e-7);
        QCOMPARE(linearToSrgb(0.f), 0.f);
        QCOMPARE(linearToSrgb(1.f), 1.f);
        QCOMPARE(srgbToLinear(1.f), 1.f);
        QVERIFY(std::abs(double(linearToSrgb(0.002f)) - 12.92 * double(0.002f)) < 1e-8); // linear segment
        QVERIFY(std::abs(double(srgbToLinear(0.04f)) - double(0.04f) / 12.92) < 1e-9);
        for (int i = 0; i <= 1000; ++i) {
            const float l = float(i) / 1000.f;
            QVERIFY(std::abs(srgbToLinear(linearToSrgb(l)) - l) < 2e-7f + 1e-6f * l);
            if (i > 0)
                QVERIFY(linearToSrgb(l) > linearToSrgb(float(i - 1) / 1000.f));
        }
        // Continuous at the segment joints.
        QVERIFY(std::abs(linearToSrgb(0.0031308f) - linearToSrgb(0.00313081f)) < 1e-6f);
        QVERIFY(std::abs(srgbToLinear(0.04045f) - srgbToLinear(0.0404501f)) < 1e-6f);
    }
};

QTEST_GUILESS_MAIN(TestStereo)
#include "test_stereo.moc"
