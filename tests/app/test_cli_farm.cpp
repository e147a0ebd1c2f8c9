// `celform render` on a render farm: frames split over processes, strides and threads
// give the same bytes as one process; --skip-existing resumes without touching finished files; a
// frame that cannot be written exits 3 naming it; a killed render leaves no partial file; usage
// errors of --frames and --threads exit 2. The sample project's highlights are keyed over 30
// frames, so its frames differ from each other.
#include "cli_run.h"
#include "test_support.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

#include <grp.h>
#include <unistd.h>

namespace {

QString sample()
{
    return QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-highlights.celform");
}

QByteArray bytesOf(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// Every file in a folder, hidden ones too, by name.
QStringList filesIn(const QString& dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::System, QDir::Name);
}

/// The arguments of a small render of a project (the sample) into dir/shot_####.SUFFIX.
QStringList renderArgs(const QString& dir, const QString& suffix, const QString& frames, const QStringList& extra = {},
    const QString& project = sample())
{
    return QStringList{QStringLiteral("render"), project, QStringLiteral("--size"), QStringLiteral("96x54"),
               QStringLiteral("--frames"), frames, QStringLiteral("--out"),
               QDir(dir).filePath(QStringLiteral("shot_####.") + suffix)}
    + extra;
}

QStringList frameNames(const QString& suffix, std::initializer_list<int> frames)
{
    QStringList names;
    for (int f : frames)
        names << QStringLiteral("shot_%1.%2").arg(f, 4, 10, QLatin1Char('0')).arg(suffix);
    return names;
}

/// The test's environment as a farm node has it: no display at all (not even QT_QPA_PLATFORM).
QProcessEnvironment nodeEnvironment()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QLatin1String(name));
    return env;
}

/// Starts celform on a node's environment, without waiting for it.
std::unique_ptr<QProcess> startCelform(const QStringList& args)
{
    auto p = std::make_unique<QProcess>();
    p->setProcessEnvironment(nodeEnvironment());
    p->start(QStringLiteral(CELFORM_EXECUTABLE), args);
    return p;
}

/// The user id of nobody, who may write in no folder of the test's.
constexpr uid_t kNobody = 65534;

/// Runs celform on a node's environment as another user.
Run runCelformAs(uid_t user, const QStringList& args)
{
    QProcess p;
    p.setProcessEnvironment(nodeEnvironment());
    if (user != ::geteuid())
        p.setChildProcessModifier([user] {
            // Groups first: after setuid they can no longer be dropped. A failure ends the child with
            // 99 before celform starts, which fails the test rather than passing it as root.
            if (::setgroups(0, nullptr) != 0 || ::setgid(gid_t(user)) != 0 || ::setuid(user) != 0)
                ::_exit(99);
        });
    p.start(QStringLiteral(CELFORM_EXECUTABLE), args);
    if (!p.waitForFinished(120000))
        p.kill();
    return {p.exitCode(), p.exitStatus(), QString::fromUtf8(p.readAllStandardOutput()),
        QString::fromUtf8(p.readAllStandardError())};
}

} // namespace

class TestCliFarm : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    /// A fresh folder under m_dir.
    QString folder(const QString& name)
    {
        const QString path = m_dir.filePath(name);
        QDir(path).removeRecursively();
        QDir().mkpath(path);
        return path;
    }

    /// The reference: frames 0-5 rendered by one process on one thread, in a folder of their own.
    QString reference(const QString& suffix)
    {
        const QString dir = m_dir.filePath(QStringLiteral("reference_") + suffix);
        if (!QDir(dir).exists()) {
            QDir().mkpath(dir);
            const Run r = runCelform(renderArgs(dir, suffix, QStringLiteral("0-5"), {"--threads", "1"}));
            if (r.exitCode != 0)
                qWarning("%s", qPrintable(r.err));
        }
        return dir;
    }

    /// Whether two folders hold the same files with the same bytes (and nothing else).
    static void compareFolders(const QString& expected, const QString& actual)
    {
        const QStringList names = filesIn(expected);
        QCOMPARE(filesIn(actual), names);
        for (const QString& name : names)
            QVERIFY2(bytesOf(QDir(expected).filePath(name)) == bytesOf(QDir(actual).filePath(name)), qPrintable(name));
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void splitsGiveTheSameBytes_data()
    {
        QTest::addColumn<QString>("suffix");
        for (const char* suffix : {"png", "exr", "tif", "jpg"})
            QTest::newRow(suffix) << QString::fromLatin1(suffix);
    }
    // Requirement (a): two processes at once on complementary strides, and two on the two
    // halves, write the files one process writes, byte for byte (no time stamp in EXR or TIFF).
    void splitsGiveTheSameBytes()
    {
        QFETCH(QString, suffix);
        const QString expected = reference(suffix);
        QCOMPARE(filesIn(expected), frameNames(suffix, {0, 1, 2, 3, 4, 5}));
        // The frames differ, so a frame written under another frame's name would be noticed.
        QVERIFY(bytesOf(QDir(expected).filePath(frameNames(suffix, {0})[0]))
            != bytesOf(QDir(expected).filePath(frameNames(suffix, {5})[0])));

        for (const auto& [first, second] : {std::pair{"0-5:2", "1-5:2"}, std::pair{"0-2", "3-5"}}) {
            QThread::msleep(1100); // a second later: a time stamp in the files would show
            const QString dir = folder(QStringLiteral("split_") + suffix);
            auto a = startCelform(renderArgs(dir, suffix, QLatin1String(first), {"--threads", "1"}));
            auto b = startCelform(renderArgs(dir, suffix, QLatin1String(second), {"--threads", "2"}));
            for (QProcess* p : {a.get(), b.get()}) {
                QVERIFY(p->waitForFinished(120000));
                QVERIFY2(p->exitCode() == 0, p->readAllStandardError().constData());
            }
            compareFolders(expected, dir);
        }
    }

    // With a camera path (a turntable) the camera, and with it the view-dependent shape, changes
    // from frame to frame: strides on several threads still give one process's bytes.
    void cameraPathSplitsGiveTheSameBytes()
    {
        const QString project = m_dir.filePath(QStringLiteral("turntable.celform"));
        QFile::remove(project);
        QVERIFY(QFile::copy(sample(), project));
        const Run turntable = runCelform({"camera", project, "--turntable", "24"});
        QVERIFY2(turntable.exitCode == 0, qPrintable(turntable.err));
        const QString whole = folder(QStringLiteral("turntable_whole"));
        const QString split = folder(QStringLiteral("turntable_split"));
        const QString exr = QStringLiteral("exr");
        QCOMPARE(runCelform(renderArgs(whole, exr, QStringLiteral("0-5"), {"--threads", "1"}, project)).exitCode, 0);
        QCOMPARE(runCelform(renderArgs(split, exr, QStringLiteral("0-5:2"), {"--threads", "2"}, project)).exitCode, 0);
        QCOMPARE(runCelform(renderArgs(split, exr, QStringLiteral("1-5:2"), {"--threads", "3"}, project)).exitCode, 0);
        compareFolders(whole, split);
        QVERIFY(bytesOf(QDir(whole).filePath(QStringLiteral("shot_0001.exr")))
            != bytesOf(QDir(whole).filePath(QStringLiteral("shot_0002.exr"))));
    }

    // Requirement (b): --threads 2 writes what --threads 1 writes; progress goes to standard
    // error, one line per frame, and nothing to standard output.
    void threadsGiveTheSameBytes()
    {
        const QString expected = reference(QStringLiteral("exr"));
        const QString dir = folder(QStringLiteral("threads"));
        const Run r = runCelform(renderArgs(dir, QStringLiteral("exr"), QStringLiteral("0-5"), {"--threads", "2"}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        const QStringList lines = r.err.trimmed().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 6);
        for (int f = 0; f < 6; ++f)
            QVERIFY2(r.err.contains(QStringLiteral("frame %1 (").arg(f)), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("(6/6) -> ")), qPrintable(r.err));
        compareFolders(expected, dir);
    }

    // A chunk of one frame, and --out without #, are named as that frame of a longer range.
    void oneFrameChunksAreNumbered()
    {
        const QString expected = reference(QStringLiteral("png"));
        const QString dir = folder(QStringLiteral("single"));
        const Run r = runCelform({"render", sample(), "--size", "96x54", "--frames", "4-4", "--out",
            QDir(dir).filePath(QStringLiteral("shot.png"))});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(filesIn(dir), QStringList{QStringLiteral("shot_0004.png")});
        QCOMPARE(bytesOf(QDir(dir).filePath(QStringLiteral("shot_0004.png"))),
            bytesOf(QDir(expected).filePath(QStringLiteral("shot_0004.png"))));
    }

    // Requirement (c): --skip-existing leaves an existing whole picture alone and renders the
    // missing ones, and (issue 27) those whose file is not a whole picture; --json lists both, in
    // frame order.
    void skipExistingResumes()
    {
        const QString expected = reference(QStringLiteral("png"));
        const QString dir = folder(QStringLiteral("resume"));
        QVERIFY(runCelform(renderArgs(dir, QStringLiteral("png"), QStringLiteral("0-5"), {"--threads", "1"})).exitCode
            == 0);
        const QString kept = QDir(dir).filePath(QStringLiteral("shot_0001.png"));
        const QString foreign = QDir(dir).filePath(QStringLiteral("shot_0000.png"));
        QVERIFY(QFile::remove(QDir(dir).filePath(QStringLiteral("shot_0002.png"))));
        QVERIFY(QFile::remove(QDir(dir).filePath(QStringLiteral("shot_0005.png"))));
        QFile junk(foreign);
        QVERIFY(junk.open(QIODevice::WriteOnly | QIODevice::Truncate));
        junk.write("left by somebody else");
        junk.close();
        // A frame cut short by an earlier run (a full disk, a killed node): half its bytes.
        const QString cut = QDir(dir).filePath(QStringLiteral("shot_0004.png"));
        QVERIFY(QFile::resize(cut, QFileInfo(cut).size() / 2));
        const QDateTime keptTime = QFileInfo(kept).lastModified();
        QThread::msleep(1100);

        const Run r = runCelform(renderArgs(
            dir, QStringLiteral("png"), QStringLiteral("0-5"), {"--skip-existing", "--threads", "2", "--json"}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QFileInfo(kept).lastModified(), keptTime);
        // Only whole images are skipped: the foreign file and the cut frame are rendered again (issue 27).
        for (const char* name :
            {"shot_0000.png", "shot_0001.png", "shot_0002.png", "shot_0003.png", "shot_0004.png", "shot_0005.png"})
            QCOMPARE(bytesOf(QDir(dir).filePath(QLatin1String(name))),
                bytesOf(QDir(expected).filePath(QLatin1String(name))));
        QCOMPARE(filesIn(dir), frameNames(QStringLiteral("png"), {0, 1, 2, 3, 4, 5}));
        for (int f : {1, 3})
            QVERIFY2(r.err.contains(QStringLiteral("frame %1 (").arg(f)) && r.err.contains(QStringLiteral("skipped")),
                qPrintable(r.err));

        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        auto frames = [&](const char* key) {
            QList<int> list;
            for (const QJsonValue& v : json[QLatin1String(key)].toArray())
                list << v[QStringLiteral("frame")].toInt();
            return list;
        };
        QCOMPARE(frames("written"), (QList<int>{0, 2, 4, 5}));
        QCOMPARE(frames("skipped"), (QList<int>{1, 3}));
        QCOMPARE(json[QStringLiteral("count")].toInt(), 6);

        // Without the option every frame is written again.
        QVERIFY(runCelform(renderArgs(dir, QStringLiteral("png"), QStringLiteral("0-5"))).exitCode == 0);
        QVERIFY(QFileInfo(kept).lastModified() > keptTime);
    }

    // Issue 27: on a full disk (here every file ends at 512 bytes, and each frame is larger) the
    // write of every image format fails: exit 3, one line naming the frame, the file and the
    // system's reason, and neither a short frame nor a temporary file is left. The frame already at
    // the name stays as it was. Before, PNG reported success with cut files and JPEG crashed.
    void fullDiskFramesExitThree_data()
    {
        QTest::addColumn<QString>("suffix");
        for (const char* suffix : {"png", "jpg", "tif", "exr"})
            QTest::newRow(suffix) << QString::fromLatin1(suffix);
    }
    void fullDiskFramesExitThree()
    {
        QFETCH(QString, suffix);
        const QString dir = folder(QStringLiteral("full_") + suffix);
        const QString previous = QDir(dir).filePath(QStringLiteral("shot_0000.") + suffix);
        QFile old(previous);
        QVERIFY(old.open(QIODevice::WriteOnly) && old.write("the previous frame") > 0);
        old.close();
        const Run r = runCelformOnFullDisk(renderArgs(dir, suffix, QStringLiteral("0-1"), {"--threads", "1"}), 512);
        QCOMPARE(r.exitCode, 3);
        const QString last = r.err.trimmed().section(QLatin1Char('\n'), -1);
        QVERIFY2(last.startsWith(QStringLiteral("celform: frame 0: ")) && last.contains(previous)
                && last.contains(QStringLiteral("File too large")),
            qPrintable(r.err));
        QCOMPARE(filesIn(dir), QStringList{QFileInfo(previous).fileName()});
        QCOMPARE(bytesOf(previous), QByteArray("the previous frame"));

        // A device that takes nothing: /dev/full says ENOSPC at the first write and stays a device.
        const QString link = QDir(dir).filePath(QStringLiteral("full.") + suffix);
        QVERIFY(QFile::link(QStringLiteral("/dev/full"), link));
        const Run device = runCelform({"render", sample(), "--size", "96x54", "--out", link});
        QCOMPARE(device.exitCode, 3);
        QVERIFY2(device.err.contains(link) && device.err.contains(QStringLiteral("No space left on device")),
            qPrintable(device.err));
        QVERIFY(!QFileInfo(QStringLiteral("/dev/full")).isFile());
    }

    // Requirement (d): a frame whose file cannot be written (its name is taken by a folder) ends
    // the render with exit code 3 and one line naming the frame and the file; the frames written
    // before it stay.
    void failingFrameExitsThree()
    {
        const QString expected = reference(QStringLiteral("png"));
        const QString dir = folder(QStringLiteral("failing"));
        QVERIFY(QDir(dir).mkdir(QStringLiteral("shot_0003.png")));
        Run r = runCelform(renderArgs(dir, QStringLiteral("png"), QStringLiteral("0-5"), {"--threads", "1"}));
        QCOMPARE(r.exitCode, 3);
        const QString last = r.err.trimmed().section(QLatin1Char('\n'), -1);
        QVERIFY2(last.startsWith(QStringLiteral("celform: frame 3: ")) && last.contains(QStringLiteral("shot_0003.png"))
                && last.contains(QStringLiteral("Is a directory")),
            qPrintable(r.err));
        for (const char* name : {"shot_0000.png", "shot_0001.png", "shot_0002.png"})
            QCOMPARE(bytesOf(QDir(dir).filePath(QLatin1String(name))),
                bytesOf(QDir(expected).filePath(QLatin1String(name))));
        QVERIFY(!QFileInfo::exists(QDir(dir).filePath(QStringLiteral("shot_0005.png"))));
        // Nothing is left behind under a hidden name either.
        QCOMPARE(filesIn(dir), frameNames(QStringLiteral("png"), {0, 1, 2}));

        // With threads the lowest failing frame is named, the same every time.
        r = runCelform(renderArgs(dir, QStringLiteral("png"), QStringLiteral("0-5"), {"--threads", "3"}));
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(QStringLiteral("celform: frame 3: ")), qPrintable(r.err));
    }

    // A folder that does not take files: the first frame fails, named with the system's reason.
    // Root writes into any folder, so as root celform runs as nobody.
    void unwritableFolderExitsThree()
    {
        const uid_t user = ::geteuid() == 0 ? kNobody : ::geteuid();
        if (runCelformAs(user, {"--version"}).exitCode != 0)
            QSKIP("celform cannot be run as nobody here (its folders are not readable by others)");
        const QString locked = folder(QStringLiteral("locked"));
        QVERIFY(QFile::setPermissions(locked, QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        const Run r = runCelformAs(user, renderArgs(locked, QStringLiteral("png"), QStringLiteral("7-9")));
        QFile::setPermissions(locked, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(QStringLiteral("celform: frame 7: ")) && r.err.contains(QStringLiteral("shot_0007.png"))
                && r.err.contains(QStringLiteral("Permission denied")),
            qPrintable(r.err));
        QVERIFY(filesIn(locked).isEmpty());
    }

    // Issue 27: a drawing with text (SVG <text>) on a node without a display: `new --drawing`,
    // `key add --drawing` and `render` aborted in Qt's font database. The text is drawn (fontconfig's
    // fonts, in the import child on the offscreen platform): its outline has an area.
    void svgTextOnANode()
    {
        const QString dir = folder(QStringLiteral("text"));
        auto write = [&](const QString& name, const QByteArray& bytes) {
            QFile f(QDir(dir).filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size());
        };
        write(QStringLiteral("tetra.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
        write(QStringLiteral("words.svg"),
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\" viewBox=\"0 0 200 100\">"
            "<text x=\"10\" y=\"70\" font-family=\"DejaVu Sans\" font-size=\"60\">Hi</text></svg>");
        const QString project = QDir(dir).filePath(QStringLiteral("p.celform"));
        const QString svg = QDir(dir).filePath(QStringLiteral("words.svg"));
        const uid_t me = ::geteuid();
        Run r = runCelformAs(
            me, {"new", QDir(dir).filePath(QStringLiteral("tetra.obj")), "--drawing", svg, "--out", project});
        QVERIFY2(r.exitCode == 0 && r.status == QProcess::NormalExit, qPrintable(r.err));
        r = runCelformAs(
            me, {"key", "add", project, "--name", "side", "--from-base", "--view", "1,0,0", "--drawing", svg});
        QVERIFY2(r.exitCode == 0 && r.status == QProcess::NormalExit, qPrintable(r.err));
        r = runCelformAs(me,
            {"outline", project, "--drawing", "words", "--json", "--out",
                QDir(dir).filePath(QStringLiteral("words_outline.svg"))});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(QJsonDocument::fromJson(r.out.toUtf8()).object()[QStringLiteral("area_pixels")].toInt() > 1000,
            qPrintable(r.out));
        r = runCelformAs(
            me, {"render", project, "--size", "64x48", "--out", QDir(dir).filePath(QStringLiteral("f.png"))});
        QVERIFY2(r.exitCode == 0 && r.status == QProcess::NormalExit, qPrintable(r.err));
    }

    // A render killed at any moment leaves whole pictures under the frames' names, and at most
    // hidden temporary files beside them.
    void killedRenderLeavesNoPartialFile()
    {
        const QString dir = folder(QStringLiteral("killed"));
        auto p = startCelform({"render", sample(), "--size", "640x360", "--frames", "0-99", "--threads", "2", "--out",
            QDir(dir).filePath(QStringLiteral("shot_####.png"))});
        QVERIFY(p->waitForStarted());
        QElapsedTimer timer;
        timer.start();
        while (QDir(dir).entryList({QStringLiteral("shot_*.png")}, QDir::Files).size() < 3 && timer.elapsed() < 60000)
            QThread::msleep(20);
        p->kill(); // SIGKILL
        QVERIFY(p->waitForFinished(10000));
        QCOMPARE(p->exitStatus(), QProcess::CrashExit);
        const QStringList frames = QDir(dir).entryList({QStringLiteral("shot_*.png")}, QDir::Files);
        QVERIFY(frames.size() >= 3 && frames.size() < 100);
        for (const QString& name : frames)
            QCOMPARE(QImage(QDir(dir).filePath(name)).size(), QSize(640, 360));
        for (const QString& name : filesIn(dir))
            QVERIFY2(
                frames.contains(name) || (name.startsWith(QLatin1Char('.')) && name.contains(QStringLiteral(".tmp."))),
                qPrintable(name));
    }

    // Fewer frames at once when that many would not fit in memory, said on standard error (the
    // files exist, so --skip-existing renders nothing and the test needs no memory itself).
    void threadsFitInMemory()
    {
        if (celform::test::kAddressSanitizer)
            QSKIP("the memory check reads the address-space limit, which AddressSanitizer's shadow memory rules out");
        const QString dir = folder(QStringLiteral("memory"));
        // Whole images (--skip-existing skips nothing less): a pixel each.
        QImage pixel(1, 1, QImage::Format_RGB32);
        pixel.fill(Qt::white);
        for (const QString& name : frameNames(QStringLiteral("png"), {0, 1, 2, 3}))
            QVERIFY(pixel.save(QDir(dir).filePath(name), "PNG"));
        // 4000 x 4000 pixels need about 1.4 GB a frame: one fits in 2 GB of address space.
        const Run r = runCelformLimited(
            {"render", sample(), "--size", "4000x4000", "--frames", "0-3", "--threads", "4", "--skip-existing",
                "--json", "--out", QDir(dir).filePath(QStringLiteral("shot_####.png"))},
            2ll << 30, 60000);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("warning: rendering 1 frames at a time, not 4")), qPrintable(r.err));
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object()[QStringLiteral("threads")].toInt(), 1);
    }

    void badFramesAndThreads_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::newRow("backwards") << QStringList{"--frames", "5-2"};
        QTest::newRow("step 0") << QStringList{"--frames", "1-4:0"};
        QTest::newRow("negative step") << QStringList{"--frames", "1-4:-1"};
        QTest::newRow("step missing") << QStringList{"--frames", "1-4:"};
        QTest::newRow("step not a number") << QStringList{"--frames", "1-4:x"};
        QTest::newRow("too many frames") << QStringList{"--frames", "0-200000:2"};
        QTest::newRow("threads 0") << QStringList{"--threads", "0"};
        QTest::newRow("threads not a number") << QStringList{"--threads", "two"};
    }
    // Requirement (e): exit code 2 with the usage, and nothing written.
    void badFramesAndThreads()
    {
        QFETCH(QStringList, options);
        const QString dir = folder(QStringLiteral("usage"));
        const Run r = runCelform(QStringList{"render", sample(), "--size", "32x18", "--out",
                                     QDir(dir).filePath(QStringLiteral("shot_####.png"))}
            + options);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("usage:")) && r.err.contains(options[0]), qPrintable(r.err));
        QVERIFY(filesIn(dir).isEmpty());
    }

    // scripts/farm/slurm-render.sh as Slurm runs it on a node, one array task after another
    // (docs/farm.md): the chunks together are the whole shot, and a task beyond the last chunk
    // renders nothing.
    void slurmTasksRenderTheShot()
    {
        const QString expected = reference(QStringLiteral("exr"));
        const QString dir = folder(QStringLiteral("slurm"));
        for (int task = 0; task < 4; ++task) {
            QProcess p;
            QProcessEnvironment env = nodeEnvironment();
            env.insert(QStringLiteral("SLURM_ARRAY_TASK_ID"), QString::number(task));
            env.insert(QStringLiteral("SLURM_ARRAY_TASK_COUNT"), QStringLiteral("4"));
            env.insert(QStringLiteral("SLURM_CPUS_PER_TASK"), QStringLiteral("2"));
            env.insert(QStringLiteral("CELFORM"), QStringLiteral(CELFORM_EXECUTABLE));
            p.setProcessEnvironment(env);
            p.start(QStringLiteral("bash"),
                {QStringLiteral(CELFORM_SOURCE_DIR "/scripts/farm/slurm-render.sh"), sample(), "0", "5", "2",
                    QDir(dir).filePath(QStringLiteral("shot_####.exr")), "--size", "96x54"});
            QVERIFY(p.waitForFinished(120000));
            QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        }
        compareFolders(expected, dir);
    }

    // The templates beside the Slurm script (docs/farm.md), read with real parsers (PyYAML and
    // ElementTree from Debian's Python, Node for the Flamenco job compiler), give the commands a
    // farm would run; those run on two "nodes" (two processes at a time, alternate chunks) give
    // the shot one process renders.
    void farmTemplatesRenderTheShot_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("open job description") << QStringLiteral("openjd");
        QTest::newRow("opencue") << QStringLiteral("opencue");
        QTest::newRow("flamenco") << QStringLiteral("flamenco");
    }

    void farmTemplatesRenderTheShot()
    {
        QFETCH(QString, kind);
        const QString python = QStringLiteral("/usr/bin/python3");
        const QString node = QStandardPaths::findExecutable(QStringLiteral("node"));
        const QString farm = QStringLiteral(CELFORM_SOURCE_DIR "/scripts/farm/");
        const QString tools = QStringLiteral(CELFORM_SOURCE_DIR "/tests/app/");
        const QString dir = folder(QStringLiteral("template_") + kind);
        const QString out = QDir(dir).filePath(QStringLiteral("shot_####.exr"));
        const QString binary = QStringLiteral(CELFORM_EXECUTABLE);
        QString program;
        QStringList args;
        if (kind == QLatin1String("flamenco")) {
            if (node.isEmpty())
                QSKIP("node is not installed (scripts/setup.sh)");
            QProcess check;
            check.start(node, {QStringLiteral("--check"), farm + QStringLiteral("flamenco-celform-render.js")});
            QVERIFY(check.waitForFinished(60000));
            QVERIFY2(check.exitCode() == 0, check.readAllStandardError().constData());
            const QJsonObject settings{{"project", sample()}, {"frames", "0-5"}, {"chunk_size", 2},
                {"render_output_path", out}, {"size", "96x54"}, {"threads", 1}, {"celform", binary}};
            program = node;
            args = QStringList{tools + QStringLiteral("flamenco_shim.js"),
                farm + QStringLiteral("flamenco-celform-render.js"),
                QString::fromUtf8(QJsonDocument(settings).toJson(QJsonDocument::Compact))};
        } else {
            QProcess check;
            check.start(python, {QStringLiteral("-c"), QStringLiteral("import yaml")});
            if (!check.waitForFinished(60000) || check.exitCode() != 0)
                QSKIP("Debian's python3-yaml is not installed (scripts/setup.sh)");
            program = python;
            args = kind == QLatin1String("openjd")
                ? QStringList{tools + QStringLiteral("farm_template_commands.py"), QStringLiteral("openjd"),
                    farm + QStringLiteral("openjd-render.yaml"), QStringLiteral("Project=") + sample(),
                    QStringLiteral("Output=") + out, QStringLiteral("Frames=0-5"), QStringLiteral("ChunkSize=2"),
                    QStringLiteral("Size=96x54"), QStringLiteral("Threads=1"), QStringLiteral("Celform=") + binary}
                : QStringList{tools + QStringLiteral("farm_template_commands.py"), QStringLiteral("opencue"),
                    farm + QStringLiteral("opencue-render.xml"), QStringLiteral("CELFORM_BINARY=") + binary,
                    QStringLiteral("CELFORM_PROJECT=") + sample(), QStringLiteral("CELFORM_OUTPUT=") + out,
                    QStringLiteral("CELFORM_SIZE=96x54"), QStringLiteral("CELFORM_RANGE=0-5"),
                    QStringLiteral("CELFORM_LAST=5"), QStringLiteral("CELFORM_CHUNK=4"),
                    QStringLiteral("CELFORM_SHOW=test"), QStringLiteral("CELFORM_SHOT=sh010"),
                    QStringLiteral("CELFORM_USER=celform")};
        }
        QProcess expand;
        expand.start(program, args);
        QVERIFY(expand.waitForFinished(60000));
        QVERIFY2(expand.exitCode() == 0, expand.readAllStandardError().constData());
        const QJsonArray commands = QJsonDocument::fromJson(expand.readAllStandardOutput()).array();
        // Chunks of 2 frames (0-1, 2-3, 4-5), or of 4 for OpenCue (0-3, and 4-7 clamped to 4-5).
        QCOMPARE(commands.size(), kind == QLatin1String("opencue") ? 2 : 3);
        // Two nodes at once, each taking every other chunk.
        for (qsizetype round = 0; round < commands.size(); round += 2) {
            std::vector<std::unique_ptr<QProcess>> nodes;
            for (qsizetype c = round; c < std::min(round + 2, commands.size()); ++c) {
                QStringList argv;
                for (const QJsonValue& a : commands[c].toArray())
                    argv << a.toString();
                QVERIFY(argv.join(QLatin1Char(' ')).contains(binary + QStringLiteral(" render ")));
                auto p = std::make_unique<QProcess>();
                p->setProcessEnvironment(nodeEnvironment());
                p->start(argv.takeFirst(), argv);
                nodes.push_back(std::move(p));
            }
            for (const auto& p : nodes) {
                QVERIFY(p->waitForFinished(120000));
                QVERIFY2(p->exitCode() == 0, p->readAllStandardError().constData());
            }
        }
        compareFolders(reference(QStringLiteral("exr")), dir);
    }

    // A step renders every STEP-th frame from A, up to B.
    void stepsPickTheirFrames()
    {
        const QString dir = folder(QStringLiteral("step"));
        const Run r = runCelform(renderArgs(dir, QStringLiteral("png"), QStringLiteral("2-11:4")));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(filesIn(dir), frameNames(QStringLiteral("png"), {2, 6, 10}));
    }
};

QTEST_GUILESS_MAIN(TestCliFarm)
#include "test_cli_farm.moc"
