// Edit -> first frame of the rotate gizmo and the light shape handles (issue 14, editor3), inside
// `wavelit --size WxH --script scripts/gizmo_latency.js` on the default scene (ring_on_ground,
// default sampler). Each drag is 8 mouse moves 33 ms apart through app.dragInViewport; printed:
// msSinceEdit of the first frame of the drag's last edit (app.waitForFrame: from that edit to the
// frame on screen) and what showed it. Not a test: figures for docs/viewport.md.
var reps = Number(app.environment("WAVELIT_LATENCY_REPS") || "4");
var size = Number(app.environment("WAVELIT_LATENCY_SIZE") || "256");
app.waitForSamples(2, 900);
// The softbox hangs above and behind the camera: bring it into view; a spot light for the cone.
app.setProperty("light:softbox", "position", [0.8, 1.2, 0.8]);
var spot = app.addLight("spot", "spot");
app.setProperty(spot, "position", [-0.6, 1.0, 0.4]);
app.setProperty(spot, "direction", [0, -1, 0]);
app.waitForSamples(1, 600);
app.processEvents(800);
function drag(what, entity, mode, pick, sign) {
    app.select(entity);
    app.setGizmoMode(mode);
    var info = app.gizmoInfo(), p, dir;
    if (pick.ring) { p = info.rings[pick.ring].point; dir = info.rings[pick.ring].tangent; }
    else { p = info.handles[pick.handle]; dir = pick.dir; }
    var len = sign * pick.px;
    app.dragInViewport(p[0], p[1], p[0] + dir[0] * len, p[1] + dir[1] * len, "", 8, 33);
    var first = app.waitForFrame(600);
    console.log("gizmo-latency " + size + " | " + what + " | " + first.msSinceEdit.toFixed(0) + " ms | " + first.source);
    app.waitForSamples(1, 600);
    app.processEvents(800); // edits pause: the relighting preview catches up
}
for (var r = 0; r < reps; ++r) {
    var s = r % 2 ? -1 : 1;
    drag("rotate object (ring, Y ring)", "object:ring", "rotate", {ring: "y", px: 0.05 * size}, s);
    drag("rotate rect light (softbox, X ring)", "light:softbox", "rotate", {ring: "x", px: 0.03 * size}, s);
    drag("rect size handle (softbox)", "light:softbox", "move", {handle: "sizeX", dir: [1, 0], px: 0.03 * size}, s);
    drag("spot cone handle", "light:spot", "move", {handle: "cone", dir: [1, 0], px: 0.02 * size}, s);
}
app.quit(0);
