// The command line, timing and JSON report shared by the CPU peers, so that both take
// Raytracer's flags and print the line of `Raytracer --bench` (docs/performance.md) that
// tools/bench reads:
//   PEER SCENE [-o OUT.png] [--bench N] [--width W] [--height H] [--depth D] [--spp N]
//        [--threads T]
#pragma once

#include "cpu_render.h"
#include "peer_scene.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

struct PeerOptions {
    std::filesystem::path scenePath;
    std::filesystem::path outputPath; // empty: no PNG
    PeerRenderSettings render;
    int threads = 2;     // render threads (and the peer's own pool, where it has one)
    int benchFrames = 0; // 0: no benchmark
};

// What a peer hands the driver once its structures are built.
struct PeerRenderer {
    std::string device;          // the JSON "device", e.g. "brute force, 2 threads"
    std::size_t memoryBytes = 0; // the scene data and acceleration structure it holds
    // Renders one frame into the image and returns the number of rays traced.
    std::function<std::uint64_t(Image8&)> renderFrame;
};

// "1 thread", "2 threads": for PeerRenderer::device.
std::string threadCount(int threads);

// Builds the peer's structures for the scene; its run time is reported as build_ms
// (the float conversion before it as prepare_ms, the parse as parse_ms).
using MakePeerRenderer = std::function<PeerRenderer(const PeerScene&, const PeerOptions&)>;

// The whole program: parse, load, build, render (and time), print, write. Returns the
// exit status: 0, 1 runtime failure, 2 usage error, 3 bad scene (as Raytracer).
int runPeer(int argc, char** argv, const char* program, const MakePeerRenderer& make);
