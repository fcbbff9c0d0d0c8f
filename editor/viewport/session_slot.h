// SessionSlot: one RenderSession of the render thread and the update it has not applied yet.
// RenderWorker keeps two: the path tracer at the render size and the reduced-resolution draft
// (render_worker.h). A job is queued on a slot (queueUpdate) when it becomes current, and applied
// only when the slot renders next (sync): while a drag lasts only the draft renders, so the full
// session takes the drag's edits as ONE merged change set when the drag ends, rebuilding only what
// they invalidate (RenderSession::applyChanges), instead of one table rebuild per mouse move.
#pragma once

#include "viewport/render_frame.h"

#include "render/session/render_session.h"

#include <functional>
#include <memory>
#include <optional>

namespace wavelit::editor {

// A session can take a new scene (setScene) only when everything it was created with is the same.
bool sameSessionOptions(const render::RenderOptions& a, const render::RenderOptions& b);

struct SessionUpdate {
    std::shared_ptr<const scene::Scene> scene; // what the session should hold
    // From the scene the session holds to `scene`; empty: swap the whole scene in (setScene).
    std::optional<scene::ChangeSet> changes;
    render::RenderOptions options;
    quint64 generation = 0;
};

struct SessionSlot {
    std::unique_ptr<render::RenderSession> session;
    render::RenderOptions options;
    quint64 generation = 0; // the job whose scene the session holds; 0: none
    std::optional<SessionUpdate> update;

    // Queues `scene` of job `generation`: incremental (the job's change set, merged onto a queued
    // update it follows) when `changes` leads from the scene the slot will hold
    // (`baseGeneration`), `incremental` allows it and the options match; else a whole swap.
    void queue(std::shared_ptr<const scene::Scene> scene, const render::RenderOptions& options,
               quint64 generation, const std::optional<scene::ChangeSet>& changes, quint64 baseGeneration,
               bool incremental);
    // Applies the queued update (creating the session when there is none or the options
    // changed). Errors are the session's (a bad scene, no device).
    util::Status sync(const render::InterruptCheck& interrupt);
    bool current(quint64 jobGeneration) const { return session && !update && generation == jobGeneration; }
    void reset();
};

} // namespace wavelit::editor
