// Huge and hostile inputs: each is refused with a one-line InputError/DeviceError before any large
// allocation or long computation (docs/failures.md states the limits and why).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::DeviceError;
using foldkit::InputError;

namespace {

class Limits : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = foldkit::test::temp_dir("limits"); }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& bytes) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  // The InputError message of loading `path`, or a marker when it loads or throws something else.
  static std::string load_error(const fs::path& path, const foldkit::unfold::LoadOptions& o = {}) {
    try {
      foldkit::unfold::load_mesh(path, o);
    } catch (const InputError& e) {
      return e.what();
    } catch (const std::exception& e) {
      return std::string("(not an InputError) ") + e.what();
    }
    return "(loaded)";
  }
  fs::path dir_;
};

std::string binary_stl(std::uint32_t declared, std::size_t facets) {
  std::string s(80, ' ');
  for (int i = 0; i < 4; ++i)
    s += static_cast<char>((declared >> (8 * i)) & 0xff);
  s += std::string(50 * facets, '\0');
  return s;
}

const char* kPlyHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

using foldkit::test::slurp;

}  // namespace

// ---- meshes ----------------------------------------------------------------------------------------

TEST_F(Limits, AFileOverTheSizeLimitIsRefusedBeforeAnyByteIsRead) {
  const fs::path p = dir_ / "huge.obj";
  std::ofstream(p).put('v');
  fs::resize_file(p, (std::uintmax_t{1} << 30) + 1);  // sparse: no disk space used
  const std::string m = load_error(p);
  EXPECT_NE(m.find("over the limit of 1073741824 bytes"), std::string::npos) << m;
}

TEST_F(Limits, HeadersClaimingMillionsOfFacesAreRefusedBeforeParsing) {
  const auto off = write("claims.off", "OFF\n3 3000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_NE(load_error(off).find("3000000 triangles, over the limit of 2000000"), std::string::npos)
      << load_error(off);
  const auto ply = write("claims.ply", std::string(kPlyHead) +
                                           "element face 4000000000\nproperty list uchar int vertex_indices\n"
                                           "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_NE(load_error(ply).find("over the limit of 2000000"), std::string::npos) << load_error(ply);
}

TEST_F(Limits, ABinaryStlClaimingFourBillionTrianglesIsRefusedWithoutAllocatingThem) {
  const auto p = write("claims.stl", binary_stl(0xffffffffu, 1));
  const std::string m = load_error(p);
  EXPECT_NE(m.find("4294967295 triangles"), std::string::npos) << m;
}

TEST_F(Limits, AConsistentBinaryStlOverTheFaceLimitIsRefusedFromItsHeaderAlone) {
  // 20 million triangles, size consistent with the count, just under 1 GiB: sparse, so nothing is
  // written; reading it whole would take seconds and gigabytes before the count check.
  const fs::path p = write("big.stl", binary_stl(20'000'000u, 0));
  fs::resize_file(p, 84 + 50 * std::uintmax_t{20'000'000});
  const std::string m = load_error(p);
  EXPECT_NE(m.find("20000000 triangles, over the limit of 2000000"), std::string::npos) << m;
}

// Bytes this process has read so far (Linux: /proc/self/io), to prove a file was refused unread.
std::uint64_t bytes_read_so_far() {
  std::ifstream io("/proc/self/io");
  for (std::string key; io >> key;) {
    std::uint64_t value = 0;
    io >> value;
    if (key == "rchar:") return value;
  }
  return 0;
}

TEST_F(Limits, ABinaryStlWhoseCountDisagreesWithItsSizeIsRefusedFromItsFirstBytes) {
  // Just under 1 GiB, one triangle declared: reading it whole cost 11 s and 2 GB before the check.
  const fs::path p = write("liar.stl", binary_stl(1u, 1));
  fs::resize_file(p, (std::uintmax_t{1} << 30) - 100);  // sparse: no disk space used
  const std::uint64_t before = bytes_read_so_far();
  const std::string m = load_error(p);
  const std::uint64_t read = bytes_read_so_far() - before;
  EXPECT_NE(m.find("binary STL header says 1 triangles (134 bytes) but the file has 1073741724 bytes"),
            std::string::npos)
      << m;
  if (before == 0) GTEST_SKIP() << "/proc/self/io is not readable here";
  EXPECT_LT(read, std::uint64_t{1} << 20) << "bytes read before refusing";
}

TEST_F(Limits, AnAsciiStlIsNotTakenForABinaryOneWhoseCountDisagrees) {
  const char* corners[] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string text = "solid tetrahedron\n";
  for (const auto& f : faces) {
    text += " facet normal 0 0 0\n  outer loop\n";
    for (const int i : f)
      text += std::string("   vertex ") + corners[i] + "\n";
    text += "  endloop\n endfacet\n";
  }
  text += "endsolid tetrahedron\n";
  EXPECT_EQ(load_error(write("ascii.stl", text)), "(loaded)");
}

TEST_F(Limits, AMeshOverTheUnfoldingFaceLimitIsRefusedWithAHintToDecimate) {
  const auto mesh = foldkit::unfold::load_mesh(foldkit::test::example_mesh("spot_128.obj")).mesh;
  foldkit::unfold::UnfoldOptions options;
  options.face_limit = 100;
  try {
    foldkit::unfold::unfold_mesh(mesh, options);
    FAIL() << "unfolded a mesh over the face limit";
  } catch (const foldkit::unfold::TooManyFaces& e) {
    EXPECT_NE(std::string(e.what()).find("decimate first"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos)
        << "the library names no flag: " << e.what();
  }
}

TEST_F(Limits, OffCountsTooLargeForAnyIntegerAreAnErrorNotTakenFromTheNextLine) {
  // Regression: the overflowing counts line was skipped and the first vertex ("0 0 0") read as the
  // counts; OpenMesh then reserved for 1e20 faces (10 GB and minutes before this fix).
  const auto p = write("overflow.off", "OFF\n3 99999999999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_NE(load_error(p).find("unparsable OFF header"), std::string::npos) << load_error(p);
}

TEST_F(Limits, PlyCountsTooLargeForAnyIntegerAreAnError) {
  const auto p = write("overflow.ply", std::string(kPlyHead) +
                                           "element face 99999999999999999999\n"
                                           "property list uchar int vertex_indices\nend_header\n"
                                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string m = load_error(p);
  EXPECT_EQ(m.find("(loaded)"), std::string::npos);
  EXPECT_EQ(m.find("not an InputError"), std::string::npos) << m;
}

TEST_F(Limits, AnObjWithMoreFacesThanTheLimitIsRefusedBeforeOpenMeshParsesIt) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 1001; ++i)
    obj += "f 1 2 3\n";
  foldkit::unfold::LoadOptions o;
  o.face_limit = 1000;
  const std::string m = load_error(write("many.obj", obj), o);
  EXPECT_NE(m.find("over the limit of 1000"), std::string::npos) << m;
}

TEST_F(Limits, FaceIndicesOutOfRangeNameTheIndexInEveryFormat) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (const char* face : {"f 1 2 99", "f 1 2 -7", "f 0 1 2", "f 1 2 99999999999999999999"}) {
    const std::string m = load_error(write("index.obj", tri + face + "\n"));
    EXPECT_NE(m.find("references vertex"), std::string::npos) << face << ": " << m;
    EXPECT_NE(m.find("line 4"), std::string::npos) << face << ": " << m;
  }
  const std::string off = load_error(write("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
  EXPECT_NE(off.find("references vertex 8"), std::string::npos) << off;
  const std::string ply = load_error(
      write("index.ply",
            std::string(kPlyHead) +
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 "
                "0\n3 0 1 9\n"));
  EXPECT_NE(ply.find("references vertex 10"), std::string::npos) << ply;
}

// ---- profiles --------------------------------------------------------------------------------------

struct AbsurdValue {
  const char* base;     // file under profiles/
  const char* from;     // text replaced
  const char* to;       // absurd replacement
  const char* message;  // part of the expected error
};

class AbsurdProfiles : public Limits, public ::testing::WithParamInterface<AbsurdValue> {};

TEST_P(AbsurdProfiles, AreRefusedNamingTheFileAndTheKey) {
  const AbsurdValue& v = GetParam();
  std::string text = slurp(foldkit::test::source_dir() / "profiles" / v.base);
  const auto at = text.find(v.from);
  ASSERT_NE(at, std::string::npos) << v.from << " not in " << v.base;
  text.replace(at, std::string(v.from).size(), v.to);
  const fs::path p = write("absurd.toml", text);
  try {
    if (std::string(v.base).rfind("devices/", 0) == 0) {
      foldkit::devices::load_device_profile(p);
    } else {
      foldkit::devices::load_media_profile(p);
    }
    FAIL() << v.to << " was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(p.string() + ": ", 0), 0u) << m;
    EXPECT_NE(m.find(v.message), std::string::npos) << m;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Limits, AbsurdProfiles,
    ::testing::Values(
        AbsurdValue{"devices/cameo3.toml", "units_per_mm = 20", "units_per_mm = 1e308",
                    "units_per_mm: must be between 1 and 1000, got 1e+308"},
        AbsurdValue{"devices/cameo3.toml", "units_per_mm = 20", "units_per_mm = 1e-300",
                    "units_per_mm: must be between 1 and 1000"},
        AbsurdValue{"devices/cameo3.toml", "units_per_mm = 20", "units_per_mm = nan",
                    "units_per_mm: must be a finite number"},
        AbsurdValue{"devices/cameo3.toml", "max_length_mm = 3000", "max_length_mm = 1e12",
                    "area.max_length_mm: must be at most 100000"},
        AbsurdValue{"devices/cameo3.toml", "length_mm = 609.6", "length_mm = 1e200",
                    "mats[2].length_mm: must be at most 100000"},
        AbsurdValue{"devices/cameo3.toml", "travel_speed_mm_s = 300", "travel_speed_mm_s = 1e300",
                    "travel_speed_mm_s: must be at most 10000"},
        AbsurdValue{"devices/cameo3.toml", "max = 33", "max = 2147483648", "force.max: must be between"},
        AbsurdValue{"devices/cameo3.toml", "max = 33", "max = 99999999999999999999", "not representable"},
        AbsurdValue{"devices/cameo3.toml", "count = 2", "count = 1000000", "holders.count"},
        AbsurdValue{"devices/cameo3.toml", "vendor = 0x0b4d", "vendor = 0x10000", "usb.vendor"},
        AbsurdValue{"devices/cameo3.toml", "tool_change_s = 0.25", "tool_change_s = -1", "tool_change_s"},
        AbsurdValue{"media/copy-80.toml", "passes = 1", "passes = 1000000000", "cut.passes"},
        AbsurdValue{"media/copy-80.toml", "force_gf = 80", "force_gf = -5", "cut.force_gf"},
        AbsurdValue{"media/copy-80.toml", "speed_mm_s = 100", "speed_mm_s = 1e308",
                    "cut.speed_mm_s: must be at most 10000"},
        AbsurdValue{"media/copy-80.toml", "thickness_mm = 0.10", "thickness_mm = 1e9",
                    "thickness_mm: must be at most 10"},
        AbsurdValue{"media/copy-80.toml", "cut_mm = 1.0", "cut_mm = 1e-300",
                    "perforation.cut_mm: must be between 0.1 and 1000"},
        AbsurdValue{"media/copy-80.toml", "gap_mm = 1.0", "gap_mm = inf", "perforation.gap_mm"}));

// ---- device streams --------------------------------------------------------------------------------

namespace {
std::span<const std::byte> bytes(const std::string& s) {
  return {reinterpret_cast<const std::byte*>(s.data()), s.size()};
}
std::string device_error(foldkit::devices::Protocol protocol, const std::string& stream) {
  const auto set = foldkit::devices::load_profiles(foldkit::test::profiles_dir());
  foldkit::devices::SimOptions o;
  o.require_initialize = false;
  foldkit::devices::SimulatedDevice device(
      set.device(protocol == foldkit::devices::Protocol::Gpgl ? "cameo3" : "roland-gx24"), o);
  try {
    device.write(bytes(stream));
    device.close();
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "(accepted)";
}
}  // namespace

TEST(DeviceStreamLimits, CoordinatesBeyondAnyIntegerAreRefusedWithTheByteOffset) {
  const std::string g = device_error(foldkit::devices::Protocol::Gpgl,
                                     "M0,0\x03"
                                     "D99999999999999999999,5\x03");
  EXPECT_NE(g.find("GP-GL byte 5"), std::string::npos) << g;
  const std::string h = device_error(foldkit::devices::Protocol::Hpgl, "IN;PU0,0;PD1e300,5;");
  EXPECT_NE(h.find("HP-GL byte"), std::string::npos) << h;
}

TEST(DeviceStreamLimits, ACommandWithoutItsTerminatorIsCutOffAfterFourKibibytes) {
  const std::string g = device_error(foldkit::devices::Protocol::Gpgl, "M" + std::string(10000, '1'));
  EXPECT_NE(g.find("GP-GL byte"), std::string::npos) << g;
  EXPECT_EQ(g.find("(accepted)"), std::string::npos);
}
