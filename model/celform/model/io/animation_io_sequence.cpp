// A numbered mesh sequence (walk_0001.obj, walk_0002.obj, ...) as an animated base: the first
// file is the rest mesh, and every file's positions are one stored frame of the animation's vertex
// frames (algo::BaseAnimation), so memory is linear in the sequence. Each file is read by mesh_io's
// reader table. The
// numbers are kept as frames, counted from the first file's: a missing number holds the frame
// before it, with a warning naming the missing numbers (issue 27).
#include "celform/model/io/animation_io_common.h"
#include "celform/model/io/mesh_io_common.h"

#include <QDir>
#include <QStringList>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <optional>
#include <vector>

namespace celform::model::animio {

namespace {

/// The files of a sequence share a folder, a text before the frame number and one after it.
struct SequenceName {
    QDir folder;
    QString prefix;
    QString suffix;
    /// The pattern's run of '#': numbers of exactly that many digits (zero-padded), or longer
    /// without a leading zero (frame 10000 of "####"). 0 for a numbered file: any digits.
    int digits = 0;
};

struct Frame {
    QString path;
    qint64 number = 0;
};

bool isSequenceSuffix(const QString& suffix)
{
    const QString s = suffix.toLower();
    return s == QLatin1String("obj") || s == QLatin1String("ply") || s == QLatin1String("off");
}

/// "walk_####.obj": the last run of '#' in the file name stands for the frame number;
/// "walk_0001.obj": the last run of digits is the frame number.
std::optional<SequenceName> parseSequenceName(const QString& path)
{
    const QFileInfo info(path);
    static const QRegularExpression kPattern(QStringLiteral("^(.*[^#])?(#+)([^#]*)$"));
    static const QRegularExpression kNumbered(QStringLiteral("^(.*\\D)?(\\d+)(\\D*)$"));
    const bool pattern = info.fileName().contains(QLatin1Char('#'));
    const auto m = (pattern ? kPattern : kNumbered).match(info.fileName());
    if (!m.hasMatch() || !isSequenceSuffix(info.suffix()))
        return std::nullopt;
    return SequenceName{info.absoluteDir(), m.captured(1), m.captured(3), pattern ? int(m.capturedLength(2)) : 0};
}

/// The sequence's files in numeric order. Throws IoError naming path for two files with one
/// number and for numbers too long to be frame numbers.
std::vector<Frame> listFrames(const QString& path, const SequenceName& name)
{
    const QRegularExpression match(QStringLiteral("^") + QRegularExpression::escape(name.prefix)
        + QStringLiteral("(\\d+)") + QRegularExpression::escape(name.suffix) + QStringLiteral("$"));
    std::vector<Frame> frames;
    for (const QString& file : name.folder.entryList(QDir::Files | QDir::Hidden)) {
        const auto m = match.match(file);
        if (!m.hasMatch())
            continue;
        const QString digits = m.captured(1);
        if (name.digits > 0 && digits.size() != name.digits && (digits.size() < name.digits || digits[0] == '0'))
            continue;
        if (digits.size() > 15)
            throw IoError(path, AnimationIo::tr("%1: the frame number is too long").arg(file));
        frames.push_back({name.folder.filePath(file), digits.toLongLong()});
        if (qint64(frames.size()) > kMaxFrames)
            throw IoError(
                path, AnimationIo::tr("the sequence has more than the %1 frames Celform can load").arg(kMaxFrames));
    }
    std::sort(frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.number < b.number; });
    const auto same = std::adjacent_find(
        frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.number == b.number; });
    if (same != frames.end())
        throw IoError(path,
            AnimationIo::tr("%1 and %2 are both frame %3")
                .arg(QFileInfo(same->path).fileName(), QFileInfo((same + 1)->path).fileName())
                .arg(same->number));
    return frames;
}

/// The numbers missing between the frames' ("3, 7-9"), at most a dozen runs named; empty when none.
QString missingNumbers(const std::vector<Frame>& frames)
{
    QStringList runs;
    qint64 more = 0;
    for (std::size_t k = 1; k < frames.size(); ++k) {
        const qint64 from = frames[k - 1].number + 1, to = frames[k].number - 1;
        if (from > to)
            continue;
        if (runs.size() < 12)
            runs << (from == to ? QString::number(from) : QStringLiteral("%1-%2").arg(from).arg(to));
        else
            ++more;
    }
    if (more > 0)
        runs << AnimationIo::tr("and %n more", nullptr, int(std::min<qint64>(more, 1'000'000'000)));
    return runs.join(QStringLiteral(", "));
}

/// The first difference between a frame's faces and the first frame's, empty when equal.
QString faceDifference(const algo::Faces& faces, const algo::Faces& first, const QString& firstName)
{
    if (faces.rows() != first.rows())
        return AnimationIo::tr("%1 triangles, the first frame (%2) has %3")
            .arg(faces.rows())
            .arg(firstName)
            .arg(first.rows());
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        if (faces.row(f) != first.row(f))
            return AnimationIo::tr("triangle %1 is (%2, %3, %4), the first frame's (%5) is (%6, %7, %8)")
                .arg(f + 1)
                .arg(faces(f, 0))
                .arg(faces(f, 1))
                .arg(faces(f, 2))
                .arg(firstName)
                .arg(first(f, 0))
                .arg(first(f, 1))
                .arg(first(f, 2));
    return {};
}

} // namespace

AnimatedImport readMeshSequence(const QString& path, double fps)
{
    if (!QFileInfo(path).fileName().contains(QLatin1Char('#')))
        meshio::requireRegularFile(path);
    const std::optional<SequenceName> name = parseSequenceName(path);
    if (!name)
        throw IoError(path,
            AnimationIo::tr("not an animated base: use a .gltf or .glb file, or a numbered .obj, .ply or .off "
                            "sequence (walk_0001.obj, or walk_####.obj)"));
    const std::vector<Frame> frames = listFrames(path, *name);
    if (frames.empty())
        throw IoError(path, AnimationIo::tr("no file matches the pattern"));

    // The numbers are frames: their range is the animation's length, whatever files it misses.
    const qint64 range = frames.back().number - frames.front().number + 1;
    if (range > kMaxFrames)
        throw IoError(path,
            AnimationIo::tr("the sequence's numbers run from %1 to %2, more than the %3 frames Celform can load")
                .arg(frames.front().number)
                .arg(frames.back().number)
                .arg(kMaxFrames));

    MeshImport first;
    meshio::readMeshInOrder(frames[0].path, first);
    const Eigen::Index vertexCount = first.mesh.vertexCount();
    const auto stored = static_cast<std::int64_t>(frames.size());
    if (stored * vertexCount * 3 + range > kMaxAnimationFloats)
        throw IoError(path,
            AnimationIo::tr("%1 frames of %2 vertices are more than Celform can hold")
                .arg(frames.size())
                .arg(vertexCount));

    AnimatedImport out;
    out.fps = fps;
    algo::BaseAnimation& anim = out.animation;
    anim.firstFrame = 0;
    anim.frameCount = static_cast<int>(range);
    // Each file one stored frame; each sample shows the file of its number, or the one before it
    // for a missing number.
    anim.vertexFrames.resize(stored * vertexCount, 3);
    anim.vertexFrameOfSample.resize(std::size_t(range));
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const qint64 end = k + 1 < frames.size() ? frames[k + 1].number : frames.back().number + 1;
        for (qint64 n = frames[k].number; n < end; ++n)
            anim.vertexFrameOfSample[std::size_t(n - frames.front().number)] = std::int32_t(k);
    }
    if (const QString missing = missingNumbers(frames); !missing.isEmpty())
        out.warnings << AnimationIo::tr(
            "the sequence has no file numbered %1; each missing number holds the frame before it")
                            .arg(missing);
    anim.vertexFrames.topRows(vertexCount) = first.mesh.vertices;
    const QString firstName = QFileInfo(frames[0].path).fileName();
    for (std::size_t k = 1; k < frames.size(); ++k) {
        MeshImport frame;
        meshio::readMeshInOrder(frames[k].path, frame);
        if (frame.mesh.vertexCount() != vertexCount)
            throw IoError(frames[k].path,
                AnimationIo::tr("%1 vertices, the first frame (%2) has %3")
                    .arg(frame.mesh.vertexCount())
                    .arg(firstName)
                    .arg(vertexCount));
        const QString faces = faceDifference(frame.mesh.faces, first.mesh.faces, firstName);
        if (!faces.isEmpty())
            throw IoError(frames[k].path, faces);
        anim.vertexFrames.middleRows(Eigen::Index(k) * vertexCount, vertexCount) = frame.mesh.vertices;
    }
    out.mesh = std::make_shared<algo::TriMesh>(std::move(first.mesh));
    return out;
}

bool isMeshSequence(const QString& path)
{
    const auto name = parseSequenceName(path);
    if (!name)
        return false;
    if (name->digits > 0) // a pattern
        return !listFrames(path, *name).empty();
    return QFileInfo(path).isFile() && listFrames(path, *name).size() >= 2;
}

} // namespace celform::model::animio
