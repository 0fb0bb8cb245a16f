/**
 * @class   vtkGlobePageCache
 * @brief   The GPU side of streamed layers: a virtual texture per data kind (a page atlas
 *          and per-layer page tables), filled by worker threads within an upload budget.
 *
 * Streamed layers (vtkGlobeLayer::IsStreamed) are pyramids of fixed-size pages
 * (vtkGlobePageSource). This cache holds the pages the frames show:
 * - one page atlas per data kind, a GL_TEXTURE_2D_ARRAY of (PageSize + 2 Border)^2 texels
 *   per slot: R32F for heights, RGBA8 for images; GPUMemory MiB each, fixed when allocated;
 * - one page table per layer (an RGBA32UI texture) with one texel per page of every level,
 *   holding two entries (slot << 6 | level, column | row << 16): the page itself when it is
 *   resident, else its finest resident ancestor, and the same for the page a lookup one level
 *   up finds, so a lookup never misses (the coarsest level, one page, is read synchronously
 *   when the layer is first seen and is never evicted) and trilinear filtering reads one
 *   texel; each level's first row follows from level 0's page rows (GetPyramid). A layer
 *   with more than 65,535 pages along an axis is refused (raise PageSize);
 * - Request() marks a page used by this frame; a page that is not resident is queued for
 *   the worker threads (coarse levels first), which read it with vtkGlobeLayer::ReadPage;
 * - BeginFrame() uploads finished pages through a pixel-buffer object, at most UploadBudget
 *   MiB per frame, into free slots or those of the least recently used pages that the
 *   previous frame did not use; when every slot holds a page in use, a page displaces the
 *   finest page in use that is finer than itself, or else it is dropped
 *   (NumberOfDeferredPages; the frame keeps its coarser ancestor and asks again when a slot
 *   frees up): the cache keeps the coarse levels every finer page falls back to. A
 *   frame never waits for disk unless it asks to (BeginFrame's wait, vtkGlobeMapper's
 *   WaitForPages).
 *
 * The feedback that decides which pages a frame needs comes from vtkGlobeLayerSet
 * (RequestPages); the GLSL that reads the tables is vtkGlobeLayerSet's as well.
 * Documentation/streaming.md has the design and the measurements.
 */
#ifndef vtkGlobePageCache_h
#define vtkGlobePageCache_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkGlobeLayer;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKGLOBERENDERING_EXPORT vtkGlobePageCache : public vtkObject
{
public:
  static vtkGlobePageCache* New();
  vtkTypeMacro(vtkGlobePageCache, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Data kinds: each has its own atlas.
  enum Kinds
  {
    Heights = 0,
    Images = 1
  };

  ///@{
  /// Payload texels on a page side (default 256); a change empties the cache.
  vtkSetClampMacro(PageSize, int, 16, 1024);
  vtkGetMacro(PageSize, int);
  ///@}

  /// Texels each page repeats from its neighbours on every side (for seamless filtering).
  static constexpr int Border = 2;

  ///@{
  /// GPU memory of each atlas in MiB (default 120: both atlases and the page tables of a few
  /// global layers stay under 256 MB); a change empties the cache.
  vtkSetClampMacro(GPUMemory, double, 0.01, 65536.0);
  vtkGetMacro(GPUMemory, double);
  ///@}

  ///@{
  /// CPU cache of each streamed layer in MiB (its vtkGlobePageSource's CacheMemory,
  /// default 256), set when the layer is first seen.
  vtkSetClampMacro(CPUMemory, double, 1.0, 1048576.0);
  vtkGetMacro(CPUMemory, double);
  ///@}

  ///@{
  /// Bytes uploaded per frame at most, in MiB (default 16); 0 means no limit.
  vtkSetClampMacro(UploadBudget, double, 0.0, 65536.0);
  vtkGetMacro(UploadBudget, double);
  ///@}

  ///@{
  /// Worker threads that read pages (default 2).
  vtkSetClampMacro(NumberOfThreads, int, 1, 64);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /**
   * Starts a frame: registers the streamed layers it composes (AddFrameLayer before), drops
   * the pages of layers no longer composed or reloaded since, reads the coarsest page of new
   * layers, uploads finished pages within the budget and rebuilds the page tables that
   * changed. Needs a current context. With wait, first waits for every queued read and
   * uploads everything (no budget): vtkGlobeMapper's complete mode.
   */
  void BeginFrame(vtkOpenGLRenderWindow* window, bool wait = false);
  /// Lists a streamed layer for the next BeginFrame (call once per layer and frame).
  void AddFrameLayer(vtkGlobeLayer* layer);

  /**
   * Gives a layer's page source this cache's page size, border and CPU memory, before the
   * layer's Update() (vtkGlobeLayerSet does), so a streamed layer opens its file once. When
   * they differ, the reading threads end first: a page source is reconfigured only when no
   * thread reads it (so are reloading layers: the cache observes their StartEvent).
   */
  void ConfigureSource(vtkGlobeLayer* layer);

  /// The frame uses page (level, column, row) of a layer (after BeginFrame).
  void Request(vtkGlobeLayer* layer, int level, int column, int row);

  /// Requests that found their page resident (counted once per page and frame).
  vtkGetMacro(NumberOfHits, long long);

  /// True when no read is queued or running and no finished page waits for upload.
  bool IsIdle();

  ///@{
  /// For binding: a kind's atlas and a layer's page table (nullptr when absent), and the
  /// number of levels of a layer's pyramid.
  vtkTextureObject* GetAtlas(int kind);
  vtkTextureObject* GetTable(vtkGlobeLayer* layer);
  int GetNumberOfLevels(vtkGlobeLayer* layer);
  ///@}

  /**
   * What the shader needs besides a layer's table: level 0's size in texels, the number of
   * levels and level 0's page rows (level l's table rows start at
   * 2 l + floor(2 rows0 (1 - 2^-l))). False (zeros) for a layer the cache does not hold.
   */
  bool GetPyramid(vtkGlobeLayer* layer, double pyramid[4]);

  ///@{
  /// Statistics (cumulative unless said otherwise; ResetStatistics() zeroes them).
  /// Pages resident now (all kinds), slots of a kind's atlas.
  int GetNumberOfResidentPages();
  int GetNumberOfSlots(int kind);
  /// Pages queued for reading; read and uploaded; evicted to make room.
  vtkGetMacro(NumberOfRequestedPages, long long);
  vtkGetMacro(NumberOfLoadedPages, long long);
  vtkGetMacro(NumberOfEvictedPages, long long);
  /// Requests that found their page not resident (once per page and frame).
  vtkGetMacro(NumberOfMisses, long long);
  /// Finished pages that found every slot in use by the frame (they wait).
  vtkGetMacro(NumberOfDeferredPages, long long);
  /// Bytes uploaded by the last BeginFrame, and in total.
  vtkGetMacro(BytesUploadedLastFrame, long long);
  vtkGetMacro(BytesUploaded, long long);
  /// GPU memory held: atlases and page tables, in bytes.
  size_t GetGPUMemoryUsed();
  /// Bytes the layers' CPU caches (OpenImageIO) hold now.
  long long GetCPUMemoryUsed();
  void ResetStatistics();
  ///@}

  /// Empties the cache (keeps the settings); the next frame starts from the coarsest pages.
  void Flush();

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkGlobePageCache();
  ~vtkGlobePageCache() override;

  int PageSize = 256;
  double GPUMemory = 120.0;
  double CPUMemory = 256.0;
  double UploadBudget = 16.0;
  int NumberOfThreads = 2;

  long long NumberOfRequestedPages = 0;
  long long NumberOfLoadedPages = 0;
  long long NumberOfEvictedPages = 0;
  long long NumberOfMisses = 0;
  long long NumberOfHits = 0;
  long long NumberOfDeferredPages = 0;
  long long BytesUploadedLastFrame = 0;
  long long BytesUploaded = 0;

private:
  vtkGlobePageCache(const vtkGlobePageCache&) = delete;
  void operator=(const vtkGlobePageCache&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
