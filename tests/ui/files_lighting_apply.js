// wavelit-args: --size 48x48 --sampler bsdf --max-spp 8
// wavelit-scene: scenes/glossy_sphere.wlscene
// A lighting setup saved from one scene and applied onto another renders like a scene that holds
// the same setup inline. Both renders use the same seed, so they draw the same samples: the
// images agree to float rounding (relative RMS < 1e-4), far inside the noise the status line
// estimates (printed), while the scene before the setup was applied differs by far more.
//   1. glossy_sphere (sun_sky by reference): edit the sun and the environment, save the setup
//      (app.saveLighting) and, as the reference, the scene with that lighting inline.
//   2. another scene — glossy_sphere lit by studio_soft, saved and reopened — renders a while,
//      then gets the saved setup with app.applyLighting (an edit of a running session).
//   3. its image against the inline reference's.
var res = app.environment("WAVELIT_UI_RESOURCES");
var out = app.environment("WAVELIT_SCRIPT_OUT");
var spp = 8;
check(app.waitForSamples(1, 300) >= 1, "no first frame");

app.setProperty("sun", "intensity", 7.5);
app.setProperty("sun", "direction", [0.3, -0.7, -0.6]);
app.setProperty("environment", "rotation", 110);
check(app.saveLighting(out + "/look.wllight"), "saveLighting: " + app.lastError());
app.saveScene(out + "/reference_inline.wlscene", "inline");

// The other scene: the same objects under studio_soft, from its own file.
app.openScene(res + "/scenes/glossy_sphere.wlscene");
check(app.applyLighting(res + "/lighting/studio_soft.wllight"), "apply studio_soft: " + app.lastError());
app.saveScene(out + "/other.wlscene");
app.openScene(out + "/other.wlscene");
check(app.entities().indexOf("sun") < 0, "the other scene still has the sun: " + app.entities());
app.waitForSamples(spp, 300);
app.saveImage(out + "/other_before.exr");

check(app.applyLighting(out + "/look.wllight"), "applyLighting: " + app.lastError());
check(app.entities().indexOf("sun") >= 0, "the applied setup's sun is not in the outline: " + app.entities());
check(Math.abs(app.getProperty("sun", "intensity") - 7.5) < 1e-6, "the sun's intensity was not applied");
check(Math.abs(app.getProperty("environment", "rotation") - 110) < 1e-6, "the rotation was not applied");
check(app.windowTitle().indexOf("*") >= 0, "applying a setup did not mark the document modified");
app.waitForSamples(spp, 300);
app.saveImage(out + "/applied.exr");
var noise = app.noiseEstimate();

app.openScene(out + "/reference_inline.wlscene");
app.waitForSamples(spp, 300);
app.saveImage(out + "/reference.exr");
var refNoise = app.noiseEstimate();

var same = app.compareImages(out + "/applied.exr", out + "/reference.exr");
var before = app.compareImages(out + "/other_before.exr", out + "/reference.exr");
var tolerance = 1e-4; // the same samples; the noise estimate is printed for scale
console.log("applied vs inline: relative RMS " + same.relativeRms.toFixed(5) + " (means " + same.meanA.toFixed(4) +
            ", " + same.meanB.toFixed(4) + "); noise estimate " + noise.toFixed(4) + " / " + refNoise.toFixed(4) +
            "; tolerance " + tolerance.toFixed(4) + "; studio_soft vs inline: " + before.relativeRms.toFixed(4));
check(same.relativeRms < tolerance, "the applied setup renders differently from the inline one");
check(before.relativeRms > Math.max(noise, 0.05), "the test cannot tell lighting setups apart");

// Undo puts the studio lighting back.
app.openScene(out + "/other.wlscene");
check(app.applyLighting(out + "/look.wllight"), "applyLighting again");
check(app.undo(), "nothing to undo");
check(app.entities().indexOf("sun") < 0, "undo did not remove the applied sun");
check(!app.isModified(), "undo did not return to the saved state");
check(app.validationMessages() == 0, "Vulkan validation messages: " + app.validationMessages());
app.quit(0);
