#include "window/screenshot.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"

#include <cstring>

Image8 readOutputImage(const Context& context, const Renderer& renderer) {
    VK_CHECK(vkDeviceWaitIdle(context.device));
    const Image& output = renderer.outputImage;
    Buffer readback = createHostBuffer(context, VkDeviceSize(output.width) * output.height * 4,
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    ScopeExit release([&] { destroyBuffer(context, readback); });
    runOneTimeCommands(context, [&](VkCommandBuffer commands) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {output.width, output.height, 1};
        vkCmdCopyImageToBuffer(commands, output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               readback.buffer, 1, &region);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                             0, 1, &toHost, 0, nullptr, 0, nullptr);
    });
    Image8 image;
    image.width = int(output.width);
    image.height = int(output.height);
    image.rgba.resize(std::size_t(image.width) * image.height * 4);
    std::memcpy(image.rgba.data(), readback.mapped, image.rgba.size());
    return image;
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
