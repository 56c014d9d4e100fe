#include "foldkit/devices/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "foldkit/error.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::OutputError;
using foldkit::devices::AtomicFile;
using foldkit::devices::AtomicFileSet;
using foldkit::devices::write_file_atomically;

namespace {

using foldkit::test::slurp;

using foldkit::test::count_entries;

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
  EXPECT_EQ(slurp(target), "IN;PU0,0;");
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
  EXPECT_EQ(slurp(target), "old");
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
  EXPECT_EQ(slurp(target), "moved");
}

TEST(AtomicFile, AFileInTheCurrentDirectoryNeedsNoDirectoryPart) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path old_cwd = fs::current_path();
  fs::current_path(dir);
  write_file_atomically("plain.txt", std::string_view("here"));
  fs::current_path(old_cwd);
  EXPECT_EQ(slurp(dir / "plain.txt"), "here");
}

TEST(AtomicFile, ASymbolicLinkIsWrittenThroughAndStaysALink) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  fs::create_directory(dir / "real");
  write_file_atomically(dir / "real" / "model.svg", std::string_view("old"));
  fs::create_symlink("real/model.svg", dir / "link.svg");
  write_file_atomically(dir / "link.svg", std::string_view("new"));
  EXPECT_TRUE(fs::is_symlink(dir / "link.svg"));
  EXPECT_EQ(slurp(dir / "real" / "model.svg"), "new");
  EXPECT_EQ(count_entries(dir / "real"), 1) << "the temporary lived beside the file the link names";
  EXPECT_EQ(count_entries(dir), 2);
}

TEST(AtomicFile, ADanglingLinkCreatesTheFileItNames) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  fs::create_symlink("net.obj", dir / "link.obj");
  write_file_atomically(dir / "link.obj", std::string_view("v 0 0 0"));
  EXPECT_TRUE(fs::is_symlink(dir / "link.obj"));
  EXPECT_EQ(slurp(dir / "net.obj"), "v 0 0 0");
}

TEST(AtomicFile, AFifoIsWrittenIntoAndNeverReplaced) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  write_file_atomically(fifo, std::string_view("PU0,0;"));
  reader.join();
  EXPECT_EQ(received, "PU0,0;");
  EXPECT_TRUE(fs::is_fifo(fifo)) << "the node is still a FIFO, not a regular file renamed over it";
  EXPECT_EQ(count_entries(dir), 1) << "no temporary file beside a node";
}

TEST(AtomicFile, ACharacterDeviceIsResolvedAsANodeNotAFile) {
  EXPECT_EQ(foldkit::devices::resolve_output("/dev/null").kind, foldkit::devices::OutputKind::Node);
  EXPECT_EQ(foldkit::devices::resolve_output("-").kind, foldkit::devices::OutputKind::Stdout);
  AtomicFile null("/dev/null");
  EXPECT_TRUE(null.temp_path().empty()) << "nothing is created in /dev";
  null.stream() << "discarded";
  null.commit();
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(AtomicFile, SameFileIsToldByDeviceAndInodeThroughLinks) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  write_file_atomically(dir / "a.obj", std::string_view("v 0 0 0"));
  fs::create_symlink("a.obj", dir / "soft.obj");
  fs::create_hard_link(dir / "a.obj", dir / "hard.obj");
  write_file_atomically(dir / "b.obj", std::string_view("v 0 0 0"));
  EXPECT_TRUE(foldkit::devices::is_same_file(dir / "a.obj", dir / "soft.obj"));
  EXPECT_TRUE(foldkit::devices::is_same_file(dir / "hard.obj", dir / "soft.obj"));
  EXPECT_TRUE(foldkit::devices::is_same_file(dir / "." / "a.obj", dir / "a.obj"));
  EXPECT_FALSE(foldkit::devices::is_same_file(dir / "a.obj", dir / "b.obj"));
  EXPECT_FALSE(foldkit::devices::is_same_file(dir / "a.obj", dir / "missing.obj"));
  EXPECT_FALSE(foldkit::devices::is_same_file("-", "-"));
}

TEST(AtomicFileSet, AllFilesAppearTogether) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  AtomicFileSet set;
  set.add(dir / "m.svg").stream() << "one";
  set.add(dir / "m-2.svg").stream() << "two";
  EXPECT_EQ(count_entries(dir), 2) << "two temporaries, no target yet";
  EXPECT_FALSE(fs::exists(dir / "m.svg"));
  set.commit();
  EXPECT_EQ(slurp(dir / "m.svg"), "one");
  EXPECT_EQ(slurp(dir / "m-2.svg"), "two");
  EXPECT_EQ(count_entries(dir), 2);
}

TEST(AtomicFileSet, AFailedRenamePutsTheFilesAlreadyReplacedBack) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  write_file_atomically(dir / "m.svg", std::string_view("old one"));
  {
    AtomicFileSet set;
    set.add(dir / "m.svg").stream() << "new one";
    set.add(dir / "m-2.svg").stream() << "new two";
    set.add(dir / "m-3.svg").stream() << "new three";
    // Sheet 2 cannot be renamed into place: a non-empty directory took its name meanwhile.
    fs::create_directories(dir / "m-2.svg" / "x");
    EXPECT_THROW(set.commit(), OutputError);
  }
  EXPECT_EQ(slurp(dir / "m.svg"), "old one") << "sheet 1 has its old contents back";
  EXPECT_FALSE(fs::exists(dir / "m-3.svg"));
  EXPECT_EQ(count_entries(dir), 2) << "no temporary or backup left: only m.svg and the directory";
}

TEST(AtomicFile, PendingTemporariesAreRemovedForAProcessEndingOnASignal) {
  const fs::path dir = foldkit::test::temp_dir("atomic");
  // In a child: the clean-up locks commits for good, as befits a process that is about to end.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    AtomicFile first(dir / "a.pdf");
    AtomicFile second(dir / "b.svg");
    first.stream() << "partial";
    const bool both_exist = fs::exists(first.temp_path()) && fs::exists(second.temp_path());
    foldkit::devices::remove_pending_temporaries();
    ::_exit(both_exist && count_entries(dir) == 0 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(count_entries(dir), 0);
}

TEST(AtomicFile, ATemporaryBeingCreatedWhenTheSignalComesIsRemovedToo) {
  // The signal's clean-up may run while another thread is between creating its temporary and
  // registering it. A child per trial creates and drops temporaries in a loop on one thread while its
  // other thread cleans up after a short, varying delay; nothing may be left in the directory.
  constexpr int kTrials = 40;
  int left_behind = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const fs::path dir = foldkit::test::temp_dir("atomic-race-" + std::to_string(trial));
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::thread writer([&dir] {
        for (;;) {
          AtomicFile f(dir / "sheet.png");
          f.stream() << "x";
        }
      });
      std::this_thread::sleep_for(std::chrono::microseconds(500 + 97 * trial));
      foldkit::devices::remove_pending_temporaries();
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    if (count_entries(dir) != 0) ++left_behind;
  }
  EXPECT_EQ(left_behind, 0) << "of " << kTrials << " trials";
}
