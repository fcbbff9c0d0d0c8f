// Property rows come from the registry (one per applicable property, IdRefs shown by name), the
// panel shows them, entity names resolve for scripts, and edits report their cost.
#include "commands/property_command.h"
#include "commands/property_edit.h"
#include "panels/outline_panel.h"
#include "panels/property_panel.h"
#include "panels/property_rows.h"

#include "scene/scene_io.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSlider>
#include <QTableWidget>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

scene::Scene makeScene() {
    scene::Scene s;
    s.name = "test";
    scene::Material gold;
    gold.id = 1;
    gold.name = "Gold";
    gold.brdf = "ggx";
    gold.roughness = 0.25f;
    s.materials.push_back(gold);
    scene::Object ring;
    ring.id = 2;
    ring.name = "Ring";
    ring.meshPath = "meshes/ring.obj";
    ring.materialId = 1;
    s.objects.push_back(ring);
    scene::Light sun;
    sun.id = 3;
    sun.name = "Sun";
    sun.type = scene::LightType::Sun;
    scene::Light bulb;
    bulb.id = 4;
    bulb.name = "Bulb";
    bulb.type = scene::LightType::Point;
    s.lighting.lights = {sun, bulb};
    return s;
}

const PropertyRow* findRow(const std::vector<PropertyRow>& rows, const std::string& name) {
    for (const auto& r : rows)
        if (r.info->name == name) return &r;
    return nullptr;
}

} // namespace

class PropertyRowsTest : public QObject {
    Q_OBJECT
private slots:
    void rowsFollowRegistry() {
        const scene::Scene s = makeScene();
        const auto rows = propertyRows(s, {scene::EntityKind::Material, 1});
        QCOMPARE(rows.size(), scene::properties(scene::EntityKind::Material).size());
        const PropertyRow* roughness = findRow(rows, "roughness");
        QVERIFY(roughness);
        QCOMPARE(roughness->value, scene::formatValue(0.25f));
        QCOMPARE(findRow(rows, "name")->value, scene::formatValue(std::string("Gold")));
    }
    void idRefShowsName() {
        const scene::Scene s = makeScene();
        const auto rows = propertyRows(s, {scene::EntityKind::Object, 2});
        const PropertyRow* material = findRow(rows, "material");
        QVERIFY(material);
        QCOMPARE(material->value, std::string("Gold"));
    }
    void onlyApplicableLightRows() {
        const scene::Scene s = makeScene();
        const auto sun = propertyRows(s, {scene::EntityKind::Light, 3});
        QVERIFY(findRow(sun, "angularDiameter"));
        QVERIFY(!findRow(sun, "position")); // a sun has a direction, not a position
        const auto bulb = propertyRows(s, {scene::EntityKind::Light, 4});
        QVERIFY(findRow(bulb, "position"));
        QVERIFY(!findRow(bulb, "angularDiameter"));
    }
    void missingEntityHasNoRows() {
        QVERIFY(propertyRows(makeScene(), {scene::EntityKind::Material, 99}).empty());
    }
    void namesResolve() {
        const scene::Scene s = makeScene();
        QCOMPARE(findEntityByName(s, "Ring"), std::optional(EntityRef{scene::EntityKind::Object, 2}));
        QCOMPARE(findEntityByName(s, "CAMERA")->kind, scene::EntityKind::Camera);
        QVERIFY(!findEntityByName(s, "Nope"));
        QCOMPARE(entityName(s, {scene::EntityKind::Light, 4}), std::string("Bulb"));
    }
    void editsReportCostAndKeepOriginal() {
        const scene::Scene s = makeScene();
        auto rough = applyEdit(s, {{scene::EntityKind::Material, 1}, "roughness", 0.5f});
        QVERIFY(rough.ok());
        QCOMPARE(rough->change, scene::ChangeKind::Restart);
        QCOMPARE(rough->scene->materials[0].roughness, 0.5f);
        QCOMPARE(std::get<float>(rough->previous), 0.25f);
        QCOMPARE(s.materials[0].roughness, 0.25f); // the snapshot is untouched

        auto exposure = applyEdit(s, {{scene::EntityKind::Camera, 0}, "exposure", 1.5f});
        QVERIFY(exposure.ok());
        QCOMPARE(exposure->change, scene::ChangeKind::Display);

        auto unknown = applyEdit(s, {{scene::EntityKind::Material, 1}, "shininess", 1.0f});
        QVERIFY(!unknown.ok());
        QVERIFY(unknown.error().message().find("shininess") != std::string::npos);
        auto outOfRange = applyEdit(s, {{scene::EntityKind::Material, 1}, "roughness", 2.0f});
        QVERIFY(!outOfRange.ok());
    }
    void commandsMergeOnlyWithinAGesture() {
        auto current = std::make_shared<const scene::Scene>(makeScene());
        auto commit = [&](const PropertyEdit& e) {
            auto applied = applyEdit(*current, e);
            QVERIFY(applied.ok());
            current = applied->scene;
        };
        QUndoStack stack;
        const EntityRef gold{scene::EntityKind::Material, 1};
        auto push = [&](PropertyEdit edit) {
            auto applied = applyEdit(*current, edit);
            QVERIFY(applied.ok());
            stack.push(new PropertyCommand(edit, applied->previous, commit));
        };
        // Three separate edits (no gesture: typed values, script calls): three steps.
        for (float r : {0.3f, 0.4f, 0.5f}) push({gold, "roughness", r});
        QCOMPARE(stack.count(), 3);
        // One drag (one gesture): one step, even across many values.
        const GestureId drag = newGestureId();
        QVERIFY(drag != kNoGesture);
        for (float r : {0.6f, 0.7f, 0.8f}) push({gold, "roughness", r, drag});
        QCOMPARE(stack.count(), 4);
        // A second drag of the same property is a step of its own.
        const GestureId secondDrag = newGestureId();
        QVERIFY(secondDrag != drag);
        for (float r : {0.85f, 0.9f}) push({gold, "roughness", r, secondDrag});
        QCOMPARE(stack.count(), 5);
        const EntityRef ring{scene::EntityKind::Object, 2};
        push({ring, "translation", glm::vec3(0, 1, 0), secondDrag}); // another property: never merges
        QCOMPARE(stack.count(), 6);
        QCOMPARE(current->materials[0].roughness, 0.9f);
        stack.undo();
        QCOMPARE(current->objects[0].transform.translation, glm::vec3(0.0f));
        stack.undo();
        QCOMPARE(current->materials[0].roughness, 0.8f); // the second drag, whole
        stack.undo();
        QCOMPARE(current->materials[0].roughness, 0.5f); // the first drag, whole
        stack.undo();
        QCOMPARE(current->materials[0].roughness, 0.4f); // one typed edit at a time
        stack.redo();
        QCOMPARE(current->materials[0].roughness, 0.5f);
    }
    void entityNamesResolveByKind() {
        scene::Scene s = makeScene();
        scene::Material ground;
        ground.id = 5;
        ground.name = "ground";
        s.materials.push_back(ground);
        scene::Object groundObject;
        groundObject.id = 6;
        groundObject.name = "ground";
        groundObject.materialId = 5;
        s.objects.push_back(groundObject);

        QCOMPARE(resolveEntity(s, "material:ground").value(), (EntityRef{scene::EntityKind::Material, 5}));
        QCOMPARE(resolveEntity(s, "object:ground").value(), (EntityRef{scene::EntityKind::Object, 6}));
        QCOMPARE(resolveEntity(s, "light:Sun").value(), (EntityRef{scene::EntityKind::Light, 3}));
        QCOMPARE(resolveEntity(s, "Ring").value(), (EntityRef{scene::EntityKind::Object, 2}));
        QCOMPARE(resolveEntity(s, "camera").value().kind, scene::EntityKind::Camera);
        auto ambiguous = resolveEntity(s, "ground");
        QVERIFY(!ambiguous.ok());
        const QString message = QString::fromStdString(ambiguous.error().message());
        QVERIFY2(message.contains("object:ground") && message.contains("material:ground"), qPrintable(message));
        auto wrongKind = resolveEntity(s, "light:ground");
        QVERIFY(!wrongKind.ok());
        QVERIFY(QString::fromStdString(wrongKind.error().message()).contains("light:ground"));
        QCOMPARE(qualifiedName(s, {scene::EntityKind::Material, 5}), std::string("material:ground"));
        QCOMPARE(qualifiedName(s, {scene::EntityKind::Environment, 0}), std::string("environment"));
    }
    void panelEditsGoThroughSignalAndRefreshInPlace() {
        scene::Scene s = makeScene();
        PropertyPanel panel;
        const EntityRef gold{scene::EntityKind::Material, 1};
        panel.showEntity(s, gold);
        QWidget* row = panel.editorFor("roughness");
        QVERIFY(row);
        auto* roughness = row->findChild<QDoubleSpinBox*>("spin");
        QVERIFY(roughness);
        QCOMPARE(roughness->value(), 0.25);
        QCOMPARE(roughness->minimum(), 0.0); // the registry's range
        QCOMPARE(roughness->maximum(), 1.0);

        QSignalSpy spy(&panel, &PropertyPanel::editRequested);
        roughness->setValue(0.5);
        QCOMPARE(spy.count(), 1);
        const auto edit = spy.takeFirst().at(0).value<PropertyEdit>();
        QCOMPARE(edit.entity, gold);
        QCOMPARE(edit.name, std::string("roughness"));
        QCOMPARE(std::get<float>(edit.value), 0.5f);
        QCOMPARE(edit.gesture, kNoGesture); // a value set without a gesture stands alone
        QCOMPARE(s.materials[0].roughness, 0.25f); // the panel never edits the scene itself

        // A slider drag: every value it sends shares one gesture; the next drag gets another.
        auto* slider = row->findChild<QSlider*>("slider");
        QVERIFY(slider);
        auto drag = [&](std::initializer_list<int> positions) {
            slider->setSliderDown(true); // sliderPressed, as a mouse press on the handle
            for (int p : positions) slider->setValue(p);
            slider->setSliderDown(false);
        };
        drag({600, 700, 800});
        QCOMPARE(spy.count(), 3);
        const GestureId first = spy.at(0).at(0).value<PropertyEdit>().gesture;
        QVERIFY(first != kNoGesture);
        for (int i = 0; i < 3; ++i) QCOMPARE(spy.at(i).at(0).value<PropertyEdit>().gesture, first);
        QCOMPARE(std::get<float>(spy.at(2).at(0).value<PropertyEdit>().value), 0.8f);
        QCOMPARE(roughness->value(), 0.8); // the spin box follows the slider
        spy.clear();
        drag({300});
        QCOMPARE(spy.count(), 1);
        QVERIFY(spy.at(0).at(0).value<PropertyEdit>().gesture != first);
        spy.clear();

        // The document's answer (here: an undo back to 0.25) refreshes the same widget, silently.
        s.materials[0].roughness = 0.125f;
        panel.showEntity(s, gold);
        QCOMPARE(panel.editorFor("roughness"), row);
        QCOMPARE(roughness->value(), 0.125);
        QCOMPARE(slider->value(), 125);
        QCOMPARE(spy.count(), 0);

        // Another entity rebuilds the rows.
        panel.showEntity(s, EntityRef{scene::EntityKind::Object, 2});
        QVERIFY(!panel.editorFor("roughness"));
        QVERIFY(panel.editorFor("translation"));
    }
    void panelsShowScene() {
        const scene::Scene s = makeScene();
        OutlinePanel outline;
        outline.setScene(s);
        QCOMPARE(outline.namesUnder("Objects"), QStringList{"Ring"});
        QCOMPARE(outline.namesUnder("Materials"), QStringList{"Gold"});
        QCOMPARE(outline.namesUnder("Lighting"), (QStringList{"Environment", "Sun", "Bulb"}));

        PropertyPanel panel;
        std::optional<EntityRef> selected;
        connect(&outline, &OutlinePanel::entitySelected, this,
                [&](std::optional<EntityRef> ref) { selected = ref; });
        QVERIFY(outline.select({scene::EntityKind::Object, 2}));
        QVERIFY(selected);
        panel.showEntity(s, selected);
        const auto rows = propertyRows(s, *selected);
        QCOMPARE(panel.table()->rowCount(), int(rows.size()));
        QCOMPARE(panel.title(), QString("Ring (object)"));
        auto* material = qobject_cast<QComboBox*>(panel.editorFor("material"));
        QVERIFY(material);
        QCOMPARE(material->currentText(), QString("Gold"));
        auto* translation = panel.editorFor("translation");
        QVERIFY(translation);
        QCOMPARE(translation->findChildren<QDoubleSpinBox*>().size(), 3); // one per component
        // Rebuilding the tree keeps the selection.
        outline.setScene(s);
        QCOMPARE(outline.selectedEntity(), std::optional(EntityRef{scene::EntityKind::Object, 2}));
    }
    void defaultSceneOutline() {
        // The bundled scene through the real loader: every entity listed, every row formatted.
        auto loaded = scene::loadScene(WAVELIT_DEFAULT_SCENE);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message().c_str());
        const scene::Scene& s = loaded.value();
        OutlinePanel outline;
        outline.setScene(s);
        QStringList objects, materials, lights{"Environment"};
        for (const auto& o : s.objects) objects << QString::fromStdString(o.name);
        for (const auto& m : s.materials) materials << QString::fromStdString(m.name);
        for (const auto& l : s.lighting.lights) lights << QString::fromStdString(l.name);
        QVERIFY(objects.size() >= 2); // the ring and the ground
        QCOMPARE(outline.namesUnder("Objects"), objects);
        QCOMPARE(outline.namesUnder("Materials"), materials);
        QCOMPARE(outline.namesUnder("Lighting"), lights);
        for (const auto& o : s.objects) {
            const auto rows = propertyRows(s, {scene::EntityKind::Object, o.id});
            const PropertyRow* material = findRow(rows, "material");
            QVERIFY(material);
            QCOMPARE(material->value, s.findMaterial(o.materialId)->name);
        }
    }
};

QTEST_MAIN(PropertyRowsTest)
#include "property_rows_test.moc"
