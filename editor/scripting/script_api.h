// AppApi: the `app` object scripts see (docs/scripting.md). Scripts run on the UI thread; the
// waiting calls (openScene, waitForSamples) spin a local event loop, so the window keeps painting
// and the render thread keeps delivering frames while a script waits. Failures throw a JS Error
// whose message names the file or property.
#pragma once

#include <QJSValue>
#include <QObject>
#include <QString>

#include <functional>

class QJSEngine;

namespace wavelit::editor {

class MainWindow;

class AppApi : public QObject {
    Q_OBJECT
public:
    AppApi(MainWindow* window, QJSEngine* engine);

    // Opens a scene and waits until it is loaded (throws on failure).
    Q_INVOKABLE bool openScene(const QString& path);
    // Waits until the render has at least `spp` samples per pixel (throws on a render error or
    // after timeoutSeconds, default 600). Returns the samples per pixel reached.
    Q_INVOKABLE int waitForSamples(int spp, double timeoutSeconds = 600.0);
    // The viewport's current frame: .exr = linear radiance, .png = tone-mapped with the exposure.
    Q_INVOKABLE bool saveImage(const QString& path);
    // Save (File → Save): the scene to its file and, if edited, the lighting setup it refers to.
    Q_INVOKABLE bool save();
    // Save As without a dialog: `lighting` says where edited referenced lighting goes — "copy"
    // (default: a *.wllight beside the scene), "inline", "setup" (into the shared setup) or
    // "reference" (keep the reference; only for unedited lighting).
    Q_INVOKABLE bool saveScene(const QString& path, const QString& lighting = QString());
    // Answers every "Save changes?" prompt from now on: "save", "discard" or "cancel"; "" clears
    // (then, while a script runs, prompts answer "cancel").
    Q_INVOKABLE bool answerPrompts(const QString& answer);
    Q_INVOKABLE bool isModified() const;
    // Writes the open document's recovery file now and waits (false: nothing unsaved to write).
    Q_INVOKABLE bool autosave();
    // The recovery file of the open document if one exists (newer than the scene file), else "".
    Q_INVOKABLE QString recoveryFile() const;
    // Answers every later "Recover unsaved changes?" offer: "recover", "discard" or "keep"; ""
    // clears (then, while a script runs, recoveries are kept).
    Q_INVOKABLE bool answerRecovery(const QString& answer);
    // The window title as shown, with "*" when the document has unsaved changes.
    Q_INVOKABLE QString windowTitle() const;
    // A screenshot of the whole editor window (PNG), for documentation and bug reports.
    Q_INVOKABLE bool grabWindow(const QString& path);
    // entity: "camera", "environment", "render", "kind:name" ("material:ground") or a light/object/
    // material name that only one entity has (else the error lists the candidates); name: the
    // registry's property name; value: number, bool, string, [x, y(, z)] or an entity name (IdRef).
    // Each call is its own undo step.
    Q_INVOKABLE bool setProperty(const QString& entity, const QString& name, const QJSValue& value);
    Q_INVOKABLE QJSValue getProperty(const QString& entity, const QString& name);
    Q_INVOKABLE bool triggerAction(const QString& objectName);
    // Selects an entity in the outline (its properties show in the property panel).
    Q_INVOKABLE bool select(const QString& entity);
    Q_INVOKABLE int samples() const;
    // LightMix (docs/lightmix.md; script_api_lightmix.cpp). setMute: the light's `muted` property,
    // one undo step. solo: mutes every other light and unmutes this one, one undo step (the
    // environment is left as it is). frameStatus: what the latest frame's update did ("remixed:
    // no restart" when an edit was shown by recombining light-group layers, `wavelit --light-mix`).
    Q_INVOKABLE bool setMute(const QString& light, bool muted);
    Q_INVOKABLE bool solo(const QString& light);
    Q_INVOKABLE QString frameStatus() const;
    // LightMix (issue 21): Extract sun and A/B (docs/lightmix.md, script_api_lightmix.cpp).
    // extractSun: the environment's sun becomes a `sun` light and the map gets a mask, one undo
    // step; returns the new light's name (throws when the map has no sun).
    // snapshot: stores the current lighting under `name`. compare(a, b): the A/B split view, each
    // side a snapshot name, "current" (the open setup, live) or a *.wllight path (needs
    // `wavelit --light-mix`); returns each side's mode, {a: "remix"|"render", b: ...}: a remix of
    // the rendered layers where only weights differ, its own render otherwise. setCompareWipe: the wipe line, 0..1 (the part showing A). compareMeans: [A, B], each
    // side's mean luminance at the latest frame. saveCompare: the split view as shown (PNG).
    Q_INVOKABLE QString extractSun();
    Q_INVOKABLE bool snapshot(const QString& name);
    Q_INVOKABLE QJSValue compare(const QString& a, const QString& b);
    Q_INVOKABLE bool setCompareWipe(double fraction);
    Q_INVOKABLE QJSValue compareMeans();
    Q_INVOKABLE bool saveCompare(const QString& path);
    Q_INVOKABLE bool endCompare();
    // --- lightmix3: A/B renders and groups ---
    // compareSamples: [A, B], each side's samples per pixel (a remix: the viewport's; a render:
    // its own session's). (script_api_lightmix.cpp)
    Q_INVOKABLE QJSValue compareSamples();
    // Viewport (issue 14)
    // script_api_viewport.cpp, docs/scripting.md "Viewport". Image points are
    // the viewport image's pixels ((0, 0) its top-left corner). dragInViewport sends real mouse
    // events (press, `steps` moves `msPerStep` apart, release) through the viewport's handlers;
    // modifiers: '+'-joined ctrl, shift, alt, middle, right. pickInViewport clicks and returns the
    // selected entity ("kind:name", "" for nothing). handleInViewport: where an entity's handle
    // (a light's position, a sun's handle, an object's origin) is drawn, [x, y] or null.
    // waitForFrame: waits for the first frame of the latest edit on screen and returns {spp, kind:
    // "preview"|"pathtraced", source: "relight"|"draft"|"pathtraced", msSinceEdit,
    // estimatedRelError}. frameLuminance: the latest path-traced (or "displayed") frame's Rec.709
    // luminance, row-major. (undo/redo: in the files block below.)
    // processEvents: lets the editor run for `ms` milliseconds (edits pause, frames arrive).
    Q_INVOKABLE bool dragInViewport(double x0, double y0, double x1, double y1,
                                    const QString& modifiers = QString(), int steps = 8, int msPerStep = 0);
    Q_INVOKABLE QString pickInViewport(double x, double y);
    Q_INVOKABLE QJSValue handleInViewport(const QString& entity);
    Q_INVOKABLE QJSValue waitForFrame(double timeoutSeconds = 600.0);
    Q_INVOKABLE QJSValue frameLuminance(const QString& which = QString());
    Q_INVOKABLE void processEvents(int ms);
    Q_INVOKABLE int framesShown() const; // frames the viewport has been given so far (any kind)
    Q_INVOKABLE QString scenePath() const;
    Q_INVOKABLE QStringList entities() const; // every outline entry's display name
    Q_INVOKABLE QString environment(const QString& name) const; // an environment variable
    // Files, outline and panels (issue 14; script_api_files.cpp, docs/scripting.md). Outline edits
    // are one undo step each and throw on a refused edit; file calls return false on a bad file
    // and keep the message for lastError() (the window shows it in a dialog).
    Q_INVOKABLE QString addLight(const QString& type, const QString& name = QString());
    Q_INVOKABLE QJSValue addObject(const QString& meshPath, const QString& name = QString());
    Q_INVOKABLE QString addMaterial(const QString& name = QString());
    Q_INVOKABLE bool remove(const QString& entity);
    Q_INVOKABLE QString duplicate(const QString& entity);
    Q_INVOKABLE bool rename(const QString& entity, const QString& name);
    Q_INVOKABLE bool undo();
    Q_INVOKABLE bool redo();
    Q_INVOKABLE bool newScene();
    Q_INVOKABLE bool saveLighting(const QString& path);
    Q_INVOKABLE bool applyLighting(const QString& path);
    Q_INVOKABLE bool setEnvironmentMap(const QString& path);
    Q_INVOKABLE bool dropFile(const QString& path);
    Q_INVOKABLE bool renderToFile(const QString& path, const QJSValue& budget);
    Q_INVOKABLE QString lastError() const;
    Q_INVOKABLE QStringList recentFiles() const;
    Q_INVOKABLE QString statusText() const;
    Q_INVOKABLE double noiseEstimate() const;
    // Vulkan validation messages of the viewport's session so far (tests require 0; the layers
    // are on with --validation or WAVELIT_VK_VALIDATION=1).
    Q_INVOKABLE int validationMessages() const;
    // Image files for tests: {width, height, finite, mean: [r, g, b], meanLuminance} or throws;
    // compareImages: {rms, relativeRms, meanA, meanB} over luminance (same size, else throws).
    Q_INVOKABLE QJSValue imageInfo(const QString& path);
    Q_INVOKABLE QJSValue compareImages(const QString& a, const QString& b);
    // --- editor3: gizmo modes and manipulators ---
    // script_api_gizmo.cpp, docs/scripting.md "Gizmo modes, shape handles, cross-fade".
    // setGizmoMode: "move" or "rotate" (the W / E keys). gizmoInfo: where the selection's handles
    // are drawn now, in image pixels: {mode, ringRadius, rings: {x|y|z: {point, tangent}},
    // handles: {radius|sizeX|sizeY|cone: [x, y]}} (rings only in rotate mode). viewportMessage:
    // the refusal a clamped shape-handle drag shows ("" for none). projectToViewport: a world point's
    // image point ([x, y] or null behind the camera). setCrossFadeMs: the preview -> path-traced
    // fade's length (0: switch at once; default 200). viewportPixels: the viewport as painted,
    // sampled at the image's pixel centres, {fade, luminance: [W x H sRGB-encoded luminance,
    // 0..255]} (fade: the new image's opacity in that paint, -1 when one image was painted);
    // "frame" gives the displayed frame's own display image instead (fade -1).
    Q_INVOKABLE bool setGizmoMode(const QString& mode);
    Q_INVOKABLE QString gizmoMode() const;
    Q_INVOKABLE QJSValue gizmoInfo();
    Q_INVOKABLE QString viewportMessage() const;
    Q_INVOKABLE QJSValue projectToViewport(const QJSValue& point);
    Q_INVOKABLE bool setCrossFadeMs(int ms);
    Q_INVOKABLE QJSValue viewportPixels(const QString& which = QString());
    // --- end editor3 ---
    // Ends the editor with this exit code once the script returns.
    Q_INVOKABLE void quit(int exitCode = 0);

    bool quitRequested() const { return m_quit; }
    int exitCode() const { return m_exitCode; }

private:
    bool fail(const QString& message); // throws in the engine, returns false
    bool waitForSave(const std::function<void()>& start);
    // Runs a FileActions operation and spins the event loop until its `done` reports.
    bool waitForFileOperation(const std::function<void(std::function<void(const QString&)>)>& start);

    MainWindow* m_window;
    QJSEngine* m_engine;
    bool m_quit = false;
    int m_exitCode = 0;
};

} // namespace wavelit::editor
