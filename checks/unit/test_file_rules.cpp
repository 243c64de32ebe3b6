// The one rule for writing and reading files (checks/file_rules.json), met
// by the C++ side: every "writer" case through the check before a run
// (whyNotWritable) and, where it lets the write go on, through both writers
// (writeFileAtomically, openExclusiveOutput); every "reader" case through
// the one bounded reader (readBoundedFile). The Node peers and the lab meet
// the same table with their own checks.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "SafeFile.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json loadRules() {
  std::ifstream in(ODELAB_FILE_RULES);
  if (!in) return json::object();  // the tests below fail, naming the file
  return json::parse(in);
}

std::vector<json> cases(const char* list) {
  static const json rules = loadRules();
  std::vector<json> out;
  if (rules.contains(list))
    for (const json& entry : rules.at(list)) out.push_back(entry);
  return out;
}

// What a case needs of the user running it; "" when it can run.
std::string skipReason(const json& entry) {
  const bool root = geteuid() == 0;
  if (entry.value("root_only", false) && !root) return "needs root (mknod)";
  if (entry.value("not_root", false) && root) return "root passes any permission";
  return "";
}

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Kind {
  bool exists, link, regular, fifo, chardev, folder;
  nlink_t links;
};
Kind kindOf(const std::string& path) {
  struct stat info {};
  if (lstat(path.c_str(), &info) != 0) return {false, false, false, false, false, false, 0};
  return {true, S_ISLNK(info.st_mode), S_ISREG(info.st_mode), S_ISFIFO(info.st_mode), S_ISCHR(info.st_mode),
          S_ISDIR(info.st_mode), info.st_nlink};
}

// A fresh folder per case, removed afterwards (write permission restored first).
class RuleFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/odelab_file_rules.XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    folder_ = pattern;
  }
  void TearDown() override {
    chmod(folder_.c_str(), 0700);
    fs::remove_all(folder_);
  }
  std::string path(const std::string& name) const { return folder_ + "/" + name; }
  int entries() const { return static_cast<int>(std::distance(fs::directory_iterator(folder_), {})); }
  std::string folder_;
};

// ---- writers ---------------------------------------------------------------------

enum class Writer { Atomic, Streamed };

struct WriterCase {
  json entry;
  Writer writer;
};
// How gtest names a case in its messages (not as a dump of bytes).
void PrintTo(const WriterCase& c, std::ostream* out) {
  *out << c.entry.dump() << (c.writer == Writer::Atomic ? " through writeFileAtomically" : " through openExclusiveOutput");
}

std::vector<WriterCase> writerCases() {
  std::vector<WriterCase> out;
  for (const json& entry : cases("writer"))
    for (Writer writer : {Writer::Atomic, Writer::Streamed}) out.push_back({entry, writer});
  return out;
}

class WriterRule : public RuleFolder, public ::testing::WithParamInterface<WriterCase> {
 protected:
  // Sets up what the case names at the target; returns the target's path.
  std::string plant(const std::string& setup) {
    const std::string target = path("target.out"), victim = path("victim");
    if (setup == "absent") return target;
    if (setup == "regular") {
      std::ofstream(target) << "old";
    } else if (setup == "symlink_to_regular") {
      std::ofstream(victim) << "precious";
      EXPECT_EQ(symlink(victim.c_str(), target.c_str()), 0);
    } else if (setup == "dangling_symlink") {
      EXPECT_EQ(symlink(victim.c_str(), target.c_str()), 0);
    } else if (setup == "hardlink") {
      std::ofstream(victim) << "precious";
      EXPECT_EQ(link(victim.c_str(), target.c_str()), 0);
    } else if (setup == "fifo") {
      EXPECT_EQ(mkfifo(target.c_str(), 0600), 0);
    } else if (setup == "char_device") {
      EXPECT_EQ(mknod(target.c_str(), S_IFCHR | 0600, makedev(1, 3)), 0);
    } else if (setup == "folder") {
      EXPECT_EQ(mkdir(target.c_str(), 0700), 0);
    } else if (setup == "missing_folder") {
      return path("missing/target.out");
    } else if (setup == "long_name") {
      return path(std::string(250, 'a'));
    } else if (setup == "read_only_folder") {
      EXPECT_EQ(chmod(folder_.c_str(), 0555), 0);
    } else {
      ADD_FAILURE() << "a setup this check does not know: " << setup;
    }
    return target;
  }

  // What the setup's description promises is still there after a refusal.
  void expectLeftAsItWas(const std::string& setup, const std::string& target) {
    const std::string victim = path("victim");
    const Kind kind = kindOf(target);
    if (setup == "symlink_to_regular") {
      EXPECT_TRUE(kind.link);
      EXPECT_EQ(contents(victim), "precious");
    } else if (setup == "dangling_symlink") {
      EXPECT_TRUE(kind.link);
      EXPECT_FALSE(kindOf(victim).exists);
    } else if (setup == "hardlink") {
      EXPECT_TRUE(kind.regular);
      EXPECT_EQ(kind.links, 2u);
      EXPECT_EQ(contents(victim), "precious");
    } else if (setup == "fifo") {
      EXPECT_TRUE(kind.fifo);
    } else if (setup == "char_device") {
      EXPECT_TRUE(kind.chardev);
    } else if (setup == "folder") {
      EXPECT_TRUE(kind.folder);
      EXPECT_TRUE(fs::is_empty(target));
    } else if (setup == "missing_folder") {
      EXPECT_FALSE(kindOf(path("missing")).exists);
    }
    // Nothing was created beside it: no output, no temporary file.
    const int planted = setup == "symlink_to_regular" || setup == "hardlink" ? 2
                        : setup == "dangling_symlink" || setup == "fifo" || setup == "char_device" || setup == "folder"
                            ? 1
                            : 0;
    EXPECT_EQ(entries(), planted);
  }

  static void write(Writer writer, const std::string& target, const std::string& bytes) {
    if (writer == Writer::Atomic) {
      odelab::writeFileAtomically(target, bytes);
      return;
    }
    std::FILE* file = odelab::openExclusiveOutput(target);
    ASSERT_EQ(std::fwrite(bytes.data(), 1, bytes.size(), file), bytes.size());
    ASSERT_EQ(std::fclose(file), 0);
  }
};

TEST_P(WriterRule, CheckBeforeTheRunThenWrite) {
  const json& entry = GetParam().entry;
  const std::string skip = skipReason(entry);
  if (!skip.empty()) GTEST_SKIP() << skip;
  const std::string setup = entry.at("setup");
  const std::string target = plant(setup);
  const std::string why = odelab::whyNotWritable(target);
  if (entry.at("expect") == "refused") {
    const std::string phrase = entry.at("why");
    EXPECT_NE(why.find(phrase), std::string::npos) << "refusal '" << why << "' lacks '" << phrase << "'";
    // The writer itself refuses too, should the target change after the check.
    if (GetParam().writer == Writer::Atomic) {
      EXPECT_THROW(write(Writer::Atomic, target, "new"), std::runtime_error);
    }
    expectLeftAsItWas(setup, target);
  } else {
    ASSERT_EQ(entry.at("expect"), "written");
    EXPECT_EQ(why, "");
    write(GetParam().writer, target, "new");
    EXPECT_EQ(contents(target), "new");
    EXPECT_EQ(entries(), 1);  // the target alone: no temporary file left
  }
}

std::string writerName(const ::testing::TestParamInfo<WriterCase>& info) {
  return info.param.entry.at("name").get<std::string>() + (info.param.writer == Writer::Atomic ? "_atomic" : "_streamed");
}

INSTANTIATE_TEST_SUITE_P(FileRules, WriterRule, ::testing::ValuesIn(writerCases()), writerName);

// ---- the bounded reader ----------------------------------------------------------------

class ReaderRule : public RuleFolder, public ::testing::WithParamInterface<json> {};

constexpr std::size_t LIMIT = 4096;  // the limit this check gives the reader

TEST_P(ReaderRule, ReadsOnlyASmallRegularFile) {
  const json& entry = GetParam();
  const std::string skip = skipReason(entry);
  if (!skip.empty()) GTEST_SKIP() << skip;
  const std::string setup = entry.at("setup");
  std::string input = path("input");
  if (setup == "regular") {
    std::ofstream(input) << "ok\n";
  } else if (setup == "absent") {
  } else if (setup == "folder") {
    ASSERT_EQ(mkdir(input.c_str(), 0700), 0);
  } else if (setup == "fifo") {
    ASSERT_EQ(mkfifo(input.c_str(), 0600), 0);  // no writer: opening it to read would block
  } else if (setup == "dev_zero") {
    input = "/dev/zero";
  } else if (setup == "oversized") {
    std::ofstream(input).close();
    ASSERT_EQ(truncate(input.c_str(), LIMIT + 1), 0);  // sparse
  } else {
    FAIL() << "a setup this check does not know: " << setup;
  }
  if (entry.at("expect") == "read") {
    EXPECT_EQ(odelab::readBoundedFile(input, LIMIT, "the input"), "ok\n");
    return;
  }
  ASSERT_EQ(entry.at("expect"), "refused");
  const std::string phrase = entry.at("why");
  try {
    odelab::readBoundedFile(input, LIMIT, "the input");
    ADD_FAILURE() << input << " was read";
  } catch (const odelab::ReadRefused& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cannot read the input '" + input + "': "), std::string::npos) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << "refusal '" << message << "' lacks '" << phrase << "'";
  }
}

std::string readerName(const ::testing::TestParamInfo<json>& info) { return info.param.at("name").get<std::string>(); }

INSTANTIATE_TEST_SUITE_P(FileRules, ReaderRule, ::testing::ValuesIn(cases("reader")), readerName);

// The table is there and names cases of both kinds (a missing or emptied
// table would otherwise pass with no case run).
TEST(FileRules, TableHasWriterAndReaderCases) {
  EXPECT_GE(cases("writer").size(), 10u) << ODELAB_FILE_RULES;
  EXPECT_GE(cases("reader").size(), 6u) << ODELAB_FILE_RULES;
}

}  // namespace
