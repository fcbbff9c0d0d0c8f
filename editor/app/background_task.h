// runInBackground: runs `work` on a pool thread and hands its result to `done` on the UI thread
// (architecture.md §9: the UI thread never waits on disk). `context` owns the watcher; if it is
// destroyed first, `done` is never called.
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>

#include <utility>

namespace wavelit::editor {

template <typename Work, typename Done> void runInBackground(QObject* context, Work work, Done done) {
    using T = decltype(work());
    auto* watcher = new QFutureWatcher<T>(context);
    QObject::connect(watcher, &QFutureWatcherBase::finished, context, [watcher, done = std::move(done)] {
        watcher->deleteLater();
        done(watcher->result());
    });
    watcher->setFuture(QtConcurrent::run(std::move(work)));
}

} // namespace wavelit::editor
