#include "render/gpu/sampler_shader_defines.h"

#include "render/gpu/gpu_sampler_data.h"
#include "render/gpu/product_cache.h"
#include "render/sampling/product/flat_product_layout.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_window.h"
#include "render/session/render_options.h"

#include <cstdio>
#include <string_view>

namespace wavelit::render {
namespace {

// A literal GLSL reads back as the same double: 17 significant digits, a '.' or exponent so the
// LF suffix applies.
std::string doubleLiteral(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos)
        s += ".0";
    return s + "LF";
}

std::string floatLiteral(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", double(float(v)));
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos)
        s += ".0";
    return s;
}

std::string define(std::string_view name, const std::string& value) {
    return "WAVELIT_" + std::string(name) + "=" + value;
}
std::string define(std::string_view name, int value) { return define(name, std::to_string(value)); }
std::string defineUint(std::string_view name, unsigned value) {
    return define(name, std::to_string(value) + "u");
}

} // namespace

std::vector<std::string> samplerShaderDefines() {
    namespace fl = flat_layout;
    return {
        // render::SamplerKind codes, in its order.
        defineUint("SAMPLER_UNIFORM", unsigned(SamplerKind::Uniform)),
        defineUint("SAMPLER_COSINE", unsigned(SamplerKind::Cosine)),
        defineUint("SAMPLER_BSDF", unsigned(SamplerKind::Bsdf)),
        defineUint("SAMPLER_ENV", unsigned(SamplerKind::Env)),
        defineUint("SAMPLER_MIS", unsigned(SamplerKind::Mis)),
        defineUint("SAMPLER_WAVELET", unsigned(SamplerKind::Wavelet)),
        defineUint("SAMPLER_ORACLE", unsigned(SamplerKind::Oracle)),
        // GpuSamplerMaterial::mode.
        defineUint("MODE_BSDF_ONLY", kGpuSamplerBsdfOnly),
        defineUint("MODE_PRODUCT", kGpuSamplerProduct),
        defineUint("MODE_BSDF_LOBE", kGpuSamplerBsdfLobe),
        defineUint("MODE_ENV_MIS", kGpuSamplerEnvMis),
        defineUint("MODE_ORACLE", kGpuSamplerOracle),
        // The mixtures.
        define("MIS_WEIGHT", doubleLiteral(kMisWeight)),
        define("WAVELET_PRODUCT_VERTICES", kWaveletProductVertices),
        define("PRODUCT_CACHE_HEADER_WORDS", int(GpuProductCacheLayout::kHeaderWords)),
        define("PRODUCT_CACHE_PYRAMID_AT", int(GpuProductCacheLayout::kPyramidAt)),
        define("WAVELET_MIN_ENV_SHARE", doubleLiteral(kWaveletMinEnvShare)),
        define("ORACLE_MIN_ENV_SHARE", doubleLiteral(kOracleMinEnvShare)),
        define("MAX_ENV_SHARE", doubleLiteral(kMaxEnvShare)),
        define("LOBE_STRATA", kLobeStrata),
        define("TAIL_LEVEL", kTailLevel),
        // The products.
        define("LOBE_FLOOR", floatLiteral(kLobeFloor)),
        define("MAX_PRODUCT_LEVEL", kGpuMaxProductLevel),
        define("ORACLE_LEVEL", kGpuOracleLevel),
        define("ORACLE_DEPTH_BELOW_ENV", kOracleDepthBelowEnv),
        // chooseWindow.
        define("WHOLE_SPHERE_CAP_ANGLE", floatLiteral(kWholeSphereCapAngle)),
        define("RIM_PROBES", kRimProbes),
        define("RIM_INNER_RING", floatLiteral(kRimInnerRing)),
        define("MAX_COMPACT_EXTENT", floatLiteral(kMaxCompactExtent)),
        // The flat product tables.
        defineUint("FLAT_HEADER_WORDS", fl::kHeaderWords),
        defineUint("FLAT_BIN_LEVEL", fl::kBinLevel),
        defineUint("FLAT_PRODUCT_LEVEL", fl::kProductLevel),
        defineUint("FLAT_BIN_COUNT", fl::kBinCount),
        defineUint("FLAT_BIN_WORDS", fl::kBinWords),
        defineUint("FLAT_BIN_K", fl::kBinK),
        defineUint("FLAT_BIN_OX", fl::kBinOx),
        defineUint("FLAT_BIN_OY", fl::kBinOy),
        defineUint("FLAT_BIN_FACTOR", fl::kBinFactor),
        defineUint("FLAT_FACTOR_WORDS", fl::kFactorWords),
        defineUint("FLAT_FACTOR_FIRST_NODE", fl::kFactorFirstNode),
        defineUint("FLAT_FACTOR_NODE_COUNT", fl::kFactorNodeCount),
        defineUint("FLAT_NODE_WORDS", fl::kNodeWords),
        defineUint("FLAT_NODE_DETAIL", fl::kNodeDetail),
        defineUint("FLAT_NODE_CHILD", fl::kNodeChild),
    };
}

} // namespace wavelit::render
