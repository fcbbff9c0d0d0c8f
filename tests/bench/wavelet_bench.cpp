// Wavelet core timings (issue 4): transforms, dense vs sparse products by coefficient density,
// factor-tree updates vs rebuilds, sampling rate. Reported in docs/wavelet-benchmarks.md; never
// asserted (machines are noisy, architecture.md §8).
#include "wavelet/factor_product_tree.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/product.h"
#include "wavelet/refined_sampler.h"
#include "wavelet/test_support.h"

#include <benchmark/benchmark.h>

namespace wv = wavelit::wavelet;

namespace {

// An environment-like factor (sky gradient + sun + noise) and a BRDF-like one (smooth lobe).
wv::SquareGrid envGrid(int n) {
    wavelit::util::Pcg32 rng(1);
    wv::SquareGrid g = wv::testing::sunSky(n, (1 << n) / 3, (1 << n) / 5, 1e4);
    for (double& v : g.values)
        v += 0.2 * rng.nextDouble();
    return g;
}
wv::SquareGrid brdfGrid(int n) {
    return wv::testing::lobe(n, 0.4 * (1 << n), 0.3 * (1 << n), 0.1 * (1 << n));
}

void BM_ForwardHaar(benchmark::State& state) {
    const wv::SquareGrid g = envGrid(int(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(wv::forwardHaar(g));
    state.SetItemsProcessed(state.iterations() * int64_t(g.values.size()));
}
BENCHMARK(BM_ForwardHaar)->Arg(6)->Arg(7)->Arg(9)->Unit(benchmark::kMicrosecond);

void BM_InverseHaar(benchmark::State& state) {
    const wv::HaarImage h = wv::forwardHaar(envGrid(int(state.range(0))));
    for (auto _ : state)
        benchmark::DoNotOptimize(wv::inverseHaar(h));
    state.SetItemsProcessed(state.iterations() * int64_t(h.coeffs.size()));
}
BENCHMARK(BM_InverseHaar)->Arg(6)->Arg(7)->Arg(9)->Unit(benchmark::kMicrosecond);

// range(0) = n, range(1) = density in per mille.
template <bool Sparse> void BM_Product(benchmark::State& state) {
    const int n = int(state.range(0));
    const double density = double(state.range(1)) / 1000.0;
    const wv::SparseHaar a = wv::testing::truncatedCoefficients(envGrid(n), density),
                         b = wv::testing::truncatedCoefficients(brdfGrid(n), density);
    const wv::SparseHaar* list[] = {&a, &b};
    size_t nodes = 0;
    for (auto _ : state) {
        wv::ScalingTree t = Sparse ? wv::sparseProduct(list) : wv::denseProduct(list);
        nodes = t.nodes.size();
        benchmark::DoNotOptimize(t);
    }
    state.counters["pyramid_nodes"] = double(nodes);
}
void productArgs(benchmark::internal::Benchmark* b) {
    for (int n : {6, 8, 9})
        for (int perMille : {10, 50, 200, 500, 1000})
            b->Args({n, perMille});
    b->Unit(benchmark::kMicrosecond);
}
BENCHMARK_TEMPLATE(BM_Product, false)->Name("BM_ProductDense")->Apply(productArgs);
BENCHMARK_TEMPLATE(BM_Product, true)->Name("BM_ProductSparse")->Apply(productArgs);

std::vector<wv::SparseHaar> treeFactors(int m, int n) {
    std::vector<wv::SparseHaar> f;
    for (int k = 0; k < m; ++k)
        f.push_back(wv::testing::truncatedCoefficients(k % 2 ? brdfGrid(n) : envGrid(n), 0.05));
    return f;
}

void BM_TreeUpdate(benchmark::State& state) {
    const int m = int(state.range(0)), n = 6;
    std::vector<wv::SparseHaar> f = treeFactors(m, n);
    wv::FactorProductTree tree(f);
    size_t products = 0;
    int j = 0;
    for (auto _ : state) {
        tree.replace(size_t(j), f[size_t(j)]);
        products = tree.update();
        j = (j + 1) % m;
    }
    state.counters["products_per_update"] = double(products);
}
BENCHMARK(BM_TreeUpdate)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);

void BM_TreeRebuild(benchmark::State& state) {
    const int m = int(state.range(0)), n = 6;
    const std::vector<wv::SparseHaar> f = treeFactors(m, n);
    for (auto _ : state)
        benchmark::DoNotOptimize(wv::FactorProductTree(f).integral());
    state.counters["products_per_update"] = double(m - 1);
}
BENCHMARK(BM_TreeRebuild)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);

void BM_Sample(benchmark::State& state) {
    const int n = int(state.range(0));
    const wv::SparseHaar a = wv::testing::truncatedCoefficients(envGrid(n), 0.05),
                         b = wv::testing::truncatedCoefficients(brdfGrid(n), 0.05);
    const wv::SparseHaar* list[] = {&a, &b};
    auto sampler = wv::HierarchicalSampler::build(wv::sparseProduct(list));
    wavelit::util::Pcg32 rng(2);
    for (auto _ : state)
        benchmark::DoNotOptimize(sampler->sample({rng.nextDouble(), rng.nextDouble()}));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Sample)->Arg(5)->Arg(6)->Arg(9);

void BM_SampleRefined32x512(benchmark::State& state) {
    const wv::SparseHaar a = wv::testing::truncatedCoefficients(envGrid(5), 0.05),
                         b = wv::testing::truncatedCoefficients(brdfGrid(5), 0.05);
    const wv::SparseHaar* list[] = {&a, &b};
    auto product = wv::HierarchicalSampler::build(wv::sparseProduct(list));
    auto env = wv::HierarchicalSampler::build(wv::ScalingTree::fromGrid(envGrid(9)));
    wv::RefinedSampler refined(*product, *env);
    wavelit::util::Pcg32 rng(3);
    for (auto _ : state)
        benchmark::DoNotOptimize(refined.sample({rng.nextDouble(), rng.nextDouble()}));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SampleRefined32x512);

void BM_BuildSampler(benchmark::State& state) {
    const wv::ScalingTree t = wv::ScalingTree::fromGrid(envGrid(int(state.range(0))));
    for (auto _ : state)
        benchmark::DoNotOptimize(wv::HierarchicalSampler::build(t));
}
BENCHMARK(BM_BuildSampler)->Arg(6)->Arg(9)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
