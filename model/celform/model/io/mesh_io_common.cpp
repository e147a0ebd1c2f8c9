// The out-of-line parts of the readers' shared helpers (mesh_io_common.h): opening and mapping
// the file, and the messages for skipped faces, impossible counts and unexpected text.
#include "celform/model/io/mesh_io_common.h"

#include <QFileInfo>

namespace celform::model::meshio {

void requireRegularFile(const QString& path)
{
    const QFileInfo info(path);
    if (!info.exists())
        throw IoError(path, MeshIo::tr("the file does not exist"));
    if (info.isDir())
        throw IoError(path, MeshIo::tr("this is a folder, not a regular file"));
    if (!info.isFile())
        throw IoError(path, MeshIo::tr("this is not a regular file (a pipe, a socket or a device)"));
}

bool referenceAllowed(const QString& modelFolder, const QString& file)
{
    if (qEnvironmentVariableIntValue("CELFORM_ALLOW_OUTSIDE_REFERENCES") == 1)
        return true;
    const QString target = QFileInfo(file).canonicalFilePath();
    if (target.isEmpty())
        return true; // missing: the reader says so
    const QString folder = QFileInfo(modelFolder).canonicalFilePath();
    return !folder.isEmpty() && target.startsWith(folder + QLatin1Char('/'));
}

QString outsideReferenceProblem(const QString& reference)
{
    return MeshIo::tr("it refers to “%1”, outside its folder; such references are not read unless "
                      "CELFORM_ALLOW_OUTSIDE_REFERENCES=1 is set")
        .arg(reference);
}

FileBytes::FileBytes(const QString& path)
    : m_file(path)
{
    requireRegularFile(path);
    if (!m_file.open(QIODevice::ReadOnly))
        throw IoError(path, MeshIo::tr("the file cannot be opened: %1").arg(m_file.errorString()));
    // Replaced by a device between the check and the open: its size says nothing, refuse it too.
    if (m_file.isSequential())
        throw IoError(path, MeshIo::tr("this is not a regular file (a pipe, a socket or a device)"));
    const qint64 size = m_file.size();
    if (size == 0)
        throw IoError(path, MeshIo::tr("the file is empty"));
    if (uchar* mapped = m_file.map(0, size)) {
        m_data = reinterpret_cast<const char*>(mapped);
        m_size = static_cast<std::size_t>(size);
    } else {
        m_copy = m_file.readAll();
        if (m_copy.size() != size)
            throw IoError(path, MeshIo::tr("the file cannot be read: %1").arg(m_file.errorString()));
        m_data = m_copy.constData();
        m_size = static_cast<std::size_t>(m_copy.size());
    }
}

void checkVertexCount(const QString& path, std::int64_t vertices)
{
    if (vertices > kMaxMeshVertices)
        throw IoError(path,
            MeshIo::tr("the file has %1 vertices, more than the %2 vertices Celform can load")
                .arg(vertices)
                .arg(kMaxMeshVertices));
}

void checkFaceCount(const QString& path, std::int64_t faces)
{
    if (faces > kMaxMeshTriangles)
        throw IoError(path,
            MeshIo::tr("the file has %1 faces, more than the %2 triangles Celform can load")
                .arg(faces)
                .arg(kMaxMeshTriangles));
}

void checkTriangleCount(const QString& path, std::int64_t triangles)
{
    if (triangles > kMaxMeshTriangles)
        throw IoError(path,
            MeshIo::tr("the file's faces make %1 triangles, more than the %2 triangles Celform can load")
                .arg(triangles)
                .arg(kMaxMeshTriangles));
}

QString skippedFacesWarning(std::int64_t skipped)
{
    if (skipped == 1)
        return MeshIo::tr("1 face with fewer than three corners ignored");
    return MeshIo::tr("%n faces with fewer than three corners ignored", nullptr, static_cast<int>(skipped));
}

[[noreturn]] void throwTooLarge(const QString& path, std::int64_t vertices, std::int64_t faces)
{
    if (vertices > kMaxMeshVertices)
        throw IoError(path,
            MeshIo::tr("the header announces %1 vertices and %2 faces, more than the file holds and more than the "
                       "%3 vertices Celform can load")
                .arg(vertices)
                .arg(faces)
                .arg(kMaxMeshVertices));
    if (faces > kMaxMeshTriangles)
        throw IoError(path,
            MeshIo::tr("the header announces %1 vertices and %2 faces, more than the file holds and more than the "
                       "%3 triangles Celform can load")
                .arg(vertices)
                .arg(faces)
                .arg(kMaxMeshTriangles));
    throw IoError(path,
        MeshIo::tr("the header announces %1 vertices and %2 faces, more than the file holds").arg(vertices).arg(faces));
}

void TextCursor::fail(const char* what) const
{
    if (m_p >= m_end)
        throw IoError(m_path, MeshIo::tr("the file ends early, while reading %1").arg(MeshIo::tr(what)));
    throw IoError(m_path, MeshIo::tr("line %1: expected %2").arg(m_line).arg(MeshIo::tr(what)));
}

} // namespace celform::model::meshio
