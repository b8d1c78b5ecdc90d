// pixelStoryJson (pixel_story.h): the GpuPixelStory in words, the kernel's slots turned
// into the file's indices and lines. tools/reference/reference_story.cpp writes the same
// fields for the CPU reference; tools/pixel_story puts the two side by side.
#include "render/pixel_story.h"

#include "base/json.h"

#include <string>

namespace {

// The kernel's floats to 9 significant digits, which give each float back exactly.
constexpr int kFloatDigits = 9;

std::string number(float value) {
    return jsonNumber(value, kFloatDigits);
}

std::string triple(const glm::vec4& v) {
    return jsonTriple(v, kFloatDigits);
}

const char* kindName(std::uint32_t kind) {
    return kind == 1u ? "sphere" : kind == 2u ? "triangle" : "none";
}

const char* nextName(std::uint32_t next) {
    switch (next) {
    case STORY_NEXT_REFLECT:
        return "reflect";
    case STORY_NEXT_MISS:
        return "miss";
    case STORY_NEXT_NO_MIRROR:
        return "no-mirror";
    case STORY_NEXT_DEPTH:
        return "depth";
    case STORY_NEXT_ZERO_THROUGHPUT:
        return "zero-throughput";
    default:
        return "?";
    }
}

const char* lightResult(std::uint32_t state) {
    return state == STORY_LIGHT_LIT ? "lit" : state == STORY_LIGHT_BLOCKED ? "blocked" : "behind";
}

// "kind", "index" (the file's, among that kind), "slot" (the kernel's) and "line" of a hit.
std::string primitive(std::uint32_t kind, std::uint32_t slot, const SlotSources& sources) {
    std::string text = "\"kind\": \"" + std::string(kindName(kind)) + "\"";
    const auto& indices = kind == 1u ? sources.sphereIndex : sources.triangleIndex;
    const auto& lines = kind == 1u ? sources.sphereLine : sources.triangleLine;
    if ((kind == 1u || kind == 2u) && slot < indices.size())
        text += ", \"index\": " + std::to_string(indices[slot]) +
                ", \"slot\": " + std::to_string(slot) +
                ", \"line\": " + std::to_string(lines[slot]);
    return text;
}

std::string lightJson(const gpu::GpuStoryLight& light, std::uint32_t index,
                      const SlotSources& sources) {
    std::string text = "{\"light\": " + std::to_string(index);
    if (index < sources.lightLine.size())
        text += ", \"line\": " + std::to_string(sources.lightLine[index]);
    text += ", \"result\": \"" + std::string(lightResult(light.shadow.x)) + "\"";
    if (light.shadow.x == STORY_LIGHT_BLOCKED)
        text += ", \"blocker\": {" + primitive(light.shadow.y, light.shadow.z, sources) + "}";
    text += ", \"n_dot_l\": " + number(light.contribution.w) +
            ", \"contribution\": " + triple(light.contribution) + "}";
    return text;
}

std::string bounceJson(const gpu::GpuStoryBounce& b, std::uint32_t index, std::uint32_t lights,
                       const SlotSources& sources) {
    const std::uint32_t kind = b.hit.x;
    std::string text = "    {\"bounce\": " + std::to_string(index) +
                       ",\n     \"ray\": {\"origin\": " + triple(b.origin) +
                       ", \"direction\": " + triple(b.direction) + "},\n     \"hit\": {" +
                       primitive(kind, b.hit.y, sources);
    if (kind != 0u) text += ", \"t\": " + number(b.origin.w);
    if (kind == 2u) text += ", \"barycentric\": " + triple(b.barycentric);
    text += "},\n";
    if (kind != 0u) {
        text += "     \"normal\": " + triple(b.normal) +
                ",\n     \"material\": {\"diffuse\": " + triple(b.diffuseShininess) +
                ", \"specular\": " + triple(b.specular) +
                ", \"shininess\": " + number(b.diffuseShininess.w) + "},\n     \"lights\": [";
        const std::uint32_t recorded = b.hit.z < lights ? b.hit.z : lights;
        for (std::uint32_t i = 0; i < recorded; ++i)
            text +=
                std::string(i ? ",\n                " : "") + lightJson(b.lights[i], i, sources);
        text += "],\n";
    }
    text += std::string("     \"") + (kind != 0u ? "local" : "background") +
            "\": " + triple(b.local) + ", \"throughput\": " + triple(b.throughput) +
            ", \"color\": " + triple(b.color) + ", \"next\": \"" + nextName(b.hit.w) + "\"}";
    return text;
}

} // namespace

std::string pixelStoryJson(const gpu::GpuPixelStory& story, const SlotSources& sources,
                           const StoryHeader& header) {
    const std::uint32_t lights = story.counts.y;
    const std::uint32_t recorded = lights < MAX_STORY_LIGHTS ? lights : MAX_STORY_LIGHTS;
    std::string text = "{\"renderer\": \"gpu\", \"scene\": " + jsonString(header.scene) +
                       ", \"pixel\": [" + std::to_string(header.x) + ", " +
                       std::to_string(header.y) + "], \"image\": [" + std::to_string(header.width) +
                       ", " + std::to_string(header.height) +
                       "], \"spp\": " + std::to_string(header.samples) +
                       ", \"depth\": " + std::to_string(header.depth) + ",\n";
    text += " \"sample\": 0, \"sample_offset\": [" + number(story.sampleOffset.x) + ", " +
            number(story.sampleOffset.y) + "], \"lights\": " + std::to_string(lights) +
            ", \"lights_recorded\": " + std::to_string(recorded) +
            ", \"lights_truncated\": " + (lights > recorded ? "true" : "false") +
            ",\n \"bounces\": [\n";
    const std::uint32_t bounces = story.counts.x < MAX_DEPTH + 1 ? story.counts.x : MAX_DEPTH + 1;
    for (std::uint32_t b = 0; b < bounces; ++b)
        text += (b ? ",\n" : "") + bounceJson(story.bounces[b], b, recorded, sources);
    const glm::uvec4 level = story.pixelLevel;
    text += "\n ],\n \"sample_color\": " + triple(story.sampleColor) +
            ",\n \"pixel_color\": " + triple(story.pixelColor) + ", \"pixel_8bit\": [" +
            std::to_string(level.x) + ", " + std::to_string(level.y) + ", " +
            std::to_string(level.z) + "]}\n";
    return text;
}
