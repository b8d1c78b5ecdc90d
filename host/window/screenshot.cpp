#include "window/screenshot.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"
#include "render/headless.h"

#include <algorithm>
#include <charconv>

Image8 readOutputImage(const Context& context, const Renderer& renderer) {
    VK_CHECK(vkDeviceWaitIdle(context.device));
    const Image& output = renderer.outputImage;
    Buffer readback = createHostBuffer(context, VkDeviceSize(output.width) * output.height * 4,
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    ScopeExit release([&] { destroyBuffer(context, readback); });
    runOneTimeCommands(
        context, [&](VkCommandBuffer commands) { recordCopyToHost(commands, output, readback); });
    return imageFromHostCopy(output, readback);
}

std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder,
                                         const std::string& stem, std::uint32_t samples) {
    // N counts every screenshot of the scene, whatever its sample count: one past the
    // largest N among STEM-screenshot-N.png and STEM-screenshot-N-Sspp.png there.
    const std::string prefix = stem + "-screenshot-";
    unsigned largest = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0) continue;
        unsigned n = 0;
        const char* digits = name.c_str() + prefix.size();
        const auto [end, failure] = std::from_chars(digits, name.c_str() + name.size(), n);
        if (failure == std::errc() && end != digits && (*end == '-' || *end == '.'))
            largest = std::max(largest, n);
    }
    return folder /
           (prefix + std::to_string(largest + 1) + "-" + std::to_string(samples) + "spp.png");
}
