// GpuPathTracer's measured BRDF tables (gpu_brdf_tables.h): one storage buffer, rewritten when
// the materials change (a new brdfFile is a material edit), recreated when its size changes.
#include "render/gpu/gpu_path_tracer_impl.h"

#include <algorithm>

namespace wavelit::render::gpu_tracer {

util::Status GpuPathTracer::uploadBrdfTables(const std::vector<float>& tables) {
    const size_t bytes = tables.size() * sizeof(float);
    if (m_brdfTables.handle() == VK_NULL_HANDLE || m_brdfTables.size() != std::max<size_t>(bytes, 16)) {
        auto b = upload(nullptr, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "BRDF tables");
        if (!b) return b.error();
        m_brdfTables = std::move(b.value());
        bindAll(m_brdfTableBinding, m_brdfTables);
    }
    m_brdfTables.write(tables.data(), bytes);
    return util::okStatus();
}

} // namespace wavelit::render::gpu_tracer
