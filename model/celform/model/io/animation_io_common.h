// Internal to the animation_io files: the AnimationIo translation context, the limits on what an
// animated base may allocate, and the two readers readAnimatedBase() dispatches to.
#pragma once

#include "celform/model/io/animation_io.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>

#include <cstdint>

namespace celform::model {

// Gives lupdate the context "celform::model::AnimationIo" for the animation_io files' messages.
struct AnimationIo {
    Q_DECLARE_TR_FUNCTIONS(celform::model::AnimationIo)
};

namespace animio {

/// Samples an animation may have: 100,000 frames is over an hour at 24 frames per second. An
/// animation lasting 1e30 seconds is refused before anything is allocated for it.
constexpr std::int64_t kMaxFrames = 100'000;
/// Floats the morph targets, weights and skin matrices together may take: 2 GB.
constexpr std::int64_t kMaxAnimationFloats = 500'000'000;

/// Throws IoError naming path when fps is not a positive finite number below 1000.
void checkFps(const QString& path, double fps);

/// animation_io_gltf.cpp: a .gltf or .glb file.
AnimatedImport readGltfAnimation(const QString& path, double fps);
/// Why the JSON of a glTF file's bytes (a .gltf, or a GLB's first chunk) cannot be read: nested too
/// deep, or not JSON, with the error and its byte offset in the file (NaN and Infinity are no JSON
/// numbers); empty when it parses. Both glTF readers (tinygltf and Assimp) ask it first, so the
/// user reads what is wrong rather than "No suitable reader" (issue 27). With refuseDeep false, JSON
/// nested too deep is left alone (empty): Assimp reads it in its child process, which contains the
/// crash it may cause.
QString gltfJsonProblem(const char* data, std::size_t size, bool refuseDeep = true);
/// Whether the glTF file's JSON declares animations, skins or morph targets; false when unreadable.
bool gltfIsAnimated(const QString& path);

/// animation_io_sequence.cpp: a numbered OBJ/PLY/OFF sequence.
AnimatedImport readMeshSequence(const QString& path, double fps);
/// Whether path is a pattern matching a file, or a numbered file with a numbered sibling.
bool isMeshSequence(const QString& path);

} // namespace animio
} // namespace celform::model
