// The reference's geometry: its own ray-sphere and ray-triangle tests (the methods and their
// accuracy: reference_renderer.cpp's opening comment), the nearest hit and shadow
// queries, the surface point a hit gives, and the camera's eye rays. The reference's shading
// (reference_renderer.cpp) is built on it; so can be other shading, such as a model of
// another tracer's, without touching the reference's own.
#pragma once

#include "reference/reference_renderer.h"
#include "reference/reference_story.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace reference_geometry {

using glm::dvec3;

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr int fromEye = -1; // the primitive id of a ray that leaves no surface

// Primitive ids: spheres 0..S-1, then triangles S..S+T-1 in file order. Equal
// distances go to the lower id (the first in the file, spheres before triangles).
struct Ray {
    dvec3 origin;
    dvec3 dir;
    int from = fromEye;
};

struct RefTriangle {
    dvec3 a, b, c;
    dvec3 normal; // cross(b - a, c - a): the plane, for t, and the fallback normal
    int id;       // primitive id; triangleAt(scene, id - sphereCount) holds the rest
};

struct World {
    const Scene& scene;
    int sphereCount = 0;
    std::vector<RefTriangle> triangles; // those with non-zero area only
    // Shadow rays leave from SurfacePoint::shadowPoint, Hanika's shifted point (--terminator).
    bool shiftShadowOrigin = false;
};

struct Hit {
    double t = infinity;
    int id = fromEye;
    dvec3 weights{0.0}; // barycentric weights of the triangle's vertices
};

struct SurfacePoint {
    dvec3 position;
    dvec3 normal; // unit, facing the incoming ray
    Material material;
    // The mirror weight: ks times the mirror share; on a triangle each corner's, interpolated.
    dvec3 mirrorWeight{0.0};
    // Where shadow rays leave from: position, or with World::shiftShadowOrigin on a triangle,
    // position - sum w_i min(0, dot(position - v_i, n_i)) n_i over its vertices v_i with their
    // unit normals n_i turned to the side the shading normal faces (Hanika's shadow
    // terminator fix; the kernel's shiftedShadowPoint).
    dvec3 shadowPoint{0.0};
};

struct Camera {
    double width, height, tanHalfX, tanHalfY;
    // World-space axes: camera-space x, y and the view direction (camera -z). The default
    // camera's are the unit axes, which keeps its rays exactly (x, y, -1).
    dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
    dvec3 eye{0.0};
    std::vector<glm::dvec2> samples; // offsets (u, v) inside a pixel
};

// How a ray meets surfaces: the reference's way by default. The others are mistakes that
// another tracer might make (the student model's, student_model.h); the reference itself
// never sets them.
struct HitRules {
    bool cullBackFaces = false; // triangles seen from behind their winding are missed
    bool farSphereRoot = false; // a sphere is met at its far root, not its near one
};

// The scene's primitives as the reference intersects them: every sphere, and the triangles
// of non-zero area (no ray can hit the others).
World prepareWorld(const Scene& scene, bool shiftShadowOrigin = false);

// The nearest surface the ray meets before hit.t (hit as it comes: infinity, or a bound),
// never the primitive it leaves; false when there is none.
bool closestHit(const World& world, const Ray& ray, Hit& hit, const HitRules& rules = {});

// Whether any surface lies strictly between the ray's origin and origin + maxT * dir.
bool occluded(const World& world, const Ray& ray, double maxT, const HitRules& rules = {});

// The point a hit gives: its position, its normal (interpolated for a triangle, facing the
// incoming ray) and its material (interpolated for a triangle).
SurfacePoint surfaceAt(const World& world, const Ray& ray, const Hit& hit);

// Primitive id as the pixel story names it: kind, index among its kind, line in the file.
StoryPrimitive storyPrimitive(const World& world, int id);

// spp samples on the most square rows x cols grid with rows * cols == spp, at the
// cell centres: n*n gives a regular grid, 1 the pixel centre as the model requires.
// Throws std::invalid_argument for settings renderReference refuses.
Camera makeCamera(const ReferenceSettings& settings);

// the default camera: x = (2 (i + u) / W - 1) * aspect * tan(fov/2),
// y = (1 - 2 (j + v) / H) * tan(fov/2), direction normalize(x, y, -1) in camera space,
// turned into the world by the camera's axes.
dvec3 eyeDirection(const Camera& camera, int i, int j, glm::dvec2 sample);

// Calls a body for sample 0's eye ray of each pixel of pixels, body(k, ray) for pixel k: the
// pixels shared among threads (0: the host's policy) in chunks of 256, each thread with a
// body of its own from makeBody (its scratch buffers live there). Bodies write disjoint
// results, so they need no lock.
using EyeRayBody = std::function<void(std::size_t, const Ray&)>;
void forEachEyeRay(const Camera& camera, const std::vector<glm::ivec2>& pixels, int threads,
                   const std::function<EyeRayBody()>& makeBody);

} // namespace reference_geometry
