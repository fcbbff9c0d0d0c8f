// wavelit-args: --size 48x48 --sampler mis
// wavelit-scene: scenes/ring_on_ground.wlscene
// Issue 14: Ctrl + drag in the viewport rotates the environment (viewport_interaction.h: a drag
// across the whole image width is 180 degrees), as one undo step, and renders the same image as
// typing the same rotation (the same scene, so within noise).
check(app.getProperty("environment", "rotation") == 0, "the scene's environment rotation is not 0");
app.waitForSamples(8, 300);
var before = app.frameLuminance();
check(app.dragInViewport(10, 40, 26, 40, "ctrl"), "drag"); // 16 of 48 pixels: 60 degrees
var rotation = app.getProperty("environment", "rotation");
console.log("environment rotation after the drag: " + rotation);
check(Math.abs(rotation - 60) < 0.05, "rotation " + rotation + ", expected 60");
check(app.getProperty("camera", "position")[0] == 0, "the drag moved the camera");
var m = app.waitForSamples(8, 300);
var dragged = app.frameLuminance();
var n = app.waitForSamples(2 * m, 300);
var dragged16 = app.frameLuminance();
var noise = relRmse(dragged, dragged16) * Math.sqrt(m / (n - m)); // the n-spp frame's error (render_frame.h)
check(app.undo(), "undo");
check(!app.undo(), "the drag was more than one undo step");
check(app.getProperty("environment", "rotation") == 0, "undo did not restore the rotation");
app.setProperty("environment", "rotation", Math.round(rotation * 1000) / 1000);
app.waitForSamples(n, 300);
var typed = app.frameLuminance();
var same = relRmse(typed, dragged16), changed = relRmse(dragged16, before);
console.log("relRMSE: dragged vs typed " + same.toFixed(4) + ", dragged vs unrotated " + changed.toFixed(4) +
            ", noise at " + n + " spp " + noise.toFixed(4));
check(same <= 3 * Math.SQRT2 * noise + 0.01, "dragging and typing the rotation render differently: " + same);
check(changed > 2 * same, "rotating the environment did not change the image: " + changed);
app.quit(0);
