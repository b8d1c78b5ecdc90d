// A SourceModel made a Scene: what a model file lacks and a scene needs (an up axis, normals
// where none are given, a place in view, a ground, lights, an ambient colour), each by a
// rule of docs/models.md that tools/obj_to_scene.py follows too, operation for operation.
#pragma once

#include "model/model_lights.h"
#include "model/model_view.h"
#include "model/source_model.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <string>

// The model's axis that is up: it is turned (exactly: a swap and negation of coordinates)
// so that this axis points along +y, the default camera's up.
enum class UpAxis { PosX, NegX, PosY, NegY, PosZ, NegZ };

struct ModelSceneSetup {
    UpAxis up = UpAxis::PosY;
    bool upGiven = false; // --up was given: no note that the model may lie on its back
    // A corner without a normal averages the faces around it that meet its own face at
    // most this many degrees apart (0: flat faces; 180: smooth everywhere).
    double creaseDegrees = 60.0;
    // Scale the model to kFitSize across and put it straight ahead of the default camera,
    // as far away as makes it fill kFrameShare (model_fit.h) of the view (of this field of
    // view and aspect ratio); else the model stays where its file puts it.
    bool fit = true;
    ModelView view = ModelView::ThreeQuarter; // the side the fit shows (model_view.h)
    // No view was asked for: a fitted model that encloses its centre (a room) is seen from
    // inside (enclosesItsCentre, docs/models.md).
    bool insideWhenEnclosed = true;
    double fovDegrees = 60.0;
    double aspect = 640.0 / 480.0;
    bool ground = true;   // a wide floor under the model, for its shadow
    bool lightRig = true; // key, fill and rim lights around the model; else one at (0, 4, 0)
    // The camera the rig is placed for (--camera-*): the model's place does not depend on
    // it (the fit is for the default camera), its lights do. When none is given, a fitted
    // model's rig is placed for the model's own camera (Scene::model's centre and up).
    CameraPose camera;
    bool cameraGiven = false;
    glm::dvec3 ambient{0.1};
};

inline constexpr double kFitSize = 1.5;
// The floor sits this share of the model's largest extent below its lowest point: never in
// the plane of a face of it (a flat model on a coplanar floor is noise), close enough that
// a model standing on it still seems to.
inline constexpr double kFloorGap = 0.002;
// Seen from inside, the eye stands this share of the room's depth in front of its centre
// (towards +z), looking at the centre; the rig's lights hang at this share of their usual
// distances, inside the room.
inline constexpr double kInteriorEyeDepth = 0.4;
inline constexpr double kInteriorRigShare = 0.15;

// Triangles with two corners at one position, or of no area, are left out, and counted in
// a warning; fileName names the model in it. The model is taken, not copied (std::move it),
// so that its arrays go as soon as they have served: the phase's peak of memory.
Scene sceneFromModel(SourceModel model, const ModelSceneSetup& setup, const std::string& fileName);
