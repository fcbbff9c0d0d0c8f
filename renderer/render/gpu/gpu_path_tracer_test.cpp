// The Vulkan path tracer on the real device (lavapipe in CI) with validation on: closed forms,
// agreement with the CPU reference tracer (same estimator and random streams), shader errors
// (scene swaps and resets: gpu_path_tracer_scene_swap_test.cpp).
// Images are small (64x64) because lavapipe shares two CPU cores with everything else.
#include "render/testing/cpu_analytic_scenes.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_path_tracer_test_support.h"
#include "render/session/integrator_factory.h"
#include "render/session/render_session.h"
#include "render/sampling/direction_sampler_tables.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_environment.h"
#include "render/testing/sampler_test_envs.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace wavelit::render {
namespace {

using namespace gpu_tracer_test;
namespace fs = std::filesystem;

// Sets an environment variable for a scope and puts back its previous value (or its absence),
// also when an ASSERT leaves the test early, so later tests see the environment they started with.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : m_name(name) {
        const char* previous = std::getenv(name);
        m_hadValue = previous != nullptr;
        if (previous)
            m_previous = previous;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (m_hadValue)
            setenv(m_name, m_previous.c_str(), 1);
        else
            unsetenv(m_name);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* m_name;
    bool m_hadValue = false;
    std::string m_previous;
};

// Acceptance bound of issue 3 for the closed-form mean.
constexpr double kMeanTolerance = 0.05;

bool allFinite(const util::ImageRGB& img) {
    for (const auto& p : img.pixels)
        if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b))
            return false;
    return true;
}

double meanLuminance(const util::ImageRGB& img) {
    double sum = 0.0;
    for (const auto& p : img.pixels)
        sum += util::luminance(p);
    return sum / double(img.pixels.size());
}

// Fraction of each pixel the sphere covers, by the same camera rays as the tracer on a
// kSub x kSub grid of jitters, cast through the CPU BVH.
std::vector<double> coverage(const scene::Scene& scene, const scene::Bvh& bvh, int w, int h) {
    constexpr int kSub = 8;
    const scene::Camera& c = scene.camera;
    glm::vec3 forward = glm::normalize(c.target - c.position);
    glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    glm::vec3 up = glm::cross(right, forward);
    float tanHalf = std::tan(0.5f * glm::radians(c.verticalFovDeg));
    float aspect = float(w) / float(h);
    std::vector<double> cov(size_t(w) * size_t(h), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int j = 0; j < kSub * kSub; ++j) {
                float u = (float(j % kSub) + 0.5f) / kSub, v = (float(j / kSub) + 0.5f) / kSub;
                float sx = (2.0f * (float(x) + u) / float(w) - 1.0f) * tanHalf * aspect;
                float sy = (1.0f - 2.0f * (float(y) + v) / float(h)) * tanHalf;
                glm::vec3 d = glm::normalize(forward + sx * right + sy * up);
                scene::BvhHit hit;
                if (scene::intersect(bvh, c.position, d, 0.0f, std::numeric_limits<float>::max(),
                                     hit))
                    cov[size_t(y) * w + x] += 1.0 / (kSub * kSub);
            }
    return cov;
}

TEST(GpuPathTracer, DirectLightingOfDiffuseSphereInConstantEnvIsAlbedoTimesL) {
    // bounces = 1: a convex sphere cannot see itself, so every sphere pixel is albedo x L and
    // every background pixel is L; lambert's f cos / pdf = albedo exactly, so noise comes only
    // from pixel coverage at the silhouette.
    const float albedo = 0.5f;
    const glm::vec3 L(1.5f);
    scene::Material mat;
    mat.id = 1;
    mat.brdf = "lambert";
    mat.baseColor = glm::vec3(albedo);
    auto scene = makeFurnaceScene(mat, L);
    auto bvh = scene::buildBvh(*scene);
    auto gpu = makeGpu(scene, testOptions(1));
    ASSERT_TRUE(gpu);
    util::ImageRGB img = renderPasses(*gpu, 8);
    EXPECT_EQ(gpu->samplesPerPixel(), 8);
    ASSERT_TRUE(allFinite(img));

    std::vector<double> cov = coverage(*scene, bvh, kSize, kSize);
    double expected = 0.0;
    int interior = 0;
    for (size_t i = 0; i < cov.size(); ++i) {
        expected += (cov[i] * albedo + (1.0 - cov[i])) * L.g;
        if (cov[i] == 1.0) {
            ++interior;
            // Shading normals can send a few cosine samples below a facet (the path then ends),
            // so interior pixels may fall slightly short of albedo x L, never above it.
            EXPECT_NEAR(img.pixels[i].g, albedo * L.g, 0.02 * albedo * L.g) << "pixel " << i;
        } else if (cov[i] == 0.0) {
            EXPECT_FLOAT_EQ(img.pixels[i].g, L.g) << "pixel " << i;
        }
    }
    expected /= double(cov.size());
    double mean = meanLuminance(img);
    std::printf("closed form: mean %.5f, expected %.5f (%d interior pixels), validation "
                "messages %d\n",
                mean, expected, interior, gpu->validationMessageCount());
    EXPECT_GT(interior, kSize * kSize / 4);
    EXPECT_NEAR(mean, expected, kMeanTolerance * expected);
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

TEST(GpuPathTracer, InsideAnEmissiveDiffuseSphereRadianceIsTheGeometricSeries) {
    // Camera inside a closed Lambert sphere of albedo rho emitting Le: every path stays inside,
    // so after B scattering events the pixel is Le (1 + rho + ... + rho^B), and Russian roulette
    // (from depth 2) only adds noise. Exercises emission, multi-bounce and roulette.
    const float rho = 0.5f, le = 1.0f;
    const int bounces = 4;
    scene::Material mat;
    mat.id = 1;
    mat.brdf = "lambert";
    mat.baseColor = glm::vec3(rho);
    mat.emission = glm::vec3(le);
    auto scene = makeClosedSphereScene(mat);
    auto gpu = makeGpu(scene, testOptions(bounces, 32, 32));
    ASSERT_TRUE(gpu);
    util::ImageRGB img = renderPasses(*gpu, 16);
    ASSERT_TRUE(allFinite(img));
    double expected = 0.0;
    for (int k = 0; k <= bounces; ++k)
        expected += le * std::pow(rho, k);
    double mean = meanLuminance(img);
    // Roulette noise only: a sample is 1.75, 2.75 or 3.75 with probabilities 7/8, 1/16, 1/16
    // (sigma 0.53), so the standard error over 32*32*16 samples is 0.0041 and 1% (0.019) is
    // 4.7 sigma.
    constexpr double kSeriesTolerance = 0.01;
    std::printf("closed sphere: mean %.5f, expected %.5f\n", mean, expected);
    EXPECT_NEAR(mean, expected, kSeriesTolerance * expected);
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

// Glossy sphere on a Lambert ground (4 bounces, roulette) in an env image.
std::shared_ptr<scene::Scene> glossySphereOnGround(std::shared_ptr<const util::ImageRGB> env,
                                                   float roughness = 0.3f) {
    scene::Material mat;
    mat.id = 1;
    mat.brdf = "ggx";
    mat.baseColor = glm::vec3(0.9f, 0.6f, 0.3f);
    mat.roughness = roughness;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 48, 24);
    scene->lighting.environment.image = std::move(env);
    scene->lighting.environment.rotationDeg = 30.0f;
    scene::Material floor;
    floor.id = 2;
    floor.brdf = "lambert";
    floor.baseColor = glm::vec3(0.5f);
    scene->materials.push_back(floor);
    scene::Object ground = scene->objects[0];
    ground.id = 3;
    ground.materialId = 2;
    ground.transform.translation = glm::vec3(0.0f, -2.0f, 0.0f);
    scene->objects.push_back(ground);
    return scene;
}

// Both tracers draw the same numbers per pixel and pass, so images agree pixel by pixel up to
// float rounding; a few paths may diverge where rounding flips a branch, so a small fraction may
// differ. rouletteConstant (optional) receives the `mis` roulette constant of the scene's env.
void expectGpuMatchesCpu(const std::shared_ptr<scene::Scene>& scene, SamplerKind kind,
                         float* rouletteConstant = nullptr) {
    RenderOptions options = testOptions(4);
    options.sampler = kind;
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto gpu = createGpuPathTracer(scene, bvh, options);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    auto cpu = createCpuPathTracer(scene, bvh, options);
    ASSERT_TRUE(cpu.ok()) << cpu.error().message();
    if (rouletteConstant && (*cpu)->samplerTables())
        *rouletteConstant =
            misEnvRoulette((*cpu)->samplerTables()->environment().effectiveSolidAngle());
    constexpr int kPasses = 4;
    util::ImageRGB g = renderPasses(**gpu, kPasses), c = renderPasses(**cpu, kPasses);
    ASSERT_TRUE(allFinite(g));
    // Relative agreement per pixel: float rounding differs between LLVM and the C++ compiler.
    constexpr float kPixelTolerance = 1e-3f;
    int differing = 0;
    for (size_t i = 0; i < g.pixels.size(); ++i) {
        glm::vec3 d = glm::abs(g.pixels[i] - c.pixels[i]);
        float scale = std::max(1e-3f, util::luminance(c.pixels[i]));
        if (std::max(d.r, std::max(d.g, d.b)) > kPixelTolerance * scale + 1e-5f)
            ++differing;
    }
    double gm = meanLuminance(g), cm = meanLuminance(c);
    std::printf("cpu vs gpu, sampler %s: mean %.5f vs %.5f, %d of %zu pixels differ\n",
                samplerKindName(kind), cm, gm, differing, g.pixels.size());
    // Diverged paths: a few percent at most (rounding flips roulette or a grazing test).
    EXPECT_LT(differing, int(g.pixels.size() / 20)) << samplerKindName(kind);
    EXPECT_NEAR(gm, cm, 0.02 * cm) << samplerKindName(kind);
    EXPECT_EQ((*gpu)->validationMessageCount(), 0);
}

TEST(GpuPathTracer, MatchesCpuReferenceWithTheSameRandomStreams) {
    auto env = gradientEnvironment();
    // A one-texel sun 10^5 x the sky: the tabulated samplers' draws land on it, where a pdf
    // evaluated in the wrong texel would show as a firefly.
    env->at(20, 4) = glm::vec3(1e5f);
    auto scene = glossySphereOnGround(env);
    // Every sampler whose GPU form draws as its CPU form does (the same techniques from the same
    // numbers; `wavelet` under a map where it forms products is the next test; `oracle` builds
    // its product differently on the GPU and is judged statistically in
    // gpu_product_sampler_test.cpp and gpu_sampler_unbiased_test.cpp).
    for (SamplerKind kind : {SamplerKind::Bsdf, SamplerKind::Uniform, SamplerKind::Cosine,
                             SamplerKind::Env, SamplerKind::Mis})
        expectGpuMatchesCpu(scene, kind);
}

// `mis`'s shadow-ray roulette under a concentrated env, where its constant c is scaled down
// from kMisEnvRoulette (sampler_constants.h misEnvRoulette): the Vulkan tracer reads c from its
// params block, the CPU tracer computes it; the same c makes the same coin decisions.
TEST(GpuPathTracer, MisRouletteUnderASunMatchesCpu) {
    const scene::Environment sunSky =
        makeSunSkyEnvironment(128, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e4, 2.0);
    float c = 0.0f;
    expectGpuMatchesCpu(glossySphereOnGround(sunSky.image), SamplerKind::Mis, &c);
    EXPECT_LT(c, float(kMisEnvRoulette)) << "the scaled constant, not the old one";
}

// `wavelet` where the sphere keeps its product (a 13-degree sun, a glossy r = 0.2 lobe of
// comparable extent): both tracers build the kernel's 16^2 product at the camera vertex
// (ProductBuild::Tracer), so the same numbers draw the same directions.
TEST(GpuPathTracer, WaveletMatchesCpuWithTheSameRandomStreams) {
    const scene::Environment sunSky =
        makeSunSkyEnvironment(256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e4, 13.0);
    expectGpuMatchesCpu(glossySphereOnGround(sunSky.image, 0.2f), SamplerKind::Wavelet);
}

// Two renders of one scene by two code paths that must compute the same numbers: a lit,
// finite image, the same bit for bit.
void expectTheSameImage(const util::ImageRGB& a, const util::ImageRGB& b, const std::string& what) {
    ASSERT_TRUE(allFinite(a)) << what;
    EXPECT_GT(meanLuminance(a), 0.0) << what;
    int differing = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        differing += a.pixels[i] != b.pixels[i] ? 1 : 0;
    EXPECT_EQ(differing, 0) << what;
}

// The kernel's two code shapes (path_vertex.glsl: one loop on GPUs, `wavelet`'s camera vertex in
// its own copy on CPU devices) compute the same estimator with the same numbers: the same image
// bit for bit, for `wavelet` where the sphere keeps its product and for `mis`.
TEST(GpuPathTracer, KernelShapesRenderTheSameImage) {
    const scene::Environment sunSky =
        makeSunSkyEnvironment(256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e4, 13.0);
    auto scene = glossySphereOnGround(sunSky.image, 0.2f);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    for (SamplerKind kind : {SamplerKind::Wavelet, SamplerKind::Mis}) {
        RenderOptions options = testOptions(4);
        options.sampler = kind;
        util::ImageRGB images[2];
        const char* shapes[2] = {"loop", "split"};
        for (int i = 0; i < 2; ++i) {
            ScopedEnv shape("WAVELIT_KERNEL_SHAPE", shapes[i]);
            auto gpu = createGpuPathTracer(scene, bvh, options);
            ASSERT_TRUE(gpu.ok()) << gpu.error().message();
            images[i] = renderPasses(**gpu, 3);
            EXPECT_EQ((*gpu)->validationMessageCount(), 0);
        }
        expectTheSameImage(images[0], images[1], samplerKindName(kind));
    }
}

// The scene's buffers read as storage buffers (GPUs) or through texel views (CPU devices:
// kSceneTexelViews) are the same words: the same image bit for bit, for `bsdf`, `mis` and
// `wavelet` where the sphere keeps its product (its cache's build kernel traces too), with a
// point light (the light records), and again after setScene swaps in a finer mesh, whose new
// buffers take new views.
TEST(GpuPathTracer, SceneReadsThroughTexelsRenderTheSameImage) {
    const scene::Environment sunSky =
        makeSunSkyEnvironment(256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e4, 13.0);
    auto withLamp = [&](std::shared_ptr<scene::Scene> scene) {
        scene::Light lamp;
        lamp.id = 7;
        lamp.name = "lamp";
        lamp.position = glm::vec3(1.5f, 2.0f, 2.0f);
        lamp.intensity = 40.0f;
        scene->lighting.lights.push_back(lamp);
        return scene;
    };
    auto first = withLamp(glossySphereOnGround(sunSky.image, 0.2f));
    auto firstBvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*first));
    // Moved, and a finer mesh: every geometry buffer is new, and so are its views.
    auto second = withLamp(glossySphereOnGround(sunSky.image, 0.2f));
    second->objects[0].transform.translation += glm::vec3(0.3f, 0.0f, 0.0f);
    auto finer = makeFurnaceScene(first->materials[0], glm::vec3(1.0f), 64, 32);
    second->objects[0].meshPath = finer->objects[0].meshPath;
    second->objects[0].mesh = finer->objects[0].mesh;
    auto secondBvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*second));
    for (SamplerKind kind : {SamplerKind::Bsdf, SamplerKind::Mis, SamplerKind::Wavelet}) {
        RenderOptions options = testOptions(4);
        options.sampler = kind;
        util::ImageRGB before[2], after[2];
        const char* reads[2] = {"storage", "texels"};
        for (int i = 0; i < 2; ++i) {
            ScopedEnv mode("WAVELIT_SCENE_READS", reads[i]);
            auto gpu = createGpuPathTracer(first, firstBvh, options);
            ASSERT_TRUE(gpu.ok()) << gpu.error().message();
            before[i] = renderPasses(**gpu, 2);
            auto status = (*gpu)->setScene(second, secondBvh);
            ASSERT_TRUE(status.ok()) << status.error().message();
            after[i] = renderPasses(**gpu, 2);
            EXPECT_EQ((*gpu)->validationMessageCount(), 0) << reads[i];
        }
        expectTheSameImage(before[0], before[1], std::string(samplerKindName(kind)) + ", before");
        expectTheSameImage(after[0], after[1], std::string(samplerKindName(kind)) + ", after");
        int changed = 0;
        for (size_t i = 0; i < before[0].pixels.size(); ++i)
            changed += before[0].pixels[i] != after[0].pixels[i] ? 1 : 0;
        EXPECT_GT(changed, 0) << "the swapped scene renders differently";
    }
}

TEST(GpuPathTracer, ShaderCompileErrorNamesFileAndLine) {
    fs::path dir = fs::temp_directory_path() / "wavelit_gpu_broken_shader";
    fs::create_directories(dir);
    std::ofstream(dir / "path_tracer.comp") << "#version 460\nlayout(local_size_x = 8) in;\n"
                                               "void main() {\n    int x = notDeclared;\n}\n";
    scene::Material mat;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 8, 4);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto gpu = [&] {
        ScopedEnv shaders("WAVELIT_SHADER_DIR", dir.string());
        return createGpuPathTracer(scene, bvh, testOptions(1, 8, 8));
    }();
    ASSERT_FALSE(gpu.ok());
    std::string message = gpu.error().message();
    EXPECT_NE(message.find("path_tracer.comp"), std::string::npos) << message;
    EXPECT_NE(message.find("line 4"), std::string::npos) << message;
    EXPECT_NE(message.find("notDeclared"), std::string::npos) << message;
    fs::remove_all(dir);
}

TEST(GpuPathTracer, UnknownBrdfIsUnsupported) {
    scene::Material mat;
    mat.name = "weird";
    mat.brdf = "toon";
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 8, 4);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto gpu = createGpuPathTracer(scene, bvh, testOptions(1, 8, 8));
    ASSERT_FALSE(gpu.ok());
    EXPECT_EQ(gpu.error().kind, util::ErrorKind::Unsupported);
    EXPECT_NE(gpu.error().message().find("weird"), std::string::npos);
}

} // namespace
} // namespace wavelit::render
