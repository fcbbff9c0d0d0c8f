#include "render/gpu/gpu_path_tracer_impl.h"

#include "util/timer.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <utility>
#include <variant>
#include <vector>

namespace wavelit::render::gpu_tracer {

// Bindings kParams..kLights, then with samplers kEnvTable, kSamplerMaterials, kSamplerWords, each
// with what the user can change to make it smaller.
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

util::Result<vk::Buffer> GpuPathTracer::upload(const void* data, size_t bytes,
                                               VkBufferUsageFlags usage, const std::string& name) {
    if ((usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) &&
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

util::Status GpuPathTracer::uploadScene(const scene::Scene& scene, const scene::Bvh& bvh,
                                        const UploadMask& mask,
                                        const std::vector<scene::Invalidation>* changed) {
    // The texels are copied only when they are sent (~12 MiB at 1024x1024 on every drag before).
    auto packed = packGpuScene(scene, bvh, m_options, mask.envTexels);
    if (!packed)
        return packed.error();
    GpuSceneData& d = *packed;
    if (d.usesBrdfTables && !m_brdfTablesCompiled)
        return util::makeError(util::ErrorKind::Unsupported, "",
                               "the kernel was compiled without BRDF tables");
    if (d.brdfPlugins & ~m_brdfPluginsCompiled)
        return util::makeError(util::ErrorKind::Unsupported, "",
                               "the kernel was compiled without one of the scene's BRDFs");
    GpuSamplerData samplers;
    SceneSamplerTables samplerTables;
    bool uploadSamplers = false;
    uint32_t samplerInfo[4] = {m_samplerInfo[0], m_samplerInfo[1], m_samplerInfo[2], m_samplerInfo[3]};
    float samplerEnvMean = m_samplerEnvMean;
    float samplerEnvRoulette = m_samplerEnvRoulette;
    const SamplerTablesRebuilds rebuildsBefore = m_tablesCache.rebuilds();
    if (usesDirectionSamplers()) {
        if (m_createTables) {
            // create() built them (beside the compile, or first for `wavelet`, whose kernel
            // code depends on them): the same scene, one build.
            samplerTables = std::move(*m_createTables);
            m_createTables.reset();
        } else {
            auto tables = m_tablesCache.update(scene, m_options.sampler, changed);
            if (!tables)
                return tables.error();
            samplerTables = std::move(tables.value());
        }
        if (samplerTables.tables && samplerTables.tables->kind() == SamplerKind::Wavelet &&
            samplerTables.tables->anyProduct() && !m_productCompiled)
            return util::makeError(util::ErrorKind::Unsupported, "",
                                   "the kernel was compiled without the wavelet product code");
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
            samplerEnvRoulette = samplers.envRoulette;
        }
        std::copy(std::begin(samplerInfo), std::end(samplerInfo), d.params.samplerInfo);
        d.params.samplerEnv[0] = samplerEnvMean;
        d.params.samplerEnv[1] = samplerEnvRoulette;
    }
    constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    // Buffers the kernel also reads as texels where it is compiled so (kSceneTexelViews).
    const VkBufferUsageFlags kScene =
        m_sceneTexelBinding ? kStorage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : kStorage;
    struct Upload {
        uint32_t binding;
        vk::Buffer* target;
        const void* data;
        size_t bytes;
        VkBufferUsageFlags usage;
        const char* name;
        bool send;
    } uploads[] = {
        {kParams, &m_params, &d.params, sizeof(d.params), kStorage, "params",
         m_params.handle() == VK_NULL_HANDLE ||
             std::memcmp(&d.params, &m_uploadedParams, sizeof(d.params)) != 0},
        {kNodes, &m_nodes, bvh.nodes.data(), bvh.nodes.size() * sizeof(scene::BvhNode), kScene,
         "bvh nodes", mask.geometry},
        {kTriangles, &m_triangles, bvh.triangles.data(),
         bvh.triangles.size() * sizeof(scene::BvhTriangle), kScene, "bvh triangles", mask.geometry},
        {kMaterials, &m_materials, d.materials.data(), d.materials.size() * sizeof(GpuMaterial),
         kScene, "materials", mask.materials},
        {kEnvironment, &m_environment, d.envTexels.data(), d.envTexels.size() * sizeof(float),
         kScene, "environment", mask.envTexels},
        {kLights, &m_lights, d.lights.data(), d.lights.size() * sizeof(GpuLight), kScene,
         "lights", mask.lights},
        {kEnvTable, &m_envTable, samplers.envNodes.data(),
         samplers.envNodes.size() * sizeof(samplers.envNodes[0]), kStorage, "env sampling table",
         uploadSamplers},
        {kSamplerMaterials, &m_samplerMaterials, samplers.materials.data(),
         samplers.materials.size() * sizeof(GpuSamplerMaterial), kStorage, "sampler materials",
         uploadSamplers},
        {kSamplerWords, &m_samplerWords, samplers.words.data(),
         samplers.words.size() * sizeof(uint32_t), kScene, "sampler tables", uploadSamplers},
    };
    // The first six are the scene's; the last three exist only with direction samplers.
    const size_t uploadCount = usesDirectionSamplers() ? std::size(uploads) : 6;
    // The whole plan (the sizes of `uploads`) is checked before any buffer is created
    // (render_limits.h). Buffers that stay as they are count toward the total only.
    {
        std::vector<GpuBufferPlan> plans =
            sceneBufferPlans(d, bvh, uploadSamplers ? &samplers : nullptr);
        for (size_t i = 0; i < std::min(plans.size(), uploadCount); ++i)
            if (!uploads[i].send)
                plans[i] = {"kept buffer", uploads[i].target->size(), 0, "", "", ""};
        if (usesDirectionSamplers() && !uploadSamplers)
            for (const vk::Buffer* kept : {&m_envTable, &m_samplerMaterials, &m_samplerWords})
                plans.push_back({"kept sampler buffer", kept->size(), 0, "", "", ""});
        if (m_options.lightGroups)
            plans.push_back(gpuLightGroupPlan(lightGroupsOf(scene).size(), m_options.width,
                                              m_options.height));
        plans.push_back({"BRDF tables", d.brdfTables.size() * sizeof(float),
                         d.brdfTables.size(), "floats", "the scene's BRDF table files",
                         "use fewer or smaller BRDF table files"});
        if (auto fits = checkPlan(std::move(plans)); !fits)
            return fits.error();
    }
    for (size_t i = 0; i < uploadCount; ++i)
        if (uploads[i].send)
            if (auto fits = checkSceneTexels(uploads[i].binding, uploads[i].bytes, uploads[i].name);
                !fits)
                return fits;
    // A buffer of the same size is written in place (most edits keep every size): creating and
    // freeing ~2 MB of buffers per edit cost a Vulkan allocation each and ~45 KB of validation-
    // layer bookkeeping per edit that was never given back. New buffers are all created before
    // any is written, so a failed creation still leaves the previous scene intact.
    constexpr size_t kMinimumBufferBytes = 16; // vk::Buffer::create's rounding
    std::vector<std::pair<size_t, vk::Buffer>> fresh;
    for (size_t i = 0; i < uploadCount; ++i) {
        const Upload& u = uploads[i];
        if (!u.send || (u.target->handle() != VK_NULL_HANDLE &&
                        u.target->size() == std::max(u.bytes, kMinimumBufferBytes)))
            continue;
        auto buffer = upload(nullptr, u.bytes, u.usage, u.name);
        if (!buffer)
            return buffer.error();
        fresh.emplace_back(i, std::move(buffer.value()));
    }
    if (m_options.lightGroups)
        if (auto groups = uploadLightGroups(scene); !groups) return groups;
    if (m_brdfTablesCompiled && (mask.materials || m_brdfTables.handle() == VK_NULL_HANDLE))
        if (auto tables = uploadBrdfTables(d.brdfTables); !tables) return tables;
    for (auto& [i, buffer] : fresh) {
        *uploads[i].target = std::move(buffer);
        bindAll(uploads[i].binding, *uploads[i].target);
        if (auto bound = bindSceneTexels(uploads[i].binding, *uploads[i].target); !bound)
            return bound;
    }
    for (size_t i = 0; i < uploadCount; ++i)
        if (uploads[i].send && uploads[i].data && uploads[i].bytes)
            uploads[i].target->write(uploads[i].data, uploads[i].bytes);
    m_uploadedParams = d.params;
    m_samplerTables = std::move(samplerTables);
    if (uploadSamplers)
        m_packedSamplerMaterials = samplers.materials;
    std::copy(std::begin(samplerInfo), std::end(samplerInfo), m_samplerInfo);
    m_samplerEnvMean = samplerEnvMean;
    m_samplerEnvRoulette = samplerEnvRoulette;

    UpdateCounts& c = m_lastUpdate;
    c = UpdateCounts{};
    c.paramUploads = uploads[0].send ? 1 : 0;
    c.geometryUploads = mask.geometry ? 1 : 0;
    c.materialUploads = mask.materials ? 1 : 0;
    c.envTexelUploads = mask.envTexels ? 1 : 0;
    c.lightUploads = mask.lights ? 1 : 0;
    c.samplerTableUploads = uploadSamplers ? 1 : 0;
    const SamplerTablesRebuilds& after = m_tablesCache.rebuilds();
    c.samplerTableBuilds = (after.environmentBuilds - rebuildsBefore.environmentBuilds) +
                           (after.materialBuilds - rebuildsBefore.materialBuilds);
    c.samplerTablesTurned = after.environmentRotations - rebuildsBefore.environmentRotations;
    return util::okStatus();
}

util::Status GpuPathTracer::setScene(std::shared_ptr<const scene::Scene> scene,
                                     std::shared_ptr<const scene::Bvh> bvh) {
    util::Timer timer;
    auto status = uploadScene(*scene, *bvh, UploadMask{}, nullptr);
    if (!status)
        return status;
    m_scene = std::move(scene);
    m_bvh = std::move(bvh);
    m_timings.bvhBuildSeconds = m_bvh->buildSeconds;
    m_timings.uploadSeconds = timer.seconds();
    resetAccumulation();
    return util::okStatus();
}

util::Status GpuPathTracer::applyChanges(std::shared_ptr<const scene::Scene> scene,
                                         std::shared_ptr<const scene::Bvh> bvh,
                                         const scene::ChangeSet& changes) {
    util::Timer timer;
    const std::vector<scene::Invalidation> changed = changes.invalidations();
    UploadMask mask;
    mask.geometry = bvh != m_bvh; // the session hands back the same BVH when no geometry changed
    mask.lights = mask.materials = mask.envTexels = false;
    for (const scene::Invalidation& inv : changed) {
        mask.lights |= inv.factor == scene::FactorKind::Light;
        mask.materials |= inv.factor == scene::FactorKind::MaterialBrdf;
    }
    // Rotation, intensity and tint are parameters; only a new map changes the texels.
    for (const scene::Edit& edit : changes.edits())
        if (const auto* p = std::get_if<scene::PropertyEdit>(&edit))
            mask.envTexels |= p->entity.kind == scene::EntityKind::Environment && p->property == "map";
    const auto tablesBefore = m_samplerTables.tables;
    auto status = uploadScene(*scene, *bvh, mask, &changed);
    if (!status)
        return status;
    // The per-pixel product cache depends on the camera, the geometry, the materials and the
    // sampler tables: an edit of lights, or of the environment that left the tables as they were
    // (its intensity: tablesEnvironment), keeps a complete one (a light drag's next frame skips
    // the cache-building pass).
    using scene::FactorKind;
    const bool keepProductCache =
        m_productCacheReady && !mask.geometry &&
        scene::onlyFactors(changed, {FactorKind::Light, FactorKind::Environment}) &&
        m_samplerTables.tables == tablesBefore;
    m_scene = std::move(scene);
    if (mask.geometry)
        m_timings.bvhBuildSeconds = bvh->buildSeconds;
    m_bvh = std::move(bvh);
    m_timings.uploadSeconds = timer.seconds();
    resetAccumulation();
    m_productCacheReady = keepProductCache;
    return util::okStatus();
}

} // namespace wavelit::render::gpu_tracer
