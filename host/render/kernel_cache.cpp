#include "render/kernel_cache.h"

#include "base/scope_guard.h"

const TracePipeline& cachedTracePipeline(KernelCache& cache, const Context& context,
                                         const KernelSource& source,
                                         const TraceSpecialization& specialization,
                                         Precision precision) {
    // The struct has no padding (trace_pipeline.cpp relies on it too): its bytes are its values.
    std::string key(reinterpret_cast<const char*>(&specialization), sizeof(specialization));
    key += char(precision);
    key += source.shaderDirectory.string();
    if (auto found = cache.pipelines.find(key); found != cache.pipelines.end()) {
        ++cache.reused;
        return found->second;
    }
    TracePipeline pipeline = loadTracePipeline(context, source, specialization, precision);
    OnFailure release([&] { destroyTracePipeline(context, pipeline); });
    ++cache.compiled;
    return cache.pipelines.emplace(key, pipeline).first->second;
}

void destroyKernelCache(KernelCache& cache, const Context& context) {
    for (auto& [key, pipeline] : cache.pipelines)
        destroyTracePipeline(context, pipeline);
    cache = KernelCache{};
}
