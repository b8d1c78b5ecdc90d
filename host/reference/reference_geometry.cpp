#include "reference/reference_geometry.h"

#include "base/parallel.h"
#include "scene/scene_triangles.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace reference_geometry {

World prepareWorld(const Scene& scene, bool shiftShadowOrigin) {
    World world{scene, int(scene.spheres.size()), {}, shiftShadowOrigin};
    world.triangles.reserve(triangleCount(scene));
    int k = 0; // the triangle's number (scene_triangles.h)
    forEachTriangle(scene, [&](const Triangle& triangle) {
        const Vertex* v = triangle.vertices;
        RefTriangle t{v[0].position, v[1].position, v[2].position, {}, world.sphereCount + k++};
        t.normal = glm::cross(t.b - t.a, t.c - t.a);
        if (t.normal != dvec3(0.0)) world.triangles.push_back(t);
    });
    return world;
}

namespace {

// The nearest t > 0 where the ray meets the sphere (with farRoot, the far root when it is
// ahead: a mistake's, see HitRules), or infinity. Geometric
// method: the closest approach of the ray's line to the centre is at tca, at a
// squared distance d2; the line is inside the sphere for tca +- thc.
double hitSphere(const Sphere& sphere, const Ray& ray, bool leavesIt, bool farRoot) {
    const double dd = glm::dot(ray.dir, ray.dir);
    if (leavesIt) {
        // The origin is on the sphere, so t = 0 is one root of
        // |O + tD - C|^2 = r^2; the other is where the two roots sum to.
        const double t = -2.0 * glm::dot(ray.origin - sphere.center, ray.dir) / dd;
        return t > 0 ? t : infinity;
    }
    const dvec3 toCenter = sphere.center - ray.origin;
    const double tca = glm::dot(toCenter, ray.dir) / dd;
    const double d2 = glm::dot(toCenter, toCenter) - tca * tca * dd;
    const double r2 = sphere.radius * sphere.radius;
    if (d2 > r2) return infinity;
    const double thc = std::sqrt((r2 - d2) / dd);
    if (tca - thc > 0 && !farRoot) return tca - thc;
    if (tca + thc > 0) return tca + thc;
    return infinity;
}

// Signed-volume test: with the vertices relative to the ray origin, the ray passes
// inside the triangle iff the three triple products [D, a, b], [D, b, c],
// [D, c, a] have no two of opposite sign. Each is the (unnormalised) barycentric
// weight of the vertex opposite that edge. Both sides of the triangle count.
// Only hits with 0 < t < tMax are reported; the cheap plane distance is checked
// first so that most triangles cost no edge test (the result is the same).
bool hitTriangle(const RefTriangle& tri, const Ray& ray, double tMax, double& t, dvec3& weights,
                 bool cullBackFaces) {
    const double facing = glm::dot(tri.normal, ray.dir);
    if (facing == 0)
        return false; // the ray runs in the triangle's plane: it sees an edge-on sliver
    if (cullBackFaces && facing > 0) return false;
    const dvec3 a = tri.a - ray.origin;
    t = glm::dot(tri.normal, a) / facing;
    if (!(t > 0 && t < tMax)) return false;
    const dvec3 b = tri.b - ray.origin, c = tri.c - ray.origin;
    const double wc = glm::dot(ray.dir, glm::cross(a, b));
    const double wa = glm::dot(ray.dir, glm::cross(b, c));
    if ((wa < 0 && wc > 0) || (wa > 0 && wc < 0)) return false;
    const double wb = glm::dot(ray.dir, glm::cross(c, a));
    if ((wb < 0 && (wa > 0 || wc > 0)) || (wb > 0 && (wa < 0 || wc < 0))) return false;
    const double sum = wa + wb + wc; // mathematically dot(D, normal), non-zero here
    if (sum == 0) return false;      // only if rounding flushed all three: nothing to interpolate
    weights = dvec3(wa, wb, wc) / sum;
    return true;
}

// The texture's colour at uv (docs/models.md): u across from the left edge, v up from the
// bottom, each wrapped to [0, 1); bilinear between the four nearest texel centres, which
// lie at (i + 0.5) / size, wrapping at the edges; each texel's rgb / 255.
dvec3 textureColor(const Image8& image, glm::dvec2 uv) {
    const double u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
    const double x = u * image.width - 0.5, y = (1.0 - v) * image.height - 0.5;
    const double left = std::floor(x), top = std::floor(y);
    const double fx = x - left, fy = y - top;
    auto wrap = [](double i, int size) { return (int(i) % size + size) % size; };
    const int x0 = wrap(left, image.width), x1 = (x0 + 1) % image.width;
    const int y0 = wrap(top, image.height), y1 = (y0 + 1) % image.height;
    auto texel = [&](int i, int j) {
        const std::uint8_t* p = &image.rgba[(std::size_t(j) * std::size_t(image.width) + i) * 4];
        return dvec3(p[0], p[1], p[2]) / 255.0;
    };
    const dvec3 upper = texel(x0, y0) * (1 - fx) + texel(x1, y0) * fx;
    const dvec3 lower = texel(x0, y1) * (1 - fx) + texel(x1, y1) * fx;
    return upper * (1 - fy) + lower * fy;
}

} // namespace

bool closestHit(const World& world, const Ray& ray, Hit& hit, const HitRules& rules) {
    for (int s = 0; s < world.sphereCount; ++s) {
        const double t =
            hitSphere(world.scene.spheres[std::size_t(s)], ray, ray.from == s, rules.farSphereRoot);
        if (t < hit.t) {
            hit.t = t;
            hit.id = s;
        }
    }
    double t = 0;
    dvec3 weights;
    for (const RefTriangle& tri : world.triangles) {
        if (tri.id != ray.from && hitTriangle(tri, ray, hit.t, t, weights, rules.cullBackFaces)) {
            hit.t = t;
            hit.id = tri.id;
            hit.weights = weights;
        }
    }
    return hit.id != fromEye;
}

bool occluded(const World& world, const Ray& ray, double maxT, const HitRules& rules) {
    for (int s = 0; s < world.sphereCount; ++s)
        if (hitSphere(world.scene.spheres[std::size_t(s)], ray, ray.from == s,
                      rules.farSphereRoot) < maxT)
            return true;
    double t = 0;
    dvec3 weights;
    for (const RefTriangle& tri : world.triangles)
        if (tri.id != ray.from && hitTriangle(tri, ray, maxT, t, weights, rules.cullBackFaces))
            return true;
    return false;
}

SurfacePoint surfaceAt(const World& world, const Ray& ray, const Hit& hit) {
    SurfacePoint p;
    p.position = ray.origin + hit.t * ray.dir;
    if (hit.id < world.sphereCount) {
        const Sphere& sphere = world.scene.spheres[std::size_t(hit.id)];
        p.normal = (p.position - sphere.center) / sphere.radius;
        p.material = sphere.material;
        p.mirrorWeight = mirrorWeight(sphere.material);
        p.shadowPoint = p.position;
    } else {
        const Triangle tri = triangleAt(world.scene, std::size_t(hit.id - world.sphereCount));
        const Vertex* v = tri.vertices;
        const dvec3 w = hit.weights;
        const dvec3 n = w.x * v[0].normal + w.y * v[1].normal + w.z * v[2].normal;
        const double length = glm::length(n);
        if (length > 0) {
            p.normal = n / length;
        } else {
            const dvec3 a = v[0].position, b = v[1].position, c = v[2].position;
            p.normal = glm::normalize(glm::cross(b - a, c - a));
        }
        const Material &m0 = v[0].material, &m1 = v[1].material, &m2 = v[2].material;
        p.material.diffuse = w.x * m0.diffuse + w.y * m1.diffuse + w.z * m2.diffuse;
        p.material.specular = w.x * m0.specular + w.y * m1.specular + w.z * m2.specular;
        p.material.shininess = w.x * m0.shininess + w.y * m1.shininess + w.z * m2.shininess;
        p.mirrorWeight = w.x * mirrorWeight(m0) + w.y * mirrorWeight(m1) + w.z * mirrorWeight(m2);
        // A textured material's kd multiplies the texture's colour.
        if (const auto texturing =
                triangleTexturingAt(world.scene, std::size_t(hit.id - world.sphereCount))) {
            const glm::dvec2* uv = texturing->texcoords;
            p.material.diffuse *= textureColor(world.scene.textures[texturing->texture].image,
                                               w.x * uv[0] + w.y * uv[1] + w.z * uv[2]);
        }
        p.shadowPoint = p.position;
        if (world.shiftShadowOrigin) {
            const double facing = glm::dot(p.normal, ray.dir) > 0 ? -1.0 : 1.0;
            for (int i = 0; i < 3; ++i) {
                const double size = glm::length(v[i].normal);
                const dvec3 ni = facing * (size > 0 ? v[i].normal / size : p.normal);
                p.shadowPoint -=
                    w[i] * std::min(0.0, glm::dot(p.position - v[i].position, ni)) * ni;
            }
        }
    }
    if (glm::dot(p.normal, ray.dir) > 0) p.normal = -p.normal;
    return p;
}

StoryPrimitive storyPrimitive(const World& world, int id) {
    if (id == fromEye) return {};
    if (id < world.sphereCount) return {"sphere", id, world.scene.spheres[std::size_t(id)].line};
    const int index = id - world.sphereCount;
    return {"triangle", index, triangleAt(world.scene, std::size_t(index)).line};
}

Camera makeCamera(const ReferenceSettings& settings) {
    if (settings.width <= 0 || settings.height <= 0)
        throw std::invalid_argument("image size must be positive, got " +
                                    std::to_string(settings.width) + "x" +
                                    std::to_string(settings.height));
    if (settings.spp <= 0) throw std::invalid_argument("samples per pixel must be positive");
    if (settings.depth < 0) throw std::invalid_argument("depth must not be negative");
    if (!(settings.fovDegrees > 0 && settings.fovDegrees < 180))
        throw std::invalid_argument("field of view must be between 0 and 180 degrees");
    Camera camera;
    const dvec3 view = settings.cameraTarget - settings.cameraPosition;
    if (glm::length(view) == 0) throw std::invalid_argument("camera target equals camera position");
    camera.forward = glm::normalize(view);
    const dvec3 side = glm::cross(camera.forward, settings.cameraUp);
    if (glm::length(side) < 1e-9 * glm::length(settings.cameraUp) ||
        glm::length(settings.cameraUp) == 0)
        throw std::invalid_argument("camera up is zero or parallel to the view direction");
    camera.right = glm::normalize(side);
    camera.up = glm::cross(camera.right, camera.forward);
    camera.eye = settings.cameraPosition;
    camera.width = settings.width;
    camera.height = settings.height;
    camera.tanHalfY = std::tan(settings.fovDegrees * (std::numbers::pi / 360.0));
    camera.tanHalfX = camera.width / camera.height * camera.tanHalfY;
    int rows = int(std::sqrt(double(settings.spp)));
    while (settings.spp % rows != 0)
        --rows;
    const int cols = settings.spp / rows;
    const double corner = settings.cornerRays ? 0.5 : 0.0;
    for (int k = 0; k < settings.spp; ++k)
        camera.samples.emplace_back((k % cols + 0.5) / cols - corner,
                                    (k / cols + 0.5) / rows - corner);
    return camera;
}

dvec3 eyeDirection(const Camera& camera, int i, int j, glm::dvec2 sample) {
    const double x = (2.0 * (i + sample.x) / camera.width - 1.0) * camera.tanHalfX;
    const double y = (1.0 - 2.0 * (j + sample.y) / camera.height) * camera.tanHalfY;
    return glm::normalize(x * camera.right + y * camera.up + camera.forward);
}

void forEachEyeRay(const Camera& camera, const std::vector<glm::ivec2>& pixels, int threads,
                   const std::function<EyeRayBody()>& makeBody) {
    constexpr std::size_t kChunk = 256; // pixels a task: enough to outweigh handing it out
    parallelForPerThread(
        (pixels.size() + kChunk - 1) / kChunk,
        [&]() -> IndexBody {
            return [&, body = makeBody()](std::size_t chunk) {
                const std::size_t end = std::min(pixels.size(), (chunk + 1) * kChunk);
                for (std::size_t k = chunk * kChunk; k < end; ++k)
                    body(k, Ray{camera.eye, eyeDirection(camera, pixels[k].x, pixels[k].y,
                                                         camera.samples.front())});
            };
        },
        unsigned(std::max(threads, 0)));
}

} // namespace reference_geometry
