// Imports of third-party formats in a child process (celform/model/io/import_process.h): however the child
// ends (a crash, the time or memory limit, a refusal, nonsense), the caller gets one IoError line
// naming the file, the document stays as it was, and what crosses between the processes is whole.
#include "celform/model/document/document.h"
#include "celform/model/io/image_io.h"
#include "celform/model/io/import_process.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "test_support.h"

#include <QBuffer>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtEndian>
#include <QtTest/QtTest>

using celform::model::decodeImage;
using celform::model::ImportIsolation;
using celform::model::importLimits;
using celform::model::importMesh;
using celform::model::IoError;
using celform::model::MeshImport;

namespace {

QString writeFile(const QString& path, const QByteArray& bytes, bool executable = false)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    if (executable)
        f.setPermissions(f.permissions() | QFileDevice::ExeOwner);
    return path;
}

/// Two triangles with a material each, and a line (which the reader skips with a warning).
QByteArray twoMaterialGltf()
{
    QByteArray buffer;
    auto put = [&](auto value) {
        char b[sizeof value];
        qToLittleEndian(value, b);
        buffer.append(b, sizeof value);
    };
    for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f})
        put(c);
    for (quint16 i : {0, 1, 2, 1, 3, 2, 0, 3})
        put(i);
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0},
                               {"attributes":{"POSITION":0},"indices":2,"material":1},
                               {"attributes":{"POSITION":0},"indices":3,"mode":1}]}],
      "materials":[{"name":"red","pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1]}},
                   {"name":"blue","pbrMetallicRoughness":{"baseColorFactor":[0,0,1,1]}}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},
                   {"bufferView":2,"componentType":5123,"count":3,"type":"SCALAR"},
                   {"bufferView":3,"componentType":5123,"count":2,"type":"SCALAR"}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":6},
                     {"buffer":0,"byteOffset":54,"byteLength":6},{"buffer":0,"byteOffset":60,"byteLength":4}],
      "buffers":[{"byteLength":64,"uri":"data:application/octet-stream;base64,)"
        + buffer.toBase64() + R"("}]})";
}

/// An 8-bit RGB PSD of w x h pixels without layers, raw: red ramps with x, green with y, blue 7.
QByteArray rgbPsd(int w, int h)
{
    QByteArray out("8BPS");
    auto put16 = [&](quint16 v) { out.append(char(v >> 8)).append(char(v & 0xff)); };
    auto put32 = [&](quint32 v) { put16(quint16(v >> 16)), put16(quint16(v & 0xffff)); };
    put16(1);
    out.append(6, '\0');
    put16(3);
    put32(quint32(h));
    put32(quint32(w));
    put16(8);
    put16(3); // RGB
    put32(0); // colour mode data
    put32(0); // image resources
    put32(0); // layers and masks
    put16(0); // raw
    for (int c = 0; c < 3; ++c)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                out.append(char(c == 0 ? x * 255 / (w - 1) : c == 1 ? y * 255 / (h - 1) : 7));
    return out;
}

/// The IoError work throws; one naming no file (which the callers' checks then fail on) if none.
template <typename Work> IoError ioErrorOf(Work work)
{
    try {
        work();
    } catch (const IoError& e) {
        return e;
    }
    return IoError(QString(), QStringLiteral("no IoError"));
}

/// Sets environment variables for one test and puts back what was there before.
class Environment {
public:
    void set(const char* name, const QByteArray& value)
    {
        if (!m_saved.contains(name))
            m_saved.insert(name, qEnvironmentVariableIsSet(name) ? std::optional(qgetenv(name)) : std::nullopt);
        qputenv(name, value);
    }
    void restore()
    {
        for (auto it = m_saved.cbegin(); it != m_saved.cend(); ++it) {
            if (it.value())
                qputenv(it.key().constData(), *it.value());
            else
                qunsetenv(it.key().constData());
        }
        m_saved.clear();
    }

private:
    QMap<QByteArray, std::optional<QByteArray>> m_saved;
};

} // namespace

class TestImportProcess : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup() { m_environment.restore(); }
    void limitsFromEnvironment();
    void meshCrossesWhole();
    void transferCarriesUvsAndMaterials();
    void psdCrossesWhole();
    void drawingsShareOneChild();
    void psdHeaderReadHere();
    void batchFailureNamesTheDrawing();
    void childEndings_data();
    void childEndings();
    void memoryLimit();
    void documentUnchangedAfterCrash();

private:
    QString script(const QString& name, const QByteArray& body)
    {
        return writeFile(m_dir.filePath(name), "#!/bin/sh\n" + body + "\n", true);
    }

    QTemporaryDir m_dir;
    Environment m_environment;
    QString m_gltf;
    QString m_psd;
};

void TestImportProcess::init()
{
    QVERIFY(m_dir.isValid());
    m_gltf = writeFile(m_dir.filePath(QStringLiteral("two.gltf")), twoMaterialGltf());
    m_psd = writeFile(m_dir.filePath(QStringLiteral("ramp.psd")), rgbPsd(16, 8));
    QVERIFY2(!celform::model::importProgram().isEmpty(), "no celform to run as the importer");
}

void TestImportProcess::limitsFromEnvironment()
{
    m_environment.set("CELFORM_IMPORT_MEMORY_MB", "");
    m_environment.set("CELFORM_IMPORT_SECONDS", "");
    QCOMPARE(importLimits().memoryBytes, qint64(4) << 30);
    QCOMPARE(importLimits().seconds, 60);
    m_environment.set("CELFORM_IMPORT_MEMORY_MB", "1536");
    m_environment.set("CELFORM_IMPORT_SECONDS", " 5 ");
    QCOMPARE(importLimits().memoryBytes, qint64(1536) << 20);
    QCOMPARE(importLimits().seconds, 5);
    m_environment.set("CELFORM_IMPORT_MEMORY_MB", "-1");
    m_environment.set("CELFORM_IMPORT_SECONDS", "soon");
    QCOMPARE(importLimits().memoryBytes, qint64(4) << 30);
    QCOMPARE(importLimits().seconds, 60);
}

// What Assimp read in the child is what it reads in this process: positions, faces, materials
// with their colours, each face's material, and the reader's warnings.
void TestImportProcess::meshCrossesWhole()
{
    const MeshImport here = importMesh(m_gltf, ImportIsolation::ThisProcess);
    const MeshImport there = importMesh(m_gltf);
    QCOMPARE(here.mesh.faceCount(), 2);
    QCOMPARE(int(here.mesh.materials.size()), 3); // red, blue and Assimp's default for the line
    QCOMPARE(here.mesh.materials[1].baseColor, Eigen::Vector3f(0, 0, 1));
    QVERIFY2(here.warnings.join('|').contains(QStringLiteral("1 point or line ignored")),
        qPrintable(here.warnings.join('|')));
    QVERIFY(there.mesh == here.mesh);
    QCOMPARE(there.warnings, here.warnings);
}

// The transfer file carries UVs too (no Assimp format gives them today): a stand-in importer reads
// an OBJ with UVs and materials and hands it back for a glTF.
void TestImportProcess::transferCarriesUvsAndMaterials()
{
    const QString obj = writeFile(m_dir.filePath(QStringLiteral("uv.obj")),
        "mtllib uv.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
        "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 2/2 4/4 3/3\nf 1 2\n");
    writeFile(m_dir.filePath(QStringLiteral("uv.mtl")), "newmtl a\nKd 1 0.5 0\nnewmtl b\nKd 0 0.5 1\n");
    const MeshImport here = importMesh(obj, ImportIsolation::ThisProcess);
    QVERIFY(here.mesh.hasUvs());
    QCOMPARE(int(here.mesh.materials.size()), 2);
    QVERIFY(!here.warnings.isEmpty());
    m_environment.set("CELFORM_EXECUTABLE",
        QFile::encodeName(script(QStringLiteral("stand-in"),
            "exec '" + QFile::encodeName(celform::model::importProgram()) + "' import-mesh -- '"
                + QFile::encodeName(obj) + "' \"$4\"")));
    const MeshImport there = importMesh(m_gltf);
    QVERIFY(there.mesh == here.mesh);
    // The reader's warnings cross; the parent adds its topology warning in front of them again.
    QCOMPARE(there.warnings.mid(1), here.warnings.mid(1));
}

// OpenImageIO's PSD reader runs in the child; the pixels come back as it decodes them here.
void TestImportProcess::psdCrossesWhole()
{
    QFile file(m_psd);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    const QImage here = decodeImage(bytes, QStringLiteral("psd"), m_psd, ImportIsolation::ThisProcess);
    const QImage there = decodeImage(bytes, QStringLiteral("psd"), m_psd);
    QCOMPARE(here.size(), QSize(16, 8));
    QCOMPARE(qRed(here.pixel(15, 0)), 255);
    QCOMPARE(qGreen(here.pixel(0, 7)), 255);
    QCOMPARE(qBlue(here.pixel(3, 3)), 7);
    QCOMPARE(there.format(), here.format());
    QVERIFY(there == here);
}

// A project's drawings are decoded together: one child (OpenImageIO loaded once) for the PSDs,
// the PNG here; each image as decodeImage() gives it alone.
void TestImportProcess::drawingsShareOneChild()
{
    const QByteArray small = rgbPsd(16, 8), large = rgbPsd(40, 30);
    QImage png(5, 4, QImage::Format_RGBA8888);
    png.fill(QColor(10, 20, 30));
    QByteArray pngBytes;
    QBuffer buffer(&pngBytes);
    QVERIFY(buffer.open(QIODevice::WriteOnly) && png.save(&buffer, "PNG"));
    // A stand-in that counts its runs before it runs the real importer.
    const QString runs = m_dir.filePath(QStringLiteral("runs"));
    m_environment.set("CELFORM_EXECUTABLE",
        QFile::encodeName(script(QStringLiteral("counting"),
            "echo run >> '" + QFile::encodeName(runs) + "'; exec '" + QFile::encodeName(celform::model::importProgram())
                + "' \"$@\"")));
    const std::vector<QImage> decoded = celform::model::decodeImages(
        {{small, QStringLiteral("psd"), QStringLiteral("a")}, {pngBytes, QStringLiteral("png"), QStringLiteral("b")},
            {large, QStringLiteral("PSD"), QStringLiteral("c")}});
    QCOMPARE(int(decoded.size()), 3);
    QVERIFY(decoded[0] == decodeImage(small, QStringLiteral("psd"), QStringLiteral("a"), ImportIsolation::ThisProcess));
    QCOMPARE(decoded[1].pixel(4, 3), qRgba(10, 20, 30, 255));
    QVERIFY(decoded[2] == decodeImage(large, QStringLiteral("psd"), QStringLiteral("c"), ImportIsolation::ThisProcess));
    QFile counted(runs);
    QVERIFY(counted.open(QIODevice::ReadOnly));
    QCOMPARE(counted.readAll(), QByteArray("run\n"));
}

// A PSD's size comes from its header, read in this process: `celform info` starts no child for it,
// and a header stating too many pixels is refused before one is started.
void TestImportProcess::psdHeaderReadHere()
{
    m_environment.set("CELFORM_EXECUTABLE", "/nonexistent/celform");
    QCOMPARE(celform::model::decodedImageSize(rgbPsd(16, 8), QStringLiteral("psd"), QStringLiteral("a")), QSize(16, 8));
    QByteArray bomb = rgbPsd(16, 8);
    bomb[14] = bomb[18] = char(0x7f); // over two billion pixels a side
    const IoError e = ioErrorOf([&] { decodeImage(bomb, QStringLiteral("psd"), QStringLiteral("bomb")); });
    QCOMPARE(e.file(), QStringLiteral("bomb"));
    QVERIFY2(e.problem().startsWith(QStringLiteral("the image is too large")), qPrintable(e.message()));
}

// When the shared child fails, each drawing is decoded alone, so that the error names the one that
// fails: a damaged PSD, or (with an importer that crashes) the first.
void TestImportProcess::batchFailureNamesTheDrawing()
{
    const QByteArray good = rgbPsd(16, 8);
    const QByteArray damaged = good.left(40);
    const std::vector<celform::model::EncodedImage> images{{good, QStringLiteral("psd"), QStringLiteral("first")},
        {damaged, QStringLiteral("psd"), QStringLiteral("second")},
        {good, QStringLiteral("tif"), QStringLiteral("third")}};
    IoError e = ioErrorOf([&] { celform::model::decodeImages(images); });
    QCOMPARE(e.file(), QStringLiteral("second"));
    QVERIFY2(!e.problem().contains(QStringLiteral("the importer")), qPrintable(e.message())); // the decoder's words
    m_environment.set("CELFORM_EXECUTABLE", QFile::encodeName(script(QStringLiteral("crash"), "kill -SEGV $$")));
    e = ioErrorOf([&] { celform::model::decodeImages(images); });
    QCOMPARE(e.file(), QStringLiteral("first"));
    QVERIFY2(e.problem().startsWith(QStringLiteral("the importer crashed")), qPrintable(e.message()));
}

void TestImportProcess::childEndings_data()
{
    // A stand-in for the importer (CELFORM_EXECUTABLE), run as `PROGRAM import-... -- FILE OUT`.
    QTest::addColumn<QByteArray>("program");
    QTest::addColumn<QByteArray>("seconds"); // CELFORM_IMPORT_SECONDS
    QTest::addColumn<QString>("expected"); // the problem, or its start
    const QStringList kinds{QStringLiteral("mesh"), QStringLiteral("image")};
    for (const QString& kind : kinds) {
        const auto row = [&](const char* name) -> QTestData& { return QTest::addRow("%s %s", qPrintable(kind), name); };
        row("crash") << QByteArray("kill -SEGV $$") << QByteArray("10")
                     << "the importer crashed on it (signal 11, Segmentation fault)";
        row("abort") << QByteArray("kill -ABRT $$") << QByteArray("10")
                     << "the importer crashed on it (signal 6, Aborted)";
        row("hang") << QByteArray("exec sleep 60") << QByteArray("1")
                    << "the importer took longer than 1 s and was stopped (the limit is CELFORM_IMPORT_SECONDS)";
        row("processor time") << QByteArray("kill -XCPU $$") << QByteArray("10")
                              << "the importer used more than 25 s of processor time and was stopped";
        row("out of memory") << QByteArray("exit 4") << QByteArray("10")
                             << "the importer needs more than 2 GB of memory for it and was stopped (the limit is "
                                "CELFORM_IMPORT_MEMORY_MB)";
        row("refusal") << QByteArray("echo 'a warning first' >&2; echo 'the scene is upside down' >&2; exit 3")
                       << QByteArray("10") << "the scene is upside down";
        row("silent refusal") << QByteArray("exit 3") << QByteArray("10") << "the importer refused it";
        row("unknown exit") << QByteArray("echo 'no such option' >&2; exit 9") << QByteArray("10")
                            << "the importer failed on it (exit code 9): no such option";
        row("no result") << QByteArray("exit 0") << QByteArray("10") << "the importer's result";
        // OUT is a file for a mesh, a folder for images.
        row("garbage result") << QByteArray(
            "f=\"$4\"; [ -d \"$f\" ] && f=\"$f/0.pixels\"; head -c 100 /dev/urandom > \"$f\"")
                              << QByteArray("10") << "the importer's result is damaged";
        row("missing program") << QByteArray() << QByteArray("10") << "cannot be read: the importer (";
    }
}

// However the importer ends, the caller gets an IoError naming the file, in one line, in time.
void TestImportProcess::childEndings()
{
    QFETCH(QByteArray, program);
    QFETCH(QByteArray, seconds);
    QFETCH(QString, expected);
    const QString name = QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-'));
    m_environment.set("CELFORM_EXECUTABLE",
        program.isEmpty() ? QByteArray("/nonexistent/celform") : QFile::encodeName(script(name, program)));
    m_environment.set("CELFORM_IMPORT_SECONDS", seconds);
    m_environment.set("CELFORM_IMPORT_MEMORY_MB", "2048");
    const bool mesh = QByteArray(QTest::currentDataTag()).startsWith("mesh");
    const QString path = mesh ? m_gltf : m_psd;
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    QElapsedTimer timer;
    timer.start();
    const IoError e = ioErrorOf([&] {
        if (mesh)
            importMesh(path);
        else
            decodeImage(bytes, QStringLiteral("psd"), path);
    });
    QVERIFY2(timer.elapsed() < 10000, qPrintable(QString::number(timer.elapsed())));
    QCOMPARE(e.file(), path);
    QVERIFY2(e.problem().startsWith(expected), qPrintable(e.message()));
    QVERIFY2(!e.message().contains(QLatin1Char('\n')), qPrintable(e.message()));
}

// The real child under a real memory limit: Assimp's endless index loop (a DAE found by fuzzing)
// grows until an allocation fails, which ends the child with the out-of-memory code.
void TestImportProcess::memoryLimit()
{
    m_environment.set("CELFORM_IMPORT_MEMORY_MB", "1024");
    m_environment.set("CELFORM_IMPORT_SECONDS", "60");
    const QString path = celform::test::testDataPath(
        QStringLiteral("fuzz-regressions/mesh/dae-comment-in-index-list-endless-loop.dae"));
    QElapsedTimer timer;
    timer.start();
    const IoError e = ioErrorOf([&] { importMesh(path); });
    QCOMPARE(e.file(), path);
    QCOMPARE(e.problem(),
        QStringLiteral("the importer needs more than 1 GB of memory for it and was stopped (the limit is "
                       "CELFORM_IMPORT_MEMORY_MB)"));
    QVERIFY2(timer.elapsed() < 30000, qPrintable(QString::number(timer.elapsed())));
}

// A crash inside Assimp (a glTF nested 30,000 nodes deep overflows its stack)
// or inside OpenImageIO no longer takes the open document along: the import is refused, the
// document keeps its model, drawings and undo history.
void TestImportProcess::documentUnchangedAfterCrash()
{
    celform::model::Document doc;
    doc.newFromMesh(celform::test::testDataPath(QStringLiteral("fuzz-regressions/cli/tetrahedron.off")));
    doc.drawings().importDrawing(m_psd);
    const auto mesh = doc.data().baseMesh;
    const auto drawings = doc.data().drawings.size();
    const int steps = doc.undoStack()->count();
    const bool modified = doc.isModified();

    const QString nested = celform::test::testDataPath(
        QStringLiteral("fuzz-regressions/mesh/gltf-30000-nested-nodes-stack-overflow.gltf"));
    const IoError e = ioErrorOf([&] { doc.importBaseMesh(nested); });
    QCOMPARE(e.file(), nested);
    // AddressSanitizer catches the overflow itself, reports it and aborts (signal 6).
    QVERIFY2(e.problem().startsWith(celform::test::kAddressSanitizer
                     ? QStringLiteral("the importer crashed on it (signal 6")
                     : QStringLiteral("the importer crashed on it (signal 11")),
        qPrintable(e.message()));
    m_environment.set("CELFORM_EXECUTABLE", QFile::encodeName(script(QStringLiteral("crash"), "kill -SEGV $$")));
    QVERIFY_THROWS_EXCEPTION(IoError, doc.drawings().importDrawing(m_psd));

    QCOMPARE(doc.data().baseMesh, mesh);
    QCOMPARE(doc.data().drawings.size(), drawings);
    QCOMPARE(doc.undoStack()->count(), steps);
    QCOMPARE(doc.isModified(), modified);
}

QTEST_GUILESS_MAIN(TestImportProcess)
#include "test_import_process.moc"
