// Temporary file + rename.
#include "output/atomic_file.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "interrupt.hpp"
#include "output/run_id.hpp"

namespace pd {

void write_file_atomically(const std::string& path, std::string_view content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  if (ec) throw std::runtime_error("cannot create the directory of " + path + ": " + ec.message());
  throw_if_interrupted("before writing " + path);
  // Unique per run and per write: two runs (or two threads) writing one path never
  // share a temporary, and the last rename wins whole.
  static std::atomic<unsigned> writes{0};
  const std::string tmp = fmt::format("{}.{}.{}.tmp", path, run_id(), writes++);
  set_pending_temporary(tmp.c_str());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      set_pending_temporary(nullptr);
      throw std::runtime_error("cannot open " + tmp + " for writing");
    }
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      out.close();
      remove_pending_temporary();
      throw std::runtime_error("cannot write " + tmp + " (disk full?)");
    }
  }
  // A signal that arrived while writing: drop the temporary rather than publish a
  // result of a run the user has abandoned.
  if (interrupt_signal() != 0) {
    remove_pending_temporary();
    throw_if_interrupted("while writing " + path + " (the temporary file was removed)");
  }
  fs::rename(tmp, target, ec);
  set_pending_temporary(nullptr);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
  }
}

}  // namespace pd
