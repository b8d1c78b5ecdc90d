// A SPIR-V module specialised before the driver sees it: its specialization constants
// frozen to given values and the code they switch off removed, by SPIRV-Tools' optimizer
// (only the passes that fold those constants and remove dead code; no pass that changes
// arithmetic).
//
// Why: lavapipe translates the whole module to NIR and optimises it on every pipeline
// creation, before it looks in its on-disk shader cache, so every start paid for the code
// of every variant (the other sphere and triangle tests, samplers, ray offsets, the pixel
// story). For test2.scene that took 144-223 ms from the general module and 66-79 ms from
// the specialised one (docs/performance.md, measured with strace); the specialisation is
// cached on disk like the SPIR-V (host/render/trace_pipeline.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

// values: specialization constant id -> its 32-bit value (0 or 1 for a bool). Returns
// nothing when the optimizer fails; the caller then passes the module as it is, with the
// values as specialization constants, which gives the same kernel.
std::optional<std::vector<std::uint32_t>>
specializeSpirv(const std::vector<std::uint32_t>& spirv,
                const std::map<std::uint32_t, std::uint32_t>& values);
