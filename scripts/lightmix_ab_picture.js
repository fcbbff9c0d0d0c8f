// The A/B pictures of docs/lightmix.md (run by scripts/lightmix_pictures.sh): two snapshots of the
// night setup, remixed from one render, in the editor's split view with the wipe at 45%; then the
// warm snapshot against one whose lamp is moved to the other side (a render side: its own
// session, waited for to the same samples per pixel).
var out = app.environment("WAVELIT_SCRIPT_OUT");
var spp = app.waitForSamples(64, 3000);
app.setProperty("light:lamp", "intensity", app.getProperty("light:lamp", "intensity") * 4);
app.setProperty("light:window", "intensity", app.getProperty("light:window", "intensity") * 0.25);
app.snapshot("warm");
app.triggerAction("actionUndo");
app.triggerAction("actionUndo");
app.setProperty("light:spot", "color", [0.3, 0.6, 2.5]);
app.setMute("lamp", true);
app.snapshot("cool");
app.waitForSamples(spp + 1, 600);
app.compare("warm", "cool");
app.setCompareWipe(0.45);
app.saveCompare(out + "/lightmix_ab.png");
console.log("A/B means (warm, cool): " + app.compareMeans());
app.setMute("lamp", false);
app.setProperty("light:lamp", "position", [-1.2, 0.8, 1.2]);
app.snapshot("lamp moved");
app.triggerAction("actionUndo");
app.triggerAction("actionUndo");
spp = app.waitForSamples(64, 3000); // the lamp's move and its undo restarted the render
var modes = app.compare("warm", "lamp moved");
console.log("A/B modes (warm, lamp moved): " + JSON.stringify(modes));
var t0 = Date.now();
while (app.compareSamples()[1] < spp && Date.now() - t0 < 3000000) app.processEvents(200);
app.setCompareWipe(0.5);
app.saveCompare(out + "/lightmix_ab_render.png");
console.log("A/B samples (warm, lamp moved): " + app.compareSamples());
app.answerPrompts("discard");
app.quit(0);
