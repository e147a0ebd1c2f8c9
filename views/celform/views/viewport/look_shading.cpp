// The look's shader on a VTK actor: the shared GLSL mirror of shading.cpp plus the per-style
// colour of algo::renderFrame, written as replacements of VTK 9.1's polydata shader tags
// (docs/pitfalls.md, "Custom shading in VTK").
#include "celform/views/viewport/look_shading.h"

#include "celform/views/viewport/look_face_table.h"

#include "celform/algorithms/render.h"
#include "celform/algorithms/shading.h"
#include "celform/model/render/render_output.h"
#include "celform_shading_glsl.h" // generated from resources/shaders/celform_shading.glsl

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLShaderProperty.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace celform::views {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Array names in the polydata and attribute names in the vertex shader.
constexpr const char* kOffsetArray = "cfShadingOffset";
constexpr const char* kLutArray = "cfLutIntensity";
// Highlights: per layer the vertex's du and the handedness of its frame (dv = w * N x du, as
// makeTangentFrame builds it, N the layer's normal), and per layer the layer's smoothed normal
// (zero: the surface's). The layers' patches are per face, in the face table (LookFaceTable).
constexpr int kMaxHighlightLayers = kViewportHighlightLayers;
constexpr int kMaxHighlightCombinations = kViewportHighlightCombinations;
constexpr int kMaxHighlightOperations = kViewportHighlightOperations;
constexpr const char* kHighlightDuArrays[kMaxHighlightLayers]
    = {"cfHighlightDu0", "cfHighlightDu1", "cfHighlightDu2", "cfHighlightDu3"};
constexpr const char* kHighlightDuAttributes[kMaxHighlightLayers]
    = {"cfHlDuAttr0", "cfHlDuAttr1", "cfHlDuAttr2", "cfHlDuAttr3"};
constexpr const char* kHighlightNormalArrays[kMaxHighlightLayers]
    = {"cfHighlightN0", "cfHighlightN1", "cfHighlightN2", "cfHighlightN3"};
constexpr const char* kHighlightNormalAttributes[kMaxHighlightLayers]
    = {"cfHlNAttr0", "cfHlNAttr1", "cfHlNAttr2", "cfHlNAttr3"};

// Vertex shader: model-space position and normal, and the per-vertex look attributes, passed on.
// The highlight layers' attributes and varyings are added per layer in use (layerDeclarations):
// with none, the shader carries none of them (software GL interpolates every varying of every
// fragment). With 4 layers: 44 varying components (GL 3.2 guarantees 60), 13 attributes (16).
const char* const kVertexDec = R"glsl(//VTK::Normal::Dec
in vec3 cfNormalAttr;
in float cfOffsetAttr;
in float cfLutAttr;
out vec3 cfPositionMC;
out vec3 cfNormalMC;
out float cfOffset;
out float cfLutIntensity;

// The normal a layer's vertex frame was built against: the layer's smoothed normal, else the
// surface's (unit or zero).
vec3 cfFrameNormal(vec3 layerNormal, vec3 surfaceNormal)
{
  float l = length(layerNormal);
  return l > 0.0 ? layerNormal / l : surfaceNormal;
}
)glsl";

const char* const kVertexImpl = R"glsl(//VTK::Normal::Impl
  cfPositionMC = vertexMC.xyz;
  cfNormalMC = cfNormalAttr;
  cfOffset = cfOffsetAttr;
  cfLutIntensity = cfLutAttr;
  float cfNl = length(cfNormalAttr);
  vec3 cfNv = cfNl > 0.0 ? cfNormalAttr / cfNl : vec3(0.0);
)glsl";

// Fragment shader declarations after the shared functions: the light, the camera and the style.
const char* const kFragmentDec = R"glsl(
in vec3 cfPositionMC;
in vec3 cfNormalMC;
in float cfOffset;
in float cfLutIntensity;
uniform vec3 cfLightVector;  // towards the light (directional) or its position (point), model space
uniform int cfPointLight;
uniform int cfEvaluation;    // 0 PerPixel, 1 PerVertexLut, 2 PerFace (algo::ToonEvaluation)
uniform vec3 cfLineColor;
uniform vec3 cfEye;          // camera position, model space
uniform vec3 cfForward;      // unit view axis, model space
uniform float cfPixelScale;  // model units per pixel: times depth (perspective) or as is (ortho)
uniform int cfOrthographic;

// render.cpp's lightDirection: unit vector towards the light, +Z for a degenerate one.
vec3 cfLightDirection(vec3 position)
{
  vec3 l = cfPointLight != 0 ? cfLightVector - position : cfLightVector;
  float n = length(l);
  return n > 0.0 ? l / n : vec3(0.0, 0.0, 1.0);
}

// algo::toonTone (the shared mirror only exposes the intensity): the number of thresholds at or
// below lambert, clamped to the tones.
int cfToneIndex(float lambert)
{
  int tone = 0;
  for (int i = 0; i < 7; ++i)
    if (i < cfToneCount - 1 && lambert >= cfThresholds[i])
      ++tone;
  return clamp(tone, 0, max(0, cfToneCount - 1));
}

// algo::linearToSrgb: the encoding of the 8-bit files the offline renderer writes (the
// framebuffer is not sRGB, so the shader encodes).
float cfEncode(float l)
{
  return l > 0.0031308 ? 1.055 * pow(l, 1.0 / 2.4) - 0.055 : 12.92 * l;
}

// render.cpp's highlightAt, one layer: "over" with premultiplied colour, nothing on a face outside
// the layer's patch (inPatch: the face's bit in the face table, as render.cpp tests the layer's
// faceMask at the pixel's face), evaluated with the layer's normal (its interpolated smoothed
// normal, else n). The coverage is evaluated everywhere so that its derivatives stay in uniform
// control flow.
void cfHighlightOver(int layer, vec3 du, vec3 dv, vec3 layerNormal, bool inPatch, vec3 p, vec3 n,
    inout float coverage, inout vec3 premultiplied)
{
  if (layer >= cfHlLayerCount)
    return;
  vec3 ln = cfHighlightNormal(layerNormal, n);
  float c = cfLayerCoverage(layer, p, ln, du, dv, cfLightVector, cfPointLight != 0, cfEye);
  c = inPatch ? c : 0.0;
  premultiplied = premultiplied * (1.0 - c) + cfHlColor[layer] * c;
  coverage = c + coverage * (1.0 - c);
}
)glsl";

// Appended after VTK's own lighting code: overrides the fragment colour with render.cpp's.
const char* const kFragmentImpl = R"glsl(//VTK::Light::Impl
  {
    // The face under the fragment, as render.cpp takes it from its G-buffer: its material's
    // colour and style (no interpolation across faces) and its per-face values. VTK draws the
    // triangles in one batch numbered from PrimitiveIDOffset on (after any vertex and line
    // primitives), so the triangle's index in drawing order is:
#ifdef CF_FACE_TABLE
    int cfTriangle = gl_PrimitiveID + PrimitiveIDOffset - cfPrimitiveBase;
    vec4 cfFace = cfFaceTexel(cfTriangle);
#else
    vec4 cfFace = cfSameFace;
#endif
    vec3 cfBase = cfFace.rgb;
    int cfFaceCode = int(cfFace.w + 0.5);
    int cfStyleIndex = cfCodeStyle(cfFaceCode);
    int cfMaterial = cfCodeEntry(cfFaceCode);
    vec3 cfP = cfPositionMC;
    float cfLength = length(cfNormalMC);
    vec3 cfN = cfLength > 0.0 ? cfNormalMC / cfLength : vec3(0.0);
    // Seen from behind, a surface is lit from the viewer's side (render.cpp).
    if (dot(cfN, cfEye - cfP) < 0.0)
      cfN = -cfN;
    vec3 cfL = cfLightDirection(cfP);
    float cfLambert = dot(cfN, cfL) + cfOffset;
    // Screen-space width of N.L, taken in uniform control flow: the anti-aliased tone boundary
    // (render.cpp's ToneAntialiasing::Coverage from the same differences between pixels).
    float cfLambertWidth = fwidth(cfLambert);
    vec3 cfColor;
    if (cfStyleIndex == 0) {
      float cfIntensity = 0.15 + 0.85 * max(0.0, cfLambert);
      cfColor = cfBase * cfIntensity;
    } else if (cfStyleIndex == 1) {
      float cfIntensity;
      if (cfEvaluation == 1) {
        cfIntensity = cfLutIntensity;
      } else if (cfEvaluation == 2) {
        // render.cpp's per-face tone: the face normal turned towards the eye, the light at the
        // face's centre and the mean of its corners' offsets. The CPU evaluates both sides (the
        // eye moves without a new table); the side test takes this fragment's position, on the
        // face's plane like the corner render.cpp takes.
#ifdef CF_FACE_TABLE
        vec4 cfFaceTone = cfFaceToneTexel(cfTriangle);
        int cfTones = int(cfFaceTone.w + 0.5);
        cfIntensity = cfIntensities[dot(cfFaceTone.xyz, cfEye - cfP) < 0.0 ? cfTones >> 3 : cfTones & 7];
#else
        cfIntensity = 0.0; // not reached: PerFace always builds the table
#endif
      } else {
        cfIntensity = cfToonIntensityAntialiased(cfLambert, cfLambertWidth);
      }
      cfColor = cfBase * cfIntensity;
    } else if (cfStyleIndex == 2) {
      // The face's material's coefficients (the "auto" preset varies them per material).
#ifdef CF_FACE_TABLE
      vec4 cfG1 = cfEntryTexel(cfMaterial, 0);
      vec4 cfG2 = cfEntryTexel(cfMaterial, 1);
      vec4 cfG3 = cfEntryTexel(cfMaterial, 2);
#else
      vec4 cfG1 = cfSameGooch[0];
      vec4 cfG2 = cfSameGooch[1];
      vec4 cfG3 = cfSameGooch[2];
#endif
      cfColor = cfGoochShadeWith(cfBase, cfN, cfL, CfGoochParams(cfG1.x, cfG1.y, cfG1.z, cfG1.w, cfG2.x, cfG2.yzw, cfG3.xyz));
    } else {
      // Comic: flat brightest tone, shadow tones as ink strokes; the pixel footprint as in
      // render.cpp (2 * depth * tan(fov / 2) / height, or orthoHeight / height).
      int cfTone = cfToneIndex(cfLambert);
      float cfDepth = dot(cfP - cfEye, cfForward);
      float cfFootprint = cfOrthographic != 0 ? cfPixelScale : cfDepth * cfPixelScale;
      float cfInk = cfHatchCoverage(cfP, cfN, cfTone, cfToneCount, cfFootprint);
      cfColor = cfBase * cfIntensities[max(0, cfToneCount - 1)] * (1.0 - cfInk) + cfLineColor * cfInk;
    }
    //CF::Highlights::Impl
    cfColor = clamp(cfColor, 0.0, 1.0);
    gl_FragData[0] = vec4(cfEncode(cfColor.r), cfEncode(cfColor.g), cfEncode(cfColor.b), 1.0);
  }
)glsl";

/// The per-layer parts of the shaders for `layers` highlight layers in use (0 to 4): the vertex
/// attributes and varyings, the frames (dv = w * (N x du), N the layer's smoothed normal where
/// it has one, else the surface's, as renderHighlightsFor builds them), and each layer's "over" in
/// the fragment shader, on the faces of its patch (the face code's bit for the layer).
struct HighlightShaderParts {
    std::string vertexDec, vertexImpl, fragmentDec, fragmentImpl;
};

HighlightShaderParts highlightShaderParts(int layers)
{
    HighlightShaderParts parts;
    std::string over;
    for (int i = 0; i < layers; ++i) {
        const std::string n = std::to_string(i);
        parts.vertexDec += "in vec4 cfHlDuAttr" + n + ";\nin vec3 cfHlNAttr" + n + ";\nout vec3 cfHlDu" + n
            + ";\nout vec3 cfHlDv" + n + ";\nout vec3 cfHlN" + n + ";\n";
        parts.vertexImpl += "  cfHlDu" + n + " = cfHlDuAttr" + n + ".xyz;\n  cfHlDv" + n + " = cfHlDuAttr" + n
            + ".w * cross(cfFrameNormal(cfHlNAttr" + n + ", cfNv), cfHlDuAttr" + n + ".xyz);\n  cfHlN" + n
            + " = cfHlNAttr" + n + ";\n";
        parts.fragmentDec += "in vec3 cfHlDu" + n + ";\nin vec3 cfHlDv" + n + ";\nin vec3 cfHlN" + n + ";\n";
        over += "      cfHighlightOver(" + n + ", cfHlDu" + n + ", cfHlDv" + n + ", cfHlN" + n
            + ", cfCodeInPatch(cfFaceCode, " + n + "), cfP, cfN, cfHlCoverage, cfHlPremultiplied);\n";
    }
    if (layers > 0)
        parts.fragmentImpl = "    // Highlights after shading, before lines: mix(shaded, layer colour, coverage).\n"
                             "    {\n"
                             "      float cfHlCoverage = 0.0;\n"
                             "      vec3 cfHlPremultiplied = vec3(0.0);\n"
            + over
            + "      vec3 cfHlColorHere = cfHlCoverage > 0.0 ? cfHlPremultiplied / cfHlCoverage : vec3(0.0);\n"
              "      cfColor = cfColor * (1.0 - cfHlCoverage) + cfHlColorHere * cfHlCoverage;\n"
              "    }\n";
    return parts;
}

vtkSmartPointer<vtkFloatArray> namedArray(const char* name, int components)
{
    auto array = vtkSmartPointer<vtkFloatArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(components);
    return array;
}

/// What the shader needs of the look, kept so the uniforms can be set at every bind.
struct Uniforms {
    int toneCount = 2;
    std::array<float, 7> thresholds{};
    std::array<float, 8> intensities{};
    std::array<float, 32> lut{};
    float hatchSpacing = 0, hatchAngle = 0, hatchWidth = 0;
    std::array<float, 3> light{0.f, 0.f, 1.f};
    int pointLight = 0;
    int evaluation = 0;
    std::array<float, 3> lineColor{};
    // Highlights (see celform_shading.glsl for the layout).
    int hlLayerCount = 0;
    std::array<float, 3 * kMaxHighlightLayers> hlColor{};
    std::array<float, kMaxHighlightLayers> hlCut{};
    std::array<int, kMaxHighlightLayers> hlCombCount{};
    std::array<int, kMaxHighlightLayers * kMaxHighlightCombinations> hlCombMode{};
    std::array<float, kMaxHighlightLayers*(1 + kMaxHighlightCombinations)> hlEpsilon{};
    std::array<int, kMaxHighlightLayers*(1 + kMaxHighlightCombinations)> hlOpCount{};
    std::array<int, kMaxHighlightLayers*(1 + kMaxHighlightCombinations) * kMaxHighlightOperations> hlOpType{};
    std::array<float, kMaxHighlightLayers*(1 + kMaxHighlightCombinations) * kMaxHighlightOperations> hlOpA{};
    std::array<float, kMaxHighlightLayers*(1 + kMaxHighlightCombinations) * kMaxHighlightOperations> hlOpB{};
};

/// Operation type as the shader numbers it (HighlightOperationType order).
int operationIndex(algo::HighlightOperationType type)
{
    switch (type) {
    case algo::HighlightOperationType::Translation:
        return 0;
    case algo::HighlightOperationType::Rotation:
        return 1;
    case algo::HighlightOperationType::DirectionalScaling:
        return 2;
    case algo::HighlightOperationType::Split:
        return 3;
    case algo::HighlightOperationType::Squaring:
        return 4;
    }
    return 0;
}

/// One shape into the uniform tables at slot `shape`.
void storeShape(Uniforms& u, int shape, const algo::HighlightShape& s)
{
    u.hlEpsilon[std::size_t(shape)] = s.epsilon;
    const int count = int(std::min<std::size_t>(s.operations.size(), kMaxHighlightOperations));
    u.hlOpCount[std::size_t(shape)] = count;
    for (int i = 0; i < count; ++i) {
        const auto k = std::size_t(shape * kMaxHighlightOperations + i);
        u.hlOpType[k] = operationIndex(s.operations[std::size_t(i)].type);
        u.hlOpA[k] = s.operations[std::size_t(i)].a;
        u.hlOpB[k] = s.operations[std::size_t(i)].b;
    }
}

} // namespace

struct LookShading::Impl {
    Impl(vtkActor* actor, vtkPolyData* mesh, vtkRenderer* renderer)
        : actor(actor)
        , mesh(mesh)
        , renderer(renderer)
        , faceTable(mesh, renderer)
    { }

    vtkActor* actor = nullptr;
    vtkOpenGLPolyDataMapper* mapper = nullptr;
    vtkPolyData* mesh = nullptr;
    vtkRenderer* renderer = nullptr;
    vtkNew<vtkCallbackCommand> bindObserver;
    vtkSmartPointer<vtkFloatArray> offsets = namedArray(kOffsetArray, 1);
    vtkSmartPointer<vtkFloatArray> lut = namedArray(kLutArray, 1);
    std::array<vtkSmartPointer<vtkFloatArray>, kMaxHighlightLayers> highlightDu{namedArray(kHighlightDuArrays[0], 4),
        namedArray(kHighlightDuArrays[1], 4), namedArray(kHighlightDuArrays[2], 4),
        namedArray(kHighlightDuArrays[3], 4)};
    std::array<vtkSmartPointer<vtkFloatArray>, kMaxHighlightLayers> highlightNormal{
        namedArray(kHighlightNormalArrays[0], 3), namedArray(kHighlightNormalArrays[1], 3),
        namedArray(kHighlightNormalArrays[2], 3), namedArray(kHighlightNormalArrays[3], 3)};
    Uniforms uniforms;
    bool active = false;
    int compiledLayers = -1; ///< highlight layers the installed shaders carry; -1: none installed
    bool compiledFaceTable = false; ///< whether the installed shaders read the face table
    algo::RenderCache highlightCache; ///< the layers' geometry across parameter edits and frames
    // Clay settings restored when the look is turned off.
    bool clayLighting = true;
    double claySpecular = 0.0;
    LookFaceTable faceTable; ///< each face's data, read by the shaders when faces differ

    void setUniforms(vtkShaderProgram* program);
    void attachArrays();
    /// Maps the per-vertex arrays and installs the shaders for `layers` highlight layers.
    void installShaders(int layers, bool faceTable);
};

void LookShading::Impl::setUniforms(vtkShaderProgram* program)
{
    if (!program || !active)
        return;
    faceTable.setUniforms(program, compiledFaceTable);
    const Uniforms& u = uniforms;
    // Unused uniforms (optimised away for a style) are simply not found: no error.
    program->SetUniformi("cfToneCount", u.toneCount);
    program->SetUniform1fv("cfThresholds", 7, u.thresholds.data());
    program->SetUniform1fv("cfIntensities", 8, u.intensities.data());
    program->SetUniform1fv("cfLut", 32, u.lut.data());
    program->SetUniformf("cfHatchSpacing", u.hatchSpacing);
    program->SetUniformf("cfHatchAngle", u.hatchAngle);
    program->SetUniformf("cfHatchWidth", u.hatchWidth);
    program->SetUniform3f("cfLightVector", u.light.data());
    program->SetUniformi("cfPointLight", u.pointLight);
    program->SetUniformi("cfEvaluation", u.evaluation);
    program->SetUniform3f("cfLineColor", u.lineColor.data());
    program->SetUniformi("cfHlLayerCount", u.hlLayerCount);
    program->SetUniform3fv("cfHlColor", kMaxHighlightLayers, u.hlColor.data());
    program->SetUniform1fv("cfHlCut", kMaxHighlightLayers, u.hlCut.data());
    program->SetUniform1iv("cfHlCombCount", kMaxHighlightLayers, u.hlCombCount.data());
    program->SetUniform1iv("cfHlCombMode", int(u.hlCombMode.size()), u.hlCombMode.data());
    program->SetUniform1fv("cfHlEpsilon", int(u.hlEpsilon.size()), u.hlEpsilon.data());
    program->SetUniform1iv("cfHlOpCount", int(u.hlOpCount.size()), u.hlOpCount.data());
    program->SetUniform1iv("cfHlOpType", int(u.hlOpType.size()), u.hlOpType.data());
    program->SetUniform1fv("cfHlOpA", int(u.hlOpA.size()), u.hlOpA.data());
    program->SetUniform1fv("cfHlOpB", int(u.hlOpB.size()), u.hlOpB.data());

    // The camera as it is for this very draw (stereo eyes move it between draws).
    vtkCamera* camera = renderer ? renderer->GetActiveCamera() : nullptr;
    if (!camera)
        return;
    double eye[3], focal[3];
    camera->GetPosition(eye);
    camera->GetFocalPoint(focal);
    double forward[3] = {focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2]};
    const double length = std::sqrt(forward[0] * forward[0] + forward[1] * forward[1] + forward[2] * forward[2]);
    for (double& f : forward)
        f = length > 0 ? f / length : 0.0;
    program->SetUniform3f("cfEye", eye);
    program->SetUniform3f("cfForward", forward);
    const int* size = renderer->GetSize();
    const double height = std::max(size[1], 1);
    const bool ortho = camera->GetParallelProjection() != 0;
    const double scale = ortho ? 2.0 * camera->GetParallelScale() / height
                               : 2.0 * std::tan(camera->GetViewAngle() * kPi / 360.0) / height;
    program->SetUniformf("cfPixelScale", float(scale));
    program->SetUniformi("cfOrthographic", ortho ? 1 : 0);
}

void LookShading::Impl::attachArrays()
{
    // rebuildMesh() re-initialises the polydata, dropping its arrays: put ours back.
    vtkPointData* pd = mesh->GetPointData();
    for (vtkFloatArray* a : {offsets.Get(), lut.Get()})
        if (pd->GetArray(a->GetName()) != a)
            pd->AddArray(a);
    // The highlight arrays of the layers in use; the others are stale and leave the mesh.
    for (int layer = 0; layer < kMaxHighlightLayers; ++layer)
        for (vtkFloatArray* a : {highlightDu[std::size_t(layer)].Get(), highlightNormal[std::size_t(layer)].Get()}) {
            if (layer >= uniforms.hlLayerCount)
                pd->RemoveArray(a->GetName());
            else if (pd->GetArray(a->GetName()) != a)
                pd->AddArray(a);
        }
}

void LookShading::Impl::installShaders(int layers, bool faceTable)
{
    const int points = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    mapper->RemoveAllVertexAttributeMappings();
    mapper->MapDataArrayToVertexAttribute("cfNormalAttr", "Normals", points, -1);
    mapper->MapDataArrayToVertexAttribute("cfOffsetAttr", kOffsetArray, points, -1);
    mapper->MapDataArrayToVertexAttribute("cfLutAttr", kLutArray, points, -1);
    for (int layer = 0; layer < layers; ++layer) {
        mapper->MapDataArrayToVertexAttribute(kHighlightDuAttributes[layer], kHighlightDuArrays[layer], points, -1);
        mapper->MapDataArrayToVertexAttribute(
            kHighlightNormalAttributes[layer], kHighlightNormalArrays[layer], points, -1);
    }
    if (auto* shaders = vtkOpenGLShaderProperty::SafeDownCast(actor->GetShaderProperty())) {
        const HighlightShaderParts parts = highlightShaderParts(layers);
        shaders->ClearAllShaderReplacements();
        shaders->AddVertexShaderReplacement("//VTK::Normal::Dec", true, kVertexDec + parts.vertexDec, false);
        shaders->AddVertexShaderReplacement("//VTK::Normal::Impl", true, kVertexImpl + parts.vertexImpl, false);
        const std::string declarations = std::string("//VTK::Light::Dec\n")
            + (faceTable ? "#define CF_FACE_TABLE\n" : "") + kCelformShadingGlsl + LookFaceTable::glslDeclarations()
            + kFragmentDec + parts.fragmentDec;
        shaders->AddFragmentShaderReplacement("//VTK::Light::Dec", true, declarations, false);
        std::string impl = kFragmentImpl;
        const std::string marker = "    //CF::Highlights::Impl\n";
        impl.replace(impl.find(marker), marker.size(), parts.fragmentImpl);
        shaders->AddFragmentShaderReplacement("//VTK::Light::Impl", true, impl, false);
    }
    compiledLayers = layers;
    compiledFaceTable = faceTable;
    mapper->Modified();
}

LookShading::LookShading(vtkActor* actor, vtkPolyData* mesh, vtkRenderer* renderer)
    : m(std::make_unique<Impl>(actor, mesh, renderer))
{
    m->mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
    if (m->mapper) {
        // vertexMC must be the document's coordinates: hatching and the light use them as such.
        m->mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
        m->bindObserver->SetClientData(m.get());
        m->bindObserver->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
            static_cast<Impl*>(clientData)->setUniforms(static_cast<vtkShaderProgram*>(callData));
        });
        m->mapper->AddObserver(vtkCommand::UpdateShaderEvent, m->bindObserver);
    }
}

LookShading::~LookShading()
{
    if (m->mapper)
        m->mapper->RemoveObserver(m->bindObserver);
}

bool LookShading::isActive() const
{
    return m->active;
}

void LookShading::setActive(bool active)
{
    if (active == m->active || !m->mapper)
        return;
    m->active = active;
    auto* shaders = vtkOpenGLShaderProperty::SafeDownCast(m->actor->GetShaderProperty());
    vtkProperty* property = m->actor->GetProperty();
    if (!active) {
        if (shaders)
            shaders->ClearAllShaderReplacements();
        m->mapper->RemoveAllVertexAttributeMappings();
        m->compiledLayers = -1;
        property->SetLighting(m->clayLighting);
        property->SetSpecular(m->claySpecular);
        m->mapper->Modified();
        return;
    }
    m->clayLighting = property->GetLighting();
    m->claySpecular = property->GetSpecular();
    // VTK's lights play no part: the shader computes the whole colour from the look.
    property->LightingOff();
    property->SetSpecular(0.0);
    m->installShaders(m->uniforms.hlLayerCount, m->faceTable.needed());
}

void LookShading::update(const model::ProjectData& data, const model::Look& documentLook, const algo::Positions& shape,
    const float* normals, int frame, std::uint64_t shapeGeneration, const std::vector<float>* shadingOffsets)
{
    // The renderer's own resolution of the look (styles, colours and Gooch presets per material),
    // so the two paths cannot disagree on what the document means.
    const algo::RenderLook look = model::renderLookFor(data, documentLook, shadingOffsets);
    const std::vector<float>& offsets = shadingOffsets ? *shadingOffsets : data.shadingOffsets;
    const algo::TriMesh* mesh = data.baseMesh.get();
    const Eigen::Index count = shape.rows();
    if (!mesh || !normals || mesh->vertexCount() != count)
        return;

    // Uniforms (paper 3, section 3.3 ramp; comic hatching; the light).
    Uniforms& u = m->uniforms;
    u.toneCount = int(std::clamp<std::size_t>(look.toon.intensities.size(), 1, 8));
    u.thresholds.fill(0.f);
    u.intensities.fill(0.f);
    for (std::size_t i = 0; i < look.toon.thresholds.size() && i < u.thresholds.size(); ++i)
        u.thresholds[i] = look.toon.thresholds[i];
    for (std::size_t i = 0; i < look.toon.intensities.size() && i < u.intensities.size(); ++i)
        u.intensities[i] = look.toon.intensities[i];
    u.lut = algo::toonLookupTable(look.toon);
    u.hatchSpacing = look.hatch.spacing;
    u.hatchAngle = float(look.hatch.angleDegrees * 0.0174532925);
    u.hatchWidth = look.hatch.width;
    const Eigen::Vector3f light = look.light;
    u.light = {light.x(), light.y(), light.z()};
    u.pointLight = look.pointLight ? 1 : 0;
    u.evaluation = look.toonEvaluation == algo::ToonEvaluation::PerVertexLut ? 1
        : look.toonEvaluation == algo::ToonEvaluation::PerFace               ? 2
                                                                             : 0;
    u.lineColor = {look.lineStyle.color.x(), look.lineStyle.color.y(), look.lineStyle.color.z()};

    // The highlight layers, then each face's material, PerFace tones and patches, as render.cpp
    // resolves them.
    const std::vector<algo::RenderHighlight> layers
        = updateHighlights(data, documentLook, shape, normals, frame, count, shapeGeneration);
    m->faceTable.update(look, *mesh, shape, offsets, layers);

    // Per vertex: the shading offset and the PerVertexLut intensity.
    const auto offsetAt
        = [&](Eigen::Index v) { return std::size_t(v) < offsets.size() ? offsets[std::size_t(v)] : 0.f; };
    m->offsets->SetNumberOfTuples(count);
    m->lut->SetNumberOfTuples(count);
    float* offset = m->offsets->GetPointer(0);
    float* lut = m->lut->GetPointer(0);
    const bool perVertex = look.toonEvaluation == algo::ToonEvaluation::PerVertexLut;
    for (Eigen::Index v = 0; v < count; ++v) {
        offset[v] = offsetAt(v);
        lut[v] = 0.f;
        if (perVertex) {
            // render.cpp: lookupIntensity(table, N.L + O_v) per vertex, interpolated.
            const Eigen::Vector3f p = shape.row(v);
            const Eigen::Vector3f n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
            lut[v] = algo::lookupIntensity(u.lut, n.dot(lookLightDirection(light, look.pointLight, p)) + offset[v]);
        }
    }
    for (vtkFloatArray* a : {m->offsets.Get(), m->lut.Get()})
        a->Modified();
    m->attachArrays();
    // Shaders carry only the layers in use, and the face table only when faces differ: a change
    // rebuilds them (rare: a mesh or a look of another kind).
    if (m->active && (m->compiledLayers != m->uniforms.hlLayerCount || m->compiledFaceTable != m->faceTable.needed()))
        m->installShaders(m->uniforms.hlLayerCount, m->faceTable.needed());
    m->mesh->Modified();
}

std::vector<algo::RenderHighlight> LookShading::updateHighlights(const model::ProjectData& data,
    const model::Look& documentLook, const algo::Positions& shape, const float* normals, int frame, Eigen::Index count,
    std::uint64_t shapeGeneration)
{
    // The offline renderer's resolution of the tracks at the frame (keys, combinations, patches,
    // per-vertex frames), so both paths draw the same layers.
    std::vector<algo::RenderHighlight> layers
        = model::renderHighlightsFor(data, documentLook, shape, frame, &m->highlightCache, shapeGeneration);
    Uniforms& u = m->uniforms;
    u.hlLayerCount = int(std::min<std::size_t>(layers.size(), kMaxHighlightLayers));
    u.hlColor.fill(0.f);
    u.hlCut.fill(-1.f);
    u.hlCombCount.fill(0);
    u.hlCombMode.fill(0);
    u.hlEpsilon.fill(0.f);
    u.hlOpCount.fill(0);
    u.hlOpType.fill(0);
    u.hlOpA.fill(0.f);
    u.hlOpB.fill(0.f);
    // Only the layers in use have arrays (the shaders carry no others).
    for (int layer = 0; layer < u.hlLayerCount; ++layer)
        for (auto* a : {m->highlightDu[std::size_t(layer)].Get(), m->highlightNormal[std::size_t(layer)].Get()}) {
            a->SetNumberOfTuples(count);
            a->FillValue(0.f);
            a->Modified();
        }
    for (int layer = 0; layer < u.hlLayerCount; ++layer) {
        const algo::RenderHighlight& h = layers[std::size_t(layer)];
        const auto l = std::size_t(layer);
        u.hlColor[3 * l + 0] = h.layer.color.x();
        u.hlColor[3 * l + 1] = h.layer.color.y();
        u.hlColor[3 * l + 2] = h.layer.color.z();
        u.hlCut[l] = h.layer.offSpecularCut;
        storeShape(u, layer * (1 + kMaxHighlightCombinations), h.layer.shape);
        const int combinations = int(std::min<std::size_t>(h.layer.combinations.size(), kMaxHighlightCombinations));
        u.hlCombCount[l] = combinations;
        for (int k = 0; k < combinations; ++k) {
            const algo::HighlightCombination& c = h.layer.combinations[std::size_t(k)];
            u.hlCombMode[l * kMaxHighlightCombinations + std::size_t(k)]
                = c.mode == algo::HighlightBoolean::Union ? 0 : 1;
            storeShape(u, layer * (1 + kMaxHighlightCombinations) + 1 + k, c.shape);
        }
        // The layer's smoothed normals (zero: the surface's).
        float* layerNormal = m->highlightNormal[l]->GetPointer(0);
        const bool haveNormals = h.normals.rows() == count;
        for (Eigen::Index v = 0; haveNormals && v < count; ++v)
            for (int k = 0; k < 3; ++k)
                layerNormal[3 * v + k] = h.normals(v, k);
        // du and the handedness w of each vertex frame: dv = w * (N x du), N the normal the
        // vertex shader builds dv with (cfFrameNormal: the layer's, else the surface's).
        float* du = m->highlightDu[l]->GetPointer(0);
        const bool haveFrames = h.du.rows() == count && h.dv.rows() == count;
        for (Eigen::Index v = 0; haveFrames && v < count; ++v) {
            const Eigen::Vector3f d = h.du.row(v);
            const Eigen::Vector3f e = h.dv.row(v);
            Eigen::Vector3f n(layerNormal[3 * v], layerNormal[3 * v + 1], layerNormal[3 * v + 2]);
            if (!(n.squaredNorm() > 0.f))
                n = Eigen::Vector3f(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
            const float nl = n.norm();
            n = nl > 0.f ? Eigen::Vector3f(n / nl) : Eigen::Vector3f::Zero();
            const float handedness = n.cross(d).dot(e);
            du[4 * v + 0] = d.x();
            du[4 * v + 1] = d.y();
            du[4 * v + 2] = d.z();
            du[4 * v + 3] = handedness > 0.f ? 1.f : (handedness < 0.f ? -1.f : 0.f);
        }
    }
    layers.resize(std::size_t(u.hlLayerCount)); // those beyond the shader's are not drawn
    return layers;
}

} // namespace celform::views
