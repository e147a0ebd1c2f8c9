// Import of an animated base model (paper 1, section 4.1): a glTF 2.0 file with skins, morph
// targets and an animation, or a numbered OBJ/PLY sequence, sampled at whole frames into an
// algo::BaseAnimation over the rest mesh.
#pragma once

#include "celform/algorithms/base_animation.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/project_data.h"

#include <QString>
#include <QStringList>

#include <memory>

namespace celform::model {

struct AnimatedImport {
    /// The rest (bind) pose: positions, faces, UVs when the file has them, materials (base colour).
    std::shared_ptr<algo::TriMesh> mesh;
    /// firstFrame 0, frameCount samples at whole frames (sample F at time F / fps).
    algo::BaseAnimation animation;
    double fps = 24.0; ///< frames per second the samples were taken at
    /// What the reader let pass with a remark (a numbered sequence's missing numbers), one line each.
    QStringList warnings;
};

/// Reads an animated base by suffix: .gltf/.glb, or a numbered OBJ/PLY (or OFF) sequence given as
/// a pattern ("walk_####.obj", a run of '#' standing for the frame number) or as the path of any
/// one of its files ("walk_0001.obj": its numbered siblings in the same folder are the other
/// frames, in numeric order).
///
/// glTF: the triangles of every mesh the default scene instances, merged in scene order (the
/// scene's nodes depth first, parents before children, each node's primitives in order, each
/// primitive's vertices in accessor order; unindexed primitives are not welded), so the vertex
/// order is the same at every frame. Skinned meshes rest in their bind pose; other meshes have
/// their node's transform applied. Only the file's first animation is sampled, at
/// t = F / fps for F = 0 .. ceil(end * fps); a file without animations gives one sample.
///
/// Sequences: the first file is the rest mesh and frame 0, each later file one morph target
/// (its positions minus the first file's) with a one-hot weight at its frame; every file must
/// have the first file's vertex count and faces.
///
/// Throws IoError naming the file and the problem (for a sequence, the frame that failed).
AnimatedImport readAnimatedBase(const QString& path, double fps = 24.0);

/// Whether path names an animated base readAnimatedBase() would read as one: a glTF/GLB file
/// with animations, skins or morph targets (only its JSON is read), a sequence pattern matching
/// at least one file, or a numbered OBJ/PLY/OFF file with at least one numbered sibling. Never
/// throws; false for anything unreadable.
bool isAnimatedBaseFile(const QString& path);
/// Whether a base model file is opened as an animated base without being asked: a glTF/GLB file
/// with an animation, skins or morph targets, or a sequence pattern ("walk_####.obj"). A numbered
/// file with numbered siblings is a sequence only when the user says so (celform new --sequence).
bool opensAsAnimatedBase(const QString& path);
/// A new project on an import: newProject() on its rest mesh, plus its animation (when it has one)
/// as the animated base, the scene's fps and frame range taken from it.
ProjectData newAnimatedProject(AnimatedImport animated, const QString& meshName);

} // namespace celform::model
