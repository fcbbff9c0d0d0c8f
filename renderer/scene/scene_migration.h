// Upgrades older *.wlscene / *.wllight JSON to the current layout before it is read, so the
// reader only knows one version (architecture.md §6: older versions migrated, newer ones rejected).
//
// Version 0 (pre-release files): the environment had "exposure" in EV stops instead of a linear
// "intensity"; objects named their material by name ("material": "gold") instead of by id.
#pragma once

#include "scene/property_json.h"
#include "util/result.h"

#include <string>

namespace wavelit::scene {

// Checks "format" and "version" and migrates `doc` in place to the current version.
// expectedFormat: "wavelit-scene" or "wavelit-lighting".
util::Status checkAndMigrate(Json& doc, const std::string& expectedFormat, int currentVersion,
                             const std::string& file);

} // namespace wavelit::scene
