#include "render/testing/gpu_sampler_probe.h"

#include "render/gpu/brdf_shader_source.h"
#include "render/gpu/gpu_brdf_tables.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_scene_data.h"
#include "render/gpu/sampler_shader_defines.h"
#include "util/hemisphere_sampling.h"
#include "util/image.h"
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/shader_compiler.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace wavelit::render {
namespace {

constexpr int kHeaderFloats = 10; // shares (5), window (k, ox, oy), m, refine levels

int infoFloats(SamplerKind kind) { return kHeaderFloats + gpuPyramidFloats(kind); }

// Inputs per point: t, b, n, wo (world; w of n = BRDF type, w of wo = roughness), base colour.
// Outputs per draw: (wi, pdf); per point (from its draw 0): the mixture's pieces.
std::string kernelSource(SamplerKind kind) {
    const bool oracle = kind == SamplerKind::Oracle;
    return std::string(R"(#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
)") + "#define WAVELIT_PRODUCT_SAMPLER 1\n" + (oracle ? "#define WAVELIT_ORACLE_SAMPLER 1\n" : "") + R"(
layout(local_size_x = 64) in;
#include "sampling/sampler_structs.glsl"
layout(std430, binding = 0) readonly buffer EnvTable { EnvNode envNodes[]; };
layout(std430, binding = 0) readonly buffer EnvTable64 { u64vec2 envNodes64[]; };
layout(std430, binding = 1) readonly buffer SamplerMaterials { SamplerMaterial samplerMaterials[]; };
layout(std430, binding = 2) readonly buffer SamplerWords { uint samplerWords[]; };
layout(std430, binding = 2) readonly buffer SamplerWords64 { uint64_t samplerWords64[]; };
layout(std430, binding = 3) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 4) buffer Samples { vec4 samples[]; };
layout(std430, binding = 5) buffer Info { float info[]; };
layout(push_constant) uniform Push { uint drawsPerPoint, points, tailOffset, lit; float envMean, cosYaw, sinYaw; int envLevel; uint kind, seedLo, seedHi; } pc;
#include "sampling/direction_sampler.glsl"
#include "common/rng.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.drawsPerPoint * pc.points) return;
    uint c = i / pc.drawsPerPoint;
    vec4 t = inputs[5u * c], b = inputs[5u * c + 1u], n = inputs[5u * c + 2u], wo = inputs[5u * c + 3u];
    vec3 color = inputs[5u * c + 4u].rgb;
    Frame f;
    f.t = t.xyz;
    f.b = b.xyz;
    f.n = n.xyz;
    SamplerGlobals g;
    g.kind = pc.kind;
    g.lit = pc.lit != 0u;
    g.tailOffset = pc.tailOffset;
    g.envMean = pc.envMean;
    g.envLevel = pc.envLevel;
    g.cosSinYaw = vec2(pc.cosYaw, pc.sinYaw);
    DirSampler s = dsSetup(g, samplerMaterials[c], f, frameToLocal(f, wo.xyz), uint(n.w), color, wo.w);
    Pcg32 rng = pcgSeed((uint64_t(pc.seedHi) << 32) + uint64_t(pc.seedLo) + uint64_t(c), uint64_t(i));
    float u1 = pcgFloat(rng);
    float u2 = pcgFloat(rng);
    float u3 = pcgFloat(rng);
    vec3 wi;
    float pdf;
    bool valid = dsSample(s, u1, u2, u3, wi, pdf);
    samples[i] = valid ? vec4(wi, pdf) : vec4(0.0, 0.0, 0.0, -1.0);
    if (i % pc.drawsPerPoint == 0u) {
        uint base = c * uint()" + std::to_string(infoFloats(kind)) + R"();
        float header[10] = float[10](s.cProduct, s.cBsdf, s.cEnv, s.cUniform, s.cCosine, float(s.k),
                                     float(s.ox), float(s.oy), float(s.m), float(s.refineLevels));
        for (int k = 0; k < 10; ++k) info[base + uint(k)] = header[k];
        for (int k = 0; k < )" + std::to_string(gpuPyramidFloats(kind)) + R"(; ++k) info[base + 10u + uint(k)] = dsMass(s, k);
    }
}
)";
}

glm::vec3 toLocal(const ShadingPoint& p, const glm::vec3& w) {
    return {glm::dot(w, p.t), glm::dot(w, p.b), glm::dot(w, p.n)};
}

double brdfCosAt(const SamplerMaterial& material, const ShadingPoint& point, const glm::vec3& wi) {
    const glm::vec3 local = toLocal(point, wi);
    if (local.z <= 0.0f)
        return 0.0;
    return double(util::luminance(
        material.brdf->eval(material.params, toLocal(point, point.wo), local) * local.z));
}

// The GPU's product as the production sampler: its leaves (level m of the read-back pyramid)
// over its window, refined below them as many levels as the GPU did, with this point's BRDF.
void buildProduct(GpuMixture& mix) {
    if (!(mix.cProduct > 0.0) || mix.m < 1)
        return;
    wavelet::SquareGrid leaves(mix.m);
    const int side = 1 << mix.m, offset = ((1 << (2 * mix.m)) - 1) / 3;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            leaves.at(x, y) = mix.mass[size_t(offset + y * side + x)];
    mix.product = EnvProductSampler::buildDense(*mix.env, {mix.k, mix.ox, mix.oy}, leaves);
    if (!mix.product)
        return;
    const SamplerEnvironment* env = mix.env;
    const SamplerMaterial* material = mix.material;
    const ShadingPoint point = mix.point;
    mix.product->setLobeRefinement(
        [env, material, point](const glm::dvec3 (&d)[4], double (&out)[4]) {
            for (int c = 0; c < 4; ++c)
                out[c] = brdfCosAt(*material, point, glm::vec3(env->toWorld(d[c])));
        },
        mix.refineLevels);
}

} // namespace

int gpuPyramidFloats(SamplerKind kind) {
    const int m = kind == SamplerKind::Oracle ? kGpuOracleLevel : kGpuMaxProductLevel;
    return ((1 << (2 * (m + 1))) - 1) / 3;
}

double GpuMixture::brdfCos(const glm::vec3& wi) const { return brdfCosAt(*material, point, wi); }

double GpuMixture::pdf(const glm::vec3& wi) const {
    const glm::vec3 local = toLocal(point, wi);
    double v = cUniform * double(util::uniformHemispherePdf(local)) +
               cCosine * double(util::cosineHemispherePdf(local));
    if (cBsdf > 0)
        v += cBsdf * material->brdf->pdf(material->params, toLocal(point, point.wo), local);
    if (cEnv > 0)
        v += cEnv * env->pdfWorld(wi);
    if (cProduct > 0 && product)
        v += cProduct * product->pdfLocal(env->toLocal(glm::dvec3(wi)));
    return v;
}

util::Result<GpuProbeResult> probeGpuSampler(vk::Context& context,
                                             const DirectionSamplerTables& tables, SamplerKind kind,
                                             const std::vector<ShadingPoint>& points,
                                             int drawsPerPoint, uint64_t seed) {
    if (points.empty() || drawsPerPoint < 1)
        return util::makeError(util::ErrorKind::Invalid, "", "probe: no points or draws");
    if (!context.hasFloat64())
        return util::makeError(util::ErrorKind::Unsupported, "",
                               context.deviceName() + ": the samplers need shaderFloat64");
    SceneSamplerTables scene;
    scene.tables = std::shared_ptr<const DirectionSamplerTables>(
        std::shared_ptr<const DirectionSamplerTables>{}, &tables); // not owned
    // Measured materials read their tables as the tracer's kernel does (gpu_brdf_tables.h): the
    // kernel binds them at binding 6 and a point carries its table's offset in its roughness slot.
    scene::Scene tableScene;
    for (const ShadingPoint& p : points)
        if (p.material < tables.materialCount() && tables.material(p.material).params.table) {
            scene::Material m;
            m.brdf = "measured";
            m.brdfTable = tables.material(p.material).params.table;
            tableScene.materials.push_back(m);
        }
    auto brdfTables = packGpuBrdfTables(tableScene);
    if (!brdfTables)
        return brdfTables.error();
    const bool bindTables = !tableScene.materials.empty();
    std::vector<float> in;
    for (const ShadingPoint& p : points) {
        if (p.material >= tables.materialCount())
            return util::makeError(util::ErrorKind::Invalid, "", "probe: material out of range");
        const SamplerMaterial& m = tables.material(p.material);
        if (const std::string problem = plugins::brdfGpuTwinProblem(*m.brdf); !problem.empty())
            return util::makeError(util::ErrorKind::Unsupported, "", "probe: " + problem);
        scene.samplerIndexOfMaterial.push_back(int(p.material));
        const float type = float(gpuBrdfType(*m.brdf, m.params));
        const auto table = brdfTables->offsetOf.find(m.params.table.get()); // 0: the zero table
        const float v[20] = {p.t.x,  p.t.y,  p.t.z,  0,    p.b.x,  p.b.y,  p.b.z,
                             0,      p.n.x,  p.n.y,  p.n.z, type, p.wo.x, p.wo.y,
                             p.wo.z,
                             !plugins::brdfReadsFile(*m.brdf) ? m.params.roughness
                             : table != brdfTables->offsetOf.end() ? float(table->second)
                                                                   : 0.0f,
                             m.params.baseColor.x,
                             m.params.baseColor.y, m.params.baseColor.z, 0};
        in.insert(in.end(), v, v + 20);
    }
    auto packed = packGpuSamplers(scene, kind, points.size());
    if (!packed)
        return packed.error();
    std::vector<std::string> defines = samplerShaderDefines();
    if (bindTables)
        defines.push_back(std::string(kBrdfTableBindingDefine) + "=6");
    auto spirv = compileWithBrdfDispatch(kernelSource(kind), "gpu_sampler_probe.comp",
                                         {{gpuShaderDirectory(), gpuPluginDirectory()}, defines});
    if (!spirv)
        return spirv.error();
    const size_t total = points.size() * size_t(drawsPerPoint);
    const int perPoint = infoFloats(kind);
    std::vector<float> samples(total * 4), info(points.size() * size_t(perPoint));
    const int validationBefore = context.validationMessageCount();
    {
        auto kernel = vk::ComputeKernel::create(
            context, {"gpu sampler probe", *spirv,
                      std::vector<vk::BindingKind>(bindTables ? 7 : 6, vk::BindingKind::StorageBuffer),
                      44});
        if (!kernel)
            return kernel.error();
        const GpuSamplerData& d = *packed;
        struct Blob {
            const void* data;
            size_t bytes;
        } blobs[] = {{d.envNodes.data(), d.envNodes.size() * sizeof(d.envNodes[0])},
                     {d.materials.data(), d.materials.size() * sizeof(GpuSamplerMaterial)},
                     {d.words.data(), d.words.size() * sizeof(uint32_t)},
                     {in.data(), in.size() * sizeof(float)},
                     {nullptr, samples.size() * sizeof(float)},
                     {nullptr, info.size() * sizeof(float)},
                     {brdfTables->floats.data(), brdfTables->floats.size() * sizeof(float)}};
        std::vector<vk::Buffer> buffers;
        for (uint32_t i = 0; i < (bindTables ? 7u : 6u); ++i) {
            auto b = vk::Buffer::create(context, blobs[i].bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        "probe buffer");
            if (!b)
                return b.error();
            if (blobs[i].data)
                b->write(blobs[i].data, blobs[i].bytes);
            buffers.push_back(std::move(b.value()));
            kernel->bind(i, buffers.back());
        }
        const double yaw = double(tables.sourceEnvironment().rotationDeg) * std::numbers::pi / 180.0;
        struct {
            uint32_t drawsPerPoint, points, tailOffset, lit;
            float envMean, cosYaw, sinYaw;
            int32_t envLevel;
            uint32_t kind, seedLo, seedHi;
        } push{uint32_t(drawsPerPoint), uint32_t(points.size()), d.tailOffset, d.lit ? 1u : 0u,
               d.envMean, float(std::cos(yaw)), float(std::sin(yaw)), int32_t(d.envLevel),
               d.kind, uint32_t(seed), uint32_t(seed >> 32)};
        static_assert(sizeof(push) == 44);
        auto runner = vk::CommandRunner::create(context, "gpu sampler probe");
        if (!runner)
            return runner.error();
        if (auto s = (*runner)->run([&](VkCommandBuffer cmd) {
                kernel->dispatch(cmd, uint32_t((total + 63) / 64), 1, 1, &push);
                vk::computeToComputeAndHostBarrier(cmd);
            });
            !s)
            return s.error();
        buffers[4].read(samples.data(), samples.size() * sizeof(float));
        buffers[5].read(info.data(), info.size() * sizeof(float));
    }
    GpuProbeResult r;
    r.validationMessages = context.validationMessageCount() - validationBefore;
    for (size_t c = 0; c < points.size(); ++c) {
        const float* f = &info[c * size_t(perPoint)];
        GpuMixture mix;
        mix.cProduct = f[0];
        mix.cBsdf = f[1];
        mix.cEnv = f[2];
        mix.cUniform = f[3];
        mix.cCosine = f[4];
        mix.k = int(f[5]);
        mix.ox = int(f[6]);
        mix.oy = int(f[7]);
        mix.m = int(f[8]);
        mix.refineLevels = int(f[9]);
        mix.mass.assign(f + kHeaderFloats, f + perPoint);
        mix.env = &tables.environment();
        mix.material = &tables.material(points[c].material);
        mix.point = points[c];
        buildProduct(mix);
        r.mixtures.push_back(std::move(mix));
    }
    r.draws.resize(total);
    for (size_t i = 0; i < total; ++i)
        r.draws[i] = {glm::vec3(samples[4 * i], samples[4 * i + 1], samples[4 * i + 2]),
                      samples[4 * i + 3]};
    return r;
}

} // namespace wavelit::render
