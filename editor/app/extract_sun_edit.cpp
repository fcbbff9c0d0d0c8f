#include "app/extract_sun_edit.h"

#include "app/scene_document.h"

#include "render/lights/extract_sun.h"
#include "scene/change_set.h"
#include "scene/scene_io.h"

#include <filesystem>

namespace wavelit::editor {

util::Result<std::string> extractSunEdit(SceneDocument& document) {
    const std::shared_ptr<const scene::Scene> current = document.scene();
    if (!current) return util::makeError(util::ErrorKind::Invalid, "", "extract sun: no scene is open");
    const std::string scenePath = document.path().toStdString();
    const std::string file = current->lightingPath.empty()
                                 ? scenePath
                                 : (std::filesystem::path(scenePath).parent_path() / current->lightingPath)
                                       .lexically_normal()
                                       .string();
    scene::Scene working = *current;
    // After an edit of the map the document holds no image (the render thread loads it): load it
    // here, masked as the scene says, to search it.
    if (!working.lighting.environment.path.empty() && !working.lighting.environment.image)
        if (auto loaded = scene::loadAssets(working, scenePath); !loaded) return loaded.error();
    auto extracted = render::extractSun(working, file);
    if (!extracted) return extracted.error();

    const scene::Environment& masked = extracted->scene.lighting.environment;
    const scene::EntityRef environment{scene::EntityKind::Environment, scene::kInvalidId};
    scene::ChangeSet changes;
    changes.addLight(*current, extracted->scene.lighting.lights.back());
    if (auto s = changes.setProperty(*current, environment, "maskDirection", masked.maskDirection); !s) return s.error();
    if (auto s = changes.setProperty(*current, environment, "maskRadius", masked.maskRadiusDeg); !s) return s.error();
    if (auto s = document.applyChanges(changes, QStringLiteral("extract sun")); !s) return s.error();
    return extracted->lightName;
}

} // namespace wavelit::editor
