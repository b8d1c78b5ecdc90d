// A model's lights (model_lights.h): the rig that follows the camera and the lights of its
// emitting materials. tools/obj_to_scene.py's light_rig and emitter_lights do the same,
// operation for operation.
#include "model/model_lights.h"

#include "model/exact_vectors.h"

#include <algorithm>
#include <map>

using namespace exact_vectors;

// A point light for each emitting material (MTL Ke), in the order the mesh's triangles first
// use them: at the area-weighted centroid of its triangles, lifted by lift along the sum of
// their (area-weighted) winding normals, the side its faces show, so that its own surface
// does not shadow it; its colour Ke clamped to [0, 1]. An approximation of an area light in
// the classic model of point lights: a closed emitter (a bulb), whose normals cancel, keeps
// its light at its centre, inside it, and lights nothing outside.
std::vector<Light> emitterLights(const Mesh& mesh, double lift) {
    struct Sums {
        double area = 0.0;
        glm::dvec3 weighted{0.0}, normal{0.0};
    };
    // Most models emit nothing: then no triangle need be looked at.
    if (std::none_of(mesh.materials.begin(), mesh.materials.end(),
                     [](const MeshMaterial& m) { return m.emission != glm::dvec3(0.0); }))
        return {};
    std::vector<std::uint32_t> order;
    std::map<std::uint32_t, Sums> sums;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::uint32_t material = mesh.triangleMaterials[t];
        const glm::dvec3 emission = mesh.materials[material].emission;
        if (emission == glm::dvec3(0.0)) continue;
        const glm::uvec3 v = mesh.triangles[t];
        const glm::dvec3 a = mesh.positions[v.x], b = mesh.positions[v.y], c = mesh.positions[v.z];
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        const double area = length(cross);
        auto [entry, added] = sums.try_emplace(material);
        if (added) order.push_back(material);
        entry->second.area += area;
        entry->second.weighted += (a + b + c) * (area / 3.0);
        entry->second.normal += cross;
    }
    std::vector<Light> lights;
    for (const std::uint32_t material : order) {
        const Sums& s = sums.at(material);
        if (!(s.area > 0.0)) continue;
        const glm::dvec3 position = s.weighted / s.area + normalizedOrZero(s.normal) * lift;
        lights.push_back(
            Light{position, glm::clamp(mesh.materials[material].emission, 0.0, 1.0), 0});
    }
    return lights;
}

std::vector<Light> lightRig(const LightRigAnchor& anchor, const CameraPose& camera) {
    // From the model towards the eye; an eye at the centre uses the camera's own backward axis.
    glm::dvec3 back = normalizedOrZero(camera.position - anchor.centre);
    if (back == glm::dvec3(0.0)) back = normalizedOrZero(camera.position - camera.target);
    // Level with the camera's up (a model's up, for its own camera): the rig keeps its
    // height above the model however far the camera looks down, so the sides it sees stay
    // lit as the front view lights them. Seen from straight along up, back stays as it is.
    const glm::dvec3 upAxis = normalizedOrZero(camera.up);
    const glm::dvec3 level = normalizedOrZero(back - upAxis * dot(back, upAxis));
    if (level != glm::dvec3(0.0)) back = level;
    // Seen from straight along the camera's up, the camera's own right (then perpendicular
    // to back) keeps the frame turning with the view.
    glm::dvec3 right = normalizedOrZero(glm::cross(camera.up, back));
    if (right == glm::dvec3(0.0))
        right = normalizedOrZero(glm::cross(camera.target - camera.position, camera.up));
    const glm::dvec3 up = glm::cross(back, right);
    // For the default camera these are the unit axes, up to rounding where the fitted
    // model's centre is a hair off the line of sight.
    struct Place {
        double right, up, back, brightness;
    };
    const Place places[] = {{-2.0, 2.5, 2.5, 0.8}, {2.5, 0.5, 2.0, 0.3}, {0.5, 3.0, -3.0, 0.5}};
    const double radius = anchor.radius;
    std::vector<Light> lights;
    lights.reserve(3 + anchor.emitters.size());
    for (const Place& p : places) {
        const glm::dvec3 offset =
            right * (radius * p.right) + up * (radius * p.up) + back * (radius * p.back);
        lights.push_back(Light{anchor.centre + offset, glm::dvec3(p.brightness), 0});
    }
    lights.insert(lights.end(), anchor.emitters.begin(), anchor.emitters.end());
    return lights;
}

void placeLightRig(Scene& scene, const CameraPose& camera) {
    if (scene.lightRig) scene.lights = lightRig(*scene.lightRig, camera);
}
