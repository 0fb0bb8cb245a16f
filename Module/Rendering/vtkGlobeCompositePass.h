/**
 * @class   vtkGlobeCompositePass
 * @brief   The screen-space work: G-buffer -> colour and depth in the renderer's framebuffer.
 *
 * One full-screen pass (deferred texturing): for each pixel covered by terrain, the G-buffer's
 * direction gives the geodetic position; the colour layers of a vtkGlobeLayerSet are composed
 * there at the window's resolution, the terrain normal comes from the composed height
 * gradient, and the light of the scene shades it. The G-buffer's depth is written with the
 * depth test on, in VTK's depth convention, so the globe and every other actor occlude each
 * other correctly. The program is generated from the active layers and rebuilt only when they
 * change (GetNumberOfShaderBuilds()).
 */
#ifndef vtkGlobeCompositePass_h
#define vtkGlobeCompositePass_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

#include <string> // for std::string

class vtkGlobeEllipsoid;
class vtkGlobeLayerSet;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderTimer;
class vtkTextureObject;

class VTKGLOBERENDERING_EXPORT vtkGlobeCompositePass : public vtkOpenGLRenderPass
{
public:
  static vtkGlobeCompositePass* New();
  vtkTypeMacro(vtkGlobeCompositePass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Draws into the currently bound framebuffer and viewport.
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /// Inputs: the G-buffer (direction xyz, height) and its depth, the body and the layers.
  void SetGBuffer(vtkTextureObject* gbuffer, vtkTextureObject* depth);
  void SetEllipsoid(vtkGlobeEllipsoid* ellipsoid);
  void SetLayers(vtkGlobeLayerSet* layers);
  ///@}

  ///@{
  /// Lighting: unit direction towards the light in the body frame, its colour, the ambient
  /// fraction, and the colour of ground no colour layer covers.
  vtkSetVector3Macro(LightDirection, double);
  vtkGetVector3Macro(LightDirection, double);
  vtkSetVector3Macro(LightColor, double);
  vtkGetVector3Macro(LightColor, double);
  vtkSetClampMacro(Ambient, double, 0.0, 1.0);
  vtkGetMacro(Ambient, double);
  vtkSetVector3Macro(BaseColor, double);
  vtkGetVector3Macro(BaseColor, double);
  ///@}

  /// GPU time of the pass (seconds) from the last finished frame; -1 without timer queries.
  double GetCompositeTime();

  vtkGetMacro(NumberOfShaderBuilds, int);

  /// The fragment shader source of the current program (for tests and curiosity).
  std::string GetFragmentShaderSource() { return this->FragmentSource; }

protected:
  vtkGlobeCompositePass();
  ~vtkGlobeCompositePass() override;

  vtkTextureObject* GBuffer = nullptr;
  vtkTextureObject* Depth = nullptr;
  vtkGlobeEllipsoid* Ellipsoid = nullptr;
  vtkGlobeLayerSet* Layers = nullptr;
  double LightDirection[3] = { 0, 0, 1 };
  double LightColor[3] = { 1, 1, 1 };
  double Ambient = 0.15;
  double BaseColor[3] = { 0.12, 0.2, 0.38 };
  vtkOpenGLQuadHelper* Quad = nullptr;
  std::string ShaderKey;
  std::string FragmentSource;
  vtkOpenGLRenderTimer* Timer = nullptr;
  int NumberOfShaderBuilds = 0;

private:
  vtkGlobeCompositePass(const vtkGlobeCompositePass&) = delete;
  void operator=(const vtkGlobeCompositePass&) = delete;
};

#endif
