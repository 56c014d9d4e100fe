#pragma once
// Seams chosen by the user (the seed's interface for seams): edges that must be cut (`--cut FILE`)
// or must stay folded (`--keep FILE`), named by the numbers the mesh file gives their two ends.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "foldkit/error.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"

namespace foldkit::unfold {

/// Reads an edge list: one edge per line as two vertex numbers of the mesh file, counted from
/// `index_base` (1: OBJ as written, 0: OFF and PLY as written) ("12 40", commas allowed), blank lines and
/// '#' comments ignored. Returns them 0-based with their line numbers. Throws InputError(file, "line N:
/// ...") for a malformed line, and for a file that is not a regular file or is over 64 MiB.
std::vector<FileEdge> read_edge_list(const std::filesystem::path& path, int index_base);

/// The mesh's vertex pairs for edges named by the file's vertex numbers (an edge list, or the file's own
/// OBJ `l` elements), through the loader's welding and repair; an edge of the file split by a pinched
/// vertex gives each of its copies. Throws InputError(list_file, "line N: a-b ...") naming the pair in
/// the list's numbering (`index_base`) when it is not an edge of the file's polygons or the repair
/// removed it, and Error (usage) when the mesh was decimated (no vertex of the file is left).
std::vector<std::array<int, 2>> to_mesh_edges(const LoadedMesh& loaded, const std::vector<FileEdge>& edges,
                                              const std::string& list_file, int index_base);

/// How messages name the two seam lists (the CLI names them by its options).
struct SeamListNames {
  std::string cut = "the cut list", keep = "the keep list";
};

/// An impossible seam (a usage error): the problem and the edge, worded with the lists' names.
class SeamError : public Error {
 public:
  enum class Problem {
    NotAnEdgeToCut,   ///< a pair of the cut list is not an edge of the mesh
    NotAnEdgeToKeep,  ///< a pair of the keep list is not an edge of the mesh
    CutAndKept,       ///< an edge in both lists
    KeptOnBoundary,   ///< a kept edge on the mesh boundary (it has no second face to fold onto)
    KeptLoop,         ///< a kept edge closing a loop of kept edges
  };
  SeamError(Problem problem, std::string edge, std::string mesh_name)
      : Error(message(problem, edge, mesh_name, {}), ExitCode::Usage),
        problem_(problem),
        edge_(std::move(edge)),
        mesh_name_(std::move(mesh_name)) {}
  Problem problem() const { return problem_; }
  /// The message with the lists called by `names`.
  std::string message(const SeamListNames& names) const {
    return message(problem_, edge_, mesh_name_, names);
  }

 private:
  static std::string message(Problem problem, const std::string& edge, const std::string& mesh_name,
                             const SeamListNames& names);
  Problem problem_;
  std::string edge_, mesh_name_;
};

/// Turns vertex pairs into per-edge rules. Throws SeamError naming the first pair that is not an edge
/// of the mesh, an edge that is both cut and kept, or kept edges that close a loop of folds (which no
/// flat piece can have).
EdgeConstraints resolve_seams(const Mesh& mesh, const SeamConstraints& seams);

}  // namespace foldkit::unfold
