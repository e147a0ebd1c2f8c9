// BaseAnimation::evaluate: morph targets then skinning, frames held at the ends, and unused
// influences (weight 0) never read, whatever joint they name.
#include "celform/algorithms/base_animation.h"

#include <QtTest/QtTest>

using celform::algo::BaseAnimation;
using celform::algo::Positions;
using celform::algo::SkinMatrix;

class TestBaseAnimation : public QObject {
    Q_OBJECT
private slots:
    void morphThenSkin();
    void unusedInfluenceNamesAnyJoint();
};

namespace {

SkinMatrix translation(float x, float y, float z)
{
    SkinMatrix m = SkinMatrix::Zero();
    m.leftCols<3>().setIdentity();
    m.col(3) << x, y, z;
    return m;
}

} // namespace

void TestBaseAnimation::morphThenSkin()
{
    Positions rest(2, 3);
    rest << 0, 0, 0, 1, 0, 0;
    BaseAnimation a;
    a.frameCount = 2;
    Positions delta(2, 3);
    delta << 0, 1, 0, 0, 2, 0;
    a.morphTargets = {delta};
    a.morphWeights = {0.0f, 0.5f};
    a.jointCount = 2;
    a.joints = {{0, 1, 0, 0}, {1, 0, 0, 0}};
    a.jointWeights = {Eigen::Vector4f(0.5f, 0.5f, 0, 0), Eigen::Vector4f(1, 0, 0, 0)};
    a.skinMatrices = {translation(0, 0, 0), translation(0, 0, 0), translation(10, 0, 0), translation(0, 0, 4)};
    QVERIFY(a.problem(2).empty());
    Positions out;
    a.evaluate(rest, 0, out);
    QCOMPARE(out, rest);
    a.evaluate(rest, 5, out); // held at the last sample
    Positions expected(2, 3);
    expected << 5, 0.5f, 2, 1, 1, 4;
    QCOMPARE(out, expected);
    for (Eigen::Index v = 0; v < 2; ++v) // the same floats, vertex by vertex
        QCOMPARE(a.evaluateVertex(rest, 5, v), Eigen::Vector3f(out.row(v).transpose()));
}

// The first influence used to be read whatever its weight: joint 7 of 1 read past the matrices.
void TestBaseAnimation::unusedInfluenceNamesAnyJoint()
{
    Positions rest(1, 3);
    rest << 1, 2, 3;
    BaseAnimation a;
    a.frameCount = 1;
    a.jointCount = 1;
    a.joints = {{7, 0, 0, 0}};
    a.jointWeights = {Eigen::Vector4f(0, 1, 0, 0)};
    a.skinMatrices = {translation(1, 1, 1)};
    QVERIFY(a.problem(1).empty());
    Positions out;
    a.evaluate(rest, 0, out);
    Positions expected(1, 3);
    expected << 2, 3, 4;
    QCOMPARE(out, expected);
    QCOMPARE(a.evaluateVertex(rest, 0, 0), Eigen::Vector3f(2, 3, 4));
}

QTEST_APPLESS_MAIN(TestBaseAnimation)
#include "test_base_animation.moc"
