/**
 * @class   vtkGlobePageSource
 * @brief   A georeferenced raster as a pyramid of fixed-size pages, read on demand through
 *          OpenImageIO's ImageCache: the CPU side of a virtual texture.
 *
 * Levels: level 0 is the full-resolution raster; level L+1 is max(1, w/2) x max(1, h/2) of
 * level L (OpenImageIO's MIP-size convention), and the last level is the first one that fits
 * in one page (both sizes <= PageSize). Each level spans the whole raster, so its texel size
 * is the raster's extent divided by the level's size. Where the levels come from:
 * - a file written by vtkGlobeRasterPreparer (GlobePrepare): its reduced-resolution IFDs,
 *   which OpenImageIO reads as MIP levels (nodata-aware averages for heights);
 * - a file without levels whose full resolution fits in memory (up to 4096 x 4096 texels):
 *   averaged here, nodata-aware, as below (OpenImageIO's automip would average -32768 voids
 *   into deep pits);
 * - a larger file without levels (tiled or not: OpenImageIO 2.4 applies "automip" to both):
 *   the ImageCache makes them on demand from the level above (OpenImageIO's filter, a box
 *   average for halving; not nodata-aware, so voids bleed into their surroundings: prepare
 *   such files with GlobePrepare);
 * - a file whose own chain stops before a level fits in one page (e.g. a prepared file whose
 *   tiles are larger than PageSize, or other multi-level TIFFs): the missing levels are
 *   averaged here, nodata-aware, from the file's coarsest level, which is read whole once
 *   (allowed up to 4096 x 4096 texels, i.e. at most 64 MiB, kept in memory; a larger coarsest
 *   level is an error that says to prepare the file with GlobePrepare).
 *
 * Pages: level L is cut into pages of PageSize x PageSize payload texels, page (column, row)
 * holding texels [column * PageSize, (column + 1) * PageSize) x [row * PageSize, ...), row 0
 * NORTH. ReadPage gives (PageSize + 2 Border)^2 texels: the payload plus Border texels on each
 * side taken from the neighbouring texels of the same level, so bilinear filtering inside a
 * page with Border >= 1 matches filtering the whole level (seamless across pages). Outside
 * the raster, texels clamp to the edge texel (north and south always; east and west for
 * regional rasters); a global raster (all longitudes, the rule of vtkGlobeLayer::IsGlobal:
 * geographic or cylindrical projected) wraps east-west instead, so the westmost border holds the eastmost
 * texels. Pages at the east or south edge that reach past the raster are filled the same way
 * (clamped, or wrapped for global rasters); GetPageBounds gives their full, nominal extent.
 *
 * Values: 1-channel rasters are heights: a 1-component float array of the native values
 * (integers are converted here, not by OpenImageIO, which would normalise them), nodata and
 * NaN posts become NaN. Others are imagery: 4-component unsigned char RGBA (8-bit conversion by
 * OpenImageIO; grey + alpha is spread to RGB), alpha 255 when the file has none, and 0 where
 * all colour channels equal the nodata value.
 *
 * Georeferencing and nodata come from vtkGlobeRasterReader (its header and one row of field
 * data, read once when the source opens). Files stored south-up or east-to-west (by their
 * GeoTIFF tags or world file) are read flipped, so row 0 is always north.
 *
 * Memory: the ImageCache holds at most CacheMemory MiB of tiles (OpenImageIO's max_memory_MB;
 * it evicts least recently used tiles, and may exceed the limit by the tiles that concurrent
 * reads hold at once); besides it, ReadPage allocates about two pages, and synthesised levels
 * (above) are kept. Each source has its own, private ImageCache, so settings and statistics
 * are per source.
 *
 * Thread safety: ReadPage, GetPageBounds and the getters may be called from several threads at
 * once. The source opens lazily (on the first call after FileName or a setting changed) under
 * a lock and then only reads immutable state; changing a setting while other threads read is
 * not supported. Errors (missing file, no georeferencing, unsupported sample type, level or
 * page out of range, wrong output array type) are reported with vtkErrorMacro naming the file
 * and the reason, and make the call return false; nothing crashes.
 */
#ifndef vtkGlobePageSource_h
#define vtkGlobePageSource_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkDataArray;

class VTKGLOBECORE_EXPORT vtkGlobePageSource : public vtkObject
{
public:
  static vtkGlobePageSource* New();
  vtkTypeMacro(vtkGlobePageSource, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The georeferenced raster (ideally one written by vtkGlobeRasterPreparer).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Payload texels per page side (default 256, 16..2048).
  vtkSetClampMacro(PageSize, int, 16, 2048);
  vtkGetMacro(PageSize, int);
  ///@}

  ///@{
  /// Border texels on each side of a page (default 1, 0..64).
  vtkSetClampMacro(Border, int, 0, 64);
  vtkGetMacro(Border, int);
  ///@}

  ///@{
  /// The ImageCache's memory limit in MiB (default 256; OpenImageIO's max_memory_MB).
  vtkSetClampMacro(CacheMemory, double, 1.0, 1048576.0);
  vtkGetMacro(CacheMemory, double);
  ///@}

  /// Opens the file (done lazily by every other call); false with an error on failure.
  bool Open();

  ///@{
  /// What the opened raster is (0 / false when it cannot be opened).
  /// Columns and rows of level 0.
  int GetNumberOfColumns();
  int GetNumberOfRows();
  /// 1 (heights, float) or 4 (RGBA, unsigned char): the components of a page.
  int GetNumberOfComponents();
  /// VTK_FLOAT or VTK_UNSIGNED_CHAR: the type of the array ReadPage fills.
  int GetPageDataType();
  /// vtkGlobeRasterReader::ModelTypes (1 geographic, 2 projected), and the EPSG code.
  int GetModelType();
  int GetEPSG();
  bool GetHasNoDataValue();
  double GetNoDataValue();
  /// A raster spanning all longitudes (vtkGlobeLayer::IsGlobal's rule): pages wrap east-west.
  bool IsGlobal();
  /// x and y of the north-west outer corner and the pixel size (east, south), as
  /// vtkGlobeRasterReader's GlobeGeoTransform. False when not open.
  bool GetGeoTransform(double transform[4]);
  ///@}

  ///@{
  /// The pyramid: levels, each level's size in texels, and its pages across and down.
  int GetNumberOfLevels();
  bool GetLevelSize(int level, int size[2]);
  bool GetNumberOfPages(int level, int count[2]);
  /// Levels the file provides through the ImageCache (its own or automip); the rest of
  /// GetNumberOfLevels() are averaged in memory here.
  int GetNumberOfFileLevels();
  ///@}

  /// PageSize + 2 * Border: texels per side of what ReadPage gives.
  int GetPageTexels() { return this->PageSize + 2 * this->Border; }

  /**
   * Fills `out` (a vtkFloatArray for heights, a vtkUnsignedCharArray for imagery; see
   * GetPageDataType) with the page's GetPageTexels()^2 tuples, row 0 north, index
   * row * GetPageTexels() + column. Returns false, with an error, for a level or page out of
   * range, a wrong array type, or a read failure. Thread-safe.
   */
  bool ReadPage(int level, int column, int row, vtkDataArray* out);

  /**
   * The page's payload outer edges in map units (degrees for geographic rasters): west, east,
   * south, north. Edge pages extend past the raster (see the class description).
   */
  bool GetPageBounds(int level, int column, int row, double bounds[4]);

  ///@{
  /// Statistics: pages read by ReadPage, the ImageCache's tile memory now
  /// (stat:cache_memory_used), and pixel bytes it read from the file (stat:bytes_read, the
  /// uncompressed size). ResetStatistics() zeroes the page count and the cache's counters.
  vtkTypeInt64 GetNumberOfPagesRead();
  vtkTypeInt64 GetCacheMemoryUsed();
  vtkTypeInt64 GetFileBytesRead();
  void ResetStatistics();
  ///@}

protected:
  vtkGlobePageSource();
  ~vtkGlobePageSource() override;

  char* FileName = nullptr;
  int PageSize = 256;
  int Border = 1;
  double CacheMemory = 256.0;

private:
  vtkGlobePageSource(const vtkGlobePageSource&) = delete;
  void operator=(const vtkGlobePageSource&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
