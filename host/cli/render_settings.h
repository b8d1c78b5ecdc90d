// The command line's Options turned into the renderer's RenderSettings, and the headless
// device they ask for, in one place for the headless paths and the window (which then sets
// what it does differently). Kept
// apart from renderer.h so that the renderer does not depend on the command line.
#pragma once

#include "cli/options.h"
#include "render/renderer.h"
#include "scene/scene_capacity.h"

#include <optional>

// The settings as the command line gives them, the shader and pipeline cache folder
// included (none with --no-cache). Not progressive: one frame of samplesPerPixel.
RenderSettings renderSettingsFrom(const Options& options);

// The camera a scene is seen from: the command line's, or, when it gives none, a model's
// fitted to the view (the eye at the origin, looking at the model's centre, with the model's
// up as placed: the same image as the default camera's, and turntables and the window's
// orbit turn about the model's up).
CameraPose cameraFor(const Options& options, const Scene& scene);
// Whether cameraFor gives a model's own camera: no --camera-* and a fitted model.
bool seesModelWithItsCamera(const Options& options, const Scene& scene);

// The point --turntable orbits: --orbit-center; else the camera's target where one is given
// (or where cameraFor looks at a fitted model's centre); else the centre of what the camera
// sees (subjectBounds: a floor that reaches far beyond the frame does not move it).
glm::dvec3 turntableCentre(const Options& options, const Scene& scene, const CameraPose& camera);
// The axis it orbits about: a model's up (the camera's, for its own camera), else the
// scene's floor's normal (floorAxis), else the camera's up.
glm::dvec3 turntableAxis(const Scene& scene, const CameraPose& camera);
// Frame `frame` of --turntable: turntableCamera about centre and axis; a model seen from its
// own camera, from outside, about its own centre (no --orbit-center), is fitted again for
// every frame but the first (refitCamera: the eye moves along its line of sight), so a long
// model seen end-on fills the frame as it does side-on. Frame 0 is camera itself, bit for bit.
CameraPose turntableFrameCamera(const Options& options, const Scene& scene,
                                const CameraPose& camera, glm::dvec3 centre, glm::dvec3 axis,
                                std::uint32_t frame);

// Whether shadow rays use the shadow terminator fix: --terminator, else on for an OBJ model.
bool terminatorFixFor(const Options& options, const Scene& scene);

// The device of a headless render (one image or a batch): an instance, with the validation
// layer for --validate, the device --device names (with fp64 when --precision fp64 asks
// for it), and the image size checked against what it can hold.
void openHeadlessDevice(Context& context, const Options& options);

// What the device of this run can hold, for loadScene's early check (scene_capacity.h):
// probed before a file of kProbedFileBytes or more is read, or whatever its size when a hidden
// option lowers a limit (the tests). A smaller file does not pay for an instance; the upload
// checks it.
inline constexpr std::uintmax_t kProbedFileBytes = 16u << 20;
std::optional<SceneCapacity> capacityBeforeLoading(const Options& options);
