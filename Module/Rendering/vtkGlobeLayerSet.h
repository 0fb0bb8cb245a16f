/**
 * @class   vtkGlobeLayerSet
 * @brief   The GPU side of a globe's layers: textures, and GLSL generated for exactly them.
 *
 * Holds the layers of a globe (vtkGlobeLayer), uploads each one to a texture when its data
 * changed (and only then: GetNumberOfUploads() counts them), and generates the GLSL that
 * composes the enabled ones, in increasing DrawOrder (ties: the order they were added), one
 * unrolled block per layer:
 *   float globe_composeHeight(float lon, float lat, out vec2 gradient)
 *       metres, and the gradient per radian of (lon, lat); grid pass and screen pass;
 *   vec3  globe_composeColor(float lon, float lat, vec3 base)     Color layers over a base;
 *   vec4  globe_composeNormal(float lon, float lat)               NormalMap: ENU normal, weight;
 *   float globe_composeMask(float lon, float lat)                 Mask (water = 1);
 *   vec3  globe_composeNightLights(float lon, float lat)          NightLights;
 *   vec4  globe_composeOverlay(float lon, float lat)   Overlay, premultiplied: lit*(1-a) + rgb.
 * The functions of roles without layers are absent. Each must be called in uniform control
 * flow (they take screen derivatives to choose mipmap levels).
 *
 * A layer's weight is its coverage (inside the extent, not nodata / NaN / outside its valid
 * range, the alpha of images) times its feathered border, its opacity and, if asked for,
 * Kooima's projection-quality weight; it blends by the layer's BlendMode. Where every weight
 * is zero the layers below (or the base) show; nothing divides by a zero sum.
 *
 * The generated source depends only on the roles, order, blend modes, projections and
 * quality flags of the enabled layers (GetShaderKey()); opacity, gamma, valid range, feather
 * width and filtering are uniforms or sampler state, so changing them rebuilds nothing.
 */
#ifndef vtkGlobeLayerSet_h
#define vtkGlobeLayerSet_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkGlobeLayer;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

class VTKGLOBERENDERING_EXPORT vtkGlobeLayerSet : public vtkObject
{
public:
  static vtkGlobeLayerSet* New();
  vtkTypeMacro(vtkGlobeLayerSet, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The layers, bottom first.
  void AddLayer(vtkGlobeLayer* layer);
  void RemoveLayer(vtkGlobeLayer* layer);
  void RemoveAllLayers();
  int GetNumberOfLayers();
  vtkGlobeLayer* GetLayer(int index);
  ///@}

  /**
   * Brings every layer up to date (loading files) and decides which are active: loaded,
   * valid and of a projection the renderer supports. Layers that fail are reported once with
   * the reason and skipped; the rest still render. Returns the number of active layers.
   */
  int Update();

  ///@{
  /// Range of the active height layers (m); 0 when there are none.
  double GetMinimumHeight();
  double GetMaximumHeight();
  int GetNumberOfActiveHeightLayers();
  /// Active layers of one role (vtkGlobeLayer::Roles).
  int GetNumberOfActiveLayers(int role);
  int GetNumberOfActiveColorLayers() { return this->GetNumberOfActiveLayers(1); }
  ///@}

  /// Uploads changed layers to textures (needs a current context).
  void UploadTextures(vtkOpenGLRenderWindow* window);

  /// Bit masks of roles (1 << vtkGlobeLayer::Roles) for the calls below.
  enum RoleMasks
  {
    HeightRoles = 1,
    AllRoles = 63
  };

  /// GLSL declarations and functions for the active layers of the roles in the mask: the
  /// grid pass asks for the heights only, the screen pass for the roles its effects use.
  std::string GetShaderCode(int roles = AllRoles);

  /// A key that changes exactly when GetShaderCode(roles) would.
  std::string GetShaderKey(int roles = AllRoles);

  /// Binds the textures and sets the uniforms of the generated code on a ready program.
  void BindTextures(vtkShaderProgram* program, int roles = AllRoles);
  void UnbindTextures(int roles = AllRoles);

  /// Texture uploads so far (a layer is uploaded when it, or its data, changed).
  vtkGetMacro(NumberOfUploads, int);

  /// Bytes of GPU texture memory held.
  size_t GetTextureMemory();

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkGlobeLayerSet();
  ~vtkGlobeLayerSet() override;

  int NumberOfUploads = 0;

private:
  bool PrepareProjection(void* entry);
  vtkGlobeLayerSet(const vtkGlobeLayerSet&) = delete;
  void operator=(const vtkGlobeLayerSet&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
