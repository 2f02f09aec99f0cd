// VTK's encoded data blocks (input/particle_vtu.cpp reads the arrays): base64 text
// (VTK's "binary") or raw appended bytes, a UInt32 or UInt64 block header in either byte
// order, optionally vtkZLibDataCompressor blocks. Every error is a std::runtime_error
// saying what is wrong with the data; the reader adds the file, line and array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pd::vtu {

// How a file encodes its blocks (its VTKFile attributes).
struct BlockFormat {
  bool swap = false;     // the file's byte order is not the machine's
  int header_bytes = 4;  // UInt32 or UInt64 block headers
  bool zlib = false;
};

// RFC 4648 base64, whitespace skipped: the first `chars` characters of `text` from `from`.
std::string base64_decode(const std::string& text, std::size_t from, std::size_t chars);
// The base64 characters that encode `bytes` bytes.
std::size_t base64_chars(std::size_t bytes);

// Where the encoded bytes of one array come from: raw appended bytes, or base64 text.
struct Source {
  const std::string* text;
  std::size_t start;
  bool base64;
  std::size_t end = std::string::npos;  // raw data: where the appended section ends
  // `n` bytes at byte `at` of this block's decoded stream (base64 decodes from the start).
  std::string bytes(std::size_t at, std::size_t n) const;
  // A separately encoded base64 segment starting `chars` characters in (VTK encodes a
  // compressed block's header apart from its data).
  Source after_chars(std::size_t chars) const;
};

// zlib cannot pack more than 1032 bytes into one (deflate's longest match per code): what
// a file of n bytes can hold at most, and what a compressed block of n bytes can inflate to.
constexpr std::uint64_t kZlibMaxRatio = 1032;

// The bytes of a binary or appended array, after the block header and decompression. The
// array needs `expected` bytes: a header that claims another size is refused before
// anything is allocated for it (a block header is outside input, and so is its size), and
// so is a zlib block claiming more than zlib's largest ratio (1032:1) allows.
std::string block_data(const BlockFormat& d, const Source& s, std::uint64_t expected);

// Decoded bytes as doubles: values of `size` bytes of VTK type `type` (Float32, ..., UInt64;
// integers exact up to 2^53), byte-swapped when `swap`.
std::vector<double> values(const std::string& bytes, const std::string& type, std::size_t size, bool swap);

}  // namespace pd::vtu
