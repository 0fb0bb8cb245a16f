#include "vtkGlobePointPicker.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkGlobeDepthPass.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeTerrain.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

#include <cmath>

vtkStandardNewMacro(vtkGlobePointPicker);
vtkCxxSetObjectMacro(vtkGlobePointPicker, DepthPass, vtkGlobeDepthPass);
vtkCxxSetObjectMacro(vtkGlobePointPicker, Mapper, vtkGlobeMapper);

vtkGlobePointPicker::vtkGlobePointPicker() = default;

vtkGlobePointPicker::~vtkGlobePointPicker()
{
  this->SetDepthPass(nullptr);
  this->SetMapper(nullptr);
}

int vtkGlobePointPicker::Pick(
  double selectionX, double selectionY, double selectionZ, vtkRenderer* renderer)
{
  this->Initialize();
  this->Hit = false;
  this->Renderer = renderer;
  this->SelectionPoint[0] = selectionX;
  this->SelectionPoint[1] = selectionY;
  this->SelectionPoint[2] = selectionZ;
  if (!renderer || !renderer->GetActiveCamera())
  {
    vtkErrorMacro(<< "Pick: no renderer or camera");
    return 0;
  }
  this->InvokeEvent(vtkCommand::StartPickEvent, nullptr);

  vtkCamera* camera = renderer->GetActiveCamera();
  double z = renderer->GetZ(static_cast<int>(selectionX), static_cast<int>(selectionY));
  if (z < 1.0)
  {
    this->Hit = true;
    vtkGlobeDepthPass* pass =
      this->DepthPass ? this->DepthPass : vtkGlobeDepthPass::SafeDownCast(renderer->GetPass());
    if (pass)
    {
      z = pass->GetPerspectiveDepth(z, camera);
    }
  }
  else
  {
    // Nothing drawn: the focal plane, as vtkWorldPointPicker does.
    double focal[3];
    camera->GetFocalPoint(focal);
    renderer->SetWorldPoint(focal[0], focal[1], focal[2], 1.0);
    renderer->WorldToDisplay();
    z = renderer->GetDisplayPoint()[2];
  }
  renderer->SetDisplayPoint(selectionX, selectionY, z);
  renderer->DisplayToWorld();
  const double* world = renderer->GetWorldPoint();
  for (int i = 0; i < 3; ++i)
  {
    this->PickPosition[i] = world[i] / world[3];
  }
  this->ComputeGeodetic(renderer);
  this->InvokeEvent(vtkCommand::EndPickEvent, nullptr);
  return this->Hit ? 1 : 0;
}

void vtkGlobePointPicker::ComputeGeodetic(vtkRenderer* renderer)
{
  this->GeodeticHit = false;
  this->PickGeodetic[0] = this->PickGeodetic[1] = this->PickGeodetic[2] = vtkMath::Nan();
  this->PickOrthometricHeight = this->PickTerrainHeight = this->PickDistance = vtkMath::Nan();
  if (!this->Hit)
  {
    return;
  }
  // The globe and its actor: the mapper set, or the first visible globe.
  vtkActor* globe = vtkGlobeMapper::FindGlobeActor(renderer, this->Mapper);
  if (!globe)
  {
    return;
  }
  auto* mapper = vtkGlobeMapper::SafeDownCast(globe->GetMapper());
  vtkNew<vtkMatrix4x4> worldToBody;
  vtkMatrix4x4::Invert(globe->GetMatrix(), worldToBody);
  double p[4] = { this->PickPosition[0], this->PickPosition[1], this->PickPosition[2], 1.0 };
  worldToBody->MultiplyPoint(p, p);
  double llh[3];
  if (!mapper->GetEllipsoid()->CartesianToGeodeticQuiet(p, llh))
  {
    return;
  }
  this->GeodeticHit = true;
  for (int i = 0; i < 3; ++i)
  {
    this->PickGeodetic[i] = llh[i];
  }
  vtkGlobeTerrain* terrain = mapper->GetTerrain();
  this->PickOrthometricHeight = llh[2] - terrain->GetGeoidUndulation(llh[0], llh[1]);
  this->PickTerrainHeight = terrain->GetHeight(llh[0], llh[1]);
  const double* eye = renderer->GetActiveCamera()->GetPosition();
  this->PickDistance = std::sqrt(vtkMath::Distance2BetweenPoints(eye, this->PickPosition));
}

void vtkGlobePointPicker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthPass: " << this->DepthPass << "\n";
  os << indent << "Hit: " << this->Hit << "\n";
  os << indent << "Mapper: " << this->Mapper << "\n";
  os << indent << "GeodeticHit: " << this->GeodeticHit << "\n";
  os << indent << "PickGeodetic: " << this->PickGeodetic[0] << ", " << this->PickGeodetic[1]
     << ", " << this->PickGeodetic[2] << "\n";
  os << indent << "PickOrthometricHeight: " << this->PickOrthometricHeight << "\n";
  os << indent << "PickTerrainHeight: " << this->PickTerrainHeight << "\n";
  os << indent << "PickDistance: " << this->PickDistance << "\n";
}
