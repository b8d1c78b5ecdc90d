#include "compare/student_model.h"

#include "reference/reference_geometry.h"
#include "scene/scene_triangles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace reference_geometry;

namespace {

// The surface as a tracer with mistake sees it: the reference's point, with the normal or
// the material of a triangle taken the wrong way when that is the mistake.
SurfacePoint studentSurface(const World& world, const Ray& ray, const Hit& hit, Mistake mistake) {
    SurfacePoint p = surfaceAt(world, ray, hit);
    if (hit.id < world.sphereCount) {
        // A tracer that takes the far root seldom turns the normal to face the ray either.
        if (mistake == Mistake::SphereFarRoot)
            p.normal = glm::normalize(p.position - world.scene.spheres[std::size_t(hit.id)].center);
        return p;
    }
    if (mistake != Mistake::FlatNormals && mistake != Mistake::MaterialsNotInterpolated &&
        mistake != Mistake::NormalsNotNormalised)
        return p;
    const Triangle tri = triangleAt(world.scene, std::size_t(hit.id - world.sphereCount));
    const Vertex* v = tri.vertices;
    if (mistake == Mistake::NormalsNotNormalised) {
        const dvec3 w = hit.weights;
        const dvec3 n = w.x * v[0].normal + w.y * v[1].normal + w.z * v[2].normal;
        if (n != dvec3(0.0)) p.normal = glm::dot(n, ray.dir) > 0 ? -n : n;
    } else if (mistake == Mistake::FlatNormals) {
        p.normal = glm::normalize(
            glm::cross(v[1].position - v[0].position, v[2].position - v[0].position));
        if (glm::dot(p.normal, ray.dir) > 0) p.normal = -p.normal;
    } else {
        p.material = v[0].material;
        p.mirrorWeight = mirrorWeight(v[0].material);
    }
    return p;
}

HitRules hitRules(Mistake mistake) {
    HitRules rules;
    rules.cullBackFaces = mistake == Mistake::BackFacesCulled;
    rules.farSphereRoot = mistake == Mistake::SphereFarRoot;
    return rules;
}

// Phong with hard shadows as docs/model.md's "Shading" has it, but for mistake.
dvec3 studentLocal(const World& world, const SurfacePoint& p, dvec3 view, int id, Mistake mistake) {
    const Material& m = p.material;
    const Scene& scene = world.scene;
    dvec3 local = scene.ambient;
    if (mistake == Mistake::AmbientPerLight)
        local = scene.ambient * double(std::max<std::size_t>(scene.lights.size(), 1));
    for (const Light& light : scene.lights) {
        const dvec3 toLight = light.position - p.position;
        const double distance = glm::length(toLight);
        if (distance == 0) continue;
        const dvec3 l = toLight / distance;
        const double nl = glm::dot(p.normal, l);
        if (nl <= 0) {
            if (mistake == Mistake::UnclampedNDotL) local += light.color * m.diffuse * nl;
            continue;
        }
        // Shadow acne: the shadow ray does not skip the surface it leaves, so rounding can
        // find it again a hair's breadth away.
        const Ray shadowRay{p.position, l, mistake == Mistake::ShadowAcne ? fromEye : id};
        const bool shadowed =
            mistake != Mistake::NoShadows &&
            occluded(world, shadowRay,
                     mistake == Mistake::ShadowIgnoresDistance ? infinity : distance,
                     hitRules(mistake));
        double highlight = 0;
        if (mistake == Mistake::BlinnPhong) {
            const double nh = glm::dot(p.normal, glm::normalize(l + view));
            highlight = nh > 0 ? std::pow(nh, m.shininess) : 0.0;
        } else {
            const double rv = glm::dot(2.0 * nl * p.normal - l, view);
            highlight =
                rv > 0 || mistake == Mistake::UnclampedRDotV ? std::pow(rv, m.shininess) : 0.0;
        }
        if (shadowed) {
            if (mistake == Mistake::SpecularInShadow)
                local += light.color * (m.specular * highlight);
            continue;
        }
        local += light.color * (m.diffuse * nl + m.specular * highlight);
    }
    return local;
}

struct Bounce {
    dvec3 local, ks;
};

// The recursion of docs/model.md's "Reflection", folded from the innermost bounce out as
// the reference does, with the local colours of studentLocal.
dvec3 studentRay(const World& world, const ReferenceSettings& settings, Ray ray, Mistake mistake,
                 std::vector<Bounce>& path) {
    path.clear();
    dvec3 color = settings.background;
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        if (!closestHit(world, ray, hit, hitRules(mistake))) {
            color = settings.background;
            break;
        }
        const SurfacePoint p = studentSurface(world, ray, hit, mistake);
        dvec3 local = studentLocal(world, p, -glm::normalize(ray.dir), hit.id, mistake);
        if (mistake == Mistake::ColourClampedPerBounce) local = glm::clamp(local, 0.0, 1.0);
        const dvec3 ks = p.mirrorWeight;
        if (bounce >= settings.depth || ks == dvec3(0.0)) {
            color = local;
            break;
        }
        path.push_back({local, ks});
        const dvec3 reflected = ray.dir - 2.0 * glm::dot(ray.dir, p.normal) * p.normal;
        ray = Ray{p.position, glm::normalize(reflected), hit.id};
    }
    for (std::size_t k = path.size(); k-- > 0;) {
        const dvec3 keep = mistake == Mistake::ReflectionAdded ? dvec3(1.0) : 1.0 - path[k].ks;
        color = keep * path[k].local + path[k].ks * color;
    }
    return color;
}

// A colour as a tracer that writes (unsigned char)(c * 255 + 0.5) without a clamp shows it:
// a byte over 255 keeps its low 8 bits (1.1 becomes 25/255).
dvec3 wrappedBytes(dvec3 colour) {
    for (int c = 0; c < 3; ++c) {
        const double byte = std::floor(colour[c] * 255.0 + 0.5);
        if (byte > 255.0) colour[c] = std::fmod(byte, 256.0) / 255.0;
    }
    return colour;
}

} // namespace

const std::vector<MistakeDescription>& mistakeCatalogue() {
    static const std::vector<MistakeDescription> catalogue = {
        {Mistake::NoShadows, "no-shadows", "no shadows: shadow rays are never cast"},
        {Mistake::ShadowIgnoresDistance, "shadow-ignores-distance",
         "shadows ignore the light's distance: a surface beyond the light still blocks it"},
        {Mistake::SpecularInShadow, "specular-in-shadow", "the highlight is added in shadow too"},
        {Mistake::BlinnPhong, "blinn-phong",
         "Blinn-Phong highlights, (N.H)^n, instead of Phong's (R.V)^n"},
        {Mistake::UnclampedNDotL, "unclamped-n-dot-l",
         "N.L not clamped at zero: lights behind a surface darken it"},
        {Mistake::AmbientPerLight, "ambient-per-light",
         "the ambient term is added once per light, not once"},
        {Mistake::FlatNormals, "flat-normals",
         "triangles shaded with their flat normal, not the interpolated vertex normals"},
        {Mistake::MaterialsNotInterpolated, "materials-not-interpolated",
         "a triangle's material taken from its first corner, not interpolated"},
        {Mistake::UnclampedRDotV, "unclamped-r-dot-v",
         "R.V not clamped at zero: highlights where the reflection points away"},
        {Mistake::NormalsNotNormalised, "normals-not-normalised",
         "interpolated normals not normalised: triangles darker between their corners"},
        {Mistake::ShadowAcne, "shadow-acne",
         "shadow acne: shadow rays start on the surface and hit it again"},
        {Mistake::ReflectionAdded, "reflection-added",
         "the reflection added to the local colour instead of blended with weight ks"},
        {Mistake::ColourClampedPerBounce, "colour-clamped-per-bounce",
         "each bounce's colour clamped before the reflections are blended"},
        {Mistake::BackFacesCulled, "back-faces-culled",
         "back faces culled: triangles seen against their winding are missed"},
        {Mistake::SphereFarRoot, "sphere-far-root",
         "the far root of the sphere taken: its back is seen through its front"},
        {Mistake::WrongAspectRatio, "wrong-aspect-ratio",
         "a wrong aspect ratio: the horizontal angle taken equal to the vertical one"},
        {Mistake::ColourNotClamped, "colour-not-clamped",
         "colours over 1 not clamped: their bytes wrap around, so the brightest spots turn dark"},
    };
    return catalogue;
}

std::vector<glm::dvec3> studentColours(const Scene& scene, const ReferenceSettings& settings,
                                       Mistake mistake, const std::vector<glm::ivec2>& pixels,
                                       int threads) {
    Camera camera = makeCamera(settings);
    if (mistake == Mistake::WrongAspectRatio) camera.tanHalfX = camera.tanHalfY;
    if (settings.spp != 1) throw std::invalid_argument("the student model traces one sample");
    const World world = prepareWorld(scene);
    std::vector<glm::dvec3> colours(pixels.size());
    forEachEyeRay(camera, pixels, threads, [&]() -> EyeRayBody {
        return [&, path = std::vector<Bounce>()](std::size_t k, const Ray& ray) mutable {
            colours[k] = studentRay(world, settings, ray, mistake, path);
            if (mistake == Mistake::ColourNotClamped) colours[k] = wrappedBytes(colours[k]);
        };
    });
    return colours;
}
