// The push-pull void fill of vtkGlobeLayer on synthetic 64 x 64 rasters (SetHeightData).
//
// Every filled value is a convex combination of valid posts, so:
// - a constant field is reproduced exactly, and no filled value leaves the range of the
//   valid values (no spike, no pit);
// - a plane h = a x + b y (x = column, y = row, in posts) is reproduced only approximately.
//   The bound: in the pull, a level-k cell (2^k x 2^k posts) with a valid child stores the
//   mean of its valid children, whose centres lie 2^(k-2) posts from its own centre along
//   each axis; the mean of a plane over points is the plane at their centroid, so a level-k
//   value differs from the plane at its centre by at most e_k = e_(k-1) + (|a| + |b|) 2^(k-2),
//   i.e. e_k <= (|a| + |b|) (2^k - 1) / 2. The push fills a cell by bilinear interpolation of
//   the next coarser level at its centre, which reproduces a plane exactly away from the
//   raster border, so a filled post inherits a convex combination of the coarser errors.
//   The coarsest level involved is L, the first one with no all-void cell (no aligned
//   2^L x 2^L block of posts is entirely void). Hence |fill - plane| <= (|a| + |b|)(2^L - 1)/2
//   for voids at least 2^L posts from the border. It is an upper bound: the centroid offsets
//   of partly valid cells mostly cancel, and the measured error is far smaller.
//   Near the raster border the bilinear push clamps (extrapolates flat) and a convex
//   combination cannot follow a slope outwards, so no such bound is claimed there: only the
//   range is checked.
// A peak whose top is void (a synthetic cone, 100 m per post) shows the fill's character:
// a flat, slightly bowl-shaped top at the level of the surrounding posts, never above them.
// With FillVoids off the voids stay NaN; the mapper must treat NaN as zero coverage (the
// layer below shows through), never as a height.
#include "vtkGlobeTestHelpers.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

constexpr int N = 64;

/// A void: columns c0..c1, rows r0..r1 (inclusive).
struct Box
{
  int C0, C1, R0, R1;
};

std::vector<bool> Mask(const std::vector<Box>& boxes)
{
  std::vector<bool> m(N * N, false);
  for (const Box& b : boxes)
  {
    for (int r = b.R0; r <= b.R1; ++r)
    {
      for (int c = b.C0; c <= b.C1; ++c)
      {
        m[r * N + c] = true;
      }
    }
  }
  return m;
}

/// L: the first pyramid level with no all-void aligned 2^L x 2^L block.
int TopLevel(const std::vector<bool>& mask)
{
  for (int level = 0;; ++level)
  {
    const int s = 1 << level;
    bool anyAllVoid = false;
    for (int r = 0; r < N && !anyAllVoid; r += s)
    {
      for (int c = 0; c < N && !anyAllVoid; c += s)
      {
        bool all = true;
        for (int y = r; y < std::min(r + s, N) && all; ++y)
        {
          for (int x = c; x < std::min(c + s, N) && all; ++x)
          {
            all = mask[y * N + x];
          }
        }
        anyAllVoid = all;
      }
    }
    if (!anyAllVoid)
    {
      return level;
    }
  }
}

struct Result
{
  double WorstError = 0;
  int WorstRow = -1, WorstCol = -1;
  long NaNs = 0;
  bool ValidKept = true;
  double FillMin = 1e300, FillMax = -1e300;
  double ValidMin = 1e300, ValidMax = -1e300;
  double MaxStep = 0; // largest difference between 4-neighbours touching a filled post
};

/// Fills `field` with the voids of `mask` through a layer and compares with the field.
Result Run(
  vtkGlobeLayer* layer, const std::function<double(int, int)>& field, const std::vector<bool>& mask)
{
  std::vector<float> values(N * N);
  Result r;
  for (int y = 0; y < N; ++y)
  {
    for (int x = 0; x < N; ++x)
    {
      const double v = field(x, y);
      values[y * N + x] =
        mask[y * N + x] ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(v);
      if (!mask[y * N + x])
      {
        r.ValidMin = std::min(r.ValidMin, v);
        r.ValidMax = std::max(r.ValidMax, v);
      }
    }
  }
  // Any geographic box will do; 1 degree per post.
  layer->SetHeightData(N, N, values.data(), 0, N, -N / 2, N / 2);
  vtkFloatArray* out = vtkFloatArray::SafeDownCast(layer->GetData());
  if (!out)
  {
    r.NaNs = N * N;
    return r;
  }
  const float* f = out->GetPointer(0);
  for (int y = 0; y < N; ++y)
  {
    for (int x = 0; x < N; ++x)
    {
      const int i = y * N + x;
      if (std::isnan(f[i]))
      {
        ++r.NaNs;
        continue;
      }
      if (!mask[i])
      {
        r.ValidKept = r.ValidKept && f[i] == values[i];
        continue;
      }
      const double e = std::abs(f[i] - field(x, y));
      if (e > r.WorstError)
      {
        r.WorstError = e;
        r.WorstRow = y;
        r.WorstCol = x;
      }
      r.FillMin = std::min(r.FillMin, static_cast<double>(f[i]));
      r.FillMax = std::max(r.FillMax, static_cast<double>(f[i]));
      if (x + 1 < N)
      {
        r.MaxStep = std::max(r.MaxStep, static_cast<double>(std::abs(f[i + 1] - f[i])));
      }
      if (x > 0)
      {
        r.MaxStep = std::max(r.MaxStep, static_cast<double>(std::abs(f[i - 1] - f[i])));
      }
      if (y + 1 < N)
      {
        r.MaxStep = std::max(r.MaxStep, static_cast<double>(std::abs(f[i + N] - f[i])));
      }
      if (y > 0)
      {
        r.MaxStep = std::max(r.MaxStep, static_cast<double>(std::abs(f[i - N] - f[i])));
      }
    }
  }
  return r;
}
} // namespace

int TestGlobeLayerVoidFill(int, char*[])
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkGlobeLayer> layer;
  layer->AddObserver(vtkCommand::ErrorEvent, observer);
  const double a = 3.0, b = 2.0;
  const auto plane = [a, b](int x, int y) { return a * x + b * y; };

  const struct
  {
    const char* Name;
    std::vector<Box> Voids;
  } cases[] = {
    { "a 16 x 12 block (columns 24-39, rows 26-37)", { { 24, 39, 26, 37 } } },
    { "a 20 x 16 block (columns 24-43, rows 20-35)", { { 24, 43, 20, 35 } } },
    { "a single post (32, 33)", { { 32, 32, 33, 33 } } },
    { "three separate voids (4 x 4, 6 x 6, 1 x 9)",
      { { 10, 13, 10, 13 }, { 40, 45, 40, 45 }, { 20, 20, 44, 52 } } },
  };
  for (const auto& c : cases)
  {
    std::printf("Plane h = %g x + %g y, %s:\n", a, b, c.Name);
    const std::vector<bool> mask = Mask(c.Voids);
    const long voids = static_cast<long>(std::count(mask.begin(), mask.end(), true));
    const int level = TopLevel(mask);
    const double bound = (std::abs(a) + std::abs(b)) * ((1 << level) - 1) / 2.0 + 1e-3;
    Result r = Run(layer, plane, mask);
    Expect(layer->IsValid() && !observer->GetError() && layer->GetNumberOfVoids() == voids,
      vtkGlobeTest::Printf("valid, %lld voids counted (%ld NaN given)",
        static_cast<long long>(layer->GetNumberOfVoids()), voids));
    Expect(r.NaNs == 0, vtkGlobeTest::Printf("no void remains (%ld NaN)", r.NaNs));
    Expect(r.ValidKept, "valid posts unchanged");
    Expect(r.WorstError <= bound,
      vtkGlobeTest::Printf("|fill - plane| worst %.3f m at (col %d, row %d); bound (|a|+|b|)(2^L-1)/2 = %.3f "
             "m with L = %d",
        r.WorstError, r.WorstCol, r.WorstRow, bound, level));
    Expect(r.FillMin >= r.ValidMin && r.FillMax <= r.ValidMax,
      vtkGlobeTest::Printf("filled values %.2f .. %.2f within the valid range %.0f .. %.0f", r.FillMin, r.FillMax,
        r.ValidMin, r.ValidMax));
    // Continuity: neighbouring posts in and around the fill differ by at most twice the
    // plane's own largest step (|a| = 3): no cliff at the edge of a void.
    Expect(r.MaxStep <= 2 * std::max(std::abs(a), std::abs(b)),
      vtkGlobeTest::Printf("largest step between neighbours touching the fill %.3f m (plane: %g)", r.MaxStep,
        std::max(std::abs(a), std::abs(b))));
  }

  std::printf("Constant 1234.5 m with the 16 x 12 block and a corner void:\n");
  {
    const std::vector<bool> mask = Mask({ { 24, 39, 26, 37 }, { 0, 9, 50, 63 } });
    Result r = Run(
      layer, [](int, int) { return 1234.5; }, mask);
    Expect(r.NaNs == 0 && r.WorstError == 0.0,
      vtkGlobeTest::Printf(
        "reproduced exactly (worst %.3g m): every fill is a convex combination", r.WorstError));
  }

  std::printf("Plane with a void on the raster corner (columns 0-9, rows 50-63):\n");
  {
    const std::vector<bool> mask = Mask({ { 0, 9, 50, 63 } });
    Result r = Run(layer, plane, mask);
    Expect(r.NaNs == 0 && r.ValidKept, "filled, valid posts unchanged");
    Expect(r.FillMin >= r.ValidMin && r.FillMax <= r.ValidMax,
      vtkGlobeTest::Printf("filled values %.2f .. %.2f within the valid range (no extrapolated slope: worst "
             "|fill - plane| %.2f m at col %d row %d, reported, not bounded)",
        r.FillMin, r.FillMax, r.WorstError, r.WorstCol, r.WorstRow));
  }

  std::printf("A cone-shaped peak at (32, 32) whose top 9 x 9 posts are void:\n");
  {
    const auto cone = [](int x, int y) { return 8000.0 - 100.0 * std::hypot(x - 32.0, y - 32.0); };
    const std::vector<bool> mask = Mask({ { 28, 36, 28, 36 } });
    Result r = Run(layer, cone, mask);
    const double ringMax = cone(32, 37), ringMin = cone(37, 37); // the valid posts around it
    const double summit = layer->GetData()->GetComponent(32 * N + 32, 0);
    // The fill is a weighted mean that also reaches posts beyond the ring (lower, on a
    // cone), so a peak's void becomes a shallow bowl: its centre may dip a little below the
    // ring's lowest post. A pit would drop by the order of the surrounding relief or more;
    // require the dip to stay well under it and report it.
    const double dip = std::max(0.0, ringMin - summit);
    Expect(r.NaNs == 0 && summit <= ringMax && dip < 0.1 * (ringMax - ringMin),
      vtkGlobeTest::Printf("the summit post is filled at %.1f m; ring %.1f .. %.1f m; dip below the ring "
             "%.1f m < 10%% of the ring's relief (%.1f m): a shallow bowl, not a pit",
        summit, ringMin, ringMax, dip, ringMax - ringMin));
    Expect(r.FillMax <= ringMax,
      vtkGlobeTest::Printf("no spike: the fill %.1f .. %.1f m stays below the highest valid post %.1f m "
             "(a flat top, lower than the true 8000 m peak)",
        r.FillMin, r.FillMax, ringMax));
  }

  std::printf("FillVoids off:\n");
  {
    layer->SetFillVoids(false);
    const std::vector<bool> mask = Mask({ { 24, 39, 26, 37 } });
    Result r = Run(layer, plane, mask);
    Expect(
      layer->IsValid() && r.NaNs == 16 * 12 && layer->GetNumberOfVoids() == 16 * 12 && r.ValidKept,
      vtkGlobeTest::Printf(
        "the %ld voids stay NaN (zero coverage for the mapper), valid posts unchanged", r.NaNs));
    Expect(layer->GetMinimumValue() == 0 && layer->GetMaximumValue() == 3 * 63 + 2 * 63,
      vtkGlobeTest::Printf("range %g .. %g m from the valid posts only", layer->GetMinimumValue(),
        layer->GetMaximumValue()));
    layer->SetFillVoids(true);
    Expect(layer->Update() && layer->GetNumberOfLoads() >= 2 &&
        !std::isnan(layer->GetData()->GetComponent(30 * N + 30, 0)),
      "FillVoids on again + Update(): re-processed from the kept in-memory copy, filled");
  }

  return Checks.Result();
}
