// The search order for shaders and the HUD font (utils/ResourcePaths.h):
// explicit choices shadow everything, then the executable's directory, the
// install's data folder, the source tree (for programs in the build folder
// only) and (fonts only) the system font; every place tried is listed.

#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ResourcePaths.h"

using odelab::ResourceLookup;
using odelab::ResourceSearch;

namespace {

const std::string SYSTEM_FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";

// A fresh directory under /tmp, removed with everything in it at the end.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    char pattern[] = "/tmp/odelab_paths_XXXXXX";
    path_ = ::mkdtemp(pattern);
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::string& path() const { return path_; }
  // Creates a small file (and its directories) under this one; returns its path.
  std::string make(const std::string& relativeFile) const {
    const std::filesystem::path full = std::filesystem::path(path_) / relativeFile;
    std::filesystem::create_directories(full.parent_path());
    std::ofstream(full) << "x";
    return full.string();
  }

 private:
  std::string path_;
};

// Sets (or, given nullptr, unsets) an environment variable for one test and
// restores it afterwards.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    const char* old = std::getenv(name);
    hadValue_ = old != nullptr;
    if (old) old_ = old;
    if (value)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnvironment() {
    if (hadValue_)
      ::setenv(name_, old_.c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  bool hadValue_ = false;
  std::string old_;
};

}  // namespace

TEST(ResourcePaths, ShaderOrderWithoutExplicitChoice) {
  const ResourceSearch search{"", "", "/opt/bin", "/opt/share/odelab", "/src/odelab"};
  EXPECT_EQ(odelab::shaderDirCandidates(search),
            (std::vector<std::string>{"/opt/bin/shaders", "/opt/share/odelab/shaders", "/src/odelab/shaders"}));
}

TEST(ResourcePaths, ShaderOptionIsTheOnlyPlaceTried) {
  const ResourceSearch search{"/mine", "/from/env", "/opt/bin", "/opt/share/odelab", "/src/odelab"};
  EXPECT_EQ(odelab::shaderDirCandidates(search), (std::vector<std::string>{"/mine"}));
}

TEST(ResourcePaths, ShaderEnvironmentShadowsDefaults) {
  const ResourceSearch search{"", "/from/env", "/opt/bin", "/opt/share/odelab", "/src/odelab"};
  EXPECT_EQ(odelab::shaderDirCandidates(search), (std::vector<std::string>{"/from/env"}));
}

TEST(ResourcePaths, UnknownDirectoriesAreSkipped) {
  const ResourceSearch search{"", "", "", "", ""};
  EXPECT_TRUE(odelab::shaderDirCandidates(search).empty());
  EXPECT_EQ(odelab::fontCandidates(search), (std::vector<std::string>{SYSTEM_FONT}));
}

TEST(ResourcePaths, FontOrderEndsWithSystemFont) {
  const ResourceSearch search{"", "", "/opt/bin/", "/opt/share/odelab", "/src/odelab"};
  EXPECT_EQ(odelab::fontCandidates(search),
            (std::vector<std::string>{"/opt/bin/fonts/DejaVuSansMono.ttf", "/opt/share/odelab/fonts/DejaVuSansMono.ttf",
                                      "/src/odelab/fonts/DejaVuSansMono.ttf", SYSTEM_FONT}));
}

TEST(ResourcePaths, FontOptionIsTheOnlyPlaceTried) {
  const ResourceSearch search{"/my/font.ttf", "/env/font.ttf", "/opt/bin", "/opt/share/odelab", "/src/odelab"};
  EXPECT_EQ(odelab::fontCandidates(search), (std::vector<std::string>{"/my/font.ttf"}));
}

TEST(ResourcePaths, InstalledDataDirIsSeenFromTheProgramFolder) {
  EXPECT_EQ(odelab::installedDataDirectory("/opt/odelab/bin", "../share/odelab"), "/opt/odelab/share/odelab");
  EXPECT_EQ(odelab::installedDataDirectory("/opt/odelab/bin/", "../share/odelab/"), "/opt/odelab/share/odelab");
  // A layout with data beside the programs (DATADIR under BINDIR).
  EXPECT_EQ(odelab::installedDataDirectory("/opt/odelab", "share/odelab"), "/opt/odelab/share/odelab");
  EXPECT_EQ(odelab::installedDataDirectory("", "../share/odelab"), "");
}

TEST(ResourcePaths, SourceTreeOnlyForProgramsInTheBuildFolder) {
  EXPECT_EQ(odelab::sourceTreeFor("/src/build/tests", "/src/build", "/src"), "/src");
  EXPECT_EQ(odelab::sourceTreeFor("/src/build", "/src/build", "/src"), "/src");
  // An installed copy, and a folder whose name merely starts like the build's.
  EXPECT_EQ(odelab::sourceTreeFor("/usr/local/bin", "/src/build", "/src"), "");
  EXPECT_EQ(odelab::sourceTreeFor("/src/build-other/tests", "/src/build", "/src"), "");
  // Where the program's folder or the build's is unknown, the tree is all there is.
  EXPECT_EQ(odelab::sourceTreeFor("", "/src/build", "/src"), "/src");
  EXPECT_EQ(odelab::sourceTreeFor("/usr/local/bin", "", "/src"), "/src");
}

TEST(ResourcePaths, InstalledLayoutFindsItsOwnShaders) {
  // prefix/bin/<program> and prefix/share/odelab/shaders, as `cmake --install` lays them out.
  TemporaryDirectory prefix;
  prefix.make("share/odelab/shaders/scene.vert");
  const std::string bin = prefix.path() + "/bin";
  const ResourceSearch search{"", "", bin, odelab::installedDataDirectory(bin, "../share/odelab"),
                              odelab::sourceTreeFor(bin, "/src/build", "/src")};
  const ResourceLookup lookup = odelab::findFirst(odelab::shaderDirCandidates(search), odelab::isShaderDir);
  EXPECT_EQ(lookup.found, prefix.path() + "/share/odelab/shaders");
  EXPECT_EQ(lookup.tried, (std::vector<std::string>{bin + "/shaders", prefix.path() + "/share/odelab/shaders"}));
}

TEST(ResourcePaths, FindFirstStopsAtFirstAcceptedAndRecordsTried) {
  TemporaryDirectory first, second, third;
  second.make("scene.vert");
  third.make("scene.vert");
  const ResourceLookup lookup =
      odelab::findFirst({first.path(), second.path(), third.path()}, odelab::isShaderDir);
  EXPECT_EQ(lookup.found, second.path());
  EXPECT_EQ(lookup.tried, (std::vector<std::string>{first.path(), second.path()}));
}

TEST(ResourcePaths, NothingFoundListsEveryPlace) {
  const ResourceLookup lookup = odelab::findFirst({"/nonexistent/a", "/nonexistent/b"}, odelab::isShaderDir);
  EXPECT_FALSE(lookup.ok());
  EXPECT_EQ(lookup.triedList(), "/nonexistent/a, /nonexistent/b");
}

TEST(ResourcePaths, DirectoryWithoutSceneVertDoesNotCount) {
  TemporaryDirectory directory;
  directory.make("depth.vert");
  EXPECT_FALSE(odelab::isShaderDir(directory.path()));
  EXPECT_FALSE(odelab::isReadableFile(directory.path()));  // a directory is not a font
}

TEST(ResourcePaths, WrongShaderOptionIsReportedNotBypassed) {
  const ResourceLookup lookup = odelab::findShaderDir("/nonexistent/shaders");
  EXPECT_FALSE(lookup.ok());
  EXPECT_EQ(lookup.tried, (std::vector<std::string>{"/nonexistent/shaders"}));
}

TEST(ResourcePaths, ShaderEnvironmentVariableIsUsed) {
  TemporaryDirectory directory;
  directory.make("scene.vert");
  const ScopedEnvironment environment("ODELAB_SHADER_DIR", directory.path().c_str());
  EXPECT_EQ(odelab::findShaderDir("").found, directory.path());
  // The option still wins over the environment.
  EXPECT_FALSE(odelab::findShaderDir("/nonexistent/shaders").ok());
}

TEST(ResourcePaths, FontEnvironmentVariableIsUsed) {
  TemporaryDirectory directory;
  const std::string font = directory.make("some.ttf");
  const ScopedEnvironment environment("ODELAB_FONT", font.c_str());
  EXPECT_EQ(odelab::findFont("").found, font);
  const ResourceLookup wrong = odelab::findFont(directory.path() + "/missing.ttf");
  EXPECT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.tried.size(), 1u);
}

TEST(ResourcePaths, RealSearchStartsNextToTheExecutable) {
  const ScopedEnvironment environment("ODELAB_SHADER_DIR", nullptr);
  const std::string executableDir = odelab::executableDirectory();
  ASSERT_FALSE(executableDir.empty());
  const ResourceLookup lookup = odelab::findShaderDir("");
  ASSERT_FALSE(lookup.tried.empty());
  EXPECT_EQ(lookup.tried.front(), executableDir + "/shaders");
}

TEST(ResourcePaths, DefaultSearchFindsTheRepositoryShaders) {
  // The build defines ODELAB_SOURCE_DIR, and this test runs inside the build
  // folder, so the repository's shaders/ qualifies.
  const ScopedEnvironment environment("ODELAB_SHADER_DIR", nullptr);
  EXPECT_TRUE(odelab::findShaderDir("").ok());
}

// Issue 15: a FIFO as a shader hung the window, /dev/zero exhausted memory.
TEST(ReadSmallRegularFile, RefusesFifosDevicesAndLargeFiles) {
  const std::string folder = std::filesystem::temp_directory_path() / "odelab_small_file_test";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directory(folder);
  const std::string fifo = folder + "/shader.frag", big = folder + "/big.frag", small = folder + "/small.frag";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::ofstream(big) << std::string(odelab::MAX_SHADER_BYTES + 1, ' ');
  std::ofstream(small) << "void main() {}\n";
  for (const std::string& path : {fifo, std::string("/dev/zero"), big, folder}) {
    try {
      odelab::readSmallRegularFile(path, odelab::MAX_SHADER_BYTES);
      ADD_FAILURE() << path << " was read";
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
  }
  EXPECT_EQ(odelab::readSmallRegularFile(small, odelab::MAX_SHADER_BYTES), "void main() {}\n");
  std::filesystem::remove_all(folder);
}
