// Edit -> first frame latency and drag frame rate of the editor (issue 14), run by
// scripts/editor_latency.sh inside `wavelit --script` on the default scene (ring_on_ground).
// Edits: per edit kind, REPS edits through app.setProperty (alternating two values), each timed
// from the call to the first frame of the edited scene on screen (app.waitForFrame where the
// binary has it, whose kind is printed; else app.waitForSamples(1): the first path-traced frame).
// Drags (binaries with the viewport API): a 1 s drag (30 mouse moves 33 ms apart) per kind, the
// frames the viewport was given during it, and the first frame after the release.
var reps = Number(app.environment("WAVELIT_LATENCY_REPS") || "3");
var size = app.environment("WAVELIT_LATENCY_SIZE") || "?";
var tag = app.environment("WAVELIT_LATENCY_TAG") || "";
app.waitForSamples(2, 900);
var edits = [
    ["environment rotation", "environment", "rotation", [30, 60]],
    ["roughness", "material:gold", "roughness", [0.3, 0.2]],
    ["light intensity", "light:softbox", "intensity", [40, 60]],
    ["light position", "light:softbox", "position", [[1.2, 3.0, 2.0], [1.5, 3.0, 2.0]]],
    ["object translation", "object:ring", "translation", [[0.1, 0.12, 0.0], [0.0, 0.12, 0.0]]],
    ["camera", "camera", "position", [[0.2, 1.7, 3.4], [0.0, 1.7, 3.4]]],
];
var viewportApi = typeof app.waitForFrame === "function";
function median(a) { a = a.slice().sort(function (x, y) { return x - y; }); return a[Math.floor(a.length / 2)]; }
for (var e = 0; e < edits.length; ++e) {
    var times = [], kinds = [];
    for (var r = 0; r < reps; ++r) {
        var t0 = Date.now();
        app.setProperty(edits[e][1], edits[e][2], edits[e][3][r % 2]);
        if (viewportApi) kinds.push(app.waitForFrame(600).source);
        else app.waitForSamples(1, 600);
        times.push(Date.now() - t0);
        app.waitForSamples(1, 600); // the path tracer settles, as before an artist's next edit
        if (viewportApi) app.processEvents(800); // edits pause: the relighting preview catches up
    }
    console.log("latency " + tag + " " + size + " | edit | " + edits[e][0] + " | median " + median(times) +
                " ms | all " + times.join(" ") + (kinds.length ? " | shown " + kinds.join(" ") : ""));
}
if (viewportApi) {
    var w = Number(size), h = Number(size);
    // The softbox hangs above and behind the camera: for its drag it is brought into view first.
    app.setProperty("light:softbox", "position", [0.8, 1.2, 0.8]);
    app.waitForSamples(1, 600);
    app.select("light:softbox");
    var light = app.handleInViewport("light:softbox");
    console.log("softbox handle at " + light);
    app.select("object:ring");
    var ring = app.handleInViewport("object:ring");
    var drags = [
        ["light drag (gizmo)", "light:softbox", light, 0.08 * w, ""],
        ["environment drag (Ctrl)", "", [0.2 * w, 0.8 * h], 0.1 * w, "ctrl"],
        ["object drag (gizmo)", "object:ring", ring, 0.05 * w, ""],
        ["camera orbit", "", [0.5 * w, 0.1 * h], 0.05 * w, ""],
    ];
    for (var d = 0; d < drags.length; ++d) {
        for (var r = 0; r < reps; ++r) {
            if (drags[d][1]) app.select(drags[d][1]);
            var p = drags[d][2], dx = (r % 2 ? -1 : 1) * drags[d][3];
            var f0 = app.framesShown(), t0 = Date.now();
            app.dragInViewport(p[0], p[1], p[0] + dx, p[1], drags[d][4], 30, 33);
            var dragMs = Date.now() - t0, frames = app.framesShown() - f0;
            var t1 = Date.now();
            var first = app.waitForFrame(600);
            console.log("latency " + tag + " " + size + " | drag | " + drags[d][0] + " | " +
                        (1000 * frames / dragMs).toFixed(1) + " frames/s during " + dragMs + " ms | after release: " +
                        first.source + " in " + (Date.now() - t1) + " ms");
            app.waitForSamples(1, 600);
            app.processEvents(800);
        }
    }
}
app.quit(0);
