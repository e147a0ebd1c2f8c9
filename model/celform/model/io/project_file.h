// The .celform project file: one binary container of named chunks with a JSON manifest
// (docs/file-format.md). Writes are atomic and keep one backup; reads verify every checksum.
#pragma once

#include "celform/model/data/project_data.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

namespace celform::model {

/// The format version this build writes; it reads this and every older one.
/// 2: scene time, camera paths and animated bases. 3: the light track (look.light_keys).
constexpr int kProjectFormatVersion = 4;

/// A 3D vector as the project file stores it, [x, y, z]; the command line's JSON uses the same form.
QJsonArray vec3Json(const Eigen::Vector3d& v);

/// A camera as the project file stores it (eye, target, up, projection, fov_y_degrees,
/// ortho_height); `celform info --json` prints the same form.
QJsonObject cameraJson(const Camera& camera);

/// A camera path as the project file stores it: [{frame, camera}, ...]; `celform camera --list
/// --json` prints the same form.
QJsonArray cameraPathJson(const CameraPath& path);

/// A light as the project file stores it ({type, vector}); `celform info --json` prints the same.
QJsonObject lightJson(const Light& light);
/// A light track as the project file stores it: [{frame, light}, ...]; `celform info --json`
/// prints it as light_keys.
QJsonArray lightTrackJson(const LightTrack& track);

/// A highlight track as the project file stores it (docs/file-format.md); `celform highlight
/// --list --json` prints the same form.
QJsonObject highlightTrackJson(const HighlightTrack& track);

/// Writes the project atomically (OutputFile). When the file exists, its previous version is kept
/// as PATH.bak. Throws IoError; on error the file on disk is unchanged.
void saveProject(const ProjectData& data, const QString& path, bool keepBackup = true);

/// What loadProject does with the drawings' embedded image bytes.
enum class DrawingImages {
    Decode, ///< decoded into Drawing::image (checked readable)
    /// Drawing::image left null: for readers that need no pixels (`celform info` reads sizes with
    /// decodedImageSize()), so they pay neither for decoding nor for loading OpenImageIO.
    Skip,
};

/// Reads a project. Throws IoError for a missing, truncated or corrupt file, or one written by a
/// newer format version.
ProjectData loadProject(const QString& path, DrawingImages images = DrawingImages::Decode);

} // namespace celform::model
