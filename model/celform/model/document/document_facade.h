// The base of the document's facades (DESIGN.md, "The document": its facades per domain). A
// facade groups the edits of one domain (keys, drawings, the look, highlights, face sets, shading
// offsets, animation) over the document core: it reads the data and pushes commands, and never
// writes the data itself (only commands do).
#pragma once

#include <QCoreApplication>
#include <QString>

#include <functional>

class QUndoCommand;

namespace celform::model {

class Document;
struct ProjectData;

class DocumentFacade {
    // The facades' texts are the document's: one translation context for every edit.
    Q_DECLARE_TR_FUNCTIONS(celform::model::Document)

public:
    DocumentFacade(const DocumentFacade&) = delete;
    DocumentFacade& operator=(const DocumentFacade&) = delete;

protected:
    explicit DocumentFacade(Document& doc)
        : m_doc(&doc)
    { }
    ~DocumentFacade() = default;

    [[nodiscard]] const ProjectData& data() const;
    /// Pushes a command on the document's undo stack (QUndoStack merges it through mergeWith).
    void push(QUndoCommand* command) const;
    /// wanted (trimmed; "Untitled" when empty), or with " 2", " 3", ... appended until taken
    /// says no.
    [[nodiscard]] static QString uniqueName(const QString& wanted, const std::function<bool(const QString&)>& taken);

    Document* m_doc;
};

} // namespace celform::model
