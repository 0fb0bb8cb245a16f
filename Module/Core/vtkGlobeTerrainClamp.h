/**
 * @class   vtkGlobeTerrainClamp
 * @brief   Puts points, lines and polygons given in longitude and latitude onto the composed
 *          terrain, plus an offset, densifying long segments along geodesics.
 *
 * Input: a vtkPolyData whose point coordinates are GEODETIC: x the longitude and y the
 * latitude in degrees, z a height in metres (ignored by ClampToTerrain, added by
 * RelativeToTerrain). Output: the same cells with BODY-FIXED CARTESIAN points in metres
 * (double precision; float would round to half a metre on the Earth), ready for an ordinary
 * vtkPolyDataMapper in the globe actor's frame, at the height
 *   ClampToTerrain:     terrain(lon, lat) + HeightOffset
 *   RelativeToTerrain:  terrain(lon, lat) + z + HeightOffset
 * where terrain is the Terrain's composed ellipsoidal height (vtkGlobeTerrain::GetHeight, the
 * GPU's composition rules on the CPU). Every output point is within 1 mm of that height: the
 * conversion to Cartesian coordinates is the ellipsoid's, in double (TestGlobeTerrainClamp).
 *
 * With MaximumSegmentLength > 0, each edge of a line or polygon longer than it is divided into
 * equal parts along the geodesic between its ends (GeographicLib on a biaxial body; on a
 * triaxial one, along the chord scaled to the surface), so lines follow the ground between the
 * input points; inserted points get point data interpolated along the edge. Polygon interiors
 * are not subdivided (triangulate and subdivide upstream for filled areas), triangle strips
 * are clamped without densifying. Cell data is passed.
 *
 * Errors (vtkErrorMacro): no Terrain, no Ellipsoid. Points with a non-finite longitude or
 * latitude, or where the terrain has no value, are put on the ellipsoid plus the offsets.
 */
#ifndef vtkGlobeTerrainClamp_h
#define vtkGlobeTerrainClamp_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkGlobeEllipsoid;
class vtkGlobeTerrain;

class VTKGLOBECORE_EXPORT vtkGlobeTerrainClamp : public vtkPolyDataAlgorithm
{
public:
  static vtkGlobeTerrainClamp* New();
  vtkTypeMacro(vtkGlobeTerrainClamp, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The composed terrain (e.g. vtkGlobeMapper::GetTerrain()) and the body (e.g.
  /// vtkGlobeMapper::GetEllipsoid()). Both are required.
  void SetTerrain(vtkGlobeTerrain* terrain);
  vtkGetObjectMacro(Terrain, vtkGlobeTerrain);
  void SetEllipsoid(vtkGlobeEllipsoid* ellipsoid);
  vtkGetObjectMacro(Ellipsoid, vtkGlobeEllipsoid);
  ///@}

  enum HeightModes
  {
    ClampToTerrain = 0,   ///< terrain + HeightOffset; the input z is ignored
    RelativeToTerrain = 1 ///< terrain + z + HeightOffset
  };

  ///@{
  /// How the output height is made (default ClampToTerrain).
  vtkSetClampMacro(HeightMode, int, ClampToTerrain, RelativeToTerrain);
  vtkGetMacro(HeightMode, int);
  void SetHeightModeToClampToTerrain() { this->SetHeightMode(ClampToTerrain); }
  void SetHeightModeToRelativeToTerrain() { this->SetHeightMode(RelativeToTerrain); }
  ///@}

  ///@{
  /// Metres added above the terrain (default 0).
  vtkSetMacro(HeightOffset, double);
  vtkGetMacro(HeightOffset, double);
  ///@}

  ///@{
  /// The longest edge (m, along the geodesic) of lines and polygons in the output; 0 (the
  /// default) keeps the input's points only.
  vtkSetClampMacro(MaximumSegmentLength, double, 0.0, 1e30);
  vtkGetMacro(MaximumSegmentLength, double);
  ///@}

  /// Includes the terrain's and the ellipsoid's modification times.
  vtkMTimeType GetMTime() override;

protected:
  vtkGlobeTerrainClamp();
  ~vtkGlobeTerrainClamp() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkGlobeTerrain* Terrain = nullptr;
  vtkGlobeEllipsoid* Ellipsoid = nullptr;
  int HeightMode = ClampToTerrain;
  double HeightOffset = 0.0;
  double MaximumSegmentLength = 0.0;

private:
  vtkGlobeTerrainClamp(const vtkGlobeTerrainClamp&) = delete;
  void operator=(const vtkGlobeTerrainClamp&) = delete;
};

#endif
