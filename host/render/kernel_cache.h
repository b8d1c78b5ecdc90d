// The trace kernels of one process, kept from one scene of a batch to the next: a scene
// whose kernel has the same specialization (host/render/trace_pipeline.h), precision and
// sources gets the pipeline already made; another one compiles anew, once. The counts say
// what was reused (the batch's last line on stderr, docs/batches.md).
#pragma once

#include "render/trace_pipeline.h"

#include <cstdint>
#include <map>
#include <string>

struct KernelCache {
    std::map<std::string, TracePipeline> pipelines; // by specialization, precision and source
    std::uint32_t compiled = 0;                     // pipelines made
    std::uint32_t reused = 0;                       // requests answered by one already made
};

// The pipeline for these choices, made on first request; the cache keeps owning it.
const TracePipeline& cachedTracePipeline(KernelCache& cache, const Context& context,
                                         const KernelSource& source,
                                         const TraceSpecialization& specialization,
                                         Precision precision);

void destroyKernelCache(KernelCache& cache, const Context& context);
