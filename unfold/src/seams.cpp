#include "foldkit/unfold/seams.hpp"

#include <algorithm>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>

#include "foldkit/error.hpp"
#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::unfold {
namespace {

// Every edge of a mesh at the face limit, one per line with a comment, fits many times over.
constexpr std::uintmax_t kMaxEdgeListBytes = std::uintmax_t{64} << 20;

std::string edge_name(const std::array<int, 2>& v) {
  return std::to_string(v[0]) + "-" + std::to_string(v[1]);
}

}  // namespace

std::string SeamError::message(Problem problem, const std::string& edge, const std::string& mesh_name,
                               const SeamListNames& names) {
  switch (problem) {
    case Problem::NotAnEdgeToCut:
      return names.cut + ": " + edge + " is not an edge of " + mesh_name;
    case Problem::NotAnEdgeToKeep:
      return names.keep + ": " + edge + " is not an edge of " + mesh_name;
    case Problem::CutAndKept:
      return "edge " + edge + " is both in " + names.cut + " and in " + names.keep;
    case Problem::KeptOnBoundary:
      return names.keep + ": " + edge + " lies on the mesh boundary and cannot be folded";
    case Problem::KeptLoop:
      return names.keep + ": edge " + edge + " closes a loop of kept edges, which cannot lie flat";
  }
  return edge;
}

std::vector<FileEdge> read_edge_list(const std::filesystem::path& path, int index_base) {
  // The same checks as a mesh file: `--cut /dev/zero` or a FIFO would otherwise be read for ever.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(path.string(), "no such file");
  if (!std::filesystem::is_regular_file(status)) throw InputError(path.string(), "not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path.string(), "cannot read the file size");
  if (size > kMaxEdgeListBytes)
    throw InputError(path.string(), "file is " + std::to_string(size) + " bytes, over the limit of " +
                                        std::to_string(kMaxEdgeListBytes) + " bytes for an edge list");
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "cannot open the edge list");
  std::vector<FileEdge> edges;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    long long a = 0, b = 0;
    std::string rest;
    if (!(fields >> a)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      throw InputError(path.string(), "line " + std::to_string(number) + ": expected two vertex indices");
    }
    if (!(fields >> b) || (fields >> rest))
      throw InputError(path.string(), "line " + std::to_string(number) + ": expected two vertex indices");
    if (a < index_base || b < index_base || a > 2'000'000'000 || b > 2'000'000'000)
      throw InputError(path.string(), "line " + std::to_string(number) +
                                          ": vertex number out of range (the "
                                          "file's vertices are numbered from " +
                                          std::to_string(index_base) + ")");
    edges.push_back({{static_cast<int>(a - index_base), static_cast<int>(b - index_base)}, number});
  }
  if (in.bad()) throw InputError(path.string(), "read error");
  return edges;
}

std::vector<std::array<int, 2>> to_mesh_edges(const LoadedMesh& loaded, const std::vector<FileEdge>& edges,
                                              const std::string& list_file, int index_base) {
  if (edges.empty()) return {};
  const VertexOrigin& origin = loaded.origin;
  const Mesh& mesh = loaded.mesh;
  if (origin.file_vertex.empty())
    throw Error(list_file + ": seams name the file's vertices, and decimation keeps none of them",
                ExitCode::Usage);
  // Mesh edges by the (merged) file vertices of their ends.
  std::vector<std::pair<std::array<int, 2>, int>> by_file;
  by_file.reserve(mesh.edges.size());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const int a = origin.file_vertex[mesh.edges[e].v[0]], b = origin.file_vertex[mesh.edges[e].v[1]];
    by_file.push_back({{std::min(a, b), std::max(a, b)}, e});
  }
  std::sort(by_file.begin(), by_file.end());
  const int file_vertices = static_cast<int>(origin.merged_into.size());
  std::vector<std::array<int, 2>> out;
  for (const FileEdge& edge : edges) {
    const std::string where = "line " + std::to_string(edge.line) + ": " +
                              std::to_string(edge.v[0] + index_base) + "-" +
                              std::to_string(edge.v[1] + index_base);
    const auto refuse = [&](const std::string& why) { return InputError(list_file, where + " " + why); };
    if (std::max(edge.v[0], edge.v[1]) >= file_vertices)
      throw refuse("names a vertex past the last of " + loaded.mesh.name + " (" +
                   std::to_string(file_vertices) + " vertices)");
    const std::array<int, 2> named{std::min(edge.v[0], edge.v[1]), std::max(edge.v[0], edge.v[1])};
    if (!std::binary_search(origin.file_edges.begin(), origin.file_edges.end(), named))
      throw refuse("is not an edge of " + loaded.mesh.name);
    const int a = origin.merged_into[named[0]], b = origin.merged_into[named[1]];
    const std::array<int, 2> merged{std::min(a, b), std::max(a, b)};
    auto it = std::lower_bound(by_file.begin(), by_file.end(), std::pair{merged, -1});
    if (a == b || it == by_file.end() || it->first != merged)
      throw refuse("is an edge of " + loaded.mesh.name + " that the loader removed with a zero-area face");
    for (; it != by_file.end() && it->first == merged; ++it)
      out.push_back(mesh.edges[it->second].v);
  }
  return out;
}

EdgeConstraints resolve_seams(const Mesh& mesh, const SeamConstraints& seams) {
  EdgeConstraints result;
  if (seams.force_cut.empty() && seams.forbid_cut.empty()) return result;
  std::unordered_map<long long, int> edge_of;
  edge_of.reserve(mesh.edges.size() * 2);
  auto key = [&](int a, int b) {
    return static_cast<long long>(std::min(a, b)) * mesh.num_vertices() + std::max(a, b);
  };
  for (int e = 0; e < mesh.num_edges(); ++e)
    edge_of[key(mesh.edges[e].v[0], mesh.edges[e].v[1])] = e;
  using Problem = SeamError::Problem;
  auto lookup = [&](const std::array<int, 2>& v, Problem not_an_edge) {
    auto it = v[0] < mesh.num_vertices() && v[1] < mesh.num_vertices() ? edge_of.find(key(v[0], v[1]))
                                                                       : edge_of.end();
    if (it == edge_of.end()) throw SeamError(not_an_edge, edge_name(v), mesh.name);
    return EdgeId(it->second);
  };
  result.rule.assign(mesh.num_edges(), EdgeRule::Free);
  for (const auto& v : seams.force_cut)
    result.rule[lookup(v, Problem::NotAnEdgeToCut)] = EdgeRule::MustCut;
  DisjointSets kept(mesh.num_faces());
  for (const auto& v : seams.forbid_cut) {
    const EdgeId e = lookup(v, Problem::NotAnEdgeToKeep);
    if (result.rule[e] == EdgeRule::MustCut) throw SeamError(Problem::CutAndKept, edge_name(v), mesh.name);
    if (mesh.edge(e).boundary()) throw SeamError(Problem::KeptOnBoundary, edge_name(v), mesh.name);
    if (result.rule[e] == EdgeRule::MustFold) continue;
    if (!kept.join(mesh.edge(e).face[0], mesh.edge(e).face[1]))
      throw SeamError(Problem::KeptLoop, edge_name(v), mesh.name);
    result.rule[e] = EdgeRule::MustFold;
  }
  return result;
}

}  // namespace foldkit::unfold
