// The A/B picture of docs/lightmix.md (run by scripts/lightmix_pictures.sh): two snapshots of the
// night setup, remixed from one render, in the editor's split view with the wipe at 45%.
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
app.answerPrompts("discard");
app.quit(0);
