// Tiles (or index runs) of families as chunks; greedy colouring through the particle-to-chunk incidence.
#include "assembly/family_colouring.hpp"

#include <algorithm>
#include <cmath>

namespace pd {

namespace {
// Families sorted by the square tile of side `side` holding their center (a counting
// sort, stable: by index within a tile); chunk_start receives the tiles' ranges.
void tile_order(const Particles& P, double side, std::vector<int>& order, std::vector<int>& chunk_start) {
  const int n = P.size(), d = P.dim;
  double lo[3] = {0, 0, 0};
  int cells[3] = {1, 1, 1};
  for (int c = 0; c < d; ++c) {
    double mn = P.x[c], mx = P.x[c];
    for (int p = 0; p < n; ++p) mn = std::min(mn, P.x[p * d + c]), mx = std::max(mx, P.x[p * d + c]);
    lo[c] = mn;
    cells[c] = static_cast<int>(std::floor((mx - mn) / side)) + 1;
  }
  std::vector<int> tile(static_cast<std::size_t>(n)),
      count(static_cast<std::size_t>(cells[0]) * cells[1] * cells[2] + 1, 0);
  for (int p = 0; p < n; ++p) {
    int key = 0;
    for (int c = d - 1; c >= 0; --c)
      key = key * cells[c] + std::min(cells[c] - 1, static_cast<int>((P.x[p * d + c] - lo[c]) / side));
    tile[p] = key;
    ++count[key + 1];
  }
  for (std::size_t t = 1; t < count.size(); ++t) count[t] += count[t - 1];
  order.resize(static_cast<std::size_t>(n));
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (int p = 0; p < n; ++p) order[fill[tile[p]]++] = p;
  chunk_start.assign(1, 0);
  for (std::size_t t = 1; t < count.size(); ++t)
    if (count[t] > count[t - 1]) chunk_start.push_back(count[t]);
}
}  // namespace

FamilyColouring::FamilyColouring(const Particles& P, const Bonds& B, int chunk_size) {
  const int n = B.particle_count();
  const double max_delta = B.delta.empty() ? 0.0 : *std::max_element(B.delta.begin(), B.delta.end());
  if (chunk_size == 0 && max_delta > 0 && n > 0) {
    tile_order(P, 2 * max_delta, order_, chunk_start_);
  } else {
    const int size = std::max(1, chunk_size);
    order_.resize(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p) order_[p] = p;
    for (int s = 0; s < n; s += size) chunk_start_.push_back(s);
    chunk_start_.push_back(n);
  }
  const int n_chunks = chunks();
  std::vector<int> chunk_of(static_cast<std::size_t>(n));
  for (int ch = 0; ch < n_chunks; ++ch)
    for (int j = chunk_start_[ch]; j < chunk_start_[ch + 1]; ++j) chunk_of[order_[j]] = ch;
  // touching[q]: chunks holding a family with particle q (ascending, deduplicated
  // because families are visited in chunk order).
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0), touching, last(static_cast<std::size_t>(n), -1);
  auto members = [&](int p, auto&& f) {
    f(p);
    for (int e = B.offsets[p]; e < B.offsets[p + 1]; ++e) f(B.neighbor[e]);
  };
  auto for_each_family_in_order = [&](auto&& f) {
    for (int j = 0; j < n; ++j) f(order_[j], chunk_of[order_[j]]);
  };
  for_each_family_in_order([&](int p, int ch) {
    members(p, [&](int q) {
      if (last[q] != ch) last[q] = ch, ++start[q + 1];
    });
  });
  for (int q = 0; q < n; ++q) start[q + 1] += start[q];
  touching.resize(static_cast<std::size_t>(start[n]));
  std::fill(last.begin(), last.end(), -1);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for_each_family_in_order([&](int p, int ch) {
      members(p, [&](int q) {
        if (last[q] != ch) last[q] = ch, touching[fill[q]++] = ch;
      });
    });
  }
  std::vector<int> colour(static_cast<std::size_t>(n_chunks), -1),
      used_by;  // used_by[c] = chunk that last saw colour c taken
  int n_colours = 0;
  for (int ch = 0; ch < n_chunks; ++ch) {
    for (int j = chunk_start_[ch]; j < chunk_start_[ch + 1]; ++j)
      members(order_[j], [&](int q) {
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
