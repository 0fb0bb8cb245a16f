#include "vtkGlobePointPicker.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkGlobeDepthPass.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkGlobePointPicker);
vtkCxxSetObjectMacro(vtkGlobePointPicker, DepthPass, vtkGlobeDepthPass);

vtkGlobePointPicker::vtkGlobePointPicker() = default;

vtkGlobePointPicker::~vtkGlobePointPicker()
{
  this->SetDepthPass(nullptr);
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
  this->InvokeEvent(vtkCommand::EndPickEvent, nullptr);
  return this->Hit ? 1 : 0;
}

void vtkGlobePointPicker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthPass: " << this->DepthPass << "\n";
  os << indent << "Hit: " << this->Hit << "\n";
}
