// Recovery files: <dir>/session-<pid>-<time>.celform with a .json note and a .lock.
#include "editor/recovery_manager.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

namespace celform::app {

RecoveryManager::RecoveryManager(model::Document* document, const QString& directory, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory)
{
    QDir().mkpath(m_directory);
    const QString base = QDir(m_directory)
                             .filePath(QStringLiteral("session-%1-%2")
                                           .arg(QCoreApplication::applicationPid())
                                           .arg(QDateTime::currentMSecsSinceEpoch()));
    m_ownFile = base + QStringLiteral(".celform");
    m_lock = std::make_unique<QLockFile>(base + QStringLiteral(".lock"));
    m_lock->setStaleLockTime(0); // held for the whole session; stale only when the process is gone
    m_lock->tryLock(0);
    connect(&m_timer, &QTimer::timeout, this, &RecoveryManager::autosaveNow);
    // Any change counts, also one merged into the undo step last autosaved (a slider still
    // moving, a brush stroke going on), which leaves the undo index where it was.
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        if (!change.onlyPlayhead())
            m_dirty = true;
    });
    // A saved or reopened document needs no recovery copy.
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            removeOwn();
    });
}

RecoveryManager::~RecoveryManager() = default;

void RecoveryManager::setInterval(int milliseconds)
{
    if (milliseconds <= 0) {
        m_timer.stop();
        return;
    }
    m_timer.start(milliseconds);
}

bool RecoveryManager::autosaveNow()
{
    if (!m_document->isModified() || !m_dirty)
        return true;
    try {
        m_document->saveCopy(m_ownFile);
    } catch (const model::IoError& e) {
        emit autosaveFailed(e.message());
        return false;
    }
    QFile note(QString(m_ownFile).replace(QStringLiteral(".celform"), QStringLiteral(".json")));
    if (note.open(QIODevice::WriteOnly | QIODevice::Truncate))
        note.write(QJsonDocument(QJsonObject{{"original", m_document->filePath()},
                                     {"saved_at", QDateTime::currentDateTime().toString(Qt::ISODate)}})
                       .toJson());
    m_dirty = false;
    emit autosaved(m_ownFile);
    return true;
}

std::vector<RecoveryManager::Orphan> RecoveryManager::orphans() const
{
    std::vector<Orphan> result;
    const QDir dir(m_directory);
    for (const QFileInfo& info : dir.entryInfoList({QStringLiteral("session-*.celform")}, QDir::Files, QDir::Time)) {
        if (info.absoluteFilePath() == QFileInfo(m_ownFile).absoluteFilePath())
            continue;
        const QString base = info.absolutePath() + QLatin1Char('/') + info.completeBaseName();
        QLockFile lock(base + QStringLiteral(".lock"));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0)) {
            // tryLock fails while the owner lives; a dead owner's lock is removed as stale first.
            if (lock.error() == QLockFile::LockFailedError)
                continue;
        }
        lock.unlock();
        Orphan orphan{info.absoluteFilePath(), {}, info.lastModified()};
        QFile note(base + QStringLiteral(".json"));
        if (note.open(QIODevice::ReadOnly)) {
            const QJsonObject o = QJsonDocument::fromJson(note.readAll()).object();
            orphan.originalFile = o.value("original").toString();
            const QDateTime t = QDateTime::fromString(o.value("saved_at").toString(), Qt::ISODate);
            if (t.isValid())
                orphan.savedAt = t;
        }
        result.push_back(orphan);
    }
    return result;
}

bool RecoveryManager::adopt(const Orphan& orphan)
{
    QFile::remove(m_ownFile);
    if (!QFile::rename(orphan.recoveryFile, m_ownFile))
        return false;
    const QString oldBase = QString(orphan.recoveryFile).chopped(int(strlen(".celform")));
    // The note goes along: should this session crash before its first autosave, the copy is
    // offered again still naming the project it belongs to.
    const QString ownNote = QString(m_ownFile).replace(QStringLiteral(".celform"), QStringLiteral(".json"));
    QFile::remove(ownNote);
    if (!QFile::rename(oldBase + QStringLiteral(".json"), ownNote))
        QFile::remove(oldBase + QStringLiteral(".json"));
    QFile::remove(oldBase + QStringLiteral(".lock"));
    return true;
}

void RecoveryManager::discard(const Orphan& orphan)
{
    const QString base = QString(orphan.recoveryFile).chopped(int(strlen(".celform")));
    QFile::remove(orphan.recoveryFile);
    QFile::remove(base + QStringLiteral(".json"));
    QFile::remove(base + QStringLiteral(".lock"));
}

void RecoveryManager::removeOwn()
{
    QFile::remove(m_ownFile);
    QFile::remove(QString(m_ownFile).replace(QStringLiteral(".celform"), QStringLiteral(".json")));
    m_dirty = true;
}

} // namespace celform::app
