// The viewport look's face table: each face's row resolved as render.cpp resolves the face, and
// its upload as a texture in VTK 9.1's drawing order (degenerate triangles left out).
#include "celform/views/viewport/look_face_table.h"

#include "celform/views/viewport/look_shading.h"

#include "celform/algorithms/shading.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <QtGlobal>

#include <algorithm>
#include <string>

namespace celform::views {
namespace {

/// The table's layout (see glslDeclarations): floats per material entry and per face.
constexpr std::size_t kMaterialFloats = 12;
constexpr std::size_t kFaceFloats = 8;
/// Texels per row, as a power of two (at most the GL's maximum texture size, llvmpipe's 16384);
/// rows follow as the mesh needs them: 4096 by 16384 texels hold 33 million triangles.
constexpr int kFaceTableShift = 12;
/// Tone indices the shader's uniforms hold (cfIntensities[8]): the per-face tones are stored as
/// indices into them, front + 8 * back.
constexpr int kMaxTones = 8;
/// The code in a face's first texel: style in bits 0-1, one bit per highlight layer from bit 2
/// (set where the face is in the layer's patch), the material entry above. A float holds it
/// exactly below 2^24, so entries stop at 2^18 - 1.
constexpr int kPatchShift = 2;
constexpr int kEntryShift = kPatchShift + kViewportHighlightLayers;
constexpr std::size_t kMaxEntries = std::size_t(1) << (24 - kEntryShift);

// The texture's layout, for the fragment shader.
const char* const kGlsl = R"glsl(
// The face table (LookFaceTable), a float RGBA texture read as one row of texels wrapped every
// 2^cfFaceTableShift (shifts and masks: software GL divides slowly).
// First 3 texels per material entry, the Gooch coefficients: (ka, k1, k2, k3), (k4, warm),
// (cool, 0); the last entry is the look's fallback for material indices it has nothing for.
// Then 2 texels per triangle VTK draws, in its drawing order: (base colour, code), the code
// holding the style, the highlight layers whose patch has the face and the material entry (see
// cfCodeStyle and after), and for the PerFace toon evaluation (unit face normal, tone index seen
// from the normal's side + 8 * tone index from the other side). One fetch per fragment for most
// looks. When every face has the same first texel and nothing per face is needed (one material,
// no PerFace tones, no highlight patch: the usual case), the shaders are built without the table
// (CF_FACE_TABLE not defined): that texel and its material's entry come as uniforms, and neither
// gl_PrimitiveID nor a texture is read, so such a look costs what it did before the table.
#ifdef CF_FACE_TABLE
uniform sampler2D cfFaceTable;
uniform int cfFaceTableShift;
uniform int cfFaceBase;      // texel of the first triangle's data
uniform int cfPrimitiveBase; // primitives VTK numbers before the triangles (vertices, lines)

vec4 cfTableTexel(int i)
{
  return texelFetch(cfFaceTable, ivec2(i & ((1 << cfFaceTableShift) - 1), i >> cfFaceTableShift), 0);
}

// A triangle's first texel, its PerFace texel, and texel k of a material entry.
vec4 cfFaceTexel(int triangle)
{
  return cfTableTexel(cfFaceBase + 2 * triangle);
}

vec4 cfFaceToneTexel(int triangle)
{
  return cfTableTexel(cfFaceBase + 2 * triangle + 1);
}

vec4 cfEntryTexel(int entry, int k)
{
  return cfTableTexel(3 * entry + k);
}
#else
uniform vec4 cfSameFace;
uniform vec4 cfSameGooch[3];
#endif

// The parts of the code in a face's first texel (its w, rounded): the style (0 Lambert, 1 toon,
// 2 Gooch, 3 comic), whether the face is in highlight layer `layer`'s patch (render.cpp tests the
// layer's faceMask at the pixel's face), and the material entry.
int cfCodeStyle(int code)
{
  return code & 3;
}

bool cfCodeInPatch(int code, int layer)
{
  return ((code >> (CF_PATCH_SHIFT + layer)) & 1) != 0;
}

int cfCodeEntry(int code)
{
  return code >> CF_ENTRY_SHIFT;
}
)glsl";

int styleIndex(algo::Style style)
{
    switch (style) {
    case algo::Style::Lambert:
        return 0;
    case algo::Style::Toon:
        return 1;
    case algo::Style::Gooch:
        return 2;
    case algo::Style::Comic:
        return 3;
    }
    return 1;
}

} // namespace

Eigen::Vector3f lookLightDirection(const Eigen::Vector3f& light, bool point, const Eigen::Vector3f& position)
{
    Eigen::Vector3f l = point ? Eigen::Vector3f(light - position) : light;
    const float n = l.norm();
    return n > 0.f ? Eigen::Vector3f(l / n) : Eigen::Vector3f(0.f, 0.f, 1.f);
}

LookFaceTable::LookFaceTable(vtkPolyData* mesh, vtkRenderer* renderer)
    : m_mesh(mesh)
    , m_renderer(renderer)
    , m_shift(kFaceTableShift)
{
    if (!m_renderer)
        return;
    // The table holds a texture unit from its draw to the end of the frame.
    m_renderEndObserver = vtkSmartPointer<vtkCallbackCommand>::New();
    m_renderEndObserver->SetClientData(this);
    m_renderEndObserver->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
        auto* table = static_cast<LookFaceTable*>(clientData);
        if (table->m_texture)
            table->m_texture->Deactivate();
    });
    m_renderer->AddObserver(vtkCommand::EndEvent, m_renderEndObserver);
}

LookFaceTable::~LookFaceTable()
{
    if (m_renderer)
        m_renderer->RemoveObserver(m_renderEndObserver);
}

std::string LookFaceTable::glslDeclarations()
{
    return "#define CF_PATCH_SHIFT " + std::to_string(kPatchShift) + "\n#define CF_ENTRY_SHIFT "
        + std::to_string(kEntryShift) + "\n" + kGlsl;
}

void LookFaceTable::update(const algo::RenderLook& look, const algo::TriMesh& mesh, const algo::Positions& shape,
    const std::vector<float>& offsets, const std::vector<algo::RenderHighlight>& highlights)
{
    // Material entries: the Gooch coefficients (paper 1, section 3.2.4; the "auto" preset sets
    // them per material), one entry per index of the look's lists and one more, the look's own
    // set, for indices beyond them (and negative ones), as render.cpp resolves them.
    // (The code's bits hold kMaxEntries entries: beyond, the fallback set, with a warning.)
    const std::size_t listed
        = std::max({look.materialColors.size(), look.materialStyles.size(), look.materialGooch.size()});
    const std::size_t materials = std::min(listed, kMaxEntries - 1);
    if (listed > materials && !m_tooManyMaterials)
        qWarning(
            "Look shading: the viewport shades materials from %zu on with the look's Gooch coefficients", materials);
    m_tooManyMaterials = listed > materials;
    std::vector<float> materialTable(kMaterialFloats * (materials + 1), 0.f);
    for (std::size_t e = 0; e <= materials; ++e) {
        const algo::GoochParams& g
            = e < materials && e < look.materialGooch.size() ? look.materialGooch[e] : look.gooch;
        const std::array<float, kMaterialFloats> entry = {
            g.ka, g.k1, g.k2, g.k3, g.k4, g.warm.x(), g.warm.y(), g.warm.z(), g.cool.x(), g.cool.y(), g.cool.z(), 0.f};
        std::copy(entry.begin(), entry.end(), materialTable.begin() + std::ptrdiff_t(e * kMaterialFloats));
    }

    // Per face: its material's colour and style (each from the look's list when it has the
    // index, else the look's default, as render.cpp resolves them) and material entry, the
    // layers whose patch it is in (render.cpp's highlightAt skips a layer at a pixel whose face
    // its faceMask leaves out; an empty mask has every face), and for the PerFace toon evaluation
    // its unit normal and the tone render.cpp gives it from either side (which side faces the eye
    // is decided per fragment: the camera moves without an update).
    const algo::Faces& faces = mesh.faces;
    const std::size_t layers = std::min<std::size_t>(highlights.size(), kViewportHighlightLayers);
    const auto inPatch = [&](const algo::RenderHighlight& h, Eigen::Index f) {
        return h.faceMask.empty() || (std::size_t(f) < h.faceMask.size() && h.faceMask[std::size_t(f)] != 0);
    };
    const bool perFace = look.toonEvaluation == algo::ToonEvaluation::PerFace;
    const auto offsetAt
        = [&](std::int32_t v) { return std::size_t(v) < offsets.size() ? offsets[std::size_t(v)] : 0.f; };
    const auto toneIndex = [&](float lambert) { return std::min(algo::toonTone(look.toon, lambert), kMaxTones - 1); };
    std::vector<float> faceTable(kFaceFloats * std::size_t(faces.rows()), 0.f);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        float* row = faceTable.data() + kFaceFloats * std::size_t(f);
        const std::int32_t material = mesh.faceMaterials.empty() || std::size_t(f) >= mesh.faceMaterials.size()
            ? 0
            : mesh.faceMaterials[std::size_t(f)];
        const auto index = std::size_t(material); // negative: beyond every list
        const algo::Color color = index < look.materialColors.size() ? look.materialColors[index] : look.defaultColor;
        const algo::Style style = index < look.materialStyles.size() ? look.materialStyles[index] : look.style;
        row[0] = color.x();
        row[1] = color.y();
        row[2] = color.z();
        std::size_t patches = 0;
        for (std::size_t l = 0; l < layers; ++l)
            patches |= inPatch(highlights[l], f) ? std::size_t(1) << l : 0;
        const std::size_t entry = std::min(index, materials);
        row[3] = float((entry << kEntryShift) | (patches << kPatchShift) | std::size_t(styleIndex(style)));
        if (!perFace)
            continue;
        // render.cpp, ToonEvaluation::PerFace, the same expressions in the same order.
        const std::int32_t a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
        const Eigen::Vector3f pa = shape.row(a), pb = shape.row(b), pc = shape.row(c);
        const Eigen::Vector3f fn = (pb - pa).cross(pc - pa).normalized();
        const Eigen::Vector3f back = -fn;
        const Eigen::Vector3f centre = (pa + pb + pc) / 3.f;
        const float faceOffset = (offsetAt(a) + offsetAt(b) + offsetAt(c)) / 3.f;
        const Eigen::Vector3f l = lookLightDirection(look.light, look.pointLight, centre);
        row[4] = fn.x();
        row[5] = fn.y();
        row[6] = fn.z();
        row[7] = float(toneIndex(fn.dot(l) + faceOffset) + kMaxTones * toneIndex(back.dot(l) + faceOffset));
    }
    // The usual case, one look for every face: uniforms instead of a fetch per fragment.
    bool same = !perFace && faces.rows() > 0;
    for (Eigen::Index f = 1; same && f < faces.rows(); ++f)
        same = std::equal(
            faceTable.begin(), faceTable.begin() + 4, faceTable.begin() + std::ptrdiff_t(kFaceFloats * std::size_t(f)));
    m_needed = !same;
    m_sameFace.fill(0.f);
    m_sameGooch.fill(0.f);
    if (same) {
        std::copy_n(faceTable.begin(), 4, m_sameFace.begin());
        const auto entry = std::size_t(faceTable[3] + 0.5f) >> kEntryShift;
        std::copy_n(
            materialTable.begin() + std::ptrdiff_t(entry * kMaterialFloats), kMaterialFloats, m_sameGooch.begin());
    }
    if (materialTable != m_materialTable || faceTable != m_faceTable) {
        m_materialTable = std::move(materialTable);
        m_faceTable = std::move(faceTable);
        m_tableChanged = true;
    }
}

void LookFaceTable::setUniforms(vtkShaderProgram* program, bool texture)
{
    if (texture)
        bind(program);
    // Unused uniforms (optimised away, or absent in a program with the table) are simply not
    // found: no error.
    program->SetUniform4f("cfSameFace", m_sameFace.data());
    program->SetUniform4fv("cfSameGooch", 3, m_sameGooch.data());
}

bool LookFaceTable::findDrawnFaces()
{
    vtkPoints* points = m_mesh->GetPoints();
    vtkCellArray* polys = m_mesh->GetPolys();
    if (!points || !polys)
        return false;
    const vtkMTimeType time = std::max(points->GetMTime(), polys->GetMTime());
    if (points == m_drawnPoints && polys == m_drawnPolys && time == m_drawnTime)
        return false;
    m_drawnPoints = points;
    m_drawnPolys = polys;
    m_drawnTime = time;
    // vtkOpenGLIndexBufferObject::AppendTriangleIndexBuffer (VTK 9.1): each polygon as a fan
    // (0, i - 1, i), a triangle dropped when two of its corners are at the same coordinates.
    std::vector<std::int32_t> faces;
    std::int32_t drawn = 0;
    bool all = true;
    auto* floats = vtkFloatArray::SafeDownCast(points->GetData());
    const float* p = floats && floats->GetNumberOfComponents() == 3 ? floats->GetPointer(0) : nullptr;
    auto corner = [&](vtkIdType id) {
        if (p)
            return Eigen::Vector3d(p[3 * id], p[3 * id + 1], p[3 * id + 2]);
        Eigen::Vector3d c;
        points->GetPoint(id, c.data());
        return c;
    };
    auto scan = [&](const auto* offsets, const auto* ids, vtkIdType cells) {
        for (vtkIdType cell = 0; cell < cells; ++cell) {
            const auto first = offsets[cell], size = offsets[cell + 1] - first;
            for (vtkIdType i = 2; i < vtkIdType(size); ++i) {
                const Eigen::Vector3d a = corner(vtkIdType(ids[first])), b = corner(vtkIdType(ids[first + i - 1])),
                                      c = corner(vtkIdType(ids[first + i]));
                const bool kept = a != b && b != c && a != c;
                if (kept && all && (size != 3 || drawn != cell)) {
                    // The first change from "triangle k is face k": list every face from here on.
                    all = false;
                    faces.resize(std::size_t(drawn));
                    for (std::int32_t k = 0; k < drawn; ++k)
                        faces[std::size_t(k)] = k;
                }
                if (kept) {
                    if (!all)
                        faces.push_back(std::int32_t(cell));
                    ++drawn;
                }
            }
        }
    };
    if (polys->IsStorage64Bit())
        scan(polys->GetOffsetsArray64()->GetPointer(0), polys->GetConnectivityArray64()->GetPointer(0),
            polys->GetNumberOfCells());
    else
        scan(polys->GetOffsetsArray32()->GetPointer(0), polys->GetConnectivityArray32()->GetPointer(0),
            polys->GetNumberOfCells());
    // VTK's primitive numbering (vtkOpenGLCellToVTKCellMap): a primitive per vertex, then one per
    // line segment, then the triangles.
    vtkCellArray* lines = m_mesh->GetLines();
    const int base = int(m_mesh->GetVerts()->GetNumberOfConnectivityIds()
        + (lines->GetNumberOfConnectivityIds() - lines->GetNumberOfCells()));
    const bool changed = faces != m_drawnFaces || drawn != m_drawnCount || base != m_primitiveBase;
    m_drawnFaces = std::move(faces);
    m_drawnCount = drawn;
    m_primitiveBase = base;
    return changed;
}

bool LookFaceTable::bind(vtkShaderProgram* program)
{
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(m_renderer ? m_renderer->GetRenderWindow() : nullptr);
    if (!window)
        return false;
    if (!m_texture)
        m_texture = vtkSmartPointer<vtkTextureObject>::New();
    if (m_texture->GetContext() != window) {
        m_texture->SetContext(window);
        m_tableChanged = true;
    }
    if (findDrawnFaces())
        m_tableChanged = true;
    if (m_tableChanged || m_texture->GetHandle() == 0) {
        // Materials, then the drawn triangles' face data in drawing order.
        const std::size_t faceCount = m_faceTable.size() / kFaceFloats;
        const std::size_t texels = m_materialTable.size() / 4 + 2 * std::size_t(m_drawnCount);
        const int maxSize = vtkTextureObject::GetMaximumTextureSize(window);
        int shift = kFaceTableShift;
        while (shift > 0 && (1 << shift) > maxSize)
            --shift;
        const std::size_t width = std::size_t(1) << shift;
        const std::size_t height = std::max<std::size_t>(1, (texels + width - 1) / width);
        if (height > std::size_t(maxSize)) {
            if (!m_tooLarge)
                qWarning("Look shading: %d triangles are more than the face table of this GL can hold", m_drawnCount);
            m_tooLarge = true;
            return false;
        }
        m_tooLarge = false;
        m_packed.assign(4 * width * height, 0.f);
        std::copy(m_materialTable.begin(), m_materialTable.end(), m_packed.begin());
        m_faceBase = int(m_materialTable.size() / 4);
        m_shift = shift;
        float* faces = m_packed.data() + m_materialTable.size();
        if (m_drawnFaces.empty()) {
            const std::size_t n = std::min(faceCount, std::size_t(m_drawnCount));
            std::copy_n(m_faceTable.begin(), n * kFaceFloats, faces);
        } else {
            for (std::size_t k = 0; k < m_drawnFaces.size(); ++k) {
                const auto f = std::size_t(m_drawnFaces[k]);
                if (f < faceCount)
                    std::copy_n(
                        m_faceTable.begin() + std::ptrdiff_t(f * kFaceFloats), kFaceFloats, faces + k * kFaceFloats);
            }
        }
        m_texture->SetInternalFormat(GL_RGBA32F);
        if (!m_texture->Create2DFromRaw(
                unsigned(width), unsigned(height), 4, VTK_FLOAT, static_cast<void*>(m_packed.data())))
            return false;
        m_tableChanged = false;
    }
    // Bound for this draw; released when the renderer finishes its frame.
    m_texture->Activate();
    program->SetUniformi("cfFaceTable", m_texture->GetTextureUnit());
    program->SetUniformi("cfFaceTableShift", m_shift);
    program->SetUniformi("cfFaceBase", m_faceBase);
    program->SetUniformi("cfPrimitiveBase", m_primitiveBase);
    return true;
}

} // namespace celform::views
