/**
 * @class   vtkGlobeRasterPreparer
 * @brief   Rewrites a georeferenced raster as a tiled, multi-resolution GeoTIFF that
 *          vtkGlobePageSource (OpenImageIO's ImageCache) reads page by page.
 *
 * Input: anything vtkGlobeRasterReader reads (GeoTIFF, or an image with a world file). It is
 * read in bands of TileSize rows through the reader's UPDATE_EXTENT, so memory stays
 * O(width x TileSize) whatever the raster's height: a raster far larger than RAM can be
 * prepared (about 3 x width x TileSize x bytes per pixel in all, e.g. 130 MiB for a
 * 43200-wide float raster with 256-texel tiles).
 *
 * Output (FileName): a tiled TIFF (BigTIFF when it could exceed 4 GiB), TileSize x TileSize
 * tiles, deflate-compressed by default (horizontal or floating-point predictor), north-up:
 * - IFD 0: the full-resolution raster with its georeferencing (ModelPixelScale +
 *   ModelTiepoint at the north-west outer corner, RasterPixelIsArea, GTModelType, the
 *   geographic or projected EPSG code, degrees for geographic rasters, the linear unit for
 *   projected ones when it has an EPSG code, the datum's semi-axes when the input spells
 *   them out) and the nodata value (GDAL_NODATA, tag 42113).
 * - IFDs 1..n: reduced-resolution levels, each max(1, w/2) x max(1, h/2) of the previous one
 *   (OpenImageIO's MIP-size convention), down to the first level that fits in one tile,
 *   NEWSUBFILETYPE = FILETYPE_REDUCEDIMAGE (GDAL reads them as overviews), GDAL_NODATA on each.
 * - IFD 0 also carries the TIFF tag PIXAR_TEXTUREFORMAT = "Plain Texture". OpenImageIO's TIFF
 *   reader (2.4) treats the IFDs of a file as separate subimages unless that tag is present;
 *   with it, it reads them as the MIP levels of subimage 0, which is what the ImageCache and
 *   vtkGlobePageSource need. GDAL ignores the tag.
 *
 * Levels: a texel of level L+1 is the average of the 2 x 2 texels (2i..2i+1, 2j..2j+1) of
 * level L (an odd last column or row of level L is dropped, as in OpenGL mipmaps; each level
 * still spans the whole raster). Heights (1 channel, native sample type kept) average only
 * their valid posts (not NaN, not the nodata value); a texel over four voids is the nodata
 * value (NaN for float rasters without one); integer heights are rounded to nearest.
 * Colour rasters (2 to 4 channels, 8 bits, as vtkGlobeRasterReader gives them) are averaged
 * channel by channel, alpha included, rounded to nearest.
 *
 * Write() runs it: levels >= 1 go to temporary TIFF files next to FileName while level 0 is
 * written, and are appended as directories afterwards by copying their compressed tiles
 * (no re-encoding). ProgressEvent is fired after each band (Progress in [0, 1]); setting
 * AbortExecute from an observer stops it, removes the partial output and fails with
 * "aborted". Errors (no input, unreadable input, no georeferencing, unwritable output) are
 * reported with vtkErrorMacro naming the file and the reason; GetLastError() keeps it.
 */
#ifndef vtkGlobeRasterPreparer_h
#define vtkGlobeRasterPreparer_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for std::string

class VTKGLOBECORE_EXPORT vtkGlobeRasterPreparer : public vtkObject
{
public:
  static vtkGlobeRasterPreparer* New();
  vtkTypeMacro(vtkGlobeRasterPreparer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Compressions
  {
    NoCompression = 0,
    Deflate = 1
  };

  ///@{
  /// The georeferenced raster to read (through vtkGlobeRasterReader).
  vtkSetStringMacro(InputFileName);
  vtkGetStringMacro(InputFileName);
  ///@}

  ///@{
  /// The tiled GeoTIFF to write (replaced if it exists).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Tile width and height in texels (default 256); TIFF wants a multiple of 16, so Write()
  /// rounds it up to one.
  vtkSetClampMacro(TileSize, int, 16, 4096);
  vtkGetMacro(TileSize, int);
  ///@}

  ///@{
  /// NoCompression or Deflate (default).
  vtkSetClampMacro(Compression, int, NoCompression, Deflate);
  vtkGetMacro(Compression, int);
  void SetCompressionToNone() { this->SetCompression(NoCompression); }
  void SetCompressionToDeflate() { this->SetCompression(Deflate); }
  ///@}

  ///@{
  /// Set from a ProgressEvent observer to stop Write() (cleared when Write() starts).
  vtkSetMacro(AbortExecute, bool);
  vtkGetMacro(AbortExecute, bool);
  vtkBooleanMacro(AbortExecute, bool);
  ///@}

  /// Progress of the running Write() in [0, 1] (also the ProgressEvent's call data).
  vtkGetMacro(Progress, double);

  /// Reads InputFileName and writes FileName. Returns true on success.
  bool Write();

  /// The reason of the last failure, "" after a success.
  const char* GetLastError() { return this->LastError.c_str(); }

  ///@{
  /// What the last successful Write() wrote: levels (IFDs), and the level-0 size.
  vtkGetMacro(NumberOfLevels, int);
  vtkGetVector2Macro(Size, int);
  ///@}

protected:
  vtkGlobeRasterPreparer();
  ~vtkGlobeRasterPreparer() override;

  char* InputFileName = nullptr;
  char* FileName = nullptr;
  int TileSize = 256;
  int Compression = Deflate;
  bool AbortExecute = false;
  double Progress = 0.0;
  int NumberOfLevels = 0;
  int Size[2] = { 0, 0 };

private:
  vtkGlobeRasterPreparer(const vtkGlobeRasterPreparer&) = delete;
  void operator=(const vtkGlobeRasterPreparer&) = delete;

  bool Fail(const std::string& why);
  void SetProgressValue(double progress);
  std::string LastError;
};

#endif
