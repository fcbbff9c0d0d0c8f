// wavelit-args: --size 32x32 --sampler bsdf --max-spp 1
// wavelit-scene: scenes/ring_on_ground.wlscene
// The title's dirty marker: none after opening, "*" after an edit (and after an added light),
// none after app.save(); the files on disk hold the edits (reopened and read back); the scene
// is in the recent files; undo back to the saved state clears the marker.
var scene = app.scenePath();
check(app.windowTitle().indexOf("*") < 0, "marker before any edit: " + app.windowTitle());
app.setProperty("material:gold", "roughness", 0.35);
check(app.windowTitle().indexOf("ring_on_ground.wlscene*") >= 0, "no marker after an edit: " + app.windowTitle());
check(app.undo() && app.windowTitle().indexOf("*") < 0, "undo to the opened state left the marker");
check(app.redo() && app.windowTitle().indexOf("*") >= 0, "redo did not bring the marker back");
app.addLight("sphere", "Fill");
check(app.save(), "save");
check(app.windowTitle().indexOf("*") < 0, "marker after save: " + app.windowTitle());
check(!app.isModified(), "modified after save");
check(app.recentFiles().indexOf(scene) >= 0, "the scene is not in the recent files: " + app.recentFiles());

app.newScene();
check(app.entities().indexOf("gold") < 0, "New kept the old scene");
app.openScene(scene);
check(Math.abs(app.getProperty("material:gold", "roughness") - 0.35) < 1e-6, "the saved file lost the roughness edit");
check(app.entities().indexOf("Fill") >= 0, "the saved lighting setup lost the added light");
check(app.windowTitle().indexOf("*") < 0, "marker after reopening");
check(app.validationMessages() == 0, "Vulkan validation messages: " + app.validationMessages());
app.quit(0);
