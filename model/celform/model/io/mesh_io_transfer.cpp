// A mesh read in a child process (import_process.h) and handed back: the parent runs `celform
// import-mesh FILE OUT` and reads OUT, a private binary file of this build holding what the reader
// produced (positions, faces, UVs, materials, warnings); PLY would lose the materials and warnings.
#include "celform/model/io/mesh_io_common.h"

#include <QFile>
#include <QTemporaryDir>

#include <cstring>
#include <string>

namespace celform::model::meshio {
namespace {

constexpr char kMagic[8] = {'C', 'E', 'L', 'F', 'M', 'S', 'H', '1'};
static_assert(kHostLittleEndian, "the transfer file is written and read by the same build on one machine");

/// Reads the transfer file. The child is ours, but what it read was not: every count is checked
/// against the bytes left before anything is allocated for it.
class TransferReader {
public:
    TransferReader(const QString& fileLabel, const char* data, std::size_t size)
        : m_label(fileLabel)
        , m_p(data)
        , m_end(data + size)
    { }

    std::int64_t count(std::size_t elementBytes, std::int64_t limit = kMaxIndex)
    {
        std::int64_t n = 0;
        copy(&n, sizeof n);
        if (n < 0 || n > limit || std::size_t(n) > remaining() / elementBytes)
            damaged();
        return n;
    }
    void copy(void* destination, std::size_t bytes)
    {
        if (bytes > remaining())
            damaged();
        if (bytes > 0)
            std::memcpy(destination, m_p, bytes);
        m_p += bytes;
    }
    std::string text()
    {
        std::string s(std::size_t(count(1)), '\0');
        copy(s.data(), s.size());
        return s;
    }
    void expectEnd() const
    {
        if (m_p != m_end)
            damaged();
    }

private:
    [[nodiscard]] std::size_t remaining() const { return std::size_t(m_end - m_p); }
    [[noreturn]] void damaged() const { throw IoError(m_label, MeshIo::tr("the importer's result is damaged")); }

    const QString& m_label;
    const char* m_p;
    const char* m_end;
};

template <typename Matrix> void readRows(TransferReader& in, Matrix& m, std::int64_t limit)
{
    constexpr auto columns = Matrix::ColsAtCompileTime;
    const std::int64_t rows = in.count(sizeof(typename Matrix::Scalar) * columns, limit);
    m.resize(Eigen::Index(rows), columns);
    in.copy(m.data(), std::size_t(rows) * columns * sizeof(typename Matrix::Scalar));
}

void writeBytes(QFile& file, const void* data, std::size_t bytes)
{
    if (bytes > 0 && file.write(static_cast<const char*>(data), qint64(bytes)) != qint64(bytes))
        throw IoError(file.fileName(), MeshIo::tr("the file cannot be written: %1").arg(file.errorString()));
}

void writeCount(QFile& file, std::int64_t n)
{
    writeBytes(file, &n, sizeof n);
}

template <typename Matrix> void writeRows(QFile& file, const Matrix& m)
{
    writeCount(file, m.rows());
    writeBytes(file, m.data(), std::size_t(m.size()) * sizeof(typename Matrix::Scalar));
}

void writeText(QFile& file, const std::string& s)
{
    writeCount(file, std::int64_t(s.size()));
    writeBytes(file, s.data(), s.size());
}

} // namespace

void writeTransfer(const MeshImport& in, const QString& transferPath)
{
    QFile file(transferPath);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        throw IoError(transferPath, MeshIo::tr("the file cannot be written: %1").arg(file.errorString()));
    const algo::TriMesh& mesh = in.mesh;
    writeBytes(file, kMagic, sizeof kMagic);
    writeRows(file, mesh.vertices);
    writeRows(file, mesh.faces);
    writeRows(file, mesh.uvs);
    writeRows(file, mesh.uvFaces);
    writeCount(file, std::int64_t(mesh.faceMaterials.size()));
    writeBytes(file, mesh.faceMaterials.data(), mesh.faceMaterials.size() * sizeof(std::int32_t));
    writeCount(file, std::int64_t(mesh.materials.size()));
    for (const algo::Material& m : mesh.materials) {
        writeText(file, m.name);
        writeBytes(file, m.baseColor.data(), 3 * sizeof(float));
    }
    writeCount(file, in.warnings.size());
    for (const QString& w : in.warnings)
        writeText(file, w.toStdString());
    if (!file.flush())
        throw IoError(transferPath, MeshIo::tr("the file cannot be written: %1").arg(file.errorString()));
}

void readInChild(const QString& path, MeshImport& out)
{
    const QTemporaryDir folder;
    if (!folder.isValid())
        throw IoError(
            path, MeshIo::tr("a temporary folder for the importer cannot be made: %1").arg(folder.errorString()));
    const QString transfer = folder.filePath(QStringLiteral("mesh.transfer"));
    // "--": a file name starting with a dash is not an option.
    runImportChild({QStringLiteral("import-mesh"), QStringLiteral("--"), path, transfer}, path);

    QFile file(transfer);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError(path, MeshIo::tr("the importer's result cannot be read: %1").arg(file.errorString()));
    const qint64 size = file.size();
    const uchar* mapped = size > 0 ? file.map(0, size) : nullptr;
    if (!mapped)
        throw IoError(path, MeshIo::tr("the importer's result cannot be read: %1").arg(file.errorString()));
    TransferReader in(path, reinterpret_cast<const char*>(mapped), std::size_t(size));
    char magic[sizeof kMagic];
    in.copy(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof magic) != 0)
        throw IoError(path, MeshIo::tr("the importer's result is damaged"));
    algo::TriMesh& mesh = out.mesh;
    readRows(in, mesh.vertices, kMaxMeshVertices);
    readRows(in, mesh.faces, kMaxMeshTriangles);
    readRows(in, mesh.uvs, kMaxIndex);
    readRows(in, mesh.uvFaces, kMaxMeshTriangles);
    mesh.faceMaterials.resize(std::size_t(in.count(sizeof(std::int32_t), kMaxMeshTriangles)));
    in.copy(mesh.faceMaterials.data(), mesh.faceMaterials.size() * sizeof(std::int32_t));
    mesh.materials.resize(std::size_t(in.count(sizeof(std::int64_t) + 3 * sizeof(float))));
    for (algo::Material& m : mesh.materials) {
        m.name = in.text();
        in.copy(m.baseColor.data(), 3 * sizeof(float));
    }
    const std::int64_t warnings = in.count(sizeof(std::int64_t));
    for (std::int64_t i = 0; i < warnings; ++i)
        out.warnings << QString::fromStdString(in.text());
    in.expectEnd();
}

} // namespace celform::model::meshio
