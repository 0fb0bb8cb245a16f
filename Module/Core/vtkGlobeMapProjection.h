/**
 * @class   vtkGlobeMapProjection
 * @brief   A map projection of a datum ellipsoid: geodetic (lon, lat) <-> map (x, y), on the
 *          CPU with GeographicLib and on the GPU through globe_projection.glsl.
 *
 * Kinds (Documentation/projections.md):
 * - Geographic: x = longitude, y = latitude, in degrees (EPSG:4326).
 * - Equirectangular: x = FE + a cos(phi1) (lon - lon0), y = FN + a lat (metres, radians
 *   inside), any standard parallel phi1 (EPSG:4087).
 * - PolarStereographic: north or south, scale ScaleFactor at LatitudeOfTrueScale (variant B:
 *   k = 1 at e.g. 70 N for EPSG:3413; variant A / UPS: k0 = 0.994 at the pole), central
 *   meridian, false easting/northing (GeographicLib::PolarStereographic).
 * - Mercator: ellipsoidal, scale ScaleFactor at the standard parallel (EPSG:3395)
 *   (GeographicLib::LambertConformalConic with a standard parallel at the equator).
 * - WebMercator: spherical formulas with R = a on the datum's latitude (EPSG:3857).
 * - TransverseMercator: central meridian, ScaleFactor, latitude of origin, false
 *   easting/northing; UTM zones (GeographicLib::TransverseMercator, Krueger's series).
 * - LambertConformalConic: one standard parallel with ScaleFactor there (EPSG method 9801) or
 *   two (9802), latitude and longitude of the (false) origin, false easting/northing
 *   (GeographicLib::LambertConformalConic); e.g. EPSG:2154, 3034.
 * - AlbersEqualArea: two standard parallels, latitude of the false origin, central meridian,
 *   false easting/northing (GeographicLib::AlbersEqualArea); e.g. EPSG:5070, 3577.
 * - LambertAzimuthalEqualArea: latitude and longitude of origin, false easting/northing.
 *   Polar aspects (latitude of origin +-90), e.g. EASE-Grid 2.0 North and South (EPSG:6931,
 *   6932), through GeographicLib::AlbersEqualArea with a standard parallel at the pole; the
 *   oblique and equatorial aspects, e.g. LAEA Europe (EPSG:3035), through Snyder's ellipsoidal
 *   formulas on the authalic sphere (USGS PP 1395, 24-19 to 24-30; the inverse latitude by
 *   Newton's method on q). The valid domain leaves out 5 degrees around the centre's
 *   antipode (the image's rim, where the inverse is ill-conditioned).
 * - CylindricalEqualArea: standard parallel, central meridian, false easting/northing; e.g.
 *   EASE-Grid 2.0 Global (EPSG:6933) (GeographicLib::AlbersEqualArea with standard parallels
 *   +-phi1).
 * - Sinusoidal: on a sphere of radius SemiMajorAxis (Flattening 0), central meridian, false
 *   easting/northing: x = FE + R (lon - lon0) cos(lat), y = FN + R lat, lon - lon0 in
 *   [-180, 180). The MODIS land products' grid (R = 6371007.181 m), which has no EPSG code:
 *   SetFromDefinition takes its PROJ string or WKT. Latitudes are the datum's geodetic ones,
 *   as PROJ takes them (no datum shift to a sphere).
 *
 * For the cylindrical kinds (Geographic, Equirectangular, Mercator, WebMercator,
 * CylindricalEqualArea) Forward wraps the longitude into [LongitudeWest, LongitudeWest + 360)
 * before projecting, so both the -180..180 (default) and the 0..360 conventions give the x of
 * their rasters.
 *
 * SetFromEPSG knows 4326, 4087, 32662, 3413, 3031, 3995, 3976, 3032, 32661, 32761, 3395,
 * 3857 (900913, 3785), 326zz and 327zz (UTM zones 1-60), all on WGS84, from a table; and any
 * other code whose definition in PROJ's database uses one of the methods above (transverse
 * Mercator, polar stereographic A/B, Mercator A/B, Lambert conformal conic 1SP/2SP, Albers,
 * Lambert azimuthal equal-area, Lambert cylindrical equal-area) in metres, provided
 * that the projection then agrees with PROJ's own transformation from EPSG:4326 within 1 mm
 * at points of the CRS's area of use: a CRS on a datum that PROJ shifts against WGS 84 (e.g.
 * OSGB 36, EPSG:27700) is not drawn this way (layers reproject it on load instead).
 *
 * GPU: ComputeShaderParameters turns a raster's georeferencing into the seven vec4 of
 * globe_projection.glsl (computed in double, the big numbers folded in), and
 * GetShaderFunctionName names the GLSL function to call with them. That function maps
 * (lon, lat) in radians, as hi + lo pairs, to the raster's texture coordinates.
 *
 * Bad input (non-finite coordinates, |lat| > 90, unknown EPSG code, bad ellipsoid or raster)
 * is reported with vtkErrorMacro and the call returns false; outputs are then NaN.
 */
#ifndef vtkGlobeMapProjection_h
#define vtkGlobeMapProjection_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for SetFromPROJ

class VTKGLOBECORE_EXPORT vtkGlobeMapProjection : public vtkObject
{
public:
  /// A new projection is Geographic (EPSG:4326) on WGS84.
  static vtkGlobeMapProjection* New();
  vtkTypeMacro(vtkGlobeMapProjection, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Kinds
  {
    Geographic = 0,
    Equirectangular = 1,
    PolarStereographic = 2,
    Mercator = 3,
    WebMercator = 4,
    TransverseMercator = 5,
    LambertConformalConic = 6,
    AlbersEqualArea = 7,
    LambertAzimuthalEqualArea = 8,
    CylindricalEqualArea = 9,
    Sinusoidal = 10
  };

  /// Number of floats ComputeShaderParameters writes (seven vec4).
  enum
  {
    NumberOfShaderParameters = 28
  };

  ///@{
  /// The kind; the parameters below are kept when it changes.
  vtkSetClampMacro(Kind, int, Geographic, Sinusoidal);
  vtkGetMacro(Kind, int);
  const char* GetKindAsString();
  ///@}

  /**
   * Set everything from an EPSG code (the datum too). Returns false, with an error naming
   * the code, for codes not listed in the class description; the projection is then unchanged.
   */
  bool SetFromEPSG(int code);
  /// The EPSG code last set with SetFromEPSG; 0 after a SetTo... call or SetEllipsoid.
  vtkGetMacro(EPSG, int);

  /**
   * Set everything from a CRS definition PROJ reads (a PROJ string, WKT, or "AUTHORITY:code"),
   * for CRSs without an EPSG code, such as MODIS's sinusoidal grid
   * ("+proj=sinu +R=6371007.181 +units=m"). Accepted under the same rule as SetFromEPSG's
   * PROJ-database codes: one of the kinds above, in metres, agreeing with PROJ's own
   * transformation from EPSG:4326 within 1 mm over the CRS's area of use (the whole globe when
   * it has none). Returns false with an error otherwise; the projection is then unchanged.
   */
  bool SetFromDefinition(const char* definition);
  /// Whether SetFromDefinition accepts `definition` (without an error).
  static bool IsSupportedDefinition(const char* definition);

  ///@{
  /**
   * The datum ellipsoid: semi-major axis a (m, finite, > 0) and flattening f (in [0, 1)).
   * Default WGS84. Returns false (unchanged) with an error for bad values.
   */
  bool SetEllipsoid(double semiMajorAxis, double flattening);
  void SetEllipsoidToWGS84();
  vtkGetMacro(SemiMajorAxis, double);
  vtkGetMacro(Flattening, double);
  ///@}

  ///@{
  /// Convenience setters for each kind (angles in degrees, lengths in metres).
  void SetToGeographic();
  void SetToEquirectangular(double centralMeridian, double standardParallel,
    double falseEasting = 0.0, double falseNorthing = 0.0);
  /// North when latitudeOfTrueScale > 0; the scale there is scaleFactor (UPS: 90, 0.994).
  void SetToPolarStereographic(double latitudeOfTrueScale, double centralMeridian,
    double scaleFactor = 1.0, double falseEasting = 0.0, double falseNorthing = 0.0);
  void SetToMercator(double centralMeridian, double standardParallel, double scaleFactor = 1.0,
    double falseEasting = 0.0, double falseNorthing = 0.0);
  void SetToWebMercator(double centralMeridian = 0.0);
  void SetToTransverseMercator(double centralMeridian, double scaleFactor,
    double falseEasting = 0.0, double falseNorthing = 0.0, double latitudeOfOrigin = 0.0);
  /// UTM zone 1..60 (false and an error otherwise), north or south hemisphere.
  bool SetToUTM(int zone, bool north);
  /**
   * Two standard parallels (scale 1 on both; equal ones make the one-parallel, tangent cone),
   * the latitude of the false origin (where y = falseNorthing on the central meridian).
   */
  void SetToLambertConformalConic(double standardParallel1, double standardParallel2,
    double latitudeOfOrigin, double centralMeridian, double falseEasting = 0.0,
    double falseNorthing = 0.0);
  /// One standard parallel, which is the latitude of origin, with the scale scaleFactor there.
  void SetToLambertConformalConic1SP(double latitudeOfOrigin, double centralMeridian,
    double scaleFactor, double falseEasting = 0.0, double falseNorthing = 0.0);
  void SetToAlbersEqualArea(double standardParallel1, double standardParallel2,
    double latitudeOfOrigin, double centralMeridian, double falseEasting = 0.0,
    double falseNorthing = 0.0);
  /// Any aspect: polar when latitudeOfOrigin is +-90, else oblique (equatorial at 0).
  void SetToLambertAzimuthalEqualArea(double latitudeOfOrigin, double centralMeridian,
    double falseEasting = 0.0, double falseNorthing = 0.0);
  void SetToCylindricalEqualArea(double standardParallel, double centralMeridian,
    double falseEasting = 0.0, double falseNorthing = 0.0);
  /// The sinusoidal projection on a sphere of radius sphereRadius (which becomes the
  /// ellipsoid: SemiMajorAxis sphereRadius, Flattening 0); MODIS: 6371007.181, 0.
  void SetToSinusoidal(double sphereRadius, double centralMeridian, double falseEasting = 0.0,
    double falseNorthing = 0.0);
  ///@}

  ///@{
  /// The individual parameters (degrees, metres). Not every kind uses every one.
  vtkSetMacro(CentralMeridian, double);
  vtkGetMacro(CentralMeridian, double);
  /// Equirectangular and Mercator: the parallel where ScaleFactor holds (Mercator) or whose
  /// cosine scales x (equirectangular); cylindrical equal-area: where the scale is 1; the
  /// conics: the first standard parallel.
  vtkSetMacro(StandardParallel, double);
  vtkGetMacro(StandardParallel, double);
  /// The conics' second standard parallel (equal to the first: one standard parallel).
  vtkSetMacro(StandardParallel2, double);
  vtkGetMacro(StandardParallel2, double);
  /// Polar stereographic: the latitude where the scale is ScaleFactor; its sign picks the pole.
  vtkSetMacro(LatitudeOfTrueScale, double);
  vtkGetMacro(LatitudeOfTrueScale, double);
  vtkSetMacro(ScaleFactor, double);
  vtkGetMacro(ScaleFactor, double);
  /// Transverse Mercator and the conics: the latitude where y = FalseNorthing on the central
  /// meridian; Lambert azimuthal equal-area: the centre's latitude (+-90: a polar aspect).
  vtkSetMacro(LatitudeOfOrigin, double);
  vtkGetMacro(LatitudeOfOrigin, double);
  vtkSetMacro(FalseEasting, double);
  vtkGetMacro(FalseEasting, double);
  vtkSetMacro(FalseNorthing, double);
  vtkGetMacro(FalseNorthing, double);
  ///@}

  ///@{
  /// Cylindrical kinds: Forward's longitudes lie in [LongitudeWest, LongitudeWest + 360).
  vtkSetMacro(LongitudeWest, double);
  vtkGetMacro(LongitudeWest, double);
  void SetLongitudeDomainToMinus180To180() { this->SetLongitudeWest(-180.0); }
  void SetLongitudeDomainTo0To360() { this->SetLongitudeWest(0.0); }
  ///@}

  ///@{
  /// (longitude, latitude) in degrees -> map (x, y). False (NaN) with an error for bad input.
  bool Forward(double lon, double lat, double xy[2]);
  /// Map (x, y) -> (longitude, latitude) in degrees. False (NaN) with an error for bad input.
  bool Inverse(double x, double y, double lonLat[2]);
  ///@}

  ///@{
  /**
   * Forward and Inverse without messages, for callers that probe many points some of which
   * lie outside by design (page requests, footprints): false (NaN) where the point is not
   * finite, has no finite image, or (lon, lat) lies outside IsInValidDomain. They never touch
   * the process-wide warning flag, which other threads read.
   */
  bool ForwardInDomain(double lon, double lat, double xy[2]);
  bool InverseInDomain(double x, double y, double lonLat[2]);
  ///@}

  /**
   * West, east, south, north (degrees; east may exceed 180) of the region where the
   * projection is valid and used: the whole globe for Geographic and Equirectangular,
   * +-89.5 (Mercator), +-85.0511 (Web Mercator), its hemisphere (polar stereographic),
   * 10 degrees either side of the central meridian between 89 S and 89 N (transverse
   * Mercator; UTM: 80 S to 84 N), all longitudes and latitudes short of 0.5 degrees of the
   * pole opposite the apex (the conics and polar Lambert azimuthal equal-area), the whole
   * globe (cylindrical equal-area, sinusoidal; oblique Lambert azimuthal equal-area less a
   * cap of 5 degrees around its centre's antipode, which IsInValidDomain checks beyond this
   * box). The GPU functions return (-1, -1) outside it.
   */
  void GetValidDomain(double box[4]);
  /// Whether (lon, lat) in degrees lies in GetValidDomain's region.
  bool IsInValidDomain(double lon, double lat);

  /**
   * The GLSL parameters for a raster: map coordinates of its north-west outer corner, pixel
   * size (x east, y south, both > 0, map units) and size in pixels, as the layer gives them
   * (vtkGlobeLayer::GetProjectedGeoTransform). Computed in double, written as floats
   * (p0.xyzw, p1.xyzw, ... p6.xyzw). False with an error for bad input.
   */
  bool ComputeShaderParameters(const double origin[2], const double pixelSize[2], int width,
    int height, float parameters[28]);
  /// The same in double, for globe_projection.glsl's double C++ mirror (hi + lo pairs exact).
  bool ComputeShaderParametersDouble(const double origin[2], const double pixelSize[2],
    int width, int height, double parameters[28]);
  /**
   * The same in double with the reference point at the map point `reference` (clamped into the
   * raster) instead of the raster's centre. The GPU's float offsets from the reference are
   * relatively accurate, so they are exact to a small fraction of a texel only within some
   * 10^5 texels of it: a streamed layer wider than that puts the reference under the view each
   * frame (vtkGlobeLayerSet; Documentation/streaming.md, "Exact addressing").
   */
  bool ComputeShaderParametersAt(const double origin[2], const double pixelSize[2], int width,
    int height, const double reference[2], double parameters[28]);

  /**
   * The globe_projection.glsl function that takes these parameters:
   * globe_projectEquirectangular (Geographic too), globe_projectMercator (Web Mercator too),
   * globe_projectPolarStereographic, globe_projectTransverseMercator,
   * globe_projectConformalConic, globe_projectAlbersEqualArea (polar Lambert azimuthal
   * equal-area too), globe_projectObliqueAzimuthalEqualArea, globe_projectCylindricalEqualArea
   * or globe_projectSinusoidal.
   */
  const char* GetShaderFunctionName();

  /**
   * Whether the map is cut along the meridian opposite the central one, so that points a step
   * apart on the globe can lie on opposite sides of the map: the sinusoidal projection, the
   * conics and polar Lambert azimuthal equal-area.
   */
  bool HasMapCut();

  /**
   * Map units per radian of longitude along the x axis of a cylindrical projection
   * (Geographic: degrees, Equirectangular: a cos(standard parallel), Mercator: a k0, Web
   * Mercator: a, cylindrical equal-area: a k0); 0 for the other kinds, whose x is not proportional to longitude.
   */
  double GetMapUnitsPerRadianOfLongitude();

  /**
   * Whether a raster `width` pixels of `pixelWidth` map units wide spans all longitudes, so it
   * wraps east-west (no seam, no feather at the antimeridian): cylindrical kinds only, within
   * half a pixel of one whole turn (wider or narrower would misregister the wrap).
   */
  bool SpansAllLongitudes(double pixelWidth, int width);
  /// The same for a raster in EPSG:`code`; false for unsupported codes (without an error).
  static bool SpansAllLongitudes(int code, double pixelWidth, int width);

  /**
   * The one rule for a raster that wraps east-west (vtkGlobeLayer::IsGlobal, the page
   * source): a geographic raster (pixel width in degrees) at least 360 degrees wide, less
   * 1e-7 for a pixel size written with 15 digits (readers refuse wider than 360 plus a
   * pixel); a projected one by SpansAllLongitudes.
   */
  static bool IsGlobalRaster(bool geographic, int code, double pixelWidth, int width);

  /// Whether SetFromEPSG knows `code` (the projections the GPU draws exactly; layers in other
  /// CRSs are reprojected on load, vtkGlobeLayer::GetReprojectedFromEPSG).
  static bool IsSupportedEPSG(int code);

protected:
  vtkGlobeMapProjection();
  ~vtkGlobeMapProjection() override;

  int Kind = Geographic;
  int EPSG = 4326;
  double SemiMajorAxis = 6378137.0;
  double Flattening = 1.0 / 298.257223563;
  double CentralMeridian = 0.0;
  double StandardParallel = 0.0;
  double StandardParallel2 = 0.0;
  double LatitudeOfTrueScale = 90.0;
  double ScaleFactor = 1.0;
  double LatitudeOfOrigin = 0.0;
  double FalseEasting = 0.0;
  double FalseNorthing = 0.0;
  double LongitudeWest = -180.0;
  bool UTM = false;

private:
  vtkGlobeMapProjection(const vtkGlobeMapProjection&) = delete;
  void operator=(const vtkGlobeMapProjection&) = delete;

  void SetParameters(int kind, double centralMeridian, double standardParallel,
    double latitudeOfTrueScale, double scaleFactor, double latitudeOfOrigin, double falseEasting,
    double falseNorthing);
  bool SetFromEPSGQuietly(int code);
  // A CRS from PROJ ("EPSG:code" or any definition it reads), checked against PROJ.
  bool SetFromPROJ(const std::string& name);
  void SetToConic(int kind, double standardParallel1, double standardParallel2,
    double latitudeOfOrigin, double centralMeridian, double falseEasting, double falseNorthing);
  // +1 when the conic's apex (or the azimuthal projection's centre) is the north pole.
  double GetApexHemisphere();
  // The kinds with an apex at a pole: the conics and polar Lambert azimuthal equal-area.
  bool IsConic();
  bool ForwardUnchecked(double lon, double lat, double xy[2]);
  bool InverseUnchecked(double x, double y, double lonLat[2]);
};

#endif
