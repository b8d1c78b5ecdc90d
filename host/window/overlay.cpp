// The overlay: Dear ImGui with its GLFW and Vulkan backends (Debian's libimgui-dev builds
// both into libimgui.a). ImGui 1.86's Vulkan backend draws inside a render pass: ours loads
// the swapchain image as the blit left it, so the panel lands on top of the traced pixels
// in the swapchain image only, never in the output image that P and headless read.
#include "window/overlay.h"

#include "base/scope_guard.h"
#include "gpu/resources.h"
#include "gpu/vk_check.h"
#include "window/input.h"
#include "window/reload.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

void checkImguiResult(VkResult result) {
    if (result != VK_SUCCESS) VK_CHECK(result);
}

// LOAD keeps the blitted image; the panel is blended over it. The image arrives in
// TRANSFER_DST_OPTIMAL from the blit and leaves for presentation.
VkRenderPass createRenderPass(VkDevice device, VkFormat format) {
    VkAttachmentDescription attachment{};
    attachment.format = format;
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachment.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colour;
    // The blit's writes come before the load and the layout change; the present waits on
    // the render-finished semaphore, which makes the panel's writes visible to it.
    VkSubpassDependency dependencies[2]{};
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[0].srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[0].dstAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
    dependencies[1].dstAccessMask = 0;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &attachment;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = dependencies;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &renderPass));
    return renderPass;
}

void destroyFramebuffers(Overlay& overlay, VkDevice device) {
    for (VkFramebuffer framebuffer : overlay.framebuffers)
        vkDestroyFramebuffer(device, framebuffer, nullptr);
    for (VkImageView view : overlay.views)
        vkDestroyImageView(device, view, nullptr);
    overlay.framebuffers.clear();
    overlay.views.clear();
}

void createFramebuffers(Overlay& overlay, VkDevice device, const Swapchain& swapchain) {
    for (VkImage image : swapchain.images) {
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = swapchain.format;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
        overlay.views.push_back(view);
        VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        info.renderPass = overlay.renderPass;
        info.attachmentCount = 1;
        info.pAttachments = &view;
        info.width = swapchain.extent.width;
        info.height = swapchain.extent.height;
        info.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        VK_CHECK(vkCreateFramebuffer(device, &info, nullptr, &framebuffer));
        overlay.framebuffers.push_back(framebuffer);
    }
}

// The font atlas goes to the device once, in a command buffer of its own.
void uploadFonts(const Context& context) {
    runOneTimeCommands(
        context, [](VkCommandBuffer commands) { ImGui_ImplVulkan_CreateFontsTexture(commands); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

// The Vulkan backend and its pipeline for the render pass of overlay.format.
void initVulkanBackend(Viewer& viewer) {
    const Context& context = viewer.context;
    Overlay& overlay = viewer.overlay;
    overlay.renderPass = createRenderPass(context.device, viewer.swapchain.format);
    overlay.format = viewer.swapchain.format;
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance;
    info.PhysicalDevice = context.physicalDevice;
    info.Device = context.device;
    info.QueueFamily = context.queueFamily;
    info.Queue = context.queue;
    info.DescriptorPool = overlay.descriptorPool;
    const auto images = std::uint32_t(viewer.swapchain.images.size());
    info.MinImageCount = images < 2 ? 2 : images;
    info.ImageCount = info.MinImageCount;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImguiResult;
    if (!ImGui_ImplVulkan_Init(&info, overlay.renderPass))
        throw std::runtime_error("the overlay's Vulkan backend (ImGui) did not start");
    uploadFonts(context);
}

// A radio button per name; returns whether the choice changed.
template <typename T> bool choiceButtons(const char* label, const ChoiceNames<T>& names, T& value) {
    bool changed = false;
    ImGui::TextUnformatted(label);
    for (const auto& [name, choice] : names) {
        ImGui::SameLine();
        ImGui::PushID(label);
        if (ImGui::RadioButton(name, value == choice) && value != choice) {
            value = choice;
            changed = true;
        }
        ImGui::PopID();
    }
    return changed;
}

// The switches: each edits a copy of the window's options, applied when one changed.
void buildSwitches(Viewer& viewer) {
    Options options = viewer.options;
    bool changed = false;
    changed |= choiceButtons("sampler", samplerNames(), options.kernel.sampler);
    changed |= choiceButtons("accel", accelerationNames(), options.acceleration);
    ImGui::BeginDisabled(!viewer.context.float64Enabled); // fp64 needs the device's shaderFloat64
    changed |= choiceButtons("precision", precisionNames(), options.kernel.precision);
    ImGui::EndDisabled();
    changed |= choiceButtons("sphere-test", sphereTestNames(), options.kernel.sphereTest);
    changed |= choiceButtons("triangle-test", triangleTestNames(), options.kernel.triangleTest);
    changed |= choiceButtons("offset", rayOffsetNames(), options.kernel.offset);
    // Numbers are applied on Enter (or a step button): typing 256 should not build and
    // render 2 and 25 first.
    int depth = int(options.depth);
    if (ImGui::InputInt("depth", &depth, 1, 1, ImGuiInputTextFlags_EnterReturnsTrue) &&
        depth >= 0) {
        options.depth = std::uint32_t(depth);
        changed = true;
    }
    int target = int(viewer.sampleTarget);
    if (ImGui::InputInt("spp target", &target, 1, 16, ImGuiInputTextFlags_EnterReturnsTrue) &&
        target >= 1) {
        options.samplesPerPixel = std::uint32_t(target);
        options.samplesGiven = true;
        changed = true;
    }
    if (changed && !(options == viewer.options)) applyOptions(viewer, options);
}

void buildCamera(const Viewer& viewer) {
    std::string camera = cameraOptions(viewer);
    ImGui::TextUnformatted("camera (O prints it):");
    ImGui::InputText("##camera", camera.data(), camera.size() + 1, ImGuiInputTextFlags_ReadOnly);
    ImGui::SameLine();
    if (ImGui::Button("Copy")) glfwSetClipboardString(viewer.window, camera.c_str());
}

} // namespace

void createOverlay(Viewer& viewer) {
    OnFailure release([&] { destroyOverlay(viewer); });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    viewer.overlay.created = true; // from here on destroyOverlay has something to undo
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini in the current folder
    ImGui::StyleColorsDark();
    // Chained: ImGui's callbacks call the window's own (installInputCallbacks) first.
    ImGui_ImplGlfw_InitForVulkan(viewer.window, true);
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 1; // the font texture's
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(viewer.context.device, &poolInfo, nullptr,
                                    &viewer.overlay.descriptorPool));
    initVulkanBackend(viewer);
    createFramebuffers(viewer.overlay, viewer.context.device, viewer.swapchain);
}

void destroyOverlay(Viewer& viewer) {
    Overlay& overlay = viewer.overlay;
    if (!overlay.created) return;
    VkDevice device = viewer.context.device;
    destroyFramebuffers(overlay, device);
    if (overlay.renderPass) ImGui_ImplVulkan_Shutdown();
    if (overlay.renderPass) vkDestroyRenderPass(device, overlay.renderPass, nullptr);
    if (overlay.descriptorPool) vkDestroyDescriptorPool(device, overlay.descriptorPool, nullptr);
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    const bool shown = overlay.shown;
    overlay = Overlay{};
    overlay.shown = shown;
}

void overlaySwapchainChanged(Viewer& viewer) {
    Overlay& overlay = viewer.overlay;
    VkDevice device = viewer.context.device;
    VK_CHECK(vkDeviceWaitIdle(device));
    destroyFramebuffers(overlay, device);
    if (viewer.swapchain.format != overlay.format) {
        ImGui_ImplVulkan_Shutdown();
        vkDestroyRenderPass(device, overlay.renderPass, nullptr);
        overlay.renderPass = VK_NULL_HANDLE;
        VK_CHECK(vkResetDescriptorPool(device, overlay.descriptorPool, 0));
        initVulkanBackend(viewer);
    }
    createFramebuffers(overlay, device, viewer.swapchain);
}

void buildOverlay(Viewer& viewer) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("Raytracer", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
    const double pixels =
        double(viewer.renderer.outputImage.width) * double(viewer.renderer.outputImage.height);
    const double raysPerSecond =
        viewer.lastFrameMs > 0.0 ? viewer.lastFrameSamples * pixels / (viewer.lastFrameMs * 1e-3)
                                 : 0.0;
    // Compact by default: two lines of figures, and the switches and the camera in sections
    // that unfold on a click (9% of a 640x480 view folded: 318 x 88 pixels).
    ImGui::Text("%.1f ms  %u/%u spp  %.2f M rays/s", viewer.lastFrameMs, viewer.samplesDone,
                viewer.sampleTarget, raysPerSecond * 1e-6);
    ImGui::TextDisabled("%s  (H hides)", viewer.context.properties.deviceName);
    if (ImGui::CollapsingHeader("kernel")) buildSwitches(viewer);
    if (ImGui::CollapsingHeader("camera")) buildCamera(viewer);
    ImGui::End();
    ImGui::Render();
}

void recordOverlay(const Viewer& viewer, VkCommandBuffer commands, std::uint32_t imageIndex) {
    const Overlay& overlay = viewer.overlay;
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = overlay.renderPass;
    begin.framebuffer = overlay.framebuffers[imageIndex];
    begin.renderArea.extent = viewer.swapchain.extent;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    // A frame drawn without building the panel (none built yet) draws nothing over the image.
    if (ImDrawData* drawData = ImGui::GetDrawData())
        ImGui_ImplVulkan_RenderDrawData(drawData, commands);
    vkCmdEndRenderPass(commands);
}

bool overlayWantsMouse(const Viewer& viewer) {
    return viewer.overlay.shown && viewer.overlay.created && ImGui::GetIO().WantCaptureMouse;
}

bool overlayWantsKeyboard(const Viewer& viewer) {
    return viewer.overlay.shown && viewer.overlay.created && ImGui::GetIO().WantCaptureKeyboard;
}
