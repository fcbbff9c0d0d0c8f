// AppApi: the `app` object scripts see (docs/scripting.md). Scripts run on the UI thread; the
// waiting calls (openScene, waitForSamples) spin a local event loop, so the window keeps painting
// and the render thread keeps delivering frames while a script waits. Failures throw a JS Error
// whose message names the file or property.
#pragma once

#include <QJSValue>
#include <QObject>
#include <QString>

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
    Q_INVOKABLE bool saveScene(const QString& path);
    // A screenshot of the whole editor window (PNG), for documentation and bug reports.
    Q_INVOKABLE bool grabWindow(const QString& path);
    // entity: "camera", "environment", "render" or a light/object/material name; name: the
    // registry's property name; value: number, bool, string, [x, y(, z)] or an entity name (IdRef).
    Q_INVOKABLE bool setProperty(const QString& entity, const QString& name, const QJSValue& value);
    Q_INVOKABLE QJSValue getProperty(const QString& entity, const QString& name);
    Q_INVOKABLE bool triggerAction(const QString& objectName);
    // Selects an entity in the outline (its properties show in the property panel).
    Q_INVOKABLE bool select(const QString& entity);
    Q_INVOKABLE int samples() const;
    Q_INVOKABLE QString scenePath() const;
    Q_INVOKABLE QStringList entities() const; // every outline entry's display name
    Q_INVOKABLE QString environment(const QString& name) const; // an environment variable
    // Ends the editor with this exit code once the script returns.
    Q_INVOKABLE void quit(int exitCode = 0);

    bool quitRequested() const { return m_quit; }
    int exitCode() const { return m_exitCode; }

private:
    bool fail(const QString& message); // throws in the engine, returns false

    MainWindow* m_window;
    QJSEngine* m_engine;
    bool m_quit = false;
    int m_exitCode = 0;
};

} // namespace wavelit::editor
