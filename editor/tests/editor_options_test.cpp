// The editor's command line: defaults, each flag, and bad usage named in the error.
#include "app/editor_options.h"

#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

class EditorOptionsTest : public QObject {
    Q_OBJECT
private slots:
    void defaults() {
        auto o = parseEditorOptions({"wavelit"});
        QVERIFY(o.ok());
        QCOMPARE(o->scenePath, defaultScenePath());
        QVERIFY(o->scenePath.endsWith("resources/scenes/ring_on_ground.wlscene"));
        QVERIFY(o->scriptPath.isEmpty());
        QCOMPARE(o->render.device, render::DeviceChoice::Auto);
        QCOMPARE(o->render.width, 0); // the scene's own render size
        QCOMPARE(o->render.maxSamplesPerPixel, 0);
    }
    void everyFlag() {
        auto o = parseEditorOptions({"wavelit", "a.wlscene", "--script", "s.js", "--device", "cpu",
                                     "--size", "128x96", "--max-spp", "16", "--validation"});
        QVERIFY(o.ok());
        QCOMPARE(o->scenePath, QString("a.wlscene"));
        QCOMPARE(o->scriptPath, QString("s.js"));
        QCOMPARE(o->render.device, render::DeviceChoice::Cpu);
        QCOMPARE(o->render.width, 128);
        QCOMPARE(o->render.height, 96);
        QCOMPARE(o->render.maxSamplesPerPixel, 16);
        QVERIFY(o->render.validation);
    }
    void badUsage_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown flag") << QStringList{"wavelit", "--bogus"} << "--bogus";
        QTest::newRow("missing value") << QStringList{"wavelit", "--script"} << "--script";
        QTest::newRow("bad device") << QStringList{"wavelit", "--device", "gpu"} << "gpu";
        QTest::newRow("bad size") << QStringList{"wavelit", "--size", "12"} << "12";
        QTest::newRow("zero size") << QStringList{"wavelit", "--size", "0x5"} << "0x5";
        QTest::newRow("negative spp") << QStringList{"wavelit", "--max-spp", "-3"} << "-3";
        QTest::newRow("two scenes") << QStringList{"wavelit", "a.wlscene", "b.wlscene"} << "b.wlscene";
    }
    void badUsage() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        auto o = parseEditorOptions(args);
        QVERIFY(!o.ok());
        QCOMPARE(o.error().kind, util::ErrorKind::Usage);
        QVERIFY2(QString::fromStdString(o.error().message()).contains(mentions),
                 o.error().message().c_str());
    }
};

QTEST_APPLESS_MAIN(EditorOptionsTest)
#include "editor_options_test.moc"
