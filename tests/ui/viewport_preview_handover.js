// wavelit-args: --size 48x48 --sampler mis
// Issue 14 / issue 13: after a light edit the viewport shows the relighting preview first, then
// hands over to the path tracer once its estimated error (from its own samples) is at most the
// preview's (render_controller.h, kPreviewRelError = 0.2). The test scene has one bounce
// (direct light only), so the preview is an estimate of the same image: its relRMSE against the
// converged path-traced frame must be that of a good preview (docs/relighting.md §7: 0.12-0.34).
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_point_light.wlscene");
app.waitForSamples(2, 300);
// The preview is built after the first edit, once edits pause (relight_worker.h).
app.setProperty("light:bulb", "intensity", 12);
var deadline = Date.now() + 120000, frame = null, preview = null;
// Edits alternate until one is shown by the preview (the build takes ~1 s at 64^2).
for (var i = 0; Date.now() < deadline; ++i) {
    app.setProperty("light:bulb", "position", [-1.2 + 0.1 * (i % 2), 0.3, 0.0]);
    frame = app.waitForFrame(60);
    if (frame.kind == "preview" && frame.source == "relight") { preview = app.frameLuminance("displayed"); break; }
    app.processEvents(600); // edits pause: the preview is built (relight_worker.h)
}
check(preview !== null, "no edit was shown by the relighting preview");
console.log("preview frame: " + JSON.stringify(frame));
check(frame.msSinceEdit >= 0, "msSinceEdit missing");
// Hand-over: the displayed frame becomes path traced once its estimated error is <= 0.2.
var shown = null;
for (var spp = 2; spp <= 128; spp *= 2) {
    app.waitForSamples(spp, 300);
    shown = app.waitForFrame(60);
    if (shown.kind == "pathtraced") break;
}
console.log("handed over at " + JSON.stringify(shown));
check(shown.kind == "pathtraced", "the path tracer never took over");
check(shown.estimatedRelError >= 0 && shown.estimatedRelError <= 0.2, "handed over at error " + shown.estimatedRelError);
app.waitForSamples(128, 600);
var converged = app.frameLuminance();
var previewError = relRmse(preview, converged);
console.log("preview relRMSE vs 128-spp path traced direct light: " + previewError.toFixed(3));
check(previewError < 0.35, "the preview is far from the path-traced image: " + previewError);
app.quit(0);
