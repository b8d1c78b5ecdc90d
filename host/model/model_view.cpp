// The views' turns (model_view.h). tools/obj_to_scene.py computes the same numbers, operation
// for operation.
#include "model/model_view.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.141592653589793;

ViewTurn exact(glm::dvec3 right, glm::dvec3 up, glm::dvec3 back) {
    return {right, up, back, false};
}

} // namespace

double threeQuarterElevationDegrees(double fovDegrees) {
    return std::clamp(fovDegrees / 2.0 + kHorizonMarginDegrees, kThreeQuarterMinElevationDegrees,
                      kThreeQuarterMaxElevationDegrees);
}

ViewTurn viewTurn(ModelView view, double fovDegrees) {
    switch (view) {
    case ModelView::Front:
        return {};
    case ModelView::Back: // seen from -z
        return exact({-1, 0, 0}, {0, 1, 0}, {0, 0, -1});
    case ModelView::Right: // seen from +x: the screen's right is the model's back (-z)
        return exact({0, 0, -1}, {0, 1, 0}, {1, 0, 0});
    case ModelView::Left: // seen from -x
        return exact({0, 0, 1}, {0, 1, 0}, {-1, 0, 0});
    case ModelView::Top: // seen from +y, the model's front at the bottom of the frame
        return exact({1, 0, 0}, {0, 0, -1}, {0, 1, 0});
    case ModelView::Bottom: // seen from -y, the model's front at the top of the frame
        return exact({1, 0, 0}, {0, 0, 1}, {0, -1, 0});
    case ModelView::ThreeQuarter:
        break;
    }
    // Turned by the azimuth about y, then tilted by the elevation about x.
    const double a = kThreeQuarterAzimuthDegrees * (kPi / 180.0);
    const double e = threeQuarterElevationDegrees(fovDegrees) * (kPi / 180.0);
    const double ca = std::cos(a), sa = std::sin(a), ce = std::cos(e), se = std::sin(e);
    return exact({ca, 0.0, -sa}, {-sa * se, ce, -ca * se}, {sa * ce, se, ca * ce});
}
