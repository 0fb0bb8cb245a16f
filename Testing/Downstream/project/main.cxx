#include <vtkGlobeEllipsoid.h>
#include <vtkGlobeGeodeticTransform.h>
#include <vtkNew.h>

#include <cmath>
#include <cstdio>

int main()
{
  vtkNew<vtkGlobeEllipsoid> mars;
  mars->SetToMars();
  vtkNew<vtkGlobeGeodeticTransform> transform;
  transform->SetEllipsoid(mars);
  double llh[3] = { 0.0, 90.0, 0.0 }, xyz[3];
  transform->TransformPoint(llh, xyz);
  std::printf("downstream: Mars north pole at z = %.3f m\n", xyz[2]);
  return std::abs(xyz[2] - 3376200.0) < 1e-6 ? 0 : 1;
}
