// Saving never writes through a file an attacker (or an old crash) left beside the target.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "multidir/core/mesh/mesh_io.h"
#include "support/mesh_fixtures.h"
#include "support/test_models.h"

using namespace multidir::core;
namespace fs = std::filesystem;

namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST(MeshSave, DoesNotFollowASymlinkPlantedAtTheOldTemporaryName) {
  const std::string dir = multidir::test::scratchDirectory("MeshSave_PlantedSymlink");
  const std::string victim = dir + "/victim.txt";
  std::ofstream(victim) << "precious";
  const std::string target = dir + "/cube.stl";
  fs::create_symlink(victim, target + ".partial");

  ASSERT_TRUE(saveMesh(multidir::test::cubeMesh(), target).ok());

  EXPECT_EQ(readAll(victim), "precious") << "the save wrote through the planted link";
  EXPECT_TRUE(fs::is_symlink(target + ".partial")) << "a file the save did not create is left alone";
  EXPECT_FALSE(fs::is_symlink(target));
  EXPECT_EQ(fs::file_size(target), 84u + 12u * 50u);
}

TEST(MeshSave, LeavesNoTemporaryFileBehind) {
  const std::string dir = multidir::test::scratchDirectory("MeshSave_NoTemporary");
  ASSERT_TRUE(saveMesh(multidir::test::cubeMesh(), dir + "/cube.off").ok());
  ASSERT_FALSE(saveMesh(multidir::test::cubeMesh(), dir + "/no-such-folder/cube.off").ok());
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "cube.off");
  }
  EXPECT_EQ(files, 1u);
}

TEST(MeshSave, ReplacesALinkAtTheTargetInsteadOfWritingThroughIt) {
  const std::string dir = multidir::test::scratchDirectory("MeshSave_LinkAtTarget");
  const std::string victim = dir + "/victim.txt";
  std::ofstream(victim) << "precious";
  const std::string target = dir + "/cube.obj";
  fs::create_symlink(victim, target);

  ASSERT_TRUE(saveMesh(multidir::test::cubeMesh(), target).ok());

  EXPECT_EQ(readAll(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(target));
  EXPECT_TRUE(loadMesh(target).ok());
}
