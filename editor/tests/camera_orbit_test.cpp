// Camera orbit and dolly: distance and target kept, pitch clamped short of the poles, a full
// turn returns to the start.
#include "viewport/camera_orbit_handler.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QtTest>

#include <cmath>

using namespace wavelit;
using namespace wavelit::editor;

namespace {
// float trigonometry on O(1) coordinates: a few ulps times a handful of operations.
constexpr float kPositionTolerance = 1e-4f;

scene::Camera testCamera() {
    scene::Camera c;
    c.position = {1.0f, 2.0f, 3.0f};
    c.target = {0.5f, 0.0f, -1.0f};
    return c;
}
float distance(const scene::Camera& c) { return glm::length(c.position - c.target); }
float pitchDeg(const scene::Camera& c) {
    return glm::degrees(std::asin((c.position - c.target).y / distance(c)));
}
} // namespace

class CameraOrbitTest : public QObject {
    Q_OBJECT
private slots:
    void orbitKeepsDistanceAndTarget() {
        const scene::Camera c = testCamera();
        const scene::Camera o = orbitCamera(c, 37.0f, -12.0f);
        QVERIFY(glm::length(o.position - c.position) > 0.1f);
        QVERIFY(std::abs(distance(o) - distance(c)) < kPositionTolerance);
        QCOMPARE(o.target, c.target);
        QVERIFY(std::abs(pitchDeg(o) - (pitchDeg(c) - 12.0f)) < 1e-2f);
    }
    void fullTurnReturns() {
        const scene::Camera c = testCamera();
        const scene::Camera o = orbitCamera(c, 360.0f, 0.0f);
        QVERIFY(glm::length(o.position - c.position) < kPositionTolerance);
    }
    void pitchIsClamped() {
        const scene::Camera o = orbitCamera(testCamera(), 0.0f, 500.0f);
        QVERIFY(std::abs(pitchDeg(o) - kMaxPitchDeg) < 1e-2f);
        const scene::Camera u = orbitCamera(testCamera(), 0.0f, -500.0f);
        QVERIFY(std::abs(pitchDeg(u) + kMaxPitchDeg) < 1e-2f);
    }
    void dollyScalesDistance() {
        const scene::Camera c = testCamera();
        const scene::Camera d = dollyCamera(c, 0.5f);
        QVERIFY(std::abs(distance(d) - 0.5f * distance(c)) < kPositionTolerance);
        QVERIFY(glm::length(glm::normalize(d.position - d.target) -
                            glm::normalize(c.position - c.target)) < kPositionTolerance);
        QVERIFY(distance(dollyCamera(c, 0.0f)) == distance(c)); // refused, not collapsed
        QVERIFY(distance(dollyCamera(c, 1e-9f)) >= kMinDistance * 0.99f);
    }
    void degenerateCameraUnchanged() {
        scene::Camera c;
        c.position = c.target;
        QCOMPARE(orbitCamera(c, 10.0f, 10.0f).position, c.position);
    }
};

QTEST_MAIN(CameraOrbitTest)
#include "camera_orbit_test.moc"
