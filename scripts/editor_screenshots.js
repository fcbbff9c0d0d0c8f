// The README's editor screenshots (scripts/editor_screenshots.sh runs this in `wavelit --script`
// on the default scene): the window after a few passes with the ring selected (gizmo, property
// panel), then after a gizmo drag of the softbox and a Ctrl+drag of the environment, each
// grabbed as the user sees it. WAVELIT_SCRIPT_OUT is the folder the PNGs go to.
var out = app.environment("WAVELIT_SCRIPT_OUT");
function check(ok, what) { if (!ok) throw new Error("editor_screenshots: " + what); }
check(app.waitForSamples(8, 600) >= 8, "no frames");
check(app.select("object:ring") || app.select("ring"), "cannot select the ring");
app.processEvents(300);
check(app.grabWindow(out + "/editor_selected.png"), "grab 1");
var light = app.entities().filter(function (e) { return e.indexOf("light:") == 0; })[0];
var h = light ? app.handleInViewport(light) : null;
if (h) {
    app.pickInViewport(h[0], h[1]);
    app.dragInViewport(h[0], h[1], h[0] + 40, h[1] + 10);
}
app.dragInViewport(60, 60, 160, 60, "ctrl");
app.waitForFrame(120);
app.waitForSamples(app.samples() + 8, 600);
app.processEvents(300);
check(app.grabWindow(out + "/editor_dragged.png"), "grab 2");
app.quit(0);
