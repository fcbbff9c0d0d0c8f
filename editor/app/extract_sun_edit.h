// "Extract sun" in the editor (issue 21, docs/lightmix.md): the open scene's environment sun
// becomes a `sun` light and the environment gets the mask that removes it
// (render/lights/extract_sun.h), as one undo step of the document. Used by the Lighting menu's
// action and by app.extractSun().
#pragma once

#include "util/result.h"

#include <string>

namespace wavelit::editor {

class SceneDocument;

// The new light's name, or why there is no sun to extract (the message names the file).
util::Result<std::string> extractSunEdit(SceneDocument& document);

} // namespace wavelit::editor
