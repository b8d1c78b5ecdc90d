// The kernel's method and precision choices (--sampler, --seed, --precision, --sphere-test,
// --triangle-test, --offset): what the command line sets, the renderer compiles the kernel
// for (specialization constants and a define, host/render/trace_pipeline.h) and --bench reports.
// Defaults are the robust methods; see docs/accuracy.md.
#pragma once

#include "shared.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

// Sample positions inside a pixel for --spp N > 1 (one sample is always the centre).
enum class Sampler : std::uint32_t {
    Grid = SAMPLER_GRID,             // centres of the most nearly square grid of N equal cells
    Stratified = SAMPLER_STRATIFIED, // one jittered sample per cell of that grid
    R2 = SAMPLER_R2, // Roberts' R2 sequence, rotated per pixel: sample s does not depend on N
};
enum class Precision { Fp32, Fp64 };     // the geometric arithmetic's type
enum class SphereTest { Naive, Stable }; // textbook quadratic, or Ray Tracing Gems ch. 7
enum class TriangleTest { MollerTrumbore, Watertight }; // Moller-Trumbore 1997, or Woop et al. 2013
// Secondary-ray origins: 1e-4 along the normal, Waechter-Binder scale-relative, or the hit
// point's rounding-error bound with the own triangle skipped (shaders/ray_offset.glsl).
enum class RayOffset : std::uint32_t {
    Fixed = RAY_OFFSET_FIXED,
    Scaled = RAY_OFFSET_SCALED,
    ErrorBound = RAY_OFFSET_ERROR_BOUND,
};

struct KernelChoices {
    Sampler sampler = Sampler::R2;
    std::uint32_t seed = 0; // varies the jitter (stratified) and the per-pixel rotation (r2)
    Precision precision = Precision::Fp32;
    SphereTest sphereTest = SphereTest::Stable;
    TriangleTest triangleTest = TriangleTest::Watertight;
    RayOffset offset = RayOffset::ErrorBound;

    bool operator==(const KernelChoices&) const = default;
};

// Each choice's command-line name, in the order --help lists them.
template <typename T> using ChoiceNames = std::vector<std::pair<const char*, T>>;
inline const ChoiceNames<Sampler>& samplerNames() {
    static const ChoiceNames<Sampler> names = {
        {"grid", Sampler::Grid}, {"stratified", Sampler::Stratified}, {"r2", Sampler::R2}};
    return names;
}
inline const ChoiceNames<Precision>& precisionNames() {
    static const ChoiceNames<Precision> names = {{"fp32", Precision::Fp32},
                                                 {"fp64", Precision::Fp64}};
    return names;
}
inline const ChoiceNames<SphereTest>& sphereTestNames() {
    static const ChoiceNames<SphereTest> names = {{"naive", SphereTest::Naive},
                                                  {"stable", SphereTest::Stable}};
    return names;
}
inline const ChoiceNames<TriangleTest>& triangleTestNames() {
    static const ChoiceNames<TriangleTest> names = {{"mt", TriangleTest::MollerTrumbore},
                                                    {"watertight", TriangleTest::Watertight}};
    return names;
}
inline const ChoiceNames<RayOffset>& rayOffsetNames() {
    static const ChoiceNames<RayOffset> names = {{"fixed", RayOffset::Fixed},
                                                 {"scaled", RayOffset::Scaled},
                                                 {"error-bound", RayOffset::ErrorBound}};
    return names;
}

template <typename T> std::string choiceName(const ChoiceNames<T>& names, T value) {
    for (const auto& [name, choice] : names)
        if (choice == value) return name;
    return "?";
}
