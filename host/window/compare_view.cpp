#include "window/compare_view.h"

#include "base/scope_guard.h"
#include "compare/compare_page.h"
#include "compare/compare_report.h"
#include "compare/implied_terms.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

const char* pictureName(ComparedPicture picture) {
    switch (picture) {
    case ComparedPicture::Render:
        return "the render (the reference)";
    case ComparedPicture::Image:
        return "your image";
    case ComparedPicture::Difference:
        return "the difference (grey: matches; blue: darker, red: brighter than the reference)";
    }
    return "";
}

// Copies bytes into the picture image, through a staging buffer; waits until done.
void upload(const Context& context, const Image& picture, const Image8& bytes) {
    const VkDeviceSize size = VkDeviceSize(bytes.rgba.size());
    Buffer staging = createHostBuffer(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    ScopeExit release([&] { destroyBuffer(context, staging); });
    std::memcpy(staging.mapped, bytes.rgba.data(), bytes.rgba.size());
    runOneTimeCommands(context, [&](VkCommandBuffer commands) {
        transitionImage(commands, picture.image, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {picture.width, picture.height, 1};
        vkCmdCopyBufferToImage(commands, staging.buffer, picture.image,
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        // The frames blit from it in this layout.
        transitionImage(commands, picture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_READ_BIT);
    });
}

} // namespace

void openCompareView(Viewer& viewer) {
    CompareView& view = viewer.compare;
    if (!view.comparison) return;
    view.image = shownBytes(view.comparison->image.levels);
    view.difference = differenceHeatmap(view.comparison->match);
    // Sampled as well as copied: an image view needs a usage beyond transfers.
    view.picture = createImage(viewer.context, std::uint32_t(view.image.width),
                               std::uint32_t(view.image.height), VK_FORMAT_R8G8B8A8_UNORM,
                               VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                   VK_IMAGE_USAGE_SAMPLED_BIT);
}

void destroyCompareView(Viewer& viewer) {
    if (viewer.compare.picture.image) destroyImage(viewer.context, viewer.compare.picture);
}

void showCompared(Viewer& viewer, ComparedPicture picture) {
    CompareView& view = viewer.compare;
    if (!view.comparison) return;
    view.shown = picture;
    if (picture != ComparedPicture::Render) {
        // No frame may be blitting from the picture while it is written.
        VK_CHECK(vkDeviceWaitIdle(viewer.context.device));
        upload(viewer.context, view.picture,
               picture == ComparedPicture::Image ? view.image : view.difference);
    }
    viewer.presentNeeded = true;
    std::fprintf(stderr, "Compare: showing %s\n", pictureName(picture));
}

const Image* comparedPicture(const Viewer& viewer) {
    const CompareView& view = viewer.compare;
    if (!view.comparison || view.shown == ComparedPicture::Render) return nullptr;
    return &view.picture;
}

const Image8* comparedBytes(const Viewer& viewer) {
    const CompareView& view = viewer.compare;
    if (!view.comparison || view.shown == ComparedPicture::Render) return nullptr;
    return view.shown == ComparedPicture::Image ? &view.image : &view.difference;
}

void printPixelDiagnosis(const Viewer& viewer, glm::uvec2 pixel) {
    const Comparison& c = *viewer.compare.comparison;
    const PixelMatch& match = c.match;
    if (pixel.x >= std::uint32_t(match.width) || pixel.y >= std::uint32_t(match.height)) {
        std::fprintf(stderr, "Diagnosis: pixel %u,%u lies outside the %dx%d image\n", pixel.x,
                     pixel.y, match.width, match.height);
        return;
    }
    const std::size_t at = std::size_t(pixel.y) * std::size_t(match.width) + pixel.x;
    const int region = match.regionOf[at];
    std::string out = "pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) + ": ";
    if (region < 0)
        out += "matches the reference (within " + std::to_string(int(c.tolerance.levels)) +
               "/255, or one of its neighbours does)\n";
    else
        out += "differs: region " + std::to_string(region + 1) + " of " +
               std::to_string(match.regions.size()) + "\n" + regionText(c, std::size_t(region));
    out += readingText(readRayTreeAt(viewer.scene, c.image.levels, c.settings,
                                     glm::ivec2(int(pixel.x), int(pixel.y))));
    std::fputs(out.c_str(), stdout);
    std::fflush(stdout);
}
