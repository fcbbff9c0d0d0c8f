// Edit -> next frame latency of the editor (issue 14), run by scripts/editor_latency.sh inside
// `wavelit --script` on the default scene: per edit kind, REPS edits made through the script API
// (alternating two values), each timed from app.setProperty to the first frame of the edited
// scene (app.waitForSamples(1): a frame of the new generation). With app.waitForFrame (the
// viewport API) the frame's kind ("preview" | "pathtraced") is printed too.
var reps = Number(app.environment("WAVELIT_LATENCY_REPS") || "3");
var size = app.environment("WAVELIT_LATENCY_SIZE") || "?";
app.waitForSamples(2, 900);
var edits = [
    ["environment rotation", "environment", "rotation", [30, 60]],
    ["roughness", "material:gold", "roughness", [0.3, 0.2]],
    ["light intensity", "light:softbox", "intensity", [40, 60]],
    ["light position", "light:softbox", "position", [[1.2, 3.0, 2.0], [1.5, 3.0, 2.0]]],
    ["object translation", "object:ring", "translation", [[0.1, 0.12, 0.0], [0.0, 0.12, 0.0]]],
    ["camera", "camera", "position", [[0.2, 1.7, 3.4], [0.0, 1.7, 3.4]]],
];
var hasWaitForFrame = typeof app.waitForFrame === "function";
for (var e = 0; e < edits.length; ++e) {
    var times = [];
    var kinds = [];
    for (var r = 0; r < reps; ++r) {
        var t0 = Date.now();
        app.setProperty(edits[e][1], edits[e][2], edits[e][3][r % 2]);
        if (hasWaitForFrame) {
            var f = app.waitForFrame(600);
            kinds.push(f.kind);
        } else {
            app.waitForSamples(1, 600);
        }
        times.push(Date.now() - t0);
        // Let the path tracer settle a little, as an artist's next edit would come later.
        app.waitForSamples(1, 600);
    }
    times.sort(function (a, b) { return a - b; });
    console.log("latency " + size + " | " + edits[e][0] + " | median " + times[Math.floor(times.length / 2)] +
                " ms | all " + times.join(" ") + (kinds.length ? " | kinds " + kinds.join(" ") : "") +
                " | " + app.frameStatus());
}
app.quit(0);
