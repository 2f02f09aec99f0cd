// Writing a run's files aside and publishing them together.
#include "output/staging.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/run_id.hpp"

namespace pd {

namespace {
namespace fs = std::filesystem;
constexpr const char* kPrefix = "unfinished-";
constexpr const char* kManifest = ".pd.files";

// A manifest line names a file under DIR: relative, without "..".
bool inside(const std::string& name) {
  const fs::path p(name);
  if (name.empty() || p.is_absolute()) return false;
  for (const auto& part : p)
    if (part == "..") return false;
  return true;
}
}  // namespace

StagingDirectory::StagingDirectory(const std::string& directory)
    : directory_(directory.empty() ? "." : directory), staging_(directory_ + "/" + kPrefix + run_id()) {
  std::error_code ec;
  fs::create_directory(staging_, ec);
  if (ec)
    throw std::runtime_error(
        fmt::format("{}: cannot create the staging directory: {}", staging_, ec.message()));
}

StagingDirectory::~StagingDirectory() {
  if (published_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

std::vector<std::string> StagingDirectory::leftovers() const {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(directory_, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && name.rfind(kPrefix, 0) == 0 && e.path() != fs::path(staging_))
      out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> StagingDirectory::publish() {
  const fs::path dir(directory_), staged(staging_);
  std::vector<std::string>
      names;  // relative to the staging directory: "result.vtu", "snapshots/step_00000010.vtu"
  for (const auto& e : fs::recursive_directory_iterator(staged))
    if (e.is_regular_file() && e.path().extension() != ".tmp")
      names.push_back(fs::relative(e.path(), staged).generic_string());
  std::sort(names.begin(), names.end());
  std::error_code ec;
  if (names.empty()) {  // a run that wrote nothing leaves DIR as it was
    fs::remove_all(staged, ec);
    published_ = true;
    return names;
  }
  // From here until summary.json arrives, DIR has no summary.json: an unfinished result.
  fs::remove(dir / "summary.json");
  std::ifstream manifest(dir / kManifest);
  for (std::string old; std::getline(manifest, old);)
    if (inside(old) && old != kManifest) {
      fs::remove(dir / old, ec);
      const fs::path parent = fs::path(old).parent_path();
      if (!parent.empty() && fs::is_empty(dir / parent, ec)) fs::remove(dir / parent, ec);
    }
  std::string list;
  for (const std::string& n : names) {
    list += n + "\n";
    if (n == "summary.json") continue;
    if (fs::path(n).has_parent_path()) fs::create_directories(dir / fs::path(n).parent_path());
    fs::rename(staged / n, dir / n);
  }
  write_file_atomically((dir / kManifest).string(), list);
  if (std::find(names.begin(), names.end(), "summary.json") != names.end()) {
    // The run named its files where it wrote them: name them where they are now.
    std::ifstream in(staged / "summary.json");
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(in, nullptr, false);
    if (!j.is_discarded() && j.contains("files") && j["files"].is_array())
      for (auto& f : j["files"])
        if (f.is_string() && f.get<std::string>().rfind(staging_ + "/", 0) == 0)
          f = directory_ + f.get<std::string>().substr(staging_.size());
    in.close();
    if (!j.is_discarded()) write_file_atomically((staged / "summary.json").string(), j.dump(2) + "\n");
    fs::rename(staged / "summary.json", dir / "summary.json");
  }
  fs::remove_all(staged, ec);  // only temporaries of a stopped write can be left in it
  published_ = true;
  return names;
}

}  // namespace pd
