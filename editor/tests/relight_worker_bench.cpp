// Not a test: per-frame latency of the editor's relighting worker (relight_worker.h) on a drag,
// measured through its public API only (submit, frameReady, skipped), so the same file builds
// against older workers for before/after tables (docs/relighting.md §7.0d). No render thread
// runs, so the process's CPU time between a job's submission and the worker's answer is the
// worker's (its thread and the preview's parallelFor threads).
//   relight_worker_bench SCENE [SIZE = 512] [STEPS = 8] [OBJECT = the first]
// Drags the object round a circle of 0.3 m radius in the ground plane (5 cm per frame, so it
// stays in view however many steps), pauses, drags it on the same way STEPS / 2 frames more and
// pauses (a second drag of the same object), then steps the first glossy material's roughness
// (+0.05 per frame, at most 8 frames), pauses; prints one line per job: what came back (first answer / exact
// preview / skipped), wall ms, CPU ms; the resident memory the build added; and, after the run,
// the relative RMSE of every 4th drag frame's image against the exact preview of its scene
// (RelightPreview::create at the worker's settings: what the frame approximates).
#include "viewport/relight_worker.h"
#include "viewport/render_worker.h"

#include "relight/first_answer.h"
#include "scene/scene_io.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QThread>
#include <QTimer>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

double cpuMs() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return (double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3) + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

double rssMiB() {
    QFile file("/proc/self/status");
    if (!file.open(QIODevice::ReadOnly)) return -1.0;
    for (const QByteArray& line : file.readAll().split('\n'))
        if (line.startsWith("VmRSS:")) return line.mid(6).trimmed().split(' ').front().toDouble() / 1024.0;
    return -1.0;
}

bool spinUntil(const std::function<bool()>& done, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < timeoutMs) {
        QEventLoop loop;
        QTimer::singleShot(1, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return done();
}

struct Answer {
    quint64 generation = 0;
    bool skipped = false, first = false;
    QString what;
    std::shared_ptr<const util::ImageRGB> image;
};

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    qRegisterMetaType<RenderFrame>();
    if (argc < 2) {
        std::fprintf(stderr, "usage: relight_worker_bench SCENE [SIZE] [STEPS] [OBJECT]\n");
        return 2;
    }
    const std::string path = argv[1];
    const int size = argc > 2 ? std::atoi(argv[2]) : 512, steps = argc > 3 ? std::atoi(argv[3]) : 8;
    auto loaded = scene::loadScene(path);
    if (!loaded) return std::fprintf(stderr, "%s\n", loaded.error().message().c_str()), 1;
    scene::Scene scene = std::move(loaded).value();
    if (auto status = scene::loadAssets(scene, path); !status)
        return std::fprintf(stderr, "%s\n", status.error().message().c_str()), 1;

    auto shared = std::make_shared<RenderShared>();
    QThread thread;
    auto* worker = new RelightWorker(shared);
    worker->moveToThread(&thread);
    QObject::connect(&thread, &QThread::finished, worker, &QObject::deleteLater);
    Answer last;
    QObject::connect(worker, &RelightWorker::frameReady, &app, [&](const RenderFrame& f) {
        last = {f.generation, false, f.lastUpdate.contains("first answer"), f.lastUpdate, f.image};
    }, Qt::QueuedConnection);
    QObject::connect(worker, &RelightWorker::skipped, &app, [&](quint64 g) { last = {g, true, false, "skipped", {}}; },
                     Qt::QueuedConnection);
    thread.start();

    quint64 generation = 0;
    auto current = std::make_shared<const scene::Scene>(scene);
    auto submit = [&](std::optional<scene::ChangeSet> changes) {
        RenderJob job;
        job.scene = current;
        job.options.width = size;
        job.options.height = size;
        job.baseGeneration = generation;
        job.generation = ++generation;
        job.changes = std::move(changes);
        QMetaObject::invokeMethod(worker, [worker, job]() mutable { worker->submit(std::move(job)); },
                                  Qt::QueuedConnection);
    };
    auto edit = [&](scene::EntityRef ref, const char* property, scene::PropertyValue value) {
        scene::ChangeSet changes;
        if (!changes.setProperty(*current, ref, property, value)) std::abort();
        scene::Scene edited = *current;
        if (!changes.apply(edited)) std::abort();
        current = std::make_shared<const scene::Scene>(std::move(edited));
        submit(std::move(changes));
    };
    // One job, timed from its submission to the worker's answer about it.
    auto timed = [&](const char* label, int i, const std::function<void()>& send) {
        const double cpu0 = cpuMs();
        QElapsedTimer wall;
        wall.start();
        send();
        if (!spinUntil([&] { return last.generation == generation; }, 600000)) std::abort();
        std::printf("%-10s %2d  %-13s wall %8.1f ms  cpu %8.1f ms  | %s\n", label, i,
                    last.skipped ? "skipped" : last.first ? "first answer" : "exact", double(wall.nsecsElapsed()) * 1e-6,
                    cpuMs() - cpu0, qPrintable(last.what));
    };
    // After the last job: time until an exact frame of it (a pause), or 3 s without one.
    auto pause = [&](const char* label) {
        const double cpu0 = cpuMs();
        QElapsedTimer wall;
        wall.start();
        const bool exact = spinUntil([&] { return last.generation == generation && !last.skipped && !last.first; }, 30000);
        std::printf("%-10s     %-13s wall %8.1f ms  cpu %8.1f ms  | %s\n", label, exact ? "exact" : "none in 30 s",
                    double(wall.nsecsElapsed()) * 1e-6, cpuMs() - cpu0, qPrintable(last.what));
    };

    size_t dragged = 0;
    for (size_t i = 0; argc > 4 && i < scene.objects.size(); ++i)
        if (scene.objects[i].name == argv[4]) dragged = i;
    const scene::EntityRef object{scene::EntityKind::Object, scene.objects.at(dragged).id};
    scene::EntityRef material{scene::EntityKind::Material, scene.materials.at(0).id};
    for (const scene::Material& m : scene.materials)
        if (m.brdf != "lambert") { material.id = m.id; break; }
    std::printf("%s at %dx%d; object %s, material %s\n", path.c_str(), size, size, scene.objects.at(dragged).name.c_str(),
                scene.materials.at(size_t(std::find_if(scene.materials.begin(), scene.materials.end(),
                                                       [&](const scene::Material& m) { return m.id == material.id; }) -
                                          scene.materials.begin())).name.c_str());
    const double rss0 = rssMiB();
    submit(std::nullopt); // the scene opened
    timed("open", 0, [] {});
    const glm::vec3 t0 = scene.objects.at(dragged).transform.translation;
    timed("edit", 0, [&] { edit(object, "translation", t0 + glm::vec3(0.01f, 0.0f, 0.0f)); });
    pause("build");
    std::printf("resident memory: %.1f MiB before the build, %.1f MiB after (+%.1f)\n", rss0, rssMiB(), rssMiB() - rss0);
    // Round a circle through t0 + (0.01, 0, 0), 5 cm of arc a frame.
    auto onCircle = [&](int i) {
        const float angle = 0.05f * float(i) / 0.3f;
        return t0 + glm::vec3(0.01f + 0.3f * std::sin(angle), 0.0f, 0.3f * (1.0f - std::cos(angle)));
    };
    struct Kept {
        std::string label;
        std::shared_ptr<const scene::Scene> scene;
        std::shared_ptr<const util::ImageRGB> image;
        bool first;
    };
    std::vector<Kept> kept; // every 4th drag frame: its scene and what the worker showed
    auto drag = [&](const char* label, int from, int to) {
        for (int i = from; i <= to; ++i) {
            timed(label, i, [&] { edit(object, "translation", onCircle(i)); });
            if (i % 4 == 0 && last.image && last.generation == generation)
                kept.push_back({std::string(label) + " " + std::to_string(i), current, last.image, last.first});
        }
    };
    drag("drag", 1, steps);
    pause("pause");
    std::printf("resident memory after the drag: %.1f MiB\n", rssMiB());
    drag("drag2", steps + 1, steps + steps / 2);
    pause("pause");
    float roughness = 0.0f;
    for (const scene::Material& m : current->materials)
        if (m.id == material.id) roughness = m.roughness;
    for (int i = 1; i <= std::min(steps / 2, 8); ++i) // roughness stays within [0, 1]
        timed("roughness", i, [&] { edit(material, "roughness", roughness + 0.05f * float(i)); });
    pause("pause");
    shared->cancel.store(true);
    thread.quit();
    thread.wait();
    const relight::RelightSettings settings = RelightWorker::previewSettings(scene, size, size);
    for (const Kept& k : kept) {
        auto exact = relight::RelightPreview::create(*k.scene, settings);
        if (!exact) return 1;
        std::printf("%-9s %-13s relRMSE vs the exact preview %.4f\n", k.label.c_str(),
                    k.first ? "first answer" : "exact", relight::relativeRmse(*k.image, (*exact)->image(size, size)));
    }
    return 0;
}
