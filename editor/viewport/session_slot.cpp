#include "viewport/session_slot.h"

namespace wavelit::editor {

bool sameSessionOptions(const render::RenderOptions& a, const render::RenderOptions& b) {
    return a.width == b.width && a.height == b.height && a.bounces == b.bounces &&
           a.seed == b.seed && a.device == b.device && a.sampler == b.sampler &&
           a.vulkanDevice == b.vulkanDevice && a.validation == b.validation &&
           a.lightGroups == b.lightGroups;
}

void SessionSlot::queue(std::shared_ptr<const scene::Scene> scene, const render::RenderOptions& opts,
                        quint64 jobGeneration, const std::optional<scene::ChangeSet>& changes,
                        quint64 baseGeneration, bool incremental) {
    SessionUpdate next;
    next.scene = std::move(scene);
    next.options = opts;
    next.generation = jobGeneration;
    if (incremental && changes) {
        if (update) { // the session is already behind: chain onto its queued update
            if (update->changes && update->generation == baseGeneration &&
                sameSessionOptions(update->options, opts)) {
                next.changes = std::move(update->changes);
                next.changes->merge(*changes);
            }
        } else if (session && generation != 0 && generation == baseGeneration &&
                   sameSessionOptions(options, opts)) {
            next.changes = *changes;
        }
    }
    update = std::move(next);
}

util::Status SessionSlot::sync(const render::InterruptCheck& interrupt) {
    if (!update) return util::okStatus();
    SessionUpdate next = std::move(*update);
    update.reset();
    if (session && sameSessionOptions(options, next.options)) {
        util::Status status = next.changes ? session->applyChanges(*next.scene, *next.changes)
                                           : session->setScene(*next.scene);
        if (!status) {
            reset();
            return status;
        }
        generation = next.generation;
        return util::okStatus();
    }
    session.reset(); // release the old device before creating the next one
    auto created = render::RenderSession::create(*next.scene, next.options);
    if (!created) {
        reset();
        return created.error();
    }
    session = std::move(created.value());
    session->setInterruptCheck(interrupt);
    options = next.options;
    generation = next.generation;
    return util::okStatus();
}

void SessionSlot::reset() {
    session.reset();
    generation = 0;
    update.reset();
}

} // namespace wavelit::editor
