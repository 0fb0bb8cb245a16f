/**
 * @class   vtkGlobeLayerSet
 * @brief   The GPU side of a globe's layers: textures, and GLSL generated for exactly them.
 *
 * Holds the ordered layers of a globe (vtkGlobeLayer, first = bottom), uploads each one to a
 * texture when it changed (and only then: GetNumberOfUploads() counts them), and generates the
 * GLSL that composes them, with one unrolled block per active layer:
 *   float globe_composeHeight(float lon, float lat, vec2 dUVdx, vec2 dUVdy,
 *                             out vec2 gradient)     // metres; gradient per radian (lon, lat)
 *   vec4  globe_composeColor(float lon, float lat)     // premultiplied by coverage
 * Layers are composed in order with "replace" weighted by coverage (extent, nodata) and a
 * feathered border, so detailed insets blend into a coarse base without a seam.
 * The generated source changes only when the set of active layers or their roles change, so
 * shader programs are rebuilt only then (GetShaderKey()).
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
  int GetNumberOfActiveColorLayers();
  ///@}

  /// Uploads changed layers to textures (needs a current context).
  void UploadTextures(vtkOpenGLRenderWindow* window);

  /// GLSL declarations and functions for the active layers: the height layers only
  /// (globe_composeHeight), or with the colour layers too (and globe_composeColor).
  std::string GetShaderCode(bool withColor = true);

  /// A key that changes exactly when GetShaderCode(withColor) would.
  std::string GetShaderKey(bool withColor = true);

  /// Binds the textures and sets the uniforms of the generated code on a ready program.
  void BindTextures(vtkShaderProgram* program, bool withColor = true);
  void UnbindTextures(bool withColor = true);

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
  vtkGlobeLayerSet(const vtkGlobeLayerSet&) = delete;
  void operator=(const vtkGlobeLayerSet&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
