// A folder's new content written beside it and put in its place only when complete (StagedFolder).
#include "multidir/core/common/staged_folder.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "support/test_models.h"

using namespace multidir;

namespace {

namespace fs = std::filesystem;

std::string scratch() {
  return test::scratchDirectory(std::string("StagedFolder.") +
                                testing::UnitTest::GetInstance()->current_test_info()->name());
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Every entry of a folder with its content.
std::map<std::string, std::string> contentOf(const std::string& folder) {
  std::map<std::string, std::string> entries;
  for (const auto& entry : fs::directory_iterator(folder))
    entries[entry.path().filename().string()] = readFile(entry.path().string());
  return entries;
}

std::size_t entriesIn(const std::string& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

}  // namespace

TEST(StagedFolder, ReplaceTargetPutsTheNewContentInPlaceAndRemovesTheOld) {
  const std::string dir = scratch();
  fs::create_directories(dir + "/job");
  writeFile(dir + "/job/old.txt", "old");
  ::chmod((dir + "/job").c_str(), 0750);
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(dir + "/job");
  ASSERT_TRUE(staged.ok()) << staged.error().describe();
  EXPECT_EQ(fs::path(staged->path()).parent_path(), fs::path(dir));
  writeFile(staged->path() + "/new.txt", "new");
  ASSERT_TRUE(staged->replaceTarget().ok());
  EXPECT_EQ(contentOf(dir + "/job"), (std::map<std::string, std::string>{{"new.txt", "new"}}));
  EXPECT_EQ(entriesIn(dir), 1u);  // the old content is gone, nothing is left beside
  struct stat info {};
  ASSERT_EQ(::stat((dir + "/job").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0750u);  // the folder's permissions, not mkdtemp's 0700
}

TEST(StagedFolder, ReplaceTargetCreatesAMissingTarget) {
  const std::string dir = scratch();
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(dir + "/job/");
  ASSERT_TRUE(staged.ok()) << staged.error().describe();
  writeFile(staged->path() + "/new.txt", "new");
  ASSERT_TRUE(staged->replaceTarget().ok());
  EXPECT_EQ(contentOf(dir + "/job"), (std::map<std::string, std::string>{{"new.txt", "new"}}));
}

TEST(StagedFolder, ADroppedStagedFolderLeavesTheTargetAsItWasAndNothingBeside) {
  const std::string dir = scratch();
  fs::create_directories(dir + "/job");
  writeFile(dir + "/job/old.txt", "old");
  {
    core::Result<core::StagedFolder> staged = core::StagedFolder::beside(dir + "/job");
    ASSERT_TRUE(staged.ok()) << staged.error().describe();
    writeFile(staged->path() + "/half.txt", "half");
  }
  EXPECT_EQ(contentOf(dir + "/job"), (std::map<std::string, std::string>{{"old.txt", "old"}}));
  EXPECT_EQ(entriesIn(dir), 1u);
}

TEST(StagedFolder, MoveEntriesIntoReplacesEntriesOfTheSameNameAndKeepsTheOthers) {
  const std::string dir = scratch();
  fs::create_directories(dir + "/mixed");
  writeFile(dir + "/mixed/notes.txt", "the user's");
  writeFile(dir + "/mixed/a.gcode", "old");
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(dir + "/mixed");
  ASSERT_TRUE(staged.ok()) << staged.error().describe();
  writeFile(staged->path() + "/a.gcode", "new");
  writeFile(staged->path() + "/print-job.json", "{}");
  ASSERT_TRUE(staged->moveEntriesInto("print-job.json").ok());
  EXPECT_EQ(contentOf(dir + "/mixed"), (std::map<std::string, std::string>{
                                           {"a.gcode", "new"}, {"notes.txt", "the user's"}, {"print-job.json", "{}"}}));
  EXPECT_EQ(entriesIn(dir), 1u);
}

TEST(StagedFolder, ATargetThatIsALinkToAFolderKeepsTheLink) {
  const std::string dir = scratch();
  fs::create_directories(dir + "/real");
  fs::create_directory_symlink(dir + "/real", dir + "/link");
  core::Result<core::StagedFolder> staged = core::StagedFolder::beside(dir + "/link");
  ASSERT_TRUE(staged.ok()) << staged.error().describe();
  writeFile(staged->path() + "/new.txt", "new");
  ASSERT_TRUE(staged->replaceTarget().ok());
  EXPECT_TRUE(fs::is_symlink(dir + "/link"));
  EXPECT_EQ(contentOf(dir + "/real"), (std::map<std::string, std::string>{{"new.txt", "new"}}));
}

TEST(StagedFolder, AMissingParentIsRefusedNamingIt) {
  const std::string dir = scratch();
  const core::Result<core::StagedFolder> staged = core::StagedFolder::beside(dir + "/no-such/job");
  ASSERT_FALSE(staged.ok());
  EXPECT_EQ(staged.error().code, core::ErrorCode::WriteFailed);
  EXPECT_EQ(staged.error().where, dir + "/no-such");
}
