// Discretisation: particle counts for boxes, holes and inclusions (against an
// independent count over the lattice), volumes, the seeded perturbation, and node sets
// by region on perturbed clouds.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "discretize/discretization.hpp"
#include "input/yaml_keys.hpp"

namespace {

pd::Scene box_scene(int dim, double h) {
  pd::Scene s;
  s.file = "test.yaml";
  s.dim = dim;
  s.lo = {0, 0, 0};
  s.hi = {2, 1.5, 1};
  s.h = h;
  s.materials.resize(2);
  s.materials[1].name = "soft";
  return s;
}

// Independent count: cell centres (i + 1/2) h over the box that `keep` accepts.
int count_cells(const pd::Scene& s, const std::function<bool(const double*)>& keep) {
  int n[3] = {1, 1, 1};
  for (int c = 0; c < s.dim; ++c) n[c] = static_cast<int>(std::lround((s.hi[c] - s.lo[c]) / s.h));
  int count = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double x[3] = {s.lo[0] + (i + 0.5) * s.h, s.lo[1] + (j + 0.5) * s.h, s.lo[2] + (k + 0.5) * s.h};
        count += keep(x);
      }
  return count;
}

pd::Shape circle(double cx, double cy, double cz, double r) {
  pd::Shape c;
  c.kind = pd::Shape::Kind::Circle;
  c.center = {cx, cy, cz};
  c.radius = r;
  return c;
}

}  // namespace

TEST(Lattice, BoxCountsAndVolumes) {
  for (int dim : {2, 3}) {
    const pd::Scene s = box_scene(dim, 0.125);
    const pd::Particles p = pd::discretize(s);
    EXPECT_EQ(p.size(), dim == 2 ? 16 * 12 : 16 * 12 * 8);
    double total = 0;
    for (double v : p.volume) total += v;
    EXPECT_NEAR(total, dim == 2 ? 3.0 : 3.0, 1e-12);  // 2 x 1.5 (x 1)
    for (int i = 0; i < p.size(); ++i)
      for (int c = 0; c < dim; ++c) {
        EXPECT_GT(p.position(i)[c], s.lo[c]);
        EXPECT_LT(p.position(i)[c], s.hi[c]);
      }
  }
}

TEST(Lattice, NodePlacementIncludesTheFaces) {
  pd::Scene s = box_scene(2, 0.25);
  s.placement = pd::Placement::node;
  const pd::Particles p = pd::discretize(s);
  EXPECT_EQ(p.size(), 9 * 7);
  int on_corner = 0;
  for (int i = 0; i < p.size(); ++i) on_corner += p.position(i)[0] == 2.0 && p.position(i)[1] == 1.5;
  EXPECT_EQ(on_corner, 1);
}

TEST(Lattice, HolesRemoveExactlyTheCellsInside) {
  pd::Scene s = box_scene(2, 0.05);
  s.holes.push_back(circle(0.6, 0.75, 0, 0.3));
  pd::Shape tri;
  tri.kind = pd::Shape::Kind::Polygon;
  tri.vertices = {pd::Point{1.21, 0.21, 0}, pd::Point{1.91, 0.33, 0},
                  pd::Point{1.52, 1.31, 0}};  // edges miss the lattice
  s.holes.push_back(tri);
  pd::Shape box;
  box.kind = pd::Shape::Kind::Box;
  box.min = {0.05, 1.2, 0};
  box.max = {0.45, 1.45, 0};
  s.holes.push_back(box);
  auto in_triangle = [](const double* x) {
    // Barycentric test, independent of the even-odd rule used by the code.
    const double ax = 1.21, ay = 0.21, bx = 1.91, by = 0.33, cx = 1.52, cy = 1.31;
    const double d = (by - cy) * (ax - cx) + (cx - bx) * (ay - cy);
    const double l1 = ((by - cy) * (x[0] - cx) + (cx - bx) * (x[1] - cy)) / d;
    const double l2 = ((cy - ay) * (x[0] - cx) + (ax - cx) * (x[1] - cy)) / d;
    return l1 > 0 && l2 > 0 && 1 - l1 - l2 > 0;
  };
  const int expected = count_cells(s, [&](const double* x) {
    const bool in_circle = std::hypot(x[0] - 0.6, x[1] - 0.75) <= 0.3;
    const bool in_box = x[0] >= 0.05 && x[0] <= 0.45 && x[1] >= 1.2 && x[1] <= 1.45;
    return !(in_circle || in_triangle(x) || in_box);
  });
  const pd::Particles p = pd::discretize(s);
  EXPECT_EQ(p.size(), expected);
  EXPECT_LT(p.size(), 40 * 30);
  // The removed area approaches the shapes' area (lattice error ~ perimeter x h / 2).
  const double triangle = 0.5 * std::fabs((1.91 - 1.21) * (1.31 - 0.21) - (1.52 - 1.21) * (0.33 - 0.21));
  const double removed = (40 * 30 - p.size()) * 0.05 * 0.05;
  EXPECT_NEAR(removed, M_PI * 0.09 + triangle + 0.1, 0.06);
}

TEST(Lattice, SphereHoleIn3D) {
  pd::Scene s = box_scene(3, 0.1);
  s.holes.push_back(circle(1.0, 0.75, 0.5, 0.35));
  const int expected =
      count_cells(s, [](const double* x) { return std::hypot(x[0] - 1.0, x[1] - 0.75, x[2] - 0.5) > 0.35; });
  EXPECT_EQ(pd::discretize(s).size(), expected);
}

TEST(Lattice, InclusionsTagTheirMaterial) {
  pd::Scene s = box_scene(2, 0.1);
  pd::Shape inc = circle(1.0, 0.75, 0, 0.45);
  inc.material = "soft";
  s.inclusions.push_back(inc);
  const pd::Particles p = pd::discretize(s);
  EXPECT_EQ(p.size(), 20 * 15);
  int soft = 0;
  for (int i = 0; i < p.size(); ++i) {
    const bool inside = std::hypot(p.position(i)[0] - 1.0, p.position(i)[1] - 0.75) <= 0.45;
    EXPECT_EQ(p.material[i], inside ? 1 : 0) << i;
    soft += inside;
  }
  EXPECT_GT(soft, 0);
}

TEST(Lattice, PerturbationIsSeededAndBounded) {
  for (int dim : {2, 3}) {
    const pd::Scene plain = box_scene(dim, 0.125);
    pd::Scene a = plain;
    a.perturbation = 0.3;
    a.seed = 11;
    pd::Scene b = a;
    b.seed = 12;
    const pd::Particles p0 = pd::discretize(plain), pa = pd::discretize(a), pa2 = pd::discretize(a),
                        pb = pd::discretize(b);
    ASSERT_EQ(pa.size(), p0.size());
    EXPECT_EQ(pa.x, pa2.x);  // deterministic
    EXPECT_NE(pa.x, pb.x);   // the seed matters
    double max_shift = 0, mean = 0;
    for (std::size_t i = 0; i < pa.x.size(); ++i) {
      const double d = pa.x[i] - p0.x[i];
      max_shift = std::max(max_shift, std::fabs(d));
      mean += d / static_cast<double>(pa.x.size());
    }
    EXPECT_LE(max_shift, 0.3 * 0.125 * (1 + 1e-12));
    EXPECT_GT(max_shift, 0.2 * 0.125);  // the shift is used, not just bounded
    EXPECT_LT(std::fabs(mean), 0.02 * 0.125);
  }
}

TEST(Lattice, HolesCoveringTheDomainAreAnError) {
  pd::Scene s = box_scene(2, 0.1);
  s.holes.push_back(circle(1.0, 0.75, 0, 5.0));
  EXPECT_THROW(pd::discretize(s), pd::SceneError);
}

TEST(Regions, SidesHoldTheOutermostRowEvenWhenPerturbed) {
  for (const char* placement : {"cell", "node"}) {
    for (int dim : {2, 3}) {
      pd::Scene s = box_scene(dim, 0.125);
      s.placement = *pd::parse_name<pd::Placement>(placement);
      s.perturbation = 0.45;
      s.seed = 5;
      const pd::Particles p = pd::discretize(s);
      const int extra = std::string(placement) == "node" ? 1 : 0;
      const int nx = 16 + extra, ny = 12 + extra, nz = dim == 3 ? 8 + extra : 1;
      const std::vector<std::pair<std::string, int>> sides{
          {"left", ny * nz}, {"right", ny * nz}, {"bottom", nx * nz}, {"top", nx * nz}};
      for (const auto& [side, n] : sides) {
        pd::Region r;
        r.kind = pd::Region::Kind::Side;
        r.side = *pd::parse_name<pd::Region::Side>(side);
        EXPECT_EQ(static_cast<int>(pd::region_particles(r, p, s).size()), n)
            << placement << " " << dim << "D " << side;
      }
      if (dim == 3) {
        pd::Region r;
        r.kind = pd::Region::Kind::Side;
        r.side = pd::Region::Side::front;
        EXPECT_EQ(static_cast<int>(pd::region_particles(r, p, s).size()), nx * ny) << placement;
      }
    }
  }
}

TEST(Regions, ThicknessBoxOutsideAndAll) {
  const pd::Scene s = box_scene(2, 0.1);
  const pd::Particles p = pd::discretize(s);
  pd::Region r;
  r.kind = pd::Region::Kind::Side;
  r.side = pd::Region::Side::left;
  r.thickness = 0.3;  // three columns of cell centres 0.05, 0.15, 0.25
  EXPECT_EQ(pd::region_particles(r, p, s).size(), 3u * 15);
  r.kind = pd::Region::Kind::Box;
  r.min = {0.5, 0.5, 0};
  r.max = {1.0, 1.0, 0};
  const auto inside = pd::region_particles(r, p, s);
  EXPECT_EQ(inside.size(), 25u);
  r.kind = pd::Region::Kind::Outside;
  EXPECT_EQ(pd::region_particles(r, p, s).size(), 300u - 25u);
  r.kind = pd::Region::Kind::All;
  EXPECT_EQ(pd::region_particles(r, p, s).size(), 300u);
}

// The collar is the set of particles whose family the box truncates: checked against
// the family sizes find_bonds gives (a full family is the largest one).
TEST(Regions, CollarIsThePartiallyTruncatedFamilies) {
  for (const char* placement : {"cell", "node"})
    for (double ratio : {1.5, 2.5, 3.0, 3.5}) {
      pd::Scene s = box_scene(2, 0.1);
      s.placement = *pd::parse_name<pd::Placement>(placement);
      s.horizon_ratio = ratio;
      const pd::Particles p = pd::discretize(s);
      const pd::Bonds b = pd::find_bonds(p, s.delta(), [](double, double) { return 1.0; });
      int full = 0;
      for (int i = 0; i < p.size(); ++i) full = std::max(full, b.family_size(i));
      pd::Region r;
      r.kind = pd::Region::Kind::Collar;
      r.horizons = 1;
      const auto collar = pd::region_particles(r, p, s);
      std::vector<int> truncated;
      for (int i = 0; i < p.size(); ++i)
        if (b.family_size(i) < full) truncated.push_back(i);
      EXPECT_EQ(collar, truncated) << placement << " delta/h " << ratio;
    }
}
// Integer delta/h on a node lattice puts neighbours exactly delta away; rounding of the
// cell index once put some of them two cells away, and find_bonds dropped them from one
// family only (x = 0.9 had 27 neighbours instead of 28 at delta/h = 3, h = 0.1).
TEST(Neighbours, LatticeFamiliesAtIntegerRatiosAreComplete) {
  for (const char* placement : {"cell", "node"})
    for (double ratio : {2.0, 3.0}) {
      pd::Scene s = box_scene(2, 0.1);
      s.placement = *pd::parse_name<pd::Placement>(placement);
      s.horizon_ratio = ratio;
      const pd::Particles p = pd::discretize(s);
      const pd::Bonds b = pd::find_bonds(p, s.delta(), [](double, double) { return 1.0; });
      const int full = ratio == 2.0 ? 12 : 28;  // lattice points in a disc of radius 2 (3), centre excluded
      for (int i = 0; i < p.size(); ++i) {
        const double* x = p.position(i);
        const double margin = s.delta() + 0.5 * s.h;
        if (x[0] > margin && x[0] < 2 - margin && x[1] > margin && x[1] < 1.5 - margin) {
          EXPECT_EQ(b.family_size(i), full)
              << placement << " delta/h " << ratio << " at " << x[0] << ", " << x[1];
        }
      }
    }
}

// The short-horizon preconditioner drops the bonds of negligible weight: at delta/h = 2 with
// the cubic influence, the ring 2h away (4 of 12 neighbours; rounding leaves some of them
// at w ~ 1e-48 instead of 0). What stays is every other bond, with its data, in order.
TEST(Neighbours, NegligibleBondsAreDroppedAndTheRestKept) {
  pd::Scene s = box_scene(2, 0.1);
  s.horizon_ratio = 2.0;
  const pd::Particles p = pd::discretize(s);
  // The cubic spline's shape: zero at r = delta, positive inside.
  auto weight = [](double r, double delta) { return r >= delta ? 0.0 : std::pow(1 - r / delta, 3); };
  const pd::Bonds all = pd::find_bonds(p, s.delta(), weight);
  pd::Bonds kept = all;
  const int dropped = pd::drop_negligible_bonds(kept);
  int zero = 0;
  for (double w : all.w) zero += w < 1e-30;
  EXPECT_GT(zero, 0);
  EXPECT_EQ(dropped, zero);
  ASSERT_EQ(kept.bond_count(), all.bond_count() - zero);
  for (int i = 0; i < p.size(); ++i) {
    int k = kept.offsets[i];
    for (int b = all.offsets[i]; b < all.offsets[i + 1]; ++b) {
      if (all.w[b] < 1e-30) continue;
      ASSERT_LT(k, kept.offsets[i + 1]);
      EXPECT_EQ(kept.neighbor[k], all.neighbor[b]);
      EXPECT_EQ(kept.w[k], all.w[b]);
      EXPECT_EQ(kept.length[k], all.length[b]);
      EXPECT_EQ(kept.xi[2 * k + 1], all.xi[2 * b + 1]);
      ++k;
    }
    EXPECT_EQ(k, kept.offsets[i + 1]);
    const double* x = p.position(i);
    if (x[0] > 0.25 && x[0] < 1.75 && x[1] > 0.25 && x[1] < 1.25) {
      EXPECT_EQ(kept.family_size(i), 8) << x[0] << ", " << x[1];  // 12 minus the ring at 2h
    }
  }
  pd::Bonds constant = pd::find_bonds(p, s.delta(), [](double, double) { return 1.0; });
  EXPECT_EQ(pd::drop_negligible_bonds(constant), 0);

  // The solver-path rule counts the same short families on the bonds of a longer horizon.
  s.horizon_ratio = 3.5;
  const pd::Bonds longer = pd::find_bonds(p, s.delta(), weight);
  EXPECT_DOUBLE_EQ(pd::mean_short_family_size(longer, 2.0 * s.h, weight),
                   static_cast<double>(kept.bond_count()) / p.size());
  EXPECT_DOUBLE_EQ(pd::mean_short_family_size(longer, 2.0 * s.h, [](double, double) { return 1.0; }),
                   static_cast<double>(all.bond_count()) / p.size());
}
