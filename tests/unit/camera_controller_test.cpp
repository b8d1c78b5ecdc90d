// The camera as pure math: orientation of a pose (exactly the identity for the default
// camera), orbit, dolly, fly and look, and the scene bounds the window's controls use.
// No Vulkan, no window.
#include "scene/camera.h"
#include "scene/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr double kTight = 1e-12;

void expectNear(glm::dvec3 actual, glm::dvec3 expected, double tolerance = kTight) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

glm::dvec3 rotate(const glm::dquat& q, glm::dvec3 v) {
    return q * v;
}

TEST(CameraOrientation, SpecCameraIsExactlyTheIdentity) {
    const glm::dquat q = cameraOrientation(CameraPose{});
    EXPECT_EQ(q.x, 0.0);
    EXPECT_EQ(q.y, 0.0);
    EXPECT_EQ(q.z, 0.0);
    EXPECT_EQ(q.w, 1.0);
}

TEST(CameraOrientation, TargetFurtherAlongMinusZIsStillExactlyTheIdentity) {
    CameraPose pose;
    pose.target = {0.0, 0.0, -7.25};
    const glm::dquat q = cameraOrientation(pose);
    EXPECT_EQ(q, glm::dquat(1.0, 0.0, 0.0, 0.0));
    // The window's orbit pivot keeps the default orientation exactly too.
    SceneBounds bounds{{0.3, -0.2, -5.0}, 2.0};
    EXPECT_EQ(cameraOrientation(pivotAtScene(pose, bounds, 0.01)), glm::dquat(1.0, 0.0, 0.0, 0.0));
}

TEST(CameraOrientation, MapsCameraAxesOntoTheBasis) {
    CameraPose pose{{1.0, 2.0, 3.0}, {4.0, -1.0, 0.5}, {0.2, 1.0, 0.1}};
    const glm::dquat q = cameraOrientation(pose);
    const CameraBasis basis = cameraBasis(pose);
    expectNear(rotate(q, {0, 0, -1}), glm::normalize(pose.target - pose.position));
    expectNear(rotate(q, {1, 0, 0}), basis.right);
    expectNear(rotate(q, {0, 1, 0}), basis.up);
    EXPECT_NEAR(glm::dot(basis.up, glm::normalize(pose.up)) > 0 ? 1.0 : -1.0, 1.0,
                0.0); // up stays up
    EXPECT_NEAR(glm::length(q), 1.0, kTight);
}

TEST(CameraOrientation, LookingAlongPlusXTurnsMinusZOntoPlusX) {
    CameraPose pose{{0, 0, 0}, {5, 0, 0}, {0, 1, 0}};
    expectNear(rotate(cameraOrientation(pose), {0, 0, -1}), {1, 0, 0});
    expectNear(rotate(cameraOrientation(pose), {1, 0, 0}), {0, 0, 1});
}

TEST(CameraPose, ProblemsAreNamed) {
    EXPECT_EQ(cameraPoseProblem(CameraPose{}), "");
    EXPECT_NE(
        cameraPoseProblem(CameraPose{{1, 1, 1}, {1, 1, 1}, {0, 1, 0}}).find("target must differ"),
        std::string::npos);
    EXPECT_NE(cameraPoseProblem(CameraPose{{0, 0, 0}, {0, 3, 0}, {0, 1, 0}}).find("parallel"),
              std::string::npos);
    EXPECT_NE(cameraPoseProblem(CameraPose{{0, 0, 0}, {0, 0, -1}, {0, 0, 0}}).find("zero"),
              std::string::npos);
    EXPECT_NE(cameraPoseProblem(CameraPose{{NAN, 0, 0}, {0, 0, -1}, {0, 1, 0}}).find("finite"),
              std::string::npos);
}

TEST(Orbit, KeepsTheDistanceAndTheTarget) {
    CameraPose pose{{0, 1, 5}, {0, 0, -2}, {0, 1, 0}};
    const double distance = glm::length(pose.position - pose.target);
    CameraPose moved = orbitCamera(pose, 0.7, 0.3);
    EXPECT_EQ(moved.target, pose.target);
    EXPECT_NEAR(glm::length(moved.position - moved.target), distance, 1e-9);
    EXPECT_GT(glm::length(moved.position - pose.position), 0.1);
    EXPECT_GT(moved.position.y, pose.position.y); // a positive pitch raises the eye
}

TEST(Orbit, AFullTurnOfYawComesBack) {
    CameraPose pose{{2, 1, 5}, {0, 0, -2}, {0, 1, 0}};
    CameraPose moved = pose;
    for (int k = 0; k < 8; ++k)
        moved = orbitCamera(moved, M_PI / 4, 0.0);
    expectNear(moved.position, pose.position, 1e-9);
}

TEST(Orbit, YawTurnsAroundUp) {
    CameraPose pose{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}};
    expectNear(orbitCamera(pose, M_PI / 2, 0.0).position, {5, 0, 0}, 1e-12);
}

TEST(Orbit, PitchStopsShortOfThePole) {
    CameraPose pose{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}};
    CameraPose moved = orbitCamera(pose, 0.0, 10.0); // far past straight up
    EXPECT_EQ(cameraPoseProblem(moved), "");
    EXPECT_LT(moved.position.y, 5.0);
    EXPECT_GT(moved.position.y, 4.99);
    moved = orbitCamera(pose, 0.0, -10.0);
    EXPECT_EQ(cameraPoseProblem(moved), "");
    EXPECT_LT(moved.position.y, -4.99);
}

TEST(Dolly, MovesTowardsTheTargetAndNeverPassesIt) {
    CameraPose pose{{0, 0, 10}, {0, 0, 0}, {0, 1, 0}};
    CameraPose closer = dollyCamera(pose, 1.0);
    EXPECT_LT(closer.position.z, 10.0);
    EXPECT_GT(closer.position.z, 0.0);
    EXPECT_GT(dollyCamera(pose, -1.0).position.z, 10.0);
    CameraPose far = dollyCamera(pose, 1000.0);
    EXPECT_GT(far.position.z, 0.0);
    EXPECT_EQ(cameraPoseProblem(far), "");
    expectNear(dollyCamera(dollyCamera(pose, 3.0), -3.0).position, pose.position, 1e-9);
}

TEST(Fly, MovesEyeAndTargetTogetherAlongTheCameraAxes) {
    CameraPose pose; // looking down -z
    CameraPose moved = flyCamera(pose, {1.0, 2.0, 3.0});
    expectNear(moved.position, {1.0, 2.0, -3.0});
    expectNear(moved.target - moved.position, pose.target - pose.position);
}

TEST(Look, TurnsTheViewAroundTheEye) {
    CameraPose pose{{1, 2, 3}, {1, 2, -1}, {0, 1, 0}};
    CameraPose turned = lookCamera(pose, -M_PI / 2, 0.0); // a quarter turn to the right
    EXPECT_EQ(turned.position, pose.position);
    expectNear(turned.target, {5, 2, 3}, 1e-12);
    CameraPose up = lookCamera(pose, 0.0, 0.2);
    EXPECT_GT(up.target.y, pose.target.y);
    EXPECT_NEAR(glm::length(up.target - up.position), 4.0, 1e-12);
    EXPECT_EQ(cameraPoseProblem(lookCamera(pose, 0.0, 5.0)), "");
}

TEST(SceneBounds, CoverSpheresAndTriangles) {
    Scene scene;
    Sphere sphere;
    sphere.center = {0, 0, -5};
    sphere.radius = 1;
    scene.spheres.push_back(sphere);
    Triangle triangle;
    triangle.vertices[0].position = {4, 0, -5};
    triangle.vertices[1].position = {4, 1, -5};
    triangle.vertices[2].position = {4, 0, -6};
    scene.triangles.push_back(triangle);
    SceneBounds bounds = sceneBounds(scene);
    expectNear(bounds.centre, {1.5, 0.0, -5.0});
    EXPECT_NEAR(bounds.radius, glm::length(glm::dvec3(5, 2, 2)) / 2, kTight);
    EXPECT_EQ(sceneBounds(Scene{}).radius, 0.0);
}

TEST(SceneBounds, PivotKeepsTheLineOfSight) {
    CameraPose pose{{1, 1, 1}, {2, 1, 0}, {0, 1, 0}};
    CameraPose pivoted = pivotAtScene(pose, {{10, 1, -8}, 3}, 0.01);
    expectNear(glm::normalize(pivoted.target - pivoted.position),
               glm::normalize(pose.target - pose.position));
    EXPECT_NEAR(glm::length(pivoted.target - pivoted.position), 9.0 * std::sqrt(2.0), 1e-9);
    // A scene behind the eye leaves the pivot at the minimum distance ahead.
    EXPECT_NEAR(glm::length(pivotAtScene(pose, {{-10, 1, 10}, 1}, 0.5).target - pose.position), 0.5,
                kTight);
}

} // namespace

TEST(Turntable, FrameZeroIsThePoseBitForBit) {
    const CameraPose pose{{0.1, 0.7, 0.3}, {0.2, 0.1, -4.0}, {0.0, 1.0, 0.05}};
    EXPECT_TRUE(turntableCamera(pose, {0.3, -0.2, -5.0}, 0, 7) == pose);
}

TEST(Turntable, KeepsDistanceAndHeightAndTurnsCounterClockwiseFromAbove) {
    const CameraPose pose; // the eye at the origin, looking down -z
    const glm::dvec3 centre{0.0, 2.0, -5.0};
    for (std::uint32_t k = 1; k < 8; ++k) {
        const CameraPose turned = turntableCamera(pose, centre, k, 8);
        const glm::dvec3 offset = turned.position - centre;
        EXPECT_NEAR(std::hypot(offset.x, offset.z), 5.0, 1e-12) << k;
        EXPECT_NEAR(offset.y, -2.0, 1e-12) << k; // the height along up
        EXPECT_TRUE(turned.up == pose.up);
        // Still looking along the same line through the centre's axis: at the centre's
        // depth the view passes over the axis.
        const glm::dvec3 view = glm::normalize(turned.target - turned.position);
        const glm::dvec3 towards = glm::normalize(glm::dvec3(-offset.x, 0.0, -offset.z));
        EXPECT_NEAR(glm::dot(view, towards), 1.0, 1e-12) << k;
    }
    // A quarter turn about +y (right-handed: counter-clockwise seen from +y) takes the eye
    // from +z of the centre to +x of it.
    const CameraPose quarter = turntableCamera(pose, centre, 1, 4);
    EXPECT_NEAR(quarter.position.x, 5.0, 1e-12);
    EXPECT_NEAR(quarter.position.z, -5.0, 1e-12);
    const CameraPose full = turntableCamera(pose, centre, 4, 4);
    EXPECT_NEAR(glm::length(full.position - pose.position), 0.0, 1e-12);
}

TEST(CameraPath, ReadsFieldsCommentsAndBlankLinesExactly) {
    const std::vector<PathCamera> cameras =
        parseCameraPath("# a path\n\n  0,0,0 0,0,-1 0,1,0 60 # the default\r\n"
                        "0.1,-2,3e-3\t4,5,6   0,0,1 33.3",
                        "p.txt");
    ASSERT_EQ(cameras.size(), 2u);
    EXPECT_TRUE(cameras[0].pose == CameraPose{});
    EXPECT_EQ(cameras[0].fovDegrees, 60.0);
    EXPECT_EQ(cameras[0].line, 3);
    EXPECT_EQ(cameras[1].pose.position, glm::dvec3(0.1, -2, 3e-3));
    EXPECT_EQ(cameras[1].pose.target, glm::dvec3(4, 5, 6));
    EXPECT_EQ(cameras[1].pose.up, glm::dvec3(0, 0, 1));
    EXPECT_EQ(cameras[1].fovDegrees, 33.3);
    EXPECT_EQ(cameras[1].line, 4);
}

TEST(CameraPath, ErrorsNameTheLine) {
    try {
        parseCameraPath("0,0,0 0,0,-1 0,1,0 60\n\n0,0,0 0,0,-1 0,1,0 60 7\n", "p.txt");
        FAIL() << "no error";
    } catch (const SceneError& error) {
        EXPECT_STREQ(error.what(), "p.txt:3: error: expected 4 fields, POSITION TARGET UP FOV (as "
                                   "in 0,0,0 0,0,-1 0,1,0 60), got 5");
    }
}
