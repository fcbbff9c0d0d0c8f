// LightMixPanel (docs/lightmix.md): one row per light group plus the environment (and emission);
// changing a one-member row's mute box or intensity box asks for exactly that property edit; a
// group of lights is one row whose slider asks for ONE change set scaling every member by the same
// factor; solo silences every other row; showing a scene updates the values without asking for
// edits; the rows follow added lights. The outline's light check boxes ask for mutes.
#include "panels/lightmix_panel.h"
#include "panels/outline_panel.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalSpy>
#include <QTreeWidget>
#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

scene::Scene twoLights() {
    scene::Scene s;
    scene::Light key, lamp;
    key.id = 1;
    key.name = "key";
    key.intensity = 40.0f;
    key.color = glm::vec3(1.0f, 0.5f, 0.0f);
    lamp.id = 2;
    lamp.name = "lamp";
    lamp.group = "practicals";
    lamp.muted = true;
    s.lighting.lights = {key, lamp};
    s.lighting.environment.intensity = 0.5f;
    return s;
}

PropertyEdit only(QSignalSpy& spy) {
    if (spy.count() != 1) qFatal("expected one edit, got %d", int(spy.count()));
    return spy.takeFirst().at(0).value<PropertyEdit>();
}

} // namespace

class LightMixPanelTest : public QObject {
    Q_OBJECT
private slots:
    void showsEveryLightAndTheEnvironment() {
        LightMixPanel panel;
        panel.setScene(twoLights());
        auto* key = panel.findChild<QDoubleSpinBox*>("intensity:key");
        auto* mute = panel.findChild<QCheckBox*>("mute:practicals");
        auto* env = panel.findChild<QDoubleSpinBox*>("intensity:environment");
        QVERIFY(key && mute && env && panel.findChild<QLabel*>("swatch:key"));
        QCOMPARE(key->value(), 40.0);
        QVERIFY(mute->isChecked());
        QVERIFY(!panel.findChild<QCheckBox*>("mute:key")->isChecked());
        QCOMPARE(env->value(), 0.5);
        QVERIFY(panel.findChild<QLabel*>("swatch:key")->styleSheet().contains("rgb(255, 128, 0)"));
    }

    void editsAreRequestedPropertyByProperty() {
        LightMixPanel panel;
        panel.setScene(twoLights());
        QSignalSpy spy(&panel, &LightMixPanel::editRequested);
        panel.findChild<QDoubleSpinBox*>("intensity:key")->setValue(80.0);
        PropertyEdit e = only(spy);
        QCOMPARE(e.entity.kind, scene::EntityKind::Light);
        QCOMPARE(e.entity.id, scene::EntityId(1));
        QCOMPARE(e.name, std::string("intensity"));
        QCOMPARE(std::get<float>(e.value), 80.0f);
        panel.findChild<QCheckBox*>("mute:practicals")->setChecked(false);
        e = only(spy);
        QCOMPARE(e.entity.id, scene::EntityId(2));
        QCOMPARE(e.name, std::string("muted"));
        QCOMPARE(std::get<bool>(e.value), false);
        panel.findChild<QDoubleSpinBox*>("intensity:environment")->setValue(2.0);
        e = only(spy);
        QCOMPARE(e.entity.kind, scene::EntityKind::Environment);
        QCOMPARE(std::get<float>(e.value), 2.0f);
    }

    void showingASceneRequestsNoEditAndFollowsNewLights() {
        LightMixPanel panel;
        scene::Scene s = twoLights();
        panel.setScene(s);
        QSignalSpy spy(&panel, &LightMixPanel::editRequested);
        s.lighting.lights[0].intensity = 7.0f;
        s.lighting.lights[1].muted = false;
        panel.setScene(s);
        QCOMPARE(spy.count(), 0);
        QCOMPARE(panel.findChild<QDoubleSpinBox*>("intensity:key")->value(), 7.0);
        QVERIFY(!panel.findChild<QCheckBox*>("mute:practicals")->isChecked());
        scene::Light rim;
        rim.id = 3;
        rim.name = "rim";
        s.lighting.lights.push_back(rim);
        panel.setScene(s);
        QVERIFY(panel.findChild<QDoubleSpinBox*>("intensity:rim") != nullptr);
        QCOMPARE(spy.count(), 0);
    }

    void lightsOfOneGroupAreOneRow() {
        scene::Scene s = twoLights();
        s.lighting.lights[0].group = "practicals"; // key joins lamp
        s.lighting.lights[1].intensity = 30.0f;
        s.lighting.lights[1].muted = false;
        scene::Material glow;
        glow.id = 7;
        glow.name = "glow";
        glow.emission = glm::vec3(2.0f);
        scene::Object panelObject;
        panelObject.id = 8;
        panelObject.name = "panel";
        panelObject.materialId = 7;
        s.materials = {glow};
        s.objects = {panelObject};
        LightMixPanel panel;
        panel.setScene(s);
        QCOMPARE(panel.rows().size(), size_t(3));
        QCOMPARE(panel.rows()[0].name, std::string("practicals"));
        QCOMPARE(panel.rows()[0].lights.size(), size_t(2));
        QCOMPARE(panel.rows()[1].name, std::string("environment"));
        QCOMPARE(panel.rows()[2].name, std::string("emission"));
        QVERIFY(!panel.findChild<QDoubleSpinBox*>("intensity:key"));
        QVERIFY(!panel.findChild<QDoubleSpinBox*>("intensity:lamp"));
        QVERIFY(panel.findChild<QLabel*>("label:practicals")->text().contains("2 lights"));
        QCOMPARE(panel.findChild<QDoubleSpinBox*>("intensity:practicals")->value(), 40.0); // the first member's

        QSignalSpy single(&panel, &LightMixPanel::editRequested);
        QSignalSpy group(&panel, &LightMixPanel::groupEditRequested);
        panel.findChild<QDoubleSpinBox*>("intensity:practicals")->setValue(10.0); // x 0.25
        QCOMPARE(single.count(), 0);
        QCOMPARE(group.count(), 1);
        auto changes = group.takeFirst().at(0).value<scene::ChangeSet>();
        scene::Scene after = s;
        QVERIFY(changes.apply(after));
        QCOMPARE(after.lighting.lights[0].intensity, 10.0f);
        QCOMPARE(after.lighting.lights[1].intensity, 7.5f);
        QCOMPARE(changes.edits().size(), size_t(2));

        // Solo the environment: both lights muted and the emission off, as one change set.
        qobject_cast<QAbstractButton*>(panel.findChild<QWidget*>("solo:environment"))->click();
        QCOMPARE(group.count(), 1);
        changes = group.takeFirst().at(0).value<scene::ChangeSet>();
        after = s;
        QVERIFY(changes.apply(after));
        QVERIFY(after.lighting.lights[0].muted && after.lighting.lights[1].muted);
        QCOMPARE(after.materials[0].emission, glm::vec3(0.0f));
        QCOMPARE(after.lighting.environment.intensity, 0.5f);
        // The emission row stays while muted, and unmuting restores the emission.
        panel.setScene(after);
        QVERIFY(panel.findChild<QCheckBox*>("mute:emission")->isChecked());
        panel.findChild<QCheckBox*>("mute:emission")->setChecked(false);
        QCOMPARE(single.count(), 1);
        PropertyEdit e = single.takeFirst().at(0).value<PropertyEdit>();
        QCOMPARE(e.name, std::string("emission"));
        QCOMPARE(std::get<glm::vec3>(e.value), glm::vec3(2.0f));
    }

    // The outline's light rows carry a check box: checked = emits; unchecking asks for a mute.
    void outlineCheckBoxesMuteLights() {
        OutlinePanel outline;
        outline.setScene(twoLights());
        QTreeWidgetItem* key = nullptr;
        QTreeWidgetItem* lamp = nullptr;
        for (QTreeWidgetItemIterator it(outline.tree()); *it; ++it) {
            if ((*it)->text(0) == "key") key = *it;
            if ((*it)->text(0) == "lamp") lamp = *it;
        }
        QVERIFY(key && lamp);
        QCOMPARE(key->checkState(0), Qt::Checked);
        QCOMPARE(lamp->checkState(0), Qt::Unchecked); // muted
        QSignalSpy mute(&outline, &OutlinePanel::muteRequested);
        key->setCheckState(0, Qt::Unchecked);
        QTRY_COMPARE(mute.count(), 1);
        QCOMPARE(mute.at(0).at(0).value<scene::EntityId>(), scene::EntityId(1));
        QCOMPARE(mute.at(0).at(1).toBool(), true);
        outline.setScene(twoLights()); // a rebuild asks for nothing
        QTest::qWait(10);
        QCOMPARE(mute.count(), 1);
    }
};

QTEST_MAIN(LightMixPanelTest)
#include "lightmix_panel_test.moc"
