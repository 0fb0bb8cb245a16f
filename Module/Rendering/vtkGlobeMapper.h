/**
 * @class   vtkGlobeMapper
 * @brief   A planetary globe rendered by Projective Grid Mapping, as a VTK mapper.
 *
 * Put a body into any VTK scene:
 * @code
 *   vtkNew<vtkGlobeMapper> mapper;
 *   mapper->SetEllipsoid(wgs84);        // WGS84 unless set
 *   mapper->AddLayer(heights);          // vtkGlobeLayer, bottom first
 *   mapper->AddLayer(imagery);
 *   vtkNew<vtkActor> actor;
 *   actor->SetMapper(mapper);
 *   renderer->AddActor(actor);
 * @endcode
 * The actor's matrix places the body-fixed frame in the world. Each frame
 * (Documentation/architecture.md, "One frame"):
 *  1. CPU, in double: the eye in the body frame, the reference spheres and the sampling camera
 *     (vtkGlobeProjectiveGrid); the primary sphere is the lowest terrain seen in the previous
 *     frame (GPU min reduction), or the lowest data after a jump and on the first frame;
 *  2. vtkGlobeGridPass: PGM and height composition on a GridResolution^2 grid (by default
 *     about GridPixelsPerCell pixels per cell of the window);
 *  3. rasterization of the grid as an eye-relative mesh into a G-buffer (direction as an offset
 *     from the frame's local origin, height, depth);
 *  4. vtkGlobeCompositePass: per-pixel composition of the colour layers and lighting, written
 *     with the G-buffer's depth into the renderer's framebuffer, so other actors and the globe
 *     occlude each other;
 *  5. the minimum reduction of the visible planetary radius, read back asynchronously and
 *     used by the next frame.
 * The grid's density (GridPixelsPerCell, or a fixed GridResolution) and the per-pixel terrain
 * refinement (TerrainRefinement) are the accuracy/time dials.
 *
 * A camera at the centre of the body, at NaN, with a parallel projection, with its focal point
 * at its position or its view-up along its view draws no globe (reported once); one inside the
 * body or so far that the body is smaller than a pixel is reported once with a warning. The
 * rest of the scene renders.
 */
#ifndef vtkGlobeMapper_h
#define vtkGlobeMapper_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkWrappingHints.h" // for VTK_SIZEHINT

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkGlobeCompositePass;
class vtkGlobeEllipsoid;
class vtkGlobeGridPass;
class vtkGlobeLayer;
class vtkGlobeLayerSet;
class vtkGlobeTerrain;
class vtkGlobeProjectiveGrid;
class vtkGlobePageCache;
class vtkTextureObject;

class VTKGLOBERENDERING_EXPORT vtkGlobeMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkGlobeMapper* New();
  vtkTypeMacro(vtkGlobeMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The body (WGS84 unless set; nullptr restores WGS84).
  void SetEllipsoid(vtkGlobeEllipsoid* ellipsoid);
  vtkGlobeEllipsoid* GetEllipsoid();
  ///@}

  ///@{
  /**
   * Heights a layer may hold (m, after its ValueScale and ValueOffset). Posts outside are
   * voids (vtkGlobeLayer::SetPlausibleRange), and each layer that has any says so once with
   * its name and the count, so one corrupt value (1e30, a flipped bit) can neither blank the
   * globe nor move its reference spheres and clipping planes. By default +-5 % of the body's
   * smallest radius (GetDefaultPlausibleFraction()): +-317.8 km on WGS84, +-168.8 km on Mars,
   * +-86.9 km on the Moon, beyond the relief of any of them (Everest 8.8 km, Olympus Mons
   * 21.9 km). Set a range for small irregular bodies or exaggerated heights;
   * UseBodyPlausibleHeightRange() goes back to the default. An empty range is an error.
   */
  void SetPlausibleHeightRange(double minimum, double maximum);
  void GetPlausibleHeightRange(double range[2]);
  void UseBodyPlausibleHeightRange();
  static double GetDefaultPlausibleFraction() { return 0.05; }
  ///@}

  /**
   * The actor of a globe in a renderer: the one whose mapper is `mapper`, or without one the
   * first visible actor with a vtkGlobeMapper; nullptr when there is none. Picking and the
   * interactor style find their globe this way.
   */
  static vtkActor* FindGlobeActor(vtkRenderer* renderer, vtkGlobeMapper* mapper = nullptr);

  ///@{
  /// Layers, composed bottom first (see vtkGlobeLayerSet).
  void AddLayer(vtkGlobeLayer* layer);
  void RemoveLayer(vtkGlobeLayer* layer);
  void RemoveAllLayers();
  int GetNumberOfLayers();
  vtkGlobeLayer* GetLayer(int index);
  vtkGlobeLayerSet* GetLayerSet();
  ///@}

  /**
   * The composed terrain of the mapper's height layers on the CPU, by the GPU's rules
   * (vtkGlobeTerrain: GetHeight, GetOrthometricHeight at a longitude and latitude, with its
   * bound against the picture). It follows AddLayer and RemoveLayer.
   */
  vtkGlobeTerrain* GetTerrain();

  ///@{
  /**
   * The projective grid's size, the accuracy/time dial (Documentation/accuracy-vs-time.md).
   * By default it follows the window: ceil(L / GridPixelsPerCell) points per side, L the
   * viewport's larger side in pixels (default 1.6: 500^2 at 800 x 600, 250^2 at 400 x 300,
   * 1000^2 at 1600 x 1200), clamped to 2..2048, so the grid's error in pixels and its cost per
   * pixel stay the same in any window; where the grid spans less of the window than L (the
   * whole planet in part of it), L is that span (vtkGlobeProjectiveGrid::ComputeSamplingSpan),
   * rounded up to 16 points (336^2 for the whole Earth from 22,000 km at 800 x 600). With the default terrain refinement a coarser grid
   * (3.2) is faster and as accurate from the air, but not in views along the ground, where
   * ridges the grid misses are not found by the refinement (Documentation/accuracy-vs-time.md
   * "Defaults chosen from it"). SetGridResolution fixes the size instead (points per
   * side, clamped to 2..2048; GridPixelsPerCell becomes 0); SetGridPixelsPerCell(p > 0) makes
   * it follow the window again. GetGridResolution is the size in use: the last frame's (coarser
   * after a frame at interactive detail, AutoAdjustDetail), or before the first frame the
   * fixed size (512 unless set).
   */
  void SetGridResolution(int resolution);
  int GetGridResolution();
  void SetGridPixelsPerCell(double pixels);
  vtkGetMacro(GridPixelsPerCell, double);
  ///@}

  ///@{
  /**
   * Shading: ambient fraction and the colour of ground that no colour layer covers.
   * One owner: these and the effect switches below are held by the composite pass
   * (GetCompositePass()), and the mapper's methods read and write that same value, so the
   * two names can never disagree and neither overrides the other. The mapper keeps them
   * because they are what most scenes set; the effects' parameters live on the pass only.
   */
  void SetAmbient(double ambient);
  double GetAmbient();
  void SetBaseColor(double r, double g, double b);
  double* GetBaseColor() VTK_SIZEHINT(3);
  void GetBaseColor(double rgb[3]);
  ///@}

  ///@{
  /**
   * The globe has no input: its body is the ellipsoid and its data are its layers (AddLayer).
   * An input given to the mapper (vtkPolyDataMapper's SetInputConnection / SetInputData) is
   * refused with an error instead of being silently ignored. Of the inherited settings, the
   * actor's matrix, visibility and pickability apply, and the mapper's Static; scalar, lookup
   * table and colour-mode settings have no effect (colour comes from the layers).
   */
  void SetInputConnection(int port, vtkAlgorithmOutput* input) override;
  void SetInputConnection(vtkAlgorithmOutput* input) override;
  void AddInputConnection(int port, vtkAlgorithmOutput* input) override;
  void AddInputConnection(vtkAlgorithmOutput* input) override;
  void SetInputDataObject(int port, vtkDataObject* data) override;
  void SetInputDataObject(vtkDataObject* data) override;
  ///@}

  ///@{
  /**
   * Effects of the screen composition (held by vtkGlobeCompositePass, as above; their
   * parameters are set there):
   * the shader holds the code of the effects that are on, and only of those. Lighting,
   * NightLights (needs NightLights layers) and SpecularWater (needs Mask layers) are on;
   * Atmosphere, Graticule and Contours are off.
   */
  void SetLighting(bool on);
  bool GetLighting();
  void LightingOn() { this->SetLighting(true); }
  void LightingOff() { this->SetLighting(false); }
  void SetNightLights(bool on);
  bool GetNightLights();
  void NightLightsOn() { this->SetNightLights(true); }
  void NightLightsOff() { this->SetNightLights(false); }
  void SetSpecularWater(bool on);
  bool GetSpecularWater();
  void SpecularWaterOn() { this->SetSpecularWater(true); }
  void SpecularWaterOff() { this->SetSpecularWater(false); }
  void SetAtmosphere(bool on);
  bool GetAtmosphere();
  void AtmosphereOn() { this->SetAtmosphere(true); }
  void AtmosphereOff() { this->SetAtmosphere(false); }
  void SetGraticule(bool on);
  bool GetGraticule();
  void GraticuleOn() { this->SetGraticule(true); }
  void GraticuleOff() { this->SetGraticule(false); }
  void SetContours(bool on);
  bool GetContours();
  void ContoursOn() { this->SetContours(true); }
  void ContoursOff() { this->SetContours(false); }
  ///@}

  ///@{
  /**
   * Geodetic precision (default on; Documentation/rendering.md, "Geodetic precision"): the
   * G-buffer holds each pixel's direction as an offset from a per-frame local origin (the
   * camera's sub-point, known in double), and the passes compose layers at (lon, lat) as hi + lo
   * pairs from it, so 0.5 m data is placed as precisely at +-180 degrees longitude and 80
   * degrees latitude as at (0, 0). Off: float (lon, lat) from a float unit direction (steps of
   * up to 1.5 m near +-180 degrees, 0.4 m anywhere); the shaders are rebuilt when it changes.
   */
  void SetHighPrecisionGeodetic(bool on);
  bool GetHighPrecisionGeodetic();
  void HighPrecisionGeodeticOn() { this->SetHighPrecisionGeodetic(true); }
  void HighPrecisionGeodeticOff() { this->SetHighPrecisionGeodetic(false); }
  ///@}

  ///@{
  /**
   * Per-pixel terrain refinement (Documentation/rendering.md "Terrain refinement"): the
   * number of Newton steps (0 to 4) each pixel takes along its view ray, from the point where
   * the ray meets the rasterized mesh to where it meets the heights composed at the pixel's
   * footprint; the pixel's layers are composed there and its depth is written there. It
   * removes what the mesh adds to the error: the sag of flat triangles on the curved body and
   * the heights between grid points, so from the air the terrain's error no longer depends on
   * the grid (along the ground it still does where the grid cuts off a ridge's top: the steps
   * start behind it).
   * Each step composes the height layers once more per pixel. Default 1 (more accurate than
   * the mesh alone in every benchmark scene, for about a quarter more frame time on llvmpipe:
   * Documentation/accuracy-vs-time.md). 0 (off) leaves the rasterized surface as it is.
   * Ignored with a parallel projection and with HighPrecisionGeodeticOff.
   */
  void SetTerrainRefinement(int steps);
  int GetTerrainRefinement();
  ///@}

  ///@{
  /**
   * Interactive detail (Documentation/rendering.md "Interactive detail"), VTK's way of keeping
   * interaction fluid (vtkLODActor, the volume mappers' AutoAdjustSampleDistances): with
   * AutoAdjustDetail on (the default), a frame whose allocated render time is shorter than the
   * GPU time of the globe's last full-detail frame (FullDetailTime) is drawn at interactive
   * detail: the grid InteractiveGridCoarsening times coarser (default 2; the automatic grid's
   * pixels per cell, or the fixed size, divided) and no terrain refinement. The allocated time
   * comes from vtkRenderWindow's DesiredUpdateRate: interactor styles raise it while the camera
   * moves (vtkRenderWindowInteractor's DesiredUpdateRate, 15 frames/s) and lower it when the
   * move ends (StillUpdateRate), with a last, still render; a window whose rate is never set
   * (0.0001/s: batch images, tests, offscreen) always renders full detail. The still frame
   * after a move is final (it reads its own reduction back, as any new view does), and
   * switching levels compiles nothing after the first switch. FullDetailTime and
   * InteractiveDetailTime (s) are the last measured frame of each level (GPU timer queries;
   * 0 until measured; without timer queries, the CPU time of RenderPiece).
   */
  vtkSetMacro(AutoAdjustDetail, bool);
  vtkGetMacro(AutoAdjustDetail, bool);
  vtkBooleanMacro(AutoAdjustDetail, bool);
  vtkSetClampMacro(InteractiveGridCoarsening, double, 1.0, 16.0);
  vtkGetMacro(InteractiveGridCoarsening, double);
  /// The level of the last frame (set as the frame starts, from its allocated time).
  vtkGetMacro(LastFrameInteractive, bool);
  vtkGetMacro(FullDetailTime, double);
  vtkGetMacro(InteractiveDetailTime, double);
  ///@}

  ///@{
  /**
   * Layers filtered to each grid point's and pixel's footprint (default on;
   * Documentation/composition.md "Filtering to the footprint"): distant terrain does not alias
   * or shimmer. Off: whole-raster layers are read at level 0 whatever the footprint (each value
   * the data's own, as before the filtering existed; streamed layers always filter). Forwards
   * to vtkGlobeLayerSet::SetFootprintFiltering; no upload, no new program.
   */
  void SetFootprintFiltering(bool on);
  bool GetFootprintFiltering();
  void FootprintFilteringOn() { this->SetFootprintFiltering(true); }
  void FootprintFilteringOff() { this->SetFootprintFiltering(false); }
  ///@}

  ///@{
  /**
   * Streamed layers (vtkGlobeLayer::IsStreamed; Documentation/streaming.md). Each frame the
   * mapper samples the G-buffer's footprint (vtkGlobePageFeedback), the layer set turns it
   * into the pages each streamed layer needs, and the page cache reads them on worker
   * threads and uploads them within a budget over the next frames; until then a frame shows
   * the finest resident ancestor. An interactive application renders again while
   * IsStreamingIdle() is false, to let the picture refine. WaitForPages (default off): each
   * frame waits until the pages it needs are read and uploaded, and draws the grid again
   * with them (at most 16 rounds): final pictures in one Render(), for batch images and
   * tests, at the cost of frame time.
   */
  vtkSetMacro(WaitForPages, bool);
  vtkGetMacro(WaitForPages, bool);
  vtkBooleanMacro(WaitForPages, bool);
  /// The GPU page cache: its settings (page size, GPU and CPU memory, upload budget) and
  /// statistics (pages resident, requested, loaded, evicted; misses; bytes uploaded).
  vtkGlobePageCache* GetPageCache();
  /// True when no page is being read or waits for upload (the picture is final).
  bool IsStreamingIdle();
  ///@}

  ///@{
  /// The parts of a frame, for inspection, tests and benchmarks.
  vtkGlobeProjectiveGrid* GetProjectiveGrid();
  vtkGlobeGridPass* GetGridPass();
  vtkGlobeCompositePass* GetCompositePass();
  ///@}

  /// True when the last frame's primary sphere came from the GPU min reduction (false: fallback).
  vtkGetMacro(PrimaryFromReduction, bool);
  /// The lowest visible terrain height of the last frame (m), from the reduction.
  vtkGetMacro(LastVisibleMinimumHeight, double);
  /// False when the last frame drew no globe (not in view, or no usable camera).
  vtkGetMacro(LastFrameDrewGlobe, bool);

  ///@{
  /**
   * Temporal stability (Documentation/rendering.md, "The first frame after a move"): a frame
   * whose view differs from the last one reads its own lowest visible terrain back at once
   * (NumberOfSynchronousReductions counts these frames) and, when that asks for another
   * primary sphere, casts its grid again (NumberOfRecasts), so that the first frame after a
   * camera move already shows what the frames after it show. Frames of an unchanged view
   * wait for nothing.
   */
  vtkGetMacro(NumberOfSynchronousReductions, int);
  vtkGetMacro(NumberOfRecasts, int);
  ///@}

  ///@{
  /// GPU times (s) of the rasterization and the reduction, from the last finished frame.
  double GetRasterTime();
  double GetReductionTime();
  ///@}

  /// Bounds of the body (with the tallest terrain) in its body-fixed frame.
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkMapper::GetBounds(bounds); }

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  vtkMTimeType GetMTime() override;

protected:
  vtkGlobeMapper();
  ~vtkGlobeMapper() override;

  // The last frame's G-buffer: internal (its layout follows the precision mode), reached by
  // tests and benchmarks through vtkGlobeMapperTesting.
  friend class vtkGlobeMapperTesting;
  vtkTextureObject* GetGBufferTexture();
  vtkTextureObject* GetGBufferDepthTexture();

  double GridPixelsPerCell = 1.6; // 0: the fixed GridResolution
  bool AutoAdjustDetail = true;
  double InteractiveGridCoarsening = 2.0;
  bool LastFrameInteractive = false;
  double FullDetailTime = 0.0;
  double InteractiveDetailTime = 0.0;

  bool RenderGBuffer(vtkRenderer* ren, vtkActor* act, int width, int height);
  // The automatic grid's size for the view just cast (GridPixelsPerCell).
  void FitGrid(vtkRenderer* ren, vtkActor* act, int width, int height);
  // Reduces the G-buffer (false: the program did not compile, no levels).
  bool ReduceMinimumRadius(vtkRenderer* ren, int width, int height, const double eye[3]);
  void CollectReduction();
  void UpdateLight(vtkRenderer* ren, vtkActor* act);
  // A camera that leaves nothing of the globe to see: a key per kind ("" when fine) and the
  // message to report once.
  void DiagnoseCamera(vtkRenderer* ren, const double eyeBody[3], double minHeight,
    std::string& key, std::string& message);

  bool PrimaryFromReduction = false;
  double LastVisibleMinimumHeight = 0.0;
  bool LastFrameDrewGlobe = false;
  bool WaitForPages = false;
  int NumberOfSynchronousReductions = 0;
  int NumberOfRecasts = 0;

private:
  vtkGlobeMapper(const vtkGlobeMapper&) = delete;
  void operator=(const vtkGlobeMapper&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
