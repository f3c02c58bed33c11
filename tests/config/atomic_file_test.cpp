// Tests of config/base/atomic_file.h: an output is whole or absent, and two writers of one path (two lungar
// processes on one PC writing their stats) do not write into each other's partial file.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/base/atomic_file.h"
#include "tests/file_text.h"
#include "tests/partial_files.h"
#include "tests/scratch_dir.h"

namespace lungar {
namespace {

using testing::file_text;
using testing::partial_files_beside;
using testing::ScratchDir;

TEST(AtomicFile, TwoWritersOfOnePathEachCommitWholeAndTheLastWins) {
  const ScratchDir dir("lungar_atomic_file");
  const std::string path = (dir / "stats.json").string();
  AtomicFile first, second;
  ASSERT_TRUE(first.open(path));
  ASSERT_TRUE(second.open(path));
  EXPECT_EQ(partial_files_beside(path).size(), 2u) << "each writer has a partial file of its own";
  first.write("first writer's whole file\n");
  second.write("second\n");
  const Status one = first.commit();
  ASSERT_TRUE(one) << one.error();
  EXPECT_EQ(file_text(path), "first writer's whole file\n");
  const Status two = second.commit();
  ASSERT_TRUE(two) << two.error();
  EXPECT_EQ(file_text(path), "second\n");
  EXPECT_EQ(partial_files_beside(path), std::vector<std::string>{});
}

TEST(AtomicFile, AnAbandonedWriteLeavesNothingAndKeepsTheOldFile) {
  const ScratchDir dir("lungar_atomic_file");
  const std::string path = (dir / "report.json").string();
  ASSERT_TRUE(write_file_atomically(path, "old\n"));
  {
    AtomicFile f;
    ASSERT_TRUE(f.open(path));
    f.write("half of a new one");
  }  // destroyed before commit()
  EXPECT_EQ(file_text(path), "old\n");
  EXPECT_EQ(partial_files_beside(path), std::vector<std::string>{});
}

TEST(AtomicFile, TheFinishedFileIsReadableByAll) {
  const ScratchDir dir("lungar_atomic_file");
  const std::string path = (dir / "sub" / "snapshot.png").string();
  ASSERT_TRUE(write_file_atomically(path, "png"));
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST(AtomicFile, AnUnwritableFolderIsOneLineNamingThePath) {
  const ScratchDir dir("lungar_atomic_file");
  std::ofstream(dir / "blocker") << "a file where a folder should be";
  const std::string path = (dir / "blocker" / "x.toml").string();
  const Status s = write_file_atomically(path, "x = 1\n");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().rfind(path + ": ", 0), 0u) << s.error();
  EXPECT_EQ(s.error().find('\n'), std::string::npos) << s.error();
}

}  // namespace
}  // namespace lungar
