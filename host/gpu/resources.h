// Buffers, images and one-off command submission: allocation, upload, readback.
#pragma once

#include "gpu/context.h"

#include <cstdint>
#include <functional>

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // set for host-visible buffers, which stay mapped
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

// A host-visible, coherent, persistently mapped buffer (staging, readback).
Buffer createHostBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage);

// A device-local buffer filled from data through a staging copy; waits until done.
Buffer createDeviceBuffer(const Context& context, const void* data, VkDeviceSize size,
                          VkBufferUsageFlags usage);

// A device-local buffer whose size bytes fill writes, given where to write them: into the
// buffer's own memory where the device's memory is the host's (a CPU device or an
// integrated GPU with a device-local, host-visible type), else (or with ThroughStaging)
// into a staging buffer that is then copied; so the data exists once more at most, never
// twice. Waits until done.
enum class BufferFill { Direct, ThroughStaging };
Buffer createFilledDeviceBuffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                                const std::function<void(void* destination)>& fill,
                                BufferFill how = BufferFill::Direct);

void destroyBuffer(const Context& context, Buffer& buffer);

// A 2D image in device memory with a view covering it.
Image createImage(const Context& context, std::uint32_t width, std::uint32_t height,
                  VkFormat format, VkImageUsageFlags usage);

void destroyImage(const Context& context, Image& image);

// Records commands into a fresh command buffer, submits it and waits for it.
void runOneTimeCommands(const Context& context, const std::function<void(VkCommandBuffer)>& record);

// A pipeline barrier on a whole colour image.
void transitionImage(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags sourceStage, VkAccessFlags sourceAccess,
                     VkPipelineStageFlags destinationStage, VkAccessFlags destinationAccess);
