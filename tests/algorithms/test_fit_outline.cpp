// The drawing's outline: filled figures, open line art closed by the closing radius, a hand-made
// line drawing with inner lines, real alpha, the clear failures (empty, all background, all ink, no
// closed outline, touching the border) and a real drawing from ../shared.
#include "test_support.h"

#include "celform/algorithms/outline.h"

#include <QImage>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace celform::algo;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A grey drawing whose ink coverage at a point is given by inkAt (0 paper, 1 ink), anti-aliased
/// by 4 x 4 supersampling, black ink on white paper.
DrawingImage greyDrawing(int w, int h, const std::function<bool(double, double)>& inkAt)
{
    DrawingImage image;
    image.width = w;
    image.height = h;
    image.channels = 1;
    image.pixels.resize(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int covered = 0;
            for (int sy = 0; sy < 4; ++sy)
                for (int sx = 0; sx < 4; ++sx)
                    covered += inkAt(x + (sx + 0.5) / 4.0, y + (sy + 0.5) / 4.0) ? 1 : 0;
            image.pixels[std::size_t(y) * std::size_t(w) + std::size_t(x)]
                = std::uint8_t(std::lround(255.0 * (1.0 - covered / 16.0)));
        }
    return image;
}

/// Distance from p to the segment a-b.
double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

/// A ring of ink (line art of a circle) of the given width, with a gap of gapPx pixels at the right.
std::function<bool(double, double)> ring(double cx, double cy, double r, double width, double gapPx)
{
    return [=](double x, double y) {
        const double d = std::hypot(x - cx, y - cy);
        if (std::abs(d - r) > 0.5 * width)
            return false;
        return !(x > cx && std::abs(y - cy) < 0.5 * gapPx);
    };
}

std::size_t maskArea(const Outline& o)
{
    return std::size_t(std::count(o.mask.begin(), o.mask.end(), std::uint8_t(1)));
}

} // namespace

class TestFitOutline : public QObject {
    Q_OBJECT

private slots:
    void otsuSplitsTwoLevels()
    {
        std::vector<std::int64_t> histogram(256, 0);
        histogram[20] = 500;
        histogram[30] = 300;
        histogram[220] = 2000;
        histogram[240] = 900;
        const int t = otsuThreshold(histogram);
        QVERIFY2(t > 30 && t <= 220, qPrintable(QString::number(t)));
        std::vector<std::int64_t> flat(256, 0);
        flat[0] = 100;
        QCOMPARE(otsuThreshold(flat), -1);
        // Pure black ink on white paper: every level between ties; the middle one is chosen.
        std::vector<std::int64_t> ink(256, 0);
        ink[0] = 300;
        ink[255] = 7000;
        QCOMPARE(otsuThreshold(ink), 128);
        // Levels at 20 and 220 only: between them, again the middle.
        std::vector<std::int64_t> two(256, 0);
        two[20] = 10;
        two[220] = 10;
        QCOMPARE(otsuThreshold(two), 120);
    }

    void filledDiscGivesItsCircle()
    {
        const double cx = 100.3, cy = 96.7, r = 60.0;
        const DrawingImage image
            = greyDrawing(200, 200, [&](double x, double y) { return std::hypot(x - cx, y - cy) < r; });
        const Outline o = extractOutline(image);
        QVERIFY2(o.ok(), outlineErrorMessage(o.error).c_str());
        QCOMPARE(int(o.contours.size()), 1);
        QVERIFY(!o.usedAlpha);
        QVERIFY(o.thresholdUsed > 0.05 && o.thresholdUsed < 0.95);
        // Sub-pixel: every contour point within a quarter pixel of the true circle.
        double worst = 0.0;
        for (const auto& p : o.contours[0])
            worst = std::max(worst, std::abs(std::hypot(p.x() - cx, p.y() - cy) - r));
        QVERIFY2(worst < 0.25, qPrintable(QString::number(worst)));
        QVERIFY(polygonArea(o.contours[0]) > 0.0);
        QVERIFY(std::abs(polygonArea(o.contours[0]) - kPi * r * r) < 0.005 * kPi * r * r);
        QVERIFY(std::abs(double(maskArea(o)) - kPi * r * r) < 0.01 * kPi * r * r);
    }

    void openRingIsClosedByTheClosingRadius()
    {
        const double cx = 110, cy = 100, r = 60, width = 3;
        const DrawingImage image = greyDrawing(220, 200, ring(cx, cy, r, width, 5.0));
        OutlineSettings open;
        open.closingRadius = 0.0;
        QCOMPARE(extractOutline(image, open).error, OutlineError::NoClosedOutline);
        OutlineSettings closing;
        closing.closingRadius = 3.0;
        const Outline o = extractOutline(image, closing);
        QVERIFY2(o.ok(), outlineErrorMessage(o.error).c_str());
        const double outer = r + 0.5 * width;
        qInfo("ring: area %.1f, expected %.1f, %zu contours", polygonArea(o.contours[0]), kPi * outer * outer,
            o.contours.size());
        QVERIFY(std::abs(polygonArea(o.contours[0]) - kPi * outer * outer) < 0.01 * kPi * outer * outer);
        // The outline follows the ring's outer edge, with a shallow dent across the closed gap.
        double worst = 0.0;
        for (const auto& p : o.contours[0])
            worst = std::max(worst, std::abs(std::hypot(p.x() - cx, p.y() - cy) - outer));
        QVERIFY2(worst < 2.5, qPrintable(QString::number(worst))); // a dent where the gap was closed
    }

    void handDrawnLineArtKeepsOnlyTheOuterOutline()
    {
        // A snowman-like figure drawn as strokes: a body circle, a head circle overlapping it, two
        // eyes and a mouth inside (inner lines), a small gap in the body line, 2.5 px lines, and a
        // stray dot of dirt far away.
        const Eigen::Vector2d body(150, 190), head(150, 100);
        const double rb = 70, rh = 40;
        auto inkAt = [&](double x, double y) {
            const Eigen::Vector2d p(x, y);
            const double db = (p - body).norm(), dh = (p - head).norm();
            const bool bodyLine = std::abs(db - rb) < 1.25 && !(x < 85 && std::abs(y - 200) < 2.0) && dh > rh;
            const bool headLine = std::abs(dh - rh) < 1.25 && db > rb;
            const bool eyes = (p - Eigen::Vector2d(135, 92)).norm() < 4 || (p - Eigen::Vector2d(165, 92)).norm() < 4;
            const bool mouth = segmentDistance(p, {135, 115}, {165, 115}) < 1.25;
            const bool dirt = (p - Eigen::Vector2d(20, 20)).norm() < 2.5;
            return bodyLine || headLine || eyes || mouth || dirt;
        };
        const DrawingImage image = greyDrawing(300, 300, inkAt);
        OutlineSettings settings;
        settings.closingRadius = 3.0;
        const Outline o = extractOutline(image, settings);
        QVERIFY2(o.ok(), outlineErrorMessage(o.error).c_str());
        for (const auto& c : o.contours)
            qInfo("contour: %zu points, area %.1f at %.1f, %.1f", c.size(), polygonArea(c), c[0].x(), c[0].y());
        QCOMPARE(int(o.contours.size()), 1); // no inner lines, no dirt
        // The mask is the union of the two discs (line width included).
        std::size_t both = 0, either = 0;
        for (int y = 0; y < 300; ++y)
            for (int x = 0; x < 300; ++x) {
                const Eigen::Vector2d p(x + 0.5, y + 0.5);
                const bool truth = (p - body).norm() < rb + 1.25 || (p - head).norm() < rh + 1.25;
                const bool got = o.mask[std::size_t(y) * 300 + std::size_t(x)] != 0;
                both += truth && got;
                either += truth || got;
            }
        const double iou = double(both) / double(either);
        QVERIFY2(iou > 0.99, qPrintable(QString::number(iou)));
        // With minComponentPixels the dirt is kept as a second outline.
        settings.minComponentPixels = 5;
        settings.minThickness = 1.0;
        QCOMPARE(int(extractOutline(image, settings).contours.size()), 2);
    }

    void holesKeptWhenAsked()
    {
        // A thick annulus: filled, one outline; with its hole kept, the hole's boundary runs the
        // other way round (the figure stays on the left of both).
        const DrawingImage image = greyDrawing(200, 200, [](double x, double y) {
            const double d = std::hypot(x - 100, y - 100);
            return d > 30 && d < 70;
        });
        const Outline filled = extractOutline(image);
        QVERIFY(filled.ok());
        QCOMPARE(int(filled.contours.size()), 1);
        QVERIFY(filled.holesFilled);
        OutlineSettings settings;
        settings.fillHoles = false;
        const Outline holed = extractOutline(image, settings);
        QVERIFY(holed.ok());
        QVERIFY(!holed.holesFilled);
        QCOMPARE(int(holed.contours.size()), 2);
        QVERIFY(std::abs(polygonArea(holed.contours[0]) - kPi * 70 * 70) < 0.01 * kPi * 70 * 70);
        QVERIFY(std::abs(polygonArea(holed.contours[1]) + kPi * 30 * 30) < 0.02 * kPi * 30 * 30);
    }

    void realAlphaDecides()
    {
        DrawingImage image;
        image.width = image.height = 120;
        image.channels = 4;
        image.pixels.assign(std::size_t(120 * 120 * 4), 0); // transparent black
        for (int y = 30; y < 90; ++y)
            for (int x = 20; x < 100; ++x) {
                std::uint8_t* p = image.pixels.data() + (std::size_t(y) * 120 + std::size_t(x)) * 4;
                p[0] = p[1] = p[2] = 240; // light paint: luminance alone would miss it
                p[3] = 255;
            }
        const Outline o = extractOutline(image);
        QVERIFY2(o.ok(), outlineErrorMessage(o.error).c_str());
        QVERIFY(o.usedAlpha);
        QCOMPARE(int(maskArea(o)), 60 * 80);
        QVERIFY(std::abs(polygonArea(o.contours[0]) - 60.0 * 80.0) < 80.0);
    }

    void failuresAreClear()
    {
        QCOMPARE(extractOutline(DrawingImage{}).error, OutlineError::EmptyImage);
        DrawingImage wrongSize;
        wrongSize.width = wrongSize.height = 10;
        wrongSize.channels = 3;
        wrongSize.pixels.resize(10);
        QCOMPARE(extractOutline(wrongSize).error, OutlineError::EmptyImage);
        const DrawingImage white = greyDrawing(64, 64, [](double, double) { return false; });
        QCOMPARE(extractOutline(white).error, OutlineError::NothingFound);
        const DrawingImage black = greyDrawing(64, 64, [](double, double) { return true; });
        QCOMPARE(extractOutline(black).error, OutlineError::NothingFound);
        OutlineSettings fixed;
        fixed.threshold = 0.5;
        QCOMPARE(extractOutline(black, fixed).error, OutlineError::NothingFound);
        // An arc, wide open: line work that never encloses anything.
        const DrawingImage arc = greyDrawing(200, 200, ring(100, 100, 60, 3, 80));
        QCOMPARE(extractOutline(arc).error, OutlineError::NoClosedOutline);
        const DrawingImage cut
            = greyDrawing(200, 200, [](double x, double y) { return std::hypot(x - 30, y - 100) < 50; });
        QCOMPARE(extractOutline(cut).error, OutlineError::TouchesBorder);
        OutlineSettings lenient;
        lenient.rejectBorder = false;
        QVERIFY(extractOutline(cut, lenient).ok());
        for (OutlineError e : {OutlineError::EmptyImage, OutlineError::NothingFound, OutlineError::NoClosedOutline,
                 OutlineError::TouchesBorder})
            QVERIFY(!outlineErrorMessage(e).empty());
    }

    void resamplingKeepsTheSpacing()
    {
        std::vector<Eigen::Vector2d> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
        const auto samples = resampleClosed(square, 1.0);
        QCOMPARE(int(samples.size()), 40);
        for (std::size_t i = 0; i < samples.size(); ++i)
            QVERIFY(std::abs((samples[(i + 1) % samples.size()] - samples[i]).norm() - 1.0) < 1e-9);
    }

    void sharedElephantDrawing()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("drawings/openclipart_contour_elephant.png"));
        QImage qimage(path);
        QVERIFY(!qimage.isNull());
        qimage = qimage.convertToFormat(QImage::Format_RGBA8888);
        DrawingImage image;
        image.width = qimage.width();
        image.height = qimage.height();
        image.channels = 4;
        image.pixels.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
        for (int y = 0; y < image.height; ++y)
            std::copy_n(
                qimage.constScanLine(y), image.width * 4, image.pixels.begin() + std::ptrdiff_t(y) * image.width * 4);
        QElapsedTimer timer;
        timer.start();
        const Outline o = extractOutline(image);
        const qint64 ms = timer.elapsed();
        QVERIFY2(o.ok(), outlineErrorMessage(o.error).c_str());
        const double fill = double(maskArea(o)) / (double(image.width) * image.height);
        qInfo("elephant drawing %dx%d: %zu contours, %zu points, %.1f %% filled, threshold %.3f, %lld ms", image.width,
            image.height, o.contours.size(), o.contours[0].size(), 100.0 * fill, o.thresholdUsed, ms);
        QVERIFY(fill > 0.1 && fill < 0.9);
        QVERIFY(std::abs(polygonArea(o.contours[0])) > 0.95 * double(maskArea(o)) * 0.9);
    }
};

QTEST_GUILESS_MAIN(TestFitOutline)
#include "test_fit_outline.moc"
