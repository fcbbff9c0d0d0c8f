// wavelit-args: --size 32x32 --sampler bsdf --max-spp 2
// wavelit-scene: scenes/ring_on_ground.wlscene
// Drag-and-drop onto the window (real drag-enter and drop events): a .wllight is applied, an
// .obj becomes an object, an .exr the environment map, a .wlscene opens; each drop is one undo
// step and the scene still renders.
var res = app.environment("WAVELIT_UI_RESOURCES");
check(app.waitForSamples(1, 300) >= 1, "no first frame");
check(app.dropFile(res + "/lighting/sun_sky.wllight"), "drop .wllight: " + app.lastError());
check(app.entities().indexOf("sun") >= 0 && app.entities().indexOf("softbox") < 0, "the setup was not applied: " + app.entities());
check(app.dropFile(res + "/meshes/cube.obj"), "drop .obj: " + app.lastError());
check(app.entities().indexOf("cube") >= 0, "the mesh was not added: " + app.entities());
check(app.getProperty("object:cube", "mesh") == "../meshes/cube.obj", "mesh path not relative to the scene: " + app.getProperty("object:cube", "mesh"));
check(app.dropFile(res + "/envmaps/night.exr"), "drop .exr: " + app.lastError());
check(String(app.getProperty("environment", "map")).indexOf("night.exr") >= 0, "the map was not set: " + app.getProperty("environment", "map"));
check(app.waitForSamples(2, 300) >= 2, "no frame after the drops");
check(app.undo() && String(app.getProperty("environment", "map")).indexOf("night.exr") < 0, "undo of the map drop");
check(app.undo() && app.entities().indexOf("cube") < 0, "undo of the mesh drop");
check(app.undo() && app.entities().indexOf("softbox") >= 0, "undo of the setup drop");
check(!app.isModified(), "undoing every drop did not return to the saved state");
check(app.dropFile(res + "/scenes/glossy_sphere.wlscene"), "drop .wlscene");
check(app.scenePath().indexOf("glossy_sphere.wlscene") >= 0, "the dropped scene did not open: " + app.scenePath());
check(app.waitForSamples(1, 300) >= 1, "no frame of the dropped scene");
check(app.validationMessages() == 0, "Vulkan validation messages: " + app.validationMessages());
app.quit(0);
