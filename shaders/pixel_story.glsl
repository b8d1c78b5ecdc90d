// The pixel story (--pixel, the window's I key; docs/pixel_story.md): with recordPixel
// (trace.comp) the kernel is dispatched for one pixel and writes what it computes for
// that pixel's sample 0 into `story` (GpuPixelStory, shared.h): each ray, its hit, the
// surface, each light's shadow ray and share, the colour and throughput after each
// bounce, then the pixel's value. The calls sit where the kernel computes these values and
// record them as they are; without recordPixel every function returns at once (or returns
// its argument) and the driver compiles the calls away.
// Needs: Ray, Hit (camera.glsl, intersect.glsl), the story binding and recordPixel (trace.comp).

bool storyOn = false;  // this invocation is recording the current sample
uint storyBounce = 0u; // the bounce being recorded
Hit storyBlocker;      // the nearest hit of the last blocked shadow ray (storyShadowBlocker)

// Whether this invocation records now; false at compile time in the normal kernel.
bool storyRecording() {
    return recordPixel && storyOn;
}

// Starts a sample: only sample 0 is recorded, at offset (u, v) inside the pixel.
void storyStartSample(uint s, vec2 offset) {
    storyOn = recordPixel && s == 0u;
    if (!storyRecording()) return;
    story.sampleOffset = vec4(offset, 0.0, 0.0);
    story.counts.x = 0u;
}

// The ray of a bounce and its closest hit.
void storyRay(uint bounce, Ray ray, Hit hit) {
    if (!storyRecording()) return;
    storyBounce = bounce;
    story.counts.x = bounce + 1u;
    bool found = hit.kind != HIT_NONE;
    story.bounces[bounce].origin = vec4(vec3(ray.origin), found ? float(hit.t) : 0.0);
    story.bounces[bounce].direction = vec4(vec3(ray.direction), 0.0);
    story.bounces[bounce].hit = uvec4(hit.kind, found ? hit.index : 0u, 0u, STORY_NEXT_MISS);
    story.bounces[bounce].barycentric =
        vec4(hit.kind == HIT_TRIANGLE ? vec3(hit.barycentric) : vec3(0.0), 0.0);
}

// The nearest hit on a shadow ray that anyHit found blocked (what blocks it).
void storyShadowBlocker(Hit blocker) {
    if (storyRecording()) storyBlocker = blocker;
}

// Light i at the current bounce: STORY_LIGHT_*, N.L and its share of the local colour.
void storyLight(uint i, uint state, float nDotL, vec3 contribution) {
    if (!storyRecording() || i >= MAX_STORY_LIGHTS) return;
    bool blocked = state == STORY_LIGHT_BLOCKED;
    story.bounces[storyBounce].lights[i] =
        GpuStoryLight(vec4(contribution, nDotL), uvec4(state, blocked ? storyBlocker.kind : 0u,
                                                       blocked ? storyBlocker.index : 0u, 0u));
    story.bounces[storyBounce].hit.z = i + 1u;
}

// The surface at the current bounce, its local colour and the weight it enters the sample with.
void storySurface(rvec3 normal, vec3 kd, vec3 ks, float shininess, vec3 local, vec3 throughput) {
    if (!storyRecording()) return;
    story.bounces[storyBounce].normal = vec4(vec3(normal), 0.0);
    story.bounces[storyBounce].diffuseShininess = vec4(kd, shininess);
    story.bounces[storyBounce].specular = vec4(ks, 0.0);
    story.bounces[storyBounce].local = vec4(local, 0.0);
    story.bounces[storyBounce].throughput = vec4(throughput, 0.0);
}

// A bounce that reflects: the sample's colour so far and whether anything can follow.
void storyReflect(vec3 color, vec3 throughput) {
    if (!storyRecording()) return;
    story.bounces[storyBounce].color = vec4(color, 0.0);
    story.bounces[storyBounce].hit.w =
        all(equal(throughput, vec3(0.0))) ? STORY_NEXT_ZERO_THROUGHPUT : STORY_NEXT_REFLECT;
}

// The last bounce of the sample: how it ends and its colour, which is returned unchanged.
vec3 storyLast(uint next, vec3 throughput, vec3 local, vec3 color) {
    if (!storyRecording()) return color;
    if (next == STORY_NEXT_MISS) {
        story.bounces[storyBounce].local = vec4(local, 0.0);
        story.bounces[storyBounce].throughput = vec4(throughput, 0.0);
    }
    story.bounces[storyBounce].color = vec4(color, 0.0);
    story.bounces[storyBounce].hit.w = next;
    return color;
}

// Sample 0's colour before the clamp, returned unchanged.
vec3 storySampleColor(vec3 color) {
    if (storyRecording()) story.sampleColor = vec4(color, 0.0);
    return color;
}

// The pixel's value once samples 0..end-1 of `samples` are in `sum`: the average of its
// clamped samples and the levels the image gets (the same arithmetic as main's write).
// Before the last pass (the host traced the samples in several dispatches) pixelColor holds
// the running sum instead, which the next pass reads back (storyRunningSum).
void storyPixel(vec3 sum, uint end, uint samples) {
    if (end < samples) {
        story.pixelColor = vec4(sum, 0.0);
        return;
    }
    vec3 average = sum / float(end);
    story.pixelColor = vec4(average, 0.0);
    story.pixelLevel = uvec4(uvec3(floor(average * 255.0 + 0.5)), 0u);
    story.counts.yzw = uvec3(lightCount, samples, 1u);
}

// The running sum an earlier pass left (storyPixel).
vec3 storyRunningSum() {
    return story.pixelColor.rgb;
}
