// Issue 29: the heavy sub-commands start again with glibc's malloc asking for transparent huge
// pages (launcher/large_pages.h), unless the host takes freed memory back (a virtio balloon with
// free page reporting) or CELFORM_LARGE_PAGES=1 asks all the same; the others start once. Traced
// with strace (skipped without it, or where the kernel offers no huge pages, or in a sanitizer
// build, which never restarts). The balloon's detection is checked on made-up sysfs trees.
#include "test_support.h"

#include "launcher/large_pages.h"

#include <QDir>

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QtTest>

class TestLargePages : public QObject {
    Q_OBJECT

    /// The execve calls of `celform args` under strace -f (-v: with their environments).
    QStringList execs(const QStringList& args, const QProcessEnvironment& env)
    {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(m_strace, QStringList{"-f", "-v", "-s", "4096", "-e", "trace=execve", "--", CELFORM_EXECUTABLE} + args);
        if (!p.waitForFinished(120000))
            return {QStringLiteral("timeout")};
        QStringList calls;
        for (const QString& line : QString::fromLocal8Bit(p.readAllStandardError()).split(QLatin1Char('\n')))
            if (line.contains(QLatin1String("execve(")) && !line.contains(QLatin1String("resumed")))
                calls << line;
        return calls;
    }

    QString m_strace;
    QTemporaryDir m_dir;
    QString m_project;

private slots:
    void balloonWithFreePageReportingIsFound()
    {
        QTemporaryDir sys;
        QVERIFY(sys.isValid());
        const auto device = [&](const QString& name, const QByteArray& id, const QByteArray& features, bool bound) {
            QDir(sys.path()).mkpath(name);
            QFile d(sys.filePath(name + QStringLiteral("/device")));
            QFile f(sys.filePath(name + QStringLiteral("/features")));
            QVERIFY(d.open(QIODevice::WriteOnly) && d.write(id + "\n") > 0);
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write(features + "\n") > 0);
            if (bound)
                QVERIFY(QFile::link(sys.path(), sys.filePath(name + QStringLiteral("/driver"))));
        };
        const QByteArray root = sys.path().toLocal8Bit();
        QVERIFY(!celform::app::freedMemoryGoesToHost(root.constData())); // no device
        QVERIFY(!celform::app::freedMemoryGoesToHost("/nonexistent/virtio"));
        device(QStringLiteral("virtio0"), "0x0002", "0010011001100100", true); // a disk with bit 5 set
        device(QStringLiteral("virtio1"), "0x0005", "0110000100000000", true); // a balloon without it
        QVERIFY(!celform::app::freedMemoryGoesToHost(root.constData()));
        device(QStringLiteral("virtio2"), "0x0005", "0110010100000000", false); // reporting, no driver
        QVERIFY(!celform::app::freedMemoryGoesToHost(root.constData()));
        device(QStringLiteral("virtio3"), "0x0005", "0110010100000000", true); // reporting, bound
        QVERIFY(celform::app::freedMemoryGoesToHost(root.constData()));
    }

    void initTestCase()
    {
        m_strace = QStandardPaths::findExecutable(QStringLiteral("strace"));
        if (m_strace.isEmpty())
            QSKIP("strace is not installed");
        QFile thp(QStringLiteral("/sys/kernel/mm/transparent_hugepage/enabled"));
        if (!thp.open(QIODevice::ReadOnly) || thp.readAll().contains("[never]"))
            QSKIP("the kernel offers no transparent huge pages");
#if defined(__SANITIZE_ADDRESS__)
        QSKIP("sanitizer builds do not restart");
#endif
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
        QSKIP("sanitizer builds do not restart");
#endif
#endif
        m_project = m_dir.filePath(QStringLiteral("p.celform"));
        QVERIFY(QFile::copy(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"), m_project));
    }

    void renderRestartsWithHugePages()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("GLIBC_TUNABLES"));
        env.remove(QStringLiteral("CELFORM_LARGE_PAGES"));
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        // Left to itself, a render restarts unless this machine's host takes freed memory back.
        const bool toHost = celform::app::freedMemoryGoesToHost("/sys/bus/virtio/devices");
        QCOMPARE(
            execs({"render", m_project, "--size", "32x24", "--out", m_dir.filePath(QStringLiteral("auto.png"))}, env)
                .size(),
            toHost ? 1 : 2);
        // CELFORM_LARGE_PAGES=1 restarts everywhere; the checks below go on with it.
        env.insert(QStringLiteral("CELFORM_LARGE_PAGES"), QStringLiteral("1"));
        const QStringList render
            = execs({"render", m_project, "--size", "32x24", "--out", m_dir.filePath(QStringLiteral("a.png"))}, env);
        QCOMPARE(render.size(), 2);
        QVERIFY2(render[1].contains(QLatin1String("/proc/self/exe"))
                && render[1].contains(QLatin1String("GLIBC_TUNABLES=glibc.malloc.hugetlb=1")),
            qPrintable(render[1]));
        QVERIFY(QFile::exists(m_dir.filePath(QStringLiteral("a.png"))));

        // Another tunable is kept; a set hugetlb, CELFORM_LARGE_PAGES=0 and light commands start once.
        env.insert(QStringLiteral("GLIBC_TUNABLES"), QStringLiteral("glibc.malloc.arena_max=2"));
        const QStringList kept
            = execs({"render", m_project, "--size", "32x24", "--out", m_dir.filePath(QStringLiteral("b.png"))}, env);
        QCOMPARE(kept.size(), 2);
        QVERIFY2(kept[1].contains(QLatin1String("GLIBC_TUNABLES=glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1")),
            qPrintable(kept[1]));
        env.insert(QStringLiteral("GLIBC_TUNABLES"), QStringLiteral("glibc.malloc.hugetlb=0"));
        QCOMPARE(execs({"render", m_project, "--size", "32x24", "--out", m_dir.filePath(QStringLiteral("c.png"))}, env)
                     .size(),
            1);
        env.remove(QStringLiteral("GLIBC_TUNABLES"));
        env.insert(QStringLiteral("CELFORM_LARGE_PAGES"), QStringLiteral("0"));
        QCOMPARE(execs({"render", m_project, "--size", "32x24", "--out", m_dir.filePath(QStringLiteral("d.png"))}, env)
                     .size(),
            1);
        env.insert(QStringLiteral("CELFORM_LARGE_PAGES"), QStringLiteral("1"));
        QCOMPARE(execs({"info", m_project}, env).size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestLargePages)
#include "test_large_pages.moc"
