#include "scene/scene_summary.h"

#include "scene/scene_error.h"
#include "scene/scene_triangles.h"
#include "scene/warning_summary.h"

#include <array>
#include <charconv>
#include <set>

namespace {

// The shortest text that reads back as the same double.
std::string shortest(double value) {
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof text, value);
    return error == std::errc() ? std::string(text, end) : std::string("?");
}

std::string triple(const glm::dvec3& v) {
    return shortest(v.x) + "," + shortest(v.y) + "," + shortest(v.z);
}

using MaterialKey = std::array<double, 8>;

MaterialKey keyOf(const Material& m) {
    return {m.diffuse.x,  m.diffuse.y,  m.diffuse.z, m.specular.x,
            m.specular.y, m.specular.z, m.shininess, m.mirror};
}

} // namespace

std::string sceneSummary(const Scene& scene) {
    std::set<MaterialKey> materials;
    glm::dvec3 low(0.0), high(0.0);
    bool any = false;
    auto include = [&](const glm::dvec3& a, const glm::dvec3& b) {
        low = any ? glm::min(low, a) : a;
        high = any ? glm::max(high, b) : b;
        any = true;
    };
    for (const Sphere& sphere : scene.spheres) {
        materials.insert(keyOf(sphere.material));
        include(sphere.center - sphere.radius, sphere.center + sphere.radius);
    }
    forEachTriangle(scene, [&](const Triangle& triangle) {
        for (const Vertex& vertex : triangle.vertices) {
            materials.insert(keyOf(vertex.material));
            include(vertex.position, vertex.position);
        }
    });
    std::string model;
    if (const std::optional<ModelPlacement>& m = scene.model) {
        model = "model as read: " + triple(m->readLow) + " to " + triple(m->readHigh) + "\n" +
                "model as placed: " + triple(m->placedLow) + " to " + triple(m->placedHigh) +
                (m->fitted ? "" : " (--no-fit: as read, its up axis turned)") +
                (m->inside ? " (a room: seen from inside)" : "") + "\n" + "floor: " +
                (m->floor ? triple(m->floorLow) + " to " + triple(m->floorHigh)
                          : std::string(m->inside ? "none (a room has its own)"
                                                  : "none (--no-ground)")) +
                "\n";
        if (!scene.textures.empty()) {
            std::size_t bytes = 0;
            for (const Texture& texture : scene.textures)
                bytes += texture.image.rgba.size();
            model += "textures: " + std::to_string(scene.textures.size()) + " (" +
                     std::to_string(bytes) + " bytes of texels)\n";
        }
        const std::string unrendered = notRenderedText(scene);
        model +=
            "not rendered: " + (unrendered.empty() ? std::string("nothing") : unrendered) + "\n";
    }
    return "spheres: " + std::to_string(scene.spheres.size()) + "\n" +
           "triangles: " + std::to_string(triangleCount(scene)) + "\n" +
           "lights: " + std::to_string(scene.lights.size()) + "\n" +
           "materials: " + std::to_string(materials.size()) + "\n" + "bounds: " +
           (any ? triple(low) + " to " + triple(high) : "none (no spheres or triangles)") + "\n" +
           model + "warnings: " + std::to_string(scene.warnings.size()) + "\n";
}

std::string notRenderedText(const Scene& scene) {
    std::string text;
    if (!scene.model) return text;
    for (const auto& [what, holding] : scene.model->notRendered)
        text += (text.empty() ? "" : "; ") + what + " in " + std::to_string(holding) +
                (holding == 1 ? " material" : " materials");
    return text;
}

std::vector<std::string> loadMessages(const Scene& scene, const std::string& fileName) {
    std::vector<std::string> lines = summarisedWarnings(scene.warnings);
    if (const std::string unrendered = notRenderedText(scene); !unrendered.empty())
        lines.push_back(sceneLocation(fileName, 0) + "note: not rendered: " + unrendered);
    return lines;
}
