#include "render/gpu/gpu_path_tracer.h"

#include "render/gpu/brdf_shader_source.h"

#include "render/gpu/gpu_sampler_data.h"
#include "render/gpu/gpu_scene_data.h"
#include "render/session/integrator_factory.h"
#include "render/gpu/render_limits.h"
#include "util/log.h"
#include "util/timer.h"
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <numeric>
#include <utility>
#include <vector>

#ifndef WAVELIT_SHADER_DIR
#define WAVELIT_SHADER_DIR "shaders"
#endif
#ifndef WAVELIT_PLUGIN_DIR
#define WAVELIT_PLUGIN_DIR "plugins"
#endif

namespace wavelit::render {
namespace {

// Workgroup shape, passed to path_tracer.comp as defines.
constexpr uint32_t kWorkgroupX = 8;
constexpr uint32_t kWorkgroupY = 8;

// Binding order of path_tracer.comp.
enum Binding : uint32_t {
    kParams,
    kNodes,
    kTriangles,
    kMaterials,
    kEnvironment,
    kAccumulation,
    kLights,
    // With WAVELIT_DIRECTION_SAMPLERS only (gpu_sampler_data.h):
    kEnvTable,
    kSamplerMaterials,
    kSamplerWords
};

struct PassPush {
    uint32_t seedLo, seedHi;
};

std::string envOr(const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return v && *v ? v : fallback;
}

// The buffers of a scene in upload order (bindings kParams..kLights, then with samplers
// kEnvTable, kSamplerMaterials, kSamplerWords), sized as uploadScene creates them, each with what
// the user can change to make it smaller (render_limits.h).
std::vector<GpuBufferPlan> sceneBufferPlans(const GpuSceneData& d, const scene::Bvh& bvh,
                                            const GpuSamplerData* samplers) {
    const std::string meshes =
        "the scene's meshes (" + std::to_string(bvh.triangles.size()) + " triangles)";
    const std::string fewerTriangles = "use fewer triangles (simpler or fewer meshes)";
    const std::string envSize =
        std::to_string(d.params.envSize[0]) + "x" + std::to_string(d.params.envSize[1]);
    const std::string env = "the environment map (" + envSize + ")";
    const std::string smallerEnv = "use a smaller environment map";
    std::vector<GpuBufferPlan> plans = {
        {"params", sizeof(d.params), 0, "", "the scene parameters", ""},
        {"bvh nodes", bvh.nodes.size() * sizeof(scene::BvhNode), bvh.nodes.size(), "BVH nodes",
         meshes, fewerTriangles},
        {"bvh triangles", bvh.triangles.size() * sizeof(scene::BvhTriangle), bvh.triangles.size(),
         "triangles", meshes, fewerTriangles},
        {"materials", d.materials.size() * sizeof(GpuMaterial), d.materials.size(), "materials",
         "the scene's materials", "use fewer materials"},
        {"environment", d.envTexels.size() * sizeof(float), d.envTexels.size() / 3, "texels", env,
         smallerEnv},
        {"lights", d.lights.size() * sizeof(GpuLight), d.lights.size(), "lights",
         "the scene's analytic lights", "use fewer lights"},
    };
    if (samplers) {
        plans.push_back({"env sampling table",
                         samplers->envNodes.size() * sizeof(samplers->envNodes[0]),
                         samplers->envNodes.size(), "nodes",
                         "the sampling table of the environment map (" + envSize + ")", smallerEnv});
        plans.push_back({"sampler materials",
                         samplers->materials.size() * sizeof(GpuSamplerMaterial),
                         samplers->materials.size(), "materials", "the scene's materials",
                         "use fewer materials"});
        plans.push_back({"sampler tables", samplers->words.size() * sizeof(uint32_t),
                         samplers->words.size(), "words", "the materials' sampling tables",
                         "use a smaller environment map or fewer materials, or the bsdf sampler"});
    }
    return plans;
}

class GpuPathTracer final : public Integrator {
public:
    static util::Result<std::unique_ptr<Integrator>>
    create(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
           const RenderOptions& options);
    util::Status renderPass() override;
    int samplesPerPixel() const override { return m_passes; }
    util::Result<util::ImageRGB> image() override;
    void resetAccumulation() override;
    std::string deviceName() const override { return "vulkan: " + m_context->deviceName(); }
    IntegratorTimings timings() const override { return m_timings; }
    std::shared_ptr<const DirectionSamplerTables> samplerTables() const override {
        return m_samplerTables.tables;
    }
    SamplerTablesRebuilds samplerRebuilds() const override { return m_tablesCache.rebuilds(); }
    int validationMessageCount() const override { return m_context->validationMessageCount(); }
    void setInterruptCheck(InterruptCheck check) override { m_interrupt = std::move(check); }
    util::Status setScene(std::shared_ptr<const scene::Scene> scene,
                          std::shared_ptr<const scene::Bvh> bvh) override;

private:
    GpuPathTracer() = default;
    util::Result<vk::Buffer> upload(const void* data, size_t bytes, VkBufferUsageFlags usage,
                                    const std::string& name);
    // Packs and uploads scene + BVH into fresh buffers, then swaps them in and rebinds: on error
    // the previous scene stays intact. No dispatch is in flight (renderPass waits).
    util::Status uploadScene(const scene::Scene& scene, const scene::Bvh& bvh);
    bool usesDirectionSamplers() const { return m_options.sampler != SamplerKind::Bsdf; }
    // Checks the accumulation buffer and `buffers` against the device's limits before any of
    // them is allocated (render_limits.h).
    util::Status checkPlan(std::vector<GpuBufferPlan> buffers) const;
    // A pass is cut into tiles of kTileGroups x kTileGroups workgroups (16 x 16 pixels), taken
    // in a scattered order (tile i of the order is i * stride mod count) so that every piece
    // samples the whole image: a piece's cost then follows its tile count, whereas runs in
    // row order went from cheap sky rows to the costly ring and took 0.7 s instead of 40 ms.
    struct PassTiles {
        uint32_t groupsX = 0, groupsY = 0, tilesX = 0, count = 0, stride = 1;
    };
    static constexpr uint32_t kTileGroups = 2;
    PassTiles passTiles() const;
    // Submits tiles [first, first + count) of the order (one dispatch each) and waits.
    util::Status dispatchPiece(const PassTiles& tiles, uint32_t first, uint32_t count,
                               const PassPush& push);

    std::shared_ptr<const scene::Scene> m_scene;
    std::shared_ptr<const scene::Bvh> m_bvh;
    RenderOptions m_options;
    // The context is declared first so it is destroyed last; the runner last so its destructor
    // (which waits for the last submit) runs before any buffer goes away.
    std::unique_ptr<vk::Context> m_context;
    vk::Buffer m_params, m_nodes, m_triangles, m_materials, m_environment, m_accumulation,
        m_lights, m_envTable, m_samplerMaterials, m_samplerWords;
    // Direction-sampler tables, rebuilt per change set only where invalidated.
    SamplerTablesCache m_tablesCache;
    SceneSamplerTables m_samplerTables;
    // What the uploaded sampler buffers need in the params block (GpuParams::samplerInfo/Env).
    uint32_t m_samplerInfo[4] = {0, 0, 0, 0};
    float m_samplerEnvMean = 0.0f;
    vk::ComputeKernel m_kernel;
    std::unique_ptr<vk::CommandRunner> m_runner;
    IntegratorTimings m_timings;
    int m_passes = 0;
    // The pass in progress: the next tile (in PassTiles order) to dispatch; 0 between passes.
    uint32_t m_nextTile = 0;
    double m_passElapsed = 0.0;    // seconds spent on the unfinished pass so far
    double m_secondsPerTile = 0.0; // measured, smoothed over pieces; 0 = unknown yet
    uint32_t m_lastPieceTiles = 0;
    InterruptCheck m_interrupt;
};

util::Result<vk::Buffer> GpuPathTracer::upload(const void* data, size_t bytes,
                                               VkBufferUsageFlags usage, const std::string& name) {
    if (usage == VK_BUFFER_USAGE_STORAGE_BUFFER_BIT &&
        bytes > m_context->limits().maxStorageBufferRange)
        return util::makeError(util::ErrorKind::Unsupported, "",
                               name + " needs " + std::to_string(bytes) +
                                   " bytes, more than the device's storage-buffer range of " +
                                   std::to_string(m_context->limits().maxStorageBufferRange));
    auto buffer = vk::Buffer::create(*m_context, bytes, usage, name);
    if (!buffer)
        return buffer.error();
    if (data && bytes)
        buffer->write(data, bytes);
    return buffer;
}

util::Status GpuPathTracer::checkPlan(std::vector<GpuBufferPlan> buffers) const {
    GpuMemoryPlan plan;
    plan.width = m_options.width;
    plan.height = m_options.height;
    plan.workgroupWidth = kWorkgroupX;
    plan.workgroupHeight = kWorkgroupY;
    plan.buffers.push_back(gpuAccumulationPlan(m_options.width, m_options.height));
    for (auto& b : buffers)
        plan.buffers.push_back(std::move(b));
    return checkGpuMemoryPlan(plan, gpuDeviceLimits(*m_context));
}

util::Result<std::unique_ptr<Integrator>>
GpuPathTracer::create(std::shared_ptr<const scene::Scene> scene,
                      std::shared_ptr<const scene::Bvh> bvh, const RenderOptions& options) {
    std::unique_ptr<GpuPathTracer> pt(new GpuPathTracer());
    pt->m_scene = std::move(scene);
    pt->m_bvh = std::move(bvh);
    pt->m_options = options;
    pt->m_timings.bvhBuildSeconds = pt->m_bvh->buildSeconds;

    // Fail on an unsupported material before any device work.
    auto packed = packGpuScene(*pt->m_scene, *pt->m_bvh, options);
    if (!packed)
        return packed.error();

    util::Timer timer;
    auto ctx = vk::Context::create({options.vulkanDevice, options.validation});
    if (!ctx)
        return ctx.error();
    pt->m_context = std::move(ctx.value());
    if (pt->usesDirectionSamplers() && !pt->m_context->hasFloat64())
        return util::makeError(util::ErrorKind::Unsupported, "",
                               pt->m_context->deviceName() + ": sampler '" +
                                   samplerKindName(options.sampler) +
                                   "' needs shaderFloat64 (double-precision sampling descents)");
    // Instance + device creation is reported apart from the pipeline (it is not shader work).
    util::logInfo("vulkan device: " + pt->m_context->deviceName() + " (created in " +
                  std::to_string(int(timer.milliseconds())) + " ms)");
    timer.restart();

    // Limits first: a render size or a scene the device cannot hold is refused before the
    // pipeline is compiled and before anything is allocated (the sampler tables, built later,
    // are checked in uploadScene, again before any allocation).
    if (auto fits = pt->checkPlan(sceneBufferPlans(*packed, *pt->m_bvh, nullptr)); !fits)
        return fits.error();

    // Pipeline next: a shader error is the likeliest failure and should not wait for uploads.
    vk::ShaderCompileOptions compile{{gpuShaderDirectory(), gpuPluginDirectory()},
                                     {"WAVELIT_WORKGROUP_X=" + std::to_string(kWorkgroupX),
                                      "WAVELIT_WORKGROUP_Y=" + std::to_string(kWorkgroupY)}};
    // `bsdf` compiles without the samplers: no private product pyramid, no doubles.
    if (pt->usesDirectionSamplers())
        compile.defines.push_back("WAVELIT_DIRECTION_SAMPLERS=1");
    // Only the oracle needs the larger private pyramid (2^5 leaves instead of 2^4).
    if (options.sampler == SamplerKind::Oracle)
        compile.defines.push_back("WAVELIT_ORACLE_SAMPLER=1");
    std::string shaderPath =
        (std::filesystem::path(gpuShaderDirectory()) / "path_tracer.comp").string();
    auto spirv = compileFileWithBrdfDispatch(shaderPath, compile);
    if (!spirv)
        return spirv.error();
    using vk::BindingKind;
    std::vector<BindingKind> bindings(pt->usesDirectionSamplers() ? 10 : 7,
                                      BindingKind::StorageBuffer);
    // A storage buffer, not a uniform buffer: lavapipe re-compiles per bind otherwise (header).
    bindings[kParams] = BindingKind::StorageBuffer;
    auto kernel = vk::ComputeKernel::create(
        *pt->m_context, {"path_tracer", std::move(spirv.value()), bindings, sizeof(PassPush)});
    if (!kernel)
        return kernel.error();
    pt->m_kernel = std::move(kernel.value());
    pt->m_timings.pipelineSeconds = timer.seconds();

    timer.restart();
    // The scene first: uploadScene checks the whole plan (accumulation included) before it
    // allocates anything.
    auto uploaded = pt->uploadScene(*pt->m_scene, *pt->m_bvh);
    if (!uploaded)
        return uploaded.error();
    const GpuBufferPlan accumulationPlan = gpuAccumulationPlan(options.width, options.height);
    auto accumulation = pt->upload(nullptr, accumulationPlan.bytes,
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, accumulationPlan.name);
    if (!accumulation)
        return accumulation.error();
    pt->m_accumulation = std::move(accumulation.value());
    pt->m_kernel.bind(kAccumulation, pt->m_accumulation);
    pt->m_accumulation.fill(0);
    auto runner = vk::CommandRunner::create(*pt->m_context, "path tracer");
    if (!runner)
        return runner.error();
    pt->m_runner = std::move(runner.value());
    pt->m_timings.uploadSeconds = timer.seconds();
    return std::unique_ptr<Integrator>(std::move(pt));
}

util::Status GpuPathTracer::uploadScene(const scene::Scene& scene, const scene::Bvh& bvh) {
    auto packed = packGpuScene(scene, bvh, m_options);
    if (!packed)
        return packed.error();
    GpuSceneData& d = *packed;
    GpuSamplerData samplers;
    SceneSamplerTables samplerTables;
    bool uploadSamplers = false;
    uint32_t samplerInfo[4] = {m_samplerInfo[0], m_samplerInfo[1], m_samplerInfo[2], m_samplerInfo[3]};
    float samplerEnvMean = m_samplerEnvMean;
    if (usesDirectionSamplers()) {
        auto tables = m_tablesCache.update(scene, m_options.sampler);
        if (!tables)
            return tables.error();
        samplerTables = std::move(tables.value());
        // The cache hands back the same tables when an edit invalidated none of them (an object
        // move, a light edit): the sampler buffers on the device are then still right, and
        // re-packing them (the env table alone is ~22 MiB at 1024^2) would stall every drag.
        uploadSamplers = samplerTables.tables != m_samplerTables.tables ||
                         samplerTables.samplerIndexOfMaterial != m_samplerTables.samplerIndexOfMaterial;
        if (uploadSamplers) {
            auto packedSamplers =
                packGpuSamplers(samplerTables, m_options.sampler, d.materials.size());
            if (!packedSamplers)
                return packedSamplers.error();
            samplers = std::move(packedSamplers.value());
            samplerInfo[0] = samplers.kind;
            samplerInfo[1] = samplers.lit ? 1u : 0u;
            samplerInfo[2] = samplers.tailOffset;
            samplerInfo[3] = samplers.envLevel;
            samplerEnvMean = samplers.envMean;
        }
        std::copy(std::begin(samplerInfo), std::end(samplerInfo), d.params.samplerInfo);
        d.params.samplerEnv[0] = samplerEnvMean;
    }
    // The whole plan (the sizes of `uploads` below) is checked before any buffer is created
    // (render_limits.h). Sampler buffers that stay as they are count toward the total only.
    {
        std::vector<GpuBufferPlan> plans =
            sceneBufferPlans(d, bvh, uploadSamplers ? &samplers : nullptr);
        if (usesDirectionSamplers() && !uploadSamplers)
            for (const vk::Buffer* kept : {&m_envTable, &m_samplerMaterials, &m_samplerWords})
                plans.push_back({"kept sampler buffer", kept->size(), 0, "", "", ""});
        if (auto fits = checkPlan(std::move(plans)); !fits)
            return fits.error();
    }
    constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    struct Upload {
        uint32_t binding;
        vk::Buffer* target;
        const void* data;
        size_t bytes;
        VkBufferUsageFlags usage;
        const char* name;
    } uploads[] = {
        {kParams, &m_params, &d.params, sizeof(d.params), kStorage,
         "params"},
        {kNodes, &m_nodes, bvh.nodes.data(), bvh.nodes.size() * sizeof(scene::BvhNode), kStorage,
         "bvh nodes"},
        {kTriangles, &m_triangles, bvh.triangles.data(),
         bvh.triangles.size() * sizeof(scene::BvhTriangle), kStorage, "bvh triangles"},
        {kMaterials, &m_materials, d.materials.data(), d.materials.size() * sizeof(GpuMaterial),
         kStorage, "materials"},
        {kEnvironment, &m_environment, d.envTexels.data(), d.envTexels.size() * sizeof(float),
         kStorage, "environment"},
        {kLights, &m_lights, d.lights.data(), d.lights.size() * sizeof(GpuLight), kStorage,
         "lights"},
        {kEnvTable, &m_envTable, samplers.envNodes.data(),
         samplers.envNodes.size() * sizeof(samplers.envNodes[0]), kStorage, "env sampling table"},
        {kSamplerMaterials, &m_samplerMaterials, samplers.materials.data(),
         samplers.materials.size() * sizeof(GpuSamplerMaterial), kStorage, "sampler materials"},
        {kSamplerWords, &m_samplerWords, samplers.words.data(),
         samplers.words.size() * sizeof(uint32_t), kStorage, "sampler tables"},
    };
    // The first six are the scene's; the last three exist only with direction samplers, and are
    // re-sent only when their tables changed.
    // A buffer of the same size is written in place (most edits keep every size): creating and
    // freeing ~2 MB of buffers per edit cost a Vulkan allocation each and ~45 KB of validation-
    // layer bookkeeping per edit that was never given back. New buffers are all created before
    // any is written, so a failed creation still leaves the previous scene intact.
    const size_t uploadCount = uploadSamplers ? std::size(uploads) : 6;
    constexpr size_t kMinimumBufferBytes = 16; // vk::Buffer::create's rounding
    std::vector<std::pair<size_t, vk::Buffer>> fresh;
    for (size_t i = 0; i < uploadCount; ++i) {
        const Upload& u = uploads[i];
        if (u.target->handle() != VK_NULL_HANDLE &&
            u.target->size() == std::max(u.bytes, kMinimumBufferBytes))
            continue;
        auto buffer = upload(nullptr, u.bytes, u.usage, u.name);
        if (!buffer)
            return buffer.error();
        fresh.emplace_back(i, std::move(buffer.value()));
    }
    for (auto& [i, buffer] : fresh) {
        *uploads[i].target = std::move(buffer);
        m_kernel.bind(uploads[i].binding, *uploads[i].target);
    }
    for (size_t i = 0; i < uploadCount; ++i)
        if (uploads[i].data && uploads[i].bytes)
            uploads[i].target->write(uploads[i].data, uploads[i].bytes);
    m_samplerTables = std::move(samplerTables);
    std::copy(std::begin(samplerInfo), std::end(samplerInfo), m_samplerInfo);
    m_samplerEnvMean = samplerEnvMean;
    return util::okStatus();
}

util::Status GpuPathTracer::setScene(std::shared_ptr<const scene::Scene> scene,
                                     std::shared_ptr<const scene::Bvh> bvh) {
    util::Timer timer;
    auto status = uploadScene(*scene, *bvh);
    if (!status)
        return status;
    m_scene = std::move(scene);
    m_bvh = std::move(bvh);
    m_timings.bvhBuildSeconds = m_bvh->buildSeconds;
    m_timings.uploadSeconds = timer.seconds();
    resetAccumulation();
    return util::okStatus();
}

util::Status GpuPathTracer::renderPass() {
    const uint64_t seed = gpuPassSeed(m_options.seed, m_passes);
    const PassPush push{uint32_t(seed), uint32_t(seed >> 32)};
    const PassTiles tiles = passTiles();
    // Until a piece has been timed, a small first piece: 4 tiles (1024 pixels) take ~45 ms with
    // `wavelet` on lavapipe under load (a 1600x1000 pass took 71 s), the slowest sampler but the
    // oracle. Pieces at most double from one to the next.
    constexpr uint32_t kFirstPieceTiles = 4;
    while (m_nextTile < tiles.count) {
        if (m_interrupt && m_interrupt())
            return util::okStatus(); // unfinished: the next call resumes at m_nextTile
        uint32_t count = kFirstPieceTiles;
        if (m_secondsPerTile > 0.0)
            count = uint32_t(std::clamp(kGpuPassPieceSeconds / m_secondsPerTile, 1.0,
                                        2.0 * double(std::max(m_lastPieceTiles, kFirstPieceTiles))));
        count = std::min(count, tiles.count - m_nextTile);
        util::Timer timer;
        if (auto status = dispatchPiece(tiles, m_nextTile, count, push); !status)
            return describePassError(status.error(), m_context->deviceName());
        const double seconds = timer.seconds();
        const double perTile = seconds / double(count);
        m_secondsPerTile = m_secondsPerTile > 0.0 ? 0.5 * (m_secondsPerTile + perTile) : perTile;
        m_lastPieceTiles = count;
        m_passElapsed += seconds;
        m_nextTile += count;
    }
    m_nextTile = 0;
    ++m_passes;
    m_timings.passSeconds += m_passElapsed;
    m_passElapsed = 0.0;
    return util::okStatus();
}

GpuPathTracer::PassTiles GpuPathTracer::passTiles() const {
    PassTiles t;
    t.groupsX = (uint32_t(m_options.width) + kWorkgroupX - 1) / kWorkgroupX;
    t.groupsY = (uint32_t(m_options.height) + kWorkgroupY - 1) / kWorkgroupY;
    t.tilesX = (t.groupsX + kTileGroups - 1) / kTileGroups;
    t.count = t.tilesX * ((t.groupsY + kTileGroups - 1) / kTileGroups);
    // A stride near count / golden ratio that is coprime with count visits every tile once.
    t.stride = std::max<uint32_t>(1, uint32_t(double(t.count) * 0.6180339887));
    while (std::gcd(t.stride, t.count) != 1)
        ++t.stride;
    return t;
}

util::Status GpuPathTracer::dispatchPiece(const PassTiles& tiles, uint32_t first, uint32_t count,
                                          const PassPush& push) {
    std::vector<vk::DispatchRegion> regions;
    regions.reserve(count);
    for (uint32_t i = first; i < first + count; ++i) {
        const uint32_t tile = uint32_t((uint64_t(i) * tiles.stride) % tiles.count);
        const uint32_t x = (tile % tiles.tilesX) * kTileGroups;
        const uint32_t y = (tile / tiles.tilesX) * kTileGroups;
        regions.push_back({x, y, std::min(kTileGroups, tiles.groupsX - x),
                           std::min(kTileGroups, tiles.groupsY - y)});
    }
    return m_runner->run([&](VkCommandBuffer cmd) {
        m_kernel.dispatchRegions(cmd, regions, &push);
        vk::computeToComputeAndHostBarrier(cmd);
    });
}

util::Result<util::ImageRGB> GpuPathTracer::image() {
    util::ImageRGB img(m_options.width, m_options.height);
    if (m_passes == 0)
        return img;
    std::vector<float> sums(img.pixels.size() * 4);
    m_accumulation.read(sums.data(), sums.size() * sizeof(float));
    float inv = 1.0f / float(m_passes);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = glm::vec3(sums[4 * i], sums[4 * i + 1], sums[4 * i + 2]) * inv;
    return img;
}

void GpuPathTracer::resetAccumulation() {
    // renderPass waits for its fence, so no dispatch is in flight here.
    m_accumulation.fill(0);
    m_passes = 0;
    m_nextTile = 0; // an unfinished pass is dropped with the sums it had added
    m_passElapsed = 0.0;
    m_timings.passSeconds = 0.0;
}

} // namespace

std::string gpuShaderDirectory() {
    return envOr("WAVELIT_SHADER_DIR", WAVELIT_SHADER_DIR);
}
std::string gpuPluginDirectory() {
    return envOr("WAVELIT_PLUGIN_DIR", WAVELIT_PLUGIN_DIR);
}

util::Result<std::unique_ptr<Integrator>>
createGpuPathTracer(std::shared_ptr<const scene::Scene> scene,
                    std::shared_ptr<const scene::Bvh> bvh, const RenderOptions& options) {
    return GpuPathTracer::create(std::move(scene), std::move(bvh), options);
}

} // namespace wavelit::render
