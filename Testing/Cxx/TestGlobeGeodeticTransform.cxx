// vtkGlobeGeodeticTransform in a pipeline: lon/lat/height points through vtkTransformFilter
// land where vtkGlobeEllipsoid (checked against GeographicLib elsewhere) puts them; the
// inverse returns the input; the derivatives match finite differences; the transform follows
// changes of its ellipsoid (MTime) and survives DeepCopy/MakeTransform/Inverse.
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGeodeticTransform.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyLine.h"
#include "vtkCellArray.h"
#include "vtkTransformFilter.h"

#include <cmath>
#include <cstdio>

using vtkGlobeTest::Format;
using vtkGlobeTest::Worst;

int TestGlobeGeodeticTransform(int, char*[])
{
  bool ok = true;
  vtkNew<vtkGlobeEllipsoid> wgs84;
  vtkNew<vtkGlobeGeodeticTransform> transform;
  transform->SetEllipsoid(wgs84);

  // A flight track from Seattle over the North Pole to the date line, heights up to 12 km.
  vtkNew<vtkPoints> track;
  track->SetDataTypeToDouble();
  const int n = 181;
  for (int i = 0; i < n; ++i)
  {
    const double t = static_cast<double>(i) / (n - 1);
    const double lat = 47.45 + t * (90.0 - 47.45) * 2.0;
    const double lon = lat <= 90.0 ? -122.31 : 180.0;
    track->InsertNextPoint(lon, lat <= 90.0 ? lat : 180.0 - lat, 12000.0 * std::sin(3.14159 * t));
  }
  vtkNew<vtkPolyLine> line;
  line->GetPointIds()->SetNumberOfIds(n);
  for (int i = 0; i < n; ++i)
  {
    line->GetPointIds()->SetId(i, i);
  }
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(line);
  vtkNew<vtkPolyData> input;
  input->SetPoints(track);
  input->SetLines(lines);

  vtkNew<vtkTransformFilter> filter;
  filter->SetInputData(input);
  filter->SetTransform(transform);
  filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  filter->Update();
  vtkPoints* onGlobe = vtkPolyData::SafeDownCast(filter->GetOutput())->GetPoints();
  ok &= onGlobe->GetDataType() == VTK_DOUBLE && onGlobe->GetNumberOfPoints() == n;

  Worst forward("filter output vs vtkGlobeEllipsoid", "m");
  Worst inverse("inverse transform vs input", "m");
  for (int i = 0; i < n; ++i)
  {
    double llh[3], expected[3], got[3];
    track->GetPoint(i, llh);
    wgs84->GeodeticToCartesian(llh, expected);
    onGlobe->GetPoint(i, got);
    forward.Add(vtkGlobeTest::Distance(got, expected), Format("lon %g lat %g h %g", llh[0], llh[1], llh[2]));
    double back[3];
    transform->GetInverse()->TransformPoint(got, back);
    // Compare on the ground in metres: longitude is undefined at the pole itself.
    double again[3];
    wgs84->GeodeticToCartesian(back, again);
    inverse.Add(vtkGlobeTest::Distance(again, expected), Format("lon %g lat %g h %g", llh[0], llh[1], llh[2]));
  }

  // Derivatives against central differences (steps of 1e-6 deg and 1 mm).
  Worst derivative("forward derivative vs finite differences (rel.)", "");
  Worst inverseDerivative("inverse derivative x forward derivative - I", "");
  const double samples[][3] = { { 0, 0, 0 }, { -122.31, 47.45, 100 }, { 86.925, 27.988, 8848.86 },
    { 179.99, -80, -430 }, { -45, 89.9, 4e5 } };
  for (const auto& s : samples)
  {
    double out[3], jac[3][3];
    transform->InternalTransformDerivative(s, out, jac);
    const double steps[3] = { 1e-6, 1e-6, 1e-3 };
    for (int j = 0; j < 3; ++j)
    {
      double a[3] = { s[0], s[1], s[2] }, b[3] = { s[0], s[1], s[2] };
      a[j] += steps[j];
      b[j] -= steps[j];
      double pa[3], pb[3];
      transform->TransformPoint(a, pa);
      transform->TransformPoint(b, pb);
      double col = 0, diff = 0;
      for (int i = 0; i < 3; ++i)
      {
        const double fd = (pa[i] - pb[i]) / (2 * steps[j]);
        col = std::max(col, std::abs(fd));
        diff = std::max(diff, std::abs(fd - jac[i][j]));
      }
      derivative.Add(diff / col, Format("lon %g lat %g h %g", s[0], s[1], s[2]));
    }
    double inv[3][3], back[3];
    transform->GetInverse()->InternalTransformDerivative(out, back, inv);
    double worst = 0;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        double sum = 0;
        for (int k = 0; k < 3; ++k)
        {
          sum += inv[i][k] * jac[k][j];
        }
        worst = std::max(worst, std::abs(sum - (i == j ? 1.0 : 0.0)));
      }
    }
    inverseDerivative.Add(worst, Format("lon %g lat %g h %g", s[0], s[1], s[2]));
  }

  std::printf("WGS84:\n");
  ok &= forward.Check(1e-9);
  ok &= inverse.Check(1e-6);
  // Central differences of a smooth map with these steps: truncation ~1e-8, rounding ~1e-8.
  ok &= derivative.Check(1e-6);
  ok &= inverseDerivative.Check(1e-9);

  // The pipeline follows the body: switching to Mars re-executes and moves the points.
  const vtkMTimeType before = transform->GetMTime();
  wgs84->SetToMars();
  ok &= transform->GetMTime() > before;
  filter->Update();
  double p[3], expected[3], llh[3];
  track->GetPoint(0, llh);
  wgs84->GeodeticToCartesian(llh, expected);
  filter->GetOutput()->GetPoint(0, p);
  const double marsError = vtkGlobeTest::Distance(p, expected);
  std::printf("  after SetToMars(): first point %.3f m from Mars' answer (the filter re-executed: %s)\n",
    marsError, marsError < 1e-9 ? "yes" : "NO");
  ok &= marsError < 1e-9;

  // Copies and inverses behave as transforms do in VTK.
  vtkNew<vtkGlobeGeodeticTransform> copy;
  copy->DeepCopy(transform->GetInverse());
  double q[3];
  copy->TransformPoint(expected, q);
  ok &= copy->GetInverseFlag() == 1 && copy->GetEllipsoid() == wgs84.Get() &&
    vtkGlobeTest::Distance(q, llh) < 1e-6;
  vtkAbstractTransform* made = transform->MakeTransform();
  ok &= vtkGlobeGeodeticTransform::SafeDownCast(made) != nullptr;
  made->Delete();
  transform->Inverse();
  transform->TransformPoint(expected, q);
  ok &= vtkGlobeTest::Distance(q, llh) < 1e-6;

  std::printf("%s\n", ok ? "all within bounds" : "FAILED");
  return ok ? 0 : 1;
}
