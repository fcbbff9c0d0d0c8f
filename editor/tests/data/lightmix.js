// LightMix end to end (run by editor_script_lightmix with `wavelit --light-mix` on the default
// scene under the night lighting setup: window, lamp, spot, environment). Light intensity,
// colour, mute and solo edits are remixes (the frame keeps its samples and says "remixed: no
// restart"), each an undoable edit that undo reverts; a light move restarts the render.
var out = app.environment("WAVELIT_SCRIPT_OUT");
function check(ok, what) { if (!ok) throw new Error("lightmix: " + what); }
// Waits for a frame rendered after the last edit (one more pass than `spp`).
function nextFrame(spp) { return app.waitForSamples(spp + 1, 300); }

var spp = app.waitForSamples(3, 300);
function remix(what) {
    spp = nextFrame(spp);
    check(app.frameStatus().indexOf("remixed: no restart") == 0, what + " restarted the render: " + app.frameStatus());
    console.log(what + ": remixed at " + spp + " spp");
}
app.setProperty("light:window", "intensity", 80);
remix("window intensity");
app.setProperty("light:spot", "color", [0.2, 0.4, 1.0]);
remix("spot colour");
app.setProperty("environment", "intensity", 0.5);
remix("environment intensity");
app.setMute("lamp", true);
remix("mute lamp");
check(app.getProperty("light:lamp", "muted") === true, "lamp not muted");
app.saveImage(out + "/lightmix_muted.exr");

app.solo("window");
remix("solo window");
check(app.getProperty("light:spot", "muted") === true && app.getProperty("light:lamp", "muted") === true &&
      app.getProperty("light:window", "muted") === false, "solo did not mute the others");
app.saveImage(out + "/lightmix_solo.exr");
app.triggerAction("actionUndo"); // the whole solo is one step
check(app.getProperty("light:spot", "muted") === false && app.getProperty("light:lamp", "muted") === true,
      "undo of solo did not restore the mutes");
remix("undo solo");
app.triggerAction("actionUndo"); // the lamp's mute
check(app.getProperty("light:lamp", "muted") === false, "undo of mute");
remix("undo mute");

// Not a remix: moving a light restarts.
app.setProperty("light:lamp", "position", [1.0, 0.9, 1.2]);
app.waitForSamples(1, 300);
var waited = 0;
while (app.frameStatus().indexOf("remixed") == 0 && waited++ < 100) app.waitForSamples(app.samples() + 1, 300);
check(app.frameStatus().indexOf("remixed") != 0, "a light move was remixed");
console.log("light move: " + app.frameStatus());
app.quit(0);
