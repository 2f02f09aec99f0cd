// Binary checkpoint records.
#include "dynamics/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "output/atomic_file.hpp"

namespace pd {

namespace {
const char kMagic[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '1'};

template <class T>
void put(std::string& s, const T& v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void put_name(std::string& s, const std::string& name) {
  put(s, static_cast<std::int32_t>(name.size()));
  s += name;
}
}  // namespace

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  std::string s(kMagic, sizeof kMagic);
  put(s, c.step);
  for (const auto& [name, values] : c.arrays) {
    put_name(s, name);
    put(s, static_cast<std::int64_t>(values.size()));
    s.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  }
  put_name(s, "text");
  put(s, static_cast<std::int64_t>(c.text.size()));
  s += c.text;
  put_name(s, "end");
  write_file_atomically(path, s);
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the checkpoint");
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string s = buf.str();
  std::size_t pos = 0;
  auto take = [&](void* out, std::size_t n) {
    if (pos + n > s.size()) throw std::runtime_error(path + ": the checkpoint is truncated");
    if (n == 0) return;  // an empty array's data() may be null, which memcpy must not get (UBSan)
    std::memcpy(out, s.data() + pos, n);
    pos += n;
  };
  char magic[8];
  take(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof magic) != 0) throw std::runtime_error(path + ": not a pd checkpoint");
  Checkpoint c;
  take(&c.step, sizeof c.step);
  for (;;) {
    std::int32_t len = 0;
    take(&len, sizeof len);
    if (len < 0 || len > 256) throw std::runtime_error(path + ": corrupt checkpoint record");
    std::string name(static_cast<std::size_t>(len), '\0');
    take(name.data(), name.size());
    if (name == "end") break;
    std::int64_t count = 0;
    take(&count, sizeof count);
    if (count < 0 || static_cast<std::uint64_t>(count) > s.size()) throw std::runtime_error(path + ": corrupt checkpoint record " + name);
    if (name == "text") {
      c.text.resize(static_cast<std::size_t>(count));
      take(c.text.data(), c.text.size());
    } else {
      std::vector<double> v(static_cast<std::size_t>(count));
      take(v.data(), v.size() * sizeof(double));
      c.arrays[name] = std::move(v);
    }
  }
  return c;
}

}  // namespace pd
