// `foldkit unfold MESH -o net.obj`: the written net keeps face order, is flat, congruent, unmirrored,
// grouped by piece with no vertex shared between pieces; with a size, its parts pass the independent net
// check (tests/tools/net_check.py), which is shown to catch each kind of fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "cmd_make.hpp"
#include "cmd_unfold.hpp"
#include "foldkit/error.hpp"
#include "foldkit/geom/predicates.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "in_process.hpp"
#include "layout_options.hpp"
#include "test_paths.hpp"

using namespace foldkit;
namespace fs = std::filesystem;

namespace {

struct Net {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;  // 0-based
  std::vector<int> group_of_face;
};

Net read_net(const fs::path& path) {
  Net net;
  std::ifstream in(path);
  std::string line;
  int group = -1;
  std::map<std::string, int> groups;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3 p;
      s >> p.x >> p.y >> p.z;
      net.v.push_back(p);
    } else if (tag == "g") {
      std::string name;
      s >> name;
      group = groups.emplace(name, static_cast<int>(groups.size())).first->second;
    } else if (tag == "f") {
      std::array<int, 3> f{};
      s >> f[0] >> f[1] >> f[2];
      for (int& i : f)
        --i;
      net.f.push_back(f);
      net.group_of_face.push_back(group);
    }
  }
  return net;
}

}  // namespace

TEST(CliUnfold, TheNetKeepsFaceOrderAndIsFlatCongruentAndUnmirrored) {
  const fs::path dir = test::temp_dir("cli_unfold");
  const fs::path mesh_file = test::example_mesh("penguin_500.obj");
  cli::UnfoldArgs args;
  args.mesh = mesh_file.string();
  args.output = (dir / "net.obj").string();
  args.json = true;
  auto summary = nlohmann::json::parse(test::stdout_of([&] { cli::run_unfold(args); }));
  unfold::Mesh mesh = unfold::load_mesh(mesh_file).mesh;
  EXPECT_EQ(summary["face_count"], mesh.num_faces());
  EXPECT_GE(summary["piece_count"].get<int>(), 1);
  EXPECT_GT(summary["cut_edge_count"].get<int>(), 0);
  EXPECT_TRUE(summary.contains("unfold_s"));

  Net net = read_net(dir / "net.obj");
  ASSERT_EQ(net.f.size(), mesh.faces.size());
  std::set<int> groups(net.group_of_face.begin(), net.group_of_face.end());
  EXPECT_EQ(static_cast<int>(groups.size()), summary["piece_count"].get<int>());
  std::vector<int> group_of_vertex(net.v.size(), -1);
  for (std::size_t k = 0; k < net.f.size(); ++k) {
    auto c = mesh.corners(static_cast<int>(k));
    Triangle2 t;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = net.v[net.f[k][i]];
      EXPECT_EQ(p.z, 0.0);
      t[i] = {p.x, p.y};
      int& g = group_of_vertex[net.f[k][i]];
      EXPECT_TRUE(g < 0 || g == net.group_of_face[k]) << "vertex shared between pieces";
      g = net.group_of_face[k];
    }
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(norm(t[(i + 1) % 3] - t[i]), norm(c[(i + 1) % 3] - c[i]),
                  1e-9 * norm(c[(i + 1) % 3] - c[i]));
    EXPECT_GT(signed_area(t), 0) << "face " << k << " mirrored";
  }
  // Corners joined by folds share a vertex: far fewer vertices than three per face.
  EXPECT_LT(net.v.size(), net.f.size() * 2);
}

TEST(CliUnfold, ABadMeshGivesOneLineAndNoOutputFile) {
  const fs::path dir = test::temp_dir("cli_unfold_bad");
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
  auto run = test::run_foldkit({"unfold", (dir / "broken.obj").string(), "-o", (dir / "net.obj").string()});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_FALSE(run.signalled);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(dir / "net.obj"));
}

TEST(CliUnfold, EveryTrickyMeshUnfolds) {
  auto shared = test::shared_meshes();
  if (!shared) GTEST_SKIP() << "../shared/meshes not present";
  for (const auto& entry : fs::directory_iterator(*shared / "tricky")) {
    SCOPED_TRACE(entry.path().string());
    cli::UnfoldArgs args;
    args.mesh = entry.path().string();
    args.json = true;
    args.quiet = true;
    args.unfold.method = "mst";
    const auto j = nlohmann::json::parse(test::stdout_of([&] { cli::run_unfold(args); }));
    const unfold::Mesh mesh = unfold::load_mesh(entry.path()).mesh;
    EXPECT_EQ(j["face_count"].get<int>(), mesh.num_faces());
    EXPECT_EQ(j["method"].get<std::string>(), "mst");
    const int pieces = j["piece_count"].get<int>();
    EXPECT_GE(pieces, unfold::count_components(mesh));
    // Each piece is a tree of faces joined by folds: faces - pieces folds, every other edge is cut, and
    // every cut edge but the mesh boundary is a seam.
    int boundary = 0;
    for (const auto& e : mesh.edges)
      boundary += e.boundary() ? 1 : 0;
    EXPECT_EQ(j["cut_edge_count"].get<int>(), mesh.num_edges() - (mesh.num_faces() - pieces));
    EXPECT_EQ(j["seam_count"].get<int>(), j["cut_edge_count"].get<int>() - boundary);
  }
}

namespace {

// Faces as vertex lists (0-based) of an OBJ file, and its vertices.
struct Polygons {
  std::vector<Vec3> v;
  std::vector<std::vector<int>> f;
};

Polygons read_polygons(const fs::path& path) {
  Polygons out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3 p;
      s >> p.x >> p.y >> p.z;
      out.v.push_back(p);
    } else if (tag == "f") {
      std::vector<int> face;
      for (std::string token; s >> token;)
        face.push_back(std::stoi(token) - 1);
      out.f.push_back(face);
    }
  }
  return out;
}

// Edge lengths around a polygon, starting at its shortest-index rotation that matches `reference`.
std::vector<double> edge_lengths(const Polygons& p, const std::vector<int>& face) {
  std::vector<double> out;
  for (std::size_t i = 0; i < face.size(); ++i)
    out.push_back(norm(p.v[face[(i + 1) % face.size()]] - p.v[face[i]]));
  return out;
}

}  // namespace

TEST(CliUnfold, EachInputPolygonIsOnePolygonOfTheNetInTheFileOrder) {
  const fs::path dir = test::temp_dir("cli_unfold_polygons");
  for (const char* name : {"barn.obj", "l_block.obj", "football.obj", "cylinder12.obj"})
    for (const char* size : {"", "150mm"}) {
      const fs::path mesh_file = test::source_dir() / "tests" / "data" / "lowpoly" / name;
      std::vector<std::string> args = {"unfold", mesh_file.string(), "-o", (dir / "net.obj").string(), "-q"};
      if (*size) args.insert(args.end(), {"--size", size});
      auto run = test::run_foldkit(args);
      ASSERT_EQ(run.exit_code, 0) << run.err;
      const Polygons in = read_polygons(mesh_file), net = read_polygons(dir / "net.obj");
      ASSERT_EQ(net.f.size(), in.f.size()) << name;
      for (std::size_t k = 0; k < in.f.size(); ++k) {
        ASSERT_EQ(net.f[k].size(), in.f[k].size()) << name << " face " << k;
        // The same polygon, maybe starting at another corner: its edge lengths are a rotation of the input's.
        const std::vector<double> a = edge_lengths(in, in.f[k]), b = edge_lengths(net, net.f[k]);
        bool matched = false;
        for (std::size_t r = 0; r < a.size() && !matched; ++r) {
          matched = true;
          for (std::size_t i = 0; i < a.size(); ++i)
            matched = matched && std::abs(a[i] - b[(i + r) % b.size()]) < 1e-6 * (1 + a[i]);
        }
        EXPECT_TRUE(matched) << name << " face " << k << " is not congruent to the input's";
      }
    }
}

// The parts of a coloured model too: make keeps the gap its colour bleed needs (2.5 mm), and the parts are
// chosen for that gap. The coloured cube at 86.9 mm: three faces in a row (260.7 mm) fit the room at a
// 2 mm gap (261 mm) but not at 2.5 mm (260 mm); unfold gave 2 parts where make printed 4.
TEST(CliUnfold, WithASizeAndPaperTheNetHasThePartsMakeLaysOut) {
  const fs::path dir = test::temp_dir("cli_unfold_parts");
  const fs::path data = test::source_dir() / "tests" / "data";
  for (const auto& [mesh_file, size] : {std::pair{data / "lowpoly" / "barn.obj", std::string("150")},
                                        std::pair{data / "colour" / "cube_quads.obj", std::string("86.9")}}) {
    cli::LayoutCliOptions layout;
    layout.size = size;
    layout.paper = "A4";
    cli::UnfoldArgs unfold;
    unfold.mesh = mesh_file.string();
    unfold.json = true;
    unfold.quiet = true;
    unfold.layout = layout;
    cli::MakeArgs make;
    make.mesh = mesh_file.string();
    make.output = (dir / "sheets.pdf").string();
    make.json = true;
    make.quiet = true;
    make.layout = layout;
    const auto u = nlohmann::json::parse(test::stdout_of([&] { cli::run_unfold(unfold); }));
    const auto m = nlohmann::json::parse(test::stdout_of([&] { cli::run_make(make); }));
    EXPECT_GT(u["piece_count"].get<int>(), 1) << mesh_file << " does not fit A4 in one piece";
    EXPECT_EQ(u["piece_count"], m["piece_count"]) << mesh_file;
    EXPECT_EQ(u["seam_count"], m["seam_count"]) << mesh_file;
  }
}

TEST(CliUnfold, AFlatFaceLargerThanThePaperIsRefusedWithTheLargestSizeThatFits) {
  const fs::path mesh_file = test::source_dir() / "tests" / "data" / "lowpoly" / "barn.obj";
  auto run = test::run_foldkit({"make", mesh_file.string(), "--size", "600mm", "-o",
                                (test::temp_dir("cli_big_face") / "barn.pdf").string(), "-q"});
  EXPECT_EQ(run.exit_code, 5) << run.err;
  EXPECT_NE(run.err.find("the largest --size that fits is"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

TEST(CliUnfold, SeamListsUseTheFilesOwnVertexNumbers) {
  const fs::path dir = test::temp_dir("cli-seams");
  const std::string mesh = test::example_mesh("bob_128.obj").string();
  // The first face of bob_128.obj as written, 1-based: all three of its edges are edges of the file.
  std::ifstream in(mesh);
  std::string line;
  while (std::getline(in, line) && line.rfind("f ", 0) != 0) {
  }
  std::istringstream face(line.substr(2));
  int a = 0, b = 0, c = 0;
  face >> a >> b >> c;
  std::ofstream(dir / "cut.txt") << a << " " << b << "\n" << b << " " << c << "\n";
  // Face 0 of the net is that face; a corner of it that no other face of the net uses is one where both
  // of its edges are cut (net vertices are shared only across folds).
  const auto lone_corners_of_face_0 = [](const Net& net) {
    int lone = 0;
    for (int v : net.f[0]) {
      bool shared = false;
      for (std::size_t f = 1; f < net.f.size(); ++f)
        shared |= std::find(net.f[f].begin(), net.f[f].end(), v) != net.f[f].end();
      lone += shared ? 0 : 1;
    }
    return lone;
  };
  cli::UnfoldArgs cut;
  cut.mesh = mesh;
  cut.output = (dir / "net.obj").string();
  cut.unfold.cut_file = (dir / "cut.txt").string();
  cut.json = true;
  cut.quiet = true;
  const auto j = nlohmann::json::parse(test::stdout_of([&] { cli::run_unfold(cut); }));
  EXPECT_EQ(j["face_count"].get<int>(), unfold::load_mesh(mesh).mesh.num_faces());
  EXPECT_EQ(j["output"].get<std::string>(), cut.output);
  EXPECT_GE(j["cut_edge_count"].get<int>(), 2) << "the two edges of the list are cut";
  const Net cut_net = read_net(dir / "net.obj");
  ASSERT_EQ(static_cast<int>(cut_net.f.size()), j["face_count"].get<int>());
  EXPECT_EQ(lone_corners_of_face_0(cut_net), 1) << "the corner between the two listed edges is cut free";
  // The same list as --keep folds those edges: every corner of face 0 is shared with a neighbour.
  cli::UnfoldArgs keep = cut;
  keep.unfold.cut_file.clear();
  keep.unfold.keep_file = (dir / "cut.txt").string();
  keep.output = (dir / "net-keep.obj").string();
  const auto k = nlohmann::json::parse(test::stdout_of([&] { cli::run_unfold(keep); }));
  EXPECT_EQ(k["output"].get<std::string>(), keep.output);
  EXPECT_EQ(lone_corners_of_face_0(read_net(dir / "net-keep.obj")), 0);
  // Counted from 0, the same numbers name other vertices: not edges of the file, refused with exit 3.
  const auto run = test::run_foldkit({"unfold", mesh, "-o", (dir / "net2.obj").string(), "--cut",
                                      (dir / "cut.txt").string(), "--index-base", "0", "-q"});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(
      run.err.find("cut.txt: line 1: " + std::to_string(a) + "-" + std::to_string(b) + " is not an edge of"),
      std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "net2.obj"));
}

TEST(CliUnfold, AGapAskedForHoldsEverywhereWhileTheDefaultMayCloseToSaveASheet) {
  for (const std::string& line : {std::string{}, std::string{"--spacing 2mm"}, std::string{"--spacing 3"}}) {
    CLI::App app;
    cli::LayoutCliOptions options;
    cli::add_layout_options(app, options);
    app.parse(line, false);
    const cli::ChooseOptions choose = cli::choose_options_of(options);
    if (line.empty())
      EXPECT_EQ(choose.closer_spacing_mm, cli::kCloserSpacing_mm);
    else
      EXPECT_FALSE(choose.closer_spacing_mm.has_value()) << line;
    EXPECT_EQ(cli::to_layout_options(options).pack.spacing_mm, line == "--spacing 3" ? 3 : 2) << line;
  }
}

namespace {

bool have_shapely() {
  return std::system((test::debian_python() + " -c 'import shapely' >/dev/null 2>&1").c_str()) == 0;
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// tests/tools/net_check.py on a net, with the scale and room `summary` (unfold --json) reports, or
// another room (WxH in mm) where given.
test::CliRun net_check(const fs::path& model, const fs::path& net, const nlohmann::json& summary,
                       const std::string& room = {}) {
  std::vector<std::string> args{model.string(), net.string()};
  if (summary.contains("scale_mm_per_unit"))
    args.insert(args.end(), {"--mm-per-unit", number(summary["scale_mm_per_unit"].get<double>()), "--room",
                             !room.empty() ? room
                                           : number(summary["part_room_mm"][0].get<double>()) + "x" +
                                                 number(summary["part_room_mm"][1].get<double>())});
  return test::run_python_tool("net_check.py", args);
}

// `foldkit unfold MODEL --size SIZE --paper A4 -o NET --json`, in process: the summary, or null where
// a flat face is larger than the room.
nlohmann::json unfold_parts(const fs::path& model, const std::string& size, const fs::path& net) {
  cli::UnfoldArgs args;
  args.mesh = model.string();
  args.output = net.string();
  args.json = true;
  args.quiet = true;
  args.layout.size = size;
  args.layout.paper = "A4";
  try {
    return nlohmann::json::parse(test::stdout_of([&] { cli::run_unfold(args); }));
  } catch (const LayoutError& e) {
    EXPECT_NE(std::string(e.what()).find(model.string() + ": a flat face"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the largest --size that fits is"), std::string::npos) << e.what();
    return nullptr;
  }
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// An OBJ's text with every vertex `v x y z` moved by `move`, the rest as it was.
template <class Move>
std::string with_vertices_moved(const std::string& obj, Move move) {
  std::string out;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      Vec3 p;
      v >> p.x >> p.y >> p.z;
      p = move(p);
      line = "v " + number(p.x) + " " + number(p.y) + " " + number(p.z);
    }
    out += line + "\n";
  }
  return out;
}

// The same model as a binary PLY with double coordinates, as survey and scanning tools write one.
std::string binary_double_ply(const Polygons& model) {
  const std::vector<Vec3>& vertices = model.v;
  const std::vector<std::vector<int>>& faces = model.f;
  std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(vertices.size()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  const auto put = [&](const auto& x) { out.append(reinterpret_cast<const char*>(&x), sizeof x); };
  for (const Vec3& p : vertices) {
    put(p.x);
    put(p.y);
    put(p.z);
  }
  for (const auto& face : faces) {
    put(static_cast<unsigned char>(face.size()));
    for (const int i : face)
      put(i);
  }
  return out;
}

}  // namespace

// Issue 11: every part still passes the invariants and the independent net check. The checker shares no
// code with foldkit (it reads the model and the net itself and uses shapely): congruent, unmirrored
// faces, every flat polygon whole, folds only along real edges, no corner shared between parts, parts
// connected and overlap-free, each within the room it was cut for.
TEST(CliUnfold, ThePartsOfEveryLowPolyModelAndOfARealMeshPassTheIndependentNetCheck) {
  if (!have_shapely()) GTEST_SKIP() << "python3-shapely is not installed (bootstrap installs it)";
  const fs::path dir = test::temp_dir("cli_net_check");
  std::vector<fs::path> models;
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "tests" / "data" / "lowpoly"))
    if (entry.path().extension() == ".obj") models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  models.push_back(test::example_mesh("bob_128.obj"));
  // The barn at survey coordinates, where a float would move its corners by up to a quarter of a unit
  // and bend its walls: as an OBJ and as a PLY of doubles.
  const std::string survey = with_vertices_moved(
      test::slurp(test::source_dir() / "tests" / "data" / "lowpoly" / "barn.obj"), [](Vec3 p) {
        return p * 1.2345 + Vec3{512345.37, 5412345.71, 0.13};
      });
  write(dir / "barn_survey.obj", survey);
  models.push_back(dir / "barn_survey.obj");
  write(dir / "barn_survey.ply", binary_double_ply(read_polygons(dir / "barn_survey.obj")));
  models.push_back(dir / "barn_survey.ply");
  int checked = 0, split = 0;
  for (const fs::path& model : models)
    for (const std::string size : {"150", "250"}) {
      const fs::path net = dir / (model.filename().string() + "-" + size + ".obj");
      const nlohmann::json summary = unfold_parts(model, size, net);
      if (summary.is_null()) continue;
      ASSERT_TRUE(summary.contains("part_room_mm")) << summary.dump();
      const test::CliRun run = net_check(model, net, summary);
      EXPECT_EQ(run.exit_code, 0) << model.filename() << " at " << size << " mm:\n" << run.out << run.err;
      ++checked;
      split += summary["piece_count"].get<int>() > 1;
    }
  EXPECT_GE(checked, 17);
  EXPECT_GE(split, 14) << "most of these models must be cut into parts to fit A4";
}

// A checker that cannot fail proves nothing: each kind of fault, put into a good net, is reported.
TEST(CliUnfold, TheIndependentNetCheckReportsEachKindOfFault) {
  if (!have_shapely()) GTEST_SKIP() << "python3-shapely is not installed (bootstrap installs it)";
  const fs::path dir = test::temp_dir("cli_net_faults");
  const fs::path barn = test::source_dir() / "tests" / "data" / "lowpoly" / "barn.obj";
  const nlohmann::json summary = unfold_parts(barn, "150", dir / "good.obj");
  ASSERT_FALSE(summary.is_null());
  ASSERT_EQ(net_check(barn, dir / "good.obj", summary).exit_code, 0);
  const std::string good = test::slurp(dir / "good.obj");
  struct Fault {
    std::string name, net;
    std::string room;  ///< WxH mm in place of the room the parts were cut for, where set
    std::string reported;
  };
  // Every vertex's x negated: the net seen from behind.
  const std::string flipped = with_vertices_moved(good, [](Vec3 p) { return Vec3{-p.x, p.y, p.z}; });
  const std::vector<Fault> faults = {
      {"moved", replaced(good, "v 4 0 0", "v 4.2 0 0"), {}, "not congruent"},
      {"mirrored", flipped, {}, "mirrored"},
      {"quad in two", replaced(good, "f 1 2 3 4", "f 1 2 3\nf 1 3 4"), {}, "faces, the model 7 polygons"},
      {"parts merged", replaced(good, "g piece_1", "g piece_0"), {}, "falls apart"},
      {"too small a room", good, "100x100", "does not fit"},
  };
  for (const Fault& f : faults) {
    write(dir / "bad.obj", f.net);
    const test::CliRun run = net_check(barn, dir / "bad.obj", summary, f.room);
    EXPECT_EQ(run.exit_code, 1) << f.name << ":\n" << run.out;
    EXPECT_NE(run.out.find(f.reported), std::string::npos) << f.name << ":\n" << run.out;
  }
}

// The same for an overlap, which no mutation of a real net gives while keeping every face congruent: a
// fan of triangles around a saddle vertex (more than 360 degrees of corners), unrolled without a cut,
// comes round onto itself.
TEST(CliUnfold, TheIndependentNetCheckReportsANetThatOverlapsItself) {
  if (!have_shapely()) GTEST_SKIP() << "python3-shapely is not installed (bootstrap installs it)";
  const fs::path dir = test::temp_dir("cli_net_overlap");
  constexpr int kRim = 12;
  std::vector<Vec3> rim;
  for (int i = 0; i < kRim; ++i) {
    const double a = 2 * std::numbers::pi * i / kRim;
    rim.push_back({std::cos(a), std::sin(a), 0.8 * std::sin(3 * a)});
  }
  std::string model = "v 0 0 0\n", net = "v 0 0 0\n";
  for (const Vec3& p : rim)
    model += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
  double turned = 0;
  for (int i = 0; i <= kRim; ++i) {
    const Vec3& p = rim[i % kRim];
    if (i > 0) {
      const Vec3& q = rim[i - 1];
      turned += std::acos(dot(p, q) / (norm(p) * norm(q)));
    }
    net += "v " + number(norm(p) * std::cos(turned)) + " " + number(norm(p) * std::sin(turned)) + " 0\n";
  }
  ASSERT_GT(turned, 2 * std::numbers::pi) << "the fan must have more than a full turn of corners";
  net += "g piece_0\n";
  for (int i = 0; i < kRim; ++i) {
    model += "f 1 " + std::to_string(i + 2) + " " + std::to_string((i + 1) % kRim + 2) + "\n";
    net += "f 1 " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
  }
  write(dir / "fan.obj", model);
  write(dir / "net.obj", net);
  const test::CliRun run = net_check(dir / "fan.obj", dir / "net.obj", nullptr);
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_NE(run.out.find("overlap"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("congruent"), std::string::npos) << "every face is congruent: " << run.out;
}
