/**
 * @class   vtkGlobeDepthPass
 * @brief   Planetary-range depth for every actor of a renderer (1 cm .. 1e11 m).
 *
 * A 24-bit perspective depth buffer resolves z^2 / (near * 2^24): with the near plane 1 m from
 * a camera standing on the ground, two surfaces 20 km away must be 24 m apart to be told
 * apart. This pass wraps a delegate (a vtkRenderStepsPass unless set) and, in Logarithmic mode,
 * injects into the shaders of every mapper it renders (vtkOpenGLPolyDataMapper and subclasses:
 * polydata, glyphs, the globe's own rasterization) a fragment depth
 *     depth = log2(max(1e-6, 1 + w)) / log2(1 + far),   w = 1 / gl_FragCoord.w
 * (Cozzi & Ring / Outerra, with C = 1; w is the eye distance along the view axis, exact per
 * fragment, not interpolated per vertex), and in the vertex shader (the geometry shader where
 * a mapper has one) the matching clip z so that nothing in front of the eye is clipped by the
 * near plane. Depths a mapper writes itself keep their meaning: impostor spheres and sticks
 * (vtkOpenGLSphereMapper, vtkOpenGLStickMapper) and points or lines drawn as spheres or tubes
 * get the logarithmic depth of their surface, and VTK's coincident-topology offset (edges over
 * surfaces, lines, points) stays the same offset of the depth range. The relative resolution
 * is then constant: dw / (1 + w) = ln 2 * log2(1 + far) / 2^24 (about 1e-6 for far = 1e7 m).
 *
 * @code
 *   vtkNew<vtkGlobeDepthPass> depth;      // delegates to a vtkRenderStepsPass
 *   depth->SetModeToLogarithmic();
 *   renderer->SetPass(depth);
 * @endcode
 * Modes (the benchmark sweeps them): Default leaves VTK's perspective depth untouched (the
 * pass only delegates); Logarithmic as above. Reversed-Z with a float depth buffer is not
 * offered: see Documentation/depth.md for why it does not fit VTK 9.1's framebuffer.
 *
 * Reading depth back (pickers, tests) must invert the mode: GetPerspectiveDepth() turns a
 * window depth of the last frame into VTK's convention (in double), so
 * vtkRenderer::DisplayToWorld works on it; vtkGlobePointPicker does this.
 * Not covered in Logarithmic mode (Documentation/depth.md): depth peeling (it compares
 * gl_FragCoord.z), volume mappers (their rays stop at perspective depth), and passes that read
 * depth as perspective (SSAO, eye-dome lighting, depth of field).
 */
#ifndef vtkGlobeDepthPass_h
#define vtkGlobeDepthPass_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

#include <string> // for std::string

class vtkCamera;
class vtkRenderer;

class VTKGLOBERENDERING_EXPORT vtkGlobeDepthPass : public vtkOpenGLRenderPass
{
public:
  static vtkGlobeDepthPass* New();
  vtkTypeMacro(vtkGlobeDepthPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    Default = 0,
    Logarithmic = 1
  };

  ///@{
  /// The depth mode (Default unless set).
  void SetMode(int mode);
  vtkGetMacro(Mode, int);
  void SetModeToDefault() { this->SetMode(Default); }
  void SetModeToLogarithmic() { this->SetMode(Logarithmic); }
  static const char* GetModeAsString(int mode);
  ///@}

  ///@{
  /// The pass that renders the scene (a vtkRenderStepsPass when none is set).
  void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

  /**
   * Adds the mode's depth code at the end of main() of a vertex and a fragment shader (for
   * programs that are not built by a vtkOpenGLPolyDataMapper, such as the globe's
   * rasterization). Does nothing in Default mode.
   */
  void InjectDepthCode(std::string& vertexShader, std::string& fragmentShader);

  /// Sets the uniforms of the injected code (the far distance of the current frame).
  void SetDepthUniforms(vtkShaderProgram* program);

  /**
   * A window depth written in the last frame, turned into VTK's perspective convention for the
   * camera's clipping range (double; the identity in Default mode). 1 stays 1 (background).
   */
  double GetPerspectiveDepth(double windowDepth, vtkCamera* camera);

  /// The eye distance along the view axis (m) of a window depth of the last frame.
  double GetViewDistance(double windowDepth, vtkCamera* camera);

  /// The far distance the last frame's logarithmic depth was scaled to.
  vtkGetMacro(LastFar, double);

  /// The depth pass among the render passes an actor is rendered with, or nullptr.
  static vtkGlobeDepthPass* FindInProp(vtkProp* prop);

protected:
  vtkGlobeDepthPass();
  ~vtkGlobeDepthPass() override;

  int Mode = Default;
  vtkRenderPass* DelegatePass = nullptr;
  double LastFar = 1.0;
  vtkTimeStamp ShaderStageTime;

private:
  vtkGlobeDepthPass(const vtkGlobeDepthPass&) = delete;
  void operator=(const vtkGlobeDepthPass&) = delete;
};

#endif
