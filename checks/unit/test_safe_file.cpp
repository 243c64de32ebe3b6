// SafeFile.h: files replaced only whole and only when regular, streamed
// outputs locked against a second run; Metrics::set at scale; decimal-only
// whole numbers (issue 15).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "CommandLine.h"
#include "Metrics.h"
#include "SafeFile.h"

namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class SafeFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/odelab_safe_file.XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    folder_ = pattern;
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string path(const std::string& name) const { return folder_ + "/" + name; }
  std::string read(const std::string& name) const {
    std::ifstream in(path(name));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // Files in the folder besides `expected` (a temporary file left behind).
  int entries() const { return static_cast<int>(std::distance(fs::directory_iterator(folder_), {})); }
  std::string folder_;
};

TEST_F(SafeFileTest, ReplacesARegularFileWhole) {
  std::ofstream(path("m.json")) << "old";
  odelab::writeFileAtomically(path("m.json"), "new contents");
  EXPECT_EQ(read("m.json"), "new contents");
  EXPECT_EQ(entries(), 1);  // no temporary file left
}

TEST_F(SafeFileTest, RefusesToReplaceALinkAFifoOrAFolder) {
  std::ofstream(path("target")) << "precious";
  ASSERT_EQ(symlink(path("target").c_str(), path("link").c_str()), 0);
  ASSERT_EQ(mkfifo(path("fifo").c_str(), 0600), 0);
  fs::create_directory(path("folder"));
  for (const char* name : {"link", "fifo", "folder"}) {
    SCOPED_TRACE(name);
    EXPECT_NE(odelab::whyNotReplaceable(path(name)), "");
    EXPECT_THROW(odelab::writeFileAtomically(path(name), "x"), std::runtime_error);
  }
  EXPECT_EQ(read("target"), "precious");
  EXPECT_TRUE(fs::is_symlink(path("link")));
  EXPECT_TRUE(fs::is_fifo(path("fifo")));
  EXPECT_EQ(entries(), 4);  // no temporary file left
}

TEST_F(SafeFileTest, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  std::ofstream(path("m.json")) << "old";
  if (geteuid() == 0) GTEST_SKIP() << "root ignores the folder's mode";
  chmod(folder_.c_str(), 0500);  // no temporary file can be made
  EXPECT_THROW(odelab::writeFileAtomically(path("m.json"), "new"), std::runtime_error);
  chmod(folder_.c_str(), 0700);
  EXPECT_EQ(read("m.json"), "old");
}

TEST_F(SafeFileTest, ASecondWriterOfAStreamedOutputIsRefused) {
  std::FILE* first = odelab::openExclusiveOutput(path("Test2_output.txt"));
  ASSERT_NE(first, nullptr);
  std::fputs("row of the first run\n", first);
  std::fflush(first);
  try {
    odelab::openExclusiveOutput(path("Test2_output.txt"));
    FAIL() << "a second writer was let in";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("another run"), std::string::npos) << error.what();
  }
  EXPECT_EQ(read("Test2_output.txt"), "row of the first run\n");  // not truncated by the refused one
  std::fclose(first);
  std::FILE* again = odelab::openExclusiveOutput(path("Test2_output.txt"));  // free once closed
  ASSERT_NE(again, nullptr);
  std::fclose(again);
}

TEST_F(SafeFileTest, AStreamedOutputIsNeverOpenedThroughALinkOrAFifo) {
  std::ofstream(path("target")) << "precious";
  ASSERT_EQ(symlink(path("target").c_str(), path("link").c_str()), 0);
  ASSERT_EQ(mkfifo(path("fifo").c_str(), 0600), 0);
  EXPECT_THROW(odelab::openExclusiveOutput(path("link")), std::runtime_error);
  EXPECT_THROW(odelab::openExclusiveOutput(path("fifo")), std::runtime_error);  // and does not hang
  EXPECT_EQ(read("target"), "precious");
}

TEST_F(SafeFileTest, SamePathResolvesFolders) {
  fs::create_directory(path("out"));
  EXPECT_TRUE(odelab::sameFilePath(path("out/Test2_output.txt"), path("out/../out/./Test2_output.txt")));
  EXPECT_FALSE(odelab::sameFilePath(path("out/Test2_output.txt"), path("Test2_output.txt")));
}

// 100,000 marks took 146 s with a linear search per set; a hash index makes
// it a fraction of a second. The figure is printed, not asserted.
TEST(MetricsAtScale, HundredThousandNamesKeepTheirOrderAndValues) {
  odelab::Metrics metrics;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 100000; ++i) metrics.set("mark_" + std::to_string(i) + "_steps", i);
  for (int i = 0; i < 100000; i += 7) metrics.set("mark_" + std::to_string(i) + "_steps", -i);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("100,000 metrics set (and 14,286 replaced) in %.3f s\n", seconds);
  ASSERT_EQ(metrics.entries().size(), 100000u);
  EXPECT_EQ(metrics.entries()[7].first, "mark_7_steps");
  EXPECT_EQ(metrics.get("mark_7_steps"), -7);
  EXPECT_EQ(metrics.get("mark_8_steps"), 8);
  EXPECT_TRUE(std::isnan(metrics.get("absent")));
}

TEST(DecimalInteger, ReadsDecimalOnly) {
  const CLI::Validator decimal = odelab::cli::decimalInteger();
  for (const auto& [in, out] : {std::pair<std::string, std::string>{"010", "10"}, {"08", "8"}, {"0", "0"},
                                {"000", "0"}, {"-007", "-7"}, {"+12", "12"}}) {
    std::string text = in;
    EXPECT_EQ(decimal(text), "") << in;
    EXPECT_EQ(text, out) << in;
  }
  for (std::string bad : {"0x10", "0b1", "1e1", "1.0", "", "-", " 1", "0o7"}) EXPECT_NE(decimal(bad), "") << bad;
}

}  // namespace
