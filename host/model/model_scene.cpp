// SourceModel to Scene (model_scene.h). The arithmetic is the same, operation for operation and
// in the same order, as tools/obj_to_scene.py's in double precision, so that both write
// the same scene text; docs/models.md states the rules.
#include "model/model_scene.h"

#include "base/deduplicator.h"
#include "model/exact_vectors.h"
#include "model/far_vertices.h"
#include "model/model_fit.h"
#include "model/model_lights.h"
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

// Newell's sum of cross products over a polygon: its normal scaled by twice its area, so
// adding such sums weights faces by area; per polygon, so how a quad was split does not
// tilt its corners' normals.
// The positions are multiplied by scale, a power of two, which changes no rounding.
glm::dvec3 newellNormal(const std::vector<glm::dvec3>& positions,
                        std::span<const std::uint32_t> face, double scale) {
    glm::dvec3 normal(0.0);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
        const glm::dvec3 a = positions[face[0]] * scale;
        normal += glm::cross(positions[face[i]] * scale - a, positions[face[i + 1]] * scale - a);
    }
    return normal;
}

// The power of two that brings the largest coordinate into [0.5, 1): the Newell normals of
// a model at 1e300 would overflow to infinity (and its normals be NaN), while for every
// other model the scaled arithmetic rounds exactly as the unscaled one, so its normals are
// the same bits.
double newellScale(const std::vector<glm::dvec3>& positions) {
    double largest = 0.0;
    for (const glm::dvec3& p : positions)
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    int exponent = 0;
    std::frexp(largest, &exponent);
    return std::ldexp(1.0, -exponent);
}

// The smooth normals of corners without one: for face f and its position p, the
// normalised sum of the Newell normals of the faces around p (each face once, in file
// order) whose unit normal is within the crease angle of f's, f itself always included.
// Faces left out of the scene (leftOut[f], or none when it is empty) count for no corner.
class SmoothNormals {
  public:
    SmoothNormals(const SourceModel& model, const std::vector<glm::dvec3>& positions,
                  double creaseDegrees, const std::vector<bool>& leftOut)
        : cosine_(std::cos(creaseDegrees * (kPi / 180.0))), everywhere_(creaseDegrees >= 180.0) {
        facesAround_.resize(positions.size());
        const double scale = newellScale(positions);
        for (std::size_t f = 0; f < faceCount(model); ++f) {
            newell_.push_back(newellNormal(positions, facePositions(model, f), scale));
            unit_.push_back(normalizedOrZero(newell_.back()));
            if (!leftOut.empty() && leftOut[f]) continue;
            for (const std::uint32_t p :
                 facePositions(model, f)) // each face once, though p repeats
                if (facesAround_[p].empty() || facesAround_[p].back() != f)
                    facesAround_[p].push_back(static_cast<std::uint32_t>(f));
        }
    }

    glm::dvec3 at(std::uint32_t face, std::uint32_t position) const {
        glm::dvec3 sum(0.0);
        for (const std::uint32_t other : facesAround_[position])
            if (everywhere_ || other == face || dot(unit_[face], unit_[other]) >= cosine_)
                sum += newell_[other];
        return normalizedOrZero(sum);
    }

  private:
    double cosine_;
    bool everywhere_;
    std::vector<glm::dvec3> newell_, unit_;
    std::vector<std::vector<std::uint32_t>> facesAround_;
};

bool isDegenerate(const std::vector<glm::dvec3>& positions, const SourceTriangle& triangle) {
    const std::uint32_t a = triangle.corners[0].position, b = triangle.corners[1].position,
                        c = triangle.corners[2].position;
    if (a == b || b == c || a == c) return true;
    return length(glm::cross(positions[b] - positions[a], positions[c] - positions[a])) == 0.0;
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

std::pair<glm::dvec3, glm::dvec3> boxOf(const std::vector<glm::dvec3>& positions) {
    glm::dvec3 low = positions[0], high = positions[0];
    for (const glm::dvec3& p : positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    return {low, high};
}

// Whether the model encloses its box's centre as a room does: a ray from the centre in each
// of the 26 directions towards the box's faces, edges and corners meets one of the
// triangles, and at least 20 of those nearest triangles turn their front (their winding's
// side) to the centre. A closed solid encloses its centre too, but its faces turn their
// backs to it. The same arithmetic as tools/obj_to_scene.py's.
bool enclosesItsCentre(const std::vector<glm::dvec3>& positions,
                       const std::vector<glm::uvec3>& triangles, glm::dvec3 centre) {
    int facing = 0, away = 0;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
                if (i == 0 && j == 0 && k == 0) continue;
                const glm::dvec3 d = normalizedOrZero(glm::dvec3(i, j, k));
                double nearest = std::numeric_limits<double>::infinity();
                bool front = false;
                for (const glm::uvec3& t : triangles) {
                    const glm::dvec3 a = positions[t.x], e1 = positions[t.y] - a,
                                     e2 = positions[t.z] - a;
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
                    if (distance > 0.0 && distance < nearest) {
                        nearest = distance;
                        front = dot(glm::cross(e1, e2), d) < 0.0;
                    }
                }
                if (nearest == std::numeric_limits<double>::infinity()) return false; // open
                (front ? facing : away) += 1;
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
    glm::dvec3 low = positions[0], high = positions[0];
    for (const glm::dvec3& p : positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    Placement placement;
    placement.low = low;
    placement.high = high;
    if (setup.fit) {
        placement.centre = (low + high) / 2.0;
        placement.turn = viewTurn(setup.view, setup.fovDegrees);
        const double size = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
        placement.scale = size > 0.0 ? kFitSize / size : 1.0;
        std::vector<glm::dvec3> turned;
        turned.reserve(positions.size());
        for (const glm::dvec3& p : positions)
            turned.push_back(placement.turn.apply(p - placement.centre) * placement.scale);
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
    std::vector<glm::dvec3> read;
    for (std::size_t i = 0; i < model.positions.size(); ++i)
        if (!far[i]) read.push_back(model.positions[i]);
    std::tie(facts.readLow, facts.readHigh) = boxOf(read);
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

// A model's corner as a mesh vertex: its position, its texture coordinates' index and its
// normal, bit for bit, so that corners that agree on all three share a vertex (and its
// colour, which goes with the position).
struct CornerKey {
    std::uint32_t position = 0;
    std::uint32_t texcoord = kNoTexcoord;
    glm::dvec3 normal{0.0};
};

} // namespace

Scene sceneFromModel(const SourceModel& model, const ModelSceneSetup& setup,
                     const std::string& fileName) {
    std::vector<glm::dvec3> positions, normals;
    for (const glm::dvec3& p : model.positions)
        positions.push_back(turnUp(p, setup.up));
    for (const glm::dvec3& n : model.normals)
        normals.push_back(turnUp(n, setup.up));

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
    bool inside = false;
    if (setup.fit && setup.insideWhenEnclosed) {
        std::vector<glm::uvec3> corners;
        for (const SourceTriangle& t : model.triangles)
            if (!(anyFar && farFaces[t.face]) && !isDegenerate(positions, t))
                corners.emplace_back(t.corners[0].position, t.corners[1].position,
                                     t.corners[2].position);
        const auto [low, high] = boxOf(kept);
        inside = enclosesItsCentre(positions, corners, (low + high) / 2.0);
    }
    const Placement placement = inside ? insidePlacement(kept) : placementOf(kept, setup);
    auto place = [&](glm::dvec3 p) { return placement.place(p); };
    // Made when a corner first needs one: a model that gives every normal never pays for it.
    std::optional<SmoothNormals> smooth;

    Scene scene;
    scene.ambient = setup.ambient;
    scene.warnings = model.warnings;
    Mesh mesh;
    mesh.materials = model.materials;
    const bool anyColor = std::any_of(model.colors.begin(), model.colors.end(),
                                      [](const auto& color) { return color.has_value(); });
    std::vector<CornerKey> corners; // one per mesh vertex
    Deduplicator<CornerKey> vertexOf(corners, model.positions.size());
    std::size_t degenerate = 0, farTriangles = 0;
    for (const SourceTriangle& source : model.triangles) {
        if (anyFar && farFaces[source.face]) {
            ++farTriangles;
            continue;
        }
        if (isDegenerate(positions, source)) {
            ++degenerate;
            continue;
        }
        glm::uvec3 triangle;
        for (int k = 0; k < 3; ++k) {
            const SourceCorner& corner = source.corners[k];
            CornerKey key;
            key.position = corner.position;
            key.texcoord = corner.texcoord;
            if (!corner.normal && !smooth)
                smooth.emplace(model, positions, setup.creaseDegrees, farFaces);
            key.normal =
                corner.normal ? normals[*corner.normal] : smooth->at(source.face, corner.position);
            const std::size_t before = corners.size();
            triangle[k] = vertexOf.indexOf(key);
            if (corners.size() == before) continue; // a vertex already made
            mesh.positions.push_back(place(positions[corner.position]));
            mesh.normals.push_back(placement.turn.apply(key.normal)); // turned with the model
            if (!model.texcoords.empty())
                mesh.texcoords.push_back(corner.texcoord == kNoTexcoord
                                             ? glm::dvec2(0.0)
                                             : model.texcoords[corner.texcoord]);
            if (anyColor) {
                const auto& color = model.colors[corner.position];
                mesh.colors.push_back(color ? glm::dvec4(*color, 1.0) : glm::dvec4(0.0));
            }
        }
        mesh.triangles.push_back(triangle);
        mesh.triangleMaterials.push_back(source.material);
        mesh.triangleLines.push_back(source.line);
    }
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
                         "every one of the model's " + std::to_string(model.triangles.size()) +
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
