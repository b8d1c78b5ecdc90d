// referenceStoryJson (reference_story.h): the reference's story with the fields, names and
// nesting of Raytracer --pixel (host/render/pixel_story_json.cpp), numbers to 17 digits.
#include "reference/reference_story.h"

#include "base/json.h"

namespace {

// Doubles to 17 significant digits, which give each double back exactly.
constexpr int kDoubleDigits = 17;

std::string number(double value) {
    return jsonNumber(value, kDoubleDigits);
}

std::string triple(const glm::dvec3& v) {
    return jsonTriple(v, kDoubleDigits);
}

std::string primitive(const StoryPrimitive& p) {
    std::string text = "\"kind\": \"" + std::string(p.kind) + "\"";
    if (p.index >= 0)
        text += ", \"index\": " + std::to_string(p.index) + ", \"line\": " + std::to_string(p.line);
    return text;
}

std::string lightJson(const StoryLightRecord& light, std::size_t index, const Scene& scene) {
    std::string text = "{\"light\": " + std::to_string(index) +
                       ", \"line\": " + std::to_string(scene.lights[index].line) +
                       ", \"result\": \"" + light.result + "\"";
    if (std::string(light.result) == "blocked")
        text += ", \"blocker\": {" + primitive(light.blocker) + "}";
    return text + ", \"n_dot_l\": " + number(light.nDotL) +
           ", \"contribution\": " + triple(light.contribution) + "}";
}

std::string bounceJson(const StoryBounceRecord& b, std::size_t index, const Scene& scene) {
    const bool found = b.hit.index >= 0;
    std::string text = "    {\"bounce\": " + std::to_string(index) +
                       ",\n     \"ray\": {\"origin\": " + triple(b.origin) +
                       ", \"direction\": " + triple(b.direction) + "},\n     \"hit\": {" +
                       primitive(b.hit);
    if (found) text += ", \"t\": " + number(b.t);
    if (std::string(b.hit.kind) == "triangle")
        text += ", \"barycentric\": " + triple(b.barycentric);
    text += "},\n";
    if (found) {
        text += "     \"normal\": " + triple(b.normal) +
                ",\n     \"material\": {\"diffuse\": " + triple(b.material.diffuse) +
                ", \"specular\": " + triple(b.material.specular) +
                ", \"shininess\": " + number(b.material.shininess) + "},\n     \"lights\": [";
        for (std::size_t i = 0; i < b.lights.size(); ++i)
            text += std::string(i ? ",\n                " : "") + lightJson(b.lights[i], i, scene);
        text += "],\n";
    }
    return text + "     \"" + (found ? "local" : "background") + "\": " + triple(b.local) +
           ", \"throughput\": " + triple(b.throughput) + ", \"color\": " + triple(b.color) +
           ", \"next\": \"" + b.next + "\"}";
}

} // namespace

std::string referenceStoryJson(const ReferenceStory& story, const Scene& scene,
                               const ReferenceSettings& settings, const std::string& scenePath,
                               int i, int j) {
    const std::string lights = std::to_string(scene.lights.size());
    std::string text = "{\"renderer\": \"reference\", \"scene\": " + jsonString(scenePath) +
                       ", \"pixel\": [" + std::to_string(i) + ", " + std::to_string(j) +
                       "], \"image\": [" + std::to_string(settings.width) + ", " +
                       std::to_string(settings.height) +
                       "], \"spp\": " + std::to_string(settings.spp) +
                       ", \"depth\": " + std::to_string(settings.depth) + ",\n";
    text += " \"sample\": 0, \"sample_offset\": [" + number(story.sampleOffset.x) + ", " +
            number(story.sampleOffset.y) + "], \"lights\": " + lights +
            ", \"lights_recorded\": " + lights +
            ", \"lights_truncated\": false,\n \"bounces\": [\n";
    for (std::size_t b = 0; b < story.bounces.size(); ++b)
        text += (b ? ",\n" : "") + bounceJson(story.bounces[b], b, scene);
    const glm::dvec3 c = story.pixelColor;
    text += "\n ],\n \"sample_color\": " + triple(story.sampleColor) +
            ",\n \"pixel_color\": " + triple(c) + ", \"pixel_8bit\": [" +
            std::to_string(quantizeChannel(c.x, settings.truncate)) + ", " +
            std::to_string(quantizeChannel(c.y, settings.truncate)) + ", " +
            std::to_string(quantizeChannel(c.z, settings.truncate)) + "]}\n";
    return text;
}
