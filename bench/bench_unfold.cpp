// Micro-benchmarks: building the incremental state, one search from the minimum-perimeter tree, and
// one GA run, on the bundled example meshes with fixed seeds.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/genetic.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/search.hpp"

using namespace foldkit::unfold;

namespace {

const Mesh& example(const std::string& name) {
  static std::map<std::string, Mesh> cache;
  auto it = cache.find(name);
  if (it == cache.end())
    it = cache.emplace(name, load_mesh(std::string(FOLDKIT_SOURCE_DIR) + "/examples/" + name).mesh).first;
  return it->second;
}

const char* kMeshes[] = {"spot_350.obj", "fish_350.obj", "bob_350.obj", "penguin_500.obj"};

void BM_CutTreeFromMst(benchmark::State& state) {
  const Mesh& mesh = example(kMeshes[state.range(0)]);
  const UnfoldContext ctx = make_context(mesh);
  const EdgeStates fold = spanning_forest(mesh, ctx.weight);
  for (auto _ : state) {
    CutTree tree(ctx, fold);
    benchmark::DoNotOptimize(tree.overlap_count());
  }
  state.SetLabel(kMeshes[state.range(0)]);
}
BENCHMARK(BM_CutTreeFromMst)->DenseRange(0, 3);

void BM_SearchToOnePiece(benchmark::State& state) {
  const Mesh& mesh = example(kMeshes[state.range(0)]);
  const UnfoldContext ctx = make_context(mesh);
  const EdgeStates fold = spanning_forest(mesh, ctx.weight);
  SearchOptions opt;
  for (auto _ : state) {
    SearchResult r = search_unfold(ctx, fold, opt);
    benchmark::DoNotOptimize(r.solved);
  }
  state.SetLabel(kMeshes[state.range(0)]);
}
BENCHMARK(BM_SearchToOnePiece)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_GaToOnePiece(benchmark::State& state) {
  const Mesh& mesh = example(kMeshes[state.range(0)]);
  const UnfoldContext ctx = make_context(mesh);
  GaOptions opt;
  opt.threads = 1;
  for (auto _ : state) {
    GaResult r = genetic_unfold(ctx, opt);
    benchmark::DoNotOptimize(r.pieces);
  }
  state.SetLabel(kMeshes[state.range(0)]);
}
BENCHMARK(BM_GaToOnePiece)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
