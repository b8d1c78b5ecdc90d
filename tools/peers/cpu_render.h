// A whole image with the shared model (cpu_model.h) on N threads (base/parallel.h): the default
// camera, clamped samples averaged, bytes as floor(c * 255 + 0.5).
#pragma once

#include "base/image_io.h"
#include "base/parallel.h"
#include "cpu_model.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

struct PeerRenderSettings {
    int width = 640, height = 480;
    int spp = 1;   // 1: the pixel centre; else the most square grid of spp cells, their centres
    int depth = 5; // reflection bounces after the primary hit
    float fovDegrees = 60.0f;
    glm::vec3 background{1.0f};
};

// Sample offsets inside a pixel: spp cells of the most nearly square grid, as the
// reference does (1 gives the centre, which is all the model fixes).
inline std::vector<glm::vec2> sampleOffsets(int spp) {
    int rows = int(std::sqrt(double(spp)));
    while (spp % rows != 0)
        --rows;
    const int cols = spp / rows;
    std::vector<glm::vec2> offsets;
    for (int k = 0; k < spp; ++k)
        offsets.emplace_back((float(k % cols) + 0.5f) / float(cols),
                             (float(k / cols) + 0.5f) / float(rows));
    return offsets;
}

// Clamped to [0, 1] per channel; NaN goes to 0 (glm::clamp would keep it).
inline glm::vec3 clampColor(glm::vec3 c) {
    for (int k = 0; k < 3; ++k)
        c[k] = c[k] > 0.0f ? std::min(c[k], 1.0f) : 0.0f;
    return c;
}

inline std::uint8_t quantize(float c) {
    return std::uint8_t(std::floor(c * 255.0f + 0.5f));
}

// Renders into image (resized to fit) with `threads` threads, each taking the next
// free row, so that an expensive band (a mirror, a dense mesh) does not leave one idle.
// Each thread gets its own intersector.worker(). Returns the number of rays traced.
template <typename Intersector>
std::uint64_t renderImage(const PeerScene& scene, const Intersector& intersector,
                          const PeerRenderSettings& settings, int threads, Image8& image) {
    image.width = settings.width;
    image.height = settings.height;
    image.rgba.resize(std::size_t(settings.width) * std::size_t(settings.height) * 4);
    const std::vector<glm::vec2> offsets = sampleOffsets(settings.spp);
    // docs/model.md: x = (2 (i + u) / W - 1) aspect tan(fov/2), y = (1 - 2 (j + v) / H) tan(fov/2).
    const double tanHalfY = std::tan(double(settings.fovDegrees) * std::numbers::pi / 360.0);
    const float tanY = float(tanHalfY);
    const float tanX = float(tanHalfY * settings.width / settings.height);

    std::atomic<std::uint64_t> totalRays{0};
    // Each thread's own: the intersector's worker (a reference where it holds no state) and
    // the row's primary rays (pixel by pixel, sample by sample) and hits.
    struct ThreadState {
        decltype(intersector.worker()) worker;
        std::vector<PeerRay> primary;
        std::vector<PeerHit> hits;
    };
    auto makeRowBody = [&]() -> IndexBody {
        auto state = std::make_shared<ThreadState>(ThreadState{intersector.worker(), {}, {}});
        return [&, state](std::size_t row) {
            const int j = int(row);
            auto& worker = state->worker;
            std::vector<PeerRay>& primary = state->primary;
            std::vector<PeerHit>& hits = state->hits;
            RayCount count;
            primary.clear();
            for (int i = 0; i < settings.width; ++i) {
                for (glm::vec2 o : offsets) {
                    const float x = (2.0f * (float(i) + o.x) / float(settings.width) - 1.0f) * tanX;
                    const float y =
                        (1.0f - 2.0f * (float(j) + o.y) / float(settings.height)) * tanY;
                    primary.push_back({glm::vec3(0.0f), glm::normalize(glm::vec3(x, y, -1.0f))});
                }
            }
            // Coherent rays in one call where the worker can use it (Embree's packets).
            constexpr bool batched = requires(std::span<const PeerRay> r, std::span<PeerHit> h) {
                worker.closestHits(r, h);
            };
            if constexpr (batched) {
                hits.resize(primary.size());
                worker.closestHits(std::span<const PeerRay>(primary), std::span<PeerHit>(hits));
            }
            std::uint8_t* out = &image.rgba[std::size_t(j) * std::size_t(settings.width) * 4];
            std::size_t r = 0; // index into primary
            for (int i = 0; i < settings.width; ++i, out += 4) {
                glm::vec3 sum(0.0f);
                for (std::size_t k = 0; k < offsets.size(); ++k, ++r) {
                    sum += clampColor(traceRay(scene, worker, primary[r], settings.depth,
                                               settings.background, count,
                                               batched ? &hits[r] : nullptr));
                }
                sum /= float(offsets.size());
                out[0] = quantize(sum.x);
                out[1] = quantize(sum.y);
                out[2] = quantize(sum.z);
                out[3] = 255;
            }
            totalRays += count.rays;
        };
    };
    parallelForPerThread(std::size_t(settings.height), makeRowBody, unsigned(std::max(threads, 1)));
    return totalRays;
}
