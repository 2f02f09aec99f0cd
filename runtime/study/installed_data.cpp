// The running executable's own data directory (installed_data.hpp).
#include "study/installed_data.hpp"

#include <system_error>

namespace pd {

std::filesystem::path installed_data_file(const std::string& name) {
  // /proc/self/exe names the binary actually running, wherever it was started from or
  // moved to (argv[0] may be a bare name found on PATH).
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path bin = ec ? std::filesystem::current_path() : exe.parent_path();
  return (bin / ".." / "share" / "pdgen" / name).lexically_normal();
}

}  // namespace pd
