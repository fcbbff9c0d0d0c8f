// The LightMix panel lists groups, not lights (issue 21, docs/lightmix.md "Editor"): the default
// scene with a second softbox, both in group "key", rendered with --light-mix (48x36, `mis`).
//   - the panel shows one row "key" for the two lights (no row per light), then `environment`;
//   - one drag of that row's slider (press, three moves, release) scales BOTH lights'
//     intensities by the same factor, the slider's intensity over the first light's;
//   - the render remixes instead of restarting ("remixed: no restart"), and the frame it shows
//     equals the mix of its own layers with the key group's weight at that factor and every
//     other at 1 (to float rounding);
//   - the drag is ONE undo step: one undo restores both intensities exactly;
//   - no Vulkan validation message.
#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/lightmix_panel.h"

#include "render/session/light_groups.h"
#include "scene/scene_io.h"

#include <QSlider>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kTimeoutMs = 240000;

const scene::Light& lightNamed(const scene::Scene& s, const std::string& name) {
    return *std::find_if(s.lighting.lights.begin(), s.lighting.lights.end(),
                         [&](const scene::Light& l) { return l.name == name; });
}

} // namespace

class LightMixGroupsTest : public QObject {
    Q_OBJECT
private slots:
    void groupRowScalesItsLightsAsOneEdit();
};

void LightMixGroupsTest::groupRowScalesItsLightsAsOneEdit() {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 36;
    settings.sampler = render::SamplerKind::Mis;
    settings.lightMix = true;
    settings.relightPreview = false;
    settings.validation = qEnvironmentVariableIntValue("WAVELIT_VK_VALIDATION") == 1;
    MainWindow window(settings);
    window.show();

    const QString path = QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/ring_on_ground.wlscene");
    auto loaded = scene::loadScene(path.toStdString());
    QVERIFY2(loaded, loaded ? "" : loaded.error().message().c_str());
    auto twoSoftboxes = std::make_shared<scene::Scene>(std::move(*loaded));
    scene::Light second = twoSoftboxes->lighting.lights.front();
    second.id = 100;
    second.name = "softbox2";
    second.intensity = 35.0f;
    second.position = glm::vec3(-1.5f, 2.5f, 1.5f);
    second.direction = glm::vec3(0.5f, -0.7f, -0.5f);
    twoSoftboxes->lighting.lights.push_back(second);
    for (scene::Light& l : twoSoftboxes->lighting.lights) l.group = "key";
    window.document()->setScene(twoSoftboxes, path);
    QVERIFY(QTest::qWaitFor([&] { return window.renderer()->latestFrame().samplesPerPixel >= 2; }, kTimeoutMs));

    LightMixPanel* panel = window.lightMix();
    QCOMPARE(panel->rows().size(), size_t(2));
    QCOMPARE(panel->rows()[0].name, std::string("key"));
    QCOMPARE(panel->rows()[0].lights.size(), size_t(2));
    QCOMPARE(panel->rows()[1].name, std::string("environment"));
    QVERIFY(!panel->findChild<QSlider*>("slider:softbox") && !panel->findChild<QSlider*>("slider:softbox2"));
    auto* slider = panel->findChild<QSlider*>("slider:key");
    QVERIFY(slider);

    const scene::Scene before = *window.document()->scene();
    const float first = lightNamed(before, "softbox").intensity, other = lightNamed(before, "softbox2").intensity;
    QUndoStack* undo = window.document()->undoStack();
    const int stepsBefore = undo->count();
    const quint64 generationBefore = window.renderer()->generation();

    // One drag: press, three moves (up 0.4 decades, up 0.2, down 0.1), release.
    slider->setSliderDown(true);
    const int start = slider->value();
    for (int step : {40, 60, 50}) slider->setValue(start + step);
    slider->setSliderDown(false);
    QCOMPARE(undo->count(), stepsBefore + 1);

    const scene::Scene after = *window.document()->scene();
    const double factor = double(lightNamed(after, "softbox").intensity) / first;
    const double otherFactor = double(lightNamed(after, "softbox2").intensity) / other;
    qInfo("slider: %d -> %d; softbox %.4f -> %.4f, softbox2 %.4f -> %.4f (factors %.6f, %.6f)", start,
          slider->value(), first, lightNamed(after, "softbox").intensity, other,
          lightNamed(after, "softbox2").intensity, factor, otherFactor);
    QVERIFY(std::abs(factor - std::pow(10.0, 50.0 / 100.0)) < 0.02 * factor); // 50 steps = 0.5 decades
    QVERIFY(std::abs(otherFactor - factor) <= 1e-5 * factor);

    // The frame after the drag: a remix of the render's layers with the key group at `factor`.
    QVERIFY(QTest::qWaitFor([&] {
        const RenderFrame& f = window.renderer()->latestFrame();
        return f.generation == window.renderer()->generation() && f.image && f.layers;
    }, kTimeoutMs));
    const RenderFrame frame = window.renderer()->latestFrame();
    qInfo("after the drag: %s, %d spp (generations %llu -> %llu)", qPrintable(frame.lastUpdate),
          frame.samplesPerPixel, (unsigned long long)generationBefore, (unsigned long long)frame.generation);
    QVERIFY(frame.lastUpdate.startsWith("remixed: no restart"));
    const render::LightGroups groups = render::lightGroupsOf(*frame.layersScene);
    QCOMPARE(groups.size(), frame.layers->size());
    std::vector<glm::vec3> weights(groups.size(), glm::vec3(1.0f));
    const size_t key = size_t(std::find(groups.names.begin(), groups.names.end(), "key") - groups.names.begin());
    QVERIFY(key < groups.size());
    QCOMPARE(lightNamed(*frame.layersScene, "softbox").intensity, first); // the render did not restart
    weights[key] = glm::vec3(float(factor));
    const util::ImageRGB expected = render::mixGroupLayers(*frame.layers, weights);
    double worst = 0.0, keyShare = 0.0;
    for (size_t i = 0; i < expected.pixels.size(); ++i) {
        keyShare += util::luminance((*frame.layers)[key].pixels[i]);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, double(std::abs(expected.pixels[i][c] - frame.image->pixels[i][c])) /
                                        std::max(1e-3, double(std::abs(expected.pixels[i][c]))));
    }
    qInfo("frame against the mix of its layers (key x %.4f): worst relative difference %.2e; key layer mean %.4f",
          factor, worst, keyShare / double(expected.pixels.size()));
    QVERIFY(keyShare > 0.0); // the key layer lights the image: the weight matters
    QVERIFY(worst <= 1e-5);

    // One undo restores both lights.
    undo->undo();
    const scene::Scene undone = *window.document()->scene();
    QCOMPARE(lightNamed(undone, "softbox").intensity, first);
    QCOMPARE(lightNamed(undone, "softbox2").intensity, other);
    QCOMPARE(undo->count(), stepsBefore + 1); // undone, still redoable
    QCOMPARE(undo->index(), stepsBefore);
    QCOMPARE(frame.validationMessages, 0);
}

QTEST_MAIN(LightMixGroupsTest)
#include "lightmix_groups_test.moc"
