// wavelit-args: --size 32x32 --sampler bsdf
// wavelit-scene: scenes/ring_on_ground.wlscene
// The runner itself (run_ui_script.cmake): the scene comes from the copy of resources/, a pass
// arrives, and a failed check exits non-zero.
var res = app.environment("WAVELIT_UI_RESOURCES");
check(app.scenePath().indexOf(res) == 0, "scene not from the resources copy: " + app.scenePath());
check(app.waitForSamples(1, 300) >= 1, "no pass arrived");
check(app.entities().length > 2, "outline nearly empty: " + app.entities());
app.quit(0);
