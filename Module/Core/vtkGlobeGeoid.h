/**
 * @class   vtkGlobeGeoid
 * @brief   A geoid model: the undulation N (metres of the geoid above the ellipsoid) on a
 *          grid of (lon, lat) nodes, read from a PROJ .gtx file, e.g. EGM96.
 *
 * Heights above a geoid (orthometric heights, "above mean sea level": SRTM, most DEMs) become
 * ellipsoidal heights h = H + N. A height layer with a geoid vertical datum
 * (vtkGlobeLayer::SetVerticalDatumToEGM96, SetGeoidFileName) adds N per pixel on the GPU, by
 * the same bilinear interpolation of the nodes that GetUndulation does in double here and
 * that PROJ applies to the same file (Documentation/geodesy.md "Vertical datums").
 *
 * The file format is PROJ's GTX: a 40-byte big-endian header (south-west node's latitude and
 * longitude, latitude and longitude spacing, in degrees; rows and columns as 32-bit
 * integers), then rows x columns big-endian 32-bit floats, south row first, west to east.
 * -88.8888 marks a node without value. A grid whose columns span 360 degrees wraps east-west
 * (a repeated 360-degree column is dropped). Debian's proj-data ships EGM96 at 15' as
 * /usr/share/proj/egm96_15.gtx (GetEGM96FileName finds it, also under $PROJ_DATA or
 * $PROJ_LIB).
 *
 * Bad input (a missing, short or corrupt file, a header that is not a grid) is reported with
 * vtkErrorMacro naming the file; the geoid is then not valid and GetUndulation gives NaN.
 */
#ifndef vtkGlobeGeoid_h
#define vtkGlobeGeoid_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkFloatArray;

class VTKGLOBECORE_EXPORT vtkGlobeGeoid : public vtkObject
{
public:
  static vtkGlobeGeoid* New();
  vtkTypeMacro(vtkGlobeGeoid, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .gtx file. Changing it makes the next Update read it.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /// Path of EGM96 at 15' (egm96_15.gtx) in $PROJ_DATA, $PROJ_LIB or /usr/share/proj; an
  /// empty string when none of them has it.
  static const char* GetEGM96FileName();

  /// Reads the file if it changed since the last read; true when the grid is valid.
  bool Update();
  bool IsValid() { return this->Valid; }

  /// N at (lon, lat) in degrees, bilinear between the four nodes around it; NaN outside a
  /// regional grid, at a node without value, or when the geoid is not valid.
  double GetUndulation(double lon, double lat);

  ///@{
  /// Grid geometry: nodes (columns east, rows north) from the south-west node's (lon, lat),
  /// spacing in degrees; the range of N and its steepest slope (metres per metre on a sphere
  /// of 6,356,752 m, the smallest WGS84 radius) over the nodes.
  int GetNumberOfColumns() { return this->Columns; }
  int GetNumberOfRows() { return this->Rows; }
  vtkGetVector2Macro(Origin, double);
  vtkGetVector2Macro(Spacing, double);
  bool IsGlobal() { return this->Global; }
  vtkGetVector2Macro(Range, double);
  vtkGetMacro(MaximumSlope, double);
  ///@}

  /// The node values (rows x columns floats, south row first; nodes without value NaN), for
  /// upload as a texture.
  vtkFloatArray* GetValues();

protected:
  vtkGlobeGeoid();
  ~vtkGlobeGeoid() override;

  char* FileName = nullptr;
  bool Valid = false;
  int Columns = 0;
  int Rows = 0;
  double Origin[2] = { 0, 0 };
  double Spacing[2] = { 0, 0 };
  bool Global = false;
  double Range[2] = { 0, 0 };
  double MaximumSlope = 0;

private:
  vtkGlobeGeoid(const vtkGlobeGeoid&) = delete;
  void operator=(const vtkGlobeGeoid&) = delete;

  bool Read(const char* fileName);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
