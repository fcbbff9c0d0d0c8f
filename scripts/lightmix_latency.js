// Remix latency (docs/lightmix.md): run by scripts/lightmix_latency.sh inside
// `wavelit --light-mix`; each intensity edit is shown by a remix, whose cost the render thread
// states in the frame it publishes at once ("remixed: no restart (frame in X ms)"): the layers'
// read-back, their recombination and the tone mapping, on the render thread.
var spp = app.waitForSamples(2, 600);
for (var i = 0; i < 9; ++i) {
    app.setProperty("light:window", "intensity", 40 + 10 * (i % 2));
    spp = app.waitForSamples(spp, 600); // the remix frame: the samples so far, nothing lost
    console.log("lightmix latency: " + app.frameStatus());
    if (app.frameStatus().indexOf("remixed") != 0) throw new Error("not a remix: " + app.frameStatus());
}
app.quit(0);
