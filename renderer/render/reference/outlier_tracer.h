// The outlier tracer (issue 20): which single samples dominate an image's error, and the whole
// path of each. OutlierMonitor watches a progressive render pass by pass (the per-pass sample is
// the running sum's increment, so it works for any Integrator) and keeps the N samples largest
// relative to their pixel's running mean; traceOutlierPaths re-traces each (pixel, pass) on the
// CPU reference tracer with the same random stream (samplePixel is a function of seed, pass and
// pixel), writing the path down term by term (path_record.h). For --device vulkan this re-trace
// is the same path because the two tracers agree path for path on the same streams
// (GpuPathTracer.MatchesCpuReferenceWithTheSameRandomStreams) for uniform, cosine, bsdf, env and
// mis; `wavelet` and `oracle` build their products differently on the GPU, so there the re-traced
// path is the CPU's (each record carries both the measured and the re-traced value).
#pragma once

#include "render/reference/path_record.h"
#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/image.h"
#include "util/result.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace wavelit::render {

struct OutlierSample {
    int x = 0, y = 0, pass = 0;
    glm::vec3 value{0.0f};     // the sample, from the running sum's increment
    double pixelMean = 0.0;    // luminance of the pixel's mean over the passes before it
    double ratio = 0.0;        // luminance(value) / max(pixelMean, image mean / (pass + 1))
};

class OutlierMonitor {
public:
    OutlierMonitor(int width, int height, int count);
    // The accumulated image (mean over passes 0..p) after pass p, called once per pass in order.
    void addPass(const util::ImageRGB& mean);
    int passes() const { return m_passes; }
    // The largest by ratio, largest first.
    std::vector<OutlierSample> outliers() const;

private:
    int m_width, m_height, m_count, m_passes = 0;
    std::vector<glm::dvec3> m_sum;
    std::vector<OutlierSample> m_heap; // min-heap on ratio
};

// Re-traces each outlier's (pixel, pass) on the CPU reference tracer (options as rendered).
util::Result<std::vector<PathRecord>> traceOutlierPaths(const scene::Scene& scene,
                                                        const RenderOptions& options,
                                                        const std::vector<OutlierSample>& outliers);

// The outliers file: {"sampler", "device", "passes", "outliers": [{pixel, pass, sample,
// retraced, pixelMean, finalPixelMean, ratio, vertices: [...], events: [...]}]} (docs/performance.md).
std::string outliersJson(const RenderOptions& options, const std::string& deviceName,
                         int passes, const std::vector<OutlierSample>& outliers,
                         const std::vector<PathRecord>& paths, const util::ImageRGB& finalImage);

} // namespace wavelit::render
