#include "foldkit/devices/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "foldkit/error.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::OutputError;
using foldkit::devices::AtomicFile;
using foldkit::devices::write_file_atomically;

namespace {

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int count_entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir))
    ++n;
  return n;
}

}  // namespace

TEST(AtomicFile, CommitPutsTheContentsUnderTheTargetName) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path target = dir / "job.plt";
  {
    AtomicFile file(target);
    file.stream() << "IN;PU0,0;";
    EXPECT_FALSE(fs::exists(target)) << "nothing appears under the target name before commit";
    EXPECT_EQ(file.temp_path().parent_path(), dir) << "the temporary must be in the same directory";
    file.commit();
  }
  EXPECT_EQ(read_all(target), "IN;PU0,0;");
  EXPECT_EQ(count_entries(dir), 1) << "the temporary file is gone after rename";
}

TEST(AtomicFile, AnUncommittedFileLeavesTheOldTargetUntouchedAndNoTemporary) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path target = dir / "net.obj";
  write_file_atomically(target, std::string_view("old"));
  {
    AtomicFile file(target);
    file.stream() << "half of the new conte";
  }
  EXPECT_EQ(read_all(target), "old");
  EXPECT_EQ(count_entries(dir), 1);
}

TEST(AtomicFile, AWriterThatThrowsLeavesNothingBehind) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path target = dir / "model.svg";
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "<svg";
                                       throw std::runtime_error("renderer failed");
                                     }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(count_entries(dir), 0);
}

TEST(AtomicFile, AMissingDirectoryIsAnOutputErrorNamingTheFile) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path target = dir / "no-such-dir" / "model.pdf";
  try {
    write_file_atomically(target, std::string_view("x"));
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "no-such-dir"));
}

TEST(AtomicFile, ATargetThatIsADirectoryIsAnOutputError) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  fs::create_directory(dir / "out.pdf");
  EXPECT_THROW(write_file_atomically(dir / "out.pdf", std::string_view("x")), OutputError);
  EXPECT_EQ(count_entries(dir), 1);
}

TEST(AtomicFile, AnUnwritableDirectoryIsAnOutputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: directory permissions are not enforced";
  const fs::path dir = foldkit::test::temp_dir("atomic");
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(write_file_atomically(dir / "model.pdf", std::string_view("x")), OutputError);
  fs::permissions(dir, fs::perms::owner_all);
  EXPECT_EQ(count_entries(dir), 0);
}

TEST(AtomicFile, WrittenFilesGetTheUsualPermissionsUnderTheUmask) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const mode_t old_mask = ::umask(022);
  write_file_atomically(dir / "a.txt", std::string_view("x"));
  ::umask(old_mask);
  struct stat st {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u) << "not mkstemp's private 0600";
}

TEST(AtomicFile, AMovedFileIsCommittedByItsNewOwnerOnly) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path target = dir / "moved.txt";
  AtomicFile first(target);
  first.stream() << "moved";
  AtomicFile second(std::move(first));
  second.commit();
  EXPECT_EQ(read_all(target), "moved");
}

TEST(AtomicFile, AFileInTheCurrentDirectoryNeedsNoDirectoryPart) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path old_cwd = fs::current_path();
  fs::current_path(dir);
  write_file_atomically("plain.txt", std::string_view("here"));
  fs::current_path(old_cwd);
  EXPECT_EQ(read_all(dir / "plain.txt"), "here");
}
