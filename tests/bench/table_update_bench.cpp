// What an environment edit costs the path tracer's sampler tables (SamplerTablesCache::update,
// `wavelet`, the default scene): a rotation (the env tables turned, product tables kept), an
// intensity change (every table kept: they are built at intensity 1) and a tint change (env and
// every product table rebuilt); and an edit's time to the next
// frame through a render session (applyChanges + one pass at 256^2, lavapipe and the C++ tracer).
// Run from the build tree:  tests/bench/table_update_bench
#include "render/sampling/sampler_tables_cache.h"
#include "render/session/render_session.h"
#include "scene/change_set.h"
#include "scene/scene_io.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

namespace {

using namespace wavelit;
using Value = scene::PropertyValue;

const std::string kScene = std::string(WAVELIT_RESOURCE_DIR) + "/scenes/ring_on_ground.wlscene";

// One env property edited by `step` per iteration through a warm cache, with its change set.
void envEdit(benchmark::State &state, const char *property, Value (*valueAt)(int)) {
    auto loaded = scene::loadScene(kScene);
    if (!loaded) {
        state.SkipWithError(loaded.error().message().c_str());
        return;
    }
    scene::Scene current = *loaded;
    render::SamplerTablesCache cache;
    if (!cache.update(current, render::SamplerKind::Wavelet).ok()) {
        state.SkipWithError("first build failed");
        return;
    }
    const scene::EntityRef env{scene::EntityKind::Environment, scene::kInvalidId};
    int i = 0;
    for (auto _ : state) {
        scene::ChangeSet changes;
        if (!changes.setProperty(current, env, property, valueAt(++i)).ok()) {
            state.SkipWithError("setProperty failed");
            return;
        }
        scene::Scene next = current;
        if (!changes.apply(next).ok()) {
            state.SkipWithError("apply failed");
            return;
        }
        const auto invalidations = changes.invalidations();
        auto tables = cache.update(next, render::SamplerKind::Wavelet, &invalidations);
        benchmark::DoNotOptimize(tables);
        current = std::move(next);
    }
    const render::SamplerTablesRebuilds &r = cache.rebuilds();
    state.counters["envBuilds"] = r.environmentBuilds;
    state.counters["envTurned"] = r.environmentRotations;
    state.counters["materialBuilds"] = r.materialBuilds;
}

void BM_EnvRotationEdit(benchmark::State &state) {
    envEdit(state, "rotation", [](int i) -> Value { return float(5 * i % 360); });
}
BENCHMARK(BM_EnvRotationEdit)->Unit(benchmark::kMillisecond)->Iterations(6);

void BM_EnvIntensityEdit(benchmark::State &state) {
    envEdit(state, "intensity", [](int i) -> Value { return 1.0f + 0.1f * float(i % 7); });
}
BENCHMARK(BM_EnvIntensityEdit)->Unit(benchmark::kMillisecond)->Iterations(6);

Value tintAt(int i) {
    return glm::vec3(1.0f, 0.9f - 0.05f * float(i % 5), 0.8f);
}

void BM_EnvTintEdit(benchmark::State &state) {
    envEdit(state, "tint", tintAt);
}
BENCHMARK(BM_EnvTintEdit)->Unit(benchmark::kMillisecond)->Iterations(6);

// applyChanges + renderPass: what the artist waits for after an edit, before the first new frame.
void sessionEdit(benchmark::State &state, const char *property, Value (*valueAt)(int),
                 scene::EntityRef ref = {scene::EntityKind::Environment, scene::kInvalidId}) {
    auto loaded = scene::loadScene(kScene);
    if (!loaded) {
        state.SkipWithError(loaded.error().message().c_str());
        return;
    }
    scene::Scene current = *loaded;
    render::RenderOptions options;
    options.width = options.height = 256;
    options.sampler = render::SamplerKind::Wavelet;
    options.device = state.range(0) == 0 ? render::DeviceChoice::Vulkan : render::DeviceChoice::Cpu;
    auto session = render::RenderSession::create(current, options);
    if (!session || !(*session)->renderPass().ok()) {
        state.SkipWithError("session failed");
        return;
    }
    int i = 0;
    for (auto _ : state) {
        scene::ChangeSet changes;
        scene::Scene next = current;
        if (!changes.setProperty(current, ref, property, valueAt(++i)).ok() ||
            !changes.apply(next).ok() || !(*session)->applyChanges(next, changes).ok() ||
            !(*session)->renderPass().ok()) {
            state.SkipWithError("edit failed");
            return;
        }
        current = std::move(next);
    }
    state.SetLabel(state.range(0) == 0 ? "vulkan" : "cpu");
}

void BM_SessionEnvRotation(benchmark::State &state) {
    sessionEdit(state, "rotation", [](int i) -> Value { return float(5 * i % 360); });
}
BENCHMARK(BM_SessionEnvRotation)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(4);

void BM_SessionEnvIntensity(benchmark::State &state) {
    sessionEdit(state, "intensity", [](int i) -> Value { return 1.0f + 0.1f * float(i % 7); });
}
BENCHMARK(BM_SessionEnvIntensity)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(4);

void BM_SessionEnvTint(benchmark::State &state) {
    sessionEdit(state, "tint", tintAt);
}
BENCHMARK(BM_SessionEnvTint)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(4);

// The default scene's gold (material 1) and softbox (light 1): the other edit kinds' time to
// the next frame, for comparison.
void BM_SessionGoldRoughness(benchmark::State &state) {
    sessionEdit(state, "roughness", [](int i) -> Value { return 0.1f + 0.02f * float(i % 5); },
                {scene::EntityKind::Material, 1});
}
BENCHMARK(BM_SessionGoldRoughness)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(4);

void BM_SessionLightIntensity(benchmark::State &state) {
    sessionEdit(state, "intensity", [](int i) -> Value { return 100.0f + 10.0f * float(i % 5); },
                {scene::EntityKind::Light, 1});
}
BENCHMARK(BM_SessionLightIntensity)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(4);

} // namespace

BENCHMARK_MAIN();
