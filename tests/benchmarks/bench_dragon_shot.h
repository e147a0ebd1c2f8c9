// The export benchmarks' shot (bench_export, bench_usd): the Stanford dragon (871k triangles)
// with four key viewpoints, each offsetting a tenth of the vertices, seen from a turntable of a
// given number of frames, built once per frame count (null when ../shared is absent); and their
// baseline, writing bytes from memory with fwrite.
#pragma once

#include "bench_data.h"

#include "celform/model/data/camera_path.h"
#include "celform/model/data/project_data.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace celform::bench {

inline const model::ProjectData* dragonShot(int frames)
{
    static std::map<int, std::unique_ptr<model::ProjectData>> shots;
    auto& slot = shots[frames];
    if (slot)
        return slot.get();
    const algo::TriMesh* mesh = dragon();
    if (!mesh)
        return nullptr;
    auto data = std::make_unique<model::ProjectData>();
    data->baseMesh = std::make_shared<algo::TriMesh>(*mesh);
    data->baseMeshName = QStringLiteral("stanford_dragon.ply");
    const auto nv = std::uint32_t(mesh->vertexCount());
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> offset(-0.002f, 0.002f);
    for (int k = 0; k < 4; ++k) {
        model::KeyViewpoint key;
        key.id = data->nextId++;
        key.name = QStringLiteral("key %1").arg(k);
        const double a = k * 2 * M_PI / 4;
        key.direction = Eigen::Vector3d(std::cos(a), 0.2, std::sin(a)).normalized();
        key.camera.eye = data->baseMesh->centre() + key.direction;
        key.camera.target = data->baseMesh->centre();
        model::SparseOffsets offsets;
        const std::uint32_t count = nv / 10, start = (nv / 4) * std::uint32_t(k) % (nv - count);
        for (std::uint32_t i = 0; i < count; ++i) {
            offsets.indices.push_back(start + i);
            offsets.deltas.emplace_back(offset(rng), offset(rng), offset(rng));
        }
        key.offsetsByFrame[0] = std::move(offsets);
        data->keys.push_back(std::move(key));
    }
    model::Turntable turntable;
    turntable.frames = frames;
    const double size = algo::boundingBox(mesh->vertices).diagonal().norm();
    data->look.cameraPath = model::turntablePath(turntable, data->baseMesh->centre(), 2.0 * size, model::Camera{});
    data->time.firstFrame = 0;
    data->time.lastFrame = frames - 1;
    slot = std::move(data);
    return slot.get();
}

/// Writes bytes to a new file at path with fwrite (into the page cache); false on a failure.
inline bool fwriteBytes(const std::string& path, const std::vector<char>& bytes)
{
    std::FILE* f = std::fopen(path.c_str(), "wb");
    const std::size_t written = f ? std::fwrite(bytes.data(), 1, bytes.size(), f) : 0;
    return f && std::fclose(f) == 0 && written == bytes.size();
}

} // namespace celform::bench
