#include "headless.h"

#include "vk_check.h"

#include <chrono>
#include <cstring>

void createHeadlessTarget(HeadlessTarget& target, const Context& context, const Renderer& renderer) {
    VkDeviceSize bytes = VkDeviceSize(renderer.outputImage.width) * renderer.outputImage.height * 4;
    target.readbackBuffer = createHostBuffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(context.device, &allocateInfo, &target.commands));

    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &target.frameDone));
}

double renderHeadlessFrame(HeadlessTarget& target, const Context& context, const Renderer& renderer) {
    const Image& output = renderer.outputImage;
    VK_CHECK(vkResetCommandBuffer(target.commands, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(target.commands, &begin));
    recordTrace(renderer, target.commands);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {output.width, output.height, 1};
    vkCmdCopyImageToBuffer(target.commands, output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           target.readbackBuffer.buffer, 1, &region);
    // Make the copied bytes visible to the host's reads after the fence.
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(target.commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &toHost, 0, nullptr, 0, nullptr);
    VK_CHECK(vkEndCommandBuffer(target.commands));

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &target.commands;
    auto start = std::chrono::steady_clock::now();
    VK_CHECK(vkQueueSubmit(context.queue, 1, &submit, target.frameDone));
    VK_CHECK(vkWaitForFences(context.device, 1, &target.frameDone, VK_TRUE, UINT64_MAX));
    auto end = std::chrono::steady_clock::now();
    VK_CHECK(vkResetFences(context.device, 1, &target.frameDone));
    return std::chrono::duration<double, std::milli>(end - start).count();
}

Image8 readHeadlessImage(const HeadlessTarget& target, const Renderer& renderer) {
    Image8 image;
    image.width = static_cast<int>(renderer.outputImage.width);
    image.height = static_cast<int>(renderer.outputImage.height);
    image.rgba.resize(std::size_t(image.width) * image.height * 4);
    std::memcpy(image.rgba.data(), target.readbackBuffer.mapped, image.rgba.size());
    return image;
}

void destroyHeadlessTarget(HeadlessTarget& target, const Context& context) {
    if (context.device) vkDeviceWaitIdle(context.device);
    if (target.frameDone) vkDestroyFence(context.device, target.frameDone, nullptr);
    if (target.commands) vkFreeCommandBuffers(context.device, context.commandPool, 1, &target.commands);
    destroyBuffer(context, target.readbackBuffer);
    target = HeadlessTarget{};
}
