// program_command_test.cpp — program_command_for (program_command.h): the
// command a printed replay or re-run line starts with is one a shell runs
// where vgc is: the checkout's vgc script by its absolute path for the
// build tree's program (so that the line works from any directory), "vgc"
// when PATH finds this very program, else its
// absolute path. The installed program's printed replay line is run as
// printed in tests/install/install_consumer_test.sh.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "program_command.h"

namespace vgc {
namespace {

namespace fs = std::filesystem;

class ProgramCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/vgc_program_command.XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // An executable file at dir_/relative.
  std::string program(const std::string& relative) {
    const fs::path p = dir_ / relative;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "#!/bin/sh\n";
    fs::permissions(p, fs::perms::owner_all);
    return p.string();
  }

  fs::path dir_;
};

TEST_F(ProgramCommand, TheBuildTreesProgramIsRunByTheVgcScriptByItsAbsolutePath) {
  const std::string exe = program("build/cli/vgc");
  std::ofstream(dir_ / "build/CMakeCache.txt") << "\n";
  // No script beside the build tree (a build elsewhere): the program itself.
  EXPECT_EQ(program_command_for(exe, "/usr/bin:/bin"), exe);
  const std::string script = program("vgc");
  // A line that works from any directory, not "./vgc" (issue 31 item 5).
  EXPECT_EQ(program_command_for(exe, "/usr/bin:/bin"), script);
}

TEST_F(ProgramCommand, AProgramInstalledOnPathIsVgc) {
  const std::string exe = program("prefix/bin/vgc");
  EXPECT_EQ(program_command_for(exe, (dir_ / "elsewhere").string() + ":" + (dir_ / "prefix/bin").string()), "vgc");
  // through a symbolic link on PATH too (/usr/local/bin/vgc -> /opt/vgc/bin/vgc)
  fs::create_directories(dir_ / "links");
  fs::create_symlink(exe, dir_ / "links/vgc");
  EXPECT_EQ(program_command_for(exe, (dir_ / "links").string()), "vgc");
}

TEST_F(ProgramCommand, AProgramNotOnPathIsNamedByItsPath) {
  const std::string exe = program("prefix/bin/vgc");
  EXPECT_EQ(program_command_for(exe, "/nonexistent/bin"), exe);
  EXPECT_EQ(program_command_for(exe, ""), exe);
  // a build tree is a directory cli/ next to CMakeCache.txt, not any directory holding one
  std::ofstream(dir_ / "prefix/CMakeCache.txt") << "\n";
  EXPECT_EQ(program_command_for(exe, ""), exe);
}

TEST_F(ProgramCommand, AnotherVgcFirstOnPathIsNotThisOne) {
  const std::string exe = program("prefix/bin/vgc");
  program("other/bin/vgc");
  EXPECT_EQ(program_command_for(exe, (dir_ / "other/bin").string() + ":" + (dir_ / "prefix/bin").string()), exe);
}

TEST_F(ProgramCommand, RelativePathEntriesAreSkipped) {
  const std::string exe = program("prefix/bin/vgc");
  // "" and "." name the current directory: a printed line must not depend on it
  const fs::path before = fs::current_path();
  fs::current_path(dir_ / "prefix");
  EXPECT_EQ(program_command_for(exe, ":.:bin:./bin"), exe);
  fs::current_path(before);
}

TEST_F(ProgramCommand, APathThatNeedsQuotingIsQuoted) {
  const std::string exe = program("my tools/bin/vgc");
  EXPECT_EQ(program_command_for(exe, ""), "'" + exe + "'");
}

}  // namespace
}  // namespace vgc
