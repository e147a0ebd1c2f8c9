// The viewing-sphere panel (paper 1, figure 4) driven as an artist would: keys on a small model,
// a view inside a facet, clicks and drags, checked through the pixels it paints and its readout.
#include "celform/model/document/document.h"
#include "celform/views/panels/view_sphere_panel.h"

#include "test_meshes.h"

#include <QApplication>
#include <QHelpEvent>
#include <QSignalSpy>
#include <QStyleFactory>
#include <QToolTip>
#include <QtTest/QtTest>

#include <cmath>
#include <functional>
#include <map>
#include <memory>

Q_DECLARE_METATYPE(Eigen::Vector3d)

using celform::algo::TriMesh;
using celform::model::Document;
using celform::model::KeyViewpoint;
using celform::model::ObjectId;
using celform::model::ProjectData;
using celform::model::UnspecifiedMode;
using celform::views::ViewSpherePanel;

using celform::test::octahedron;

namespace {

struct KeySpec {
    const char* name;
    Eigen::Vector3d direction;
};

/// Front, side and top span the facet the tests look through; left and low leave room for
/// dummies at -Y and -Z, so the drawing has both kinds of points.
const KeySpec kKeys[] = {
    {"front", {0.0, 0.0, 1.0}},
    {"side", {1.0, 0.0, 0.0}},
    {"top", {0.0, 1.0, 0.0}},
    {"left", {-1.0, 0.0, 0.0}},
    {"low", Eigen::Vector3d(0.3, -0.5, 0.8).normalized()},
};

/// A view direction well inside the front-side-top facet.
const Eigen::Vector3d kInsideView = Eigen::Vector3d(1.0, 0.5, 1.0).normalized();

int countPixels(const QImage& image, const std::function<bool(const QColor&)>& match)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            n += match(image.pixelColor(x, y)) ? 1 : 0;
    return n;
}

bool isRed(const QColor& c)
{
    return c.red() > 170 && c.green() < 90 && c.blue() < 90;
}

bool isGreenish(const QColor& c)
{
    return c.green() > c.red() + 20 && c.green() > c.blue() + 12;
}

bool isOrange(const QColor& c)
{
    return c.red() > 200 && c.green() > 90 && c.green() < 170 && c.blue() < 60;
}

} // namespace

class TestViewSpherePanel : public QObject {
    Q_OBJECT

    std::unique_ptr<Document> m_doc;
    std::unique_ptr<ViewSpherePanel> m_panel;
    std::map<QString, ObjectId> m_ids;

    void makeDocument(bool withKeys)
    {
        m_panel.reset();
        m_doc = std::make_unique<Document>();
        ProjectData data;
        data.baseMesh = octahedron();
        data.baseMeshName = QStringLiteral("octahedron.obj");
        m_doc->reset(std::move(data));
        m_ids.clear();
        if (!withKeys)
            return;
        for (const KeySpec& spec : kKeys) {
            KeyViewpoint key;
            key.id = 0;
            key.name = QString::fromLatin1(spec.name);
            key.direction = spec.direction;
            const QString name = key.name; // read before key is moved into addKey
            m_ids[name] = m_doc->keys().addKey(std::move(key));
        }
    }

    void showPanel()
    {
        m_panel = std::make_unique<ViewSpherePanel>(m_doc.get());
        m_panel->resize(300, 300);
        m_panel->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_panel.get()));
    }

    QString weightText(double w) const { return m_panel->locale().toString(w, 'f', 2); }

private slots:
    void hitFacetIsGreenAndItsKeysRed()
    {
        makeDocument(true);
        showPanel();
        m_panel->setViewDirection(kInsideView);
        const celform::model::BlendResult blend = m_doc->blender().weights(m_doc->data(), kInsideView);
        QVERIFY2(blend.raw.facet >= 0, "the test view should fall inside a hull facet");

        const QImage image = m_panel->grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY(image.save(QStringLiteral("/tmp/view_sphere_panel.png")));
        const int green = countPixels(image, isGreenish);
        const int red = countPixels(image, isRed);
        QVERIFY2(green > 300, qPrintable(QStringLiteral("green pixels: %1").arg(green)));
        // Three red keys of radius 5.5 cover about 3 * 95 pixels; their halo labels add none.
        QVERIFY2(red > 120, qPrintable(QStringLiteral("red pixels: %1").arg(red)));

        const QString readout = m_panel->readout();
        for (const char* name : {"front", "side", "top"})
            QVERIFY2(readout.contains(QLatin1String(name)), qPrintable(readout));
        QVERIFY2(!readout.contains(QLatin1String("left")), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("base ")), qPrintable(readout));
        // The readout lists what the evaluator says, largest share first.
        for (const auto& share : blend.shares) {
            const QString name = m_doc->data().key(share.key)->name;
            QVERIFY2(readout.contains(name + QLatin1Char(' ') + weightText(share.weight)), qPrintable(readout));
        }

        // At its minimum size the panel still draws the facet; the readout is elided, not wrapped.
        m_panel->resize(m_panel->minimumSizeHint());
        const QImage small = m_panel->grab().toImage().convertToFormat(QImage::Format_RGB32);
        small.save(QStringLiteral("/tmp/view_sphere_panel_small.png"));
        QVERIFY(countPixels(small, isGreenish) > 50);
    }

    void keyDirectionGivesWeightOne_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<Eigen::Vector3d>("direction");
        for (const KeySpec& spec : kKeys)
            QTest::newRow(spec.name) << QString::fromLatin1(spec.name) << spec.direction;
    }

    void keyDirectionGivesWeightOne()
    {
        QFETCH(QString, name);
        QFETCH(Eigen::Vector3d, direction);
        makeDocument(true);
        showPanel();
        // Seen from near the key, so that its point is on the front of the sphere.
        m_panel->setOrientation((direction + Eigen::Vector3d(0.3, 0.4, 0.2)).normalized(), Eigen::Vector3d::UnitY());
        m_panel->setViewDirection(direction);
        const QString readout = m_panel->readout();
        QVERIFY2(readout.startsWith(name + QLatin1Char(' ') + weightText(1.0)), qPrintable(readout));
        QVERIFY2(readout.endsWith(QStringLiteral("base ") + weightText(0.0)), qPrintable(readout));
        // Only the key itself is active: one red point.
        const QImage image = m_panel->grab().toImage().convertToFormat(QImage::Format_RGB32);
        const int red = countPixels(image, isRed);
        QVERIFY2(red > 30 && red < 140, qPrintable(QStringLiteral("red pixels: %1").arg(red)));
    }

    void emptyStatesDrawWithoutCrashing()
    {
        m_panel.reset();
        m_doc = std::make_unique<Document>();
        showPanel();
        QVERIFY(m_panel->readout().isEmpty());
        QVERIFY(!m_panel->grab().isNull());
        QVERIFY(m_panel->screenPosition(1).isNull());

        makeDocument(false);
        showPanel();
        QVERIFY(m_panel->readout().isEmpty());
        QVERIFY(m_panel->grab().save(QStringLiteral("/tmp/view_sphere_panel_empty.png")));

        // A key added later shows up; disabling it empties the sphere again.
        KeyViewpoint key;
        key.name = QStringLiteral("front");
        const ObjectId id = m_doc->keys().addKey(key);
        QVERIFY(!m_panel->screenPosition(id).isNull());
        m_doc->keys().setKeyEnabled(id, false);
        QVERIFY(m_panel->screenPosition(id).isNull());
        QVERIFY(m_panel->readout().isEmpty());
        QVERIFY(!m_panel->grab().isNull());
        m_doc->undoStack()->undo();
        QVERIFY(!m_panel->screenPosition(id).isNull());
        QVERIFY(!m_panel->grab().isNull());

        // A zero view direction is "no view": base model, nothing blended.
        m_panel->setViewDirection(Eigen::Vector3d::Zero());
        QCOMPARE(m_panel->readout(), QStringLiteral("base ") + weightText(1.0));
        QVERIFY(!m_panel->grab().isNull());
    }

    void outsideTheKeysShowsFalloff()
    {
        makeDocument(true);
        m_doc->look().setUnspecifiedMode(UnspecifiedMode::Cosine);
        showPanel();
        const Eigen::Vector3d away = Eigen::Vector3d(0.1, -0.3, -1.0).normalized();
        m_panel->setViewDirection(away);
        const auto blend = m_doc->blender().weights(m_doc->data(), away);
        // Every key has z >= 0 and side and left are opposite, so the origin lies on the keys'
        // hull, not inside it: only directions in the keys' cone are covered, and away (z < 0)
        // is not. Its nearest covered direction is the side key (+X), so the blend is side alone,
        // faded by c = away . side (about 0.095), the rest going to the base model.
        QCOMPARE(blend.raw.facet, -1);
        const double c = away.dot(Eigen::Vector3d::UnitX());
        QVERIFY2(std::abs(blend.raw.falloff - c) < 1e-9, qPrintable(QString::number(blend.raw.falloff)));
        QCOMPARE(int(blend.shares.size()), 1);
        QCOMPARE(blend.shares.front().key, m_ids[QStringLiteral("side")]);
        QVERIFY2(
            std::abs(blend.shares.front().weight - c) < 1e-9, qPrintable(QString::number(blend.shares.front().weight)));
        QVERIFY2(std::abs(blend.baseShare - (1.0 - c)) < 1e-9, qPrintable(QString::number(blend.baseShare)));

        const QImage image = m_panel->grab().toImage().convertToFormat(QImage::Format_RGB32);
        image.save(QStringLiteral("/tmp/view_sphere_panel_falloff.png"));
        QVERIFY(countPixels(image, isOrange) > 20);
        const QString readout = m_panel->readout();
        QVERIFY2(readout.startsWith(QStringLiteral("side ") + weightText(c)), qPrintable(readout));
        QVERIFY2(readout.endsWith(QStringLiteral("base ") + weightText(1.0 - c)), qPrintable(readout));
    }

    void doubleClickOnKeyEmitsItsId()
    {
        makeDocument(true);
        showPanel();
        m_panel->setViewDirection(kInsideView);
        QSignalSpy spy(m_panel.get(), &ViewSpherePanel::keyActivated);
        for (const QString& name : {QStringLiteral("front"), QStringLiteral("side"), QStringLiteral("top")}) {
            const QPointF at = m_panel->screenPosition(m_ids[name]);
            QVERIFY(!at.isNull());
            QVERIFY(m_panel->rect().contains(at.toPoint()));
            spy.clear();
            QTest::mouseDClick(m_panel.get(), Qt::LeftButton, {}, at.toPoint());
            QCOMPARE(spy.count(), 1);
            QCOMPARE(spy.front().front().value<ObjectId>(), m_ids[name]);
        }
        // Empty space activates nothing.
        spy.clear();
        QTest::mouseDClick(m_panel.get(), Qt::LeftButton, {}, QPoint(3, 3));
        QCOMPARE(spy.count(), 0);
    }

    void tooltipNamesTheKey()
    {
        makeDocument(true);
        showPanel();
        m_panel->setViewDirection(kInsideView);
        const QPoint at = m_panel->screenPosition(m_ids[QStringLiteral("side")]).toPoint();
        QHelpEvent help(QEvent::ToolTip, at, m_panel->mapToGlobal(at));
        QApplication::sendEvent(m_panel.get(), &help);
        QTRY_VERIFY(QToolTip::isVisible());
        QVERIFY2(QToolTip::text().contains(QStringLiteral("side")), qPrintable(QToolTip::text()));
        QToolTip::hideText();
    }

    void dragOrbitsUntilDoubleClickOnEmptySpace()
    {
        makeDocument(true);
        showPanel();
        const ObjectId front = m_ids[QStringLiteral("front")];
        const QPointF before = m_panel->screenPosition(front);
        const QPoint start(150, 140);
        QTest::mousePress(m_panel.get(), Qt::LeftButton, {}, start);
        for (int i = 1; i <= 10; ++i)
            QTest::mouseMove(m_panel.get(), start + QPoint(4 * i, 0));
        QTest::mouseRelease(m_panel.get(), Qt::LeftButton, {}, start + QPoint(40, 0));
        QVERIFY(m_panel->isOrbitedByUser());
        const QPointF after = m_panel->screenPosition(front);
        // The grabbed surface follows the mouse: a front key moves right.
        QVERIFY2(after.x() > before.x() + 10, qPrintable(QStringLiteral("%1 -> %2").arg(before.x()).arg(after.x())));

        // The viewport's orientation does not override the user's orbit...
        const Eigen::Vector3d orbited = m_panel->drawnViewFrom();
        m_panel->setOrientation(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
        QVERIFY(m_panel->drawnViewFrom().isApprox(orbited));
        // ...until the user double-clicks empty space.
        QTest::mouseDClick(m_panel.get(), Qt::LeftButton, {}, QPoint(3, 3));
        QVERIFY(!m_panel->isOrbitedByUser());
        QVERIFY(m_panel->drawnViewFrom().isApprox(Eigen::Vector3d::UnitZ()));
        // Seen straight from the front, the front key sits at the centre of the circle.
        const QPointF centred = m_panel->screenPosition(front);
        QVERIFY(std::abs(centred.x() - m_panel->width() / 2.0) < 1.0);
    }
};

int main(int argc, char** argv)
{
    // Pure QPainter: the offscreen platform needs no X server and paints the same everywhere.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    TestViewSpherePanel test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_view_sphere_panel.moc"
