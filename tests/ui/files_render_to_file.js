// wavelit-args: --size 40x32 --sampler bsdf --max-spp 8
// wavelit-scene: scenes/ring_on_ground.wlscene
// Render to file: an EXR with a budget of samples per pixel has the viewport's size, finite
// values and — rendered with the viewport's options and seed — the viewport's image at the same
// samples (the same seed draws the same samples: relative RMS < 1e-4; the noise estimate is
// printed for scale); a PNG with a time budget is written too.
var out = app.environment("WAVELIT_SCRIPT_OUT");
app.waitForSamples(8, 300);
app.saveImage(out + "/viewport.exr");
var noise = app.noiseEstimate();
var status = app.statusText();
console.log("status: " + status);
["8 spp", " s ·", "Msamples/s", "bsdf", "noise ≈"].forEach(function (part) {
    check(status.indexOf(part) >= 0, "the status line lacks '" + part + "': " + status);
});

check(app.renderToFile(out + "/render.exr", {spp: 8}), "renderToFile exr: " + app.lastError());
var info = app.imageInfo(out + "/render.exr");
console.log("render.exr: " + info.width + "x" + info.height + ", finite " + info.finite + ", mean luminance " + info.meanLuminance.toFixed(4));
check(info.width == 40 && info.height == 32, "wrong size " + info.width + "x" + info.height);
check(info.finite, "non-finite values in the EXR");
check(info.meanLuminance > 0, "black render");
var d = app.compareImages(out + "/viewport.exr", out + "/render.exr");
var tolerance = 1e-4;
console.log("file vs viewport: relative RMS " + d.relativeRms.toFixed(5) + ", noise estimate " + noise.toFixed(4) + ", tolerance " + tolerance.toFixed(4));
check(d.relativeRms < tolerance, "the file differs from the viewport beyond noise");

check(app.renderToFile(out + "/render.png", {seconds: 0.5}), "renderToFile png: " + app.lastError());
var png = app.imageInfo(out + "/render.png");
check(png.width == 40 && png.height == 32, "png size " + png.width + "x" + png.height);
var threw = false;
check(app.renderToFile(out + "/none.exr", {}) === false, "a render without a budget started");
check(app.lastError().indexOf("budget") >= 0, "the missing budget is not named: " + app.lastError());
check(app.validationMessages() == 0, "Vulkan validation messages: " + app.validationMessages());
app.quit(0);
