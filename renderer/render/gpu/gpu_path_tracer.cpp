#include "render/gpu/gpu_path_tracer_impl.h"

#include "render/gpu/brdf_shader_source.h"
#include "render/gpu/sampler_shader_defines.h"
#include "render/session/integrator_factory.h"
#include "util/log.h"
#include "util/timer.h"
#include "vk/shader_compiler.h"

#include <cstdlib>
#include <filesystem>
#include <future>
#include <utility>
#include <vector>

#ifndef WAVELIT_SHADER_DIR
#define WAVELIT_SHADER_DIR "shaders"
#endif
#ifndef WAVELIT_PLUGIN_DIR
#define WAVELIT_PLUGIN_DIR "plugins"
#endif

namespace wavelit::render {
namespace gpu_tracer {
namespace {

std::string envOr(const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return v && *v ? v : fallback;
}

} // namespace

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
    // The sampler tables (CPU work, most of it the env's conservative map) are built on another
    // thread beside the kernel's compile, which does not need them except for `wavelet` (whether
    // the kernel carries the product code: it waits for them below). The compile is one thread,
    // the tables two: a `mis` session's first image ~0.2 s sooner on 2 cores (docs/performance.md).
    std::future<util::Result<SceneSamplerTables>> tablesBuild;
    if (pt->usesDirectionSamplers())
        tablesBuild = std::async(std::launch::async, [tracer = pt.get()] {
            return tracer->m_tablesCache.update(*tracer->m_scene, tracer->m_options.sampler);
        });

    // Pipeline next: a shader error is the likeliest failure and should not wait for uploads.
    vk::ShaderCompileOptions compile{{gpuShaderDirectory(), gpuPluginDirectory()},
                                     {"WAVELIT_WORKGROUP_X=" + std::to_string(kWorkgroupX),
                                      "WAVELIT_WORKGROUP_Y=" + std::to_string(kWorkgroupY)}};
    // `bsdf` compiles without the samplers: no private product pyramid, no doubles.
    // The sampler is fixed for the tracer's life: the kernel reads its code as a constant, so
    // the other kinds' branches compile away (a `mis` pass ~6% cheaper on lavapipe, issue 12).
    if (pt->usesDirectionSamplers()) {
        compile.defines.push_back("WAVELIT_DIRECTION_SAMPLERS=1");
        compile.defines.push_back("WAVELIT_SAMPLER_KIND=" +
                                  std::to_string(unsigned(options.sampler)) + "u");
    }
    // The product code (private pyramid, descents) only for the kinds that draw from a product:
    // carried as dead code it cost `mis` ~40% of a lavapipe pass (docs/performance.md, issue 12).
    // A `wavelet` scene whose every material's policy is EnvMis or BsdfLobe (docs/performance.md
    // "Wavelet pass cost, round 3") draws from no product: its kernel is compiled without the
    // code, and an edit that brings a product recreates the tracer (uploadScene: Unsupported).
    pt->m_productCompiled = options.sampler == SamplerKind::Oracle;
    if (options.sampler == SamplerKind::Wavelet) {
        auto tables = tablesBuild.get();
        if (!tables)
            return tables.error();
        pt->m_productCompiled = tables->tables && tables->tables->anyProduct();
        pt->m_createTables = std::move(tables.value());
    }
    if (pt->m_productCompiled)
        compile.defines.push_back("WAVELIT_PRODUCT_SAMPLER=1");
    // `wavelet`'s camera vertex in its own copy of the vertex code on a CPU device alone
    // (path_vertex.glsl; docs/performance.md "Wavelet pass cost, round 5": it cut lavapipe's
    // pass by a quarter and made an H200's 1.4x slower). Same images either way; env
    // WAVELIT_KERNEL_SHAPE=split|loop overrides the rule (tests compare the two shapes).
    const std::string shape = gpu_tracer::envOr("WAVELIT_KERNEL_SHAPE", "");
    if (shape == "split" || (shape != "loop" && pt->m_context->cpuDevice()))
        compile.defines.push_back("WAVELIT_SPLIT_CAMERA_VERTEX=1");
    // Only the oracle needs the larger private pyramid (2^5 leaves instead of the wavelet's).
    if (options.sampler == SamplerKind::Oracle)
        compile.defines.push_back("WAVELIT_ORACLE_SAMPLER=1");
    // The samplers' constants and table layouts, generated from the C++ ones.
    for (std::string& define : samplerShaderDefines())
        compile.defines.push_back(std::move(define));
    // LightMix layers: two bindings after the last one (gpu_path_tracer_impl.h).
    pt->m_groupBinding = pt->usesDirectionSamplers() ? 10u : 7u;
    if (options.lightGroups) {
        compile.defines.push_back("WAVELIT_LIGHT_GROUPS=1");
        compile.defines.push_back("WAVELIT_GROUP_INFO_BINDING=" + std::to_string(pt->m_groupBinding));
        compile.defines.push_back("WAVELIT_GROUP_LAYERS_BINDING=" +
                                  std::to_string(pt->m_groupBinding + 1));
    }
    // Measured BRDF tables: the binding after the last (gpu_path_tracer_impl.h), only in kernels
    // of scenes that read a table. Carried in every kernel, the table plugin's code (double
    // trigonometry in each of eval, sample and pdf) doubled a lavapipe `wavelet` pass of the
    // default scene, which has no measured material (issue 12). A scene swap or edit that brings
    // a table into a kernel without them recreates the tracer (uploadScene: Unsupported).
    pt->m_brdfTableBinding = pt->m_groupBinding + (options.lightGroups ? 2u : 0u);
    pt->m_brdfTablesCompiled = packed->usesBrdfTables;
    if (pt->m_brdfTablesCompiled)
        compile.defines.push_back(std::string(kBrdfTableBindingDefine) + "=" +
                                  std::to_string(pt->m_brdfTableBinding));
    // The per-pixel cache of the camera vertex's product (product_cache.h): `wavelet` kernels
    // with the product code, the binding after all others.
    pt->m_productCacheBinding = pt->m_brdfTableBinding + (pt->m_brdfTablesCompiled ? 1u : 0u);
    pt->m_productCacheCompiled = options.sampler == SamplerKind::Wavelet && pt->m_productCompiled;
    if (pt->m_productCacheCompiled)
        compile.defines.push_back("WAVELIT_PRODUCT_CACHE_BINDING=" +
                                  std::to_string(pt->m_productCacheBinding));
    // On a CPU device the kernel reads the scene through texel views of its buffers
    // (kSceneTexelViews, bound after all others): llvmpipe fetches a texel as a gather in
    // registers, an SSBO word in a loop over the lanes (docs/performance.md "Texel buffers": a
    // fifth of a pass). Same words, same images. Env WAVELIT_SCENE_READS=texels|storage
    // overrides the rule (tests compare the two).
    const std::string reads = gpu_tracer::envOr("WAVELIT_SCENE_READS", "");
    const uint32_t bindingCount =
        pt->m_productCacheBinding + (pt->m_productCacheCompiled ? 1u : 0u);
    if (reads == "texels" || (reads != "storage" && pt->m_context->cpuDevice())) {
        pt->m_sceneTexelBinding = bindingCount;
        compile.defines.push_back("WAVELIT_SCENE_TEXELS_BINDING=" +
                                  std::to_string(pt->m_sceneTexelBinding));
    }
    std::string shaderPath =
        (std::filesystem::path(gpuShaderDirectory()) / "path_tracer.comp").string();
    pt->m_brdfPluginsCompiled = packed->brdfPlugins;
    auto spirv = compileFileWithBrdfDispatch(shaderPath, compile, pt->m_brdfPluginsCompiled);
    if (!spirv)
        return spirv.error();
    using vk::BindingKind;
    std::vector<BindingKind> bindings(bindingCount, BindingKind::StorageBuffer);
    if (pt->m_sceneTexelBinding)
        bindings.insert(bindings.end(), pt->sceneTexelViewCount(), BindingKind::UniformTexelBuffer);
    // A storage buffer, not a uniform buffer: lavapipe re-compiles per bind otherwise (header).
    bindings[kParams] = BindingKind::StorageBuffer;
    auto kernel = vk::ComputeKernel::create(
        *pt->m_context, {"path_tracer", std::move(spirv.value()), bindings, sizeof(PassPush)});
    if (!kernel)
        return kernel.error();
    pt->m_kernel = std::move(kernel.value());
    if (pt->m_productCacheCompiled) {
        // The cache's build in a pipeline of its own: carried in the tracing kernel (a branch
        // taken in one pass per reset) it cost every lavapipe `wavelet` pass ~10% (issue 12).
        compile.defines.push_back("WAVELIT_BUILD_PRODUCT_CACHE=1");
        auto buildSpirv =
            compileFileWithBrdfDispatch(shaderPath, compile, pt->m_brdfPluginsCompiled);
        if (!buildSpirv)
            return buildSpirv.error();
        auto cacheKernel = vk::ComputeKernel::create(
            *pt->m_context,
            {"product_cache_build", std::move(buildSpirv.value()), bindings, sizeof(PassPush)});
        if (!cacheKernel)
            return cacheKernel.error();
        pt->m_cacheKernel = std::move(cacheKernel.value());
    }
    pt->m_timings.pipelineSeconds = timer.seconds();

    timer.restart();
    if (tablesBuild.valid()) { // the kinds whose kernel did not wait for them
        auto tables = tablesBuild.get();
        if (!tables)
            return tables.error();
        pt->m_createTables = std::move(tables.value());
    }
    // The scene first: uploadScene checks the whole plan (accumulation included) before it
    // allocates anything.
    auto uploaded = pt->uploadScene(*pt->m_scene, *pt->m_bvh, UploadMask{}, nullptr);
    if (!uploaded)
        return uploaded.error();
    const GpuBufferPlan accumulationPlan = gpuAccumulationPlan(options.width, options.height);
    auto accumulation = pt->upload(nullptr, accumulationPlan.bytes,
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, accumulationPlan.name);
    if (!accumulation)
        return accumulation.error();
    pt->m_accumulation = std::move(accumulation.value());
    pt->bindAll(kAccumulation, pt->m_accumulation);
    pt->m_accumulation.fill(0);
    auto runner = vk::CommandRunner::create(*pt->m_context, "path tracer");
    if (!runner)
        return runner.error();
    pt->m_runner = std::move(runner.value());
    pt->m_timings.uploadSeconds = timer.seconds();
    return std::unique_ptr<Integrator>(std::move(pt));
}

void GpuPathTracer::bindAll(uint32_t binding, const vk::Buffer& buffer) {
    m_kernel.bind(binding, buffer);
    if (m_productCacheCompiled)
        m_cacheKernel.bind(binding, buffer);
}

util::Status GpuPathTracer::checkSceneTexels(uint32_t binding, size_t bytes,
                                             const std::string& name) const {
    if (!m_sceneTexelBinding)
        return util::okStatus();
    const uint64_t limit = m_context->limits().maxTexelBufferElements;
    for (uint32_t i = 0; i < sceneTexelViewCount(); ++i) {
        const uint64_t texels = bytes / vk::ComputeKernel::texelBytes(kSceneTexelViews[i].format);
        if (kSceneTexelViews[i].buffer == binding && texels > limit)
            return util::makeError(util::ErrorKind::Unsupported, "",
                                   name + " is " + std::to_string(texels) +
                                       " texels, more than the device's texel-buffer limit of " +
                                       std::to_string(limit));
    }
    return util::okStatus();
}

util::Status GpuPathTracer::bindSceneTexels(uint32_t binding, const vk::Buffer& buffer) {
    if (!m_sceneTexelBinding)
        return util::okStatus();
    for (uint32_t i = 0; i < sceneTexelViewCount(); ++i) {
        if (kSceneTexelViews[i].buffer != binding)
            continue;
        const VkFormat format = kSceneTexelViews[i].format;
        if (auto bound = m_kernel.bindTexels(m_sceneTexelBinding + i, buffer, format); !bound)
            return bound;
        if (m_productCacheCompiled)
            if (auto bound = m_cacheKernel.bindTexels(m_sceneTexelBinding + i, buffer, format);
                !bound)
                return bound;
    }
    return util::okStatus();
}

} // namespace gpu_tracer

std::string gpuShaderDirectory() {
    return gpu_tracer::envOr("WAVELIT_SHADER_DIR", WAVELIT_SHADER_DIR);
}
std::string gpuPluginDirectory() {
    return gpu_tracer::envOr("WAVELIT_PLUGIN_DIR", WAVELIT_PLUGIN_DIR);
}

util::Result<std::unique_ptr<Integrator>>
createGpuPathTracer(std::shared_ptr<const scene::Scene> scene,
                    std::shared_ptr<const scene::Bvh> bvh, const RenderOptions& options) {
    return gpu_tracer::GpuPathTracer::create(std::move(scene), std::move(bvh), options);
}

} // namespace wavelit::render
