/**
 * @class   vtkGlobeLayer
 * @brief   A georeferenced raster (heights or colour imagery) for the globe mapper.
 *
 * A layer is one raster the globe mapper uploads as a texture: a height map (metres) or
 * colour imagery. It is the end of a VTK pipeline (a sink, like a writer): its input is a
 * vtkImageData carrying vtkGlobeRasterReader's georeferencing field data, so
 * `layer->SetInputConnection(reader->GetOutputPort())` works and filters may sit between
 * (vtkImageShiftScale on heights, vtkImageGaussianSmooth...). FileName is a convenience that
 * connects an internal vtkGlobeRasterReader (GetFileReader()); SetHeightData / SetColorData
 * give values in memory. Whichever of the three was set last is the layer's source.
 *
 * Update() brings the input pipeline up to date (upstream algorithms re-execute only when
 * modified) and re-loads only when the input data was regenerated or a setting that changes
 * the data was modified since the last successful load; each re-load makes a new GetData()
 * array, so its MTime tells a renderer that the layer changed.
 *
 * The reader reads pixels with OpenImageIO, integer rasters in their native type (OpenImageIO's
 * conversion to float would rescale them to [-1, 1]); georeferencing from GeoTIFF tags or a
 * world file, and the nodata value from GDAL's GDAL_NODATA tag (42113). The grid (corner and
 * pixel size) is taken from the input image's origin, spacing and extent, so filters that
 * crop or resample keep it georeferenced; model type, EPSG code, nodata and datum from the
 * field data.
 *
 * Output (GetData()): row 0 is the NORTH row, index = row * width + column.
 * - Height: a 1-component vtkFloatArray of raw * ValueScale + ValueOffset metres. Nodata
 *   and NaN posts are voids; with FillVoids on (the default) they are filled by a push-pull
 *   fill (a valid-weighted image pyramid: averages of the valid posts are pulled up to
 *   coarser levels, then pushed back down into the voids by bilinear interpolation), so a
 *   void becomes a smooth surface at the level of its surroundings. Every filled value is a
 *   convex combination of valid values, so the fill never goes above the highest or below
 *   the lowest valid post. With FillVoids off the voids are NaN: the mapper should give
 *   them zero coverage so the layer below shows through.
 * - Color: a 4-component vtkUnsignedCharArray (RGBA). Alpha is the file's alpha channel
 *   when it has one (straight, not premultiplied), else 255, and 0 where all colour channels
 *   equal the nodata value. Samples of other types are converted to 8 bits by OpenImageIO.
 *
 * Georeferencing: Geographic layers give their pixel-edge box in degrees
 * (GetGeographicExtent); points-registered rasters (RasterPixelIsPoint) are shifted by half
 * a pixel so the box is always the outer edge of the pixels. Projected layers are read too
 * (EPSG code, map origin and pixel size through GetProjectedGeoTransform); whether the
 * renderer supports a projection is the renderer's decision. Rasters stored south-up are
 * flipped so row 0 is north; rotated or sheared rasters are refused.
 *
 * Every failure (missing file, unreadable or truncated image, no georeferencing, a channel
 * count that does not fit the role, a raster without any valid post, bad in-memory input, a
 * failed input pipeline) is reported with vtkErrorMacro naming the file and the reason, and
 * leaves the layer invalid (IsValid() false, no data kept).
 */
#ifndef vtkGlobeLayer_h
#define vtkGlobeLayer_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkDeprecation.h" // for VTK_DEPRECATION
#include "vtkObject.h"
#include "vtkWrappingHints.h" // for VTK_SIZEHINT

#include <limits> // for std::numeric_limits
#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <utility> // for std::pair

class vtkAlgorithm;
class vtkAlgorithmOutput;
class vtkDataArray;
class vtkDataObject;
class vtkGlobeGeoid;
class vtkGlobeMapProjection;
class vtkGlobePageSource;
class vtkGlobeRasterReader;
class vtkImageData;

class VTKGLOBECORE_EXPORT vtkGlobeLayer : public vtkObject
{
public:
  static vtkGlobeLayer* New();
  vtkTypeMacro(vtkGlobeLayer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the raster is. Height: metres, composed per grid point. The others are images
   * (loaded as RGBA), composed per screen pixel: Color (albedo), NormalMap (tangent-space
   * normals in the east-north-up frame, RGB = 0.5 * n + 0.5), Overlay (RGBA drawn on top of
   * the lit ground, unlit), Mask (the red channel, 1 = water: specular reflection), and
   * NightLights (RGB light emitted on the night side).
   */
  enum Roles
  {
    Height = 0,
    Color = 1,
    NormalMap = 2,
    Overlay = 3,
    Mask = 4,
    NightLights = 5
  };

  /**
   * How a layer meets what the layers below it composed. Replace: mix towards this layer by
   * its weight. Add: add weight * value (e.g. topography over a geoid or areoid). Average:
   * a run of consecutive Average layers is averaged by their weights, and the average
   * replaces what is below by the summed weight (capped at 1).
   */
  enum BlendModes
  {
    Replace = 0,
    Add = 1,
    Average = 2
  };

  /// Texture filtering: Linear (mipmapped, the default) or Nearest (shows the texels).
  enum Interpolations
  {
    Nearest = 0,
    Linear = 1
  };

  enum ModelTypes
  {
    Geographic = 1,
    Projected = 2
  };

  /// Whether a file is read whole (Off) or page by page (On); Auto decides by its size.
  enum StreamingModes
  {
    StreamingOff = 0,
    StreamingOn = 1,
    StreamingAuto = 2
  };

  ///@{
  /// What the raster is (see Roles): Height by default.
  vtkSetClampMacro(Role, int, Height, NightLights);
  vtkGetMacro(Role, int);
  void SetRoleToHeight() { this->SetRole(Height); }
  void SetRoleToColor() { this->SetRole(Color); }
  void SetRoleToNormalMap() { this->SetRole(NormalMap); }
  void SetRoleToOverlay() { this->SetRole(Overlay); }
  void SetRoleToMask() { this->SetRole(Mask); }
  void SetRoleToNightLights() { this->SetRole(NightLights); }
  const char* GetRoleAsString();
  /// True for every role but Height: the raster is an image, loaded as RGBA.
  bool IsImageRole() { return this->Role != Height; }
  ///@}

  ///@{
  /**
   * Composition settings. None of them reloads or re-uploads the data, and only BlendMode,
   * Enabled, DrawOrder and ProjectionQualityWeight change the generated shaders; the others
   * are uniforms.
   * - Enabled: a disabled layer is not composed at all (its texture is kept).
   * - DrawOrder: layers compose in increasing DrawOrder, ties in the order they were added.
   * - Opacity in [0, 1] multiplies the layer's weight.
   * - Gamma (> 0): image values become v^Gamma (OpenSpace's convention; 1 = unchanged).
   * - ValidRange: height values outside [min, max] are voids here (zero weight), so the
   *   layer below shows (default: everything is valid).
   * - FeatherWidth: the weight ramps from 0 to 1 over this many texels inside the layer's
   *   border (8 by default; 0 = a hard edge). Borders a global layer wraps across have none.
   * - SkirtDistance (metres, height layers): the layer's weight falls from 1 at its border to
   *   0 this far *outside* it, where its edge heights continue (clamped to the edge texels), so
   *   an inset whose heights disagree with the terrain below by d meets it in a slope of
   *   d / SkirtDistance outside its data and keeps all of its own (no inward feather then).
   *   The default, AutomaticSkirt (any negative value), is min(AutomaticSkirtLimit, 1/4 of the
   *   raster's shorter side on the ground); 0 turns the skirt off (the inward feather below).
   *   Layers that wrap have none east-west, layers that reach both poles none north-south.
   *   Documentation/composition.md "Insets without walls".
   * - FeatherDistance (metres, default 0: off): when positive, the ramp spans this distance on
   *   the ground instead, whatever the layer's resolution; so an inset whose heights disagree
   *   with the terrain below by d meets it in a slope of d / FeatherDistance, not a wall. The
   *   distance is converted to a fraction of the raster at its centre (geographic: the radii
   *   of curvature of the layer's datum there, WGS84 when the file names none; projected: map
   *   units are metres), so it holds exactly at the centre's latitude and within the map's
   *   scale distortion elsewhere. At most half the raster either way.
   * - ProjectionQualityWeight: multiply the weight by Kooima's projection-quality weight
   *   clamp(1 - |log k / log n|, 0, 1), k the anisotropy of the pixel's footprint in texels
   *   and n = ProjectionQualityLimit, so an inset in a projection that stretches texels here
   *   (e.g. equirectangular near a pole) gives way to a layer that does not.
   */
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);
  vtkBooleanMacro(Enabled, bool);
  vtkSetMacro(DrawOrder, int);
  vtkGetMacro(DrawOrder, int);
  vtkSetClampMacro(Opacity, double, 0.0, 1.0);
  vtkGetMacro(Opacity, double);
  vtkSetClampMacro(Gamma, double, 1e-3, 1e3);
  vtkGetMacro(Gamma, double);
  vtkSetVector2Macro(ValidRange, double);
  vtkGetVector2Macro(ValidRange, double);
  vtkSetClampMacro(BlendMode, int, Replace, Average);
  vtkGetMacro(BlendMode, int);
  void SetBlendModeToReplace() { this->SetBlendMode(Replace); }
  void SetBlendModeToAdd() { this->SetBlendMode(Add); }
  void SetBlendModeToAverage() { this->SetBlendMode(Average); }
  const char* GetBlendModeAsString();
  vtkSetClampMacro(FeatherWidth, double, 0.0, 1e6);
  vtkGetMacro(FeatherWidth, double);
  vtkSetClampMacro(FeatherDistance, double, 0.0, 1e8);
  vtkGetMacro(FeatherDistance, double);
  vtkSetClampMacro(SkirtDistance, double, AutomaticSkirt, 1e8);
  vtkGetMacro(SkirtDistance, double);
  void SetSkirtDistanceToAutomatic() { this->SetSkirtDistance(AutomaticSkirt); }
  /// SkirtDistance's default (see above), and the longest skirt it gives (metres).
  static constexpr double AutomaticSkirt = -1.0;
  static constexpr double AutomaticSkirtLimit = 5000.0;
  /**
   * The skirt the composition uses, as fractions of the raster's width and height (east-west,
   * north-south): (0, 0) for images, for a layer without valid data and where SkirtDistance
   * is 0; before the borders a wrap or the poles remove.
   */
  void GetSkirtBorder(double border[2]);
  /**
   * The skirt's rule as the composition applies it (vtkGlobeTerrain, vtkGlobeLayerSet and its
   * shaders' globe_skirt): skirt = (u, v) widths as GetSkirtBorder gives them after wraps and
   * poles, and a whole turn of longitude in u for a geographic layer (0 for a projected one).
   * Inside the raster (uv in [0, 1]^2) the weight is 1; outside it falls linearly with the
   * distance per axis (a geographic layer's u > 1 counts as west of its west edge when that
   * is nearer around the turn), and uv moves to the nearest point of the raster, whose
   * heights continue there; `outside` gets the distance outside per axis (texture units).
   * 0 beyond the skirt. The continued heights are read coarser with the distance: the level
   * of detail there takes at least log2 of the distance outside in level-0 texels, so the
   * edge's detail does not streak across the skirt.
   */
  static double ApplySkirt(const double skirt[3], double uv[2], double outside[2]);
  /**
   * The feathered border the composition uses, as fractions of the raster's width and height
   * (east-west, north-south), from FeatherDistance when it is positive, else from
   * FeatherWidth; before the borders a wrap or the poles remove. (0, 0) for a layer without
   * valid data, and for a height layer with a skirt (its ramp lies outside: GetSkirtBorder).
   */
  void GetFeatherBorder(double border[2]);
  vtkSetMacro(ProjectionQualityWeight, bool);
  vtkGetMacro(ProjectionQualityWeight, bool);
  vtkBooleanMacro(ProjectionQualityWeight, bool);
  vtkSetClampMacro(ProjectionQualityLimit, double, 1.0001, 1e6);
  vtkGetMacro(ProjectionQualityLimit, double);
  vtkSetClampMacro(Interpolation, int, Nearest, Linear);
  vtkGetMacro(Interpolation, int);
  void SetInterpolationToNearest() { this->SetInterpolation(Nearest); }
  void SetInterpolationToLinear() { this->SetInterpolation(Linear); }
  ///@}

  ///@{
  /**
   * Colour match (Color layers; default off): near its border the layer's colours move towards
   * the statistics of the colour layers below it, fully at the edge and not at all
   * ColorMatchWidth texels inside (default 64), so that an inset whose colours differ from the
   * base (an aerial photo over a satellite mosaic) does not show as a rectangle. The transfer
   * maps each channel's mean and standard deviation over the layer onto those of the layers
   * below over the same ground (gain clamped to [0.25, 4]), computed on the CPU when the set
   * of layers or their data change: uniforms, no upload. It needs a whole (not streamed)
   * geographic colour layer below that covers the inset; without one, or for a global layer,
   * the layer is drawn as it is.
   */
  vtkSetMacro(ColorMatch, bool);
  vtkGetMacro(ColorMatch, bool);
  vtkBooleanMacro(ColorMatch, bool);
  vtkSetClampMacro(ColorMatchWidth, double, 1.0, 1e6);
  vtkGetMacro(ColorMatchWidth, double);
  ///@}

  enum VerticalDatums
  {
    Ellipsoidal = 0, ///< heights above the ellipsoid (the default)
    Geoid = 1        ///< heights above a geoid (orthometric): GeoidFileName's N is added
  };

  ///@{
  /**
   * The vertical datum of a height layer's values (Documentation/geodesy.md "Vertical
   * datums"). Ellipsoidal heights are drawn as they are; heights above a geoid (SRTM and most
   * DEMs are above EGM96) get the geoid's undulation N added per pixel on the GPU, h = H + N,
   * bilinear between the geoid grid's nodes as PROJ does. SetVerticalDatumToEGM96 uses
   * Debian proj-data's egm96_15.gtx (vtkGlobeGeoid::GetEGM96FileName). A geoid that cannot be
   * read skips the layer with an error naming the file. Changing the datum changes the
   * generated shaders; it does not re-read the layer.
   */
  vtkSetClampMacro(VerticalDatum, int, Ellipsoidal, Geoid);
  vtkGetMacro(VerticalDatum, int);
  void SetVerticalDatumToEllipsoidal() { this->SetVerticalDatum(Ellipsoidal); }
  void SetVerticalDatumToEGM96();
  vtkSetStringMacro(GeoidFileName);
  vtkGetStringMacro(GeoidFileName);
  /// The geoid of a layer whose VerticalDatum is Geoid (read once per file and shared by the
  /// layers that name it); nullptr for ellipsoidal heights.
  vtkGlobeGeoid* GetGeoid();
  /// N at (lon, lat) in degrees for a geoid datum (NaN where the geoid has none), 0 for
  /// ellipsoidal heights: ellipsoidal height = the layer's value + this.
  double GetGeoidUndulation(double lon, double lat);
  ///@}

  ///@{
  /**
   * The georeferenced raster file to read (GeoTIFF, or an image with a world file), through
   * the internal reader. Setting a file name replaces in-memory data given with
   * SetHeightData / SetColorData and any input connection.
   */
  virtual void SetFileName(const char* fileName);
  vtkGetStringMacro(FileName);
  ///@}

  /// The reader FileName uses (e.g. to SetEPSG for a world file without a .prj file).
  vtkGlobeRasterReader* GetFileReader();

  ///@{
  /**
   * The pipeline input: a vtkImageData with vtkGlobeRasterReader's georeferencing field
   * data (point scalars, row 0 south). Setting one replaces FileName and in-memory data.
   * GetInputConnection / GetInputAlgorithm give what the layer reads (the internal reader's
   * output while FileName is the source).
   */
  void SetInputConnection(vtkAlgorithmOutput* output);
  void SetInputData(vtkDataObject* image);
  vtkAlgorithmOutput* GetInputConnection();
  vtkAlgorithm* GetInputAlgorithm();
  ///@}

  ///@{
  /**
   * The time the layer shows of a time-varying input: a vtkGlobeRasterReader given a series of
   * files (AddFileName), or any algorithm that announces TIME_STEPS or a TIME_RANGE. Update()
   * asks the input for the time step UpdateTime falls in (the last step at or before it; the
   * first for an earlier time) by that step's own time, so a new UpdateTime within the same
   * step reads and uploads nothing, and one in another step reads that step's file and
   * re-uploads this layer alone. Default 0. An input without time ignores it.
   * Documentation/pipelines.md, "Time".
   */
  vtkSetMacro(UpdateTime, double);
  vtkGetMacro(UpdateTime, double);
  /// The time of the loaded data (its DATA_TIME_STEP: the step's time); NaN when the input
  /// has none, or nothing is loaded.
  vtkGetMacro(DataTime, double);
  ///@}

  ///@{
  /**
   * A display name. When none is set, GetName() gives the file's name without its
   * directory and last extension ("relief_2deg" for .../relief_2deg.tif), or "" for
   * in-memory data. Changing it does not cause a re-read.
   */
  vtkSetStringMacro(Name);
  const char* GetName();
  ///@}

  ///@{
  /**
   * Height = raw * ValueScale + ValueOffset (Height layers; ignored for Color). Must be finite.
   * A change does not read the file again: the next Update() maps GetData() in place (in
   * double, h' = (h - offset) / scale * scale' + offset'), and a renderer maps the texture it
   * already holds the same way with a uniform (vtkGlobeLayerSet), so it uploads nothing. Only
   * when the map cannot be inverted (a previous scale of 0), when the last load found
   * implausible heights, or when the new heights would leave the plausible range does the
   * layer load again. A streamed layer keeps its pages: they carry the values of its last
   * load (ReadStoredPage), which ReadPage and the renderer map the same way; which posts are
   * implausible stays as that load decided.
   */
  vtkSetMacro(ValueScale, double);
  vtkGetMacro(ValueScale, double);
  vtkSetMacro(ValueOffset, double);
  vtkGetMacro(ValueOffset, double);
  /**
   * True when GetData() changed since `time` (a data MTime a consumer recorded when it copied
   * the values) only by such rescales: the copy, made when ValueScale and ValueOffset were s
   * and o, gives today's values as v * (ValueScale / s) + (ValueOffset - o * ValueScale / s).
   * False after a load or an edit of the array (Modified()) since `time`.
   */
  bool IsRescaledSince(vtkMTimeType time);
  /**
   * The map from values made with one ValueScale and ValueOffset to values made with
   * another: v' = v * map[0] + map[1]. The identity when the two agree; false (and the
   * identity) when the first scale is 0 or either is not finite, so no map exists.
   */
  static bool ValueMap(double fromScale, double fromOffset, double toScale, double toOffset,
    double map[2]);
  ///@}

  ///@{
  /**
   * The raw value that marks missing posts/pixels. By default it comes from the file's
   * GDAL_NODATA tag (after Update()); setting either value overrides the file's tag until
   * UseFileNoDataValue() is called. SetNoDataValue() also turns HasNoDataValue on.
   * NaN heights are voids whatever these say.
   */
  virtual void SetNoDataValue(double value);
  vtkGetMacro(NoDataValue, double);
  virtual void SetHasNoDataValue(bool has);
  vtkGetMacro(HasNoDataValue, bool);
  vtkBooleanMacro(HasNoDataValue, bool);
  /// Forget the override: use the file's GDAL_NODATA tag again (none for in-memory data).
  void UseFileNoDataValue();
  /// True while the nodata value is the user's, not the file's.
  vtkGetMacro(NoDataValueOverridden, bool);
  ///@}

  ///@{
  /**
   * Heights (after ValueScale and ValueOffset) outside [min, max] are treated as voids when
   * the layer loads, counted in GetNumberOfImplausibleValues() and reported once with a
   * warning naming the layer: one corrupt post (1e30, a flipped bit) must not move the
   * globe's reference spheres and clipping planes. Unlimited by default; a globe sets it to
   * its vtkGlobeMapper::GetPlausibleHeightRange() (derived from the body) before every
   * update, so set the range on the mapper. Changing it reloads the layer.
   */
  vtkSetVector2Macro(PlausibleRange, double);
  vtkGetVector2Macro(PlausibleRange, double);
  vtkGetMacro(NumberOfImplausibleValues, vtkIdType);
  ///@}

  ///@{
  /// Fill the voids of a Height layer with the push-pull fill (default on).
  vtkSetMacro(FillVoids, bool);
  vtkGetMacro(FillVoids, bool);
  vtkBooleanMacro(FillVoids, bool);
  ///@}

  /**
   * (Re)load the layer if the source (file name, input, in-memory data), the input data
   * (re-executed upstream) or a setting that changes the data (role, scale, offset, nodata,
   * fill) was modified since the last successful load, or if the layer is not valid. Returns IsValid(). On failure reports with vtkErrorMacro
   * and keeps no data. Changes that do not touch the data (the Name) do not re-read; a
   * file rewritten on disk under the same name (another size or modification time) is re-read
   * by the next Update(), Modified() or not. A failure is reported once: until the source, a
   * setting, the file on disk or an algorithm upstream changes, Update() returns false
   * without trying (and without reporting) again.
   */
  bool Update();

  /// True after a successful load, until the next failure.
  bool IsValid() { return this->Valid; }

  ///@{
  /**
   * Streaming (Documentation/streaming.md): a streamed layer never reads its raster whole.
   * Update() reads the file's header, georeferencing and coarsest level only; the renderer
   * reads pages (level, column, row) on demand through GetPageSource(), an OpenImageIO
   * ImageCache capped at its CacheMemory, and keeps the pages it shows in a GPU page cache.
   * Auto (the default) streams files wider or taller than StreamingThreshold texels
   * (default 8192: such a layer would need over 256 MiB of float texture whole, and files
   * over 16384 cannot be one texture at all); On streams every file; Off reads files whole.
   * In-memory data and pipeline input are always whole (they are in memory already).
   * A streamed layer has no GetData(); its Minimum/MaximumValue span the pages read so far
   * (the coarsest at load, widened by every finer page ReadPage reads: they bound what the
   * renderer can show). FillVoids fills each page's voids as it is read, bilinearly from the
   * (filled) page one level up: the push half of the push-pull fill, page by page (the
   * nodata-aware levels are the pull half); the coarsest page gets the whole fill.
   * ValueScale, ValueOffset, the plausible range and an overridden nodata value are applied
   * to every page as it is read (NumberOfImplausibleValues counts whole loads only; the
   * file's own nodata always applies). Mask layers stream only from 3 or 4 channels.
   *
   * Before any (re)load, Update() invokes StartEvent: whoever reads the layer's pages on
   * other threads (vtkGlobePageCache) lets go of them then.
   */
  vtkSetClampMacro(Streaming, int, StreamingOff, StreamingAuto);
  vtkGetMacro(Streaming, int);
  void SetStreamingToOff() { this->SetStreaming(StreamingOff); }
  void SetStreamingToOn() { this->SetStreaming(StreamingOn); }
  void SetStreamingToAuto() { this->SetStreaming(StreamingAuto); }
  vtkSetClampMacro(StreamingThreshold, int, 1, VTK_INT_MAX);
  vtkGetMacro(StreamingThreshold, int);
  /// True when the last successful Update() made a streamed layer.
  bool IsStreamed();
  /// The page source of a streamed layer (the renderer sets its page size, border and cache
  /// memory before Update(), vtkGlobePageCache::ConfigureSource).
  vtkGlobePageSource* GetPageSource();
  /**
   * One page of a streamed layer with this layer's value settings applied: the page
   * source's ReadPage (float heights with NaN voids, or RGBA) then, for heights,
   * value * ValueScale + ValueOffset, and NaN where that lies outside the plausible range
   * or equals an overridden nodata value; with FillVoids, voids filled from the level above.
   * Thread-safe between loads (see StartEvent above); returns
   * false (with an error) when the layer is not streamed or the page cannot be read.
   */
  bool ReadPage(int level, int column, int row, vtkDataArray* page);
  /**
   * The same page as the page readers store it: heights with the ValueScale and ValueOffset
   * of the layer's last load (GetStoredValueScale/Offset), which a later change of either does
   * not re-read (ReadPage maps them to today's). For a renderer that keeps pages and maps them
   * with a uniform (vtkGlobeLayerSet); colour pages are the same either way.
   */
  bool ReadStoredPage(int level, int column, int row, vtkDataArray* page);
  /// The ValueScale and ValueOffset a streamed layer's stored pages carry (those of its last
  /// load); for a whole layer, whose GetData() follows every change, ValueScale and ValueOffset.
  double GetStoredValueScale();
  double GetStoredValueOffset();
  ///@}

  /// How many times the data was (re)built from the file or the in-memory values.
  vtkGetMacro(NumberOfLoads, int);

  ///@{
  /**
   * In-memory rasters: the values are copied (width * height * components, row 0 = north)
   * with their geographic pixel-edge box in degrees, the role is set to match, FileName is
   * cleared, and the layer is loaded at once as Update() would. Heights may contain NaN
   * (voids). Errors (size <= 0, no values, components not 3 or 4, west >= east,
   * south >= north, |latitude| > 90, a span over 360 degrees, non-finite extent) are
   * reported and leave the layer invalid. From Python, pass a sequence (or buffer) of
   * exactly width * height (* components) numbers; the wrapper checks the length.
   */
  void SetHeightData(int width, int height, const float* values, double west, double east,
    double south, double north) VTK_SIZEHINT(values, width* height);
  void SetColorData(int width, int height, int components, const unsigned char* values, double west,
    double east, double south, double north) VTK_SIZEHINT(values, width* height* components);
  ///@}

  ///@{
  /**
   * Raster size of the loaded data: columns (west to east) and rows (north to south), 0 when
   * invalid; GetDimensions gives both. And its components (1 or 4). The names avoid "height",
   * which in this API means the terrain (role Height, SetHeightData).
   */
  int GetNumberOfColumns() { return this->RasterWidth; }
  int GetNumberOfRows() { return this->RasterHeight; }
  int* GetDimensions() VTK_SIZEHINT(2);
  void GetDimensions(int dimensions[2]);
  vtkGetMacro(NumberOfComponents, int);
  /// Deprecated names of GetNumberOfColumns and GetNumberOfRows, kept for one release.
  VTK_DEPRECATION("use GetNumberOfColumns()")
  int GetWidth() { return this->RasterWidth; }
  VTK_DEPRECATION("use GetNumberOfRows(): in this API height means terrain")
  int GetHeight() { return this->RasterHeight; }
  ///@}

  /**
   * The loaded values (nullptr when invalid): Height, a vtkFloatArray of metres; Color, a
   * vtkUnsignedCharArray RGBA. Row 0 is the north row.
   */
  vtkDataArray* GetData();

  ///@{
  /**
   * The MIP pyramid of the loaded data, as the renderer uploads and filters it
   * (Documentation/composition.md "Filtering to the footprint"): level 0 is GetData(); level
   * l is max(1, floor(columns / 2^l)) x max(1, floor(rows / 2^l)), as OpenGL sizes a mipmap,
   * each texel the mean of the finer level over the texel's own area (an area-weighted box
   * filter, so that every level registers exactly with OpenGL's texture coordinates, odd
   * sizes included). Height means leave voids (NaN) out (a texel is a void only where all it
   * covers is); colour means weight by alpha. Levels are computed on first use and kept
   * until the data change (a third more memory). nullptr for an invalid or streamed layer
   * (its pyramid is its page source's) or a level out of range.
   */
  int GetNumberOfLevels();
  vtkDataArray* GetLevelData(int level);
  void GetLevelDimensions(int level, int dimensions[2]);
  ///@}

  /// Voids: posts (pixels, for Color) that were nodata or NaN, before any fill.
  vtkGetMacro(NumberOfVoids, vtkIdType);

  ///@{
  /// Geographic or Projected; 0 when unknown (not loaded).
  vtkGetMacro(ModelType, int);
  /// The geographic (GCS) or projected (PCS) EPSG code; 0 if user-defined or unknown.
  vtkGetMacro(EPSG, int);
  /**
   * A projected raster's CRS when it has no EPSG code (the reader's GlobeCRS field: a PROJ
   * string or WKT, e.g. MODIS's sinusoidal grid); "" otherwise.
   */
  const char* GetCRSDefinition();
  ///@}

  /**
   * Sets `projection` to this Projected layer's map projection (its EPSG code or its CRS
   * definition, vtkGlobeMapProjection::SetFromEPSG / SetFromDefinition) and its file's datum
   * ellipsoid when it spells one out. False, without an error and leaving `projection`
   * unchanged, when the layer is not projected or its CRS is not one the GPU draws.
   */
  bool GetMapProjection(vtkGlobeMapProjection* projection);

  /**
   * West, east, south, north in degrees: the box around the outer pixel edges. Geographic
   * layers only (NaN for Projected or invalid layers).
   */
  void GetGeographicExtent(double extent[4]);
  /// The same as a return value (Python: `west, east, south, north = layer.GetGeographicExtent()`);
  /// it lives in the layer until the next call.
  double* GetGeographicExtent() VTK_SIZEHINT(4);

  /**
   * Map coordinates of the top-left (north-west) pixel corner and the pixel size (x: east,
   * y: south, both positive), in the model's units: metres for the usual projected systems,
   * degrees for Geographic layers. NaN when invalid.
   */
  void GetProjectedGeoTransform(double origin[2], double pixelSize[2]);

  ///@{
  /**
   * The datum's ellipsoid from the file's GeogSemiMajorAxis / GeogSemiMinorAxis /
   * GeogInvFlattening keys (e.g. the Moon's 1,737,400 m sphere); 0 when the file has no
   * such keys (e.g. only an EPSG code) or for in-memory data.
   */
  vtkGetMacro(DatumSemiMajorAxis, double);
  vtkGetMacro(DatumSemiMinorAxis, double);
  ///@}

  ///@{
  /// Range of the valid (non-void) heights after scale and offset; 0 for Color or invalid.
  /// Streamed: of the pages read so far.
  double GetMinimumValue();
  double GetMaximumValue();
  ///@}

  /**
   * The EPSG code of a projected raster whose CRS the GPU does not project (not one of
   * vtkGlobeMapProjection's; any CRS PROJ knows), which the layer resampled on load into a
   * geographic grid through PROJ (Documentation/projections.md "Any other CRS"); 0 when the
   * layer is drawn in its own georeferencing. Streamed layers need a supported CRS.
   */
  vtkGetMacro(ReprojectedFromEPSG, int);
  /// Whether the layer was resampled on load into a geographic grid (ReprojectedFromEPSG, or
  /// a CRS without a code, GetReprojectedFromCRS).
  bool IsReprojected();
  /// The CRS definition a layer without an EPSG code was reprojected from; "" otherwise.
  const char* GetReprojectedFromCRS();

  /**
   * A layer that spans all longitudes and so wraps east-west, without a seam or a feathered
   * border at the antimeridian: a Geographic layer 360 degrees wide, or a Projected one in a
   * cylindrical projection (equirectangular, Mercator, Web Mercator) within half a pixel of a
   * whole turn wide (vtkGlobeMapProjection::SpansAllLongitudes).
   */
  bool IsGlobal();

  /// Degrees per pixel along x (axis 0) or y (axis 1); Geographic layers only, else NaN.
  double GetDegreesPerPixel(int axis);

protected:
  vtkGlobeLayer();
  ~vtkGlobeLayer() override;

  // Settings.
  int Role = Height;
  int VerticalDatum = Ellipsoidal;
  int ReprojectedFromEPSG = 0;
  std::string ReprojectedFromCRS;
  double ExtentResult[4] = { 0, 0, 0, 0 }; // GetGeographicExtent()'s
  char* GeoidFileName = nullptr;
  char* FileName = nullptr;
  char* Name = nullptr;
  double ValueScale = 1.0;
  double ValueOffset = 0.0;
  double NoDataValue = 0.0;
  bool HasNoDataValue = false;
  bool NoDataValueOverridden = false;
  bool FillVoids = true;
  double PlausibleRange[2] = { -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };

  // Composition settings (used by the renderer, never by the load).
  bool Enabled = true;
  int DrawOrder = 0;
  double Opacity = 1.0;
  double Gamma = 1.0;
  double ValidRange[2] = { -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  int BlendMode = Replace;
  double FeatherWidth = 8.0;
  double FeatherDistance = 0.0;
  double SkirtDistance = AutomaticSkirt;
  bool ColorMatch = false;
  double ColorMatchWidth = 64.0;
  bool ProjectionQualityWeight = false;
  double ProjectionQualityLimit = 8.0;
  int Interpolation = Linear;
  int Streaming = StreamingAuto;
  int StreamingThreshold = 8192;
  double UpdateTime = 0.0;
  double DataTime = std::numeric_limits<double>::quiet_NaN();

  // The raster's size on the ground at its centre (m, east-west and north-south).
  bool GetGroundSize(double size[2]);

  // Results of the last load.
  bool Valid = false;
  int NumberOfLoads = 0;
  int RasterWidth = 0; // not Width/Height: Height is a Roles value
  int RasterHeight = 0;
  int Dimensions[2] = { 0, 0 }; // what GetDimensions() returns
  int NumberOfComponents = 0;
  vtkIdType NumberOfVoids = 0;
  vtkIdType NumberOfImplausibleValues = 0;
  int ModelType = 0;
  int EPSG = 0;
  std::string CRSDefinition;
  double DatumSemiMajorAxis = 0.0;
  double DatumSemiMinorAxis = 0.0;
  double MinimumValue = 0.0;
  // GetData()'s MTime before its first rescale since its last other change, and after its
  // last rescale (0: none since the load).
  vtkMTimeType ValuesTime = 0;
  vtkMTimeType RescaledTime = 0;
  double MaximumValue = 0.0;

private:
  // Maps the loaded heights from one ValueScale/ValueOffset to another in place; false when
  // that cannot give what a load would (the caller loads then).
  bool Rescale(double fromScale, double fromOffset);
  vtkGlobeLayer(const vtkGlobeLayer&) = delete;
  void operator=(const vtkGlobeLayer&) = delete;

  bool Load(vtkImageData* image, int streamedRows = 0);
  bool LoadStreamed();
  void FoldPageRange();
  // Whether a streamed layer's stored pages can be mapped to this ValueScale and ValueOffset.
  bool StoredPagesMap(double scale, double offset);
  // The stored scale and offset, read together under one lock.
  std::pair<double, double> GetStoredValueMap();
  bool StartMemoryData(const char* method, const char* what, int width, int height,
    const void* values, const double extent[4]);
  void SetMemoryImage(int role, int width, int height, int components, int scalarType,
    const void* values, const double extent[4]);
  std::string DescribeSource();
  void ReportInputFailure();
  void Invalidate();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
