// Sub-commands of `celform`. Each parses its own options, works on a Document, prints JSON with
// --json, and reports bad input as one line naming the file and the problem (exit 3).
#include "cli.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/model/project_file.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <cstdio>
#include <exception>
#include <new>

namespace celform::app {
namespace {

// Gives lupdate the context "celform::app::Cli" for every Cli::tr() below.
struct Cli {
    Q_DECLARE_TR_FUNCTIONS(celform::app::Cli)
};

const QStringList kSubCommands = {QStringLiteral("new"), QStringLiteral("info")};

/// Thrown for a usage error; main turns it into exit code 2 with the message and a hint.
struct UsageError {
    QString message;
};

void printErr(const QString& line)
{
    QTextStream(stderr) << line << Qt::endl;
}
void printOut(const QString& text)
{
    QTextStream(stdout) << text;
}

QJsonArray vec3(const Eigen::Vector3d& v)
{
    return {v.x(), v.y(), v.z()};
}

/// Parses sub-command options; unknown options and a wrong number of positional arguments
/// are usage errors.
void parseOrThrow(QCommandLineParser& parser, const QStringList& args, int positionalCount, const QString& synopsis)
{
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    parser.addHelpOption();
    if (!parser.parse(args))
        throw UsageError{parser.errorText() + QLatin1Char('\n') + Cli::tr("usage: %1").arg(synopsis)};
    if (parser.isSet(QStringLiteral("help"))) {
        printOut(parser.helpText());
        throw UsageError{}; // help printed: exit 0 is handled by the caller through an empty message
    }
    if (parser.positionalArguments().size() != positionalCount)
        throw UsageError{Cli::tr("usage: %1").arg(synopsis)};
}

int commandNew(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Creates a project from a mesh file."));
    parser.addPositionalArgument(QStringLiteral("MESH"), Cli::tr("Mesh file (OBJ, PLY, STL, OFF, glTF, GLB)."));
    const QCommandLineOption out(QStringLiteral("out"), Cli::tr("Project file to write."), QStringLiteral("P.celform"));
    const QCommandLineOption drawing(
        QStringLiteral("drawing"), Cli::tr("Reference drawing to embed (repeatable)."), QStringLiteral("IMAGE"));
    parser.addOptions({out, drawing});
    parseOrThrow(parser, args, 1, QStringLiteral("celform new MESH --out P.celform [--drawing IMAGE]..."));
    if (!parser.isSet(out))
        throw UsageError{Cli::tr("--out is required\nusage: %1")
                             .arg(QStringLiteral("celform new MESH --out P.celform [--drawing IMAGE]..."))};

    model::Document doc;
    const QStringList warnings = doc.newFromMesh(parser.positionalArguments().front());
    for (const QString& w : warnings)
        printErr(Cli::tr("warning: %1: %2").arg(parser.positionalArguments().front(), w));
    for (const QString& image : parser.values(drawing))
        doc.importDrawing(image);
    doc.saveAs(parser.value(out));
    return kExitOk;
}

QJsonObject cameraJson(const model::Camera& c)
{
    return {{"eye", vec3(c.eye)}, {"target", vec3(c.target)}, {"up", vec3(c.up)}, {"right", vec3(c.right())},
        {"true_up", vec3(c.trueUp())}, {"forward", vec3(c.forward())},
        {"projection", c.projection == model::Projection::Perspective ? "perspective" : "orthographic"},
        {"fov_y_degrees", c.fovYDegrees}, {"ortho_height", c.orthoHeight}};
}

int commandInfo(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Prints what a project holds."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print machine-readable JSON."));
    parser.addOption(json);
    parseOrThrow(parser, args, 1, QStringLiteral("celform info P.celform [--json]"));

    const QString path = parser.positionalArguments().front();
    const model::ProjectData data = model::loadProject(path);

    QJsonObject root{{"file", QFileInfo(path).absoluteFilePath()}, {"format_version", model::kProjectFormatVersion}};
    if (data.baseMesh) {
        const auto& mesh = *data.baseMesh;
        const auto box = algo::boundingBox(mesh.vertices);
        root.insert("base_mesh",
            QJsonObject{{"name", data.baseMeshName}, {"vertex_count", double(mesh.vertexCount())},
                {"triangle_count", double(mesh.faceCount())},
                {"bounding_box", QJsonObject{{"min", vec3(box.min())}, {"max", vec3(box.max())}}},
                {"centroid", vec3(algo::centroid(mesh.vertices))}, {"has_uvs", mesh.hasUvs()},
                {"materials", double(mesh.materials.size())}, {"face_sets", double(mesh.faceSets.size())}});
    } else {
        root.insert("base_mesh", QJsonValue::Null);
    }
    QJsonArray drawings;
    for (const auto& d : data.drawings) {
        QJsonObject o{{"id", double(d.id)}, {"name", d.name}, {"format", d.imageFormat}, {"width", d.image.width()},
            {"height", d.image.height()}, {"bytes", double(d.imageData.size())}, {"opacity", d.opacity},
            {"frame", d.frame}, {"aligned", d.aligned}};
        if (d.aligned)
            o.insert("camera", cameraJson(d.camera));
        drawings.append(o);
    }
    root.insert("drawings", drawings);
    QJsonArray keys;
    for (const auto& k : data.keys) {
        QJsonArray frames, linked;
        for (const auto& [frame, offsets] : k.offsetsByFrame)
            frames.append(QJsonObject{{"frame", frame}, {"moved_vertices", double(offsets.indices.size())}});
        for (auto id : k.drawingIds)
            if (const auto* d = data.drawing(id))
                linked.append(d->name);
        keys.append(QJsonObject{{"id", double(k.id)}, {"name", k.name}, {"direction", vec3(k.direction)},
            {"enabled", k.enabled}, {"camera", cameraJson(k.camera)}, {"drawings", linked}, {"frames", frames}});
    }
    root.insert("key_viewpoints", keys);
    const char* unspecified[] = {"dummy", "cosine", "cosine2"};
    root.insert("blend",
        QJsonObject{{"sharpness", data.blend.sharpness}, {"unspecified", unspecified[int(data.blend.unspecified)]}});

    if (parser.isSet(json)) {
        printOut(QString::fromUtf8(QJsonDocument(root).toJson(QJsonDocument::Indented)));
        return kExitOk;
    }
    QString text;
    QTextStream s(&text);
    s << Cli::tr("Project: %1 (format %2)").arg(path).arg(model::kProjectFormatVersion) << '\n';
    if (data.baseMesh) {
        const auto& m = root["base_mesh"].toObject();
        s << Cli::tr("Base model: %1, %2 vertices, %3 triangles")
                 .arg(data.baseMeshName)
                 .arg(qint64(m["vertex_count"].toDouble()))
                 .arg(qint64(m["triangle_count"].toDouble()))
          << '\n';
    } else {
        s << Cli::tr("Base model: none") << '\n';
    }
    s << Cli::tr("Drawings: %1").arg(data.drawings.size()) << '\n';
    for (const auto& d : data.drawings)
        s << "  " << d.name << " (" << d.image.width() << "x" << d.image.height() << ' ' << d.imageFormat << ")\n";
    s << Cli::tr("Key viewpoints: %1").arg(data.keys.size()) << '\n';
    for (const auto& k : data.keys)
        s << "  " << k.name << " (" << k.direction.x() << ", " << k.direction.y() << ", " << k.direction.z() << ")\n";
    printOut(text);
    return kExitOk;
}

} // namespace

bool isCommandLineInvocation(const QStringList& arguments)
{
    if (arguments.size() < 2)
        return false;
    const QString& first = arguments.at(1);
    return kSubCommands.contains(first) || first == QLatin1String("--version") || first == QLatin1String("-v")
        || first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help");
}

int runCommandLine(const QStringList& arguments)
{
    const QString first = arguments.value(1);
    const QString usage = Cli::tr("usage: celform [PROJECT] [--screenshot FILE.png]\n"
                             "       celform new MESH --out P.celform [--drawing IMAGE]...\n"
                             "       celform info P.celform [--json]\n"
                             "       celform --version");
    try {
        if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
            printOut(QStringLiteral("celform %1\n").arg(QCoreApplication::applicationVersion()));
            return kExitOk;
        }
        if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
            printOut(usage + QLatin1Char('\n'));
            return kExitOk;
        }
        // QCommandLineParser wants the program name first.
        QStringList rest = arguments.mid(1);
        rest[0] = QStringLiteral("celform ") + first;
        if (first == QLatin1String("new"))
            return commandNew(rest);
        if (first == QLatin1String("info"))
            return commandInfo(rest);
        printErr(usage);
        return kExitUsage;
    } catch (const UsageError& e) {
        if (e.message.isEmpty())
            return kExitOk; // --help
        printErr(QStringLiteral("celform: ") + e.message);
        return kExitUsage;
    } catch (const model::IoError& e) {
        printErr(QStringLiteral("celform: ") + e.message());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        printErr(Cli::tr("celform: out of memory"));
        return kExitBadInput;
    } catch (const std::exception& e) {
        printErr(QStringLiteral("celform: ") + QString::fromLocal8Bit(e.what()));
        return kExitBadInput;
    }
}

} // namespace celform::app
