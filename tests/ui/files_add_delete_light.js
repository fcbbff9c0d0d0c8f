// wavelit-args: --size 48x48 --sampler bsdf --max-spp 8
// wavelit-scene: scenes/ring_on_ground.wlscene
// Outline edits: adding a point light brightens the image by more than the estimated noise;
// deleting it returns the image to the one before (the same seed draws the same samples, so to
// float rounding: relative RMS < 1e-4); undo/redo replay both; every light type, a material, a
// duplicate and a rename are one undo step each; refused edits throw with a reason.
var out = app.environment("WAVELIT_SCRIPT_OUT");
var spp = 8;
function frame(name) { app.waitForSamples(spp, 300); app.saveImage(out + "/" + name + ".exr"); return out + "/" + name + ".exr"; }

var base = frame("base");
var baseNoise = app.noiseEstimate();
var name = app.addLight("point", "Key");
check(name == "Key", "addLight returned " + name);
check(app.entities().indexOf("Key") >= 0, "the light is not in the outline");
app.setProperty("Key", "position", [0.6, 1.2, 0.8]);
app.setProperty("Key", "intensity", 60);
var lit = frame("lit");
var added = app.compareImages(base, lit);
console.log("with the light: mean " + added.meanA.toFixed(4) + " -> " + added.meanB.toFixed(4) +
            ", relative RMS " + added.relativeRms.toFixed(4) + ", noise " + baseNoise.toFixed(4));
check(added.meanB > added.meanA * 1.05, "the added light did not brighten the image");

check(app.remove("Key"), "remove");
check(app.entities().indexOf("Key") < 0, "the light is still in the outline");
var removed = app.compareImages(base, frame("removed"));
var tolerance = 1e-4; // the same samples; the noise estimate is printed for scale
console.log("after delete vs before add: relative RMS " + removed.relativeRms.toFixed(5) + " (tolerance " + tolerance.toFixed(4) + ")");
check(removed.relativeRms < tolerance, "deleting the light did not restore the image");
check(added.meanB - added.meanA > 3 * baseNoise * added.meanA / Math.sqrt(48 * 48), "the light's brightening is within the noise of the mean");

// Undo the delete: the light is back where it was, with its edits.
check(app.undo(), "undo delete");
check(app.entities().indexOf("Key") >= 0, "undo did not bring the light back");
var relit = app.compareImages(lit, frame("relit"));
console.log("undo delete vs lit: relative RMS " + relit.relativeRms.toFixed(5));
check(relit.relativeRms < tolerance, "undo of the delete renders differently");
check(app.redo() && app.entities().indexOf("Key") < 0, "redo delete");

// Every light type, a material, a duplicate and a rename.
["point", "sphere", "rect", "spot", "sun"].forEach(function (t) { app.addLight(t); });
var copy = app.duplicate("gold");
check(copy == "gold copy", "duplicate named " + copy);
check(app.rename("object:ring", "band"), "rename");
check(app.entities().indexOf("band") >= 0 && app.entities().indexOf("ring") < 0, "rename did not show");
check(app.undo() && app.entities().indexOf("ring") >= 0, "undo rename");
var threw = "";
try { app.remove("material:ground"); } catch (e) { threw = String(e); }
check(threw.indexOf("used by") >= 0, "deleting a material in use was not refused: " + threw);
try { app.rename("object:ring", "ground"); threw = ""; } catch (e) { threw = String(e); }
check(threw.indexOf("already exists") >= 0, "a taken name was not refused: " + threw);
try { app.addLight("laser"); threw = ""; } catch (e) { threw = String(e); }
check(threw.indexOf("laser") >= 0, "an unknown light type was not refused");
app.waitForSamples(1, 300);
check(app.validationMessages() == 0, "Vulkan validation messages: " + app.validationMessages());
app.quit(0);
