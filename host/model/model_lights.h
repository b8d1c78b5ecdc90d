// A model's lights (docs/models.md): the key, fill and rim rig that follows the camera, and
// a point light for each of its emitting materials (MTL Ke).
#pragma once

#include "scene/camera.h"
#include "scene/mesh.h"
#include "scene/scene.h"

#include <vector>

// An emitting material's light sits this share of the model's largest extent off its
// surface, on the side its faces show.
inline constexpr double kEmitterLift = 0.01;

// The key, fill and rim lights for a camera, then the anchor's emitters: at distances in
// units of the anchor's radius from its centre along the camera's right, up and backward
// axes as seen from the camera looking at the centre, levelled with the camera's up (back:
// from the centre towards the eye; right: perpendicular to back and the camera's up), so
// every camera pose sees the model lit as the front view does.
std::vector<Light> lightRig(const LightRigAnchor& anchor, const CameraPose& camera);

// Places a scene's rig (scene.lightRig) again for camera; a scene without one is left alone.
void placeLightRig(Scene& scene, const CameraPose& camera);

// A point light for each emitting material of the mesh, lifted by lift off its surface.
std::vector<Light> emitterLights(const Mesh& mesh, double lift);
