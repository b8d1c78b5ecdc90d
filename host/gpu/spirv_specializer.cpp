#include "gpu/spirv_specializer.h"

#include <spirv-tools/optimizer.hpp>

#include <unordered_map>

std::optional<std::vector<std::uint32_t>>
specializeSpirv(const std::vector<std::uint32_t>& spirv,
                const std::map<std::uint32_t, std::uint32_t>& values) {
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> bitPatterns;
    for (const auto& [id, value] : values)
        bitPatterns[id] = {value};
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&,
                                    const char*) {}); // a failure is answered by the fallback
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(bitPatterns))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
        .RegisterPass(spvtools::CreateDeadBranchElimPass())
        .RegisterPass(spvtools::CreateAggressiveDCEPass())
        .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
    std::vector<std::uint32_t> specialized;
    if (!optimizer.Run(spirv.data(), spirv.size(), &specialized)) return std::nullopt;
    return specialized;
}
