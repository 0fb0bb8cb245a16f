// A camera 1,000 km up looking away from the planet: the sampling camera's intersection with
// the body's tangent cone is empty, so the mapper draws nothing, reports nothing, and leaves
// the depth buffer untouched; a cone in front of the camera still renders.
#include "vtkConeSource.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkTestErrorObserver.h"

int TestGlobeLookingAway(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  vtkNew<vtkTest::ErrorObserver> errors;
  scene.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  scene.Mapper->AddObserver(vtkCommand::WarningEvent, errors);
  const double camera[3] = { 10.0, 45.0, 1.0e6 }, target[3] = { 10.0, 45.0, 5.0e6 };
  scene.Look(camera, target, 40.0, 1000.0, 1.0e7);
  // A cone 100 km ahead, so the frame is not empty.
  double eye[3], ahead[3];
  scene.Body->GeodeticToCartesian(camera, eye);
  scene.Body->GeodeticToCartesian(10.0, 45.0, 1.1e6, ahead);
  vtkNew<vtkConeSource> cone;
  cone->SetCenter(ahead);
  cone->SetHeight(20000.0);
  cone->SetRadius(8000.0);
  cone->SetDirection(ahead[0] - eye[0], ahead[1] - eye[1], ahead[2] - eye[2]);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  scene.Renderer->AddActor(coneActor);
  scene.Render();

  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const int covered = vtkGlobeTest::CoveredPixels(depth);
  const bool visible = scene.Mapper->GetProjectiveGrid()->GetVisible();
  std::printf("  globe in view: %s; pixels with depth: %d (the cone only); errors or warnings: %s\n",
    visible ? "yes" : "no", covered, errors->GetError() || errors->GetWarning() ? "yes" : "no");
  bool ok = !visible && !scene.Mapper->GetLastFrameDrewGlobe() && covered > 0 && covered < 3000 &&
    !errors->GetError() && !errors->GetWarning();
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
