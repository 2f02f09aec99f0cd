// Binary checkpoint records.
#include "dynamics/checkpoint.hpp"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "output/atomic_file.hpp"

namespace pd {

namespace {
const char kMagic[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '2'};
const std::uint32_t kByteOrder = 0x01020304;

template <class T>
void put(std::string& s, const T& v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void put_name(std::string& s, const std::string& name) {
  put(s, static_cast<std::int32_t>(name.size()));
  s += name;
}
std::string identity_text(const std::map<std::string, std::string>& identity) {
  std::string t;
  for (const auto& [key, value] : identity) t += key + "=" + value + "\n";
  return t;
}
std::map<std::string, std::string> parse_identity(const std::string& path, const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw CheckpointError(path + ": corrupt checkpoint identity line '" + line + "'");
    out[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return out;
}
}  // namespace

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
  return hash;
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  std::string s(kMagic, sizeof kMagic);
  put(s, kByteOrder);
  const std::string identity = identity_text(c.identity);
  put(s, static_cast<std::int64_t>(identity.size()));
  s += identity;
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
  put(s, fnv1a(s.data(), s.size()));
  write_file_atomically(path, s);
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot open the checkpoint");
  std::ostringstream buf;
  buf << in.rdbuf();
  return parse_checkpoint(buf.str(), path);
}

Checkpoint parse_checkpoint(const std::string& s, const std::string& path) {
  std::size_t pos = 0;
  auto take = [&](void* out, std::size_t n) {
    if (pos + n > s.size()) throw CheckpointError(path + ": the checkpoint is truncated");
    if (n == 0) return;  // an empty array's data() may be null, which memcpy must not get (UBSan)
    std::memcpy(out, s.data() + pos, n);
    pos += n;
  };
  char magic[8];
  take(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, 6) != 0) throw CheckpointError(path + ": not a pd checkpoint");
  if (std::memcmp(magic, kMagic, sizeof magic) != 0)
    throw CheckpointError(
        fmt::format("{}: a checkpoint of format {} (this pd reads {}): run the scene again from the start",
                    path, std::string(magic, 8), std::string(kMagic, 8)));
  std::uint32_t order = 0;
  take(&order, sizeof order);
  if (order != kByteOrder)
    throw CheckpointError(
        path +
        ": the checkpoint was written on a machine of the other byte order (endianness); it "
        "can only be resumed on one like it");
  std::uint64_t stored = 0;
  if (s.size() < pos + sizeof stored) throw CheckpointError(path + ": the checkpoint is truncated");
  std::memcpy(&stored, s.data() + s.size() - sizeof stored, sizeof stored);
  if (fnv1a(s.data(), s.size() - sizeof stored) != stored)
    throw CheckpointError(
        path +
        ": the checkpoint is damaged (its checksum does not match its contents: a truncated "
        "copy or flipped bits); use an intact copy or run again from the start");
  const std::size_t end = s.size() - sizeof stored;
  auto take_checked = [&](void* out, std::size_t n) {
    if (pos + n > end) throw CheckpointError(path + ": corrupt checkpoint record");
    take(out, n);
  };
  Checkpoint c;
  std::int64_t identity_bytes = 0;
  take_checked(&identity_bytes, sizeof identity_bytes);
  if (identity_bytes < 0 || static_cast<std::uint64_t>(identity_bytes) > end)
    throw CheckpointError(path + ": corrupt checkpoint identity");
  std::string identity(static_cast<std::size_t>(identity_bytes), '\0');
  take_checked(identity.data(), identity.size());
  c.identity = parse_identity(path, identity);
  take_checked(&c.step, sizeof c.step);
  for (;;) {
    std::int32_t len = 0;
    take_checked(&len, sizeof len);
    if (len < 0 || len > 256) throw CheckpointError(path + ": corrupt checkpoint record");
    std::string name(static_cast<std::size_t>(len), '\0');
    take_checked(name.data(), name.size());
    if (name == "end") break;
    std::int64_t count = 0;
    take_checked(&count, sizeof count);
    if (count < 0 || static_cast<std::uint64_t>(count) > s.size())
      throw CheckpointError(path + ": corrupt checkpoint record " + name);
    if (name == "text") {
      c.text.resize(static_cast<std::size_t>(count));
      take_checked(c.text.data(), c.text.size());
    } else {
      std::vector<double> v(static_cast<std::size_t>(count));
      take_checked(v.data(), v.size() * sizeof(double));
      c.arrays[name] = std::move(v);
    }
  }
  return c;
}

}  // namespace pd
