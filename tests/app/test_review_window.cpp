// The supervisors' stereo review under Xvfb: full screen, keys that change modes, the turntable,
// jumping to keys' cameras, Esc, and the View menu's F11 action.
#include "test_support.h"
#include "ui_test_support.h"

#include "editor/main_window.h"
#include "editor/review_window.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_display.h"

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QScreen>
#include <QtTest/QtTest>

#include <array>
#include <cmath>
#include <map>
#include <memory>

using namespace celform;

namespace {

/// An octahedron subdivided onto the unit sphere: small and closed.
std::shared_ptr<algo::TriMesh> ball()
{
    std::vector<Eigen::Vector3f> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<std::array<int, 3>> f
        = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int s = 0; s < 4; ++s) {
        std::vector<std::array<int, 3>> next;
        std::map<std::pair<int, int>, int> mid;
        auto m = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            if (auto it = mid.find(key); it != mid.end())
                return it->second;
            v.push_back((v[size_t(a)] + v[size_t(b)]).normalized());
            return mid[key] = int(v.size()) - 1;
        };
        for (const auto& t : f) {
            const int a = m(t[0], t[1]), b = m(t[1], t[2]), c = m(t[2], t[0]);
            next.push_back({t[0], a, c});
            next.push_back({t[1], b, a});
            next.push_back({t[2], c, b});
            next.push_back({a, b, c});
        }
        f = std::move(next);
    }
    auto mesh = std::make_shared<algo::TriMesh>();
    mesh->vertices.resize(Eigen::Index(v.size()), 3);
    for (size_t i = 0; i < v.size(); ++i)
        mesh->vertices.row(Eigen::Index(i)) = v[i].transpose();
    mesh->faces.resize(Eigen::Index(f.size()), 3);
    for (size_t i = 0; i < f.size(); ++i)
        mesh->faces.row(Eigen::Index(i)) << f[i][0], f[i][1], f[i][2];
    return mesh;
}

model::Camera cameraAt(const Eigen::Vector3d& eye)
{
    model::Camera c;
    c.eye = eye;
    c.target = Eigen::Vector3d::Zero();
    c.up = Eigen::Vector3d::UnitY();
    c.fovYDegrees = 35.0;
    return c;
}

void press(QWidget* w, Qt::Key key)
{
    QTest::keyClick(w, key);
    QApplication::processEvents();
}

} // namespace

class TestReviewWindow : public QObject {
    Q_OBJECT

private slots:
    void reviewKeys()
    {
        model::Document doc;
        doc.setBaseMesh(ball(), QStringLiteral("ball"));
        doc.createKey(QStringLiteral("Front"), cameraAt({0, 0, 4}));
        doc.createKey(QStringLiteral("Side"), cameraAt({4, 0.5, 0}));
        const model::Look lookBefore = doc.data().look;

        app::ReviewWindow review(&doc, cameraAt({0, 1, 4.5}));
        review.showReview();
        QVERIFY(QTest::qWaitForWindowExposed(&review));
        QVERIFY(QTest::qWaitFor([&] { return review.isFullScreen() || review.isMaximized(); }, 3000));
        QVERIFY(review.width() >= 800);
        views::Viewport* vp = review.viewport();
        test::waitForRender(vp);
        QCOMPARE(vp->display().stereo(), algo::StereoOutput::Anaglyph);

        // S cycles the outputs and comes back to anaglyph.
        const algo::StereoOutput expected[]
            = {algo::StereoOutput::Dubois, algo::StereoOutput::HalfColor, algo::StereoOutput::SideBySide,
                algo::StereoOutput::TopBottom, algo::StereoOutput::Off, algo::StereoOutput::Anaglyph};
        for (algo::StereoOutput output : expected) {
            press(vp, Qt::Key_S);
            QCOMPARE(vp->display().stereo(), output);
        }

        // L toggles lines, P the preview, [ and ] the review's interocular only.
        const bool lines = vp->display().linesShown();
        press(vp, Qt::Key_L);
        QCOMPARE(vp->display().linesShown(), !lines);
        press(vp, Qt::Key_L);
        QCOMPARE(vp->display().linesShown(), lines);
        press(vp, Qt::Key_P);
        QVERIFY(vp->isPreview());
        press(vp, Qt::Key_P);
        QVERIFY(!vp->isPreview());
        const double interocular = vp->display().resolvedStereoSettings().interocular;
        press(vp, Qt::Key_BracketRight);
        QVERIFY(std::abs(vp->display().resolvedStereoSettings().interocular - 1.1 * interocular)
            < 1e-9 * (1 + interocular));
        press(vp, Qt::Key_BracketLeft);
        press(vp, Qt::Key_BracketLeft);
        QVERIFY(std::abs(vp->display().resolvedStereoSettings().interocular - interocular / 1.1)
            < 1e-9 * (1 + interocular));
        QVERIFY(
            review.statusText().contains(QString::number(vp->display().resolvedStereoSettings().interocular, 'g', 3)));
        QVERIFY(doc.data().look == lookBefore);

        // H shows and hides the help.
        press(vp, Qt::Key_H);
        QVERIFY(review.isHelpShown());
        test::waitForRender(vp);
        QImage shot = review.screen()->grabWindow(0).toImage();
        shot.save(QStringLiteral("/tmp/review_help.png"));
        press(vp, Qt::Key_H);
        QVERIFY(!review.isHelpShown());

        // Space: the turntable moves the camera within a fraction of a second.
        const model::Camera start = vp->camera();
        press(vp, Qt::Key_Space);
        QVERIFY(review.isTurntable());
        QVERIFY(QTest::qWaitFor([&] { return (vp->camera().eye - start.eye).norm() > 0.02; }, 3000));
        // About 20 degrees a second around the vertical axis: the height and distance stay.
        QVERIFY(std::abs(vp->camera().eye.y() - start.eye.y()) < 1e-6);
        press(vp, Qt::Key_Space);
        QVERIFY(!review.isTurntable());

        // Right jumps to the first key's camera, again to the second, Left back.
        press(vp, Qt::Key_Right);
        QCOMPARE(review.keyIndex(), 0);
        QVERIFY((vp->camera().eye - doc.data().keys[0].camera.eye).norm() < 1e-9);
        QVERIFY(review.statusText().contains(QStringLiteral("Front")));
        press(vp, Qt::Key_Right);
        QCOMPARE(review.keyIndex(), 1);
        QVERIFY((vp->camera().eye - doc.data().keys[1].camera.eye).norm() < 1e-9);
        QVERIFY(review.statusText().contains(QStringLiteral("Side")));
        press(vp, Qt::Key_Left);
        QCOMPARE(review.keyIndex(), 0);

        test::waitForRender(vp);
        QTest::qWait(600); // one status refresh with a measured frame rate
        // What the screen shows (QWidget::grab() re-renders the GL child without the composition).
        shot = review.screen()->grabWindow(0).toImage();
        shot.save(QStringLiteral("/tmp/review.png"));
        QVERIFY(!shot.isNull());
        // The composition is on screen: red and green disagree along the model's edges.
        const QImage composed = vp->renderedImage().convertToFormat(QImage::Format_RGB32);
        int fringes = 0;
        for (int y = 0; y < composed.height(); y += 4)
            for (int x = 0; x < composed.width(); x += 4) {
                const QRgb p = composed.pixel(x, y);
                fringes += std::abs(qRed(p) - qGreen(p)) > 40 ? 1 : 0;
            }
        QVERIFY(fringes > 20);

        press(vp, Qt::Key_Escape);
        QVERIFY(QTest::qWaitFor([&] { return !review.isVisible(); }, 2000));
    }

    void menuActionOpensReview()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        auto* action = window.findChild<QAction*>(QStringLiteral("actionStereoReview"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::Key_F11));
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestReviewWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_review_window.moc"
