// wavelit-args: --size 64x64 --sampler mis
// Issue 14: drag a point light with the move gizmo (real mouse events through the viewport's
// event filters) and check the image changed where it should. The scene (data/viewport_point_light)
// looks straight down at a floor lit by a constant sky (irradiance pi * 0.5) and a 10 W bulb
// 0.3 m above it: under the bulb its irradiance is ~8.8, 5.6x the sky's; 2 m away it is ~0.03,
// 2% of the sky's. So after the drag the floor under the new position is several times brighter,
// under the old one several times darker, and far from both (|z| ~ 2 m) within a few percent.
function regionMeanAt(lum, cx, cy, r) { // mean luminance of the (2r+1)^2 pixels round (cx, cy)
    var sum = 0, n = 0;
    for (var y = Math.round(cy) - r; y <= Math.round(cy) + r; ++y)
        for (var x = Math.round(cx) - r; x <= Math.round(cx) + r; ++x)
            if (x >= 0 && x < 64 && y >= 0 && y < 64) { sum += lum[y * 64 + x]; ++n; }
    return sum / n;
}
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_point_light.wlscene");
app.waitForSamples(16, 300);
var before = app.frameLuminance();
app.select("light:bulb");
var from = app.handleInViewport("light:bulb");
// The bulb at depth 3.7 m: 32 - 1.2 / (3.7 tan 30deg) * 32 = 14.02.
check(from !== null && Math.abs(from[0] - 14.02) < 0.05 && Math.abs(from[1] - 32) < 0.05, "bulb handle at " + from);
function floorPixel(x) { return 32 + x / (4 * Math.tan(Math.PI / 6)) * 32; } // the floor under x (z = 0)
// The gizmo's centre moves in the plane facing the camera: 34 image pixels at the bulb's depth
// (3.7 m, 2 * 3.7 * tan 30deg / 64 = 0.0668 m a pixel) is 2.27 m along +x.
check(app.dragInViewport(from[0], from[1], from[0] + 34, from[1]), "drag");
var p = app.getProperty("light:bulb", "position");
console.log("bulb moved to " + p);
check(Math.abs(p[0] - (-1.2 + 34 * 0.0668)) < 0.05 && Math.abs(p[1] - 0.3) < 1e-4 && Math.abs(p[2]) < 1e-4,
      "bulb position after the drag: " + p);
var first = app.waitForFrame(120);
console.log("first frame after the drag: " + JSON.stringify(first));
app.waitForSamples(16, 300);
var after = app.frameLuminance();
var nearNew = regionMeanAt(after, floorPixel(p[0]), 32, 3) / regionMeanAt(before, floorPixel(p[0]), 32, 3);
var nearOld = regionMeanAt(after, floorPixel(-1.2), 32, 3) / regionMeanAt(before, floorPixel(-1.2), 32, 3);
var farTop = regionMeanAt(after, 32, 4, 3) / regionMeanAt(before, 32, 4, 3);
var farBottom = regionMeanAt(after, 32, 59, 3) / regionMeanAt(before, 32, 59, 3);
console.log("after/before: near the new position " + nearNew.toFixed(3) + ", near the old " +
            nearOld.toFixed(3) + ", far (top, bottom) " + farTop.toFixed(3) + " " + farBottom.toFixed(3));
check(nearNew > 2.5, "not brighter under the new position: " + nearNew);
check(nearOld < 0.4, "not darker under the old position: " + nearOld);
check(Math.abs(farTop - 1) < 0.06 && Math.abs(farBottom - 1) < 0.06, "far regions changed: " + farTop + " " + farBottom);
// One drag is one undo step.
check(app.undo(), "undo");
var q = app.getProperty("light:bulb", "position");
check(q[0] === -1.2 || Math.abs(q[0] + 1.2) < 1e-6, "undo did not restore the position: " + q);
check(!app.undo(), "the drag took more than one undo step");
app.quit(0);
