// Import of every other format through Assimp (STL, glTF/GLB, FBX, COLLADA, 3DS): one TriMesh from
// all meshes with node transforms applied, identical corners welded. importMesh() runs it in a
// child process (import_process.h); the checks here refuse what is cheap to recognise first.
#include "celform/model/io/animation_io_common.h"
#include "celform/model/io/mesh_io_common.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <QFileInfo>
#include <QRegularExpression>
#include <QtEndian>

#include <vector>

#include <sys/stat.h>

namespace celform::model::meshio {

namespace {

/// Assimp's file access, opening regular files only: a glTF buffer, an FBX texture or a COLLADA
/// reference naming a FIFO would block the open for ever, /dev/zero would be read without end.
/// (DefaultIOSystem::Exists() opens the file too, to see whether it can.)
/// Also only files in the model's folder or below it (referenceAllowed).
class RegularFilesOnly : public Assimp::DefaultIOSystem {
public:
    explicit RegularFilesOnly(QString folder)
        : m_folder(std::move(folder))
    { }
    bool Exists(const char* file) const override
    {
        return isRegular(file) && allowed(file) && DefaultIOSystem::Exists(file);
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override
    {
        return isRegular(file) && allowed(file) ? DefaultIOSystem::Open(file, mode) : nullptr;
    }
    /// The first reference refused for lying outside the folder, if any.
    [[nodiscard]] const QString& refused() const { return m_refused; }

private:
    bool allowed(const char* file) const
    {
        const QString name = QFile::decodeName(file);
        if (referenceAllowed(m_folder, name))
            return true;
        if (m_refused.isEmpty())
            m_refused = name;
        return false;
    }

    QString m_folder;
    mutable QString m_refused;

    static bool isRegular(const char* file)
    {
        struct stat info { };
        return ::stat(file, &info) == 0 && S_ISREG(info.st_mode);
    }
};

/// A binary glTF states the length of its JSON chunk, which Assimp allocates (and zeroes) before it
/// reads a byte of it: a 91-byte file stating 3.3 GB took 3.3 GB and 12 s to be refused.
void checkGlbHeader(const QString& path, const FileBytes& bytes)
{
    constexpr std::size_t kHeaders = 12 + 8; // file header, then the first chunk's
    if (bytes.size() < kHeaders || std::memcmp(bytes.data(), "glTF", 4) != 0)
        return;
    // glTF 2.0's JSON chunk length and glTF 1.0's content length are both at byte 12.
    const auto chunk = qFromLittleEndian<quint32>(bytes.data() + 12);
    if (chunk > bytes.size() - kHeaders)
        throw IoError(path,
            MeshIo::tr("its first chunk states %1 bytes, but the file holds %2 bytes after its headers")
                .arg(chunk)
                .arg(bytes.size() - kHeaders));
}

QString readableAssimpError(const char* message)
{
    QString text = QString::fromUtf8(message);
    text.replace(QRegularExpression(QStringLiteral("[?\\s]*\\n[?\\s]*|\\?\\s+")), QStringLiteral(" "));
    text.replace(QRegularExpression(QStringLiteral("\"([^\"]{24})[^\"]+\"")), QStringLiteral("\"\\1...\""));
    text = text.simplified();
    if (text.size() > 160)
        text = text.left(157) + QStringLiteral("...");
    return text;
}

void appendNode(const QString& path, const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
    std::vector<float>& positions, std::vector<std::int32_t>& indices, std::vector<std::int32_t>& materials,
    std::int64_t& skipped)
{
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        const auto base = static_cast<std::int64_t>(positions.size() / 3);
        // Assimp has read the scene by now, but our arrays are still to be filled.
        if (base + mesh.mNumVertices > kMaxMeshVertices)
            throw IoError(path, MeshIo::tr("the scene has more vertices than Celform can hold"));
        if (static_cast<std::int64_t>(indices.size() / 3) + mesh.mNumFaces > kMaxMeshTriangles)
            throw IoError(
                path, MeshIo::tr("the scene has more than the %1 triangles Celform can load").arg(kMaxMeshTriangles));
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            positions.insert(positions.end(), {p.x, p.y, p.z});
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) { // points and lines
                ++skipped;
                continue;
            }
            for (unsigned k = 0; k < 3; ++k)
                indices.push_back(static_cast<std::int32_t>(base + face.mIndices[k]));
            materials.push_back(static_cast<std::int32_t>(mesh.mMaterialIndex));
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        appendNode(path, scene, *node.mChildren[c], transform, positions, indices, materials, skipped);
}

} // namespace

void readWithAssimp(const QString& path, MeshImport& out)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    {
        const FileBytes bytes(path);
        checkGlbHeader(path, bytes);
        if (suffix == QLatin1String("gltf") || suffix == QLatin1String("glb"))
            if (const QString problem = animio::gltfJsonProblem(bytes.data(), bytes.size(), false); !problem.isEmpty())
                throw IoError(path, problem);
    }
    Assimp::Importer importer;
    auto* files = new RegularFilesOnly(QFileInfo(path).absolutePath());
    importer.SetIOHandler(files); // the importer owns it
    // STL repeats each corner with the facet normal; without removing normals the welding
    // below would keep every triangle separate.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
        aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS | aiComponent_TEXCOORDS
            | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS | aiComponent_LIGHTS | aiComponent_CAMERAS);
    const unsigned flags = aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices | aiProcess_Triangulate;
    const aiScene* scene = importer.ReadFile(QFile::encodeName(path).constData(), flags);
    if (!scene || !scene->mRootNode) {
        if (!files->refused().isEmpty())
            throw IoError(path, outsideReferenceProblem(files->refused()));
        const QString why = readableAssimpError(importer.GetErrorString());
        throw IoError(path, MeshIo::tr("not a readable %1 file: %2").arg(suffix.toUpper(), why));
    }
    std::vector<float> positions;
    std::vector<std::int32_t> indices;
    std::vector<std::int32_t> materials;
    std::int64_t skipped = 0;
    appendNode(path, *scene, *scene->mRootNode, aiMatrix4x4(), positions, indices, materials, skipped);
    const auto nv = static_cast<Eigen::Index>(positions.size() / 3);
    out.mesh.vertices = Eigen::Map<const algo::Positions>(positions.data(), nv, 3);
    out.mesh.faces = Eigen::Map<const algo::Faces>(indices.data(), static_cast<Eigen::Index>(indices.size() / 3), 3);
    if (skipped > 0)
        out.warnings << (skipped == 1 ? MeshIo::tr("1 point or line ignored")
                                      : MeshIo::tr("%n points or lines ignored", nullptr, static_cast<int>(skipped)));

    if (scene->mNumMaterials > 1) {
        for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
            const aiMaterial& source = *scene->mMaterials[m];
            algo::Material material;
            aiString name;
            if (source.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS)
                material.name = name.C_Str();
            aiColor4D colour;
            if (source.Get(AI_MATKEY_BASE_COLOR, colour) == aiReturn_SUCCESS
                || source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == aiReturn_SUCCESS)
                material.baseColor = Eigen::Vector3f(colour.r, colour.g, colour.b);
            out.mesh.materials.push_back(std::move(material));
        }
        out.mesh.faceMaterials = std::move(materials);
    }
}

} // namespace celform::model::meshio
