// wavelit-args: --size 64x64 --sampler mis
// Issue 14: the rotate gizmo (E, app.setGizmoMode("rotate")) turns a spot light by a ring drag
// through real mouse events. The scene (data/viewport_spot_light) has a 30 W spot 1 m above a
// floor pointing straight down, outer cone 20 deg, under a dim sky (radiance 0.1): under the
// spot the floor's irradiance is 30/(4 pi) = 2.4, 7.6x the sky's pi*0.1. Turning the spot 30 deg
// about +Z (the Z ring: one ring radius of mouse travel along the ring is one radian) moves its
// axis to hit the floor at x = tan 30 deg = 0.577 m: there the floor goes from outside the cone
// (30 deg off the old axis) to its centre, and the old centre goes dark (30 deg off the new axis).
// Undo restores the direction and, converged, the image. An object turns the same way: the post
// turned about +Y by a ring drag has rotation [0, angle, 0].
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_spot_light.wlscene");
app.waitForSamples(16, 300);
var before = app.frameLuminance();
var centre = app.projectToViewport([0, 0, 0]), side = app.projectToViewport([Math.tan(Math.PI / 6), 0, 0]);
app.select("light:spot");
check(app.setGizmoMode("rotate") && app.gizmoMode() == "rotate", "rotate mode");
var info = app.gizmoInfo();
console.log("gizmo: " + JSON.stringify(info));
check(info.rings.z !== undefined, "no Z ring");
var grab = info.rings.z.point, t = info.rings.z.tangent;
var angle = Math.PI / 6, travel = angle * info.ringRadius;
var t0 = Date.now();
check(app.dragInViewport(grab[0], grab[1], grab[0] + t[0] * travel, grab[1] + t[1] * travel), "drag");
var first = app.waitForFrame(120);
console.log("rotate drag -> first frame: " + JSON.stringify(first) + " (" + (Date.now() - t0) + " ms with the drag)");
var d = app.getProperty("light:spot", "direction");
console.log("direction after the drag: " + d);
check(Math.abs(d[0] - Math.sin(angle)) < 0.01 && Math.abs(d[1] + Math.cos(angle)) < 0.01 && Math.abs(d[2]) < 1e-4,
      "direction after a 30 deg turn about +Z: " + d);
app.waitForSamples(16, 300);
var after = app.frameLuminance();
var atSide = regionMean(after, side, 2) / regionMean(before, side, 2);
var atCentre = regionMean(after, centre, 2) / regionMean(before, centre, 2);
console.log("after/before: at the new axis " + atSide.toFixed(3) + ", at the old axis " + atCentre.toFixed(3));
check(atSide > 3, "the floor at the new axis did not light up: " + atSide);
check(atCentre < 0.3, "the floor at the old axis did not go dark: " + atCentre);
// One drag, one undo step; undo restores the direction and the converged pixels.
check(app.undo(), "undo");
d = app.getProperty("light:spot", "direction");
check(Math.abs(d[0]) < 1e-6 && Math.abs(d[1] + 1) < 1e-6, "undo did not restore the direction: " + d);
check(!app.undo(), "the drag took more than one undo step");
app.waitForSamples(16, 300);
var undone = app.frameLuminance();
var r1 = regionMean(undone, centre, 2) / regionMean(before, centre, 2);
var r2 = regionMean(undone, side, 2) / regionMean(before, side, 2);
console.log("undone/before: centre " + r1.toFixed(3) + ", side " + r2.toFixed(3));
check(Math.abs(r1 - 1) < 0.05 && Math.abs(r2 - 1) < 0.1, "undo did not restore the image: " + r1 + " " + r2);
// An object: the post turned about +Y.
app.select("object:post");
info = app.gizmoInfo();
check(info.rings.y !== undefined, "no Y ring on the post");
grab = info.rings.y.point; t = info.rings.y.tangent;
travel = 0.5 * info.ringRadius; // 0.5 rad
check(app.dragInViewport(grab[0], grab[1], grab[0] + t[0] * travel, grab[1] + t[1] * travel), "drag the post");
var r = app.getProperty("object:post", "rotation");
console.log("post rotation: " + r);
check(Math.abs(r[0]) < 0.01 && Math.abs(r[1] - 0.5 * 180 / Math.PI) < 0.3 && Math.abs(r[2]) < 0.01, "post rotation " + r);
check(app.undo(), "undo the post");
r = app.getProperty("object:post", "rotation");
check(r[0] === 0 && r[1] === 0 && r[2] === 0, "undo did not restore the post: " + r);
// W goes back to moving.
check(app.setGizmoMode("move") && app.gizmoMode() == "move", "move mode");
check(app.validationMessages() === 0, "validation messages: " + app.validationMessages());
app.quit(0);
