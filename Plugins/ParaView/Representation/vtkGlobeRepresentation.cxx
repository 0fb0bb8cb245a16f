#include "vtkGlobeRepresentation.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeRasterReader.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPVRenderView.h"
#include "vtkRenderer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkWeakPointer.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <map>
#include <set>
#include <string>

vtkStandardNewMacro(vtkGlobeRepresentation);

/// One globe per render view, shared by the view's Globe representations (one layer each).
struct vtkGlobeRepresentationGlobe
{
  vtkNew<vtkGlobeMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkPVRenderView* View = nullptr; // the key only: the view may go before its representations
  vtkWeakPointer<vtkRenderer> Renderer;
  // When each globe setting in force was changed (vtkGlobeRepresentation::GlobeSettings).
  vtkMTimeType SettingTimes[vtkGlobeRepresentation::NumberOfGlobeSettings] = {};
  // The visible representations: with none, the globe is hidden too (not a bare body).
  std::set<vtkGlobeRepresentation*> Shown;

  void Show(vtkGlobeRepresentation* representation, bool visible)
  {
    if (visible)
    {
      this->Shown.insert(representation);
    }
    else
    {
      this->Shown.erase(representation);
    }
    this->Actor->SetVisibility(!this->Shown.empty());
  }

  explicit vtkGlobeRepresentationGlobe(vtkPVRenderView* view)
    : View(view)
  {
    this->Actor->SetMapper(this->Mapper);
    // ParaView's selection renders ids through the actors' mappers; the globe has none.
    this->Actor->PickableOff();
    this->Renderer = view->GetRenderer();
    this->Renderer->AddActor(this->Actor);
  }
  ~vtkGlobeRepresentationGlobe()
  {
    if (this->Renderer)
    {
      this->Renderer->RemoveActor(this->Actor);
    }
  }
};

namespace
{
/// Whether `a` and `b` share their grid, their scalars and their field data's arrays.
bool SameRaster(vtkImageData* a, vtkImageData* b)
{
  int ea[6], eb[6];
  a->GetExtent(ea);
  b->GetExtent(eb);
  double oa[3], ob[3], sa[3], sb[3];
  a->GetOrigin(oa);
  b->GetOrigin(ob);
  a->GetSpacing(sa);
  b->GetSpacing(sb);
  vtkDataArray* va = a->GetPointData()->GetScalars();
  vtkDataArray* vb = b->GetPointData()->GetScalars();
  vtkFieldData* fa = a->GetFieldData();
  vtkFieldData* fb = b->GetFieldData();
  if (!va || va != vb || !std::equal(ea, ea + 6, eb) || !std::equal(oa, oa + 3, ob) ||
    !std::equal(sa, sa + 3, sb) || fa->GetNumberOfArrays() != fb->GetNumberOfArrays())
  {
    return false;
  }
  for (int i = 0; i < fa->GetNumberOfArrays(); ++i)
  {
    if (fa->GetAbstractArray(i) != fb->GetAbstractArray(i))
    {
      return false;
    }
  }
  return true;
}

// The views' globes; an entry lives while a representation holds it.
std::map<vtkPVRenderView*, std::weak_ptr<vtkGlobeRepresentationGlobe>>& Globes()
{
  static std::map<vtkPVRenderView*, std::weak_ptr<vtkGlobeRepresentationGlobe>> globes;
  return globes;
}
}

//------------------------------------------------------------------------------------------
vtkGlobeRepresentation::vtkGlobeRepresentation()
{
  this->Layer->SetRoleToHeight(); // until its data says otherwise (ApplyLayerRole)
}

vtkGlobeRepresentation::~vtkGlobeRepresentation()
{
  if (this->ViewGlobe)
  {
    this->ViewGlobe->Mapper->RemoveLayer(this->Layer);
    this->ViewGlobe->Show(this, false);
  }
}

int vtkGlobeRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------------------
int vtkGlobeRepresentation::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  // The whole raster on every rank: each rendering process draws the same globe, so IceT's
  // depth compositing picks between identical surfaces.
  for (int i = 0; i < inputVector[0]->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(i);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    }
  }
  return 1;
}

int vtkGlobeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? vtkImageData::GetData(inputVector[0], 0)
    : nullptr;
  this->Cache->Initialize();
  if (input)
  {
    this->Cache->ShallowCopy(input);
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------------------
int vtkGlobeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0; // hidden
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVView::SetPiece(inInfo, this, this->Cache);
    // The body's box: what "reset camera" frames.
    double bounds[6] = { -1, 1, -1, 1, -1, 1 };
    if (this->ViewGlobe)
    {
      double radii[3];
      this->ViewGlobe->Mapper->GetEllipsoid()->GetRadii(radii);
      for (int k = 0; k < 3; ++k)
      {
        bounds[2 * k] = -radii[k];
        bounds[2 * k + 1] = radii[k];
      }
    }
    vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    // The delivered raster. ParaView delivers a new copy whenever this representation ran
    // again, which it does for every new view time; the layer's own image changes only when
    // the raster did (not for a time within the same step of a series), since a new image
    // makes the layer load and upload its raster again.
    vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this);
    vtkAlgorithm* algorithm = producer ? producer->GetProducer() : nullptr;
    if (algorithm)
    {
      algorithm->Update(producer->GetIndex());
      auto* delivered =
        vtkImageData::SafeDownCast(algorithm->GetOutputDataObject(producer->GetIndex()));
      if (delivered && delivered->GetPointData()->GetScalars() &&
        !SameRaster(delivered, this->Shown))
      {
        this->Shown->Initialize();
        this->Shown->ShallowCopy(delivered);
        // The layer's name in its messages: the raster's file, else ParaView's name for it.
        auto* file = vtkStringArray::SafeDownCast(delivered->GetFieldData()->GetAbstractArray(
          vtkGlobeRasterReader::GetFileNameArrayName()));
        const std::string name = file && file->GetNumberOfValues() > 0
          ? vtksys::SystemTools::GetFilenameName(file->GetValue(0))
          : this->GetLogName();
        this->Layer->SetName(name.empty() ? nullptr : name.c_str());
        this->ApplyLayerRole();
        if (this->Layer->GetInputAlgorithm() == nullptr ||
          this->Layer->GetInputAlgorithm()->GetOutputDataObject(0) != this->Shown)
        {
          this->Layer->SetInputData(this->Shown);
        }
      }
    }
    // A layer joins the globe once it has its data (never as an empty layer, an error).
    if (this->ViewGlobe && this->Shown->GetPointData()->GetScalars() && !this->InGlobe)
    {
      this->ViewGlobe->Mapper->AddLayer(this->Layer);
      this->InGlobe = true;
    }
    this->ApplyGlobeSettings();
  }
  return 1;
}

//------------------------------------------------------------------------------------------
bool vtkGlobeRepresentation::AddToView(vtkView* view)
{
  auto* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview)
  {
    return false;
  }
  auto& globes = Globes();
  std::shared_ptr<vtkGlobeRepresentationGlobe> globe = globes[rview].lock();
  const bool created = !globe;
  if (created)
  {
    globe = std::make_shared<vtkGlobeRepresentationGlobe>(rview);
    globes[rview] = globe;
  }
  this->ViewGlobe = globe;
  this->Layer->SetEnabled(this->GetVisibility());
  globe->Show(this, this->GetVisibility());
  // A new globe takes all of its first representation's settings; a joining representation
  // only those it changed later than the globe's.
  this->ApplyGlobeSettings(created);
  return this->Superclass::AddToView(view);
}

bool vtkGlobeRepresentation::RemoveFromView(vtkView* view)
{
  auto* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview || !this->ViewGlobe || this->ViewGlobe->View != rview)
  {
    return false;
  }
  this->ViewGlobe->Mapper->RemoveLayer(this->Layer);
  this->ViewGlobe->Show(this, false);
  this->InGlobe = false;
  this->ViewGlobe = nullptr; // the last representation's release removes the actor
  auto& globes = Globes();
  auto found = globes.find(rview);
  if (found != globes.end() && found->second.expired())
  {
    globes.erase(found);
  }
  return this->Superclass::RemoveFromView(view);
}

void vtkGlobeRepresentation::SetVisibility(bool visible)
{
  this->Layer->SetEnabled(visible);
  if (this->ViewGlobe)
  {
    this->ViewGlobe->Show(this, visible);
  }
  this->Superclass::SetVisibility(visible);
}

//------------------------------------------------------------------------------------------
// A setting is stamped only when changed here (ParaView's initial pushes of the defaults
// change nothing), so a representation joining a globe does not undo the settings in force.
void vtkGlobeRepresentation::GlobeSettingChanged(int setting)
{
  vtkTimeStamp now;
  now.Modified();
  this->SettingTimes[setting] = now.GetMTime();
  this->Modified();
}

void vtkGlobeRepresentation::ApplyGlobeSettings(bool all)
{
  vtkGlobeRepresentationGlobe* globe = this->ViewGlobe.get();
  if (!globe)
  {
    return;
  }
  vtkGlobeMapper* mapper = globe->Mapper;
  for (int setting = 0; setting < NumberOfGlobeSettings; ++setting)
  {
    // Per setting, the last change in any of the view's Globe representations is in force.
    if (!all && globe->SettingTimes[setting] >= this->SettingTimes[setting])
    {
      continue;
    }
    globe->SettingTimes[setting] = std::max(globe->SettingTimes[setting], this->SettingTimes[setting]);
    switch (setting)
    {
      case BodySetting:
        if (this->Body == 1)
        {
          mapper->GetEllipsoid()->SetToMoon();
        }
        else if (this->Body == 2)
        {
          mapper->GetEllipsoid()->SetToMars();
        }
        else
        {
          mapper->GetEllipsoid()->SetToWGS84();
        }
        break;
      case GridSetting:
        mapper->SetGridPixelsPerCell(this->GridPixelsPerCell);
        break;
      case RefinementSetting:
        mapper->SetTerrainRefinement(this->TerrainRefinement);
        break;
      case DetailSetting:
        mapper->SetAutoAdjustDetail(this->AutoAdjustDetail);
        break;
      case LightingSetting:
        mapper->SetLighting(this->Lighting);
        break;
      case AtmosphereSetting:
        mapper->SetAtmosphere(this->Atmosphere);
        break;
      case GraticuleSetting:
        mapper->SetGraticule(this->Graticule);
        break;
      case NightLightsSetting:
        mapper->SetNightLights(this->NightLights);
        break;
      case SpecularWaterSetting:
        mapper->SetSpecularWater(this->SpecularWater);
        break;
      default:
        mapper->SetContours(this->Contours);
    }
  }
}

#define vtkGlobeGlobeSetting(name, type, setting)                                              \
  void vtkGlobeRepresentation::Set##name(type value)                                           \
  {                                                                                            \
    if (this->name != value)                                                                   \
    {                                                                                          \
      this->name = value;                                                                      \
      this->GlobeSettingChanged(setting);                                                      \
    }                                                                                          \
  }
vtkGlobeGlobeSetting(Body, int, BodySetting);
vtkGlobeGlobeSetting(GridPixelsPerCell, double, GridSetting);
vtkGlobeGlobeSetting(TerrainRefinement, int, RefinementSetting);
vtkGlobeGlobeSetting(AutoAdjustDetail, bool, DetailSetting);
vtkGlobeGlobeSetting(Lighting, bool, LightingSetting);
vtkGlobeGlobeSetting(Atmosphere, bool, AtmosphereSetting);
vtkGlobeGlobeSetting(Graticule, bool, GraticuleSetting);
vtkGlobeGlobeSetting(NightLights, bool, NightLightsSetting);
vtkGlobeGlobeSetting(SpecularWater, bool, SpecularWaterSetting);
vtkGlobeGlobeSetting(Contours, bool, ContoursSetting);
#undef vtkGlobeGlobeSetting

//------------------------------------------------------------------------------------------
// The layer's settings: uniforms or a re-load of this layer alone (vtkGlobeLayer decides).
void vtkGlobeRepresentation::SetLayerRole(int role)
{
  if (this->LayerRole != role)
  {
    this->LayerRole = role;
    this->ApplyLayerRole();
    this->Modified();
  }
}

void vtkGlobeRepresentation::ApplyLayerRole()
{
  if (this->LayerRole >= 0)
  {
    this->Layer->SetRole(this->LayerRole);
    return;
  }
  // Automatic: imagery (3 or 4 channels) is colour, one channel heights.
  vtkDataArray* values = this->Shown->GetPointData()->GetScalars();
  this->Layer->SetRole(values && values->GetNumberOfComponents() >= 3 ? vtkGlobeLayer::Color
                                                                      : vtkGlobeLayer::Height);
}
void vtkGlobeRepresentation::SetBlendMode(int mode)
{
  this->Layer->SetBlendMode(mode);
}
void vtkGlobeRepresentation::SetOpacity(double opacity)
{
  this->Layer->SetOpacity(opacity);
}
void vtkGlobeRepresentation::SetDrawOrder(int order)
{
  this->Layer->SetDrawOrder(order);
}
void vtkGlobeRepresentation::SetValueScale(double scale)
{
  this->Layer->SetValueScale(scale);
}
void vtkGlobeRepresentation::SetValueOffset(double offset)
{
  this->Layer->SetValueOffset(offset);
}
void vtkGlobeRepresentation::SetFeatherWidth(double texels)
{
  this->Layer->SetFeatherWidth(texels);
}
void vtkGlobeRepresentation::SetInterpolation(int interpolation)
{
  this->Layer->SetInterpolation(interpolation);
}
vtkGlobeLayer* vtkGlobeRepresentation::GetLayer()
{
  return this->Layer;
}

int vtkGlobeRepresentation::GetNumberOfGlobeLayers()
{
  return this->ViewGlobe ? this->ViewGlobe->Mapper->GetNumberOfLayers() : 0;
}

int vtkGlobeRepresentation::GetNumberOfGlobeUploads()
{
  return this->ViewGlobe ? this->ViewGlobe->Mapper->GetLayerSet()->GetNumberOfUploads() : 0;
}

//------------------------------------------------------------------------------------------
void vtkGlobeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LayerRole: " << this->LayerRole << (this->LayerRole < 0 ? " (automatic)" : "")
     << "\n";
  os << indent << "Body: " << this->Body << "\n";
  os << indent << "GridPixelsPerCell: " << this->GridPixelsPerCell << "\n";
  os << indent << "TerrainRefinement: " << this->TerrainRefinement << "\n";
  os << indent << "AutoAdjustDetail: " << this->AutoAdjustDetail << "\n";
  os << indent << "Lighting: " << this->Lighting << "\n";
  os << indent << "Atmosphere: " << this->Atmosphere << "\n";
  os << indent << "Graticule: " << this->Graticule << "\n";
  os << indent << "NightLights: " << this->NightLights << "\n";
  os << indent << "SpecularWater: " << this->SpecularWater << "\n";
  os << indent << "Contours: " << this->Contours << "\n";
  os << indent << "Layer:\n";
  this->Layer->PrintSelf(os, indent.GetNextIndent());
  os << indent << "GlobeLayers: " << this->GetNumberOfGlobeLayers() << "\n";
}
