// The editor camera without a window: the pose's rays against the engine's CameraSpec
// projection, its camera string against parse_camera_spec, a glTF camera taken over,
// and the input mapping that moves the pose.
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include <sherpa/scene/scene_loader.h>

#include "compare_state.h"
#include "cull_history.h"
#include "culling_monitor.h"
#include "editor_settings.h"
#include "motion_playback.h"
#include "orbit_camera.h"
#include "test_assets.h"
#include "view_catalog.h"

namespace {
// Where `p` lands in normalised device coordinates through `spec`.
glm::vec2 ndc_of(const sherpa::scene::CameraSpec& spec, glm::vec3 p) {
    const glm::vec4 clip = spec.view_projection() * glm::vec4(p, 1.0f);
    return glm::vec2(clip) / clip.w;
}
bool near(glm::vec3 a, glm::vec3 b, float eps = 1e-4f) {
    return glm::length(a - b) <= eps * std::max(1.0f, glm::length(b));
}
} // namespace

using namespace sherpa;
using namespace sherpa::editor;

class CameraStateTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void poseRaysAgreeWithTheProjection();
    void poseReadsBackFromItsStringAndSpec();
    void poseTakesAGltfCamera();
    void cameraInputMovesThePose();

private:
    QTemporaryDir settings_dir_;
};

void CameraStateTests::initTestCase() {
    QVERIFY(settings_dir_.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir_.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_dir_.path());
    QSettings().clear();
    qputenv("XDG_CACHE_HOME", (settings_dir_.path() + QStringLiteral("/cache")).toUtf8());
}

void CameraStateTests::poseRaysAgreeWithTheProjection() {
    OrbitPose pose;
    pose.yaw = 0.0f;
    pose.pitch = 0.0f;
    QVERIFY(near(pose.forward(), glm::vec3(0, 0, -1))); // glTF's default camera
    pose.target = {1.0f, 2.0f, -3.0f};
    pose.yaw = -0.7f;
    pose.pitch = 0.4f;
    pose.distance = 6.0f;
    pose.aspect = 1.5f;
    QVERIFY(near(pose.eye(), pose.target - pose.forward() * pose.distance));
    QVERIFY(glm::length(ndc_of(pose.spec(), pose.target)) < 1e-5f); // the target is centred
    glm::vec3 right, up;
    pose.axes(right, up);
    QVERIFY(std::abs(glm::dot(right, pose.forward())) < 1e-6f);
    QVERIFY(std::abs(glm::dot(up, pose.forward())) < 1e-6f);
    QVERIFY(up.y > 0.0f);
    // A ray through a point of the image hits what the engine's projection puts there.
    for (const glm::vec2 ndc : {glm::vec2(0.0f), glm::vec2(0.9f, -0.6f), glm::vec2(-1.0f, 1.0f)}) {
        glm::vec3 origin, direction;
        pose.ray(ndc, origin, direction);
        QVERIFY(near(origin, pose.eye()));
        QCOMPARE(glm::length(direction), 1.0f);
        const glm::vec2 back = ndc_of(pose.spec(), origin + direction * 4.0f);
        QVERIFY2(
            glm::length(back - ndc) < 1e-4f,
            qPrintable(
                QStringLiteral("%1 %2 -> %3 %4").arg(ndc.x).arg(ndc.y).arg(back.x).arg(back.y)));
    }
}

void CameraStateTests::poseReadsBackFromItsStringAndSpec() {
    OrbitPose pose;
    pose.target = {0.5f, -1.0f, 2.0f};
    pose.yaw = 2.0f;
    pose.pitch = -0.3f;
    pose.distance = 3.5f;
    pose.fov_degrees = 45.0f;
    pose.near_plane = 0.01f;
    scene::CameraSpec parsed;
    std::string error;
    QVERIFY2(parse_camera_spec(pose.toString(), parsed, error), error.c_str());
    QVERIFY(near(parsed.eye, pose.eye()));
    QVERIFY(near(parsed.target, pose.target));
    QCOMPARE(parsed.fov_y_degrees, 45.0f);
    QCOMPARE(parsed.near_plane, 0.01f);
    // From the spec back to a pose: the same camera, the lens kept.
    OrbitPose lens;
    lens.fov_degrees = 45.0f;
    lens.aspect = 2.0f;
    const OrbitPose again = orbit_pose_from(pose.spec(), lens);
    QVERIFY(near(again.eye(), pose.eye()));
    QVERIFY(near(again.target, pose.target));
    QCOMPARE(again.aspect, 2.0f);
    QCOMPARE(again.near_plane, 0.01f);
    // Straight down is past the pitch limit: the pose keeps a valid up.
    scene::CameraSpec down;
    down.eye = {0, 10, 0};
    down.target = {0, 0, 0};
    const OrbitPose clamped = orbit_pose_from(down, lens);
    QCOMPARE(clamped.pitch, OrbitPose::kPitchLimit);
    QCOMPARE(clamped.distance, 10.0f);
}

void CameraStateTests::poseTakesAGltfCamera() {
    scene::Scene scene;
    scene::Camera cam;
    cam.yfov = glm::radians(30.0f);
    cam.znear = 0.2f;
    scene.cameras.push_back(cam);
    scene::PlacedCamera placed;
    // At (0, 1, 10), turned 90 degrees about +Y: looks down -X.
    placed.world = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 10)) *
                   glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
    scene.placed_cameras.push_back(placed);
    scene.bounds = core::Aabb::from_min_max({-1, -1, -1}, {1, 1, 1});
    const OrbitPose before;
    QVERIFY(orbit_pose_at_camera(scene, 1, before).toString() == before.toString()); // no such
    const OrbitPose pose = orbit_pose_at_camera(scene, 0, before);
    QVERIFY(near(pose.eye(), glm::vec3(0, 1, 10)));
    QVERIFY(near(pose.forward(), glm::vec3(-1, 0, 0)));
    QVERIFY(std::abs(pose.distance - glm::length(glm::vec3(0, 1, 10))) < 1e-4f);
    QVERIFY(std::abs(pose.fov_degrees - 30.0f) < 1e-4f);
    QCOMPARE(pose.near_plane, 0.2f);
}

void CameraStateTests::cameraInputMovesThePose() {
    OrbitCamera cam;
    cam.setAspect(0.0f);
    QCOMPARE(cam.pose().aspect, 1.0f); // no aspect: square
    cam.setAspect(1.5f);
    // Orbit: 0.3 degrees per pixel, the pitch held short of the poles.
    const float yaw = cam.pose().yaw;
    cam.orbit(100.0f, 0.0f);
    QVERIFY(std::abs(cam.pose().yaw - (yaw - glm::radians(30.0f))) < 1e-5f);
    cam.orbit(0.0f, 1e6f);
    QCOMPARE(cam.pose().pitch, OrbitPose::kPitchLimit);
    cam.orbit(0.0f, -2e6f);
    QCOMPARE(cam.pose().pitch, -OrbitPose::kPitchLimit);
    cam.orbit(0.0f, 250.0f); // a pitch of about -14 degrees
    // Look turns in place: the eye stays.
    const glm::vec3 eye = cam.pose().eye();
    cam.look(40.0f, -25.0f);
    QVERIFY(near(cam.pose().eye(), eye));
    // Pan: the point under the cursor follows it, pixel for pixel.
    const float height = 600.0f, width = height * cam.pose().aspect;
    const glm::vec3 target = cam.pose().target;
    cam.pan(30.0f, -12.0f, height);
    const glm::vec2 moved = ndc_of(cam.pose().spec(), target);
    QVERIFY(std::abs(moved.x * width / 2.0f - 30.0f) < 1e-2f);
    QVERIFY(std::abs(-moved.y * height / 2.0f - -12.0f) < 1e-2f); // screen y is down
    // Dolly: 0.85 per notch, never through the target.
    const float d = cam.pose().distance;
    cam.dolly(2.0f);
    QVERIFY(std::abs(cam.pose().distance - d * 0.85f * 0.85f) < 1e-5f);
    cam.dolly(1e4f);
    QCOMPARE(cam.pose().distance, 1e-4f);
    cam.dolly(-80.0f);
    // Fly: eye and target move together, the direction stays.
    const OrbitPose before = cam.pose();
    cam.fly({1.0f, 2.0f, 3.0f});
    glm::vec3 right, up;
    before.axes(right, up);
    const glm::vec3 step = right + 2.0f * up + 3.0f * before.forward();
    QVERIFY(near(cam.pose().target, before.target + step));
    QVERIFY(near(cam.pose().eye(), before.eye() + step));
    QVERIFY(near(cam.pose().forward(), before.forward()));
}

QTEST_GUILESS_MAIN(CameraStateTests)
#include "camera_state_tests.moc"
