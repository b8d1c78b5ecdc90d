// The CPU reference renderer: the model of docs/model.md, literally, in double precision.
//
// It exists to check the GPU renderer, so it shares none of the GPU shader's
// numerical methods; a mistake in one method then shows up as a difference
// instead of being repeated on both sides.
//
//   what                 shader (float)                     reference (double)
//   -------------------  ---------------------------------  ---------------------------------
//   sphere               stable quadratic, Ray Tracing      geometric method (closest approach
//                        Gems ch.7                          of the line to the centre, Haines)
//   triangle             watertight, Woop-Benthin-Wald      signed volumes (scalar triple
//                        2013 (shear + 2D edge functions)   products of the ray with each edge,
//                                                           Pluecker-style), no shear, no
//                                                           axis permutation
//   self-intersection    origin pushed off the surface      none needed: a secondary ray knows
//                        by a scaled offset                 the primitive it leaves; its own
//                                                           triangle is skipped (a plane can't be
//                                                           re-hit) and for its own sphere the
//                                                           root at t = 0 is removed analytically
//   reflection           iterative loop                     the model's recursion, folded from the
//                                                           innermost bounce outwards
//   texture              its own bilinear filter over       the same rule (docs/models.md) in
//                        RGBA8 texels (no Vulkan sampler),  double from the decoded image:
//                        texture coordinates in float       texture coordinates interpolated
//                                                           from the model's doubles
//
// Accuracy. Spheres: the geometric method's d^2 = |L|^2 - tca^2 cancels when the
// eye is far from a small sphere; in double it keeps about 53 - 2*log2(|L|/r)
// bits, i.e. > 35 bits for |L|/r < 500, far below a float's 24. Triangles: the
// edge test of an edge shared by two triangles is computed from the same two
// (translated) vertices in both, and IEEE arithmetic makes cross(b, a) exactly
// -cross(a, b), so the two tests agree exactly on which side a ray passes: the
// test is watertight with inclusive edges and needs no epsilon. Zero-area
// triangles are dropped up front (no ray can hit them; the parser warns).
//
// Speed: brute force over every primitive for every ray (no acceleration
// structure that could itself be wrong), rows spread over threads (base/parallel.h).
#include "reference/reference_renderer.h"
#include "reference/reference_geometry.h"
#include "reference/reference_story.h"

#include "base/parallel.h"
#include "scene/scene_triangles.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using glm::dvec3;

namespace {
using namespace reference_geometry;

// Phong with hard shadows, exactly as docs/model.md's "Shading". With story, each light's
// part is recorded there too (the pixel story).
dvec3 shadeLocal(const World& world, const SurfacePoint& p, dvec3 view, int id,
                 std::vector<StoryLightRecord>* story = nullptr) {
    const Material& m = p.material;
    dvec3 local = world.scene.ambient; // k_a = 1, once per point
    for (const Light& light : world.scene.lights) {
        StoryLightRecord entry; // "behind" until found otherwise
        auto record = [&] {
            if (story) story->push_back(entry);
        };
        const dvec3 toLight = light.position - p.position;
        const double distance = glm::length(toLight);
        if (distance == 0) {
            record(); // a light on the surface itself has no direction; it adds nothing
            continue;
        }
        const dvec3 l = toLight / distance;
        const double nl = glm::dot(p.normal, l);
        entry.nDotL = nl;
        if (nl <= 0) {
            record();
            continue;
        }
        // The shadow ray: from the point towards the light, or with the terminator fix from
        // the shifted point, its direction and length taken from there, as the kernel does.
        Ray shadow{p.position, l, id};
        double reach = distance;
        if (world.shiftShadowOrigin) {
            const dvec3 fromShifted = light.position - p.shadowPoint;
            reach = glm::length(fromShifted);
            shadow = Ray{p.shadowPoint, fromShifted / reach, id};
        }
        if (occluded(world, shadow, reach)) {
            if (story) { // what blocks it: the nearest surface before the light
                Hit blocker;
                blocker.t = reach;
                closestHit(world, shadow, blocker);
                entry.result = "blocked";
                entry.blocker = storyPrimitive(world, blocker.id);
            }
            record();
            continue;
        }
        const dvec3 r = 2.0 * nl * p.normal - l;
        const double rv = glm::dot(r, view);
        // pow(x, 0) is 1 for x > 0, so shininess 0 gives a full-strength highlight.
        const double highlight = rv > 0 ? std::pow(rv, m.shininess) : 0.0;
        const dvec3 share = light.color * (m.diffuse * nl + m.specular * highlight);
        local += share;
        entry.result = "lit";
        entry.contribution = share;
        record();
    }
    return local;
}

struct Bounce {
    dvec3 local;
    dvec3 ks;
};

// The pixel story's throughput and colour after each bounce, forwards: bounce k enters
// the sample with the product of the ks before it. (The reference's own colour is folded
// from the innermost bounce out; both are the model's recursion.)
void storyColors(ReferenceStory& story) {
    dvec3 throughput(1.0), color(0.0);
    for (StoryBounceRecord& b : story.bounces) {
        b.throughput = throughput;
        const bool reflects = std::string(b.next) == "reflect";
        color += throughput * (reflects ? 1.0 - b.mirrorWeight : dvec3(1.0)) * b.local;
        throughput *= b.mirrorWeight;
        b.color = color;
    }
}

// How a path ends: in the background, or on a surface that shades only locally (no
// mirror, or the depth reached).
struct PathEnd {
    bool missed = false;
    dvec3 local{0.0};
};

// Follows a ray through at most settings.depth reflections: each bounce that reflects goes
// into path, and the bounce where the path stops is returned. With story, each bounce is
// recorded there too (the pixel story).
PathEnd followPath(const World& world, const ReferenceSettings& settings, Ray ray,
                   std::vector<Bounce>& path, ReferenceStory* story) {
    path.clear();
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        StoryBounceRecord* record = nullptr;
        if (story) {
            record = &story->bounces.emplace_back();
            record->origin = ray.origin;
            record->direction = ray.dir;
        }
        if (!closestHit(world, ray, hit)) {
            if (record) record->local = settings.background; // next: "miss"
            return {true, dvec3(0.0)};
        }
        const SurfacePoint p = surfaceAt(world, ray, hit);
        const dvec3 view = -glm::normalize(ray.dir);
        const dvec3 local = shadeLocal(world, p, view, hit.id, record ? &record->lights : nullptr);
        const dvec3 ks = p.mirrorWeight;
        if (record) {
            record->hit = storyPrimitive(world, hit.id);
            record->t = hit.t;
            if (hit.id >= world.sphereCount) record->barycentric = hit.weights;
            record->normal = p.normal;
            record->material = p.material;
            record->mirrorWeight = p.mirrorWeight;
            record->local = local;
            record->next = ks == dvec3(0.0)           ? "no-mirror"
                           : bounce >= settings.depth ? "depth"
                                                      : "reflect";
        }
        if (bounce >= settings.depth || ks == dvec3(0.0)) return {false, local};
        path.push_back({local, ks});
        const dvec3 reflected = ray.dir - 2.0 * glm::dot(ray.dir, p.normal) * p.normal;
        ray = Ray{p.position, glm::normalize(reflected), hit.id};
    }
}

// colour(ray, bounce) of docs/model.md's "Reflection": the path is followed forwards, then
// (1 - ks) * local + ks * colour(next) is evaluated from the innermost bounce out,
// the same arithmetic as the recursion without a stack frame per bounce.
dvec3 traceRay(const World& world, const ReferenceSettings& settings, Ray ray,
               std::vector<Bounce>& path, ReferenceStory* story = nullptr) {
    const PathEnd end = followPath(world, settings, ray, path, story);
    dvec3 color = end.missed ? settings.background : end.local;
    for (std::size_t k = path.size(); k-- > 0;)
        color = (1.0 - path[k].ks) * path[k].local + path[k].ks * color;
    return color;
}

// The path's terms for every depth up to the one traced (RayTerms): a depth d below the
// bounces the path reflected at ends on bounce d's surface, which then shades only locally.
RayTerms rayTerms(const World& world, const ReferenceSettings& settings, Ray ray,
                  std::vector<Bounce>& path) {
    const PathEnd end = followPath(world, settings, ray, path, nullptr);
    RayTerms terms;
    for (int depth = 0; depth <= settings.depth; ++depth) {
        const std::size_t reflections = std::min(std::size_t(depth), path.size());
        const bool last = reflections == path.size();
        dvec3 own = last ? end.local : path[reflections].local;
        dvec3 throughBackground(last && end.missed ? 1.0 : 0.0);
        for (std::size_t k = reflections; k-- > 0;) {
            own = (1.0 - path[k].ks) * path[k].local + path[k].ks * own;
            throughBackground *= path[k].ks;
        }
        terms.own.push_back(own);
        terms.throughBackground.push_back(throughBackground);
    }
    return terms;
}

double clampChannel(double c) {
    return c > 0 ? std::min(c, 1.0) : 0.0; // also sends NaN to 0
}

dvec3 pixelColor(const World& world, const ReferenceSettings& settings, const Camera& camera, int i,
                 int j, std::vector<Bounce>& path) {
    dvec3 sum(0.0);
    for (glm::dvec2 sample : camera.samples) {
        const dvec3 c =
            traceRay(world, settings, Ray{camera.eye, eyeDirection(camera, i, j, sample)}, path);
        sum += settings.clampSamples
                   ? dvec3(clampChannel(c.x), clampChannel(c.y), clampChannel(c.z))
                   : c;
    }
    return sum / double(camera.samples.size());
}

} // namespace

int quantizeChannel(double c, bool truncate) {
    const double scaled = clampChannel(c) * 255.0;
    return int(std::floor(truncate ? scaled : scaled + 0.5));
}

glm::dvec3 traceEyeRay(const Scene& scene, const ReferenceSettings& settings, glm::dvec3 dir) {
    const World world = prepareWorld(scene, settings.terminatorFix);
    std::vector<Bounce> path;
    return traceRay(world, settings, Ray{dvec3(0.0), dir}, path);
}

ReferenceStory referencePixelStory(const Scene& scene, const ReferenceSettings& settings, int i,
                                   int j) {
    const Camera camera = makeCamera(settings);
    const World world = prepareWorld(scene, settings.terminatorFix);
    std::vector<Bounce> path;
    ReferenceStory story;
    story.sampleOffset = camera.samples.front();
    story.sampleColor =
        traceRay(world, settings,
                 Ray{camera.eye, eyeDirection(camera, i, j, camera.samples.front())}, path, &story);
    storyColors(story);
    story.pixelColor = pixelColor(world, settings, camera, i, j, path);
    return story;
}

std::vector<EyeRayFacts> referenceEyeRays(const Scene& scene, const ReferenceSettings& settings,
                                          const std::vector<glm::ivec2>& pixels, int threads) {
    const Camera camera = makeCamera(settings);
    const World world = prepareWorld(scene, settings.terminatorFix);
    std::vector<EyeRayFacts> facts(pixels.size());
    forEachEyeRay(camera, pixels, threads, [&]() -> EyeRayBody {
        return [&](std::size_t k, const Ray& ray) {
            Hit hit;
            if (!closestHit(world, ray, hit)) return;
            const SurfacePoint p = surfaceAt(world, ray, hit);
            EyeRayFacts& out = facts[k];
            out.hit = storyPrimitive(world, hit.id);
            out.onMirror = settings.depth > 0 && p.mirrorWeight != dvec3(0.0);
            for (const Light& light : scene.lights) {
                const dvec3 toLight = light.position - p.position;
                const double distance = glm::length(toLight);
                if (distance == 0 || glm::dot(p.normal, toLight) <= 0) continue;
                if (occluded(world, Ray{p.position, toLight / distance, hit.id}, distance)) {
                    out.inShadow = true;
                    break;
                }
            }
        };
    });
    return facts;
}

glm::dvec3 tracePixel(const Scene& scene, const ReferenceSettings& settings, int i, int j) {
    const Camera camera = makeCamera(settings);
    const World world = prepareWorld(scene, settings.terminatorFix);
    std::vector<Bounce> path;
    return pixelColor(world, settings, camera, i, j, path);
}

std::vector<RayTerms> referenceTerms(const Scene& scene, const ReferenceSettings& settings,
                                     const std::vector<glm::ivec2>& pixels, int threads) {
    const Camera camera = makeCamera(settings);
    if (settings.spp != 1)
        throw std::invalid_argument("the terms of a pixel need one sample per pixel");
    const World world = prepareWorld(scene, settings.terminatorFix);
    std::vector<RayTerms> terms(pixels.size());
    forEachEyeRay(camera, pixels, threads, [&]() -> EyeRayBody {
        return [&, path = std::vector<Bounce>()](std::size_t k, const Ray& ray) mutable {
            terms[k] = rayTerms(world, settings, ray, path);
        };
    });
    return terms;
}

namespace {

// Calls store(i, j, colour) for every pixel, with the rows shared among threads (0: the
// host's policy, base/parallel.h); store writes disjoint pixels, so it needs no lock.
template <typename Store>
void renderPixels(const Scene& scene, const ReferenceSettings& settings, int threads,
                  const Store& store) {
    const Camera camera = makeCamera(settings);
    const World world = prepareWorld(scene, settings.terminatorFix);
    parallelFor(
        std::size_t(settings.height),
        [&](std::size_t row) {
            const int j = int(row);
            std::vector<Bounce> path;
            for (int i = 0; i < settings.width; ++i)
                store(i, j, pixelColor(world, settings, camera, i, j, path));
        },
        unsigned(std::max(threads, 0)));
}

} // namespace

Image8 renderReference(const Scene& scene, const ReferenceSettings& settings, int threads) {
    makeCamera(settings); // checks the settings before anything is allocated
    Image8 image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    renderPixels(scene, settings, threads, [&](int i, int j, const dvec3& c) {
        std::uint8_t* out =
            &image.rgba[(std::size_t(j) * std::size_t(image.width) + std::size_t(i)) * 4];
        out[0] = std::uint8_t(quantizeChannel(c.x, settings.truncate));
        out[1] = std::uint8_t(quantizeChannel(c.y, settings.truncate));
        out[2] = std::uint8_t(quantizeChannel(c.z, settings.truncate));
        out[3] = 255;
    });
    return image;
}

ImageF renderReferenceFloat(const Scene& scene, const ReferenceSettings& settings, int threads) {
    makeCamera(settings);
    ImageF image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    renderPixels(scene, settings, threads, [&](int i, int j, const dvec3& c) {
        float* out = &image.rgb[(std::size_t(j) * std::size_t(image.width) + std::size_t(i)) * 3];
        out[0] = float(c.x);
        out[1] = float(c.y);
        out[2] = float(c.z);
    });
    return image;
}
