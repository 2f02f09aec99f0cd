// The scene and study files themselves: a directory, a missing file or a device given as
// the file is named for what it is, not read as an empty YAML document ("dir:1: expected a map").
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "study/study.hpp"
#include "temp_files.hpp"

namespace {
template <class Read>
std::string error_of(Read read, const std::string& path) {
  try {
    read(path);
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "(no error)";
}
const auto scene = [](const std::string& p) { pd::read_scene(p); };
const auto study = [](const std::string& p) { pd::read_study(p); };
}  // namespace

TEST(InputFiles, ADirectoryAsTheSceneIsNamedAsADirectory) {
  const auto dir = pd::test::scratch_path("pd_input_files_cases");
  std::filesystem::create_directories(dir);
  EXPECT_EQ(error_of(scene, dir.string()),
            dir.string() + ": is a directory, not a scene file (give the .yaml file itself)");
  EXPECT_EQ(error_of(study, dir.string()),
            dir.string() + ": is a directory, not a study file (give the .yaml file itself)");
  std::filesystem::remove(dir);
}

TEST(InputFiles, AMissingFileAndADevice) {
  EXPECT_EQ(error_of(scene, "/nonexistent/s.yaml"), "/nonexistent/s.yaml: no such scene file");
  EXPECT_EQ(error_of(scene, "/dev/null"), "/dev/null: not a regular file, cannot read it as a scene file");
}

TEST(InputFiles, AStudyWhoseTopLevelIsNotAMap) {
  const auto path = pd::test::scratch_path("pd_input_files_list.yaml");
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("- a\n- b\n", f);
    std::fclose(f);
  }
  EXPECT_EQ(error_of(study, path.string()), path.string() + ":1: (top level): expected a map of keys");
  std::filesystem::remove(path);
}
