/**
 * @class   vtkGlobeTerrain
 * @brief   The composed terrain height at a longitude and latitude, on the CPU, by the rules
 *          the GPU composes height layers with.
 *
 * A vtkGlobeTerrain holds height layers (vtkGlobeLayer) as a vtkGlobeMapper does, and
 * answers, in double, what the mapper's grid pass composes from them
 * (Documentation/composition.md):
 * - the enabled, valid height layers in composition order (DrawOrder, ties as added); a
 *   layer whose geoid cannot be read is skipped as the renderer skips it;
 * - each layer's value where the GPU samples it at level 0 (GetFilteredHeight: at the level
 *   a grid step's footprint needs): bilinear between texel centres
 *   (the texel itself with Interpolation Nearest), wrapped east-west for global layers,
 *   clamped at the edges; projected layers through vtkGlobeMapProjection (GeographicLib);
 *   streamed layers from their level-0 pages (vtkGlobeLayer::ReadPage);
 * - its weight: the coverage with the feathered border, times Opacity, times Kooima's
 *   projection-quality weight when asked for; zero where the value or one of its four
 *   neighbours one texel away (the gradient's) is NaN, outside ValidRange, or where the
 *   layer's geoid has no undulation;
 * - heights above a geoid (vtkGlobeLayer::VerticalDatum Geoid) made ellipsoidal, h = H + N;
 * - blended by each layer's mode (Replace mixes towards the layer by its weight, Add adds
 *   weight * value, a run of Average layers replaces by its weighted mean), from 0.
 *
 * GetHeight is the ellipsoidal height (metres above the body's ellipsoid), what the picture
 * shows; GetOrthometricHeight is GetHeight - N, the height above the geoid of the layers'
 * vertical datum (or the one set with SetGeoid).
 *
 * The bound against the picture. GetHeight is the exact composition at level 0; what the
 * renderer draws at the same (lon, lat) (the depth buffer read back and unprojected in double)
 * differs from it by at most
 *   depth resolution along the ray * (1 + s)
 *   + s * (texel / 256 + p)                 the GPU's 8-bit filter weights, and p, where float
 *                                           arithmetic puts the sample: 0.1 mm + 3e-7 times the
 *                                           distance from the camera's sub-point with
 *                                           HighPrecisionGeodetic (the default), else 8 float
 *                                           ulps of the radius (about 3 m on the Earth)
 *   + 2 c + L^2 / (6 R)                     the projective grid's planar triangles of longest
 *                                           edge L on a body of radius R
 * with s the terrain's slope, c the data's deviation from linear over L (its second
 * differences); where L exceeds the texels the grid samples mipmapped data and c becomes half
 * the relief over L, plus s * L / 2 (vtkGlobeTest::CheckTerrain computes it per pixel).
 * TestGlobeTerrainQuery measures it looking 45 degrees down from 1 km over Mount Rainier's
 * 90 m SRTM (EGM96 datum, and across the inset's feathered border): every pixel within its
 * bound, at 0.45 of it at worst; median |difference| 3.7 m, worst 74 m on steep flanks where
 * the bound is tens of metres; the median signed difference within 3 m. On smooth synthetic
 * layers (Average and Add) from 2 km: median 0.002 m, worst 0.15 m.
 *
 * Queries do not re-read layers: Update() brings every layer up to date (vtkGlobeLayer::
 * Update); a layer never loaded is loaded by the first query. A vtkGlobeMapper keeps one for
 * its own layers (vtkGlobeMapper::GetTerrain()).
 */
#ifndef vtkGlobeTerrain_h
#define vtkGlobeTerrain_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkGlobeGeoid;
class vtkGlobeLayer;

class VTKGLOBECORE_EXPORT vtkGlobeTerrain : public vtkObject
{
public:
  static vtkGlobeTerrain* New();
  vtkTypeMacro(vtkGlobeTerrain, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The layers, in the order added (as vtkGlobeMapper::AddLayer). Layers of other roles
  /// than Height are kept and ignored.
  void AddLayer(vtkGlobeLayer* layer);
  void RemoveLayer(vtkGlobeLayer* layer);
  void RemoveAllLayers();
  int GetNumberOfLayers();
  vtkGlobeLayer* GetLayer(int index);
  ///@}

  /// Brings every layer up to date (vtkGlobeLayer::Update) and forgets the pages read from
  /// streamed layers.
  void Update();

  /// The composed ellipsoidal height (m) at (lon, lat) in degrees; 0 without height layers
  /// and at latitudes beyond +-90 degrees (outside every layer); NaN for NaN input.
  double GetHeight(double lon, double lat);

  /// Which of the renderer's level rules GetFilteredHeight follows.
  enum FootprintRules
  {
    GridFootprint,  ///< the grid pass's: the shorter axis within 16:1
    PixelFootprint ///< the screen passes' (normals, height colours): OpenGL's longer axis
  };

  /**
   * The composed height as the renderer samples it where one step along each of two axes
   * (the grid's, or the screen's for PixelFootprint) moves (lon, lat) by footprint = (dlon,
   * dlat, dlon, dlat) degrees: each layer filtered to that footprint
   * (Documentation/composition.md "Filtering to the footprint"), trilinearly between the two
   * levels of its pyramid (vtkGlobeLayer::GetLevelData, or a streamed layer's pages) around
   * the level the GPU takes, by the same rule (within 6 degrees of a pole the shorter axis
   * takes over for geographic layers). A zero footprint gives GetHeight. The GPU evaluates the
   * rule in float, so near a whole level its trilinear weight may differ by its 8-bit quantum.
   */
  double GetFilteredHeight(
    double lon, double lat, const double footprint[4], int rule = GridFootprint);

  /**
   * The undulation N (m) of the vertical datum at (lon, lat): of the geoid set with SetGeoid,
   * else of the last height layer in composition order whose vertical datum is a geoid; NaN
   * when there is none or it has no value there.
   */
  double GetGeoidUndulation(double lon, double lat);

  /// GetHeight - GetGeoidUndulation: the height above the geoid (NaN without one).
  double GetOrthometricHeight(double lon, double lat);

  ///@{
  /// The geoid for orthometric heights when the layers have none (or another one is wanted);
  /// nullptr (the default): the layers' own.
  void SetGeoid(vtkGlobeGeoid* geoid);
  vtkGetObjectMacro(Geoid, vtkGlobeGeoid);
  ///@}

protected:
  vtkGlobeTerrain();
  ~vtkGlobeTerrain() override;

  vtkGlobeGeoid* Geoid = nullptr;

private:
  vtkGlobeTerrain(const vtkGlobeTerrain&) = delete;
  void operator=(const vtkGlobeTerrain&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
