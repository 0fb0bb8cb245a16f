#include "vtkGlobeMapper.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkGlobeClippingRange.h" // depth: clipping policy
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeDepthPass.h" // depth: the scene's depth mode
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobePageCache.h"
#include "vtkGlobePageFeedback.h"
#include "vtkDoubleArray.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeShaderSources.h"
#include "vtkGlobeTerrain.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtk_glew.h"

#include "vtkGlobeRasterFS.h"
#include "vtkGlobeRasterVS.h"
#include "vtkGlobeReductionFS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGlobeMapper);

class vtkGlobeMapper::vtkInternals
{
public:
  vtkSmartPointer<vtkGlobeEllipsoid> Ellipsoid = vtkSmartPointer<vtkGlobeEllipsoid>::New();
  vtkNew<vtkGlobeLayerSet> Layers;
  vtkNew<vtkGlobeTerrain> Terrain; // the layers composed on the CPU (GetTerrain)
  vtkNew<vtkGlobeProjectiveGrid> Grid;
  vtkNew<vtkGlobeGridPass> GridPass;
  vtkNew<vtkGlobeCompositePass> Composite;
  // Streamed layers: the frame's footprint samples, read back the next frame.
  vtkNew<vtkGlobePageFeedback> Feedback;
  vtkNew<vtkDoubleArray> Footprints;
  double FeedbackGridCell = 1.0; // the grid's cell in pixels when the feedback was drawn
  // Idle: the last feedback read back asked for nothing new and was drawn from the view the
  // last frame showed (camera and window size).
  std::vector<double> FeedbackView, CollectedView, RenderedView;
  bool LastFeedbackAskedForMore = false;

  // G-buffer: direction + height, and depth.
  vtkSmartPointer<vtkTextureObject> GBuffer;
  vtkSmartPointer<vtkTextureObject> GDepth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> GFramebuffer;

  // The grid mesh: no vertex attributes, only indices; vertices fetch their grid point. The
  // last two grid sizes' indices are kept (the full and the interactive detail's), the one
  // drawn last first.
  vtkNew<vtkOpenGLVertexArrayObject> VAO;
  struct GridIndices
  {
    int Resolution = 0;
    vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
    size_t Count = 0;
  };
  std::vector<GridIndices> Indices;

  // Interactive detail (the frame's level is the mapper's LastFrameInteractive): the fixed grid
  // size it divides, and the GPU timers of the last frames with the level each drew (read when
  // done; none waits).
  int FixedResolution = 512;
  std::deque<std::pair<std::unique_ptr<vtkOpenGLRenderTimer>, bool>> FrameTimers;
  double FrameStart = -1.0; // CPU clock without timer queries (s)

  void StartFrameTimer(vtkGlobeMapper* self)
  {
    if (!vtkOpenGLRenderTimer::IsSupported())
    {
      this->FrameStart = vtkTimerLog::GetUniversalTime();
      return;
    }
    if (!this->FrameTimers.empty() && !this->FrameTimers.back().first->Stopped())
    {
      this->FrameTimers.back().first->ReleaseGraphicsResources(); // a frame that stopped early
      this->FrameTimers.pop_back();
    }
    if (this->FrameTimers.size() < 8)
    {
      this->FrameTimers.emplace_back(new vtkOpenGLRenderTimer, self->LastFrameInteractive);
      this->FrameTimers.back().first->Start();
    }
  }
  // Without timer queries the frame's CPU time is the measure, taken now.
  void StopFrameTimer(vtkGlobeMapper* self)
  {
    if (!vtkOpenGLRenderTimer::IsSupported())
    {
      if (this->FrameStart >= 0.0)
      {
        (self->LastFrameInteractive ? self->InteractiveDetailTime : self->FullDetailTime) =
          vtkTimerLog::GetUniversalTime() - this->FrameStart;
      }
      this->FrameStart = -1.0;
      return;
    }
    if (!this->FrameTimers.empty() && !this->FrameTimers.back().first->Stopped())
    {
      this->FrameTimers.back().first->Stop();
    }
  }
  // The finished frames' times, oldest first.
  void CollectFrameTimes(vtkGlobeMapper* self)
  {
    while (!this->FrameTimers.empty() && this->FrameTimers.front().first->Stopped() &&
      this->FrameTimers.front().first->Ready())
    {
      auto& front = this->FrameTimers.front();
      (front.second ? self->InteractiveDetailTime : self->FullDetailTime) =
        front.first->GetElapsedSeconds();
      front.first->ReleaseGraphicsResources();
      this->FrameTimers.pop_front();
    }
  }

  // Minimum reduction.
  std::vector<vtkSmartPointer<vtkTextureObject>> ReductionLevels;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ReductionFramebuffer;
  vtkOpenGLQuadHelper* ReductionQuad = nullptr;
  bool ReductionValid = false;
  double ReducedHeight = 0.0; // lowest visible terrain of the last frame (m)
  double ReductionEye[3] = { 0, 0, 0 };
  // The reduced value travels back through a pixel-pack buffer and is read at the start of the
  // next frame, which needs it first: no frame waits for its own GPU work.
  GLuint ReadbackBuffer = 0;
  bool ReadbackPending = false;
  double PendingEye[3] = { 0, 0, 0 };
  // The view of the frame whose G-buffer the pending and the collected reduction reduced.
  std::vector<double> PendingView, ReductionView;
  // The primary sphere's height in the last frame drawn (NaN: none).
  double PrimaryHeight = std::numeric_limits<double>::quiet_NaN();

  /**
   * The primary sphere for a view whose lowest visible terrain is `reduced`, seen from
   * `above` metres over it: 2-3 % of `above` below it (so terrain that comes into view next
   * frame stays above the sphere), on a grid of a power of two metres near 1 % of `above`,
   * so that views that differ by a little reduce to the same sphere; and the last frame's
   * sphere as long as it lies within a band below `reduced`, so that the reduction's
   * sub-millimetre changes between frames of one view never move the grid, and with it the
   * picture (temporal stability).
   */
  double PrimaryFor(double reduced, double above, double minHeight) const
  {
    const double low = reduced - (0.04 * above + 2.0), high = reduced - (0.01 * above + 0.5);
    if (this->PrimaryHeight >= std::max(minHeight, low) && this->PrimaryHeight <= high)
    {
      return this->PrimaryHeight;
    }
    const double step = std::exp2(std::floor(std::log2(0.01 * above + 0.5)));
    return std::max(minHeight, std::floor((reduced - (0.02 * above + 1.0)) / step) * step);
  }

  vtkOpenGLRenderTimer RasterTimer;
  vtkOpenGLRenderTimer ReductionTimer;
  std::string ReportedStatus;
  std::string ReportedCamera; // the last camera diagnosis reported (once each)
  double Bounds[6] = { -1, 1, -1, 1, -1, 1 };
  // The user's plausible height range; unset: from the body (PlausibleFraction of its
  // smallest radius either way).
  bool PlausibleSet = false;
  double Plausible[2] = { 0.0, 0.0 };

  void UpdateLayers()
  {
    double range[2];
    this->GetPlausible(range);
    this->Layers->SetPlausibleHeightRange(range);
    this->Layers->Update();
  }

  void GetPlausible(double range[2])
  {
    if (this->PlausibleSet)
    {
      range[0] = this->Plausible[0];
      range[1] = this->Plausible[1];
      return;
    }
    const double h = vtkGlobeMapper::GetDefaultPlausibleFraction() *
      this->Ellipsoid->GetMinimumRadius();
    range[0] = -h;
    range[1] = h;
  }

  ~vtkInternals() { delete this->ReductionQuad; }
};

//------------------------------------------------------------------------------
vtkGlobeMapper::vtkGlobeMapper()
  : Internals(new vtkInternals)
{
  // The globe has no polydata input: render without one, and without scalars.
  this->Static = 1;
  this->ScalarVisibility = 0;
  auto& in = *this->Internals;
  in.Grid->SetEllipsoid(in.Ellipsoid);
  in.GridPass->SetProjectiveGrid(in.Grid);
  in.GridPass->SetLayers(in.Layers);
  in.Composite->SetEllipsoid(in.Ellipsoid);
  in.Composite->SetLayers(in.Layers);
}

vtkGlobeMapper::~vtkGlobeMapper() = default;

void vtkGlobeMapper::SetEllipsoid(vtkGlobeEllipsoid* ellipsoid)
{
  auto& in = *this->Internals;
  if (ellipsoid == in.Ellipsoid && ellipsoid)
  {
    return;
  }
  in.Ellipsoid = ellipsoid ? ellipsoid : vtkSmartPointer<vtkGlobeEllipsoid>::New().Get();
  in.Grid->SetEllipsoid(in.Ellipsoid);
  in.Composite->SetEllipsoid(in.Ellipsoid);
  in.ReductionValid = false;
  in.ReadbackPending = false;
  this->Modified();
}

vtkGlobeEllipsoid* vtkGlobeMapper::GetEllipsoid()
{
  return this->Internals->Ellipsoid;
}

void vtkGlobeMapper::SetPlausibleHeightRange(double minimum, double maximum)
{
  auto& in = *this->Internals;
  if (!(minimum < maximum) || std::isnan(minimum) || std::isnan(maximum))
  {
    vtkErrorMacro(<< "SetPlausibleHeightRange: the range [" << minimum << ", " << maximum
                  << "] m is empty; the range is left as it was");
    return;
  }
  if (in.PlausibleSet && in.Plausible[0] == minimum && in.Plausible[1] == maximum)
  {
    return;
  }
  in.PlausibleSet = true;
  in.Plausible[0] = minimum;
  in.Plausible[1] = maximum;
  this->Modified();
}

void vtkGlobeMapper::GetPlausibleHeightRange(double range[2])
{
  this->Internals->GetPlausible(range);
}

void vtkGlobeMapper::UseBodyPlausibleHeightRange()
{
  if (this->Internals->PlausibleSet)
  {
    this->Internals->PlausibleSet = false;
    this->Modified();
  }
}

void vtkGlobeMapper::AddLayer(vtkGlobeLayer* layer)
{
  this->Internals->Layers->AddLayer(layer);
  this->Modified();
}

void vtkGlobeMapper::RemoveLayer(vtkGlobeLayer* layer)
{
  this->Internals->Layers->RemoveLayer(layer);
  this->Modified();
}

void vtkGlobeMapper::RemoveAllLayers()
{
  this->Internals->Layers->RemoveAllLayers();
  this->Modified();
}

int vtkGlobeMapper::GetNumberOfLayers()
{
  return this->Internals->Layers->GetNumberOfLayers();
}

vtkGlobeLayer* vtkGlobeMapper::GetLayer(int index)
{
  return this->Internals->Layers->GetLayer(index);
}

vtkGlobeLayerSet* vtkGlobeMapper::GetLayerSet()
{
  return this->Internals->Layers;
}

vtkGlobeTerrain* vtkGlobeMapper::GetTerrain()
{
  // The same layers, in the same order, as the mapper's (added and removed since?).
  vtkGlobeTerrain* terrain = this->Internals->Terrain;
  const int n = this->GetNumberOfLayers();
  bool same = terrain->GetNumberOfLayers() == n;
  for (int i = 0; same && i < n; ++i)
  {
    same = terrain->GetLayer(i) == this->GetLayer(i);
  }
  if (!same)
  {
    terrain->RemoveAllLayers();
    for (int i = 0; i < n; ++i)
    {
      terrain->AddLayer(this->GetLayer(i));
    }
  }
  return terrain;
}

void vtkGlobeMapper::SetGridResolution(int resolution)
{
  // Above 2048 the index buffer alone would take more than 100 MB.
  resolution = std::max(2, std::min(resolution, 2048));
  if (resolution != this->Internals->FixedResolution || this->GridPixelsPerCell != 0.0)
  {
    this->Internals->FixedResolution = resolution;
    this->Internals->GridPass->SetResolution(resolution);
    this->GridPixelsPerCell = 0.0;
    this->Modified();
  }
}

void vtkGlobeMapper::SetGridPixelsPerCell(double pixels)
{
  pixels = std::isfinite(pixels) ? std::max(0.0, std::min(pixels, 1e4)) : 0.0;
  if (pixels != this->GridPixelsPerCell)
  {
    this->GridPixelsPerCell = pixels;
    this->Modified();
  }
}

int vtkGlobeMapper::GetGridResolution()
{
  return this->Internals->GridPass->GetResolution();
}

void vtkGlobeMapper::SetAmbient(double ambient)
{
  this->Internals->Composite->SetAmbient(ambient);
  this->Modified();
}

double vtkGlobeMapper::GetAmbient()
{
  return this->Internals->Composite->GetAmbient();
}

void vtkGlobeMapper::SetBaseColor(double r, double g, double b)
{
  this->Internals->Composite->SetBaseColor(r, g, b);
  this->Modified();
}

double* vtkGlobeMapper::GetBaseColor()
{
  return this->Internals->Composite->GetBaseColor();
}

void vtkGlobeMapper::GetBaseColor(double rgb[3])
{
  this->Internals->Composite->GetBaseColor(rgb);
}

//------------------------------------------------------------------------------
// No input: refused, not ignored (a cone given to the globe would otherwise vanish silently).
void vtkGlobeMapper::SetInputConnection(int port, vtkAlgorithmOutput* input)
{
  if (input)
  {
    vtkErrorMacro(<< "vtkGlobeMapper takes no input (port " << port << "): the globe is drawn "
                  << "from its ellipsoid and its layers (AddLayer); draw other data with its own "
                  << "mapper and actor. The input is ignored.");
  }
}

void vtkGlobeMapper::SetInputConnection(vtkAlgorithmOutput* input)
{
  this->SetInputConnection(0, input);
}

void vtkGlobeMapper::AddInputConnection(int port, vtkAlgorithmOutput* input)
{
  this->SetInputConnection(port, input);
}

void vtkGlobeMapper::AddInputConnection(vtkAlgorithmOutput* input)
{
  this->SetInputConnection(0, input);
}

void vtkGlobeMapper::SetInputDataObject(int port, vtkDataObject* data)
{
  if (data)
  {
    vtkErrorMacro(<< "vtkGlobeMapper takes no input data (port " << port << "): the globe is "
                  << "drawn from its ellipsoid and its layers (AddLayer). The data is ignored.");
  }
}

void vtkGlobeMapper::SetInputDataObject(vtkDataObject* data)
{
  this->SetInputDataObject(0, data);
}

void vtkGlobeMapper::SetHighPrecisionGeodetic(bool on)
{
  if (this->Internals->Layers->GetHighPrecisionGeodetic() != on)
  {
    this->Internals->Layers->SetHighPrecisionGeodetic(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetHighPrecisionGeodetic()
{
  return this->Internals->Layers->GetHighPrecisionGeodetic();
}

void vtkGlobeMapper::SetTerrainRefinement(int steps)
{
  steps = std::max(0, std::min(4, steps));
  if (this->Internals->Composite->GetTerrainRefinement() != steps)
  {
    this->Internals->Composite->SetTerrainRefinement(steps);
    this->Modified();
  }
}

int vtkGlobeMapper::GetTerrainRefinement()
{
  return this->Internals->Composite->GetTerrainRefinement();
}

void vtkGlobeMapper::SetFootprintFiltering(bool on)
{
  if (this->Internals->Layers->GetFootprintFiltering() != on)
  {
    this->Internals->Layers->SetFootprintFiltering(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetFootprintFiltering()
{
  return this->Internals->Layers->GetFootprintFiltering();
}

vtkGlobeProjectiveGrid* vtkGlobeMapper::GetProjectiveGrid()
{
  return this->Internals->Grid;
}

vtkGlobeGridPass* vtkGlobeMapper::GetGridPass()
{
  return this->Internals->GridPass;
}

vtkGlobeCompositePass* vtkGlobeMapper::GetCompositePass()
{
  return this->Internals->Composite;
}

// --- hard cases: G-buffer access for tests
vtkTextureObject* vtkGlobeMapper::GetGBufferTexture()
{
  return this->Internals->GBuffer;
}

vtkTextureObject* vtkGlobeMapper::GetGBufferDepthTexture()
{
  return this->Internals->GDepth;
}
// --- end hard cases

double vtkGlobeMapper::GetRasterTime()
{
  return vtkOpenGLRenderTimer::IsSupported()
    ? this->Internals->RasterTimer.GetReusableElapsedSeconds()
    : -1.0;
}

double vtkGlobeMapper::GetReductionTime()
{
  return vtkOpenGLRenderTimer::IsSupported()
    ? this->Internals->ReductionTimer.GetReusableElapsedSeconds()
    : -1.0;
}

vtkMTimeType vtkGlobeMapper::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  t = std::max(t, this->Internals->Ellipsoid->GetMTime());
  // Shading and effects are held by the composite pass, whichever name set them.
  t = std::max(t, this->Internals->Composite->GetMTime());
  return std::max(t, this->Internals->Layers->GetMTime());
}

double* vtkGlobeMapper::GetBounds()
{
  auto& in = *this->Internals;
  in.UpdateLayers();
  const double* r = in.Ellipsoid->GetRadii();
  const double top = std::max(0.0, in.Layers->GetMaximumHeight());
  for (int i = 0; i < 3; ++i)
  {
    in.Bounds[2 * i] = -(r[i] + top);
    in.Bounds[2 * i + 1] = r[i] + top;
  }
  return in.Bounds;
}


//------------------------------------------------------------------------------
// Effects: forwarded to the composition pass.
void vtkGlobeMapper::SetLighting(bool on)
{
  if (this->Internals->Composite->GetLighting() != on)
  {
    this->Internals->Composite->SetLighting(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetLighting()
{
  return this->Internals->Composite->GetLighting();
}

void vtkGlobeMapper::SetNightLights(bool on)
{
  if (this->Internals->Composite->GetNightLights() != on)
  {
    this->Internals->Composite->SetNightLights(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetNightLights()
{
  return this->Internals->Composite->GetNightLights();
}

void vtkGlobeMapper::SetSpecularWater(bool on)
{
  if (this->Internals->Composite->GetSpecularWater() != on)
  {
    this->Internals->Composite->SetSpecularWater(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetSpecularWater()
{
  return this->Internals->Composite->GetSpecularWater();
}

void vtkGlobeMapper::SetAtmosphere(bool on)
{
  if (this->Internals->Composite->GetAtmosphere() != on)
  {
    this->Internals->Composite->SetAtmosphere(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetAtmosphere()
{
  return this->Internals->Composite->GetAtmosphere();
}

void vtkGlobeMapper::SetGraticule(bool on)
{
  if (this->Internals->Composite->GetGraticule() != on)
  {
    this->Internals->Composite->SetGraticule(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetGraticule()
{
  return this->Internals->Composite->GetGraticule();
}

void vtkGlobeMapper::SetContours(bool on)
{
  if (this->Internals->Composite->GetContours() != on)
  {
    this->Internals->Composite->SetContours(on);
    this->Modified();
  }
}

bool vtkGlobeMapper::GetContours()
{
  return this->Internals->Composite->GetContours();
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  auto& in = *this->Internals;
  in.Layers->ReleaseGraphicsResources(window);
  in.Feedback->ReleaseGraphicsResources(window);
  in.GridPass->ReleaseGraphicsResources(window);
  in.Composite->ReleaseGraphicsResources(window);
  for (auto* t : { in.GBuffer.Get(), in.GDepth.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  in.GBuffer = nullptr;
  in.GDepth = nullptr;
  if (in.GFramebuffer)
  {
    in.GFramebuffer->ReleaseGraphicsResources(window);
    in.GFramebuffer = nullptr;
  }
  in.VAO->ReleaseGraphicsResources();
  for (auto& indices : in.Indices)
  {
    indices.Buffer->ReleaseGraphicsResources();
  }
  in.Indices.clear();
  for (auto& timer : in.FrameTimers)
  {
    timer.first->ReleaseGraphicsResources();
  }
  in.FrameTimers.clear();
  for (auto& t : in.ReductionLevels)
  {
    t->ReleaseGraphicsResources(window);
  }
  in.ReductionLevels.clear();
  if (in.ReductionFramebuffer)
  {
    in.ReductionFramebuffer->ReleaseGraphicsResources(window);
    in.ReductionFramebuffer = nullptr;
  }
  delete in.ReductionQuad;
  in.ReductionQuad = nullptr;
  in.RasterTimer.ReleaseGraphicsResources();
  in.ReductionTimer.ReleaseGraphicsResources();
  if (in.ReadbackBuffer)
  {
    glDeleteBuffers(1, &in.ReadbackBuffer);
    in.ReadbackBuffer = 0;
  }
  in.ReadbackPending = false;
  in.ReductionValid = false;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::UpdateLight(vtkRenderer* ren, vtkActor* act)
{
  auto& in = *this->Internals;
  double toLight[3] = { 0, 0, 0 };
  double color[3] = { 1, 1, 1 };
  bool found = false;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    double p[3], f[3];
    light->GetTransformedPosition(p);
    light->GetTransformedFocalPoint(f);
    for (int i = 0; i < 3; ++i)
    {
      toLight[i] = p[i] - f[i];
      color[i] = light->GetDiffuseColor()[i] * light->GetIntensity();
    }
    found = vtkMath::Norm(toLight) > 0.0;
    break;
  }
  if (!found)
  {
    // No light: light from the camera, as VTK's headlight does.
    vtkCamera* camera = ren->GetActiveCamera();
    const double* p = camera->GetPosition();
    const double* f = camera->GetFocalPoint();
    for (int i = 0; i < 3; ++i)
    {
      toLight[i] = p[i] - f[i];
    }
  }
  // Into the body frame: the inverse of the actor's rotation.
  vtkNew<vtkMatrix4x4> worldToBody;
  vtkMatrix4x4::Invert(act->GetMatrix(), worldToBody);
  double direction[4] = { toLight[0], toLight[1], toLight[2], 0.0 };
  worldToBody->MultiplyPoint(direction, direction);
  vtkMath::Normalize(direction);
  in.Composite->SetLightDirection(direction);
  in.Composite->SetLightColor(color);
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::DiagnoseCamera(vtkRenderer* ren, const double eyeBody[3], double minHeight,
  std::string& key, std::string& message)
{
  auto& in = *this->Internals;
  key.clear();
  vtkCamera* camera = ren->GetActiveCamera();
  const double* p = camera->GetPosition();
  const double* up = camera->GetViewUp();
  double view[3];
  camera->GetDirectionOfProjection(view);
  const double length = vtkMath::Norm(view);
  if (!std::isfinite(length) || !std::isfinite(vtkMath::Norm(up)) ||
    !std::isfinite(vtkMath::Norm(p)))
  {
    return; // a NaN camera: the projective grid says so
  }
  char text[400];
  // A focal point at the position leaves VTK's direction of projection zero.
  if (!(length > 0.5))
  {
    key = "focal";
    std::snprintf(text, sizeof(text),
      "The globe is not drawn: the camera's focal point equals its position (%g, %g, %g), so "
      "the view direction is undefined; set a focal point away from the position",
      p[0], p[1], p[2]);
    message = text;
    return;
  }
  double side[3];
  vtkMath::Cross(view, up, side);
  if (!(vtkMath::Norm(side) > 1e-9 * length * vtkMath::Norm(up)))
  {
    key = "up";
    std::snprintf(text, sizeof(text),
      "The globe is not drawn: the camera's view-up (%g, %g, %g) is parallel to its view "
      "direction, so the view's orientation is undefined; set a view-up across the view (or "
      "call OrthogonalizeViewUp() after choosing one)",
      up[0], up[1], up[2]);
    message = text;
    return;
  }
  double llh[3];
  if (!in.Ellipsoid->CartesianToGeodeticQuiet(eyeBody, llh))
  {
    return; // at the centre: the projective grid says so
  }
  // Below the terrain under it, or below the lowest data anywhere: inside the body.
  bool exact = false;
  const double ground = vtkGlobeClippingRange::ComputeTerrainHeight(this, llh[0], llh[1], exact);
  const double depth = std::max(exact ? ground - llh[2] : -VTK_DOUBLE_MAX, minHeight - llh[2]);
  if (depth > 0.0)
  {
    key = "inside";
    std::snprintf(text, sizeof(text),
      "The camera is inside the body, %.6g m below the terrain at (%.6f, %.6f): the globe is "
      "seen from inside and shows little or nothing",
      depth, llh[0], llh[1]);
    message = text;
    return;
  }
  // Smaller than a pixel: nothing to draw, however correct.
  const double distance = vtkMath::Norm(eyeBody);
  const double radius = in.Ellipsoid->GetMaximumRadius() + std::max(0.0, in.Layers->GetMaximumHeight());
  int size[2] = { 1, 1 };
  if (ren->GetRenderWindow())
  {
    ren->GetTiledSize(&size[0], &size[1]);
  }
  const double pixel = vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / std::max(1, size[1]);
  const double diameter = 2.0 * std::asin(std::min(1.0, radius / distance));
  if (diameter < pixel)
  {
    key = "small";
    std::snprintf(text, sizeof(text),
      "The globe is smaller than a pixel from %.3g m (%.3g of a pixel across): nothing of it "
      "is drawn",
      distance, diameter / pixel);
    message = text;
  }
}

//------------------------------------------------------------------------------
vtkActor* vtkGlobeMapper::FindGlobeActor(vtkRenderer* renderer, vtkGlobeMapper* mapper)
{
  if (!renderer)
  {
    return nullptr;
  }
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    auto* globe = vtkGlobeMapper::SafeDownCast(actor->GetMapper());
    if (globe && (mapper ? globe == mapper : actor->GetVisibility() != 0))
    {
      return actor;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  auto& in = *this->Internals;
  this->LastFrameDrewGlobe = false;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return;
  }
  // Depth: from now on the renderer's ResetCameraClippingRange uses the globe's policy.
  vtkGlobeClippingRange::Install(ren);
  vtkOpenGLState* state = window->GetState();
  int viewport[4];
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  const int width = viewport[2], height = viewport[3];
  if (width <= 0 || height <= 0)
  {
    return;
  }

  this->CollectReduction();
  // Interactive detail: a frame allocated less time than the last full-detail frame took.
  in.CollectFrameTimes(this);
  this->LastFrameInteractive = this->AutoAdjustDetail && this->FullDetailTime > 0.0 &&
    act->GetAllocatedRenderTime() < this->FullDetailTime;
  in.Composite->SetRefinementSuspended(this->LastFrameInteractive);
  in.UpdateLayers();
  const bool streaming = in.Layers->GetNumberOfStreamedLayers() > 0;
  if (in.Feedback->IsPending())
  {
    // The last frame's footprint asks for pages before this frame uploads what came in.
    in.Feedback->Collect(in.Footprints);
    const long long requested = in.Layers->GetPageCache()->GetNumberOfRequestedPages();
    if (streaming)
    {
      in.Layers->RequestPages(in.Footprints, in.Feedback->GetBlockSize(), in.FeedbackGridCell);
    }
    in.LastFeedbackAskedForMore =
      in.Layers->GetPageCache()->GetNumberOfRequestedPages() != requested;
    in.CollectedView = in.FeedbackView;
  }
  in.Layers->UploadTextures(window, this->WaitForPages);
  double minHeight = in.Layers->GetMinimumHeight();
  double maxHeight = in.Layers->GetMaximumHeight();

  // The primary sphere: the lowest terrain seen in the last frame, unless the camera jumped
  // (moved by more than a quarter of its height over that terrain), or there is none.
  vtkCamera* camera = ren->GetActiveCamera();
  double eye[4] = { 0, 0, 0, 1 };
  camera->GetPosition(eye);
  vtkNew<vtkMatrix4x4> worldToBody;
  vtkMatrix4x4::Invert(act->GetMatrix(), worldToBody);
  worldToBody->MultiplyPoint(eye, eye);
  double primaryHeight = minHeight;
  this->PrimaryFromReduction = false;
  double llh[3];
  in.Ellipsoid->CartesianToGeodeticQuiet(eye, llh);
  if (in.ReductionValid)
  {
    const double above = std::abs(llh[2] - in.ReducedHeight);
    const double moved = std::sqrt(vtkMath::Distance2BetweenPoints(eye, in.ReductionEye));
    if (moved <= 0.25 * above + 1.0)
    {
      primaryHeight = in.PrimaryFor(in.ReducedHeight, above, minHeight);
      this->PrimaryFromReduction = true;
    }
  }
  in.PrimaryHeight = std::numeric_limits<double>::quiet_NaN(); // set again once drawn

  // Cameras that leave nothing of the globe to see: said once while they last.
  std::string key, message;
  this->DiagnoseCamera(ren, eye, minHeight, key, message);
  if (key != in.ReportedCamera)
  {
    in.ReportedCamera = key;
    if (!key.empty())
    {
      vtkWarningMacro(<< message);
    }
  }
  if (key == "focal" || key == "up")
  {
    in.ReductionValid = false;
    return;
  }

  // Every cast of the grid (this one, the page rounds', the recast) sizes the automatic grid
  // for it, so that a view always gets the same grid.
  auto castGrid = [&]() {
    const bool cast = in.Grid->Update(
      camera, act->GetMatrix(), ren->GetTiledAspectRatio(), primaryHeight, maxHeight);
    this->FitGrid(ren, act, width, height);
    return cast;
  };
  if (!castGrid())
  {
    if (in.ReportedStatus != in.Grid->GetStatus())
    {
      vtkErrorMacro(<< "The globe is not drawn: " << in.Grid->GetStatus());
      in.ReportedStatus = in.Grid->GetStatus();
    }
    in.ReductionValid = false;
    return;
  }
  in.ReportedStatus.clear();
  if (!in.Grid->GetVisible())
  {
    in.ReductionValid = false;
    return;
  }
  // Layers out of the view are left out of the passes below.
  in.Layers->CullLayers(camera, ren->GetTiledAspectRatio(), act->GetMatrix(), in.Ellipsoid);

  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkRenderState renderState(ren);
  {
    const double* p = camera->GetPosition();
    const double* f = camera->GetFocalPoint();
    const double* u = camera->GetViewUp();
    in.RenderedView = { p[0], p[1], p[2], f[0], f[1], f[2], u[0], u[1], u[2],
      camera->GetViewAngle(), static_cast<double>(width), static_cast<double>(height),
      static_cast<double>(act->GetMTime()), this->LastFrameInteractive ? 1.0 : 0.0 };
  }
  // The globe's GPU time, grid to composition, for the next frames' level of detail.
  in.StartFrameTimer(this);
  in.GridPass->Render(&renderState);
  if (!this->RenderGBuffer(ren, act, width, height))
  {
    return;
  }
  // The footprint of the G-buffer: read back by the next frame, or now when waiting.
  double reference[3] = { 0.0, 0.0, 0.0 };
  if (streaming && in.Layers->GetHighPrecisionGeodetic())
  {
    in.Layers->GetReferenceDirection(reference);
  }
  if (streaming)
  {
    in.FeedbackGridCell =
      static_cast<double>(std::max(width, height)) / std::max(1, in.GridPass->GetResolution() - 1);
    vtkGlobePageCache* cache = in.Layers->GetPageCache();
    for (int round = 0; this->WaitForPages && round < 16; ++round)
    {
      if (!in.Feedback->Render(window, in.GBuffer, in.GDepth, reference, in.Ellipsoid->GetRadii()))
      {
        break;
      }
      in.Feedback->Collect(in.Footprints);
      const long long requested = cache->GetNumberOfRequestedPages();
      in.Layers->RequestPages(in.Footprints, in.Feedback->GetBlockSize(), in.FeedbackGridCell);
      if (cache->GetNumberOfRequestedPages() == requested)
      {
        break; // everything this frame shows is resident
      }
      const long long loaded = cache->GetNumberOfLoadedPages();
      in.Layers->UploadTextures(window, true);
      if (cache->GetNumberOfLoadedPages() == loaded)
      {
        break; // no room for more: the frame keeps the ancestors
      }
      // The new pages may raise the terrain's bounds: the grid is cast again, on the same
      // primary sphere (lower terrain they show is caught by the reduction below).
      maxHeight = in.Layers->GetMaximumHeight();
      minHeight = in.Layers->GetMinimumHeight();
      primaryHeight = std::max(primaryHeight, minHeight);
      castGrid();
      in.GridPass->Render(&renderState);
      if (!this->RenderGBuffer(ren, act, width, height))
      {
        return;
      }
    }
  }
  bool reduced = false;
  bool levels = false; // the reduction's levels are this G-buffer's
  if (!(in.ReductionValid && in.ReductionView == in.RenderedView))
  {
    // A new view (or the first): its sphere came from another view's terrain, and the next
    // frame would correct it, changing the picture. This frame's own lowest terrain is read
    // back now (the one frame that waits for the GPU) and, when it asks for another sphere,
    // the grid is cast again, so the first frame after a move is final.
    levels = this->ReduceMinimumRadius(ren, width, height, eye);
    this->CollectReduction();
    reduced = in.ReductionValid;
    if (in.ReductionValid)
    {
      in.PrimaryHeight = primaryHeight;
      const double settled =
        in.PrimaryFor(in.ReducedHeight, std::abs(llh[2] - in.ReducedHeight), minHeight);
      ++this->NumberOfSynchronousReductions;
      if (settled != primaryHeight)
      {
        primaryHeight = settled;
        this->PrimaryFromReduction = true;
        ++this->NumberOfRecasts;
        reduced = levels = false; // the G-buffer changes: reduce it again below
        castGrid();
        in.GridPass->Render(&renderState);
        if (!this->RenderGBuffer(ren, act, width, height))
        {
          return;
        }
      }
    }
  }
  if (streaming && !this->WaitForPages)
  {
    // The final G-buffer's footprint, for the next frame's page requests.
    in.Feedback->Render(window, in.GBuffer, in.GDepth, reference, in.Ellipsoid->GetRadii());
    in.FeedbackView = in.RenderedView;
  }
  if (!reduced && !levels)
  {
    // The final G-buffer's reduction: the next frame's primary sphere (read back then), and
    // now the blocks the composition shades.
    levels = this->ReduceMinimumRadius(ren, width, height, eye);
  }
  state->vtkglViewport(viewport[0], viewport[1], width, height);
  this->UpdateLight(ren, act);
  in.Composite->SetGBuffer(in.GBuffer, in.GDepth);
  // The reduction's second level: 16 x 16 pixel blocks.
  in.Composite->SetCoverage(
    levels && in.ReductionLevels.size() > 1 ? in.ReductionLevels[1].Get() : nullptr, 16);
  in.Composite->Render(&renderState);
  in.Composite->SetCoverage(nullptr, 0);
  in.StopFrameTimer(this);
  this->LastFrameDrewGlobe = true;
  in.PrimaryHeight = primaryHeight;
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::FitGrid(vtkRenderer* ren, vtkActor* act, int width, int height)
{
  auto& in = *this->Internals;
  const double coarsening = this->LastFrameInteractive ? this->InteractiveGridCoarsening : 1.0;
  if (!(this->GridPixelsPerCell > 0.0))
  {
    // A fixed GridResolution (divided at interactive detail).
    in.GridPass->SetResolution(
      std::max(2, static_cast<int>(std::ceil(in.FixedResolution / coarsening))));
    return;
  }
  const double pixelsPerCell = this->GridPixelsPerCell * coarsening;
  // The grid follows the viewport (not Modified(): a window resize rebuilds nothing else), or
  // the grid's own span on screen where that is shorter (the whole planet in part of the
  // window), rounded up to 16 points so that nearby views share a size.
  const double side = std::max(width, height);
  const double windowPoints = std::ceil(side / pixelsPerCell);
  double points = windowPoints;
  const double span = in.Grid->ComputeSamplingSpan(
    ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1),
    act->GetMatrix(), width, height);
  if (span < side)
  {
    points = std::min(windowPoints, 16.0 * std::ceil(span / pixelsPerCell / 16.0));
  }
  in.GridPass->SetResolution(static_cast<int>(std::max(2.0, std::min(points, 2048.0))));
}

//------------------------------------------------------------------------------
vtkGlobePageCache* vtkGlobeMapper::GetPageCache()
{
  return this->Internals->Layers->GetPageCache();
}

bool vtkGlobeMapper::IsStreamingIdle()
{
  auto& in = *this->Internals;
  if (in.Layers->GetNumberOfStreamedLayers() == 0 || this->WaitForPages)
  {
    return true;
  }
  return in.Layers->GetPageCache()->IsIdle() && !in.LastFeedbackAskedForMore &&
    in.CollectedView == in.RenderedView;
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::CollectReduction()
{
  auto& in = *this->Internals;
  if (!in.ReadbackPending)
  {
    return;
  }
  in.ReadbackPending = false;
  float value = 1e30f;
  glBindBuffer(GL_PIXEL_PACK_BUFFER, in.ReadbackBuffer);
  if (const void* mapped = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, sizeof(float), GL_MAP_READ_BIT))
  {
    std::memcpy(&value, mapped, sizeof(float));
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  in.ReductionValid = std::isfinite(value) && value < 1e29f;
  if (in.ReductionValid)
  {
    // rho - 1 in scaled units back to a height, as vtkGlobeProjectiveGrid maps heights.
    in.ReducedHeight = value * in.Ellipsoid->GetMinimumRadius();
    this->LastVisibleMinimumHeight = in.ReducedHeight;
    for (int i = 0; i < 3; ++i)
    {
      in.ReductionEye[i] = in.PendingEye[i];
    }
    in.ReductionView = in.PendingView;
  }
}

//------------------------------------------------------------------------------
bool vtkGlobeMapper::RenderGBuffer(vtkRenderer* ren, vtkActor* act, int width, int height)
{
  auto& in = *this->Internals;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  if (!in.GFramebuffer)
  {
    in.GFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.GFramebuffer->SetContext(window);
    in.GBuffer = vtkSmartPointer<vtkTextureObject>::New();
    in.GBuffer->SetContext(window);
    in.GBuffer->SetMinificationFilter(vtkTextureObject::Nearest);
    in.GBuffer->SetMagnificationFilter(vtkTextureObject::Nearest);
    in.GBuffer->SetWrapS(vtkTextureObject::ClampToEdge);
    in.GBuffer->SetWrapT(vtkTextureObject::ClampToEdge);
    in.GBuffer->Allocate2D(width, height, 4, VTK_FLOAT);
    in.GDepth = vtkSmartPointer<vtkTextureObject>::New();
    in.GDepth->SetContext(window);
    in.GDepth->SetMinificationFilter(vtkTextureObject::Nearest);
    in.GDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
    in.GDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  in.GBuffer->Resize(width, height);
  in.GDepth->Resize(width, height);

  // The mesh's indices, built only for a grid size not drawn in the last two.
  const int n = in.GridPass->GetResolution();
  auto cached = std::find_if(in.Indices.begin(), in.Indices.end(),
    [n](const vtkInternals::GridIndices& g) { return g.Resolution == n; });
  if (cached != in.Indices.end())
  {
    std::rotate(in.Indices.begin(), cached, cached + 1);
  }
  else
  {
    if (in.Indices.size() >= 2)
    {
      in.Indices.back().Buffer->ReleaseGraphicsResources();
      in.Indices.pop_back();
    }
    std::vector<unsigned int> indices;
    indices.reserve(static_cast<size_t>(n - 1) * (n - 1) * 6);
    for (int j = 0; j + 1 < n; ++j)
    {
      for (int i = 0; i + 1 < n; ++i)
      {
        const unsigned int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
        indices.insert(indices.end(), { a, b, d, a, d, c });
      }
    }
    vtkInternals::GridIndices grid;
    grid.Resolution = n;
    grid.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    grid.Buffer->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
    grid.Buffer->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
    grid.Count = indices.size();
    in.Indices.insert(in.Indices.begin(), grid);
  }

  const bool highPrecision = in.Layers->GetHighPrecisionGeodetic();
  static const std::string vertexShaders[2] = {
    vtkGlobeShaderSources::Replace(vtkGlobeRasterVS, "//GLOBE::Math", vtkGlobeShaderSources::Math()),
    vtkGlobeShaderSources::Replace(vtkGlobeRasterVS, "//GLOBE::Math",
      "#define GLOBE_HIGH_PRECISION_GEODETIC\n" + vtkGlobeShaderSources::Math())
  };
  const std::string& vertexShader = vertexShaders[highPrecision ? 1 : 0];
  // --- depth mode (vtkGlobeDepthPass): the G-buffer's depth is written in the scene's mode,
  // and the composite pass copies it as it is.
  vtkGlobeDepthPass* depthPass = vtkGlobeDepthPass::FindInProp(act);
  std::string rasterVS = vertexShader, rasterFS = vtkGlobeRasterFS;
  if (depthPass)
  {
    depthPass->InjectDepthCode(rasterVS, rasterFS);
  }
  // --- end depth mode
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(rasterVS.c_str(), rasterFS.c_str(), "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro(<< "The globe's rasterization shader did not compile");
    return false;
  }

  // Eye-relative body coordinates (m) -> clip: projection * view rotation * actor rotation,
  // composed in double; translations cancel in eye-relative coordinates.
  vtkCamera* camera = ren->GetActiveCamera();
  vtkNew<vtkMatrix4x4> view;
  view->DeepCopy(camera->GetViewTransformMatrix());
  vtkNew<vtkMatrix4x4> model;
  model->DeepCopy(act->GetMatrix());
  for (int i = 0; i < 3; ++i)
  {
    view->SetElement(i, 3, 0.0);
    model->SetElement(i, 3, 0.0);
  }
  vtkNew<vtkMatrix4x4> eyeToClip;
  vtkMatrix4x4::Multiply4x4(view, model, eyeToClip);
  vtkMatrix4x4::Multiply4x4(
    camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1), eyeToClip, eyeToClip);
  {
    // The composition casts per-pixel view rays with the inverse.
    vtkNew<vtkMatrix4x4> clipToEye;
    vtkMatrix4x4::Invert(eyeToClip, clipToEye);
    double eyeBody[4] = { 0, 0, 0, 1 };
    camera->GetPosition(eyeBody);
    vtkNew<vtkMatrix4x4> worldToBody;
    vtkMatrix4x4::Invert(act->GetMatrix(), worldToBody);
    worldToBody->MultiplyPoint(eyeBody, eyeBody);
    in.Composite->SetView(eyeBody, clipToEye->GetData());
  }
  {
    // The refinement's frame (vtkGlobeCompositePass::SetRefinementFrame). Chord: the G-buffer
    // holds o = (p - A nadir) / rp in float (the raster shader's floats A, nadir, rp), so the
    // mesh point's direction is u = ref + o - delta with ref = -nadir (float) and delta what
    // the floats miss of the exact eye; 1 - |u|^2 = -C - 2 o.(ref - delta) - o.o.
    double chord[4] = { 0.0, 0.0, 0.0, -1.0 }; // not read: no refinement without offsets
    if (highPrecision)
    {
      const double* nadir = in.Grid->GetNadir();
      const double rp = in.Grid->GetPrimaryRadius(), alt = in.Grid->GetAltitude();
      const double rpF = static_cast<float>(rp), altF = static_cast<float>(alt);
      double ref[3], delta[3];
      for (int k = 0; k < 3; ++k)
      {
        const double nadirF = static_cast<float>(nadir[k]);
        ref[k] = -nadirF;
        delta[k] = -nadirF - altF * nadirF / rpF + (rp + alt) * nadir[k] / rp;
      }
      const double refRef = vtkMath::Dot(ref, ref), refDelta = vtkMath::Dot(ref, delta);
      chord[3] = (refRef - 1.0) - 2.0 * refDelta + vtkMath::Dot(delta, delta);
      for (int k = 0; k < 3; ++k)
      {
        chord[k] = ref[k] - delta[k];
      }
    }
    // Clip w of an eye-relative body point, and the window depth as a function of it.
    const double clipW[4] = { eyeToClip->GetElement(3, 0), eyeToClip->GetElement(3, 1),
      eyeToClip->GetElement(3, 2), eyeToClip->GetElement(3, 3) };
    double depthMap[3] = { 0.0, 0.0, 0.0 };
    if (camera->GetParallelProjection())
    {
      depthMap[0] = 2.0; // depth linear in the view distance: not refined
    }
    else if (depthPass && depthPass->GetMode() == vtkGlobeDepthPass::Logarithmic)
    {
      depthMap[0] = 1.0;
      depthMap[1] = 1.0 / std::log2(1.0 + depthPass->GetViewDistance(1.0, camera));
    }
    else
    {
      vtkMatrix4x4* projection =
        camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1);
      depthMap[1] = 0.5 - 0.5 * projection->GetElement(2, 2);
      depthMap[2] = -0.5 * projection->GetElement(2, 3);
    }
    in.Composite->SetRefinementFrame(chord, clipW, depthMap);
  }
  float columnMajor[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[c * 4 + r] = static_cast<float>(eyeToClip->GetElement(r, c));
    }
  }

  in.RasterTimer.ReusableStart();
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);
  state->PushFramebufferBindings();
  in.GFramebuffer->Bind();
  in.GFramebuffer->AddColorAttachment(0, in.GBuffer);
  in.GFramebuffer->AddDepthAttachment(in.GDepth);
  in.GFramebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  vtkGlobeGridPass* grid = in.GridPass;
  grid->GetDirectionTexture()->Activate();
  grid->GetPositionTexture()->Activate();
  grid->GetHeightTexture()->Activate();
  program->SetUniformi("globeDirection", grid->GetDirectionTexture()->GetTextureUnit());
  program->SetUniformi("globePosition", grid->GetPositionTexture()->GetTextureUnit());
  program->SetUniformi("globeHeight", grid->GetHeightTexture()->GetTextureUnit());
  program->SetUniformi("globeGridN", n);
  program->SetUniformMatrix4x4("globeEyeToClip", columnMajor);
  vtkGlobeShaderSources::SetRadii(program, in.Ellipsoid);
  program->SetUniformf("globeOneMinusRp", static_cast<float>(1.0 - in.Grid->GetPrimaryRadius()));
  if (highPrecision)
  {
    const double* nadir = in.Grid->GetNadir();
    const float nadirF[3] = { static_cast<float>(nadir[0]), static_cast<float>(nadir[1]),
      static_cast<float>(nadir[2]) };
    program->SetUniform3f("globeNadir", nadirF);
    program->SetUniformf("globePrimaryAltitude", static_cast<float>(in.Grid->GetAltitude()));
    program->SetUniformf("globePrimaryRadius", static_cast<float>(in.Grid->GetPrimaryRadius()));
  }
  if (depthPass) // depth mode
  {
    depthPass->SetDepthUniforms(program);
  }

  in.VAO->Bind();
  in.Indices.front().Buffer->Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(in.Indices.front().Count), GL_UNSIGNED_INT, nullptr);
  in.Indices.front().Buffer->Release();
  in.VAO->Release();

  grid->GetHeightTexture()->Deactivate();
  grid->GetPositionTexture()->Deactivate();
  grid->GetDirectionTexture()->Deactivate();
  in.GFramebuffer->RemoveColorAttachments(1);
  in.GFramebuffer->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  in.RasterTimer.ReusableStop();
  return true;
}

//------------------------------------------------------------------------------
bool vtkGlobeMapper::ReduceMinimumRadius(
  vtkRenderer* ren, int width, int height, const double eye[3])
{
  auto& in = *this->Internals;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  // Levels of 1/4 the size each, down to one texel.
  std::vector<std::pair<int, int>> sizes;
  int w = width, h = height;
  do
  {
    w = (w + 3) / 4;
    h = (h + 3) / 4;
    sizes.emplace_back(w, h);
  } while (w > 1 || h > 1);
  if (in.ReductionLevels.size() != sizes.size())
  {
    in.ReductionLevels.clear();
  }
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    if (i >= in.ReductionLevels.size())
    {
      auto t = vtkSmartPointer<vtkTextureObject>::New();
      t->SetContext(window);
      t->SetMinificationFilter(vtkTextureObject::Nearest);
      t->SetMagnificationFilter(vtkTextureObject::Nearest);
      t->Allocate2D(sizes[i].first, sizes[i].second, 1, VTK_FLOAT);
      in.ReductionLevels.push_back(t);
    }
    in.ReductionLevels[i]->Resize(sizes[i].first, sizes[i].second);
  }
  if (!in.ReductionFramebuffer)
  {
    in.ReductionFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.ReductionFramebuffer->SetContext(window);
  }
  if (!in.ReductionQuad)
  {
    const std::string fs = vtkGlobeShaderSources::Replace(
      vtkGlobeReductionFS, "//GLOBE::Math", vtkGlobeShaderSources::Math());
    in.ReductionQuad = new vtkOpenGLQuadHelper(window,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(in.ReductionQuad->Program);
  }
  vtkShaderProgram* p = in.ReductionQuad->Program;
  if (!p || !p->GetCompiled())
  {
    vtkErrorMacro(<< "The globe's reduction shader did not compile");
    in.ReductionValid = false;
    return false;
  }

  in.ReductionTimer.ReusableStart();
  const vtkGlobeShaderSources::ScopedOffscreenPass offscreen(state);
  in.ReductionFramebuffer->Bind();
  vtkGlobeShaderSources::SetRadii(p, in.Ellipsoid);
  {
    // The G-buffer holds reference + direction: the sub-point with high-precision geodetic
    // coordinates (it holds the offset), zero without (it holds the direction).
    const double* nadir = in.Grid->GetNadir();
    const bool offsets = in.Layers->GetHighPrecisionGeodetic();
    const float reference[3] = { offsets ? -static_cast<float>(nadir[0]) : 0.0f,
      offsets ? -static_cast<float>(nadir[1]) : 0.0f, offsets ? -static_cast<float>(nadir[2]) : 0.0f };
    p->SetUniform3f("globeReferenceDirection", reference);
  }
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    vtkTextureObject* source = i == 0 ? in.GBuffer.Get() : in.ReductionLevels[i - 1].Get();
    in.ReductionFramebuffer->AddColorAttachment(0, in.ReductionLevels[i]);
    in.ReductionFramebuffer->ActivateDrawBuffers(1);
    state->vtkglViewport(0, 0, sizes[i].first, sizes[i].second);
    source->Activate();
    in.GDepth->Activate();
    p->SetUniformi("globeSource", source->GetTextureUnit());
    p->SetUniformi("globeDepth", in.GDepth->GetTextureUnit());
    p->SetUniformi("globeFirstLevel", i == 0 ? 1 : 0);
    const float outputSize[2] = { static_cast<float>(sizes[i].first),
      static_cast<float>(sizes[i].second) };
    p->SetUniform2f("globeOutputSize", outputSize);
    in.ReductionQuad->Render();
    in.GDepth->Deactivate();
    source->Deactivate();
  }
  // One float back to the CPU, asynchronously: it sets the primary sphere of the next frame,
  // which collects it (CollectReduction).
  if (!in.ReadbackBuffer)
  {
    glGenBuffers(1, &in.ReadbackBuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, in.ReadbackBuffer);
    glBufferData(GL_PIXEL_PACK_BUFFER, sizeof(float), nullptr, GL_STREAM_READ);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  }
  in.ReductionFramebuffer->Bind(GL_READ_FRAMEBUFFER);
  in.ReductionFramebuffer->ActivateReadBuffer(0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, in.ReadbackBuffer);
  glReadPixels(0, 0, 1, 1, GL_RED, GL_FLOAT, nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  in.ReductionFramebuffer->RemoveColorAttachments(1);
  in.ReductionTimer.ReusableStop();
  in.ReadbackPending = true;
  for (int i = 0; i < 3; ++i)
  {
    in.PendingEye[i] = eye[i];
  }
  in.PendingView = in.RenderedView;
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto& in = *this->Internals;
  os << indent << "Ellipsoid: " << (in.Ellipsoid->GetName() ? in.Ellipsoid->GetName() : "custom")
     << "\n";
  os << indent << "GridResolution: " << this->GetGridResolution() << " ("
     << (this->GridPixelsPerCell > 0.0 ? "following the window" : "fixed") << ")\n";
  os << indent << "GridPixelsPerCell: " << this->GridPixelsPerCell << "\n";
  os << indent << "AutoAdjustDetail: " << this->AutoAdjustDetail
     << " (interactive grid coarsening " << this->InteractiveGridCoarsening << ")\n";
  os << indent << "LastFrameInteractive: " << this->LastFrameInteractive << "\n";
  os << indent << "FullDetailTime: " << this->FullDetailTime
     << " s, InteractiveDetailTime: " << this->InteractiveDetailTime << " s\n";
  os << indent << "Layers: " << in.Layers->GetNumberOfLayers() << "\n";
  os << indent << "HighPrecisionGeodetic: " << this->GetHighPrecisionGeodetic() << "\n";
  os << indent << "FootprintFiltering: " << this->GetFootprintFiltering() << "\n";
  os << indent << "WaitForPages: " << this->WaitForPages << "\n";
  os << indent << "PageCache:\n";
  in.Layers->GetPageCache()->PrintSelf(os, indent.GetNextIndent());
  os << indent << "PageFeedback:\n";
  in.Feedback->PrintSelf(os, indent.GetNextIndent());
  double range[2];
  in.GetPlausible(range);
  os << indent << "PlausibleHeightRange: " << range[0] << " .. " << range[1] << " m"
     << (in.PlausibleSet ? "" : " (from the body)") << "\n";
  os << indent << "PrimaryFromReduction: " << this->PrimaryFromReduction << "\n";
  os << indent << "LastVisibleMinimumHeight: " << this->LastVisibleMinimumHeight << "\n";
}
