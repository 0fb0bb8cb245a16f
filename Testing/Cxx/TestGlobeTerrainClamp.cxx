// vtkGlobeTerrainClamp (issue 13): lon/lat points, lines and polygons onto the composed terrain
// of Mount Rainier (SRTM above EGM96 over the 2-degree relief), with an offset, densified along
// geodesics. Asserted, in double:
//  - every output point's geodetic height (vtkGlobeEllipsoid, double) is the composed terrain
//    (vtkGlobeTerrain::GetHeight) at its (lon, lat) plus the offset (and the input z for
//    RelativeToTerrain) within 1 mm, the bound the class states;
//  - every inserted point lies on its edge's geodesic at k/n of its length (GeographicLib:
//    distances from both ends within 1 mm), every output edge at most MaximumSegmentLength, and
//    the number of points is the input's plus sum(ceil(s / max) - 1);
//  - point data interpolated along the edge, cell data passed, cells kept;
//  - no terrain: an error, no output.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkGlobeTerrain.h"
#include "vtkGlobeTerrainClamp.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"

#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Check;
}

int TestGlobeTerrainClamp(int, char*[])
{
  vtkNew<vtkGlobeEllipsoid> wgs84;
  vtkNew<vtkGlobeTerrain> terrain;
  terrain->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  auto inset = vtkGlobeTest::FileLayer("earth/mt_rainier_90m.tif", true);
  inset->SetVerticalDatumToEGM96();
  terrain->AddLayer(inset);

  // A track over the summit and out of the inset (its feathered border), a triangle, a vertex.
  const double track[][3] = { { -121.90, 46.80, 0.0 }, { -121.7603, 46.8523, 0.0 },
    { -121.60, 46.95, 0.0 }, { -121.55, 46.95, 0.0 }, { -120.95, 46.97, 0.0 } };
  const double triangle[][3] = { { -121.80, 46.75, 0.0 }, { -121.70, 46.75, 0.0 },
    { -121.75, 46.82, 0.0 } };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> time;
  time->SetName("time");
  for (const auto& p : track)
  {
    time->InsertNextValue(points->GetNumberOfPoints());
    points->InsertNextPoint(p);
  }
  for (const auto& p : triangle)
  {
    time->InsertNextValue(points->GetNumberOfPoints());
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> lines, polys, verts;
  lines->InsertNextCell({ 0, 1, 2, 3, 4 });
  polys->InsertNextCell({ 5, 6, 7 });
  verts->InsertNextCell({ 1 });
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetLines(lines);
  input->SetPolys(polys);
  input->SetVerts(verts);
  input->GetPointData()->AddArray(time);
  vtkNew<vtkIdTypeArray> label;
  label->SetName("label");
  for (vtkIdType c = 0; c < 3; ++c)
  {
    label->InsertNextValue(10 + c);
  }
  input->GetCellData()->AddArray(label);

  const double offset = 5.0, longest = 30.0;
  vtkNew<vtkGlobeTerrainClamp> clamp;
  clamp->SetInputData(input);
  clamp->SetTerrain(terrain);
  clamp->SetEllipsoid(wgs84);
  clamp->SetHeightOffset(offset);
  clamp->SetMaximumSegmentLength(longest);
  clamp->Update();
  vtkPolyData* out = clamp->GetOutput();

  const GeographicLib::Geodesic& geodesic = GeographicLib::Geodesic::WGS84();
  // 1. Heights.
  auto worstHeight = [&](vtkPolyData* data, double extra) {
    double worst = 0.0;
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      double llh[3];
      wgs84->CartesianToGeodetic(data->GetPoint(i), llh);
      worst = std::max(worst, std::abs(llh[2] - (terrain->GetHeight(llh[0], llh[1]) + extra)));
    }
    return worst;
  };
  const double worst = worstHeight(out, offset);
  char text[300];
  std::snprintf(text, sizeof(text),
    "%lld output points: worst |h - (terrain + %.0f m)| = %.2g m (bound 1 mm)",
    static_cast<long long>(out->GetNumberOfPoints()), offset, worst);
  Check.Expect(out->GetNumberOfPoints() > 1000 && worst <= 1e-3, text);

  // 2. Densification along the geodesics, and the point data.
  vtkIdType expected = input->GetNumberOfPoints();
  double worstOnGeodesic = 0.0, worstEdge = 0.0, worstTime = 0.0;
  auto lonLat = [&](vtkIdType id, double ll[2]) {
    double llh[3];
    wgs84->CartesianToGeodetic(out->GetPoint(id), llh);
    ll[0] = llh[0];
    ll[1] = llh[1];
  };
  auto checkCells = [&](vtkCellArray* inCells, vtkCellArray* outCells, bool closed) {
    inCells->InitTraversal();
    outCells->InitTraversal();
    vtkNew<vtkIdList> inIds, outIds;
    while (inCells->GetNextCell(inIds) && outCells->GetNextCell(outIds))
    {
      vtkIdType at = 0; // position in the output cell
      const vtkIdType n = inIds->GetNumberOfIds();
      for (vtkIdType k = 0; k < (closed ? n : n - 1); ++k)
      {
        const vtkIdType a = inIds->GetId(k), b = inIds->GetId((k + 1) % n);
        double s12, azi1, azi2;
        geodesic.Inverse(input->GetPoint(a)[1], input->GetPoint(a)[0],
          input->GetPoint(b)[1], input->GetPoint(b)[0], s12, azi1, azi2);
        const int parts = static_cast<int>(std::ceil(s12 / longest));
        expected += parts - 1;
        Check.Failures += outIds->GetId(at) == a ? 0 : 1;
        for (int j = 1; j < parts; ++j)
        {
          const vtkIdType id = outIds->GetId(at + j);
          double ll[2], s1, s2, z1, z2;
          lonLat(id, ll);
          geodesic.Inverse(input->GetPoint(a)[1], input->GetPoint(a)[0], ll[1], ll[0], s1, z1, z2);
          geodesic.Inverse(ll[1], ll[0], input->GetPoint(b)[1], input->GetPoint(b)[0], s2, z1, z2);
          worstOnGeodesic = std::max({ worstOnGeodesic, std::abs(s1 - s12 * j / parts),
            std::abs(s2 - s12 * (parts - j) / parts) });
          const double t = static_cast<double>(j) / parts;
          const double want = time->GetValue(a) + t * (time->GetValue(b) - time->GetValue(a));
          worstTime = std::max(worstTime,
            std::abs(out->GetPointData()->GetArray("time")->GetComponent(id, 0) - want));
        }
        at += parts;
      }
      // Every output edge, the closing one of a polygon included.
      const vtkIdType m = outIds->GetNumberOfIds();
      for (vtkIdType k = 0; k < (closed ? m : m - 1); ++k)
      {
        double p[2], q[2], s, z1, z2;
        lonLat(outIds->GetId(k), p);
        lonLat(outIds->GetId((k + 1) % m), q);
        geodesic.Inverse(p[1], p[0], q[1], q[0], s, z1, z2);
        worstEdge = std::max(worstEdge, s);
      }
    }
  };
  checkCells(input->GetLines(), out->GetLines(), false);
  checkCells(input->GetPolys(), out->GetPolys(), true);
  std::snprintf(text, sizeof(text),
    "inserted points on their geodesics within %.2g m (bound 1 mm); longest output edge %.3f m "
    "(max %.0f m); %lld points (expected %lld); time interpolated within %.2g",
    worstOnGeodesic, worstEdge, longest, static_cast<long long>(out->GetNumberOfPoints()),
    static_cast<long long>(expected), worstTime);
  Check.Expect(worstOnGeodesic <= 1e-3 && worstEdge <= longest + 1e-6 &&
      out->GetNumberOfPoints() == expected && worstTime <= 1e-9,
    text);
  Check.Expect(out->GetNumberOfLines() == 1 && out->GetNumberOfPolys() == 1 &&
      out->GetNumberOfVerts() == 1 && out->GetCellData()->GetArray("label") &&
      out->GetCellData()->GetArray("label")->GetComponent(2, 0) == 12,
    "one line, one polygon, one vertex; cell data passed");

  // The polyline between its points: how far the chords of the output sag from the terrain
  // (reported: the ground's curvature over 30 m, not a property of the points).
  double sag = 0.0;
  {
    vtkCellArray* l = out->GetLines();
    l->InitTraversal();
    vtkNew<vtkIdList> ids;
    l->GetNextCell(ids);
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      const double* a = out->GetPoint(ids->GetId(k));
      double b[3], mid[3], llh[3];
      out->GetPoint(ids->GetId(k + 1), b);
      for (int c = 0; c < 3; ++c)
      {
        mid[c] = 0.5 * (a[c] + b[c]);
      }
      wgs84->CartesianToGeodetic(mid, llh);
      sag = std::max(sag, std::abs(llh[2] - offset - terrain->GetHeight(llh[0], llh[1])));
    }
  }
  std::printf("  (the track's chords at their midpoints: within %.2f m of terrain + offset)\n", sag);

  // 3. RelativeToTerrain: z is added.
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[2] = 100.0;
    points->SetPoint(i, p);
  }
  points->Modified();
  clamp->SetHeightModeToRelativeToTerrain();
  clamp->Update();
  const double worstRelative = worstHeight(clamp->GetOutput(), offset + 100.0);
  std::snprintf(text, sizeof(text), "RelativeToTerrain, z = 100 m: worst |h - (terrain + 105 m)| = %.2g m",
    worstRelative);
  Check.Expect(worstRelative <= 1e-3, text);

  // 4. No terrain: an error.
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkGlobeTerrainClamp> bare;
  bare->AddObserver(vtkCommand::ErrorEvent, errors);
  bare->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  bare->SetInputData(input);
  bare->SetEllipsoid(wgs84);
  bare->Update();
  Check.Expect(errors->GetError() && errors->GetErrorMessage().find("No Terrain") != std::string::npos,
    "no terrain: the error names it");
  return Check.Result();
}
