// The command line attacked from outside, as a script or a hostile user would call it: each input
// becomes one `celform SUB ...` run in a child process (the build's own binary, sanitized in the
// sanitize build) on a copy of a small project made here through the model's API, and what the
// child did is checked against README.md's promises (section "Reliability"):
// - it ends by itself with 0, 2 or 3 (the documented exit codes), never on a signal;
// - a sanitizer report in its standard error is a finding whatever its exit code;
// - 2 and 3 come with a message, and a write error names the system's reason (never "Unknown error");
// - afterwards the project copy it was given (and its .bak, when the run made one) still opens
//   with model::loadProject and keeps the loader's promises; so does a project `new` wrote.
// A run beyond the time limit (CELFORM_FUZZ_CHILD_SECONDS, default 4) is killed with its process
// group and counts as a refusal, not a finding: with a fuzzed frame range or iteration count a
// sub-command may legitimately work for minutes, and a kill must leave the project whole anyway
// (saves are atomic), which the check after the kill covers. The child's memory is capped at 4 GB
// (runChild()); a sanitizer's report of the cap is a finding unless --size asked for that much.
//
// An input has one of two forms:
// - "celform\n" and then the arguments one a line, literally (for readable seeds and reproducers):
//   "celform\ncamera\np.celform\n--turntable\n8\n--start-angle\n1e308\n";
// - anything else is read as choices: the first byte picks a sub-command of the real table
//   (app/cli's group functions, checked against subCommandNames()), the next ones walk one of its
//   synopsis lines (choosing among "(a | b)" and whether to give each "[...]"), then add a few more
//   of its options; each value is made from the option's value name and synopsis ("X,Y,Z",
//   "A-B[:STEP]", "toon|gooch|comic|lambert", "FILE.png|.exr"): numbers (small, huge, negative,
//   NaN, infinite), the project's names, words, raw bytes, or a file name in the work folder.
// The child runs in a work folder inside this process's temporary folder, holding a fresh copy of
// the project and input files; every path given is relative to it (or /dev/null, /dev/full), and
// absolute paths and ".." are taken out of raw values, so outputs stay inside. HOME, the XDG
// folders and TMPDIR point there too.
#include "cli_process.h"

#include "test_meshes.h"

#include "cli/command.h"
#include "cli/command_line.h"

#include "celform/model/data/io_error.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define CELFORM_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CELFORM_FUZZ_ASAN 1
#endif
#endif

namespace celform::fuzz {
namespace {

using app::OptionSpec;
using app::SubCommand;

[[noreturn]] void fail(const QString& message)
{
    std::fprintf(stderr, "celform fuzz (cli-process): %s\n", qPrintable(message));
    std::abort();
}

// --- the sub-command table and its synopsis lines -----------------------------------------------

/// One element of a synopsis line: a positional word, an option (with the synopsis's value text),
/// "[...]" (optional) or "(a | b)" (one of).
struct Node {
    enum Kind { Word, Option, Optional, Choice } kind = Word;
    QString text; ///< Word: the word; Option: the name without "--"
    std::vector<std::vector<Node>> alternatives; ///< Optional, Choice
};

struct Command {
    const SubCommand* spec = nullptr;
    std::vector<std::vector<Node>> lines; ///< each synopsis line, parsed
    /// Per option: the value texts the table gives it (its value name, and what each synopsis line
    /// writes after it), split at top-level '|' into alternatives.
    std::map<QString, QStringList> values;
    [[nodiscard]] const OptionSpec* option(const QString& name) const
    {
        for (const OptionSpec& o : spec->options)
            if (name == QLatin1String(o.name))
                return &o;
        return nullptr;
    }
};

/// A synopsis line's words after "celform SUB", with group brackets as words of their own. A
/// bracket inside a value ("A-B[:STEP]") stays in it: only the unbalanced ones at a word's ends
/// open or close groups; a trailing "..." (repeatable) is dropped.
QStringList synopsisTokens(const QString& line, int skip)
{
    QStringList out;
    const QStringList words = line.split(QLatin1Char(' '), Qt::SkipEmptyParts).mid(skip);
    for (QString w : words) {
        while (w.startsWith(QLatin1Char('(')) || w.startsWith(QLatin1Char('['))) {
            out << w.left(1);
            w.remove(0, 1);
        }
        QStringList closers;
        for (;;) {
            if (w.endsWith(QLatin1String("..."))) {
                w.chop(3);
                continue;
            }
            const QChar last = w.isEmpty() ? QChar() : w.back();
            const bool closesParen = last == QLatin1Char(')') && w.count(QLatin1Char(')')) > w.count(QLatin1Char('('));
            const bool closesBracket
                = last == QLatin1Char(']') && w.count(QLatin1Char(']')) > w.count(QLatin1Char('['));
            if (!closesParen && !closesBracket)
                break;
            closers.prepend(QString(last));
            w.chop(1);
        }
        if (!w.isEmpty())
            out << w;
        out << closers;
    }
    return out;
}

std::vector<std::vector<Node>> parseAlternatives(const Command& c, const QStringList& t, int& i)
{
    std::vector<std::vector<Node>> alternatives(1);
    while (i < t.size()) {
        const QString& w = t[i];
        if (w == QLatin1String(")") || w == QLatin1String("]"))
            break;
        ++i;
        if (w == QLatin1String("|")) {
            alternatives.emplace_back();
        } else if (w == QLatin1String("(") || w == QLatin1String("[")) {
            Node group;
            group.kind = w == QLatin1String("(") ? Node::Choice : Node::Optional;
            group.alternatives = parseAlternatives(c, t, i);
            ++i; // the closer
            alternatives.back().push_back(std::move(group));
        } else if (w.startsWith(QLatin1String("--"))) {
            Node option;
            option.kind = Node::Option;
            option.text = w.mid(2);
            const OptionSpec* spec = c.option(option.text);
            const bool valued = spec && spec->valueName;
            if (valued && i < t.size() && !QStringList{"(", ")", "[", "]", "|"}.contains(t[i])
                && !t[i].startsWith(QLatin1String("--")))
                ++i; // its value: the table's templates (Command::values) hold it
            alternatives.back().push_back(std::move(option));
        } else {
            alternatives.back().push_back(Node{Node::Word, w, {}});
        }
    }
    return alternatives;
}

/// A value text split at '|' outside brackets: "LO,HI|lenient" gives two.
QStringList splitAlternatives(const QString& text)
{
    QStringList out{QString()};
    int depth = 0;
    for (const QChar ch : text) {
        depth += ch == QLatin1Char('[') ? 1 : ch == QLatin1Char(']') ? -1 : 0;
        if (ch == QLatin1Char('|') && depth == 0)
            out << QString();
        else
            out.back() += ch;
    }
    return out;
}

std::vector<Command> commandTable()
{
    // The group functions of command.h make the dispatcher's table (command_line.cpp); every name
    // subCommandNames() lists must be among them, in its order.
    static const std::vector<SubCommand> all = [] {
        std::vector<SubCommand> commands;
        for (auto group :
            {app::projectCommands, app::keyCommands, app::lookCommands, app::highlightCommands, app::analysisCommands,
                app::offsetsCommands, app::cameraCommands, app::fitCommands, app::exportCommands})
            for (SubCommand& c : group())
                commands.push_back(std::move(c));
        return commands;
    }();
    std::vector<Command> table;
    for (const QString& name : app::subCommandNames()) {
        const SubCommand* spec = nullptr;
        for (const SubCommand& c : all)
            if (name == QLatin1String(c.name))
                spec = &c;
        if (!spec)
            fail(QStringLiteral("the sub-command table has \"%1\", which no group function of cli/command.h "
                                "gives: add its group to commandTable() in tests/fuzz/cli_process.cpp")
                     .arg(name));
        Command c;
        c.spec = spec;
        for (const char* line : spec->synopsis) {
            const QStringList tokens
                = synopsisTokens(QLatin1String(line), 2 + int(QString::fromLatin1(spec->name).count(QLatin1Char(' '))));
            for (int k = 0; k + 1 < tokens.size(); ++k) {
                const OptionSpec* o = tokens[k].startsWith(QLatin1String("--")) ? c.option(tokens[k].mid(2)) : nullptr;
                if (o && o->valueName && !QStringList{"(", ")", "[", "]", "|"}.contains(tokens[k + 1]))
                    for (const QString& v : splitAlternatives(tokens[k + 1]))
                        if (!c.values[QLatin1String(o->name)].contains(v))
                            c.values[QLatin1String(o->name)] << v;
            }
            int at = 0;
            std::vector<std::vector<Node>> parsed = parseAlternatives(c, tokens, at);
            c.lines.push_back(std::move(parsed.front()));
        }
        // The value names last: a synopsis's "toon|gooch|comic|lambert" says more than "STYLE".
        for (const OptionSpec& o : spec->options)
            if (o.valueName)
                for (const QString& v : splitAlternatives(QLatin1String(o.valueName)))
                    if (!c.values[QLatin1String(o.name)].contains(v))
                        c.values[QLatin1String(o.name)] << v;
        table.push_back(std::move(c));
    }
    return table;
}

// --- the fixture: a project and input files, made once per process --------------------------------

/// The projects of the work folder: p.celform has no drawing, d.celform the same and a drawing
/// linked to the key (a project with a drawing loads OpenImageIO, 0.3 s under the sanitizers, in
/// every sub-command that opens it, so only one run in six gets it).
const QString kProject = QStringLiteral("p.celform");
const QString kDrawingProject = QStringLiteral("d.celform");
/// The project's names, for options that name a key, drawing, face set or highlight.
const QStringList kNames = {"k1", "drawing", "top", "all", "h1", "missing", "K1", ""};
/// The files of the work folder (made in fixture()): inputs the options may name.
const QStringList kMeshInputs = {"key.obj", "base.obj", "other.obj", "empty.obj", "missing.obj", "drawing.png"};
const QStringList kImageInputs = {"drawing.png", "text.svg", "empty.png", "missing.png", "base.obj"};
const QStringList kProjects = {"missing.celform", "cut.celform", "base.obj", ""};
/// Suffixes for an output whose value name gives none ("FILE", "MESH").
const QStringList kOutputSuffixes = {
    "png", "obj", "ply", "glb", "gltf", "pc2", "usda", "exr", "tif", "jpg", "svg", "json", "csv", "celform", "txt", ""};

QString objText(const algo::TriMesh& mesh, float moveFirst)
{
    QString text = QStringLiteral("# made by tests/fuzz/cli_process.cpp\n");
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
        text += QStringLiteral("v %1 %2 %3\n")
                    .arg(double(mesh.vertices(v, 0)) + (v == 0 ? double(moveFirst) : 0.0))
                    .arg(double(mesh.vertices(v, 1)))
                    .arg(double(mesh.vertices(v, 2)));
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
        text += QStringLiteral("f %1 %2 %3\n")
                    .arg(mesh.faces(f, 0) + 1)
                    .arg(mesh.faces(f, 1) + 1)
                    .arg(mesh.faces(f, 2) + 1);
    return text;
}

void writeFile(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size())
        fail(QStringLiteral("cannot write %1: %2").arg(path, file.errorString()));
}

/// A 24-pixel drawing: a dark disc on white, as PNG.
QByteArray drawingPng()
{
    QImage image(24, 24, QImage::Format_ARGB32);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            image.setPixel(x, y, (x - 12) * (x - 12) + (y - 12) * (y - 12) < 64 ? 0xff202020u : 0xffffffffu);
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG"))
        fail(QStringLiteral("cannot encode the fixture's drawing"));
    return png;
}

struct Fixture {
    QTemporaryDir root{QDir::tempPath() + QStringLiteral("/celform-fuzz-cli-XXXXXX")};
    QString inputs; ///< the files copied into the work folder before every run
    QString work; ///< the child's working folder, emptied before every run
    QString celform;
    std::vector<Command> commands;
    int seconds = 4;
};

// How the runs of this process ended, for cliProcessSummary(). Outside the fixture, whose
// destructor (it removes the temporary folder) may run before an atexit handler that prints them.
std::map<QString, int> g_endings;
int g_runs = 0;

Fixture& fixture()
{
    // Destroyed at a normal exit, which removes the temporary folder; kept after an abort (a
    // finding), for its work folder.
    static const std::unique_ptr<Fixture> made = [] {
        auto f = std::make_unique<Fixture>();
        if (!f->root.isValid())
            fail(QStringLiteral("no temporary folder: %1").arg(f->root.errorString()));
        f->celform = qEnvironmentVariable("CELFORM_FUZZ_CELFORM", QStringLiteral(CELFORM_EXECUTABLE));
        if (!QFileInfo(f->celform).isExecutable())
            fail(QStringLiteral("no celform executable at %1 (build the target celform)").arg(f->celform));
        // The import children of this process's own loadProject (an SVG drawing with text).
        if (qEnvironmentVariableIsEmpty("CELFORM_EXECUTABLE"))
            qputenv("CELFORM_EXECUTABLE", QFile::encodeName(f->celform));
        f->seconds = qEnvironmentVariableIntValue("CELFORM_FUZZ_CHILD_SECONDS");
        if (f->seconds <= 0)
            f->seconds = 4;
        f->inputs = f->root.filePath(QStringLiteral("inputs"));
        f->work = f->root.filePath(QStringLiteral("work"));
        QDir().mkpath(f->inputs);
        const QDir in(f->inputs);

        // The projects, through the model's own API: the octahedron with a key (one vertex moved
        // at frame 0) and a patch; then the same with a drawing linked to the key.
        const auto mesh = test::octahedron(); // 6 vertices, 8 faces: cheap under the sanitizers too
        model::ProjectData data = model::newProject(mesh, QStringLiteral("base.obj"));
        model::KeyViewpoint key;
        key.id = data.nextId++;
        key.name = QStringLiteral("k1");
        key.direction = (key.camera.eye - data.baseCentre(0)).normalized();
        key.offsetsByFrame[0] = model::SparseOffsets{{0}, {Eigen::Vector3f(0.2f, 0.f, 0.f)}};
        data.keys.push_back(key);
        data.faceSets.push_back(algo::FaceSet{"top", {0, 1, 2, 3}});
        const auto save = [&](const QString& name) {
            const QString path = in.filePath(name);
            try {
                model::saveProject(data, path, false);
                (void)model::loadProject(path);
            } catch (const model::IoError& e) {
                fail(QStringLiteral("the fixture's project: %1").arg(e.message()));
            }
            return path;
        };
        save(kProject);
        model::Drawing drawing;
        drawing.id = data.nextId++;
        drawing.name = QStringLiteral("drawing");
        drawing.imageData = drawingPng();
        drawing.imageFormat = QStringLiteral("png");
        drawing.aligned = true;
        data.drawings.push_back(drawing);
        data.keys.front().drawingIds = {drawing.id};
        QFile whole(save(kDrawingProject));
        if (!whole.open(QIODevice::ReadOnly))
            fail(QStringLiteral("cannot read %1").arg(whole.fileName()));
        writeFile(in.filePath(QStringLiteral("cut.celform")), whole.readAll().left(whole.size() / 2));

        writeFile(in.filePath(QStringLiteral("base.obj")), objText(*mesh, 0.f).toUtf8());
        writeFile(in.filePath(QStringLiteral("key.obj")), objText(*mesh, 0.3f).toUtf8());
        writeFile(in.filePath(QStringLiteral("other.obj")), objText(test::tetrahedronMesh(), 0.f).toUtf8());
        writeFile(in.filePath(QStringLiteral("empty.obj")), {});
        writeFile(in.filePath(QStringLiteral("drawing.png")), drawingPng());
        writeFile(in.filePath(QStringLiteral("empty.png")), {});
        // SVG text: issue 27 item 1 (fonts without a display).
        writeFile(in.filePath(QStringLiteral("text.svg")),
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"32\" height=\"32\" viewBox=\"0 0 32 32\">"
            "<circle cx=\"16\" cy=\"16\" r=\"10\" fill=\"#222\"/>"
            "<text x=\"2\" y=\"30\" font-size=\"8\">key</text></svg>\n");

        f->commands = commandTable();
        if (f->commands.empty())
            fail(QStringLiteral("the sub-command table is empty"));
        return f;
    }();
    return *made;
}

// --- the input's choices ---------------------------------------------------------------------------

/// The input read front to back as choices; once it runs out every choice is 0 (the first
/// alternative, optional parts left out), so short inputs make short, ordinary command lines.
class Reader {
public:
    explicit Reader(const QByteArray& bytes)
        : m_bytes(bytes)
    { }
    quint8 byte() { return m_at < m_bytes.size() ? quint8(m_bytes[m_at++]) : 0; }
    int below(int n) { return n <= 1 ? 0 : n <= 256 ? byte() % n : int(wide() % quint32(n)); }
    /// True once in n (never once the input is used up).
    bool oneIn(int n) { return below(n) == 1 % n; }
    quint32 wide()
    {
        quint32 v = 0;
        for (int k = 0; k < 4; ++k)
            v = v << 8 | byte();
        return v;
    }
    QByteArray take(int n)
    {
        const QByteArray out = m_bytes.mid(m_at, n);
        m_at += out.size();
        return out;
    }

private:
    QByteArray m_bytes;
    qsizetype m_at = 0;
};

/// Numbers that have broken parsers and range checks before: the float and int limits, NaN and
/// infinity in their spellings, denormals, negative zero, and malformed numbers.
const QStringList kHostileNumbers = {"nan", "NaN", "inf", "-inf", "Infinity", "1e308", "-1e308", "1.8e308", "1e-320",
    "4e-45", "3.5e38", "-3.5e38", "-0", "0", "2147483647", "2147483648", "-2147483649", "9223372036854775808", "1e999",
    "0x10", " 1", "1 ", "", "1,", ",", "1e", "+", "-", "--", "1e+", ".", "1.5.5", "100000000"};

/// A number for a placeholder: mostly one a sub-command accepts (a small whole number, else
/// negative or fractional), one in ten huge, malformed, NaN or infinite.
QString number(Reader& r, bool hostile)
{
    const int kind = hostile ? 31 : r.below(32);
    if (kind < 20)
        return QString::number(r.below(10));
    if (kind < 22)
        return QString::number(-1 - r.below(10));
    if (kind < 25) {
        const int low = r.byte();
        const int high = r.byte();
        return QString::number(double(qint16(low | high << 8)) / 100.0);
    }
    if (kind < 27)
        return QString::number(double(r.below(100)) / 100.0);
    if (kind < 28)
        return QString::number(qint32(r.wide()));
    if (kind < 29) {
        const int mantissa = 1 + r.below(9);
        const int exponent = qint8(r.byte());
        return QStringLiteral("%1e%2").arg(mantissa).arg(exponent);
    }
    return kHostileNumbers[r.below(int(kHostileNumbers.size()))];
}

/// Bytes of the input as an argument, kept inside the work folder: no absolute or home paths, no
/// "..", no NUL (the argument would end there anyway).
QString confined(QString value)
{
    value.remove(QChar(0));
    if (value == QLatin1String("/dev/null") || value == QLatin1String("/dev/full"))
        return value;
    value.replace(QLatin1String(".."), QLatin1String("_"));
    if (value.startsWith(QLatin1Char('/')) || value.startsWith(QLatin1Char('~')))
        value.prepend(QLatin1Char('x'));
    return value;
}

QString rawValue(Reader& r)
{
    const QByteArray bytes = r.take(r.below(24));
    return confined(r.oneIn(2) ? QString::fromLatin1(bytes) : QString::fromUtf8(bytes));
}

/// Placeholders of value names that stand for a name or word rather than a number.
bool namesAWord(const QString& placeholder)
{
    return QStringList{"NAME", "NEW", "OTHER", "FACESET", "KIND", "MODE", "TYPE", "STYLE"}.contains(placeholder);
}

/// One alternative of a value name filled in: upper-case runs are placeholders (numbers or
/// names), everything else is kept; "[...]" parts are kept or left out, "..." repeats or ends.
QString fill(Reader& r, const QString& alternative, const QStringList& words, bool hostile)
{
    QString out;
    static const QRegularExpression placeholder(QStringLiteral("[A-Z][A-Z0-9]*"));
    QString text = alternative;
    const bool repeats = text.endsWith(QLatin1String(",..."));
    if (repeats)
        text.chop(4);
    // Optional parts: "A-B[:STEP]".
    QString flat;
    for (int i = 0; i < text.size(); ++i) {
        if (text[i] == QLatin1Char('[')) {
            const int close = int(text.indexOf(QLatin1Char(']'), i));
            if (close < 0)
                break;
            if (r.oneIn(2))
                flat += text.mid(i + 1, close - i - 1);
            i = close;
        } else {
            flat += text[i];
        }
    }
    const int copies = repeats ? 1 + r.below(3) : 1;
    for (int copy = 0; copy < copies; ++copy) {
        if (copy > 0)
            out += QLatin1Char(',');
        qsizetype at = 0;
        auto it = placeholder.globalMatch(flat);
        while (it.hasNext()) {
            const QRegularExpressionMatch m = it.next();
            out += flat.mid(at, m.capturedStart() - at);
            const bool word = namesAWord(m.captured()) ? !r.oneIn(4) : r.oneIn(8);
            if (word && !words.isEmpty())
                out += words[r.below(int(words.size()))];
            else
                out += number(r, hostile);
            at = m.capturedEnd();
        }
        out += flat.mid(at);
    }
    return out;
}

/// Whether a value name is a file's ("FILE", "FILE.png", "IMAGE", "MESH", "KEY.obj", "P.celform").
bool isPath(const QString& valueName)
{
    static const QRegularExpression suffix(QStringLiteral("^[A-Z]+\\.[a-z]+$"));
    return valueName.contains(QLatin1String("FILE")) || valueName.contains(QLatin1String("IMAGE"))
        || valueName.contains(QLatin1String("MESH")) || suffix.match(valueName).hasMatch();
}

/// The file an option of value name names: an input of the work folder ("IMAGE", "KEY.obj"), or
/// a new file there with a suffix the value name gives ("FILE.png|.exr" or any for "FILE").
QString pathValue(Reader& r, const QStringList& alternatives)
{
    const QString all = alternatives.join(QLatin1Char('|'));
    if (all.contains(QLatin1String("IMAGE")))
        return kImageInputs[r.below(int(kImageInputs.size()))];
    if (all.contains(QLatin1String(".obj")))
        return kMeshInputs[r.below(int(kMeshInputs.size()))];
    // An output.
    switch (r.below(32)) {
    case 1:
        return QStringLiteral("/dev/full"); // a write error with errno ENOSPC (issue 27)
    case 2:
        return QStringLiteral("/dev/null");
    case 3:
        return QStringLiteral("no-folder/out.png");
    case 4:
        return QStringLiteral("base.obj"); // over an input of the work folder
    case 5:
        return QString();
    default:
        break;
    }
    QStringList suffixes;
    static const QRegularExpression given(QStringLiteral("\\.([a-z0-9]+)$"));
    for (const QString& a : alternatives)
        if (const QRegularExpressionMatch m = given.match(a); m.hasMatch())
            suffixes << m.captured(1);
    if (suffixes.isEmpty() || r.oneIn(8))
        suffixes = kOutputSuffixes;
    QString name = QStringLiteral("out");
    if (r.oneIn(4))
        name += QLatin1Char('_') + QString(1 + r.below(6), QLatin1Char('#')); // a frame pattern
    const QString suffix = suffixes[r.below(int(suffixes.size()))];
    return suffix.isEmpty() ? name : name + QLatin1Char('.') + suffix;
}

/// A value for an option of the command, from the table's value texts.
QString optionValue(Reader& r, const Command& c, const QString& option)
{
    const QStringList alternatives = c.values.count(option) ? c.values.at(option) : QStringList{QStringLiteral("X")};
    // Words to fill placeholders with: the project's names and the lower-case words of this
    // option's alternatives ("lenient", "point").
    QStringList words = kNames;
    static const QRegularExpression word(QStringLiteral("^[a-z][a-z0-9-]*$"));
    for (const QString& a : alternatives)
        if (word.match(a).hasMatch())
            words << a;
    // Mostly a value of the right form, filled in (its numbers hostile one time in ten); one
    // time in eight a hostile number, raw bytes, a word, or the form with every number hostile.
    const int mode = r.below(32);
    bool path = false;
    for (const QString& a : alternatives)
        path = path || isPath(a);
    if (path && mode < 29)
        return pathValue(r, alternatives);
    switch (mode) {
    case 28:
        return fill(r, alternatives[r.below(int(alternatives.size()))], words, true);
    case 29:
        return number(r, true);
    case 30:
        return rawValue(r);
    case 31:
        return words[r.below(int(words.size()))];
    default:
        return fill(r, alternatives[r.below(int(alternatives.size()))], words, false);
    }
}

void addOption(Reader& r, const Command& c, const QString& name, QStringList& args)
{
    const OptionSpec* spec = c.option(name);
    if (!spec || !spec->valueName) {
        args << QStringLiteral("--") + name;
        return;
    }
    const QString value = optionValue(r, c, name);
    if (r.oneIn(8))
        args << QStringLiteral("--%1=%2").arg(name, value);
    else
        args << QStringLiteral("--") + name << value;
}

void walk(Reader& r, const Command& c, const std::vector<Node>& nodes, QStringList& args, int depth)
{
    for (const Node& n : nodes) {
        switch (n.kind) {
        case Node::Word:
            if (n.text == QLatin1String("P") || n.text.endsWith(QLatin1String(".celform")))
                args << (r.oneIn(32) ? kProjects[r.below(int(kProjects.size()))]
                        : r.oneIn(6) ? kDrawingProject
                                     : kProject);
            else if (n.text == QLatin1String("MESH"))
                args << kMeshInputs[r.oneIn(8) ? r.below(int(kMeshInputs.size())) : 1];
            else
                args << (r.oneIn(32) ? rawValue(r) : n.text);
            break;
        case Node::Option:
            addOption(r, c, n.text, args);
            break;
        case Node::Optional:
            if (depth < 8 && r.oneIn(3))
                walk(r, c, n.alternatives[std::size_t(r.below(int(n.alternatives.size())))], args, depth + 1);
            break;
        case Node::Choice:
            if (depth < 8)
                walk(r, c, n.alternatives[std::size_t(r.below(int(n.alternatives.size())))], args, depth + 1);
            break;
        }
    }
}

/// The command line of a choices input: the sub-command, one synopsis line walked, and up to
/// two more of its options.
QStringList chosenArguments(const QByteArray& bytes)
{
    const Fixture& f = fixture();
    Reader r(bytes);
    const Command& c = f.commands[std::size_t(r.below(int(f.commands.size())))];
    QStringList args{QLatin1String(c.spec->name)};
    walk(r, c, c.lines[std::size_t(r.below(int(c.lines.size())))], args, 0);
    for (int extra = r.below(3); extra > 0 && !c.spec->options.empty(); --extra)
        addOption(r, c, QLatin1String(c.spec->options[std::size_t(r.below(int(c.spec->options.size())))].name), args);
    // The pictures of render, analyze, optimize-light and offsets default to 1280 x 720: a second
    // and more under the sanitizers, which would leave a handful of runs in CI's 6 s. Unless the
    // input says otherwise (one time in sixteen), a picture without --size gets a small one.
    bool sized = false;
    for (const QString& a : args)
        sized = sized || a == QLatin1String("--size") || a.startsWith(QLatin1String("--size="));
    if (c.option(QStringLiteral("size")) && !sized && !r.oneIn(16)) {
        const int width = 16 + 8 * r.below(6); // the analysis takes 16 pixels a side at least
        const int height = 16 + 6 * r.below(6);
        args << QStringLiteral("--size") << QStringLiteral("%1x%2").arg(width).arg(height);
    }
    return args;
}

/// The command line of a literal input: "celform\n" and one argument a line.
QStringList literalArguments(const QByteArray& bytes)
{
    QStringList args;
    const QList<QByteArray> lines = bytes.mid(8).split('\n');
    for (qsizetype i = 0; i < lines.size() && args.size() < 64; ++i) {
        if (i + 1 == lines.size() && lines[i].isEmpty())
            break; // the last newline ends the last argument
        args << confined(QString::fromUtf8(lines[i].left(4096)));
    }
    return args;
}

// --- one run ----------------------------------------------------------------------------------------

QString shellQuoted(const QStringList& words)
{
    QStringList out;
    static const QRegularExpression plain(QStringLiteral("^[A-Za-z0-9_./:,=+#-]+$"));
    for (QString w : words)
        out << (plain.match(w).hasMatch()
                ? w
                : QLatin1Char('\'') + w.replace(QLatin1Char('\''), QLatin1String("'\\''")) + QLatin1Char('\''));
    return out.join(QLatin1Char(' '));
}

void freshWorkFolder(const Fixture& f)
{
    QDir work(f.work);
    if (work.exists() && !work.removeRecursively())
        fail(QStringLiteral("cannot empty %1").arg(f.work));
    if (!QDir().mkpath(work.filePath(QStringLiteral(".home"))) || !QDir().mkpath(work.filePath(QStringLiteral(".tmp"))))
        fail(QStringLiteral("cannot make %1").arg(f.work));
    const QDir in(f.inputs);
    for (const QString& name : in.entryList(QDir::Files))
        if (!QFile::copy(in.filePath(name), work.filePath(name)))
            fail(QStringLiteral("cannot copy %1 into %2").arg(name, f.work));
}

struct Ending {
    bool killed = false;
    bool crashed = false;
    int exitCode = -1;
    QString err;
};

Ending runChild(const Fixture& f, const QStringList& args)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    const QString home = QDir(f.work).filePath(QStringLiteral(".home"));
    for (const char* name : {"HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_DATA_HOME"})
        env.insert(QLatin1String(name), home);
    env.insert(QStringLiteral("TMPDIR"), QDir(f.work).filePath(QStringLiteral(".tmp")));
    env.insert(QStringLiteral("CELFORM_IMPORT_SECONDS"), QString::number(f.seconds));
    env.insert(QStringLiteral("CELFORM_IMPORT_MEMORY_MB"), QStringLiteral("2048"));
    // The child's memory: 4 GB. Under AddressSanitizer (which reserves terabytes of address space,
    // so no RLIMIT_AS) as its resident-size limit, which ends it with a report; otherwise as its
    // address space, which the command line turns into a refusal (bad_alloc, or checkRenderMemory).
#ifdef CELFORM_FUZZ_ASAN
    env.insert(QStringLiteral("ASAN_OPTIONS"),
        env.value(QStringLiteral("ASAN_OPTIONS")) + QStringLiteral(":hard_rss_limit_mb=4096"));
    p.setChildProcessModifier([] { ::setpgid(0, 0); });
#else
    p.setChildProcessModifier([] {
        ::setpgid(0, 0);
        const rlimit limit{rlim_t(4) << 30, rlim_t(4) << 30};
        ::setrlimit(RLIMIT_AS, &limit);
    });
#endif
    p.setProcessEnvironment(env);
    p.setWorkingDirectory(f.work);
    p.setStandardOutputFile(QProcess::nullDevice());
    p.start(f.celform, args);
    if (!p.waitForStarted(30000))
        fail(QStringLiteral("cannot start %1: %2").arg(f.celform, p.errorString()));
    Ending e;
    if (!p.waitForFinished(f.seconds * 1000)) {
        e.killed = true;
        ::kill(-pid_t(p.processId()), SIGKILL); // with the import children it started
        p.waitForFinished(30000);
    }
    e.crashed = !e.killed && p.exitStatus() == QProcess::CrashExit;
    e.exitCode = p.exitCode();
    e.err = QString::fromUtf8(p.readAllStandardError());
    return e;
}

/// The first line of text that matches, or an empty string.
QString lineMatching(const QString& text, const QRegularExpression& re)
{
    for (const QString& line : text.split(QLatin1Char('\n')))
        if (re.match(line).hasMatch())
            return line.trimmed();
    return {};
}

/// Why the project at path breaks the promise to open, or an empty string.
QString projectRefusal(const QString& path)
{
    try {
        const QString problem = projectProblem(model::loadProject(path));
        return problem.isEmpty() ? QString() : QStringLiteral("it opens but breaks the loader's promise: ") + problem;
    } catch (const model::IoError& e) {
        return e.message();
    }
}

/// The value of an option in a command line ("--size 8x8" or "--size=8x8"), the last one given.
QString valueIn(const QStringList& args, const QString& option)
{
    QString value;
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--") + option && i + 1 < args.size())
            value = args[i + 1];
        else if (args[i].startsWith(QLatin1String("--") + option + QLatin1Char('=')))
            value = args[i].section(QLatin1Char('='), 1);
    }
    return value;
}

/// Whether the command line asks for a picture whose buffers may pass the child's 4 GB: --size
/// beyond 12 million pixels at the renderer's 88 bytes a pixel (checkRenderMemory lets it run
/// when the machine has the memory, but AddressSanitizer's resident-size limit stops it).
bool asksForHugePicture(const QStringList& args)
{
    const QStringList wh = valueIn(args, QStringLiteral("size")).split(QLatin1Char('x'));
    return wh.size() == 2
        && wh[0].toDouble() * wh[1].toDouble() * double(model::kRenderBytesPerPixel) > double(1 << 30);
}

/// What the run broke (empty when nothing): see the top of this file.
QString findingOf(const Fixture& f, const QStringList& args, const Ending& e)
{
    static const QRegularExpression sanitizer(QStringLiteral(
        "ERROR: [A-Za-z]*Sanitizer|[A-Za-z]*Sanitizer:DEADLYSIGNAL|\\.[a-z+]+:\\d+:\\d+: runtime error: "));
    static const QRegularExpression memoryCap(
        QStringLiteral("hard rss limit exhausted|out of memory|allocation-size-too-big"));
    if (const QString line = lineMatching(e.err, sanitizer); !line.isEmpty()) {
        if (!(memoryCap.match(line).hasMatch() && asksForHugePicture(args)))
            return QStringLiteral("a sanitizer report: ") + line;
    } else if (e.crashed) {
        return QStringLiteral("the child died on signal %1").arg(e.exitCode);
    } else if (!e.killed && e.exitCode != 0 && e.exitCode != 2 && e.exitCode != 3) {
        return QStringLiteral("exit %1, not one of the documented 0, 2 and 3").arg(e.exitCode);
    }
    if (!e.killed && (e.exitCode == 2 || e.exitCode == 3) && e.err.trimmed().isEmpty())
        return QStringLiteral("exit %1 without a message").arg(e.exitCode);
    static const QRegularExpression unknown(QStringLiteral("Unknown error"));
    if (const QString line = lineMatching(e.err, unknown); !line.isEmpty())
        return QStringLiteral("an error without the system's reason: ") + line;

    // The project copies the command line names, and a project the run wrote (an option of
    // value name "P.celform", as `new --out`), must open.
    const QDir work(f.work);
    QStringList projects;
    for (const QString& name : {kProject, kDrawingProject})
        if (args.contains(name))
            projects << name;
    const qsizetype copies = projects.size();
    if (!e.killed && e.exitCode == 0)
        for (const Command& c : f.commands)
            if (args[0] == QLatin1String(c.spec->name))
                for (const OptionSpec& o : c.spec->options)
                    if (o.valueName && QByteArray(o.valueName).endsWith(".celform"))
                        if (const QString written = valueIn(args, QLatin1String(o.name)); !written.isEmpty())
                            projects << written;
    for (const QString& name : projects) {
        const QString path = work.filePath(name);
        if (!QFileInfo::exists(path))
            return projects.indexOf(name) < copies ? QStringLiteral("%1 was removed").arg(name)
                                                   : QStringLiteral("%1 is missing after exit 0").arg(name);
        if (const QString why = projectRefusal(path); !why.isEmpty())
            return QStringLiteral("%1 no longer opens: %2").arg(name, why);
        const QString backup = path + QStringLiteral(".bak");
        if (QFileInfo::exists(backup))
            if (const QString why = projectRefusal(backup); !why.isEmpty())
                return QStringLiteral("%1.bak does not open: %2").arg(name, why);
    }
    return {};
}

} // namespace

Outcome feedCliProcess(const QByteArray& bytes)
{
    Fixture& f = fixture();
    const QStringList args = bytes.startsWith("celform\n") ? literalArguments(bytes) : chosenArguments(bytes);
    Outcome out;
    if (args.isEmpty() || !app::subCommandNames().contains(args[0])) {
        // Not a sub-command of the table (a mutated literal input): nothing to run.
        out.refusal = QStringLiteral("no sub-command");
        return out;
    }
    freshWorkFolder(f);
    const Ending e = runChild(f, args);
    ++g_runs;
    ++g_endings[e.killed ? QStringLiteral("killed")
            : e.crashed  ? QStringLiteral("signal")
                         : QStringLiteral("exit %1").arg(e.exitCode)];
    out.broken = findingOf(f, args, e);
    if (qEnvironmentVariableIsSet("CELFORM_FUZZ_VERBOSE"))
        std::fprintf(stderr, "celform fuzz: %s -> %s: %s\n", qPrintable(shellQuoted(args)),
            e.killed        ? "killed"
                : e.crashed ? "signal"
                            : qPrintable(QString::number(e.exitCode)),
            qPrintable(e.err.trimmed().section(QLatin1Char('\n'), 0, 0)));
    if (!out.broken.isEmpty()) {
        QStringList tail = e.err.split(QLatin1Char('\n'));
        if (tail.size() > 40)
            tail = tail.mid(tail.size() - 40);
        out.broken += QStringLiteral(
            "\n  run: cd %1 && QT_QPA_PLATFORM=offscreen %2\n  (the work folder is kept; "
            "its inputs are made again by any run of fuzz_cli_process)\n  its standard error:\n    %3")
                          .arg(f.work, shellQuoted(QStringList{f.celform} + args), tail.join(QStringLiteral("\n    ")));
        return out;
    }
    if (e.killed)
        out.refusal = QStringLiteral("killed after %1 s: %2").arg(f.seconds).arg(shellQuoted(args));
    else if (e.exitCode == 0)
        out.loaded = true;
    else
        out.refusal = e.err.trimmed().section(QLatin1Char('\n'), 0, 0);
    return out;
}

QString cliProcessSummary()
{
    QStringList parts;
    for (const auto& [ending, count] : g_endings)
        parts << QStringLiteral("%1 x%2").arg(ending).arg(count);
    return QStringLiteral("%1 runs of celform: %2").arg(g_runs).arg(parts.join(QStringLiteral(", ")));
}

} // namespace celform::fuzz
