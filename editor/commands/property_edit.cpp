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
    scene::ChangeSet changes;
    if (auto status = changes.setProperty(scene, edit.entity, edit.name, edit.value); !status)
        return status.error();
    auto edited = std::make_shared<scene::Scene>(scene);
    if (auto status = changes.apply(*edited); !status)
        return status.error();
    scene::PropertyValue previous = std::get<scene::PropertyEdit>(changes.edits().front()).oldValue;
    return AppliedEdit{std::move(edited), std::move(previous), info->change, std::move(changes)};
}

} // namespace wavelit::editor
