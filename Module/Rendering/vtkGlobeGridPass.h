/**
 * @class   vtkGlobeGridPass
 * @brief   The grid-space work of Projective Grid Mapping: PGM, then height composition.
 *
 * Renders into grid-sized float textures (Resolution x Resolution, independent of the window):
 *  - step 1, PGM: each grid point's ray from the sampling camera of a vtkGlobeProjectiveGrid is
 *    cast against the reference spheres (DirectionTexture: unit direction from the centre in the
 *    body's scaled space and a hit flag; PositionTexture: the reference point relative to the
 *    eye, scaled space);
 *  - step 2, height composition: the layers of a vtkGlobeLayerSet composed at each grid
 *    point's geodetic position (HeightTexture, metres).
 * vtkGlobeMapper drives it once per frame; it can also run on its own (the tests read its
 * textures back and compare them with vtkGlobeProjectiveGrid::ComputeGridPoint()).
 * Each step is timed with GPU timer queries where the driver has them.
 */
#ifndef vtkGlobeGridPass_h
#define vtkGlobeGridPass_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

#include <string> // for std::string

class vtkGlobeLayerSet;
class vtkGlobeProjectiveGrid;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderTimer;
class vtkTextureObject;

class VTKGLOBERENDERING_EXPORT vtkGlobeGridPass : public vtkOpenGLRenderPass
{
public:
  static vtkGlobeGridPass* New();
  vtkTypeMacro(vtkGlobeGridPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /// Grid points per side (default 512), clamped to 2..2048 (vtkGlobeMapper's range: above
  /// 2048 the index buffer alone would take more than 100 MB).
  vtkSetClampMacro(Resolution, int, 2, 2048);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /// The frame's PGM parameters and the layers (both required).
  void SetProjectiveGrid(vtkGlobeProjectiveGrid* grid);
  vtkGetObjectMacro(ProjectiveGrid, vtkGlobeProjectiveGrid);
  void SetLayers(vtkGlobeLayerSet* layers);
  vtkGetObjectMacro(Layers, vtkGlobeLayerSet);
  ///@}

  ///@{
  /// The outputs of the last Render().
  vtkTextureObject* GetDirectionTexture() { return this->DirectionTexture; }
  vtkTextureObject* GetPositionTexture() { return this->PositionTexture; }
  vtkTextureObject* GetHeightTexture() { return this->HeightTexture; }
  ///@}

  ///@{
  /// GPU time of each step (seconds) from the most recent frame whose timer query is done
  /// (0 before the first one is); -1 where the driver has no timer queries.
  double GetPGMTime();
  double GetHeightTime();
  ///@}

  /// How many times the shader programs were (re)built.
  vtkGetMacro(NumberOfShaderBuilds, int);

protected:
  vtkGlobeGridPass();
  ~vtkGlobeGridPass() override;

  bool Prepare(vtkOpenGLRenderWindow* window);

  int Resolution = 512;
  vtkGlobeProjectiveGrid* ProjectiveGrid = nullptr;
  vtkGlobeLayerSet* Layers = nullptr;
  vtkTextureObject* DirectionTexture = nullptr;
  vtkTextureObject* PositionTexture = nullptr;
  vtkTextureObject* HeightTexture = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkOpenGLQuadHelper* PGMQuad = nullptr;
  vtkOpenGLQuadHelper* HeightQuad = nullptr;
  std::string HeightShaderKey;
  vtkOpenGLRenderTimer* PGMTimer = nullptr;
  vtkOpenGLRenderTimer* HeightTimer = nullptr;
  int NumberOfShaderBuilds = 0;

private:
  vtkGlobeGridPass(const vtkGlobeGridPass&) = delete;
  void operator=(const vtkGlobeGridPass&) = delete;
};

#endif
