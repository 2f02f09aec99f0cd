// VTK's encoded data blocks: base64, block headers, zlib (vtu_blocks.hpp).
#include "input/vtu_blocks.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <stdexcept>

namespace pd::vtu {

namespace {
std::uint64_t header_value(const BlockFormat& d, const std::string& bytes, std::size_t k) {
  std::string b = bytes.substr(k * d.header_bytes, d.header_bytes);
  if (d.swap) std::reverse(b.begin(), b.end());
  if (d.header_bytes == 8) {
    std::uint64_t v;
    std::memcpy(&v, b.data(), 8);
    return v;
  }
  std::uint32_t v;
  std::memcpy(&v, b.data(), 4);
  return v;
}

}  // namespace

std::string base64_decode(const std::string& text, std::size_t from, std::size_t chars) {
  std::string clean;
  for (std::size_t k = from; k < text.size() && clean.size() < chars; ++k)
    if (!std::isspace(static_cast<unsigned char>(text[k]))) clean += text[k];
  if (clean.size() < chars) throw std::runtime_error("the base64 data ends early");
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    if (c == '=') return -1;
    throw std::runtime_error(fmt::format("'{}' is not a base64 character", c));
  };
  std::string out;
  for (std::size_t k = 0; k + 3 < clean.size(); k += 4) {
    int v[4];
    for (int j = 0; j < 4; ++j) v[j] = value(clean[k + j]);
    if (v[0] < 0 || v[1] < 0) throw std::runtime_error("misplaced base64 padding");
    out += static_cast<char>(v[0] << 2 | v[1] >> 4);
    if (v[2] >= 0) out += static_cast<char>((v[1] & 15) << 4 | v[2] >> 2);
    if (v[2] >= 0 && v[3] >= 0) out += static_cast<char>((v[2] & 3) << 6 | v[3]);
  }
  return out;
}
std::size_t base64_chars(std::size_t bytes) { return 4 * ((bytes + 2) / 3); }

std::string Source::bytes(std::size_t at, std::size_t n) const {
  if (!base64) {
    if (start + at + n > std::min(end, text->size()))
      throw std::runtime_error("the data ends before the array does");
    return text->substr(start + at, n);
  }
  const std::string all = base64_decode(*text, start, base64_chars(at + n));
  if (all.size() < at + n) throw std::runtime_error("the base64 data ends before the array does");
  return all.substr(at, n);
}

Source Source::after_chars(std::size_t chars) const {
  std::size_t k = start, seen = 0;
  while (k < text->size() && seen < chars)
    seen += std::isspace(static_cast<unsigned char>((*text)[k++])) ? 0 : 1;
  return Source{text, k, true};
}

std::string block_data(const BlockFormat& d, const Source& s, std::uint64_t expected) {
  const std::size_t hb = static_cast<std::size_t>(d.header_bytes);
  const auto claims = [expected](std::uint64_t bytes) {
    return std::runtime_error(
        fmt::format("the block header claims {} bytes where the array needs {}", bytes, expected));
  };
  if (!d.zlib) {
    const std::uint64_t n = header_value(d, s.bytes(0, hb), 0);
    if (n != expected) throw claims(n);
    return s.bytes(hb, n);
  }
  // [#blocks][block size][last block size][compressed size of each block], then the
  // zlib streams one after the other (in base64 the header is encoded on its own).
  const std::uint64_t blocks = header_value(d, s.bytes(0, hb), 0);
  if (blocks > expected + 1) throw std::runtime_error(fmt::format("{} compressed blocks", blocks));
  const std::size_t header_size = hb * (3 + blocks);
  const std::string header = s.bytes(0, header_size);
  const std::uint64_t block_size = header_value(d, header, 1), last = header_value(d, header, 2);
  // VTK writes its nominal block size (32768 by default) even when one partial block holds
  // the whole array: the size is (blocks - 1) * block_size + the last block's.
  if (blocks > 0) {
    const std::uint64_t final_block = last != 0 ? last : block_size;
    if (last > block_size) throw claims(last);
    if (blocks > 1 && (block_size == 0 || blocks - 1 > expected / block_size)) throw claims(block_size);
    if ((blocks - 1) * block_size + final_block != expected)  // no overflow: checked above
      throw claims((blocks - 1) * block_size + final_block);
  } else if (expected != 0) {
    throw claims(0);
  }
  const Source data = s.base64 ? s.after_chars(base64_chars(header_size))
                               : Source{s.text, s.start + header_size, false, s.end};
  // The compressed sizes bound the output (kZlibMaxRatio): a block claiming more is damaged,
  // and so are blocks that together are longer than the file.
  constexpr std::uint64_t kZlibOverhead = 64;
  std::uint64_t total = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = header_value(d, header, 3 + b);
    const std::uint64_t size = (b + 1 == blocks && last != 0) ? last : block_size;
    if (csize > s.text->size() || size > kZlibMaxRatio * csize + kZlibOverhead)
      throw std::runtime_error(
          fmt::format("zlib block {}: {} compressed bytes cannot hold {} bytes", b, csize, size));
    total += csize;  // each term <= the file's size, and the sum is checked against it: no overflow
    if (total > s.text->size())
      throw std::runtime_error(fmt::format("the zlib blocks are longer than the file ({} bytes)", total));
  }
  const std::string packed = data.bytes(0, total);
  std::string out;
  std::size_t at = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = header_value(d, header, 3 + b);
    uLongf size = (b + 1 == blocks && last != 0) ? last : block_size;
    std::string chunk(size, '\0');
    if (uncompress(reinterpret_cast<Bytef*>(chunk.data()), &size,
                   reinterpret_cast<const Bytef*>(packed.data() + at), csize) != Z_OK)
      throw std::runtime_error(fmt::format("zlib block {} does not decompress", b));
    chunk.resize(size);
    out += chunk;
    at += csize;
  }
  if (out.size() != expected)
    throw std::runtime_error(
        fmt::format("the zlib blocks hold {} bytes where the array needs {}", out.size(), expected));
  return out;
}

std::vector<double> values(const std::string& bytes, const std::string& type, std::size_t size, bool swap) {
  std::vector<double> out;
  out.resize(bytes.size() / size);
  for (std::size_t k = 0; k < out.size(); ++k) {
    char b[8];
    std::memcpy(b, bytes.data() + k * size, size);
    if (swap) std::reverse(b, b + size);
    auto get = [&]<class T>(T) {
      T v;
      std::memcpy(&v, b, sizeof v);
      return static_cast<double>(v);
    };
    if (type == "Float32")
      out[k] = get(float{});
    else if (type == "Float64")
      out[k] = get(double{});
    else if (type == "Int8")
      out[k] = get(std::int8_t{});
    else if (type == "UInt8")
      out[k] = get(std::uint8_t{});
    else if (type == "Int16")
      out[k] = get(std::int16_t{});
    else if (type == "UInt16")
      out[k] = get(std::uint16_t{});
    else if (type == "Int32")
      out[k] = get(std::int32_t{});
    else if (type == "UInt32")
      out[k] = get(std::uint32_t{});
    else if (type == "Int64")
      out[k] = get(std::int64_t{});
    else
      out[k] = get(std::uint64_t{});
  }
  return out;
}

}  // namespace pd::vtu
