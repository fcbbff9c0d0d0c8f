// The outline with real keys (issue 14): with a light selected and the outline focused, Ctrl+D
// duplicates it ("<name> copy", selected), F2's rename is refused for a taken name, Del deletes
// the copy, and Ctrl+Z (Edit -> Undo) brings it back — each one undo step. Del typed into a
// property's text field edits the text and deletes nothing.
#include "app/main_window.h"
#include "app/outline_actions.h"
#include "app/scene_document.h"
#include "panels/outline_panel.h"
#include "panels/property_panel.h"

#include <QLineEdit>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

class PanelsOutlineKeysTest : public QObject {
    Q_OBJECT
private slots:
    void keysEditTheOutline();
};

namespace {

QStringList lightNames(const MainWindow& window) {
    QStringList names;
    for (const auto& light : window.document()->scene()->lighting.lights) names << QString::fromStdString(light.name);
    return names;
}

} // namespace

void PanelsOutlineKeysTest::keysEditTheOutline() {
    RenderSettings settings;
    settings.width = 32;
    settings.height = 32;
    settings.sampler = render::SamplerKind::Bsdf;
    settings.maxSamplesPerPixel = 1;
    settings.validation = qEnvironmentVariableIntValue("WAVELIT_VK_VALIDATION") == 1;
    MainWindow window(settings);
    window.show();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.document()->open(QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/glossy_sphere.wlscene"));
    QVERIFY(QTest::qWaitFor([&] { return window.document()->scene() != nullptr; }, 60000));
    QCOMPARE(lightNames(window), QStringList{"sun"});
    const scene::EntityId sun = window.document()->scene()->lighting.lights.front().id;
    QTreeWidget* tree = window.outline()->tree();
    QVERIFY(window.outline()->select({scene::EntityKind::Light, sun}));
    tree->setFocus();
    QVERIFY(QTest::qWaitFor([&] { return tree->hasFocus(); }, 5000));

    QTest::keyClick(tree, Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(lightNames(window), (QStringList{"sun", "sun copy"}));
    auto selected = window.outline()->selectedEntity();
    QVERIFY(selected && selected->id != sun); // the copy is selected
    QVERIFY(!window.outlineActions()->rename(*selected, "sun")); // taken: refused

    tree->setFocus();
    QTest::keyClick(tree, Qt::Key_Delete);
    QCOMPARE(lightNames(window), QStringList{"sun"});
    QTest::keyClick(tree, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(lightNames(window), (QStringList{"sun", "sun copy"}));
    QCOMPARE(window.document()->undoStack()->index(), 1); // duplicate; the delete was undone

    // Del in a text field of the property panel is text editing, not an outline delete.
    QVERIFY(window.outline()->select({scene::EntityKind::Light, sun}));
    auto* name = qobject_cast<QLineEdit*>(window.properties()->editorFor("name"));
    QVERIFY(name);
    name->setFocus();
    name->setCursorPosition(0);
    QTest::keyClick(name, Qt::Key_Delete);
    QCOMPARE(name->text(), QStringLiteral("un"));
    QCOMPARE(lightNames(window), (QStringList{"sun", "sun copy"}));
    // The field keeps its uncommitted text: destroying the window with it is safe
    // (viewport_window_teardown_test covers that case on its own).
}

QTEST_MAIN(PanelsOutlineKeysTest)
#include "panels_outline_keys_test.moc"
