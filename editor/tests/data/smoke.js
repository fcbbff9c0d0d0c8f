// Smoke test of the scripting API (run by editor_script_smoke): OUT_DIR is passed in the
// environment as WAVELIT_SCRIPT_OUT. Renders the default scene to 4 spp, saves it, quits.
var out = app.environment("WAVELIT_SCRIPT_OUT");
console.log("entities: " + app.entities().join(", "));
var spp = app.waitForSamples(4, 300);
console.log("reached " + spp + " spp");
app.triggerAction("actionExposureUp");
app.saveImage(out + "/smoke.png");
app.saveImage(out + "/smoke.exr");
app.quit(0);
