// The PC2 point cache (export.h; Blender's and Maya's point cache format): a 32-byte header, then
// every vertex's position at every frame as little-endian float32, frame after frame in the base
// model's vertex order. docs/export.md lays out the header.
#include "celform/model/export/export.h"

#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io_common.h"
#include "celform/model/io/output_file.h"

#include <QCoreApplication>

#include <cstdint>
#include <cstring>

namespace celform::model::exporting {

namespace {

/// The header as it sits in the file (32 bytes, no padding).
struct Pc2Header {
    char signature[12];
    std::int32_t version;
    std::int32_t points;
    float startFrame;
    float sampleRate;
    std::int32_t samples;
};
static_assert(sizeof(Pc2Header) == 32, "the PC2 header is 32 bytes");
static_assert(meshio::kHostLittleEndian, "PC2 stores native numbers as little-endian");

} // namespace

void writePc2(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result)
{
    FrameWalk walk(data, source, job, progress);
    OutputFile file(job.output); // whole or not at all; every write checked (issue 27)
    Pc2Header header{};
    std::memcpy(header.signature, "POINTCACHE2", 12); // with its terminating zero
    header.version = 1;
    header.points = std::int32_t(walk.vertexCount());
    header.startFrame = float(job.firstFrame);
    header.sampleRate = 1.0f; // one sample per frame
    header.samples = job.frameCount();
    file.write(&header, sizeof header);
    // Positions are row-major floats (x y z per vertex): each frame is one write of the shape.
    const qint64 frameBytes = qint64(header.points) * 3 * qint64(sizeof(float));
    while (walk.next()) {
        file.write(walk.shape().data(), frameBytes);
        ++result.frames;
    }
    finishFile(file, walk.cancelled(), result);
}

} // namespace celform::model::exporting
