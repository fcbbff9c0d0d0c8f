// wavelit-args: --size 64x64 --sampler mis
// Issue 14: a sphere light's radius handle (light_manipulators.h). Scene: data/viewport_spot_light
// with its spot muted and a 50 W sphere light of radius 0.1 m added 1 m above the floor, seen from
// (0, 3, 3) at depth 5/sqrt 2 = 3.54 m, where an image pixel is 2 * 3.54 * tan 30 deg / 64 =
// 0.0638 m. The handle moves in the plane facing the camera along the screen diagonal
// (right, down): a drag of D image pixels along it adds D * 0.0638 m. The camera sees the sphere
// itself, of radiance 50/(4 pi^2 r^2) (127 at r = 0.1, 14 at r = 0.3) over a floor of about 1:
// the bright disc grows with r^2. A drag inward past the centre is held at 0 (the registry's
// minimum: a point light) and says so.
function brightPixels(lum, threshold) { var n = 0; for (var i = 0; i < lum.length; ++i) if (lum[i] > threshold) ++n; return n; }
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_spot_light.wlscene");
check(app.setMute("light:spot", true), "mute the spot");
var name = app.addLight("sphere", "ball");
app.setProperty(name, "position", [0, 1, 0]);
app.setProperty(name, "radius", 0.1);
app.setProperty(name, "intensity", 50);
app.waitForSamples(8, 300);
var before = app.frameLuminance();
app.select("light:ball");
var h = app.gizmoInfo().handles.radius;
check(h !== undefined, "no radius handle");
var wpp = 2 * (5 / Math.SQRT2) * Math.tan(Math.PI / 6) / 64;
var D = 0.2 / wpp; // +0.2 m
var t0 = Date.now();
check(app.dragInViewport(h[0], h[1], h[0] + D / Math.SQRT2, h[1] + D / Math.SQRT2), "drag the radius handle");
var first = app.waitForFrame(120);
console.log("radius drag -> first frame: " + JSON.stringify(first) + " (" + (Date.now() - t0) + " ms with the drag)");
var r = app.getProperty("light:ball", "radius");
console.log("radius 0.1 -> " + r.toFixed(4) + " (expected 0.3)");
check(Math.abs(r - 0.3) < 0.01, "radius after the drag: " + r);
app.waitForSamples(8, 300);
var after = app.frameLuminance();
var nBefore = brightPixels(before, 5), nAfter = brightPixels(after, 5);
console.log("pixels brighter than 5: " + nBefore + " -> " + nAfter + " (disc areas pi (r/0.0638)^2: 7.7 -> 69)");
check(nBefore >= 2 && nBefore <= 16, "disc before: " + nBefore);
check(nAfter >= 40 && nAfter <= 100, "disc after: " + nAfter);
check(app.undo() && Math.abs(app.getProperty("light:ball", "radius") - 0.1) < 1e-6, "undo restores 0.1");
h = app.gizmoInfo().handles.radius;
check(app.dragInViewport(h[0], h[1], h[0] - 3 / Math.SQRT2 * 0.1 / wpp, h[1] - 3 / Math.SQRT2 * 0.1 / wpp), "drag inward");
r = app.getProperty("light:ball", "radius");
console.log("clamped: radius " + r + ", message \"" + app.viewportMessage() + "\"");
check(r === 0, "radius not held at 0: " + r);
check(app.viewportMessage().indexOf("Radius") == 0 && app.viewportMessage().indexOf("held at 0") > 0, "no visible refusal");
check(app.validationMessages() === 0, "validation messages: " + app.validationMessages());
app.quit(0);
