// ScriptHost: runs `wavelit --script file.js` in a QJSEngine with the `app` object (script_api.h)
// and console.log. Error dialogs are turned off while a script runs (they are logged and thrown
// into the script instead), so a headless run never blocks on a dialog nobody can close.
#pragma once

#include <QObject>
#include <QString>

class QJSEngine;

namespace wavelit::editor {

class AppApi;
class MainWindow;

class ScriptHost : public QObject {
    Q_OBJECT
public:
    explicit ScriptHost(MainWindow* window);
    ~ScriptHost() override;

    // Waits for the scene that is loading (if any), then evaluates the file. Returns the exit code the editor should end with, or -1 when the script
    // finished without app.quit() (the editor stays open). An uncaught error prints
    // "file:line: message" to stderr and returns 1.
    int runFile(const QString& path);

private:
    MainWindow* m_window;
    QJSEngine* m_engine;
    AppApi* m_api;
};

} // namespace wavelit::editor
