// wavelit-args: --size 48x48 --sampler mis
// Issue 14: undoing a gizmo drag restores the converged pixels within noise. The noise is
// measured, not assumed: two frames of one render at m and n >= 2m spp give the relative error
// of the n-spp frame (render_frame.h: E|I_n - I_m|^2 = sigma^2 (n - m)/(n m), the error of I_n is
// sigma^2 / n), so two independent n-spp renders differ by about sqrt(2) of it (a frame with more
// samples than n, less).
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_point_light.wlscene");
var m = app.waitForSamples(8, 300);
var atM = app.frameLuminance();
// At least 64 spp: below that the noise bound (3 sqrt(2) x the error) nears half the drag's own
// change (0.43 relRMSE), and a loaded machine's m = 8..17 made the check below fail at n = 34.
var n = app.waitForSamples(Math.max(2 * m, 64), 300);
var before = app.frameLuminance();
// The n-spp frame's error from the two frames (render_frame.h): relMSE(I_m vs I_n) * m / (n - m).
var noise = relRmse(atM, before) * Math.sqrt(m / (n - m));
console.log("estimated relative error at " + n + " spp: " + noise.toFixed(4));
var start = app.getProperty("light:bulb", "position");
app.select("light:bulb");
var h = app.handleInViewport("light:bulb");
check(app.dragInViewport(h[0], h[1], h[0] + 15, h[1] + 8), "drag");
app.waitForSamples(n, 300);
var dragged = app.frameLuminance();
var moved = relRmse(dragged, before);
check(app.undo(), "undo");
check(!app.undo(), "the drag was more than one undo step");
var p = app.getProperty("light:bulb", "position");
check(p[0] == start[0] && p[1] == start[1] && p[2] == start[2], "undo left the bulb at " + p);
app.waitForSamples(n, 300);
var restored = relRmse(app.frameLuminance(), before);
console.log("relRMSE vs before the drag: dragged " + moved.toFixed(4) + ", after undo " + restored.toFixed(4) +
            " (bound 3 * sqrt(2) * noise = " + (3 * Math.SQRT2 * noise).toFixed(4) + ")");
check(restored <= 3 * Math.SQRT2 * noise, "undo did not restore the image: relRMSE " + restored);
check(moved > 2 * 3 * Math.SQRT2 * noise, "the drag barely changed the image: relRMSE " + moved);
// Redo brings the drag back as one step too.
check(app.redo(), "redo");
var r = app.getProperty("light:bulb", "position");
check(Math.abs(r[0] - start[0]) > 0.5, "redo did not move the bulb back: " + r);
app.quit(0);
