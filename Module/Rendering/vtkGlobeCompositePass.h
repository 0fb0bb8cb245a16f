/**
 * @class   vtkGlobeCompositePass
 * @brief   The screen-space work: G-buffer -> colour and depth in the renderer's framebuffer.
 *
 * One full-screen pass (deferred texturing): for each pixel covered by terrain, the G-buffer's
 * direction gives the geodetic position; the layers of a vtkGlobeLayerSet are composed there
 * at the window's resolution, the terrain normal comes from the composed height gradient (and
 * normal-map layers), and the enabled effects shade it. The G-buffer's depth is written with
 * the depth test on, in VTK's depth convention, so the globe and every other actor occlude
 * each other correctly.
 *
 * Effects, each present in the shader only when enabled (and when the layers it needs exist):
 * HeightColors (a colour map of the composed height over the colour layers),
 * Lighting (diffuse, the first light of the scene), NightLights (NightLights layers on the
 * dark side), SpecularWater (Blinn-Phong where Mask layers say water), Atmosphere (single
 * scattering, seen from space and from the ground: the sky around the limb and the haze over
 * the terrain), Graticule (latitude/longitude lines) and Contours (height lines), both of
 * constant pixel width. The program is generated from the description of the active layers
 * and effects (GetShaderKey()) and rebuilt only when that description changes
 * (GetNumberOfShaderBuilds()); colours, spacings, intensities are uniforms.
 */
#ifndef vtkGlobeCompositePass_h
#define vtkGlobeCompositePass_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

#include <string> // for std::string

class vtkGlobeEllipsoid;
class vtkGlobeLayerSet;
class vtkOpenGLVertexArrayObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderTimer;
class vtkScalarsToColors;
class vtkShaderProgram;
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

  /**
   * Which blocks of the viewport hold terrain: a texture of `blockSize`-pixel blocks whose red
   * is below 1e29 where a block has a pixel of terrain (the mapper's minimum reduction of the
   * G-buffer); nullptr: every block may. The pass shades only the span of such blocks in
   * each band of rows (BlockCulling).
   */
  void SetCoverage(vtkTextureObject* blocks, int blockSize);

  ///@{
  /**
   * Shade only the columns of each band of rows whose blocks hold terrain (default on), not
   * the whole viewport: the sky costs nothing (Documentation/rendering.md "What the
   * composition shades"). Off, or with the atmosphere (which shades the sky), or without a
   * coverage, every pixel of the viewport runs the program. The picture is the same.
   */
  vtkSetMacro(BlockCulling, bool);
  vtkGetMacro(BlockCulling, bool);
  vtkBooleanMacro(BlockCulling, bool);
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

  ///@{
  /// Effects (see above). Lighting, NightLights and SpecularWater are on, the others off.
  vtkSetMacro(Lighting, bool);
  vtkGetMacro(Lighting, bool);
  vtkBooleanMacro(Lighting, bool);
  vtkSetMacro(NightLights, bool);
  vtkGetMacro(NightLights, bool);
  vtkBooleanMacro(NightLights, bool);
  vtkSetMacro(SpecularWater, bool);
  vtkGetMacro(SpecularWater, bool);
  vtkBooleanMacro(SpecularWater, bool);
  vtkSetMacro(Atmosphere, bool);
  vtkGetMacro(Atmosphere, bool);
  vtkBooleanMacro(Atmosphere, bool);
  vtkSetMacro(Graticule, bool);
  vtkGetMacro(Graticule, bool);
  vtkBooleanMacro(Graticule, bool);
  vtkSetMacro(Contours, bool);
  vtkGetMacro(Contours, bool);
  vtkBooleanMacro(Contours, bool);
  ///@}

  ///@{
  /// Effect parameters (uniforms: changing them rebuilds nothing).
  /// Specular: strength and Blinn-Phong exponent. Atmosphere: the sun's intensity.
  /// Graticule: spacing in degrees; Contours: interval in metres; LineWidth in pixels.
  vtkSetClampMacro(SpecularStrength, double, 0.0, 10.0);
  vtkGetMacro(SpecularStrength, double);
  vtkSetClampMacro(SpecularPower, double, 1.0, 1e4);
  vtkGetMacro(SpecularPower, double);
  vtkSetClampMacro(AtmosphereIntensity, double, 0.0, 1e3);
  vtkGetMacro(AtmosphereIntensity, double);
  vtkSetClampMacro(GraticuleSpacing, double, 1e-6, 180.0);
  vtkGetMacro(GraticuleSpacing, double);
  vtkSetVector3Macro(GraticuleColor, double);
  vtkGetVector3Macro(GraticuleColor, double);
  vtkSetClampMacro(ContourInterval, double, 1e-3, 1e7);
  vtkGetMacro(ContourInterval, double);
  vtkSetVector3Macro(ContourColor, double);
  vtkGetVector3Macro(ContourColor, double);
  vtkSetClampMacro(LineWidth, double, 0.0, 100.0);
  vtkGetMacro(LineWidth, double);
  ///@}

  ///@{
  /**
   * Heights in colour: any vtkScalarsToColors (a vtkColorTransferFunction hypsometric tint,
   * a vtkLookupTable, ...) colours the terrain by its composed height (metres above the
   * ellipsoid, as the height layers compose it for the terrain) over the colour layers, with
   * the map's opacity times HeightColorOpacity (default 1: the tint replaces them); with
   * Lighting on it is hill-shaded like any colour, so a DEM alone reads like a relief map.
   * The map is sampled at 1024 heights over its GetRange() whenever it changes; heights
   * outside the range take the end colours. nullptr (the default) leaves it out of the shader.
   */
  void SetHeightColors(vtkScalarsToColors* colors);
  vtkGetObjectMacro(HeightColors, vtkScalarsToColors);
  vtkSetClampMacro(HeightColorOpacity, double, 0.0, 1.0);
  vtkGetMacro(HeightColorOpacity, double);
  ///@}

  /**
   * The view of this frame (the mapper sets it): the eye in the body frame (m) and the
   * 16 elements (row-major) of the matrix from clip coordinates to eye-relative body
   * coordinates, for per-pixel view rays.
   */
  void SetView(const double eye[3], const double clipToEye[16]);

  ///@{
  /**
   * Per-pixel terrain refinement (vtkGlobeMapper::SetTerrainRefinement): Newton steps along
   * each pixel's view ray from the rasterized mesh to the composed heights, 0 (off) to 4
   * (default 1).
   */
  vtkSetClampMacro(TerrainRefinement, int, 0, 4);
  vtkGetMacro(TerrainRefinement, int);
  ///@}

  ///@{
  /**
   * Per frame (the mapper's interactive detail, vtkGlobeMapper::SetAutoAdjustDetail): draw
   * without refinement whatever TerrainRefinement says. Not Modified(). The program of the
   * other level is kept while only the level alternates, so switching compiles nothing.
   */
  void SetRefinementSuspended(bool suspended) { this->RefinementSuspended = suspended; }
  bool GetRefinementSuspended() { return this->RefinementSuspended; }
  ///@}

  /**
   * What the refinement needs of the frame (the mapper sets it with the G-buffer):
   * - chord[4]: (r'x, r'y, r'z, C) such that 1 - |u|^2 = -C - 2 o.r' - o.o for the G-buffer's
   *   offset o, u the unnormalized direction of the mesh point (its shortfall from the unit
   *   sphere is the chord's sag; Documentation/rendering.md "Terrain refinement");
   * - clipW[4]: the row of the eye-relative-body -> clip matrix that gives clip w;
   * - depthMap[3]: (0, A, B) for perspective depth d = A - B / w, (1, S, 0) for logarithmic
   *   depth d = S log2(1 + w).
   */
  void SetRefinementFrame(const double chord[4], const double clipW[4], const double depthMap[3]);

  /// Whether the program refines: TerrainRefinement > 0 with high-precision geodetic
  /// coordinates (Documentation/rendering.md "Terrain refinement"), not suspended.
  bool Refines();

  /// The description the program is generated from (layers and effects).
  std::string GetShaderKey();

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
  bool Lighting = true;
  bool NightLights = true;
  bool SpecularWater = true;
  bool Atmosphere = false;
  bool Graticule = false;
  bool Contours = false;
  double SpecularStrength = 0.6;
  double SpecularPower = 40.0;
  double AtmosphereIntensity = 20.0;
  double GraticuleSpacing = 10.0;
  double GraticuleColor[3] = { 1.0, 1.0, 1.0 };
  double ContourInterval = 100.0;
  double ContourColor[3] = { 0.35, 0.2, 0.05 };
  double LineWidth = 1.5;
  vtkScalarsToColors* HeightColors = nullptr;
  double HeightColorOpacity = 1.0;
  // The map sampled for the shader, and the map's MTime and range when it was.
  vtkTextureObject* HeightColorTexture = nullptr;
  vtkMTimeType HeightColorTime = 0;
  double HeightColorRange[2] = { 0.0, 1.0 };
  double Eye[3] = { 0, 0, 0 };
  double ClipToEye[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  int TerrainRefinement = 1;
  bool RefinementSuspended = false;
  double Chord[4] = { 0, 0, 0, -1 };
  double ClipW[4] = { 0, 0, 0, 0 };
  double DepthMap[3] = { 0, 0, 0 };

  // The program (the window's shader cache owns it) and an empty vertex array: the
  // geometry comes from gl_VertexID (vtkGlobeCompositeVS).
  vtkShaderProgram* Program = nullptr;
  vtkOpenGLVertexArrayObject* VAO = nullptr;
  vtkTextureObject* Coverage = nullptr;
  int CoverageBlock = 0;
  bool BlockCulling = true;
  std::string ShaderKey;
  std::string FragmentSource;
  // The program of the other detail level (refinement suspended or not), and the level the
  // current one was built for.
  vtkShaderProgram* SpareProgram = nullptr;
  std::string SpareKey;
  std::string SpareSource;
  bool ProgramSuspended = false;
  vtkOpenGLRenderTimer* Timer = nullptr;
  int NumberOfShaderBuilds = 0;

private:
  std::string BuildFragmentShader();
  int GetRoles();
  void UpdateHeightColorTexture(vtkOpenGLRenderWindow* window);
  vtkGlobeCompositePass(const vtkGlobeCompositePass&) = delete;
  void operator=(const vtkGlobeCompositePass&) = delete;
};

#endif
