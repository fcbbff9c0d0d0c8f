// wavelit-args: --size 64x64 --sampler mis
// Issue 14: the spot's cone handle (light_manipulators.h) widens its outer cone by a drag, and
// the lit region grows. Scene: data/viewport_spot_light (a 30 W spot 1 m above the floor pointing
// down, cone 15/20 deg, seen from (0, 3, 3)). The handle sits on the outer cone's rim at a fixed
// depth d along the axis; dragging it sideways in the plane facing the camera moves the rim point
// under the mouse, so after the drag the handle is where the mouse let go and tan(outer) =
// (d tan 20 deg + travel) / d. The floor 0.5 m from the axis (26.6 deg off it) is outside the
// 20 deg cone and inside a 40 deg one. A drag toward the axis asks for less than the inner cone
// (15 deg): the value is held at 15 and the viewport says so.
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_spot_light.wlscene");
app.waitForSamples(16, 300);
var before = app.frameLuminance();
var ring = app.projectToViewport([0.5, 0, 0]), ringLeft = app.projectToViewport([-0.5, 0, 0]);
var centre = app.projectToViewport([0, 0, 0]);
app.select("light:spot");
var info = app.gizmoInfo();
var h = info.handles.cone;
check(h !== undefined, "no cone handle: " + JSON.stringify(info));
// The rim's radius on screen is d tan(20 deg); d is the screen length kConeHandleDepthPx = 60 px.
var pxScale = info.ringRadius / 50;
var dPx = 60 * pxScale;                      // d, in image pixels at the light's depth (approx.)
var travel = dPx * (Math.tan(40 * Math.PI / 180) - Math.tan(20 * Math.PI / 180)) * 0.95;
var t0 = Date.now();
check(app.dragInViewport(h[0], h[1], h[0] + travel, h[1]), "drag the cone handle");
var first = app.waitForFrame(120);
console.log("cone drag -> first frame: " + JSON.stringify(first) + " (" + (Date.now() - t0) + " ms with the drag)");
var outer = app.getProperty("light:spot", "coneOuter");
var moved = app.gizmoInfo().handles.cone;
console.log("coneOuter " + outer.toFixed(2) + ", handle " + h + " -> " + moved + " (mouse at " + (h[0] + travel) + ")");
check(outer > 33 && outer < 42, "coneOuter after the drag: " + outer);
check(Math.abs(moved[0] - (h[0] + travel)) < 0.05 && Math.abs(moved[1] - h[1]) < 0.05,
      "the rim handle did not follow the mouse: " + moved);
check(app.viewportMessage() === "", "unexpected refusal: " + app.viewportMessage());
app.waitForSamples(16, 300);
var after = app.frameLuminance();
var wider = regionMean(after, ring, 1) / regionMean(before, ring, 1);
var widerLeft = regionMean(after, ringLeft, 1) / regionMean(before, ringLeft, 1);
var inside = regionMean(after, centre, 2) / regionMean(before, centre, 2);
console.log("after/before 0.5 m off the axis: right " + wider.toFixed(3) + ", left " + widerLeft.toFixed(3) +
            ", on the axis " + inside.toFixed(3));
check(wider > 3 && widerLeft > 3, "the wider cone did not light the floor 0.5 m off its axis: " + wider + " " + widerLeft);
check(Math.abs(inside - 1) < 0.08, "the floor on the axis changed: " + inside);
check(app.undo() && app.getProperty("light:spot", "coneOuter") == 20, "undo restores 20 deg");
check(!app.undo(), "the drag took more than one undo step");
// Toward the axis and past it: less than the inner cone is refused, held at 15 deg.
h = app.gizmoInfo().handles.cone;
check(app.dragInViewport(h[0], h[1], h[0] - 2 * dPx * Math.tan(20 * Math.PI / 180), h[1]), "drag past the axis");
outer = app.getProperty("light:spot", "coneOuter");
console.log("clamped: coneOuter " + outer + ", message \"" + app.viewportMessage() + "\"");
check(outer == 15, "coneOuter not held at the inner cone: " + outer);
check(app.viewportMessage().indexOf("Cone outer") == 0 && app.viewportMessage().indexOf("held at 15") > 0,
      "no visible refusal: " + app.viewportMessage());
check(app.statusText().length > 0, "status");
check(app.undo() && app.getProperty("light:spot", "coneOuter") == 20 && !app.undo(), "one undo step for the clamped drag");
check(app.validationMessages() === 0, "validation messages: " + app.validationMessages());
app.quit(0);
