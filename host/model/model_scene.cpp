// SourceModel to Scene (model_scene.h). The arithmetic is the same, operation for operation and
// in the same order, as tools/obj_to_scene.py's in double precision, so that both write
// the same scene text; docs/models.md states the rules.
#include "model/model_scene.h"

#include "base/parallel.h"
#include "base/phase_progress.h"
#include "base/populated_memory.h"
#include "base/release.h"
#include "model/exact_vectors.h"
#include "model/far_vertices.h"
#include "model/model_fit.h"
#include "model/model_lights.h"
#include "model/model_mesh.h"
#include "scene/scene_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <tuple>
#include <utility>

namespace {

using namespace exact_vectors;

constexpr double kPi = 3.141592653589793;

// The up axis turned onto +y: swaps and negations only, so nothing is rounded.
glm::dvec3 turnUp(glm::dvec3 v, UpAxis up) {
    switch (up) {
    case UpAxis::PosX:
        return {-v.y, v.x, v.z};
    case UpAxis::NegX:
        return {v.y, -v.x, v.z};
    case UpAxis::PosY:
        return v;
    case UpAxis::NegY:
        return {v.x, -v.y, -v.z};
    case UpAxis::PosZ:
        return {v.x, v.z, -v.y};
    case UpAxis::NegZ:
        return {v.x, -v.z, v.y};
    }
    return v;
}

// Where the model goes: p -> turn(p - centre) * scale + offset, the turn being its view's.
struct Placement {
    glm::dvec3 centre{0.0};
    double scale = 1.0;
    glm::dvec3 offset{0.0};
    ViewTurn turn;
    glm::dvec3 low{0.0}, high{0.0}; // the box around the positions, unplaced (y up)
    bool inside = false;            // a room seen from inside (insidePlacement)

    glm::dvec3 place(glm::dvec3 p) const { return turn.apply(p - centre) * scale + offset; }
};

// The box around the positions (at least one), on all threads: min and max are exact in
// any order.
std::pair<glm::dvec3, glm::dvec3> boxOf(const std::vector<glm::dvec3>& positions) {
    using Box = std::pair<glm::dvec3, glm::dvec3>;
    return reduceRanges(
        positions.size(), 1 << 15,
        [&](IndexRange range) {
            Box box{positions[range.begin], positions[range.begin]};
            for (std::size_t i = range.begin; i < range.end; ++i) {
                box.first = glm::min(box.first, positions[i]);
                box.second = glm::max(box.second, positions[i]);
            }
            return box;
        },
        [](const Box& part, Box& into) {
            into.first = glm::min(into.first, part.first);
            into.second = glm::max(into.second, part.second);
        });
}

// Whether the model encloses its box's centre as a room does: a ray from the centre in each
// of the 26 directions towards the box's faces, edges and corners meets one of the
// triangles, and at least 20 of those nearest triangles turn their front (their winding's
// side) to the centre. A closed solid encloses its centre too, but its faces turn their
// backs to it. The same arithmetic as tools/obj_to_scene.py's.
bool enclosesItsCentre(const std::vector<glm::dvec3>& positions, const SourceTriangles& triangles,
                       const std::vector<TriangleFate>& fates, glm::dvec3 centre) {
    // The nearest triangle a ray meets, found on all threads: each range's first nearest,
    // the ranges combined in order, so that a tie goes to the first in file order as in one
    // pass.
    struct Nearest {
        double distance = std::numeric_limits<double>::infinity();
        bool front = false;
    };
    const std::vector<IndexRange> ranges = splitRange(triangles.size(), 16384);
    std::vector<Nearest> nearestIn(ranges.size());
    int facing = 0, away = 0;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
                if (i == 0 && j == 0 && k == 0) continue;
                const glm::dvec3 d = normalizedOrZero(glm::dvec3(i, j, k));
                parallelFor(ranges.size(), [&](std::size_t r) {
                    Nearest nearest;
                    for (std::size_t n = ranges[r].begin; n < ranges[r].end; ++n) {
                        if (fates[n] != TriangleFate::kept) continue;
                        const glm::uvec3& t = triangles.positions(n);
                        const glm::dvec3 a = positions[t[0]], e1 = positions[t[1]] - a,
                                         e2 = positions[t[2]] - a;
                        const glm::dvec3 p = glm::cross(d, e2);
                        const double det = dot(e1, p);
                        if (det == 0.0) continue;
                        const glm::dvec3 s = centre - a;
                        const double u = dot(s, p) / det;
                        if (u < 0.0 || u > 1.0) continue;
                        const glm::dvec3 q = glm::cross(s, e1);
                        const double v = dot(d, q) / det;
                        if (v < 0.0 || u + v > 1.0) continue;
                        const double distance = dot(e2, q) / det;
                        if (distance > 0.0 && distance < nearest.distance)
                            nearest = {distance, dot(glm::cross(e1, e2), d) < 0.0};
                    }
                    nearestIn[r] = nearest;
                });
                Nearest nearest;
                for (const Nearest& in : nearestIn)
                    if (in.distance < nearest.distance) nearest = in;
                if (nearest.distance == std::numeric_limits<double>::infinity())
                    return false; // open
                (nearest.front ? facing : away) += 1;
                if (away > 6) return false; // a solid, or a room turned inside out
            }
    return facing >= 20;
}

// A room seen from inside: scaled as a fit is, unturned, the eye (the origin) standing
// kInteriorEyeDepth of its depth in front of its centre.
Placement insidePlacement(const std::vector<glm::dvec3>& positions) {
    Placement placement;
    std::tie(placement.low, placement.high) = boxOf(positions);
    placement.centre = (placement.low + placement.high) / 2.0;
    const glm::dvec3 extent = placement.high - placement.low;
    const double size = std::max({extent.x, extent.y, extent.z});
    placement.scale = size > 0.0 ? kFitSize / size : 1.0;
    placement.offset = glm::dvec3(0.0, 0.0, -(kInteriorEyeDepth * extent.z) * placement.scale);
    placement.inside = true;
    return placement;
}

Placement placementOf(const std::vector<glm::dvec3>& positions, const ModelSceneSetup& setup) {
    const auto [low, high] = boxOf(positions);
    Placement placement;
    placement.low = low;
    placement.high = high;
    if (setup.fit) {
        placement.centre = (low + high) / 2.0;
        placement.turn = viewTurn(setup.view, setup.fovDegrees);
        const double size = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
        placement.scale = size > 0.0 ? kFitSize / size : 1.0;
        std::vector<glm::dvec3> turned;
        resizePopulated(turned, positions.size());
        parallelForRanges(positions.size(), 1 << 15, [&](IndexRange range) {
            for (std::size_t i = range.begin; i < range.end; ++i)
                turned[i] = placement.turn.apply(positions[i] - placement.centre) * placement.scale;
        });
        const double tanY = std::tan(setup.fovDegrees * (kPi / 180.0) / 2.0);
        placement.offset = glm::dvec3(0.0, 0.0, -fitDistance(turned, tanY, tanY * setup.aspect));
    }
    return placement;
}

double largestExtent(const Placement& placement) {
    const glm::dvec3 extent = placement.high - placement.low;
    return std::max({extent.x, extent.y, extent.z});
}

// The rig hangs at the model's box's centre, placed, with half the box's diagonal, scaled.
LightRigAnchor anchorOf(const Placement& placement) {
    const double radius = length((placement.high - placement.low) * placement.scale) / 2.0;
    return {placement.place((placement.low + placement.high) / 2.0),
            placement.inside ? radius * kInteriorRigShare : radius,
            {}};
}

// The camera a fitted model is seen from when none is given: at the origin, looking at its
// centre, its up as placed (straight above or below: the frame's up). The default camera's
// view; turntables and the window's orbit turn about the model's up.
CameraPose modelCamera(const Placement& placement) {
    CameraPose camera;
    camera.target = anchorOf(placement).centre;
    const glm::dvec3 up = placement.turn.apply(glm::dvec3(0.0, 1.0, 0.0));
    if (up.x != 0.0 || up.y != 0.0) camera.up = up;
    return camera;
}

// A floor under the model: a square kGroundSpan model sizes across, centred below it,
// kFloorGap model sizes below its lowest position, matte grey, facing the model's up; placed
// with the model. A mesh of its own after the model's, so where they touch, the model wins
// the tie (docs/model.md).
constexpr double kGroundSpan = 100.0;
Mesh groundMesh(const Placement& placement) {
    const glm::dvec3 centre = (placement.low + placement.high) / 2.0;
    const double size = largestExtent(placement);
    const double half = kGroundSpan * size / 2.0;
    const double y = placement.low.y - kFloorGap * size;
    Mesh ground;
    for (const glm::dvec3 corner : {glm::dvec3(centre.x - half, y, centre.z - half),
                                    glm::dvec3(centre.x + half, y, centre.z - half),
                                    glm::dvec3(centre.x + half, y, centre.z + half),
                                    glm::dvec3(centre.x - half, y, centre.z + half)})
        ground.positions.push_back(placement.place(corner));
    ground.normals.assign(4, placement.turn.apply(glm::dvec3(0.0, 1.0, 0.0)));
    ground.triangles = {{0, 3, 2}, {0, 2, 1}};
    ground.triangleMaterials = {0, 0};
    ground.triangleLines = {0, 0};
    ground.materials = {MeshMaterial{}};
    ground.materials[0].phong = Material{glm::dvec3(0.7), glm::dvec3(0.0), 1.0};
    return ground;
}

// Scene::model for a model placed as placement says, its mesh made.
ModelPlacement placementFacts(const SourceModel& model, const std::vector<bool>& far,
                              const Placement& placement, const Mesh& mesh, bool fitted) {
    ModelPlacement facts;
    // The box of the positions that are not far, as read (none: empty).
    struct ReadBox {
        bool empty = true;
        glm::dvec3 low{0.0}, high{0.0};
        void grow(const glm::dvec3& lo, const glm::dvec3& hi) {
            low = empty ? lo : glm::min(low, lo);
            high = empty ? hi : glm::max(high, hi);
            empty = false;
        }
    };
    const ReadBox read = reduceRanges(
        model.positions.size(), 1 << 15,
        [&](IndexRange range) {
            ReadBox box;
            for (std::size_t i = range.begin; i < range.end; ++i)
                if (!far[i]) box.grow(model.positions[i], model.positions[i]);
            return box;
        },
        [](const ReadBox& part, ReadBox& into) {
            if (!part.empty) into.grow(part.low, part.high);
        });
    facts.readLow = read.low;
    facts.readHigh = read.high;
    std::tie(facts.placedLow, facts.placedHigh) = boxOf(mesh.positions);
    const CameraPose camera = modelCamera(placement);
    facts.centre = camera.target;
    facts.up = camera.up;
    facts.fitted = fitted;
    return facts;
}

// A model read as y-up that looks like a z-up one lying on its back (Blender, most CAD and
// scanning tools write z-up): its largest extent along z (towards the camera), its smallest
// along y, and that at most 0.6 of the first. A flat model (no height at all) is a decal or
// a tile, and is left alone. A y-up car or boat, long along z, gets the note too; it says
// "if". The note, or nothing.
std::optional<std::string> lyingDown(const ModelPlacement& model) {
    const glm::dvec3 extent = model.readHigh - model.readLow;
    if (!(extent.y > 0.0 && extent.z >= extent.x && extent.y <= extent.x &&
          extent.y <= 0.6 * extent.z))
        return {};
    return "the model is longest along z and shallowest along y, as a z-up model "
           "(Blender, most CAD and scanning tools) lies on its back when read as y-up; if it is "
           "one, give --up z";
}

} // namespace

Scene sceneFromModel(SourceModel model, const ModelSceneSetup& setup, const std::string& fileName) {
    // The mesh's vertices take most of the time: its triangles are the units.
    PhaseProgress progress("Making a mesh of " + fileName, model.triangles.size());
    // The model turned so that its up axis is +y; as read, not copied, when it already is.
    const bool turned = setup.up != UpAxis::PosY;
    std::vector<glm::dvec3> turnedPositions, turnedNormals;
    if (turned) {
        auto up = [&](const glm::dvec3& v) { return turnUp(v, setup.up); };
        turnedPositions.resize(model.positions.size());
        turnedNormals.resize(model.normals.size());
        std::transform(model.positions.begin(), model.positions.end(), turnedPositions.begin(), up);
        std::transform(model.normals.begin(), model.normals.end(), turnedNormals.begin(), up);
    }
    const std::vector<glm::dvec3>& positions = turned ? turnedPositions : model.positions;
    const std::vector<glm::dvec3>& normals = turned ? turnedNormals : model.normals;

    // The fit, the floor and the rig are for the model without positions far beyond it.
    const std::vector<bool> far = farPositions(model.positions);
    const bool anyFar = std::find(far.begin(), far.end(), true) != far.end();
    std::vector<glm::dvec3> near;
    std::vector<bool> farFaces; // the faces that use one, left out
    if (anyFar) {
        for (std::size_t i = 0; i < positions.size(); ++i)
            if (!far[i]) near.push_back(positions[i]);
        farFaces.assign(faceCount(model), false);
        for (std::size_t f = 0; f < faceCount(model); ++f)
            for (const std::uint32_t p : facePositions(model, f))
                farFaces[f] = farFaces[f] || far[p];
    }
    const std::vector<glm::dvec3>& kept = anyFar ? near : positions;
    if (kept.empty()) { // every position far from the others (a damaged file): nothing to fit
        const FarPositions said = describeFar(model, far, model.triangles.size());
        throw SceneError(fileName, static_cast<int>(said.line),
                         said.message + ": nothing is left to render");
    }
    // A room (it encloses its centre) is seen from inside unless a view was asked for.
    const std::vector<TriangleFate> fates = triangleFates(model, positions, farFaces);
    bool inside = false;
    if (setup.fit && setup.insideWhenEnclosed) {
        const auto [low, high] = boxOf(kept);
        inside = enclosesItsCentre(positions, model.triangles, fates, (low + high) / 2.0);
    }
    const Placement placement = inside ? insidePlacement(kept) : placementOf(kept, setup);

    Scene scene;
    scene.ambient = setup.ambient;
    scene.warnings = model.warnings;
    std::optional<SmoothNormals> smooth;
    if (needsSmoothNormals(model, fates))
        smooth.emplace(model, positions, setup.creaseDegrees, farFaces);
    // The model's arrays go as soon as they have served, for the phase's peak of memory: the
    // faces once the smooth normals are made, the triangles once the mesh is.
    release(model.facePositions);
    release(model.faceStarts);
    release(farFaces);
    const std::size_t triangleCount = model.triangles.size();
    Mesh mesh = modelMesh(model, positions, normals, fates, std::move(smooth),
                          {[&](const glm::dvec3& p) { return placement.place(p); },
                           [&](const glm::dvec3& n) { return placement.turn.apply(n); }},
                          &progress);
    model.triangles = SourceTriangles{};
    mesh.materials = model.materials;
    const auto farTriangles =
        static_cast<std::size_t>(std::count(fates.begin(), fates.end(), TriangleFate::far));
    const auto degenerate =
        static_cast<std::size_t>(std::count(fates.begin(), fates.end(), TriangleFate::degenerate));
    if (anyFar) {
        const FarPositions said = describeFar(model, far, farTriangles);
        if (mesh.triangles.empty())
            throw SceneError(fileName, static_cast<int>(said.line),
                             said.message + ": nothing is left to render");
        scene.warnings.push_back(sceneLocation(fileName, static_cast<int>(said.line)) +
                                 "warning: " + said.message);
    }
    if (mesh.triangles.empty())
        throw SceneError(fileName, 0,
                         "every one of the model's " + std::to_string(triangleCount) +
                             " triangles is degenerate (two corners at one position, or no area): "
                             "nothing is left to render");
    // The rig (or one light above the camera), then the model's own emitters.
    std::vector<Light> emitters =
        emitterLights(mesh, kEmitterLift * largestExtent(placement) * placement.scale);
    if (setup.lightRig) {
        scene.lightRig = anchorOf(placement);
        scene.lightRig->emitters = std::move(emitters);
        scene.lights =
            lightRig(*scene.lightRig,
                     setup.cameraGiven || !setup.fit ? setup.camera : modelCamera(placement));
    } else {
        scene.lights = {Light{glm::dvec3(0.0, 4.0, 0.0), glm::dvec3(1.0), 0}};
        scene.lights.insert(scene.lights.end(), emitters.begin(), emitters.end());
    }
    scene.model = placementFacts(model, far, placement, mesh, setup.fit);
    scene.model->notRendered = model.notRendered;
    if (!setup.upGiven && !placement.inside) { // a room is often longer than it is tall
        if (std::optional<std::string> lying = lyingDown(*scene.model))
            scene.warnings.push_back(sceneLocation(fileName, 0) + "warning: " + *lying);
    }
    scene.meshes.push_back(std::move(mesh));
    scene.model->inside = placement.inside;
    if (setup.ground && !placement.inside) { // a room has a floor of its own
        scene.meshes.push_back(groundMesh(placement));
        const auto [low, high] = boxOf(scene.meshes.back().positions);
        scene.model->floor = true;
        scene.model->floorLow = low;
        scene.model->floorHigh = high;
    }
    if (degenerate > 0)
        scene.warnings.push_back(sceneLocation(fileName, 0) +
                                 "warning: " + std::to_string(degenerate) +
                                 " degenerate triangle(s) left out (two corners at one "
                                 "position, or no area)");
    return scene;
}
