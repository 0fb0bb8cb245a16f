/**
 * @class   vtkGlobeRasterReader
 * @brief   Reads a georeferenced raster (GeoTIFF, or any image with an ESRI world file) into
 *          vtkImageData whose field data carries the georeferencing.
 *
 * Pixels are read with OpenImageIO; georeferencing comes from the GeoTIFF tags (libgeotiff)
 * or from an ESRI world file next to the image (`name.tfw`/`name.tifw`, `.pgw`/`.pngw`,
 * `.jgw`/`.jpgw`, generally the extension's first and last letters + `w`, the extension + `w`,
 * or `.wld`). A world file's projection comes from `name.prj` (WKT whose top-level
 * AUTHORITY/ID is EPSG; a WKT or PROJ string PROJ identifies with an EPSG CRS; or a projected
 * CRS PROJ reads that matches none, kept as its definition in GlobeCRS), else from SetEPSG();
 * a world file without either is taken as geographic WGS 84 (EPSG:4326) only when its numbers
 * are degrees, otherwise it is an error.
 *
 * Output orientation, the VTK way: point (i, j) is the centre of a pixel, i grows east and
 * j grows NORTH, so row j = 0 is the southern row; the origin is the centre of the south-west
 * pixel and the spacing is the pixel size, both in map units (degrees for geographic rasters,
 * usually metres for projected ones). Files stored north-up (the usual case), south-up or
 * east-to-west are all brought to this orientation.
 *
 * Scalars: a 1-channel raster keeps its native sample type (8/16/32-bit integers, float,
 * double; half becomes float); rasters with more channels (RGB, RGBA) become unsigned char,
 * converted by OpenImageIO; straight alpha is kept as stored (not premultiplied).
 *
 * Field data (names returned by the static Get...ArrayName() methods):
 * - GlobeModelType (int, 1): 1 geographic, 2 projected (vtkGlobeRasterReader::ModelTypes).
 * - GlobeEPSG (int, 1): the geographic or projected EPSG code; 0 when user-defined/unknown.
 * - GlobeCRS (string, 1; only for a projected CRS that PROJ reads but matches with no EPSG
 *   code, e.g. MODIS's sinusoidal grid): its definition, a PROJ string or WKT.
 * - GlobeGeoTransform (double, 4): x and y of the north-west OUTER pixel corner, pixel width
 *   (east) and pixel height (south), both positive, in map units.
 * - GlobeGeographicExtent (double, 4; geographic only): west, east, south, north outer edges.
 * - GlobeNoDataValue (double, 1; only when the file names one, GDAL_NODATA): may be NaN.
 * - GlobeUnits (string, 1): the map unit ("degree", "metre", ...; "unknown").
 * - GlobeDatumSemiAxes (double, 2; only when the file spells the ellipsoid out).
 * - GlobeFileName (string, 1): the file read.
 * - GlobeGeoreferenceSource (string, 1): where the georeferencing came from ("GeoTIFF",
 *   "world file + .prj", "world file + SetEPSG", "world file, assumed WGS 84").
 * - GlobeStorageOrientation (int, 2): how the FILE stores its pixels, for code that reads
 *   them directly: 1 when its columns run east to west, 1 when its rows run south to north
 *   (0, 0 for the usual north-up file).
 *
 * RequestInformation reads headers only (image header, GeoTIFF tags, world and .prj files)
 * and sets WHOLE_EXTENT, ORIGIN, SPACING and the scalar type and components. RequestData
 * reads the update extent's rows in chunks, firing ProgressEvent after each chunk, and honours
 * AbortExecute between chunks.
 *
 * RequestData refuses a request larger than MaximumMemory before allocating anything.
 *
 * Errors (missing, unreadable, corrupt or truncated file, strips or tiles shorter than their
 * pixels, no georeferencing, GeoKeys stored with the wrong type, rotated or sheared rasters,
 * a pixel size too small for its coordinates, contradictory georeferencing such as a world
 * file disagreeing with the GeoTIFF tags, a .prj or SetEPSG code disagreeing with the file's,
 * or a geographic model with a projected EPSG code, an EPSG code PROJ's database does not
 * know, a request beyond MaximumMemory) are reported with vtkErrorMacro naming the file and
 * the reason, set the algorithm's error code and make the request fail, so the executive
 * stops the pipeline there. GetLastError() gives the reason of the last failure.
 */
#ifndef vtkGlobeRasterReader_h
#define vtkGlobeRasterReader_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class VTKGLOBECORE_EXPORT vtkGlobeRasterReader : public vtkImageAlgorithm
{
public:
  static vtkGlobeRasterReader* New();
  vtkTypeMacro(vtkGlobeRasterReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The values of GlobeModelType (the same as vtkGlobeLayer::ModelTypes).
  enum ModelTypes
  {
    Geographic = 1,
    Projected = 2
  };

  ///@{
  /// The raster file (ignored while a series is given with AddFileName).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * A time series: one raster per time step (a folder of dated GeoTIFFs, say), read as one
   * time-varying image. With two files or more the output information carries TIME_STEPS and
   * TIME_RANGE, and RequestData reads the file of the requested UPDATE_TIME_STEP: the last step
   * at or before it (the first step for an earlier time), stamping the output's DATA_TIME_STEP
   * with that step's own time. VTK's executive runs the reader again for any new time; within
   * the step last read, it gives the same arrays again without decoding anything. Times are
   * those given with the files (in any order; the steps are sorted by them, and two files may
   * not share one); when none is given, the dates the files' names hold (TimeFromFileNames),
   * else the files' positions 0, 1, 2...; a series with times for only some files is refused.
   * Every file must share the first step's size, samples and georeferencing: a file that does
   * not is an error naming both files and the difference.
   * While a series is given, FileName is ignored. Documentation/pipelines.md, "Time".
   */
  void AddFileName(const char* fileName);
  void AddFileName(const char* fileName, double time);
  void RemoveAllFileNames();
  int GetNumberOfFileNames();
  /// The i-th file as added (not sorted by time); nullptr out of range.
  const char* GetSeriesFileName(int i);
  /**
   * For a series given without times: when every file's name holds a date (YYYY-MM-DD,
   * YYYYMMDD, YYYY_MM_DD, or YYYY-MM for the month's first day), the steps are those dates as
   * decimal years (sst_2026-04-01.tif is at 2026 + 90/365 = 2026.2466), in date order;
   * otherwise, or with this off, at the files' positions. Default on.
   */
  vtkSetMacro(TimeFromFileNames, bool);
  vtkGetMacro(TimeFromFileNames, bool);
  vtkBooleanMacro(TimeFromFileNames, bool);
  ///@}

  ///@{
  /**
   * The EPSG code of the raster's coordinates, for files that carry none (a world file
   * without a .prj file). 0 (default): none given. A code that disagrees with the file's own
   * is an error (contradictory georeferencing), as is a code PROJ's database does not know.
   */
  vtkSetMacro(EPSG, int);
  vtkGetMacro(EPSG, int);
  ///@}

  ///@{
  /**
   * The most memory, in MiB, that reading one request may allocate (the output scalars plus
   * the read buffer). A request that would need more is refused before anything is allocated,
   * with an error giving the declared size, the bytes it needs and this budget: a corrupt or
   * hostile header (a few hundred bytes declaring 30000 x 30000 floats) cannot exhaust memory;
   * RequestInformation still describes such a file. vtkGlobeLayer holds its own copy of a
   * raster (4 bytes a pixel) to the budget of its file reader (vtkGlobeLayer::GetFileReader()).
   * Default 2048 MiB: more than any raster that fits one OpenGL texture needs (16384 x 16384
   * x 4 bytes = 1024 MiB). At least 1.
   */
  vtkSetClampMacro(MaximumMemory, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumMemory, int);
  ///@}

  /// The reason of the last failure, "" when the last request succeeded.
  const char* GetLastError();

  ///@{
  /// The names of the field-data arrays (see the class description).
  static const char* GetModelTypeArrayName() { return "GlobeModelType"; }
  static const char* GetEPSGArrayName() { return "GlobeEPSG"; }
  static const char* GetGeoTransformArrayName() { return "GlobeGeoTransform"; }
  static const char* GetGeographicExtentArrayName() { return "GlobeGeographicExtent"; }
  static const char* GetNoDataValueArrayName() { return "GlobeNoDataValue"; }
  static const char* GetUnitsArrayName() { return "GlobeUnits"; }
  static const char* GetDatumSemiAxesArrayName() { return "GlobeDatumSemiAxes"; }
  static const char* GetFileNameArrayName() { return "GlobeFileName"; }
  static const char* GetGeoreferenceSourceArrayName() { return "GlobeGeoreferenceSource"; }
  static const char* GetCRSDefinitionArrayName() { return "GlobeCRS"; }
  static const char* GetStorageOrientationArrayName() { return "GlobeStorageOrientation"; }
  ///@}

protected:
  vtkGlobeRasterReader();
  ~vtkGlobeRasterReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;
  int EPSG = 0;
  int MaximumMemory = 2048;
  bool TimeFromFileNames = true;

private:
  vtkGlobeRasterReader(const vtkGlobeRasterReader&) = delete;
  void operator=(const vtkGlobeRasterReader&) = delete;

  int Fail(unsigned long errorCode, const std::string& why);
  // Reads `file`'s header (no pixels) into the internals; 0, with the error said, on failure.
  int ReadHeader(const std::string& file);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
