// RelightPreview's translation drag through a shadow field (relight_preview.h enableShadowField,
// docs/relighting.md §7.0e): per point, the dragged object's occlusion looked up in its field at
// the point's offset from the object and combined with the point's drag cache (drag_cache.h).
#include "relight/relight_preview.h"

#include "relight/camera_lights.h"
#include "relight/edit_rules.h"
#include "util/parallel_for.h"
#include "util/timer.h"
#include "wavelet/haar.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace wavelit::relight {
namespace {

// A worker's clock for the hit-changed points' time. Not the thread's CPU clock: that one is a
// system call (no vDSO), and two per point were 3% of a drag step; the workers own their cores
// during a drag, so their wall time is their CPU time.
int64_t workerNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool occludedBy(const PointState& s, size_t object) {
    for (const Occlusion& o : s.occlusions)
        if (o.object == object) return true;
    return false;
}

// FieldDrag::approximate: 1, the terms from the field (O_j and T stale); kCarriedState, a point
// of the moved object with its visibility carried from the drag start (carriedVisibilityState).
constexpr uint8_t kCarriedState = 2;

int64_t cellKey(const glm::vec3& offset, float cell, int dx = 0, int dy = 0, int dz = 0) {
    const int64_t x = int64_t(std::floor(offset.x / cell)) + dx, y = int64_t(std::floor(offset.y / cell)) + dy,
                  z = int64_t(std::floor(offset.z / cell)) + dz;
    return (x & 0x1fffff) | ((y & 0x1fffff) << 21) | ((z & 0x1fffff) << 42);
}

} // namespace

int64_t RelightPreview::FieldDrag::nearestOwn(const glm::vec3& offset, const glm::vec3& normal) const {
    int64_t best = -1;
    float bestDistance = 2.0f * cell * cell; // within about one cell
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                auto it = ownGrid.find(cellKey(offset, cell, dx, dy, dz));
                if (it == ownGrid.end()) continue;
                for (uint32_t k : it->second) {
                    const glm::vec3 d = ownOffset[k] - offset;
                    const float d2 = glm::dot(d, d);
                    if (d2 < bestDistance && glm::dot(ownNormal[k], normal) > 0.9f) {
                        bestDistance = d2;
                        best = int64_t(k);
                    }
                }
            }
    return best;
}

ShadowFieldInfo RelightPreview::enableShadowField(size_t object, const ShadowFieldSettings& settings) {
    if (m_field) settleFieldDrag(true);
    PreparedShadowField prepared = prepareShadowField(object, settings);
    const ShadowFieldInfo info = prepared.info;
    installShadowField(std::move(prepared));
    return info;
}

RelightPreview::PreparedShadowField RelightPreview::prepareShadowField(size_t object,
                                                                       const ShadowFieldSettings& settings,
                                                                       const std::atomic<bool>* cancel,
                                                                       std::shared_ptr<const ShadowField> reuse) const {
    PreparedShadowField prepared;
    if (object >= m_occluders.size() || fieldApproximate()) return prepared;
    auto drag = std::make_unique<FieldDrag>();
    drag->object = object;
    ShadowFieldInfo& info = prepared.info;
    util::Timer timer;
    if (reuse && reuse->settings() == settings && reuse->maskTexels() == m_dirs.count())
        drag->field = std::move(reuse);
    else if (m_field && m_field->object == object && m_field->field->settings() == settings)
        drag->field = m_field->field; // world-axis masks about the object's centre: still valid
    else
        drag->field = std::make_shared<const ShadowField>(
            ShadowField::build(m_occluders[object], m_dirs, settings, m_settings.threads, cancel));
    auto cancelled = [&] { return cancel && cancel->load(); };
    if (cancelled()) return prepared;
    info.fieldMs = timer.milliseconds();
    info.fieldBytes = drag->field->bytes();
    drag->approximate.assign(m_points.size(), 0);
    timer.restart();
    buildDragCaches(*drag, cancel);
    if (cancelled()) return prepared;
    info.cacheMs = timer.milliseconds();
    for (const PointDragCache& c : drag->caches)
        if (c.valid) {
            ++info.cachedPoints;
            info.cacheBytes += c.bytes();
        }
    prepared.drag = std::move(drag);
    prepared.revision = m_revision;
    return prepared;
}

bool RelightPreview::installShadowField(PreparedShadowField&& prepared) {
    if (!prepared.drag || prepared.revision != m_revision || fieldApproximate()) return false;
    m_field = std::move(prepared.drag);
    return true;
}

bool RelightPreview::fieldDragReady(size_t object) const {
    return m_field && m_field->object == object && m_field->cachesValid;
}

bool RelightPreview::fieldApproximate() const {
    return m_field && std::any_of(m_field->approximate.begin(), m_field->approximate.end(),
                                  [](uint8_t a) { return a != 0; });
}

size_t RelightPreview::approximatePoints() const {
    return m_field ? size_t(std::count_if(m_field->approximate.begin(), m_field->approximate.end(),
                                          [](uint8_t a) { return a != 0; }))
                   : 0;
}

const std::vector<glm::vec3>& RelightPreview::fieldEnvTexels() const {
    static const std::vector<glm::vec3> none;
    return m_field ? m_field->envTexels : none;
}

bool RelightPreview::isFieldDrag(const scene::Scene& edited, const scene::ChangeSet& changes) const {
    if (!m_field || edited.objects.size() != m_scene->objects.size()) return false;
    const std::optional<scene::EntityId> moved = onlyTranslatedObject(changes);
    return moved && *moved == m_scene->objects[m_field->object].id;
}

void RelightPreview::buildDragCaches(FieldDrag& f, const std::atomic<bool>* cancel) const {
    scene::Scene without = *m_scene;
    without.objects.erase(without.objects.begin() + std::ptrdiff_t(f.object));
    f.bvhWithout = scene::buildBvh(without);
    f.envTexels.assign(m_dirs.count(), glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) {
        const wavelet::SquareGrid grid =
            wavelet::inverseHaar(wavelet::HaarImage{m_settings.level, m_environment.coefficients[size_t(c)]});
        for (size_t t = 0; t < f.envTexels.size(); ++t)
            f.envTexels[t][c] = float(grid.values[t] * m_dirs.texelSolidAngle());
    }
    const TransferContext ctx = context();
    TransferContext ctxWithout = ctx;
    ctxWithout.sceneBvh = &f.bvhWithout;
    f.caches.assign(m_points.size(), PointDragCache{});
    // The object's own points (their self-visibility, for the points the drag brings into view).
    const ObjectOccluder& own = m_occluders[f.object];
    f.centre = own.bounds.centre;
    f.ownOffset.clear();
    f.ownNormal.clear();
    f.ownSelf.clear();
    f.ownOcclusions.clear();
    f.ownGrid.clear();
    const bool convex = own.convexFront && own.convexBack;
    const bool reuse = f.field->settings().reuseOwnStates;
    if (!convex || reuse) {
        for (size_t i = 0; i < m_points.size(); ++i) {
            const PreviewPoint& p = m_points[i];
            if (!p.hit || p.object != f.object) continue;
            if (!convex) {
                TexelBits self = m_states[i].above;
                for (size_t w = 0; w < self.size(); ++w) self[w] &= ~m_states[i].lit[w];
                f.ownSelf.push_back(std::move(self));
            }
            if (reuse) f.ownOcclusions.push_back(m_states[i].occlusions);
            f.ownOffset.push_back(rayOrigin(p) - f.centre);
            f.ownNormal.push_back(p.geometric);
        }
        // Cells of ~2 point spacings: the points cover the visible surface about evenly.
        f.cell = std::max(1e-4f, 4.0f * own.bounds.radius / std::sqrt(float(std::max<size_t>(f.ownOffset.size(), 1))));
        for (uint32_t k = 0; k < f.ownOffset.size(); ++k) f.ownGrid[cellKey(f.ownOffset[k], f.cell)].push_back(k);
    }
    util::parallelFor(m_points.size(), m_settings.threads, [&](size_t i) {
        const PreviewPoint& p = m_points[i];
        if (!p.hit || p.object == f.object || (cancel && cancel->load(std::memory_order_relaxed))) return;
        PointState without = m_states[i];
        if (occludedBy(without, f.object)) { // T' differs from T: its coefficients and 4 pi <T'_K, L>
            std::erase_if(without.occlusions, [&](const Occlusion& o) { return o.object == f.object; });
            rebuildTransfer(ctx, p, without);
            updateEnvironmentTerms(ctx, without);
        }
        f.caches[i] = buildDragCache(ctxWithout, p, without);
    });
    f.cachesValid = true;
}

void RelightPreview::settleFieldDrag(bool dropField) {
    FieldDrag& f = *m_field;
    const TransferContext ctx = context();
    util::parallelFor(m_points.size(), m_settings.threads, [&](size_t i) {
        if (!f.approximate[i]) return;
        if (f.approximate[i] == kCarriedState) {
            m_states[i] = buildPointState(ctx, m_points[i]);
        } else {
            updateOcclusion(ctx, m_points[i], m_states[i], uint32_t(f.object));
            updateTransferAndTerms(ctx, m_points[i], m_states[i]);
        }
        f.approximate[i] = 0;
    });
    f.caches.clear();
    f.caches.shrink_to_fit();
    f.cachesValid = false;
    if (dropField) m_field.reset();
}

EditSummary RelightPreview::applyFieldDrag(const scene::Scene& edited) {
    FieldDrag& f = *m_field;
    const size_t j = f.object;
    EditSummary summary;
    summary.kind = "object";
    summary.method = "shadowField";
    util::Timer timer;
    if (!f.cachesValid) { // from the state before this edit: the object's own points where it was
        buildDragCaches(f);
        summary.cacheMs = timer.milliseconds();
    }
    const BoundingSphere oldBounds = m_occluders[j].bounds;
    m_scene = std::make_unique<scene::Scene>(edited);
    resolveMaterials();
    m_occluders[j] = buildObjectOccluder(*m_scene, j, m_convexity);
    summary.factorsRebuilt = {"occlusion:" + m_scene->objects[j].name + " (shadow field)", "gbuffer"};
    m_bvh = scene::buildBvh(*m_scene);
    const BoundingSphere sphere = m_occluders[j].bounds;
    const std::vector<PreviewPoint> cast = recastNear({oldBounds, sphere});
    summary.sharedMs = timer.milliseconds();
    timer.restart();

    const TransferContext ctx = context();
    TransferContext ctxWithout = ctx;
    ctxWithout.sceneBvh = &f.bvhWithout;
    const CameraRays rays(m_scene->camera, m_settings.width, m_settings.height);
    const bool nearest = !f.field->settings().interpolate;
    const bool ownConvex = m_occluders[j].convexFront && m_occluders[j].convexBack;
    const bool reuseOwn = f.field->settings().reuseOwnStates;
    const float lobeCut = f.field->settings().carriedLobeCut;
    std::atomic<int64_t> rebuiltNs{0}; // time of the rebuilt points (hit changed, or own)
    std::vector<uint8_t> touched(m_points.size(), 0), rebuilt(m_points.size(), 0), fallback(m_points.size(), 0),
        reused(m_points.size(), 0), carried(m_points.size(), 0);
    util::parallelFor(m_points.size(), m_settings.threads, [&](size_t i) {
        PreviewPoint& p = m_points[i];
        PointState& s = m_states[i];
        PointDragCache& cache = f.caches[i];
        // A point of a non-convex moved object whose camera hit stayed put (a face parallel to
        // the drag) still moved against the rest of its object: its self-visibility changed.
        const bool hitChanged = !(cast[i] == p) || (p.hit && p.object == j && !ownConvex);
        if (hitChanged) {
            const int64_t start = workerNs();
            struct Charge { // the hit-changed branch's time, on every way out of it
                std::atomic<int64_t>& sum;
                int64_t start;
                ~Charge() { sum += workerNs() - start; }
            } charge{rebuiltNs, start};
            p = cast[i];
            touched[i] = 1;
            for (size_t k = 0; k < m_cameraLights.size(); ++k) updateCameraLight(k, i, rays);
            cache = PointDragCache{};
            f.approximate[i] = 0;
            if (!p.hit) {
                s = PointState{};
                m_background[i] = environmentRadiance(m_scene->lighting.environment, -p.wo);
                return;
            }
            if (p.object == j) { // the object's own surface: its factors, self-visibility cached
                // Its offset from the object's centre now, as the cached points' from the centre then.
                const glm::vec3 offset = rayOrigin(p) - sphere.centre;
                const int64_t k = f.ownGrid.empty() ? -1 : f.nearestOwn(offset, p.geometric);
                const TexelBits* self = k >= 0 && !ownConvex ? &f.ownSelf[size_t(k)] : nullptr;
                if (k >= 0 && reuseOwn) { // no rays, no T: the nearest point's visibility carried
                    s = carriedVisibilityState(ctx, p, self, f.ownOcclusions[size_t(k)], f.envTexels,
                                               LobeAverage::Full, lobeCut);
                    f.approximate[i] = kCarriedState;
                    carried[i] = 1;
                } else {
                    s = buildPointState(ctx, p, UINT32_MAX, self);
                    rebuilt[i] = 1;
                }
                reused[i] = self ? 1 : 0;
                return;
            }
            // A surface the object uncovered: its visibility without the object and the cache
            // from it (no T: the terms come from the cache, and the settle rebuilds it), then the
            // field.
            s = visibilityState(ctx, p, uint32_t(j));
            cache = buildDragCache(ctxWithout, p, s, &f.envTexels);
            rebuilt[i] = 1;
        } else if (!p.hit || !cache.valid) {
            return;
        }
        const glm::vec3 origin = rayOrigin(p);
        // The interpolated field: the union of the blended samples' masks, and per texel of it
        // the blended occlusion (thread-local, dense, written only on the union's texels).
        thread_local std::vector<float> weight;
        thread_local TexelBits unionBits;
        const float* weights = nullptr;
        const uint64_t* mask = nullptr;
        ShadowField::Blend blend;
        if (!nearest && f.field->blend(origin - sphere.centre, blend)) {
            weight.resize(m_dirs.count());
            unionBits.assign(cache.visible.size(), 0);
            for (size_t w = 0; w < unionBits.size(); ++w) {
                uint64_t any = 0;
                for (int k = 0; k < blend.count; ++k) any |= blend.masks[k][w];
                unionBits[w] = any; // not only visible': a light's shadow-ray entries read it too
                float* at = &weight[w * 64];
                for (uint64_t bits = any; bits; bits &= bits - 1) at[__builtin_ctzll(bits)] = 0.0f;
                // Sample by sample, so each texel's sum takes the samples in order (as summing
                // per texel would) while the texels' additions overlap.
                for (int k = 0; k < blend.count; ++k) {
                    const float wk = blend.weights[k];
                    for (uint64_t bits = blend.masks[k][w]; bits; bits &= bits - 1) at[__builtin_ctzll(bits)] += wk;
                }
                for (uint64_t bits = any; bits; bits &= bits - 1) {
                    float& v = at[__builtin_ctzll(bits)];
                    v = std::min(v, 1.0f);
                }
            }
            mask = unionBits.data();
            weights = weight.data();
        } else if (nearest) {
            mask = f.field->lookup(origin - sphere.centre);
        }
        TexelBits cast_;
        if (!mask) { // beyond the outer shell: j covers a few texels, ray-cast them
            fallback[i] = 1;
            cast_ = coneTexels(sphere, origin, m_dirs, cache.visible);
            if (anyBit(cast_)) cast_ = castOcclusion(m_occluders[j], origin, m_dirs, cast_);
            mask = cast_.data();
        }
        bool blocks = false;
        for (size_t w = 0; w < cache.visible.size() && !blocks; ++w) blocks = (mask[w] & cache.visible[w]) != 0;
        // Nothing of j in view now, nor in the terms the point holds: unchanged.
        if (!blocks && !hitChanged && !f.approximate[i] && !occludedBy(s, j)) return;
        applyDragMask(cache, mask, sphere, origin, f.envTexels, s, nullptr, mask == cast_.data() ? nullptr : weights);
        f.approximate[i] = 1;
        touched[i] = 1;
    });
    summary.pointsTouched = size_t(std::count(touched.begin(), touched.end(), uint8_t(1)));
    summary.pointsRebuilt = size_t(std::count(rebuilt.begin(), rebuilt.end(), uint8_t(1)));
    summary.fieldFallbacks = size_t(std::count(fallback.begin(), fallback.end(), uint8_t(1)));
    summary.selfMasksReused = size_t(std::count(reused.begin(), reused.end(), uint8_t(1)));
    summary.statesCarried = size_t(std::count(carried.begin(), carried.end(), uint8_t(1)));
    summary.rebuiltCpuMs = double(rebuiltNs.load()) * 1e-6;
    summary.pointsMs = timer.milliseconds();
    m_touched = std::move(touched);
    return summary;
}

} // namespace wavelit::relight
