// A track draped on the terrain shows without gaps (issue 13), 1 km and 100 km above the ground
// near Mount Rainier (SRTM above EGM96 over the 2-degree relief), default perspective depth with
// the globe's clipping policy.
//
// The track is a loop of 64 lon/lat points drawn as a magenta line (unlit, 2 px), a colour
// the globe here never shows (checked: 0 magenta pixels without the track). Gap pixels: the
// track's own polyline is projected (double) and walked in steps of a quarter pixel; every
// pixel it passes through whose ray from the eye clears the terrain (vtkGlobeTerrain, marched
// in 400 steps up to 2 % of the distance short of the point) must have track colour within one
// pixel; the pixels that do not are counted. Four drapings of the same loop, all reported:
//  - its 64 points on the terrain (vtkGlobeTerrain), nothing else: gaps (asserted > 0, so the
//    count sees gaps when there are some);
//  - its 64 points 5 m over the terrain, as drape_track.py and users did before this issue;
//  - vtkGlobeTerrainClamp: 5 m over the terrain, densified along geodesics to 1/200 of the
//    camera's height over the ground;
//  - the same with vtkGlobeDepthOffset (the default 2e-3): 0 gap pixels (asserted).
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkGlobeDepthOffset.h"
#include "vtkGlobeTerrain.h"
#include "vtkGlobeTerrainClamp.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

namespace
{
vtkGlobeTest::Checklist Check;

bool IsTrack(const unsigned char* p)
{
  return p[0] > 200 && p[1] < 80 && p[2] > 200;
}

struct Count
{
  int Visible = 0; // distinct pixels along the path with a clear view
  int Gaps = 0;    // of those, without track colour within one pixel
  int Hidden = 0;  // pixels of the path behind terrain (not judged)
};

/// Walks the track's polyline on the screen and counts its gap pixels.
Count CountGaps(vtkGlobeTest::Scene& scene, vtkPolyData* track, vtkGlobeTerrain* terrain)
{
  Count count;
  const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(scene.Window);
  const int* size = scene.Window->GetSize();
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  auto project = [&](const double p[3], double d[2]) {
    scene.Renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    scene.Renderer->WorldToDisplay();
    d[0] = scene.Renderer->GetDisplayPoint()[0];
    d[1] = scene.Renderer->GetDisplayPoint()[1];
  };
  // Whether terrain hides a point: the ray from the eye, up to 2 % short of it.
  auto hidden = [&](const double p[3]) {
    for (int k = 1; k < 400; ++k)
    {
      const double t = 0.98 * k / 400.0;
      const double q[3] = { eye[0] + t * (p[0] - eye[0]), eye[1] + t * (p[1] - eye[1]),
        eye[2] + t * (p[2] - eye[2]) };
      double llh[3];
      scene.Body->CartesianToGeodetic(q, llh);
      if (llh[2] < terrain->GetHeight(llh[0], llh[1]))
      {
        return true;
      }
    }
    return false;
  };
  std::set<std::pair<int, int>> visible, gaps, behind;
  vtkCellArray* lines = track->GetLines();
  lines->InitTraversal();
  vtkNew<vtkIdList> ids;
  while (lines->GetNextCell(ids))
  {
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      double a[3], b[3], da[2], db[2];
      track->GetPoint(ids->GetId(k), a);
      track->GetPoint(ids->GetId(k + 1), b);
      project(a, da);
      project(b, db);
      const int steps = std::max(1, static_cast<int>(std::ceil(4.0 * std::hypot(db[0] - da[0], db[1] - da[1]))));
      for (int s = 0; s <= steps; ++s)
      {
        const double t = static_cast<double>(s) / steps;
        const double p[3] = { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]) };
        double d[2];
        project(p, d);
        const int x = static_cast<int>(std::floor(d[0])), y = static_cast<int>(std::floor(d[1]));
        if (x < 1 || y < 1 || x >= size[0] - 1 || y >= size[1] - 1)
        {
          continue;
        }
        const std::pair<int, int> pixel(x, y);
        if (visible.count(pixel) || behind.count(pixel))
        {
          continue;
        }
        if (hidden(p))
        {
          behind.insert(pixel);
          continue;
        }
        visible.insert(pixel);
        bool found = false;
        for (int v = -1; v <= 1 && !found; ++v)
        {
          for (int u = -1; u <= 1 && !found; ++u)
          {
            found = IsTrack(&rgb[3 * (static_cast<size_t>(y + v) * size[0] + x + u)]);
          }
        }
        if (!found)
        {
          gaps.insert(pixel);
        }
      }
    }
  }
  count.Visible = static_cast<int>(visible.size());
  count.Gaps = static_cast<int>(gaps.size());
  count.Hidden = static_cast<int>(behind.size());
  return count;
}

/// A loop of 64 points around (lon, lat) with a radius in metres: lon/lat/0 coordinates.
vtkSmartPointer<vtkPolyData> Loop(double lon, double lat, double radius)
{
  auto loop = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  const double perDegree = 111320.0;
  lines->InsertNextCell(65);
  for (int k = 0; k <= 64; ++k)
  {
    const double a = 2.0 * vtkMath::Pi() * k / 64.0;
    if (k < 64)
    {
      points->InsertNextPoint(lon + radius * std::cos(a) / (perDegree * std::cos(vtkMath::RadiansFromDegrees(lat))),
        lat + radius * std::sin(a) / perDegree, 0.0);
    }
    lines->InsertCellPoint(k % 64);
  }
  loop->SetPoints(points);
  loop->SetLines(lines);
  return loop;
}

void Case(const char* name, const double camera[2], double above, const double centre[2], double radius)
{
  vtkGlobeTest::Scene scene(400, 300);
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  auto inset = vtkGlobeTest::FileLayer("earth/mt_rainier_90m.tif", true);
  inset->SetVerticalDatumToEGM96();
  scene.Mapper->AddLayer(inset);
  vtkGlobeTerrain* terrain = scene.Mapper->GetTerrain();
  const double eye[3] = { camera[0], camera[1], terrain->GetHeight(camera[0], camera[1]) + above };
  const double target[3] = { centre[0], centre[1], terrain->GetHeight(centre[0], centre[1]) };
  vtkGlobeClippingRange::Install(scene.Renderer);
  scene.Look(eye, target, 40.0);
  std::printf("%s:\n", name);

  // Without a track, no pixel has its colour.
  scene.Render();
  {
    const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(scene.Window);
    int magenta = 0;
    for (size_t i = 0; i + 2 < rgb.size(); i += 3)
    {
      magenta += IsTrack(&rgb[i]) ? 1 : 0;
    }
    Check.Expect(magenta == 0, std::string(name) + ": no track colour without the track");
  }

  vtkSmartPointer<vtkPolyData> loop = Loop(centre[0], centre[1], radius);
  // The loop's own points `lift` metres over the terrain, converted by the ellipsoid.
  auto pointsOnly = [&](double lift) {
    auto data = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < loop->GetNumberOfPoints(); ++i)
    {
      const double* p = loop->GetPoint(i);
      double xyz[3];
      scene.Body->GeodeticToCartesian(p[0], p[1], terrain->GetHeight(p[0], p[1]) + lift, xyz);
      points->InsertNextPoint(xyz);
    }
    data->SetPoints(points);
    data->SetLines(loop->GetLines());
    return data;
  };
  // The clamp filter: 5 m over the terrain, densified.
  vtkNew<vtkGlobeTerrainClamp> clamp;
  clamp->SetInputData(loop);
  clamp->SetTerrain(terrain);
  clamp->SetEllipsoid(scene.Body);
  clamp->SetHeightOffset(5.0);
  clamp->SetMaximumSegmentLength(above / 200.0);
  clamp->Update();

  const char* names[] = { "the 64 points on the terrain", "the 64 points 5 m over it",
    "clamped 5 m over it and densified", "clamped, densified and the depth offset" };
  int gaps[4];
  for (int variant = 0; variant < 4; ++variant)
  {
    vtkSmartPointer<vtkPolyData> track =
      variant < 2 ? pointsOnly(variant == 0 ? 0.0 : 5.0) : vtkSmartPointer<vtkPolyData>(clamp->GetOutput());
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(track);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(1.0, 0.0, 1.0);
    actor->GetProperty()->SetLighting(false);
    actor->GetProperty()->SetLineWidth(2.0);
    if (variant == 3)
    {
      vtkGlobeDepthOffset::Apply(actor, vtkGlobeDepthOffset::GetDefaultOffset());
    }
    scene.Renderer->AddActor(actor);
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();
    const Count count = CountGaps(scene, track, terrain);
    scene.Renderer->RemoveActor(actor);
    gaps[variant] = count.Gaps;
    std::printf("  %-42s (%4lld points): %4d gap pixels of %4d visible along the path (%d behind "
                "terrain)\n",
      names[variant], static_cast<long long>(track->GetNumberOfPoints()), count.Gaps,
      count.Visible, count.Hidden);
    if (variant == 3)
    {
      char text[200];
      std::snprintf(text, sizeof(text), "%s: %d gap pixels of %d visible", name, count.Gaps, count.Visible);
      Check.Expect(count.Visible > 200 && count.Gaps == 0, text);
    }
  }
  // The count sees gaps where there are some: the points laid on the terrain break up.
  Check.Expect(gaps[0] > 0, std::string(name) + ": the points on the terrain alone show gaps");
}
} // namespace

int TestGlobeDrapedTrack(int, char*[])
{
  // 1 km above the flank, looking about 60 degrees down at a loop of 300 m radius.
  const double camera1[2] = { -121.80, 46.80 }, centre1[2] = { -121.797, 46.804 };
  Case("1 km above the ground", camera1, 1000.0, centre1, 300.0);
  // 100 km above the ground, 60 km south of a loop of 12 km radius around the summit.
  const double camera2[2] = { -121.80, 46.25 }, centre2[2] = { -121.80, 46.80 };
  Case("100 km above the ground", camera2, 100000.0, centre2, 12000.0);
  return Check.Result();
}
