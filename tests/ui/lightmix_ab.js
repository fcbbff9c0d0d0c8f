// wavelit-args: --light-mix --size 48x36 --sampler mis
// wavelit-scene: scenes/glossy_sphere.wlscene
// LightMix in the editor (issue 21, docs/lightmix.md) on the glossy sphere under sun_sky (the
// courtyard map and one `sun` light): remix, mute, solo and undo keep the render's samples;
// snapshots and the A/B split view remix the same layers with each side's weights (checked by
// linearity: the sun's share scales exactly with its intensity); Extract sun adds a light and a
// mask as one undo step (on the city map: courtyard has no compact sun).
var out = app.environment("WAVELIT_SCRIPT_OUT");
var res = app.environment("WAVELIT_UI_RESOURCES");
var spp = app.waitForSamples(3, 300);
function remix(what) {
    spp = app.waitForSamples(spp + 1, 300);
    check(app.frameStatus().indexOf("remixed: no restart") == 0, what + " restarted the render: " + app.frameStatus());
    console.log(what + ": remixed at " + spp + " spp");
}

// Remix, mute, solo, undo.
app.setProperty("light:sun", "intensity", 10);
remix("sun intensity 10");
app.setMute("sun", true);
remix("mute sun");
check(app.getProperty("light:sun", "muted") === true, "sun not muted");
app.triggerAction("actionUndo");
check(app.getProperty("light:sun", "muted") === false, "undo did not unmute the sun");
remix("undo mute");
app.solo("sun");
check(app.getProperty("light:sun", "muted") === false, "solo muted the soloed light");
remix("solo sun");

// Snapshots: the sun at 10, at 1, and muted.
app.snapshot("bright");
app.setProperty("light:sun", "intensity", 1);
remix("sun intensity 1");
app.snapshot("dim");
app.setMute("sun", true);
remix("mute sun for a snapshot");
app.snapshot("dark");
app.triggerAction("actionUndo");
check(app.getProperty("light:sun", "muted") === false, "undo of the snapshot's mute");
remix("undo the snapshot's mute"); // compare() composes from the latest frame

// A/B: each side a remix of the same layers, so sun-only differences are exactly linear.
check(app.compare("bright", "dim"), "compare bright/dim");
var bd = app.compareMeans();
check(app.compare("dim", "dark"), "compare dim/dark");
var dk = app.compareMeans();
console.log("A/B means: bright " + bd[0] + ", dim " + bd[1] + " (" + dk[0] + "), dark " + dk[1]);
check(bd[1] == dk[0], "the same side gave two means within one frame: " + bd[1] + " vs " + dk[0]);
check(bd[0] > bd[1] && bd[1] > dk[1], "brighter sun, brighter side");
var ratio = (bd[0] - dk[1]) / (bd[1] - dk[1]);
check(Math.abs(ratio - 10) < 1e-3, "the sun's share should scale by 10 between bright and dim, got " + ratio);
app.setCompareWipe(0.3);
check(app.saveCompare(out + "/lightmix_ab.png"), "saveCompare");
// The open setup (sun at 1) against the setup on disk (sun at 5): the disk side is brighter.
check(app.compare("current", res + "/lighting/sun_sky.wllight"), "compare current/file");
var cf = app.compareMeans();
check(Math.abs(cf[0] - bd[1]) <= 1e-6 * bd[1], "the open setup (sun at 1) should be the dim side: " + cf[0] + " vs " + bd[1]);
check(cf[1] > cf[0], "the file's sun (5) should be brighter than the open setup's (1): " + cf);
// A side that differs in more than weights gets its own render: the open setup's sun moved, the
// viewport renders the moved sun, so "current" is a remix and the snapshot a render of its own.
app.setProperty("light:sun", "direction", [0.3, -0.9, 0.2]);
app.waitForSamples(1, 300);
var modes = app.compare("current", "bright");
console.log("modes with a moved sun: " + JSON.stringify(modes));
check(modes.a == "remix" && modes.b == "render", "current should remix, the unmoved snapshot render: " + JSON.stringify(modes));
var t0 = Date.now();
while (app.compareSamples()[1] < 2 && Date.now() - t0 < 120000) app.processEvents(50);
var rs = app.compareSamples();
check(rs[1] >= 2, "the render side did not render: " + rs);
var rm = app.compareMeans();
console.log("render side at " + rs[1] + " spp, means " + rm);
check(rm[1] > 0 && isFinite(rm[1]), "the render side's mean: " + rm);
check(app.validationMessages() == 0, "validation messages");
app.triggerAction("actionUndo");
app.endCompare();

// Extract sun: courtyard's bright sky has no compact sun (refused with a message); under the
// city map a new `sun2` light and a mask arrive as one undo step.
var noSun = "";
try { app.extractSun(); } catch (e) { noSun = String(e); }
console.log("courtyard: " + noSun);
check(noSun.indexOf("no compact sun") >= 0, "extractSun on courtyard did not say why: " + noSun);
app.setProperty("environment", "map", "../envmaps/city.exr");
spp = app.waitForSamples(1, 300);
var name = app.extractSun();
check(name == "sun2", "extractSun returned " + name);
check(app.getProperty("environment", "maskRadius") > 0, "no mask after extractSun");
check(app.getProperty("light:sun2", "angularDiameter") > 0, "the new sun has no angular diameter");
check(app.entities().join(",").indexOf("sun2") >= 0, "sun2 not in the outline: " + app.entities());
check(app.waitForSamples(2, 300) >= 2, "no render after extractSun");
app.triggerAction("actionUndo");
check(app.getProperty("environment", "maskRadius") == 0, "undo kept the mask");
check(app.getProperty("environment", "map") == "../envmaps/city.exr", "undo went past the extraction");
check(app.entities().join(",").indexOf("sun2") < 0, "undo kept sun2");
app.quit(0);
