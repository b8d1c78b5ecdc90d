#include "model/polygon_triangulation.h"

#include <cmath>

namespace {

struct Point2 {
    double u = 0.0, v = 0.0;
    bool operator==(const Point2&) const = default;
};

// Twice the signed area of the triangle a, b, c in the plane.
double turn(Point2 a, Point2 b, Point2 c) {
    return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

PolygonTriangles fan(std::size_t n, bool concave) {
    PolygonTriangles result;
    for (std::size_t i = 1; i + 1 < n; ++i)
        result.triangles.push_back({0, i, i + 1});
    result.fannedConcave = concave;
    return result;
}

} // namespace

PolygonTriangles triangulatePolygon(const std::vector<glm::dvec3>& corners) {
    const std::size_t n = corners.size();
    if (n <= 3) return fan(n, false);
    // The polygon's normal (Newell's, as a fan's sum of cross products) and the axis it
    // points along most, which is dropped to see the polygon in a plane, turned so that
    // its corners run counter-clockwise there when sign is 1.
    glm::dvec3 normal(0.0);
    for (std::size_t i = 1; i + 1 < n; ++i)
        normal += glm::cross(corners[i] - corners[0], corners[i + 1] - corners[0]);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
    if (normal[axis] == 0.0) return fan(n, false); // no area: the triangles are left out later
    const double sign = normal[axis] > 0.0 ? 1.0 : -1.0;
    const int uAxis = (axis + 1) % 3, vAxis = (axis + 2) % 3;
    std::vector<Point2> points;
    for (const glm::dvec3& corner : corners)
        points.push_back({corner[uAxis], corner[vAxis]});

    bool convex = true;
    for (std::size_t i = 0; i < n && convex; ++i)
        convex = turn(points[(i + n - 1) % n], points[i], points[(i + 1) % n]) * sign >= 0.0;
    if (convex) return fan(n, false);

    const double length = std::sqrt(glm::dot(normal, normal));
    double reach = 0.0, offPlane = 0.0;
    for (const glm::dvec3& corner : corners) {
        const glm::dvec3 d = corner - corners[0];
        reach = std::max(reach, std::sqrt(glm::dot(d, d)));
        offPlane = std::max(offPlane, std::abs(glm::dot(d, normal)) / length);
    }
    if (offPlane > kPlanarTolerance * reach) return fan(n, true);

    // Ear clipping: the first corner, in order, that turns the polygon's way and whose
    // triangle holds no other corner (corners at one of its own points do not count, so
    // a ring cut open along a bridge clips), is cut off; again until three are left.
    std::vector<std::size_t> left(n);
    for (std::size_t i = 0; i < n; ++i)
        left[i] = i;
    PolygonTriangles result;
    while (left.size() > 3) {
        const std::size_t m = left.size();
        bool clipped = false;
        for (std::size_t j = 0; j < m && !clipped; ++j) {
            const std::size_t a = left[(j + m - 1) % m], b = left[j], c = left[(j + 1) % m];
            if (turn(points[a], points[b], points[c]) * sign <= 0.0) continue;
            bool empty = true;
            for (const std::size_t p : left) {
                const Point2 q = points[p];
                if (q == points[a] || q == points[b] || q == points[c]) continue;
                if (turn(points[a], points[b], q) * sign >= 0.0 &&
                    turn(points[b], points[c], q) * sign >= 0.0 &&
                    turn(points[c], points[a], q) * sign >= 0.0) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            result.triangles.push_back({a, b, c});
            left.erase(left.begin() + std::ptrdiff_t(j));
            clipped = true;
        }
        if (!clipped) { // it crosses itself: no ear; the rest is fanned, and counted
            for (std::size_t i = 1; i + 1 < left.size(); ++i)
                result.triangles.push_back({left[0], left[i], left[i + 1]});
            result.fannedConcave = true;
            return result;
        }
    }
    result.triangles.push_back({left[0], left[1], left[2]});
    return result;
}
