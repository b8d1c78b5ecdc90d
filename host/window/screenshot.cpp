#include "window/screenshot.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"
#include "render/headless.h"

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
                                         const std::string& stem) {
    for (unsigned n = 1;; ++n) {
        std::filesystem::path candidate =
            folder / (stem + "-screenshot-" + std::to_string(n) + ".png");
        std::error_code error;
        if (!std::filesystem::exists(candidate, error)) return candidate;
    }
}
