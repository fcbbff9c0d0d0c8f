#include "commands/property_edit.h"

#include <atomic>

namespace wavelit::editor {

GestureId newGestureId() {
    static std::atomic<GestureId> next{1};
    return next.fetch_add(1);
}

util::Result<AppliedEdit> applyEdit(const scene::Scene& scene, const PropertyEdit& edit) {
    const scene::PropertyInfo* info = scene::findProperty(edit.entity.kind, edit.name);
    if (!info)
        return util::makeError(util::ErrorKind::Invalid, "",
                               std::string(scene::entityKindName(edit.entity.kind)) +
                                   " has no property '" + edit.name + "'");
    auto previous = scene::getProperty(scene, edit.entity, edit.name);
    if (!previous) return previous.error();
    auto edited = std::make_shared<scene::Scene>(scene);
    if (auto status = scene::setProperty(*edited, edit.entity, edit.name, edit.value); !status)
        return status.error();
    return AppliedEdit{std::move(edited), std::move(previous.value()), info->change};
}

} // namespace wavelit::editor
