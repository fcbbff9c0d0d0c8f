// Scene and lighting-setup JSON through the public loaders, migration included (version 0 seeds):
// bytes -> input.wlscene (or input.wllight when built with WAVELIT_FUZZ_LIGHTING) -> loadScene /
// loadLightingSetup. An error must name the file (fuzz_support.h); a file that loads must save and
// load back unchanged (scene_compare.h), because the editor saves what it opened.
#include "fuzz_support.h"

#include "scene/scene_compare.h"
#include "scene/scene_io.h"

namespace {

using namespace wavelit;

template <typename T, typename Load, typename Save>
void loadSaveLoad(const std::string& path, const std::string& copy, Load load, Save save) {
    scene::LoadReport report;
    util::Result<T> loaded = load(path, &report);
    if (!loaded) {
        fuzz::checkError(loaded.error(), path);
        return;
    }
    if (auto s = save(*loaded, copy); !s) fuzz::finding("a loaded file does not save: " + s.error().message());
    util::Result<T> again = load(copy, nullptr);
    if (!again) fuzz::finding("a saved file does not load: " + again.error().message());
    if (auto d = scene::firstDifference(*loaded, *again); !d.empty()) fuzz::finding("saving changed it: " + d);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
#ifdef WAVELIT_FUZZ_LIGHTING
    const std::string path = fuzz::writeInput(data, size, "input.wllight");
    loadSaveLoad<scene::LightingSetup>(path, fuzz::inputFolder() + "/saved.wllight", scene::loadLightingSetup,
                                       scene::saveLightingSetup);
#else
    const std::string path = fuzz::writeInput(data, size, "input.wlscene");
    loadSaveLoad<scene::Scene>(
        path, fuzz::inputFolder() + "/saved.wlscene",
        [](const std::string& p, scene::LoadReport* r) {
            auto s = scene::loadScene(p, r);
            if (s) {
                for (const scene::Object& o : s->objects)
                    if (!o.mesh) fuzz::finding("object '" + o.name + "' loaded without its mesh");
                if (!s->lighting.environment.path.empty() && !s->lighting.environment.image)
                    fuzz::finding("environment map not loaded");
            }
            return s;
        },
        scene::saveScene);
#endif
    return 0;
}
