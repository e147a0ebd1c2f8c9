// The one error type of the model's file I/O: it names the file and the problem, so the editor
// can show it in a dialog and the command line can print it as one line.
#pragma once

#include <QString>

#include <stdexcept>

namespace celform::model {

class IoError : public std::runtime_error {
public:
    IoError(QString file, QString problem)
        : std::runtime_error((file + QStringLiteral(": ") + problem).toStdString())
        , m_file(std::move(file))
        , m_problem(std::move(problem))
    { }
    [[nodiscard]] const QString& file() const { return m_file; }
    [[nodiscard]] const QString& problem() const { return m_problem; }
    /// "file: problem", the one-line form used by the status bar and the command line.
    [[nodiscard]] QString message() const { return m_file + QStringLiteral(": ") + m_problem; }

private:
    QString m_file;
    QString m_problem;
};

/// An edit the document refuses (two keys with the same direction, a key deformation whose
/// vertex count does not match): the document is unchanged; the message says why.
class EditRefused : public std::runtime_error {
public:
    explicit EditRefused(QString message)
        : std::runtime_error(message.toStdString())
        , m_message(std::move(message))
    { }
    [[nodiscard]] const QString& message() const { return m_message; }

private:
    QString m_message;
};

} // namespace celform::model
