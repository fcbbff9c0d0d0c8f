// The Vulkan path tracer's class, shared by its three source files: gpu_path_tracer.cpp (creation:
// device, limits, shader compile, pipeline), gpu_path_tracer_upload.cpp (packing and uploading the
// scene, setScene/applyChanges: only what a change set invalidates) and gpu_path_tracer_pass.cpp
// (passes in pieces, read-back). Internal to render/gpu: include gpu_path_tracer.h or
// integrator_factory.h instead.
#pragma once

#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_sampler_data.h"
#include "render/gpu/gpu_scene_data.h"
#include "render/gpu/render_limits.h"
#include "render/session/integrator.h"
#include "render/session/light_groups.h"
#include "render/session/render_options.h"
#include "render/sampling/sampler_tables_cache.h"
#include "scene/bvh.h"
#include "scene/change_set.h"
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wavelit::render::gpu_tracer {

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

// The buffers path_tracer.comp also reads as texels where the driver compiles it so (CPU
// devices: gpu_path_tracer.cpp create), in the order of their bindings after all others (its
// WAVELIT_SCENE_TEXELS_BINDING + i declarations); the sampler tables' two views only in kernels
// with direction samplers.
struct SceneTexelView {
    uint32_t buffer; // the storage binding of the same buffer
    VkFormat format;
};
inline constexpr SceneTexelView kSceneTexelViews[] = {
    {kNodes, VK_FORMAT_R32G32B32A32_UINT},     {kTriangles, VK_FORMAT_R32G32B32A32_UINT},
    {kMaterials, VK_FORMAT_R32G32B32A32_UINT}, {kLights, VK_FORMAT_R32G32B32A32_UINT},
    {kEnvironment, VK_FORMAT_R32_SFLOAT},      {kSamplerWords, VK_FORMAT_R32_UINT},
    {kSamplerWords, VK_FORMAT_R32G32_UINT}};
inline constexpr uint32_t kSceneTexelViewsWithoutSamplers = 5;

// LightMix (shaders/common/light_groups.glsl): with RenderOptions::lightGroups two more bindings
// follow the last of the list above (7 and 8 for `bsdf`, 10 and 11 with samplers): the group info
// (this packing) and the layers. kNoLightGroup: no emissive material.
inline constexpr uint32_t kNoLightGroup = 0xFFFFFFFFu;
// The measured BRDF tables (gpu_brdf_tables.h, plugins/measured.glsl) take the binding after
// all of these (after the light groups' when they are on).
std::vector<uint32_t> packGpuLightGroups(const LightGroups& groups, uint64_t pixels);

// path_tracer.comp's push constant: what its PathSampler needs besides the pixel.
struct PassPush {
    uint32_t seedKey; // util::PathSampler::seedKey(options.seed)
    uint32_t pass;
};

// The buffers of a scene in upload order, sized as uploadScene creates them (render_limits.h).
std::vector<GpuBufferPlan> sceneBufferPlans(const GpuSceneData& d, const scene::Bvh& bvh,
                                            const GpuSamplerData* samplers);

// The product cache's layout traces its centre rays in bands of whole rows of about this many
// pixels (~4 ms on 2 cores) and polls the interrupt check between bands.
inline constexpr int kProductCacheLayoutBandPixels = 16384;

class GpuPathTracer final : public Integrator {
public:
    static util::Result<std::unique_ptr<Integrator>>
    create(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
           const RenderOptions& options);
    util::Status renderPass() override;
    int samplesPerPixel() const override { return m_passes; }
    util::Result<util::ImageRGB> image() override;
    util::Result<std::vector<util::ImageRGB>> groupImages() override;
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
    util::Status applyChanges(std::shared_ptr<const scene::Scene> scene,
                              std::shared_ptr<const scene::Bvh> bvh,
                              const scene::ChangeSet& changes) override;
    UpdateCounts lastUpdate() const override { return m_lastUpdate; }
    // How often the per-pixel product cache was laid out and built (tests: rebuilt after edits).
    uint64_t productCacheBuilds() const { return m_productCacheBuilds; }
    uint64_t productCacheBytes() const { return m_productCache.size(); }

private:
    GpuPathTracer() = default;
    // Which scene buffers an update re-sends (architecture.md §5.B "What an edit rebuilds"). The
    // params block is re-packed every time and sent when its bytes differ; the sampler buffers
    // when the cache hands back other tables.
    struct UploadMask {
        bool geometry = true, materials = true, envTexels = true, lights = true;
    };
    util::Result<vk::Buffer> upload(const void* data, size_t bytes, VkBufferUsageFlags usage,
                                    const std::string& name);
    // Packs and uploads scene + BVH (the parts `mask` names; `changed`: the change set's
    // invalidations, for the sampler tables cache) into the buffers, creating those whose size
    // changed first: on error the previous scene stays intact. Counts into m_lastUpdate. No
    // dispatch is in flight (renderPass waits).
    util::Status uploadScene(const scene::Scene& scene, const scene::Bvh& bvh,
                             const UploadMask& mask,
                             const std::vector<scene::Invalidation>* changed);
    bool usesDirectionSamplers() const { return m_options.sampler != SamplerKind::Bsdf; }
    // With light groups: (re)creates the info and layer buffers for `scene`'s groups (sizes
    // already checked by uploadScene) and writes the info; a new layer buffer starts at zero.
    util::Status uploadLightGroups(const scene::Scene& scene);
    // Writes the packed measured BRDF tables (GpuSceneData::brdfTables), creating the buffer
    // when its size changed (gpu_path_tracer_brdf_tables.cpp).
    util::Status uploadBrdfTables(const std::vector<float>& tables);
    // Checks the accumulation buffer and `buffers` against the device's limits before any of
    // them is allocated (render_limits.h).
    util::Status checkPlan(std::vector<GpuBufferPlan> buffers) const;
    // The per-pixel product cache (`wavelet` kernels with the product code; product_cache.h):
    // lays it out for the current scene and camera and uploads the layout, so that the next pass
    // builds the entries (gpu_path_tracer_cache.cpp). Called at a pass's first piece while the
    // cache is not ready; resetAccumulation (every scene or camera change) makes it not ready,
    // except after applyChanges of lights only (the entries do not depend on lights). False:
    // the interrupt check fired between two bands of the layout's centre rays; the next call
    // resumes there.
    util::Result<bool> prepareProductCache();
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
    std::optional<SceneSamplerTables> m_createTables; // built by create(), used by its upload
    // What the uploaded sampler buffers need in the params block (GpuParams::samplerInfo/Env).
    uint32_t m_samplerInfo[4] = {0, 0, 0, 0};
    float m_samplerEnvMean = 0.0f;
    float m_samplerEnvRoulette = 0.0f;
    // LightMix layers (RenderOptions::lightGroups only; gpu_path_tracer_groups.cpp).
    vk::Buffer m_groupInfo, m_groupLayers;
    uint32_t m_groupBinding = 0; // the info's binding; the layers' is the next
    // Measured BRDF tables: always bound (the dispatch reads them for `measured` materials).
    vk::Buffer m_brdfTables;
    uint32_t m_brdfTableBinding = 0;
    bool m_brdfTablesCompiled = false; // the kernel reads measured tables (create)
    bool m_productCompiled = false;    // the kernel carries the product code (create)
    // The per-pixel product cache: its binding (the last), whether the kernel has it, the packed
    // sampler materials it is laid out from, its state and figures for the report.
    vk::Buffer m_productCache;
    uint32_t m_productCacheBinding = 0;
    bool m_productCacheCompiled = false;
    // The first binding of kSceneTexelViews (after all others); 0 = the kernel reads no texels.
    uint32_t m_sceneTexelBinding = 0;
    uint32_t sceneTexelViewCount() const {
        return usesDirectionSamplers() ? uint32_t(std::size(kSceneTexelViews))
                                       : kSceneTexelViewsWithoutSamplers;
    }
    std::vector<GpuSamplerMaterial> m_packedSamplerMaterials;
    bool m_productCacheReady = false;  // entries built for the current scene and camera
    bool m_productCacheBuilding = false; // the pass in progress builds them
    // The layout's centre rays, traced a band of rows at a time between interrupt checks (at
    // 1600 x 1000 they take ~0.2 s on 2 cores, several times that under load): each pixel's
    // entry words so far and the rows done; reset with the accumulation.
    std::vector<uint32_t> m_productCacheEntryWords;
    int m_productCacheRowsTraced = 0;
    double m_productCacheLayoutSeconds = 0.0;
    uint64_t m_productCacheBuilds = 0;
    BrdfPluginSet m_brdfPluginsCompiled = 0; // the BRDF twins the kernel carries (create)
    size_t m_groupCount = 0;
    vk::ComputeKernel m_kernel;
    // The product cache's build kernel (path_tracer.comp with WAVELIT_BUILD_PRODUCT_CACHE), run
    // over each piece of the pass that builds the entries, before m_kernel; only with the cache.
    vk::ComputeKernel m_cacheKernel;
    // Points `binding` of every kernel at `buffer` (the kernels share the binding layout).
    void bindAll(uint32_t binding, const vk::Buffer& buffer);
    // Whether `bytes` at storage `binding` fit the device's texel views (checked before any
    // buffer is made), and the views of the buffer there in every kernel; both nothing when the
    // kernels read no texels.
    util::Status checkSceneTexels(uint32_t binding, size_t bytes, const std::string& name) const;
    util::Status bindSceneTexels(uint32_t binding, const vk::Buffer& buffer);
    std::unique_ptr<vk::CommandRunner> m_runner;
    IntegratorTimings m_timings;
    int m_passes = 0;
    // The pass in progress: the next tile (in PassTiles order) to dispatch; 0 between passes.
    uint32_t m_nextTile = 0;
    double m_passElapsed = 0.0;    // seconds spent on the unfinished pass so far
    double m_secondsPerTile = 0.0; // measured, smoothed over pieces; 0 = unknown yet
    uint32_t m_lastPieceTiles = 0;
    InterruptCheck m_interrupt;
    GpuParams m_uploadedParams{}; // what the params buffer holds (sent again only when changed)
    UpdateCounts m_lastUpdate;
};


} // namespace wavelit::render::gpu_tracer
