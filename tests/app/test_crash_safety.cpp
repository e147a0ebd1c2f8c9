// Crash-safe saving: `celform set P --sharpness X` saves a large project, and is killed
// with SIGKILL while it runs, at random moments spread over the run and over its save, and (when
// strace can inject signals) at each system call of the save in turn. After every kill the project
// opens and holds the old or the new sharpness, never a mixture, and its backup P.bak exists and
// opens. The test reports where the kills landed.
//
// CELFORM_KILL_SEED changes the random delays (the seed is printed); CELFORM_KILL_ROUNDS the number
// of random kills (at least 50 by default).
#include "test_support.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"

#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <map>
#include <optional>
#include <random>
#include <thread>

#include <csignal>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

using namespace celform;
using namespace celform::model;

namespace {

constexpr int kKeys = 20;
constexpr std::uint64_t kDefaultSeed = 1414;

/// Where a save stood when its process died, from what the process had open just before the kill
/// and what it left on disk.
enum class Phase {
    Starting, ///< before or between the load and the save: neither the project nor a temporary file open
    Loading, ///< reading the project
    Writing, ///< writing the new version into a temporary file
    NoBackup, ///< the old backup removed and the new one not made (must never be seen)
    BackupStaged, ///< the new backup made under a temporary name, the old one still P.bak
    BackupLinked, ///< P.bak made from the old version; the new one not yet in place
    TemporaryNamed, ///< the new version given a temporary name beside P, not yet renamed over it
    Replaced, ///< the new version in place (the process was exiting)
    Untouched, ///< project and backup as they were (where nothing is known of the process)
};

QString phaseName(Phase p)
{
    switch (p) {
    case Phase::Starting:
        return QStringLiteral("starting up / between load and save");
    case Phase::Loading:
        return QStringLiteral("loading the project");
    case Phase::Writing:
        return QStringLiteral("writing the new version (temporary file)");
    case Phase::NoBackup:
        return QStringLiteral("old backup removed, new backup not made");
    case Phase::BackupStaged:
        return QStringLiteral("new backup made beside the old one, not yet renamed");
    case Phase::BackupLinked:
        return QStringLiteral("backup made, new version not yet in place");
    case Phase::TemporaryNamed:
        return QStringLiteral("new version named beside the project, not yet renamed");
    case Phase::Replaced:
        return QStringLiteral("new version in place");
    case Phase::Untouched:
        return QStringLiteral("project and backup as they were");
    }
    return {};
}

/// The environment of the command line: no display, as in test_cli.
std::vector<std::string> childEnvironment()
{
    std::vector<std::string> env;
    std::string asanOptions;
    for (char** e = environ; *e; ++e) {
        const std::string var(*e);
        if (var.rfind("DISPLAY=", 0) == 0 || var.rfind("WAYLAND_DISPLAY=", 0) == 0
            || var.rfind("QT_QPA_PLATFORM=", 0) == 0)
            continue;
        if (var.rfind("ASAN_OPTIONS=", 0) == 0)
            asanOptions = var.substr(13);
        else
            env.push_back(var);
    }
    env.emplace_back("QT_QPA_PLATFORM=offscreen");
    // Under AddressSanitizer: LeakSanitizer suspends the process with ptrace at exit, which fails
    // under strace (killAtEachStepOfTheSave). The same command's leaks are checked by test_cli.
    if (celform::test::kAddressSanitizer)
        asanOptions += ":detect_leaks=0";
    if (!asanOptions.empty())
        env.push_back("ASAN_OPTIONS=" + asanOptions);
    return env;
}

/// Starts a program without waiting (posix_spawn: the test reaps the child itself, so its pid
/// cannot be reused before the kill). Returns the pid, or -1.
pid_t spawn(const QString& program, const QStringList& args)
{
    std::vector<std::string> argStrings{program.toStdString()};
    for (const QString& a : args)
        argStrings.push_back(a.toStdString());
    std::vector<char*> argv;
    for (auto& a : argStrings)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> envStrings = childEnvironment();
    std::vector<char*> envp;
    for (auto& e : envStrings)
        envp.push_back(e.data());
    envp.push_back(nullptr);
    pid_t pid = -1;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // The children's output (there is none on success) stays out of the test log.
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    const int rc = posix_spawn(&pid, argStrings[0].c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    return rc == 0 ? pid : -1;
}

/// Runs a program to its end; returns its wait status.
int runToEnd(const QString& program, const QStringList& args)
{
    const pid_t pid = spawn(program, args);
    int status = -1;
    if (pid > 0)
        waitpid(pid, &status, 0);
    return status;
}

/// What a live process has open or mapped, by path.
QStringList openFiles(pid_t pid)
{
    QStringList targets;
    const QString fdDir = QStringLiteral("/proc/%1/fd").arg(pid);
    for (const QString& fd : QDir(fdDir).entryList(QDir::NoDotAndDotDot | QDir::AllEntries | QDir::System)) {
        char buffer[4096];
        const QByteArray link = QFile::encodeName(fdDir + QLatin1Char('/') + fd);
        const ssize_t n = ::readlink(link.constData(), buffer, sizeof(buffer) - 1);
        if (n > 0)
            targets << QFile::decodeName(QByteArray(buffer, int(n)));
    }
    QFile maps(QStringLiteral("/proc/%1/maps").arg(pid));
    if (maps.open(QIODevice::ReadOnly))
        for (const QByteArray& line : maps.readAll().split('\n'))
            if (const int slash = line.indexOf('/'); slash >= 0)
                targets << QFile::decodeName(line.mid(slash));
    return targets;
}

ino_t inode(const QString& path)
{
    struct stat st { };
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 ? st.st_ino : 0;
}

QString number(double x)
{
    return QString::number(x, 'g', 17);
}

} // namespace

class TestCrashSafety : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_project;
    ProjectData m_reference; ///< the project as built, sharpness aside
    double m_current = 1.0; ///< the sharpness the project holds now
    double m_next = 2.0;
    qint64 m_saveMs = 0; ///< one saveProject of the project, in this process
    std::map<Phase, int> m_phases;
    int m_leftovers = 0;

    QString celform() const { return QStringLiteral(CELFORM_EXECUTABLE); }
    QStringList setArgs(double sharpness) const
    {
        return {QStringLiteral("set"), m_project, QStringLiteral("--sharpness"), number(sharpness)};
    }

    /// The start of the hidden temporary name a save writes or links its new version under
    /// (".NAME." for the project NAME.celform).
    QString hiddenPrefix() const
    {
        return QLatin1Char('.') + QFileInfo(m_project).completeBaseName() + QLatin1Char('.');
    }

    /// Files a killed save left beside the project, removed after counting: complete new versions
    /// under their hidden temporary name, and a new backup under its temporary name (P.bak.new).
    struct Leftovers {
        int versions = 0;
        int backups = 0;
    };
    Leftovers removeLeftovers()
    {
        const QString base = QFileInfo(m_project).fileName();
        const QString hidden = hiddenPrefix();
        Leftovers found;
        for (const QString& name : QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden)) {
            const bool version = name.startsWith(hidden);
            const bool backup = name.startsWith(base + QStringLiteral(".bak")) && name != base + QStringLiteral(".bak");
            if (!version && !backup)
                continue;
            QFile::remove(m_dir.filePath(name));
            ++(backup ? found.backups : found.versions);
        }
        return found;
    }

    /// Loads a file of the project; the sharpness it holds, or an error message.
    std::pair<double, QString> sharpnessIn(const QString& path) const
    {
        try {
            ProjectData data = loadProject(path, DrawingImages::Skip);
            const double sharpness = data.blend.sharpness;
            data.blend.sharpness = m_reference.blend.sharpness;
            if (!(data == m_reference))
                return {0.0, QStringLiteral("%1 opens but differs from the project beyond its sharpness").arg(path)};
            return {sharpness, {}};
        } catch (const IoError& e) {
            return {0.0, e.message()};
        }
    }

    /// The checks after a killed save of sharpness `next`; returns the phase it left, or an error.
    /// openBeforeKill: what the process had open just before the kill, when known.
    std::pair<Phase, QString> afterKill(double next, const std::optional<QStringList>& openBeforeKill)
    {
        const QString backup = m_project + QStringLiteral(".bak");
        const bool backupExists = QFileInfo::exists(backup);
        const bool backupIsCurrent = backupExists && inode(backup) == inode(m_project);
        const Leftovers leftovers = removeLeftovers();
        m_leftovers += leftovers.versions + leftovers.backups;

        const auto [sharpness, error] = sharpnessIn(m_project);
        if (!error.isEmpty())
            return {Phase::Starting, QStringLiteral("the project does not open: %1").arg(error)};
        if (sharpness != m_current && sharpness != next)
            return {Phase::Starting,
                QStringLiteral("the project holds sharpness %1, neither the old %2 nor the new %3")
                    .arg(number(sharpness), number(m_current), number(next))};
        if (!backupExists)
            return {Phase::NoBackup, QStringLiteral("the backup %1 is missing").arg(backup)};
        // The backup is a whole earlier version: it opens, equal to the project but for its sharpness.
        const QString backupError = sharpnessIn(backup).second;
        if (!backupError.isEmpty())
            return {Phase::Starting, QStringLiteral("the backup does not open: %1").arg(backupError)};

        // A backup made from the old version and a project not yet replaced are the same file
        // (a hard link): give the project a file of its own again, so that the next kill tells
        // apart a backup it made from one made before.
        if (backupIsCurrent) {
            const QString copy = m_project + QStringLiteral(".copy");
            QFile::remove(copy);
            if (!QFile::copy(m_project, copy)
                || ::rename(QFile::encodeName(copy).constData(), QFile::encodeName(m_project).constData()) != 0)
                return {Phase::Starting, QStringLiteral("could not separate the project from its backup")};
        }

        Phase phase = Phase::Starting;
        const bool replaced = sharpness == next;
        m_current = sharpness;
        if (replaced)
            phase = Phase::Replaced;
        else if (leftovers.versions > 0)
            phase = Phase::TemporaryNamed;
        else if (leftovers.backups > 0)
            phase = Phase::BackupStaged;
        else if (backupIsCurrent)
            phase = Phase::BackupLinked;
        else if (!openBeforeKill)
            phase = Phase::Untouched;
        else if (std::any_of(openBeforeKill->begin(), openBeforeKill->end(), [this](const QString& f) {
                     // An unnamed (O_TMPFILE: "DIR/#inode (deleted)") or a named temporary file.
                     return (f.startsWith(m_dir.path()) && f.contains(QLatin1String("/#")))
                         || f.startsWith(m_dir.filePath(hiddenPrefix()));
                 }))
            phase = Phase::Writing;
        else if (openBeforeKill->contains(m_project))
            phase = Phase::Loading;
        return {phase, {}};
    }

private slots:
    void initTestCase()
    {
        CELFORM_REQUIRE_SHARED(mesh, QStringLiteral("meshes/stanford_dragon.ply"));
        QVERIFY(m_dir.isValid());
        QVERIFY2(QFileInfo::exists(celform()), "the celform binary is missing");
        // The dragon with 20 keys around it, each moving a tenth of the vertices, made with the
        // document API as the editor makes them.
        Document doc;
        doc.newFromMesh(mesh);
        const algo::TriMesh& base = *doc.data().baseMesh;
        const Eigen::Vector3f lo = base.vertices.colwise().minCoeff(), hi = base.vertices.colwise().maxCoeff();
        const Eigen::Vector3d centre = ((lo + hi) / 2).cast<double>();
        const double radius = double((hi - lo).norm());
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> delta(-0.01f, 0.01f);
        for (int k = 0; k < kKeys; ++k) {
            // Directions spread over the sphere (a Fibonacci lattice), far apart enough for keys.
            const double y = 1.0 - 2.0 * (k + 0.5) / kKeys, r = std::sqrt(1.0 - y * y);
            const double phi = k * 2.39996322972865332;
            const Eigen::Vector3d dir(r * std::cos(phi), y, r * std::sin(phi));
            Camera camera;
            camera.eye = centre + dir * 3.0 * radius;
            camera.target = centre;
            camera.up = std::abs(dir.y()) > 0.9 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 1, 0);
            SparseOffsets offsets;
            for (std::uint32_t v = std::uint32_t(k); v < std::uint32_t(base.vertexCount()); v += 10) {
                offsets.indices.push_back(v);
                offsets.deltas.emplace_back(delta(rng), delta(rng), delta(rng));
            }
            doc.keys().createKey(QStringLiteral("key %1").arg(k + 1), camera, {}, std::move(offsets));
        }
        doc.look().setSharpness(m_current);
        m_project = m_dir.filePath(QStringLiteral("dragon.celform"));
        doc.saveAs(m_project);
        QElapsedTimer timer;
        timer.start();
        doc.saveAs(m_project); // the second save leaves P.bak
        m_saveMs = timer.elapsed();
        QVERIFY(QFileInfo::exists(m_project + QStringLiteral(".bak")));
        m_reference = loadProject(m_project, DrawingImages::Skip);
        QCOMPARE(m_reference.keys.size(), std::size_t(kKeys));
        qInfo("project: %lld MB, %d keys; one save in this process: %lld ms",
            static_cast<long long>(QFileInfo(m_project).size() >> 20), kKeys, static_cast<long long>(m_saveMs));
    }

    void killDuringSaves()
    {
        // One whole run first: the kills spread over it, and half of them over its save.
        QElapsedTimer timer;
        qint64 runMs = 0;
        for (int i = 0; i < 2; ++i) {
            timer.start();
            const int status = runToEnd(celform(), setArgs(m_next));
            const qint64 ms = timer.elapsed();
            QVERIFY2(WIFEXITED(status) && WEXITSTATUS(status) == 0, "celform set failed");
            QCOMPARE(sharpnessIn(m_project).first, m_next);
            m_current = m_next;
            m_next += 0.125;
            runMs = i == 0 ? ms : std::min(runMs, ms);
        }
        const qint64 saveMs = std::clamp<qint64>(m_saveMs, 1, runMs);

        bool ok = false;
        const qulonglong envSeed = qEnvironmentVariable("CELFORM_KILL_SEED").toULongLong(&ok);
        const std::uint64_t seed = ok ? envSeed : kDefaultSeed;
        int rounds = qEnvironmentVariableIntValue("CELFORM_KILL_ROUNDS", &ok);
        if (!ok || rounds <= 0)
            rounds = 60;
        std::mt19937_64 rng(seed);
        qInfo("random kills: seed %llu, %d kills over a %lld ms run whose save takes about %lld ms",
            static_cast<unsigned long long>(seed), rounds, static_cast<long long>(runMs),
            static_cast<long long>(saveMs));

        m_phases.clear();
        int kills = 0, finished = 0;
        for (int round = 0; kills < rounds && round < 4 * rounds; ++round) {
            // Even rounds anywhere in the run, odd ones in its last part, where the save is (with
            // some margin: a run under load takes longer than the one measured).
            const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
            const double startMs = round % 2 == 0 ? 0.0 : double(std::max<qint64>(0, runMs - 2 * saveMs));
            const auto delayUs = qint64((startMs + u * (double(runMs) * 1.1 - startMs)) * 1000.0);
            const double next = m_next;
            m_next += 0.125;

            const pid_t pid = spawn(celform(), setArgs(next));
            QVERIFY(pid > 0);
            std::this_thread::sleep_for(std::chrono::microseconds(delayUs));
            int status = 0;
            if (waitpid(pid, &status, WNOHANG) == pid) {
                // Finished before the kill: a complete save, checked like the others.
                ++finished;
                QVERIFY2(sharpnessIn(m_project).first == next, "a finished save did not store its sharpness");
                m_current = next;
                continue;
            }
            const QStringList open = openFiles(pid);
            ::kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            ++kills;
            const auto [phase, error] = afterKill(next, open);
            QVERIFY2(error.isEmpty(),
                qPrintable(QStringLiteral("kill %1 after %2 ms (seed %3): %4")
                               .arg(kills)
                               .arg(double(delayUs) / 1000.0)
                               .arg(seed)
                               .arg(error)));
            ++m_phases[phase];
        }
        QVERIFY2(kills >= rounds, "too many runs finished before their kill");
        for (const auto& [phase, count] : m_phases)
            qInfo("  %3d kills: %s", count, qPrintable(phaseName(phase)));
        qInfo("  %d runs finished before their kill; %d temporary files left behind", finished, m_leftovers);
    }

    void killAtEachStepOfTheSave()
    {
        // strace runs the save once recording its file system calls, then again for each call
        // from the temporary file's creation on, killing the process as it enters that call.
        const QString strace = QStandardPaths::findExecutable(QStringLiteral("strace"));
        if (strace.isEmpty())
            QSKIP("strace is not installed");
        if (runToEnd(strace, {QStringLiteral("-o"), QStringLiteral("/dev/null"), QStringLiteral("/bin/true")}) != 0)
            QSKIP("strace cannot trace here (ptrace not permitted)");

        const QString calls = QStringLiteral(
            "openat,write,unlink,unlinkat,link,linkat,rename,renameat,renameat2,fsync,fdatasync,exit_group");
        const QString log = m_dir.filePath(QStringLiteral("save.strace"));
        const int status = runToEnd(strace,
            QStringList{QStringLiteral("-qq"), QStringLiteral("-o"), log, QStringLiteral("-e"),
                QStringLiteral("trace=") + calls, celform()}
                + setArgs(m_next));
        QVERIFY2(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the traced save failed");
        m_current = m_next;
        m_next += 0.125;

        // Each call of the save: its name and its occurrence among the calls of that name.
        QFile file(log);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QRegularExpression line(QStringLiteral("^(\\w+)\\((.*)$"));
        std::map<QString, int> seen;
        std::vector<std::pair<QString, int>> steps;
        bool saving = false;
        const QString dirName = m_dir.path();
        for (const QByteArray& raw : file.readAll().split('\n')) {
            const auto m = line.match(QString::fromUtf8(raw));
            if (!m.hasMatch())
                continue;
            const QString name = m.captured(1);
            const int occurrence = ++seen[name];
            // The save starts where the temporary file is made: O_TMPFILE in the project's folder,
            // or a named file beside the project where O_TMPFILE is missing.
            const QString args = m.captured(2);
            if (!saving)
                saving = name == QLatin1String("openat")
                    && ((args.contains(QLatin1String("O_TMPFILE")) && args.contains(dirName))
                        || (args.contains(m_dir.filePath(hiddenPrefix())) && args.contains(QLatin1String("O_CREAT"))));
            else if (name != QLatin1String("openat"))
                steps.emplace_back(name, occurrence);
        }
        // The data goes out in many writes: keep the first, the middle and the last of a run of
        // writes (every other call stays).
        std::vector<std::pair<QString, int>> kept;
        const QLatin1String write("write");
        for (std::size_t i = 0; i < steps.size(); ++i) {
            if (steps[i].first != write) {
                kept.push_back(steps[i]);
                continue;
            }
            std::size_t end = i;
            while (end + 1 < steps.size() && steps[end + 1].first == write)
                ++end;
            for (const std::size_t k : {i, (i + end) / 2, end})
                if (kept.empty() || kept.back() != steps[k])
                    kept.push_back(steps[k]);
            i = end;
        }
        steps = std::move(kept);
        QVERIFY2(steps.size() >= 4, "the traced save shows too few steps");

        QStringList sequence;
        for (const auto& [name, occurrence] : steps) {
            const double next = m_next;
            m_next += 0.125;
            const QString inject = QStringLiteral("inject=%1:signal=KILL:when=%2").arg(name).arg(occurrence);
            runToEnd(strace,
                QStringList{QStringLiteral("-qq"), QStringLiteral("-o"), QStringLiteral("/dev/null"),
                    QStringLiteral("-e"), QStringLiteral("trace=") + name, QStringLiteral("-e"), inject, celform()}
                    + setArgs(next));
            const auto [phase, error] = afterKill(next, std::nullopt);
            QVERIFY2(error.isEmpty(),
                qPrintable(QStringLiteral("killed on entering %1 (call %2 of its name): %3")
                               .arg(name)
                               .arg(occurrence)
                               .arg(error)));
            sequence << QStringLiteral("%1#%2 -> %3").arg(name).arg(occurrence).arg(phaseName(phase));
        }
        for (const QString& s : sequence)
            qInfo("  killed on entering %s", qPrintable(s));
    }
};

QTEST_GUILESS_MAIN(TestCrashSafety)
#include "test_crash_safety.moc"
