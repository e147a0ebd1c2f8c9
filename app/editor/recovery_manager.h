// Autosave and crash recovery. Each editor session autosaves its unsaved document to its own
// recovery file and holds a lock; a recovery file whose lock is free belongs to a session that
// crashed, and is offered on the next launch. Recovery files are deleted only by their own
// session on a clean exit, or when the user says so.
#pragma once

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace celform::model {
class Document;
}

namespace celform::app {

class RecoveryManager : public QObject {
    Q_OBJECT
public:
    struct Orphan {
        QString recoveryFile; ///< the autosaved project
        QString originalFile; ///< the project it was a copy of, empty when never saved
        QDateTime savedAt;
    };

    /// directory: where recovery files live (created when missing).
    RecoveryManager(model::Document* document, const QString& directory, QObject* parent = nullptr);
    ~RecoveryManager() override;

    /// Autosave period; 0 disables the timer.
    void setInterval(int milliseconds);
    /// The autosave period, 0 when off.
    [[nodiscard]] int interval() const { return m_timer.isActive() ? m_timer.interval() : 0; }
    /// Writes the recovery file now if the document changed since the last autosave.
    /// Returns false on a write error (reported through the autosaveFailed signal).
    bool autosaveNow();
    /// Recovery files left behind by sessions that did not exit cleanly.
    [[nodiscard]] std::vector<Orphan> orphans() const;
    /// Makes an orphan this session's own recovery file (after the user recovered it).
    bool adopt(const Orphan& orphan);
    /// Deletes an orphan (only after the user asked for it).
    static void discard(const Orphan& orphan);
    /// Deletes this session's recovery file (clean exit, or the document was saved).
    void removeOwn();
    [[nodiscard]] QString ownRecoveryFile() const { return m_ownFile; }

signals:
    void autosaved(const QString& file);
    void autosaveFailed(const QString& message);

private:
    model::Document* m_document;
    QString m_directory;
    QString m_ownFile;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    bool m_dirty = true; ///< the document changed since the last autosave
};

} // namespace celform::app
