#include "gpu/resources.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace {

std::uint32_t findMemoryType(const Context& context, std::uint32_t allowedTypes,
                             VkMemoryPropertyFlags wanted) {
    const VkPhysicalDeviceMemoryProperties& memory = context.memoryProperties;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((allowedTypes & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    throw std::runtime_error("the device has no memory type with properties 0x" +
                             std::to_string(wanted) + " for this resource");
}

VkDeviceMemory allocate(const Context& context, const VkMemoryRequirements& requirements,
                        VkMemoryPropertyFlags properties) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = findMemoryType(context, requirements.memoryTypeBits, properties);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateMemory(context.device, &info, nullptr, &memory));
    return memory;
}

Buffer createBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags properties) {
    Buffer buffer;
    OnFailure release([&] { destroyBuffer(context, buffer); });
    buffer.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(context.device, &info, nullptr, &buffer.buffer));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(context.device, buffer.buffer, &requirements);
    buffer.memory = allocate(context, requirements, properties);
    VK_CHECK(vkBindBufferMemory(context.device, buffer.buffer, buffer.memory, 0));
    return buffer;
}

} // namespace

Buffer createHostBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer buffer =
        createBuffer(context, size, usage,
                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    OnFailure release([&] { destroyBuffer(context, buffer); });
    VK_CHECK(vkMapMemory(context.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
    return buffer;
}

Buffer createDeviceBuffer(const Context& context, const void* data, VkDeviceSize size,
                          VkBufferUsageFlags usage) {
    return createFilledDeviceBuffer(
        context, size, usage, [&](void* destination) { std::memcpy(destination, data, size); });
}

Buffer createFilledDeviceBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                                const std::function<void(void* destination)>& fill,
                                BufferFill how) {
    constexpr VkMemoryPropertyFlags kMappable = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT |
                                                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    const VkPhysicalDeviceType type = context.properties.deviceType;
    if (how == BufferFill::Direct &&
        (type == VK_PHYSICAL_DEVICE_TYPE_CPU || type == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU)) {
        bool mappable = false;
        for (std::uint32_t i = 0; i < context.memoryProperties.memoryTypeCount; ++i)
            mappable |=
                (context.memoryProperties.memoryTypes[i].propertyFlags & kMappable) == kMappable;
        if (mappable) {
            // TRANSFER_DST all the same: later updates (updateGpuLights) write with commands.
            Buffer buffer =
                createBuffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, kMappable);
            OnFailure release([&] { destroyBuffer(context, buffer); });
            void* mapped = nullptr;
            VK_CHECK(vkMapMemory(context.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &mapped));
            ScopeExit unmap([&] { vkUnmapMemory(context.device, buffer.memory); });
            fill(mapped);
            return buffer;
        }
    }
    Buffer staging = createHostBuffer(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    ScopeExit releaseStaging([&] { destroyBuffer(context, staging); });
    fill(staging.mapped);
    Buffer buffer = createBuffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    OnFailure release([&] { destroyBuffer(context, buffer); });
    runOneTimeCommands(context, [&](VkCommandBuffer commands) {
        VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(commands, staging.buffer, buffer.buffer, 1, &region);
    });
    return buffer;
}

void destroyBuffer(const Context& context, Buffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(context.device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(context.device, buffer.memory, nullptr);
    buffer = Buffer{};
}

Image createImage(const Context& context, std::uint32_t width, std::uint32_t height,
                  VkFormat format, VkImageUsageFlags usage) {
    Image image;
    OnFailure release([&] { destroyImage(context, image); });
    image.format = format;
    image.width = width;
    image.height = height;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(context.device, &info, nullptr, &image.image));
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(context.device, image.image, &requirements);
    image.memory = allocate(context, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkBindImageMemory(context.device, image.image, image.memory, 0));

    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image.image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(context.device, &viewInfo, nullptr, &image.view));
    return image;
}

void destroyImage(const Context& context, Image& image) {
    if (image.view) vkDestroyImageView(context.device, image.view, nullptr);
    if (image.image) vkDestroyImage(context.device, image.image, nullptr);
    if (image.memory) vkFreeMemory(context.device, image.memory, nullptr);
    image = Image{};
}

void runOneTimeCommands(const Context& context,
                        const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(context.device, &allocateInfo, &commands));
    // The queue is drained first (unchecked) so that a failed wait never frees a buffer
    // that is still pending; after a successful wait it returns at once.
    ScopeExit release([&] {
        vkQueueWaitIdle(context.queue);
        vkFreeCommandBuffers(context.device, context.commandPool, 1, &commands);
    });

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    record(commands);
    VK_CHECK(vkEndCommandBuffer(commands));

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    VK_CHECK(vkQueueSubmit(context.queue, 1, &submit, VK_NULL_HANDLE));
    VK_CHECK(vkQueueWaitIdle(context.queue));
}

void transitionImage(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags sourceStage, VkAccessFlags sourceAccess,
                     VkPipelineStageFlags destinationStage, VkAccessFlags destinationAccess) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = sourceAccess;
    barrier.dstAccessMask = destinationAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(commands, sourceStage, destinationStage, 0, 0, nullptr, 0, nullptr, 1,
                         &barrier);
}
