// A run id made once per process.
#include "output/run_id.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <ctime>
#include <random>

namespace pd {

const std::string& run_id() {
  static const std::string id = [] {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &utc);
    std::random_device random;
    return fmt::format("{}-{}-{:08x}", stamp, static_cast<long>(::getpid()), random());
  }();
  return id;
}

}  // namespace pd
