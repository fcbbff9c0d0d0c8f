// The property panel with real input (issue 14): a mouse drag on the roughness slider of the
// ring's material changes the scene's roughness to the value under the handle, as ONE undo step,
// and the viewport's image changes (an unchanged scene would render the same samples to the same
// image); a roughness typed outside [0, 1] is refused with a visible message and the value stays;
// the BRDF is a combo box of the plugin registry's names; a colour is a swatch (an HDR colour with
// an intensity beside it that scales it); a path has a file button.
#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/outline_panel.h"
#include "panels/property_panel.h"

#include "plugins/brdf.h"
#include "util/image.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QStyleOptionSlider>
#include <QUndoStack>
#include <QtTest>

#include <glm/vec3.hpp>

#include <cmath>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kTimeoutMs = 240000;
constexpr int kSpp = 8;

RenderSettings settings() {
    RenderSettings s;
    s.width = 48;
    s.height = 48;
    s.sampler = render::SamplerKind::Bsdf;
    s.maxSamplesPerPixel = kSpp;
    s.validation = qEnvironmentVariableIntValue("WAVELIT_VK_VALIDATION") == 1;
    return s;
}

std::shared_ptr<const util::ImageRGB> waitForImage(MainWindow& window) {
    const bool reached = QTest::qWaitFor(
        [&] { return window.renderer()->latestFrame().samplesPerPixel >= kSpp; }, kTimeoutMs);
    if (!reached) return nullptr;
    return window.renderer()->latestFrame().image;
}

double relativeRms(const util::ImageRGB& a, const util::ImageRGB& b) {
    double squares = 0.0, sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double d = util::luminance(a.pixels[i]) - util::luminance(b.pixels[i]);
        squares += d * d;
        sum += util::luminance(a.pixels[i]);
    }
    const double n = double(a.pixels.size());
    return std::sqrt(squares / n) / (sum / n);
}

// The centre of the slider's handle, and the point of the groove for a position.
QPoint handleCentre(QSlider* slider) {
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    return slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
}

float roughnessOf(const MainWindow& window) {
    return window.document()->scene()->materials.front().roughness; // "gold", the ring's
}

} // namespace

class PanelsRoughnessSliderTest : public QObject {
    Q_OBJECT
private slots:
    void sliderDragChangesRoughnessAndImage();
};

void PanelsRoughnessSliderTest::sliderDragChangesRoughnessAndImage() {
    MainWindow window(settings());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.document()->open(QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/ring_on_ground.wlscene"));
    QVERIFY(QTest::qWaitFor([&] { return window.document()->scene() != nullptr; }, kTimeoutMs));
    QCOMPARE(window.document()->scene()->materials.front().name, std::string("gold"));
    const auto before = waitForImage(window);
    QVERIFY(before);
    QVERIFY(window.outline()->select({scene::EntityKind::Material, window.document()->scene()->materials.front().id}));

    // The BRDF combo lists the plugin registry's names; colours are swatches; paths have "…".
    auto* brdf = qobject_cast<QComboBox*>(window.properties()->editorFor("brdf"));
    QVERIFY(brdf);
    QStringList names;
    for (int i = 0; i < brdf->count(); ++i) names << brdf->itemText(i);
    for (const std::string& n : plugins::brdfNames()) QVERIFY2(names.contains(QString::fromStdString(n)), qPrintable(names.join(",")));
    QCOMPARE(brdf->currentText(), QStringLiteral("ggx"));
    QWidget* base = window.properties()->editorFor("baseColor");
    QVERIFY(base && base->findChild<QPushButton*>("swatch"));
    QVERIFY(!base->findChild<QDoubleSpinBox*>("intensity")); // [0, 1]: no intensity
    QWidget* emission = window.properties()->editorFor("emission");
    QVERIFY(emission && emission->findChild<QDoubleSpinBox*>("intensity")); // HDR
    // The intensity beside an HDR swatch scales the colour: a black emission becomes white x 2.5
    // (typed and committed with Enter: one edit), and undo puts the black back.
    auto* strength = emission->findChild<QDoubleSpinBox*>("intensity");
    strength->setFocus();
    strength->selectAll();
    QTest::keyClicks(strength, "2.5");
    QTest::keyClick(strength, Qt::Key_Return);
    QCOMPARE(window.document()->scene()->materials.front().emission, glm::vec3(2.5f));
    window.document()->undoStack()->undo();
    QCOMPARE(window.document()->scene()->materials.front().emission, glm::vec3(0.0f));
    QWidget* file = window.properties()->editorFor("brdfFile");
    if (file) QVERIFY(file->findChild<QPushButton*>("browse"));

    // Drag the roughness slider's handle from 0.2 to about three quarters of the groove.
    QWidget* row = window.properties()->editorFor("roughness");
    QVERIFY(row);
    auto* slider = row->findChild<QSlider*>("slider");
    auto* spin = row->findChild<QDoubleSpinBox*>("spin");
    QVERIFY(slider && spin);
    QCOMPARE(spin->suffix(), QString()); // roughness has no unit; the range is the registry's
    QCOMPARE(spin->minimum(), 0.0);
    QCOMPARE(spin->maximum(), 1.0);
    const int stepsBefore = window.document()->undoStack()->index();
    const QPoint from = handleCentre(slider);
    const QPoint to(int(slider->width() * 0.75), from.y());
    QTest::mousePress(slider, Qt::LeftButton, Qt::NoModifier, from);
    for (int i = 1; i <= 8; ++i)
        QTest::mouseMove(slider, from + (to - from) * i / 8, 5);
    QTest::mouseRelease(slider, Qt::LeftButton, Qt::NoModifier, to);
    const float dragged = roughnessOf(window);
    qInfo("roughness after the drag: %.3f (slider %d of %d)", double(dragged), slider->value(), slider->maximum());
    QVERIFY2(dragged > 0.55f && dragged < 0.95f, "the drag did not move the roughness to the handle");
    QVERIFY(std::abs(double(dragged) - spin->value()) < 1e-6);
    QCOMPARE(window.document()->undoStack()->index(), stepsBefore + 1); // one drag, one step

    const auto after = waitForImage(window);
    QVERIFY(after);
    const double change = relativeRms(*before, *after);
    qInfo("image change: relative RMS %.4f", change);
    QVERIFY2(change > 0.01, "the roughness drag did not change the image");

    // Typed out of range: refused with a message, the value stays.
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, "1.5");
    QTest::keyClick(spin, Qt::Key_Return);
    const QString message = window.properties()->message();
    qInfo("refusal: %s", qPrintable(message));
    QVERIFY2(message.contains("Roughness") && message.contains("1.5"), qPrintable(message));
    QVERIFY(window.properties()->findChild<QLabel*>("propertyMessage")->isVisible());
    QCOMPARE(roughnessOf(window), dragged);

    // Undo the drag: one step back to 0.2.
    window.document()->undoStack()->undo();
    QCOMPARE(roughnessOf(window), 0.2f);
}

QTEST_MAIN(PanelsRoughnessSliderTest)
#include "panels_roughness_slider_test.moc"
