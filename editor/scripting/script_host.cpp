#include "scripting/script_host.h"

#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "scripting/script_api.h"

#include <QFile>
#include <QEventLoop>
#include <QJSEngine>
#include <QTimer>

#include <cstdio>

namespace wavelit::editor {

ScriptHost::ScriptHost(MainWindow* window)
    : QObject(window), m_window(window), m_engine(new QJSEngine(this)),
      m_api(new AppApi(window, m_engine)) {
    m_engine->installExtensions(QJSEngine::ConsoleExtension);
    m_engine->globalObject().setProperty("app", m_engine->newQObject(m_api));
}

ScriptHost::~ScriptHost() = default;

int ScriptHost::runFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        std::fprintf(stderr, "wavelit: cannot read script '%s': %s\n", qPrintable(path),
                     qPrintable(file.errorString()));
        return 1;
    }
    const QString source = QString::fromUtf8(file.readAll());
    m_window->errors()->setDialogsEnabled(false);
    // The scene named on the command line (or the default) is open before the first line runs.
    while (m_window->document()->isLoading()) {
        QEventLoop loop;
        QTimer::singleShot(20, &loop, &QEventLoop::quit);
        loop.exec();
    }
    const QJSValue result = m_engine->evaluate(source, path);
    m_window->errors()->setDialogsEnabled(true);
    if (result.isError()) {
        std::fprintf(stderr, "%s:%d: %s\n", qPrintable(path),
                     result.property("lineNumber").toInt(), qPrintable(result.toString()));
        return 1;
    }
    return m_api->quitRequested() ? m_api->exitCode() : -1;
}

} // namespace wavelit::editor
