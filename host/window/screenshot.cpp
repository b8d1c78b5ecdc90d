#include "window/screenshot.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"

#include <cstdio>
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

std::string headlessCommand(const Options& options, const CameraPose& camera, int width, int height,
                            std::uint32_t spp) {
    auto format = [](const char* pattern, auto... values) {
        char text[256];
        std::snprintf(text, sizeof text, pattern, values...);
        return std::string(text);
    };
    auto triple = [&](const char* flag, const glm::dvec3& v) {
        return format(" %s %.17g,%.17g,%.17g", flag, v.x, v.y, v.z);
    };
    std::string command = "Raytracer " + options.scenePath.string() + " -o OUT.png";
    command += format(" --width %d --height %d --spp %u --depth %u --fov %.17g", width, height, spp,
                      options.depth, options.fovDegrees);
    command += triple("--camera-pos", camera.position) + triple("--camera-target", camera.target) +
               triple("--camera-up", camera.up);
    const Options defaults;
    if (options.background != defaults.background)
        command += triple("--background", options.background);
    const KernelChoices &kernel = options.kernel, &plain = defaults.kernel;
    if (kernel.sampler != plain.sampler)
        command += " --sampler " + choiceName(samplerNames(), kernel.sampler);
    if (kernel.seed != plain.seed) command += format(" --seed %u", kernel.seed);
    if (kernel.precision != plain.precision)
        command += " --precision " + choiceName(precisionNames(), kernel.precision);
    if (kernel.sphereTest != plain.sphereTest)
        command += " --sphere-test " + choiceName(sphereTestNames(), kernel.sphereTest);
    if (kernel.triangleTest != plain.triangleTest)
        command += " --triangle-test " + choiceName(triangleTestNames(), kernel.triangleTest);
    if (kernel.offset != plain.offset)
        command += " --offset " + choiceName(rayOffsetNames(), kernel.offset);
    if (!options.shaderDirectory.empty())
        command += " --shader-dir " + options.shaderDirectory.string();
    return command;
}
