// Files written whole or not at all, and read with a reason when they cannot be: a write that
// fails (here a file size limit, as a full disk fails) leaves the old file as it was and no
// temporary file behind.
#include "io/whole_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace vibro {
namespace {

namespace fs = std::filesystem;

class WholeFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vibro-whole-file-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directory(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  }
  // The names in the directory: no temporary file may stay.
  std::vector<std::string> names() const {
    std::vector<std::string> all;
    for (const auto& e : fs::directory_iterator(dir_)) all.push_back(e.path().filename());
    std::sort(all.begin(), all.end());
    return all;
  }

  fs::path dir_;
};

TEST_F(WholeFile, WritesAndReplacesWhole) {
  const std::string out = path("out.csv");
  ASSERT_FALSE(write_whole_file(out, "a,b\n1,2\n"));
  EXPECT_EQ(slurp(out), "a,b\n1,2\n");
  ::chmod(out.c_str(), 0640);
  ASSERT_FALSE(write_whole_file(out, "c\n"));
  EXPECT_EQ(slurp(out), "c\n");
  struct stat st {};
  ASSERT_EQ(::stat(out.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u) << "the replaced file's permissions are kept";
  EXPECT_EQ(names(), std::vector<std::string>{"out.csv"});
}

// A write that fails part way (a full disk fails the same way): the old file stays whole.
TEST_F(WholeFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const std::string out = path("out.csv");
  ASSERT_FALSE(write_whole_file(out, "the good result\n"));
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of the signal
  rlimit small = before;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const auto problem = write_whole_file(out, std::string(100000, 'x'));
  ::setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, old_handler);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->message.find(out + " cannot be written: File too large"), std::string::npos)
      << problem->message;
  EXPECT_EQ(slurp(out), "the good result\n");
  EXPECT_EQ(names(), std::vector<std::string>{"out.csv"});
}

TEST_F(WholeFile, ADirectoryInTheWayOrNoDirectoryIsAProblem) {
  fs::create_directory(path("out.csv"));
  const auto problem = write_whole_file(path("out.csv"), "x");
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->message.find("Is a directory"), std::string::npos) << problem->message;
  EXPECT_EQ(names(), std::vector<std::string>{"out.csv"});
  EXPECT_TRUE(fs::is_directory(path("out.csv")));
  const auto nowhere = write_whole_file(path("missing/out.csv"), "x");
  ASSERT_TRUE(nowhere);
  EXPECT_NE(nowhere->message.find("No such file or directory"), std::string::npos);
}

TEST_F(WholeFile, ASymbolicLinkStaysAndItsFileIsReplaced) {
  ASSERT_FALSE(write_whole_file(path("real.json"), "old"));
  fs::create_symlink("real.json", path("link.json"));
  ASSERT_FALSE(write_whole_file(path("link.json"), "new"));
  EXPECT_TRUE(fs::is_symlink(path("link.json")));
  EXPECT_EQ(slurp(path("real.json")), "new");
}

TEST_F(WholeFile, ReadsWholeOrSaysWhyNot) {
  const std::string bytes(200000, 'y');
  ASSERT_FALSE(write_whole_file(path("scene.json"), bytes));
  auto read = read_whole_file(path("scene.json"));
  ASSERT_TRUE(std::holds_alternative<std::string>(read));
  EXPECT_EQ(std::get<std::string>(read), bytes);

  read = read_whole_file(path("missing.json"));
  ASSERT_TRUE(std::holds_alternative<FileProblem>(read));
  EXPECT_EQ(std::get<FileProblem>(read).message, path("missing.json") + " does not exist");
  EXPECT_EQ(std::get<FileProblem>(read).error, ENOENT);

  read = read_whole_file(dir_.string());
  ASSERT_TRUE(std::holds_alternative<FileProblem>(read));
  EXPECT_EQ(std::get<FileProblem>(read).message, dir_.string() + " is a directory, not a file");
}

}  // namespace
}  // namespace vibro
