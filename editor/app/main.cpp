// wavelit: the lighting-design editor. See app/editor_options.h for the command line and
// docs/scripting.md for --script.
#include "app/editor_options.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "scripting/script_host.h"

#include <QApplication>
#include <QTimer>

#include <cstdio>
#include <cstdlib>

namespace {

bool hasDisplay() {
    return std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY") || std::getenv("QT_QPA_PLATFORM");
}

} // namespace

int main(int argc, char** argv) {
    // Parse before QApplication exists, so bad usage is reported even where no display is.
    QStringList arguments;
    for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
    if (arguments.contains("--help") || arguments.contains("-h")) {
        std::fputs(qPrintable(wavelit::editor::editorUsage()), stdout);
        return 0;
    }
    auto options = wavelit::editor::parseEditorOptions(arguments);
    if (!options) {
        std::fprintf(stderr, "wavelit: %s\n%s", options.error().message().c_str(),
                     qPrintable(wavelit::editor::editorUsage()));
        return 2;
    }
    if (!hasDisplay()) {
        // A script needs no screen: the renderer draws into memory (no Vulkan window).
        if (!options->scriptPath.isEmpty()) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        } else {
            std::fprintf(stderr, "wavelit: no display (DISPLAY/WAYLAND_DISPLAY unset). Run under "
                                 "xvfb-run, set QT_QPA_PLATFORM=offscreen, or render headless "
                                 "with wavelit-cli render.\n");
            return 1;
        }
    }

    QApplication app(argc, argv);
    QApplication::setApplicationName("Wavelit");
    QApplication::setOrganizationName("Wavelit");

    wavelit::editor::MainWindow window(options->render);
    window.show();
    // A script starts on the named (or default) scene too; its app.openScene() replaces it.
    window.document()->open(options->scenePath);
    if (options->scriptPath.isEmpty()) return app.exec();

    auto* host = new wavelit::editor::ScriptHost(&window);
    const QString script = options->scriptPath;
    QTimer::singleShot(0, &window, [host, script] {
        const int code = host->runFile(script);
        if (code >= 0) QCoreApplication::exit(code);
    });
    return app.exec();
}
