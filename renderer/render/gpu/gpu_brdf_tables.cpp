#include "render/gpu/gpu_brdf_tables.h"

#include <string>

namespace wavelit::render {

util::Result<GpuBrdfTables> packGpuBrdfTables(const scene::Scene& scene) {
    GpuBrdfTables t;
    // Offset 0: a 1 x 1 x 1 table of zeros for a material whose file is not loaded (yet): f = 0,
    // as the C++ plugin without a table.
    t.floats = {1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    t.offsetOf[nullptr] = 0;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        const plugins::BrdfTable* table = m.brdfTable.get();
        if (!table || t.offsetOf.count(table))
            continue;
        const size_t offset = t.floats.size();
        if (offset >= kMaxGpuBrdfTableOffset)
            return util::makeError(util::ErrorKind::Unsupported, table->file,
                                   "material '" + m.name +
                                       "': too many BRDF tables for the Vulkan tracer (this one "
                                       "would start at float " + std::to_string(offset) +
                                       ", past 2^24); use fewer or smaller tables, or --device cpu",
                                   "/materials/" + std::to_string(i) + "/brdfFile");
        t.offsetOf[table] = uint32_t(offset);
        t.floats.push_back(float(table->thetaHalfBins));
        t.floats.push_back(float(table->thetaDiffBins));
        t.floats.push_back(float(table->phiDiffBins));
        t.floats.push_back(0.0f);
        t.floats.insert(t.floats.end(), table->f.begin(), table->f.end());
        while (t.floats.size() % 4 != 0)
            t.floats.push_back(0.0f);
    }
    return t;
}

} // namespace wavelit::render
