// wavelit-args: --size 64x64 --sampler mis
// Issue 14: a rect light's size handles (light_manipulators.h). Scene: data/viewport_spot_light with
// the spot muted and a 20 W rect light 0.2 m x 0.2 m added 0.5 m above the floor, facing down (its
// width axis U = +X, light_sampler.h). The width handle sits at (0.1, 0.5, 0), depth 5.5/sqrt 2 =
// 3.89 m, where an image pixel is 2 * 3.89 * tan 30 deg / 64 = 0.0701 m; the drag runs in the
// rect's plane and the handle is the edge's middle, so D pixels to the right widen it by
// 2 * D * 0.0701 m. The same power from a 0.9 m wide panel: the floor under its centre gets less
// (the panel's radiance drops 4.5x and most of it now arrives slanted), the floor at x = 0.55 m,
// which is under the new panel's end, gets more.
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_spot_light.wlscene");
check(app.setMute("light:spot", true), "mute the spot");
var name = app.addLight("rect", "panel");
app.setProperty(name, "position", [0, 0.5, 0]);
app.setProperty(name, "direction", [0, -1, 0]);
app.setProperty(name, "size", [0.2, 0.2]);
app.setProperty(name, "intensity", 20);
app.waitForSamples(16, 300);
var before = app.frameLuminance();
var centre = app.projectToViewport([0, 0, 0]), end = app.projectToViewport([0.55, 0, 0]);
app.select("light:panel");
var handles = app.gizmoInfo().handles;
check(handles.sizeX !== undefined && handles.sizeY !== undefined, "size handles: " + JSON.stringify(handles));
var h = handles.sizeX;
var D = 5;
var t0 = Date.now();
check(app.dragInViewport(h[0], h[1], h[0] + D, h[1]), "drag the width handle");
var first = app.waitForFrame(120);
console.log("size drag -> first frame: " + JSON.stringify(first) + " (" + (Date.now() - t0) + " ms with the drag)");
var s = app.getProperty("light:panel", "size");
var expected = 0.2 + 2 * D * 2 * (5.5 / Math.SQRT2) * Math.tan(Math.PI / 6) / 64;
console.log("size " + s + " (expected width " + expected.toFixed(3) + ")");
check(Math.abs(s[0] - expected) < 0.03 && Math.abs(s[1] - 0.2) < 1e-6, "size after the drag: " + s);
app.waitForSamples(16, 300);
var after = app.frameLuminance();
var atCentre = regionMean(after, centre, 1) / regionMean(before, centre, 1);
var atEnd = regionMean(after, end, 1) / regionMean(before, end, 1);
console.log("after/before: under the centre " + atCentre.toFixed(3) + ", at x = 0.55 m " + atEnd.toFixed(3));
check(atCentre < 0.9, "the floor under the centre did not dim: " + atCentre);
check(atEnd > 1.3, "the floor under the new end did not brighten: " + atEnd);
check(app.undo() && Math.abs(app.getProperty("light:panel", "size")[0] - 0.2) < 1e-6 && app.undo() === true,
      "undo restores 0.2 (then the intensity edit)");
check(app.redo(), "redo");
// Narrower than nothing: held at 1 mm, said in the viewport.
h = app.gizmoInfo().handles.sizeX;
check(app.dragInViewport(h[0], h[1], h[0] - 20, h[1]), "drag inward");
s = app.getProperty("light:panel", "size");
console.log("clamped: size " + s + ", message \"" + app.viewportMessage() + "\"");
check(Math.abs(s[0] - 0.001) < 1e-6, "width not held at 1 mm: " + s);
check(app.viewportMessage().indexOf("Width") == 0, "no visible refusal");
check(app.validationMessages() === 0, "validation messages: " + app.validationMessages());
app.quit(0);
