// wavelit-args: --size 64x64 --sampler bsdf
// Issue 14: a click in the viewport selects what is under it (light handles first, then the
// first object along the camera ray), in sync with the outline; a click on nothing clears it.
app.openScene(app.environment("WAVELIT_SOURCE_DIR") + "/tests/ui/data/viewport_point_light.wlscene");
app.waitForSamples(1, 300);
var bulb = app.handleInViewport("light:bulb");
check(app.pickInViewport(bulb[0], bulb[1]) == "light:bulb", "the bulb's handle did not pick the bulb");
// The post (a 0.25 m box at x = 1.6, z = -1.6) is seen from above: its top face round its centre.
var post = app.handleInViewport("object:post");
console.log("post at " + post);
check(Math.abs(post[0] - 54.2) < 1 && Math.abs(post[1] - 9.8) < 1, "post projects to " + post);
check(app.pickInViewport(post[0], post[1]) == "object:post", "the post's pixel did not pick the post");
// 3 pixels off the post's 2.2-pixel-wide top: the floor.
check(app.pickInViewport(post[0] - 4, post[1] + 4) == "object:floor", "beside the post is not the floor");
check(app.pickInViewport(40, 40) == "object:floor", "the floor");
// The outline follows: its selection is the picked entity.
app.pickInViewport(bulb[0] + 0.2, bulb[1]);
check(app.pickInViewport(bulb[0], bulb[1] + 0.3) == "light:bulb", "near the handle");
app.quit(0);
