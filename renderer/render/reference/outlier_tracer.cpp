#include "render/reference/outlier_tracer.h"

#include "render/reference/cpu_path_tracer.h"
#include "scene/bvh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace wavelit::render {
namespace {

bool heapLess(const OutlierSample& a, const OutlierSample& b) { return a.ratio > b.ratio; }

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out;
}

std::string num(double v) {
    if (!std::isfinite(v)) return v > 0 ? "1e308" : (v < 0 ? "-1e308" : "null");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string vec(const glm::vec3& v) {
    // Appended piece by piece: GCC 12's -Wrestrict misfires on `"[" + std::string` chains.
    std::string out = "[";
    out += num(v.x);
    out += ", ";
    out += num(v.y);
    out += ", ";
    out += num(v.z);
    out += "]";
    return out;
}

std::string pdfs(const std::vector<PathPdf>& p) {
    std::string out = "{";
    for (size_t i = 0; i < p.size(); ++i)
        out += (i ? ", \"" : "\"") + escape(p[i].name) + "\": " + num(p[i].value);
    return out + "}";
}

} // namespace

OutlierMonitor::OutlierMonitor(int width, int height, int count)
    : m_width(width), m_height(height), m_count(std::max(0, count)),
      m_sum(size_t(width) * size_t(height), glm::dvec3(0.0)) {}

void OutlierMonitor::addPass(const util::ImageRGB& mean) {
    const int pass = m_passes++;
    // The image's mean luminance / (pass + 1) floors the pixel means: a running mean of a few
    // samples says little (a first sample in a black pixel is not infinitely far out), and a
    // genuinely dark pixel ranks by its own mean once it has had enough samples.
    double imageMean = 0.0;
    for (const glm::vec3& p : mean.pixels) imageMean += util::luminance(p);
    imageMean /= double(std::max<size_t>(1, mean.pixels.size()));
    const double floor = std::max(imageMean / double(pass + 1), 1e-12);
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x) {
            const size_t i = size_t(y) * size_t(m_width) + size_t(x);
            const glm::dvec3 total = glm::dvec3(mean.pixels[i]) * double(pass + 1);
            const glm::vec3 value = glm::vec3(total - m_sum[i]);
            const double before =
                pass > 0 ? double(util::luminance(glm::vec3(m_sum[i] / double(pass)))) : 0.0;
            m_sum[i] = total;
            if (m_count == 0) continue;
            OutlierSample s{x, y, pass, value, before,
                            double(util::luminance(value)) / std::max(before, floor)};
            if (int(m_heap.size()) < m_count) {
                m_heap.push_back(s);
                std::push_heap(m_heap.begin(), m_heap.end(), heapLess);
            } else if (s.ratio > m_heap.front().ratio) {
                std::pop_heap(m_heap.begin(), m_heap.end(), heapLess);
                m_heap.back() = s;
                std::push_heap(m_heap.begin(), m_heap.end(), heapLess);
            }
        }
}

std::vector<OutlierSample> OutlierMonitor::outliers() const {
    std::vector<OutlierSample> out = m_heap;
    std::sort(out.begin(), out.end(),
              [](const OutlierSample& a, const OutlierSample& b) { return a.ratio > b.ratio; });
    return out;
}

util::Result<std::vector<PathRecord>> traceOutlierPaths(const scene::Scene& scene,
                                                        const RenderOptions& options,
                                                        const std::vector<OutlierSample>& outliers) {
    auto s = std::make_shared<const scene::Scene>(scene);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*s));
    RenderOptions o = options;
    o.device = DeviceChoice::Cpu;
    auto tracer = CpuPathTracer::create(s, bvh, o, 1);
    if (!tracer) return tracer.error();
    std::vector<PathRecord> paths;
    for (const OutlierSample& out : outliers) {
        PathRecord r;
        (*tracer)->samplePixel(out.x, out.y, out.pass, &r);
        paths.push_back(std::move(r));
    }
    return paths;
}

std::string outliersJson(const RenderOptions& options, const std::string& deviceName, int passes,
                         const std::vector<OutlierSample>& outliers,
                         const std::vector<PathRecord>& paths, const util::ImageRGB& finalImage) {
    std::ostringstream j;
    j << "{\n  \"format\": \"wavelit-outliers\",\n  \"version\": 1,\n"
      << "  \"sampler\": \"" << samplerKindName(options.sampler) << "\",\n"
      << "  \"device\": \"" << escape(deviceName) << "\",\n"
      << "  \"retracedOn\": \"CPU reference tracer, same random stream\",\n"
      << "  \"passes\": " << passes << ",\n  \"outliers\": [";
    for (size_t k = 0; k < outliers.size(); ++k) {
        const OutlierSample& o = outliers[k];
        const size_t pi = size_t(o.y) * size_t(finalImage.width) + size_t(o.x);
        const glm::vec3 finalMean =
            pi < finalImage.pixels.size() ? finalImage.pixels[pi] : glm::vec3(0.0f);
        j << (k ? ",\n" : "\n") << "    {\"rank\": " << k << ", \"pixel\": [" << o.x << ", " << o.y
          << "], \"pass\": " << o.pass << ", \"sampler\": \"" << samplerKindName(options.sampler)
          << "\", \"sample\": " << vec(o.value) << ", \"ratio\": " << num(o.ratio)
          << ", \"pixelMeanBefore\": " << num(o.pixelMean)
          << ", \"finalPixelMean\": " << vec(finalMean);
        if (k < paths.size()) {
            const PathRecord& p = paths[k];
            j << ", \"retraced\": " << vec(p.value) << ",\n      \"vertices\": [";
            for (size_t v = 0; v < p.vertices.size(); ++v) {
                const PathVertex& x = p.vertices[v];
                j << (v ? ",\n" : "\n") << "        {\"index\": " << v << ", \"depth\": " << x.depth
                  << ", \"material\": \"" << escape(x.material) << "\", \"position\": "
                  << vec(x.position) << ", \"throughputIn\": " << vec(x.throughputIn)
                  << ", \"technique\": \"" << escape(x.technique) << "\", \"pdf\": " << num(x.pdf)
                  << ", \"pdfs\": " << pdfs(x.pdfs) << ", \"fcos\": " << vec(x.fcos)
                  << ", \"continueProbability\": " << num(x.continueProbability)
                  << ", \"throughputOut\": " << vec(x.throughputOut) << ", \"end\": \""
                  << escape(x.end) << "\"}";
            }
            j << "\n      ],\n      \"events\": [";
            for (size_t e = 0; e < p.events.size(); ++e) {
                const PathEvent& x = p.events[e];
                j << (e ? ",\n" : "\n") << "        {\"vertex\": " << x.vertex << ", \"kind\": \""
                  << escape(x.kind) << "\", \"technique\": \"" << escape(x.technique)
                  << "\", \"pdf\": " << num(x.pdf) << ", \"misPdfs\": " << pdfs(x.misPdfs)
                  << ", \"weight\": " << num(x.weight) << ", \"fcos\": " << vec(x.fcos)
                  << ", \"radiance\": " << vec(x.radiance) << ", \"throughput\": "
                  << vec(x.throughput) << ", \"contribution\": " << vec(x.contribution) << "}";
            }
            j << "\n      ]";
        }
        j << "}";
    }
    j << "\n  ]\n}\n";
    return j.str();
}

} // namespace wavelit::render
