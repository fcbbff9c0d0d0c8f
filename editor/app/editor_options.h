// Command line of the editor:
//   wavelit [SCENE.wlscene] [--script FILE.js] [--device auto|vulkan|cpu]
//           [--size WxH] [--max-spp N] [--validation] [--light-mix]
// With no scene the bundled default scene (WAVELIT_DEFAULT_SCENE) opens. --size overrides the
// scene's render resolution (tests render at 128x128); --max-spp stops refining after N samples.
// --light-mix renders light-group layers so light intensity, colour and mute edits remix the
// layers instead of restarting (docs/lightmix.md).
#pragma once

#include "viewport/render_controller.h"

#include "util/result.h"

#include <QString>
#include <QStringList>

namespace wavelit::editor {

struct EditorOptions {
    QString scenePath;  // empty: open nothing
    QString scriptPath; // empty: interactive
    RenderSettings render;
};

QString defaultScenePath();

// Parses arguments (argv[0] included). Bad usage is an error of kind Usage naming the flag.
util::Result<EditorOptions> parseEditorOptions(const QStringList& arguments);

// The usage text printed by --help and on bad usage.
QString editorUsage();

} // namespace wavelit::editor
