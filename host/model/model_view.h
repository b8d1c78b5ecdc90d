// The side a fitted model is seen from (--view): a turn of the model, about its centre, that
// shows the default camera (at the origin, looking down -z) that side of it. The named views
// are exact (swaps and negations of coordinates); the three-quarter view, the default, looks
// down on the model from the front right, as model viewers open.
#pragma once

#include <glm/glm.hpp>

enum class ModelView { ThreeQuarter, Front, Back, Left, Right, Top, Bottom };

// The three-quarter view: this far round from the front towards the model's right (+x),
// and this far above the horizon, at least: higher when the field of view is wide enough to
// show the horizon, so the floor's far edge stays out of the frame.
inline constexpr double kThreeQuarterAzimuthDegrees = 45.0;
inline constexpr double kThreeQuarterMinElevationDegrees = 30.0;
inline constexpr double kHorizonMarginDegrees = 5.0;
inline constexpr double kThreeQuarterMaxElevationDegrees = 60.0;

// A rotation as its three rows: the camera's right, up and backward axes in the model's
// coordinates (after its up axis is turned onto +y). identity skips the arithmetic, so the
// front view places a model to the bit as before the views existed.
struct ViewTurn {
    glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, back{0, 0, 1};
    bool identity = true;

    // r.x v.x + r.y v.y + r.z v.z per row, in that order (tools/obj_to_scene.py's too).
    glm::dvec3 apply(glm::dvec3 v) const {
        if (identity) return v;
        return {right.x * v.x + right.y * v.y + right.z * v.z, up.x * v.x + up.y * v.y + up.z * v.z,
                back.x * v.x + back.y * v.y + back.z * v.z};
    }
};

// The turn for a view, for a vertical field of view of fovDegrees.
ViewTurn viewTurn(ModelView view, double fovDegrees);

// The three-quarter view's elevation for a vertical field of view: the horizon
// kHorizonMarginDegrees above the frame's top edge, from kThreeQuarterMinElevationDegrees
// to kThreeQuarterMaxElevationDegrees.
double threeQuarterElevationDegrees(double fovDegrees);
