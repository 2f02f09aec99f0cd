// Greedy colouring of family chunks through the particle-to-chunk incidence.
#include "assembly/family_colouring.hpp"

#include <algorithm>

namespace pd {

FamilyColouring::FamilyColouring(const Bonds& B, int chunk_size) : n_(B.particle_count()) {
  // About 64 chunks per expected colour count leaves each of 2-8 threads several
  // chunks per colour; a chunk of at least 16 families amortises its bookkeeping.
  chunk_size_ = chunk_size > 0 ? chunk_size : std::clamp(n_ / 512, 16, 256);
  const int n_chunks = (n_ + chunk_size_ - 1) / chunk_size_;
  // touching[q]: chunks holding a family with particle q (ascending, deduplicated
  // because families are visited in chunk order).
  std::vector<int> start(static_cast<std::size_t>(n_) + 1, 0), touching, last(static_cast<std::size_t>(n_), -1);
  auto members = [&](int p, auto&& f) {
    f(p);
    for (int e = B.offsets[p]; e < B.offsets[p + 1]; ++e) f(B.neighbor[e]);
  };
  for (int p = 0; p < n_; ++p)
    members(p, [&](int q) {
      if (last[q] != p / chunk_size_) last[q] = p / chunk_size_, ++start[q + 1];
    });
  for (int q = 0; q < n_; ++q) start[q + 1] += start[q];
  touching.resize(static_cast<std::size_t>(start[n_]));
  std::fill(last.begin(), last.end(), -1);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int p = 0; p < n_; ++p)
      members(p, [&](int q) {
        if (last[q] != p / chunk_size_) last[q] = p / chunk_size_, touching[fill[q]++] = p / chunk_size_;
      });
  }
  std::vector<int> colour(static_cast<std::size_t>(n_chunks), -1), used_by;  // used_by[c] = chunk that last saw colour c taken
  int n_colours = 0;
  for (int ch = 0; ch < n_chunks; ++ch) {
    for (int p = ch * chunk_size_; p < std::min(n_, (ch + 1) * chunk_size_); ++p)
      members(p, [&](int q) {
        for (int i = start[q]; i < start[q + 1]; ++i) {
          const int c = colour[touching[i]];
          if (c >= 0) used_by[c] = ch;
        }
      });
    int c = 0;
    while (c < n_colours && used_by[c] == ch) ++c;
    if (c == n_colours) used_by.push_back(-1), ++n_colours;
    colour[ch] = c;
  }
  colour_start_.assign(static_cast<std::size_t>(n_colours) + 1, 0);
  for (int ch = 0; ch < n_chunks; ++ch) ++colour_start_[colour[ch] + 1];
  for (int c = 0; c < n_colours; ++c) colour_start_[c + 1] += colour_start_[c];
  chunk_ids_.resize(static_cast<std::size_t>(n_chunks));
  std::vector<int> fill(colour_start_.begin(), colour_start_.end() - 1);
  for (int ch = 0; ch < n_chunks; ++ch) chunk_ids_[fill[colour[ch]]++] = ch;
}

}  // namespace pd
