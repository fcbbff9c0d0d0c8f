// Run by scripts/lightmix_boost_noise.sh: each remix and fresh render against the reference
// (luminance RMSE), and the medians.
var dir = app.environment("LIGHTMIX_NOISE_DIR");
var reps = parseInt(app.environment("LIGHTMIX_NOISE_REPS"));
function median(v) { v = v.slice().sort(function (a, b) { return a - b; }); return v[Math.floor(v.length / 2)]; }
var mix = [], fresh = [];
for (var i = 1; i <= reps; ++i) {
    var m = app.compareImages(dir + "/mix_" + i + ".exr", dir + "/ref.exr");
    var f = app.compareImages(dir + "/fresh_" + i + ".exr", dir + "/ref.exr");
    mix.push(m.relativeRms);
    fresh.push(f.relativeRms);
    console.log("lightmix noise: rep " + i + ": remix x4 relRMSE " + m.relativeRms.toFixed(4) + " (mean " +
                m.meanA.toFixed(4) + "), fresh " + f.relativeRms.toFixed(4) + " (mean " + f.meanA.toFixed(4) +
                "), reference mean " + m.meanB.toFixed(4));
}
console.log("lightmix noise: median relRMSE remix x4 " + median(mix).toFixed(4) + ", fresh " + median(fresh).toFixed(4));
app.quit(0);
