// wavelit-args: --size 32x32 --sampler bsdf --max-spp 2
// wavelit-scene: scenes/ring_on_ground.wlscene
// Bad files give an error naming the file, never a crash: each file call returns false and
// app.lastError() says which file and what is wrong; the document is unchanged and still renders.
var data = app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/";
var out = app.environment("WAVELIT_SCRIPT_OUT");
check(app.waitForSamples(1, 300) >= 1, "no first frame");
var before = app.entities().join(",");

function refused(call, file, what) {
    var ok = call();
    var message = app.lastError();
    console.log(what + " -> " + ok + ": " + message.replace(/\n/g, " | "));
    check(ok === false, what + " should fail");
    check(message.indexOf(file) >= 0, what + ": the message does not name " + file + ": " + message);
}
refused(function () { return app.applyLighting(data + "bad_truncated.wllight"); }, "bad_truncated.wllight", "truncated setup");
refused(function () { return app.applyLighting(data + "bad_unknown_key.wllight"); }, "bad_unknown_key.wllight", "unknown key");
check(app.lastError().indexOf("intensty") >= 0, "the unknown key is not named: " + app.lastError());
refused(function () { return app.applyLighting(data + "missing.wllight"); }, "missing.wllight", "missing setup");
refused(function () { return app.setEnvironmentMap(data + "bad_not_an.exr"); }, "bad_not_an.exr", "not an EXR");
refused(function () { return app.addObject(data + "bad_index.obj", "broken"); }, "bad_index.obj", "bad mesh");
refused(function () { return app.renderToFile(out + "/image.tga", {spp: 1}); }, "image.tga", "unknown image type");
refused(function () { return app.saveLighting(out + "/setup.txt"); }, "setup.txt", "not a .wllight");

// A dropped file of a type the window does not take is refused at once.
var threw = false;
try { app.dropFile(data + "../files_bad_files.js"); } catch (e) { threw = String(e).indexOf("files_bad_files.js") >= 0; }
check(threw, "a dropped .js file was not refused naming it");
// A dropped bad setup goes through the same checks as the menu.
check(app.dropFile(data + "bad_unknown_key.wllight") === false, "a dropped bad setup was accepted");
check(app.lastError().indexOf("bad_unknown_key.wllight") >= 0, "the dropped file is not named");

check(app.entities().join(",") == before, "a failed call changed the outline: " + app.entities());
check(!app.isModified(), "a failed call marked the document modified");
check(app.undo() === false, "a failed call left an undo step");
app.setProperty("environment", "rotation", 45);
check(app.waitForSamples(2, 300) >= 2, "the editor no longer renders after the errors");
check(app.validationMessages() == 0, "Vulkan validation messages: " + app.validationMessages());
app.quit(0);
