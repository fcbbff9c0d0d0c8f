// Helpers of the scripted UI tests: run_ui_script.cmake puts this file before each test script
// (so a test's error line numbers are offset by this file's length).
// check: fail the test (exit 1) with a message unless `ok`.
function check(ok, what) { if (!ok) { console.log("FAIL: " + what); app.quit(1); throw new Error(what); } }
// Mean luminance of the (2r+1)^2 pixels round c = [x, y] of a 64 x 64 app.frameLuminance().
function regionMean(lum, c, r) {
    var sum = 0, n = 0;
    for (var y = Math.round(c[1]) - r; y <= Math.round(c[1]) + r; ++y)
        for (var x = Math.round(c[0]) - r; x <= Math.round(c[0]) + r; ++x)
            if (x >= 0 && x < 64 && y >= 0 && y < 64) { sum += lum[y * 64 + x]; ++n; }
    return sum / n;
}
// Relative RMSE of luminance arrays a against b (image_metrics.h relativeMse, epsilon 1e-2).
function relRmse(a, b) {
    var s = 0;
    for (var i = 0; i < a.length; ++i) s += (a[i] - b[i]) * (a[i] - b[i]) / (b[i] * b[i] + 1e-2);
    return Math.sqrt(s / a.length);
}
