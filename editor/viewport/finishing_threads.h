// Threads a RenderController or a LightMix side render let go while they finished a step no
// interrupt reaches: a render session's creation (lavapipe's pipeline compile and the sampler
// tables: 2-7 s for `wavelet` on 2 cores) or a relighting preview's build. Their cancel flag is set, so they stop at the end
// of that step; the UI thread does not wait for them (closing a window right after opening a
// scene used to freeze the editor for those seconds). Each is deleted once it has finished, on
// the UI thread, or, at the latest, when the application object goes (a post routine joins what
// is left), so no QThread is destroyed while it runs and no Vulkan device outlives the process.
#pragma once

#include <QDeadlineTimer>
#include <QThread>

#include <memory>

namespace wavelit::editor {

// How long an owner waits for its threads before it lets them finish on their own.
inline constexpr int kJoinMs = 200;

// Waits until `deadline` for `thread` (already told to quit) to finish; if it has not, keeps it
// until it does. Call on the UI thread, with a QCoreApplication.
void joinOrLetFinish(std::unique_ptr<QThread> thread, QDeadlineTimer deadline);

// Joins and deletes every thread still finishing (the application's exit runs it too).
void joinFinishingThreads();

// How many let-go threads have not been deleted yet.
int finishingThreadCount();

} // namespace wavelit::editor
