/**
 * @class   vtkGlobeLayerSet
 * @brief   The GPU side of a globe's layers: textures, and GLSL generated for exactly them.
 *
 * Holds the layers of a globe (vtkGlobeLayer), uploads each one to a texture when its data
 * changed (and only then: GetNumberOfUploads() counts them), and generates the GLSL that
 * composes the enabled ones, in increasing DrawOrder (ties: the order they were added), one
 * unrolled block per layer. (lon, lat) are radians, each as a hi + lo pair (LL below stands
 * for float lonHi, float lonLo, float latHi, float latLo):
 *   float globe_composeHeight(LL, out vec2 gradient)
 *       metres, and the gradient per radian of (lon, lat); grid pass and screen pass;
 *   vec3  globe_composeColor(LL, vec3 base)     Color layers over a base;
 *   vec4  globe_composeNormal(LL)               NormalMap: ENU normal, weight;
 *   float globe_composeMask(LL)                 Mask (water = 1);
 *   vec3  globe_composeNightLights(LL)          NightLights;
 *   vec4  globe_composeOverlay(LL)              Overlay, premultiplied: lit*(1-a) + rgb.
 * The functions of roles without layers are absent. Each must be called in uniform control
 * flow (they take screen derivatives to choose mipmap levels).
 *
 * Geodetic precision (HighPrecisionGeodetic, on by default; Documentation/rendering.md): the
 * passes give (lon, lat) as a per-frame local origin (SetGeodeticReference, in double on the
 * CPU, hi + lo uniforms) plus a small offset, and every layer forms its texture coordinates
 * from differences to its own hi + lo edges or projection reference, so nothing near +-pi is
 * rounded to float: 0.5 m data is placed as precisely at +-180 degrees as at 0. Off, the
 * functions add hi + lo into one float first (the earlier path, 1.5 m steps near +-180).
 *
 * A layer's weight is its coverage (inside the extent, not nodata / NaN / outside its valid
 * range, the alpha of images) times its feathered border, its opacity and, if asked for,
 * Kooima's projection-quality weight; it blends by the layer's BlendMode. Where every weight
 * is zero the layers below (or the base) show; nothing divides by a zero sum.
 *
 * Streamed layers (vtkGlobeLayer::IsStreamed; Documentation/streaming.md) have no texture:
 * their pages live in the set's vtkGlobePageCache (GetPageCache), the generated code reads them
 * through the layer's page table (globe_pageGrad, globe_pageHeights: the level from the
 * footprint, as OpenGL picks mipmap levels), and RequestPages turns the frame's footprint
 * samples into the pages to load.
 *
 * The generated source depends only on the roles, order, blend modes, projections and
 * quality flags of the enabled layers, and for streamed layers their filtering
 * (GetShaderKey()); opacity, gamma, valid range, feather width and the filtering of whole
 * layers are uniforms or sampler state, so changing them rebuilds nothing.
 */
#ifndef vtkGlobeLayerSet_h
#define vtkGlobeLayerSet_h

#include "vtkGlobeLayer.h"            // for vtkGlobeLayer::Roles
#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkCamera;
class vtkDoubleArray;
class vtkGlobeEllipsoid;
class vtkMatrix4x4;
class vtkGlobePageCache;
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
  /// Active layers of one role, e.g. GetNumberOfActiveLayers(vtkGlobeLayer::Mask).
  int GetNumberOfActiveLayers(vtkGlobeLayer::Roles role);
  int GetNumberOfActiveColorLayers();
  ///@}

  /**
   * Uploads changed layers to textures and starts the page cache's frame for streamed
   * layers (needs a current context). waitForPages: the page cache first waits for every
   * page read that is under way and uploads all (vtkGlobeMapper's WaitForPages).
   */
  void UploadTextures(vtkOpenGLRenderWindow* window, bool waitForPages = false);

  /// The GPU page cache of the streamed layers (settings and statistics).
  vtkGlobePageCache* GetPageCache();

  /// Active streamed layers.
  int GetNumberOfStreamedLayers();

  /**
   * Asks the page cache for the pages the streamed layers need, from footprint samples of
   * the frame (vtkGlobeMapper's feedback): 6 components per tuple, (lon, lat, dlon/dx,
   * dlat/dx, dlon/dy, dlat/dy) in radians and radians per pixel, each standing for a block
   * of blockPixels x blockPixels pixels. For each sample and layer: the texture coordinates
   * (in double, through the layer's projection), the level the composition samples
   * (log2 of the footprint in level-0 texels, as OpenGL chooses mipmap levels; the two
   * levels linear filtering blends), and every page the block reaches at that level. Height
   * layers are also composed at the projective grid's points, gridCellPixels apart: their
   * pages at that footprint are asked for as well.
   */
  void RequestPages(vtkDoubleArray* footprints, int blockPixels, double gridCellPixels);

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

  ///@{
  /**
   * Per-frame layer culling (on by default): a layer whose footprint lies wholly outside one
   * plane of the view frustum is left out of the generated grid and screen programs this frame
   * (a changed culled set builds them anew). The footprint is the layer's extent sampled 9 x 9
   * (projected layers: their raster's edges and inside mapped back to lon/lat) between the
   * composed terrain's lowest and highest heights plus the bulge of the surface between
   * samples; layers that wrap, reach within a degree of a pole or span more than 40 degrees
   * are never culled. vtkGlobeMapper calls
   * CullLayers each frame with its camera; GetNumberOfCulledLayers tells the last frame's count.
   */
  void CullLayers(vtkCamera* camera, double aspect, vtkMatrix4x4* bodyToWorld,
    vtkGlobeEllipsoid* body);
  vtkSetMacro(LayerCulling, bool);
  vtkGetMacro(LayerCulling, bool);
  vtkBooleanMacro(LayerCulling, bool);
  vtkGetMacro(NumberOfCulledLayers, int);
  /// Active layers of a role that the passes compose this frame (not culled).
  int GetNumberOfComposedLayers(int role);
  ///@}

  ///@{
  /**
   * Whole-raster layers filtered to the footprint (default on; Documentation/composition.md
   * "Filtering to the footprint"). Off: their textures are read at level 0 whatever the
   * footprint, each value the data's own (bilinear between posts) but distant terrain
   * aliasing; what the renderer did before the pyramid was uploaded, kept to compare and for
   * inspecting values. Streamed layers always filter. A texture parameter: no upload.
   */
  vtkSetMacro(FootprintFiltering, bool);
  vtkGetMacro(FootprintFiltering, bool);
  vtkBooleanMacro(FootprintFiltering, bool);
  ///@}

  ///@{
  /**
   * How height layers are filtered (Documentation/composition.md, "Exact height filtering").
   * Automatic (the default): in the shader with float weights, unless this OpenGL's texture
   * unit filters float textures exactly itself (probed once per window: llvmpipe does; GPUs,
   * with 8-bit weights, do not). Shader: always in the shader. Hardware: always the texture
   * unit, as before 2026-11-28. Part of GetShaderKey().
   */
  enum HeightFilteringModes
  {
    HeightFilteringAutomatic,
    HeightFilteringShader,
    HeightFilteringHardware
  };
  vtkSetClampMacro(HeightFiltering, int, HeightFilteringAutomatic, HeightFilteringHardware);
  vtkGetMacro(HeightFiltering, int);
  /// Whether the programs filter heights in the shader (the mode, and the probe's answer).
  bool GetFiltersHeightsInShader();
  /// The probe's answer for the last window: 1 exact, 0 not, -1 not probed (yet).
  int GetTextureUnitFiltersExactly();
  ///@}

  ///@{
  /// Hi + lo geodetic (lon, lat) from a local origin (default on); part of GetShaderKey().
  vtkSetMacro(HighPrecisionGeodetic, bool);
  vtkGetMacro(HighPrecisionGeodetic, bool);
  vtkBooleanMacro(HighPrecisionGeodetic, bool);
  ///@}

  /**
   * The frame's local origin: a direction in the body's scaled space (x/a, y/b, z/c) and the
   * body's radii (m). Its geodetic (lon, lat) is computed here in double; BindTextures() passes
   * it as hi + lo (uniform vec4 globeGeodeticReference) with the direction (uniform vec3
   * globeReferenceDirection); the passes turn the G-buffer's offsets from it into (lon, lat)
   * with globe_geodeticFromOffset. Changes every frame and rebuilds nothing (no Modified()).
   * vtkGlobeGridPass sets it to the camera's sub-point before it composes heights.
   */
  void SetGeodeticReference(const double direction[3], const double radii[3]);
  /// The local origin's (lon, lat) in radians.
  void GetGeodeticReference(double lonLat[2]);
  /// The local origin's direction (scaled space), as set.
  void GetReferenceDirection(double direction[3]);

  ///@{
  /**
   * Heights outside this range (m) are voids (vtkGlobeLayer::SetPlausibleRange, given to
   * every height layer before it updates). vtkGlobeMapper sets it from its body.
   */
  vtkSetVector2Macro(PlausibleHeightRange, double);
  vtkGetVector2Macro(PlausibleHeightRange, double);
  ///@}

  /// Bytes of GPU texture memory held.
  size_t GetTextureMemory();

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkGlobeLayerSet();
  ~vtkGlobeLayerSet() override;

  int NumberOfUploads = 0;
  bool LayerCulling = true;
  int NumberOfCulledLayers = 0;
  bool HighPrecisionGeodetic = true;
  bool FootprintFiltering = true;
  int HeightFiltering = HeightFilteringAutomatic;
  double ReferenceDirection[3] = { 1.0, 0.0, 0.0 };
  double ReferenceLonLat[2] = { 0.0, 0.0 };
  double PlausibleHeightRange[2] = { -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };

private:
  bool PrepareProjection(void* entry);
  void ComputeHeightRange();
  vtkGlobeLayerSet(const vtkGlobeLayerSet&) = delete;
  void operator=(const vtkGlobeLayerSet&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
