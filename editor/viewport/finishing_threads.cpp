#include "viewport/finishing_threads.h"

#include <QCoreApplication>

#include <algorithm>
#include <vector>

namespace wavelit::editor {
namespace {

// Touched on the UI thread only (joinOrLetFinish, the queued finished handler, the post
// routine), so no lock. Keyed by a serial number, not the QThread's address: a finished handler
// queued for a thread already forgotten must not find a newer thread at the same address.
struct Finishing {
    quint64 id;
    std::unique_ptr<QThread> thread;
};

std::vector<Finishing>& finishing() {
    static std::vector<Finishing> threads;
    return threads;
}

void forget(quint64 id) {
    auto& threads = finishing();
    auto it = std::find_if(threads.begin(), threads.end(),
                           [id](const Finishing& f) { return f.id == id; });
    if (it == threads.end()) return;
    it->thread->wait(); // `finished` comes just before the thread's end
    threads.erase(it);
}

} // namespace

void joinOrLetFinish(std::unique_ptr<QThread> thread, QDeadlineTimer deadline) {
    if (!thread || thread->wait(deadline)) return;
    static bool routineAdded = false;
    if (!routineAdded) {
        qAddPostRoutine(joinFinishingThreads);
        routineAdded = true;
    }
    static quint64 nextId = 0;
    const quint64 id = ++nextId;
    QThread* raw = thread.get();
    // Queued to the UI thread (the application object's): the QThread is deleted there.
    QObject::connect(raw, &QThread::finished, QCoreApplication::instance(), [id] { forget(id); },
                     Qt::QueuedConnection);
    finishing().push_back({id, std::move(thread)});
    if (raw->isFinished()) forget(id); // it ended before the connection was made
}

void joinFinishingThreads() {
    auto& threads = finishing();
    for (Finishing& f : threads) f.thread->wait();
    threads.clear();
}

int finishingThreadCount() { return int(finishing().size()); }

} // namespace wavelit::editor
