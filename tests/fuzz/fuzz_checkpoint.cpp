// Fuzz target for the checkpoint reader (`pd run --restart`): any input must either parse
// or raise CheckpointError -- never crash, hang, leak, trip a sanitizer or allocate what
// a record's count merely claims. A random input almost never carries a valid FNV-1a
// checksum, so each input is read twice: as it is (the header and checksum checks), and
// with its last 8 bytes replaced by the checksum of the rest, which lets the fuzzer into
// the identity block and the records behind the checksum.
//
// Built with clang as `fuzz_checkpoint` (PD_FUZZ); without libFuzzer the same entry point
// replays tests/fuzz/corpus/checkpoint/ as a ctest (replay_main.cpp).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "dynamics/checkpoint.hpp"
#include "fuzz_verdict.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    pd::parse_checkpoint(bytes, "fuzz.ckpt");
    pdfuzz::accepted = true;  // as it is, not after the checksum is re-stamped
  } catch (const pd::CheckpointError&) {
  }
  if (bytes.size() >= sizeof(std::uint64_t)) {
    const std::size_t body = bytes.size() - sizeof(std::uint64_t);
    const std::uint64_t hash = pd::fnv1a(bytes.data(), body);
    std::memcpy(bytes.data() + body, &hash, sizeof hash);
    try {
      pd::parse_checkpoint(bytes, "fuzz.ckpt");
    } catch (const pd::CheckpointError&) {
    }
  }
  return 0;
}
