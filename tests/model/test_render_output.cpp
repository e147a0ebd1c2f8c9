// The document's highlight tracks resolved for the renderer (model::renderHighlightsFor): patch
// masks, smoothed normals and frames, and the cache that keeps a track's per-vertex geometry across
// parameter edits and frames without changing a single value.
#include "test_meshes.h"

#include "celform/model/data/project_data.h"
#include "celform/model/render/render_output.h"

#include <QtTest/QtTest>

using namespace celform;

namespace {

model::ProjectData sphereWithTracks()
{
    model::ProjectData data;
    data.baseMesh = test::icosphere(3);
    std::vector<std::int32_t> upper;
    for (Eigen::Index f = 0; f < data.baseMesh->faceCount(); ++f)
        if (data.baseMesh->vertices(data.baseMesh->faces(f, 0), 1) > 0.0f)
            upper.push_back(std::int32_t(f));
    data.faceSets.push_back({"upper", upper});
    for (const char* name : {"plain", "smooth"}) {
        model::HighlightTrack t;
        t.name = QString::fromLatin1(name);
        t.patch = QStringLiteral("upper");
        t.smoothing = t.name == QLatin1String("smooth") ? 5 : 0;
        algo::HighlightLayer key0, key10;
        key10.shape.epsilon = 0.2f;
        t.setKey(0, key0);
        t.setKey(10, key10);
        data.look.highlights.push_back(t);
    }
    return data;
}

void compareGeometry(const std::vector<algo::RenderHighlight>& a, const std::vector<algo::RenderHighlight>& b)
{
    QCOMPARE(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        QVERIFY(a[i].layer == b[i].layer);
        QVERIFY(a[i].faceMask == b[i].faceMask);
        QVERIFY(a[i].normals.rows() == b[i].normals.rows() && a[i].normals == b[i].normals);
        QVERIFY(a[i].du == b[i].du && a[i].dv == b[i].dv);
    }
}

} // namespace

class TestRenderOutput : public QObject {
    Q_OBJECT

private slots:
    void tracksResolveWithPatchAndSmoothing()
    {
        const model::ProjectData data = sphereWithTracks();
        const auto layers = model::renderHighlightsFor(data, data.look, data.baseMesh->vertices, 5);
        QCOMPARE(layers.size(), std::size_t(2));
        QCOMPARE(layers[0].layer.shape.epsilon, 0.5f * (0.05f + 0.2f)); // halfway between the keys
        QCOMPARE(layers[0].normals.rows(), Eigen::Index(0)); // no smoothing: the surface's normals
        QCOMPARE(layers[1].normals.rows(), data.baseMesh->vertexCount());
        // Outside the patch: no face, zero frames and normals.
        const auto& mesh = *data.baseMesh;
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
            const bool lower = (mesh.vertices.row(mesh.faces(f, 0)).y() < -0.5f
                && mesh.vertices.row(mesh.faces(f, 1)).y() < -0.5f && mesh.vertices.row(mesh.faces(f, 2)).y() < -0.5f);
            if (lower) {
                QCOMPARE(int(layers[1].faceMask[std::size_t(f)]), 0);
                QCOMPARE(layers[1].normals.row(mesh.faces(f, 0)).norm(), 0.0f);
                QCOMPARE(layers[1].du.row(mesh.faces(f, 0)).norm(), 0.0f);
            }
        }
    }

    void cacheKeepsGeometryAndFollowsChanges()
    {
        model::ProjectData data = sphereWithTracks();
        const algo::Positions& shape = data.baseMesh->vertices;
        algo::RenderCache cache;
        // The shapes are known by their generations (algo::Shape), as the viewport's and the
        // renderer's are: no pass over the positions to recognise them.
        const std::uint64_t still = algo::newShapeGeneration();
        // Cold and warm cache give exactly what no cache gives, at every frame.
        for (int frame : {0, 5, 10}) {
            const auto reference = model::renderHighlightsFor(data, data.look, shape, frame);
            compareGeometry(model::renderHighlightsFor(data, data.look, shape, frame, &cache, still), reference);
            compareGeometry(model::renderHighlightsFor(data, data.look, shape, frame, &cache, still), reference);
        }
        QCOMPARE(cache.highlights.size(), std::size_t(2)); // one entry per track: the keys play no part
        // A new guide, smoothing, patch or shape is a new entry, and the result follows it.
        data.look.highlights[1].guide = Eigen::Vector3f(1.0f, 0.0f, 0.0f);
        data.look.highlights[1].smoothing = 2;
        compareGeometry(model::renderHighlightsFor(data, data.look, shape, 0, &cache, still),
            model::renderHighlightsFor(data, data.look, shape, 0));
        QCOMPARE(cache.highlights.size(), std::size_t(3));
        algo::Positions moved = shape;
        moved.col(0) *= 1.5f;
        compareGeometry(model::renderHighlightsFor(data, data.look, moved, 0, &cache, algo::newShapeGeneration()),
            model::renderHighlightsFor(data, data.look, moved, 0));
        data.faceSets[0].faces.resize(data.faceSets[0].faces.size() / 2);
        compareGeometry(model::renderHighlightsFor(data, data.look, shape, 0, &cache, still),
            model::renderHighlightsFor(data, data.look, shape, 0));
        // Bounded: old entries go.
        for (int i = 0; i < 20; ++i) {
            data.look.highlights[0].guide = Eigen::Vector3f(1.0f, float(i), 0.0f);
            model::renderHighlightsFor(data, data.look, shape, 0, &cache, still);
        }
        QVERIFY(cache.highlights.size() <= 8);
    }
};

QTEST_GUILESS_MAIN(TestRenderOutput)
#include "test_render_output.moc"
