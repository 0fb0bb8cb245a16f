#include "vtkGlobePageCache.h"

#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobePageSource.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtkCallbackCommand.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <vector>

vtkStandardNewMacro(vtkGlobePageCache);

namespace
{
using PageKey = unsigned long long;
PageKey MakeKey(int level, int column, int row)
{
  return (static_cast<PageKey>(level) << 48) | (static_cast<PageKey>(column) << 24) |
    static_cast<PageKey>(row);
}
int KeyLevel(PageKey k)
{
  return static_cast<int>(k >> 48);
}
int KeyColumn(PageKey k)
{
  return static_cast<int>((k >> 24) & 0xFFFFFF);
}
int KeyRow(PageKey k)
{
  return static_cast<int>(k & 0xFFFFFF);
}

// The first page-table row of a level, from level 0's page rows alone, so the shader computes
// it (globe_pageCoord) instead of reading it: level l's region is at least
// floor(rows0 / 2^l) + 2 rows high, which holds its pages whatever its size rounding
// (ceil(rows0 / 2^l) at most). Exact in float as in double (small integers, powers of two).
int FirstTableRow(int level, int rows0)
{
  return 2 * level + static_cast<int>(std::floor(2.0 * rows0 * (1.0 - std::ldexp(1.0, -level))));
}

// A page read by a worker, waiting for its upload.
struct Finished
{
  int LayerId = 0;
  PageKey Key = 0;
  vtkSmartPointer<vtkDataArray> Data;
  bool Ok = false;
};

struct Job
{
  int LayerId = 0;
  PageKey Key = 0;
  vtkSmartPointer<vtkGlobeLayer> Layer;
  bool Heights = true;
};

struct Slot
{
  int LayerId = -1; // -1: free
  PageKey Key = 0;
  long long LastUsed = -1;
  bool Pinned = false;
};

struct Atlas
{
  unsigned int Handle = 0;
  vtkSmartPointer<vtkTextureObject> Texture; // wraps Handle for binding
  unsigned int PixelBuffer = 0;
  int Texels = 0;
  std::vector<Slot> Slots;
  std::vector<int> Free;
};

// An observer on a layer, removed with its owner (move-only).
struct LayerObserver
{
  vtkWeakPointer<vtkObject> Object;
  unsigned long Tag = 0;
  LayerObserver() = default;
  LayerObserver(vtkObject* object, unsigned long event, vtkCommand* command)
    : Object(object)
    , Tag(object->AddObserver(event, command))
  {
  }
  LayerObserver(LayerObserver&& o) noexcept
    : Object(o.Object)
    , Tag(o.Tag)
  {
    o.Object = nullptr;
  }
  LayerObserver& operator=(LayerObserver&& o) noexcept
  {
    std::swap(this->Object, o.Object);
    std::swap(this->Tag, o.Tag);
    return *this;
  }
  ~LayerObserver()
  {
    if (this->Object)
    {
      this->Object->RemoveObserver(this->Tag);
    }
  }
};

struct LayerState
{
  int Id = 0;
  vtkSmartPointer<vtkGlobeLayer> Layer;
  int Loads = 0;
  int Kind = 0;
  int Levels = 0;
  // Width, Height: texels per unit of the layer's texture coordinates at each level, level 0's
  // size / 2^level (a texel of level l averages 2^l x 2^l texels of level 0, also where a
  // size is odd and the level drops the last one: registered, not stretched).
  std::vector<double> Width, Height;
  std::vector<int> Columns, Rows, FirstRow;
  int TableWidth = 0, TableHeight = 0;
  vtkSmartPointer<vtkTextureObject> Table;
  bool TableDirty = true;
  std::unordered_map<PageKey, int> Resident; // page -> slot
  LayerObserver Observer; // the layer's StartEvent: the readers let go before it reloads
  bool Listed = false; // composed by the coming frame
};

} // namespace

class vtkGlobePageCache::vtkInternals
{
public:
  // Main thread only.
  std::map<vtkGlobeLayer*, LayerState> Layers;
  // Layers whose pyramid or coarsest page could not be read or placed, by their load count:
  // not tried again every frame (each try would read the file and restart the readers),
  // only after they reload, the cache is reconfigured or a registered layer frees its slots.
  std::map<vtkGlobeLayer*, std::pair<vtkWeakPointer<vtkGlobeLayer>, int>> Refused;
  std::vector<vtkGlobeLayer*> FrameLayers;
  Atlas Atlases[2];
  std::unordered_set<PageKey> InFlight[2]; // per kind: (layer id, page) hashed below
  std::deque<Finished> Waiting;            // read, not uploaded yet
  std::unordered_set<unsigned long long> TouchedThisFrame;
  // Pages dropped for want of a free slot: not asked for again until a slot frees up, so a
  // view that needs more pages than the cache holds settles on what fits.
  std::unordered_set<unsigned long long> Deferred;
  bool Retrying = false; // deferred pages were released this frame: the next asks for them
  long long Frame = 0;
  int NextId = 1;
  int AllocatedPageSize = 0;
  double AllocatedMemory = 0.0;

  // Shared with the workers.
  std::mutex Mutex;
  std::condition_variable Wake;
  std::condition_variable Done;
  std::deque<Job> Queue;
  std::vector<Finished> Results;
  int Running = 0;
  bool Stop = false;
  std::vector<std::thread> Workers;

  static unsigned long long Tag(int layerId, PageKey key)
  {
    // Levels < 64, columns and rows < 2^24: 54 bits; the layer id above them.
    return (static_cast<unsigned long long>(layerId) << 54) ^ key;
  }

  LayerState* Find(vtkGlobeLayer* layer)
  {
    auto it = this->Layers.find(layer);
    return it == this->Layers.end() ? nullptr : &it->second;
  }

  bool IsRefused(vtkGlobeLayer* layer)
  {
    auto it = this->Refused.find(layer);
    return it != this->Refused.end() && it->second.first.GetPointer() == layer &&
      it->second.second == layer->GetNumberOfLoads();
  }

  void Refuse(vtkGlobeLayer* layer)
  {
    this->Refused[layer] = { layer, layer->GetNumberOfLoads() };
  }

  LayerState* FindId(int id)
  {
    for (auto& kv : this->Layers)
    {
      if (kv.second.Id == id)
      {
        return &kv.second;
      }
    }
    return nullptr;
  }

  void Work()
  {
    for (;;)
    {
      Job job;
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        this->Wake.wait(lock, [this] { return this->Stop || !this->Queue.empty(); });
        if (this->Stop)
        {
          return;
        }
        // Coarse levels first: they cover the most screen and refine what the finer wait for.
        auto best = std::max_element(this->Queue.begin(), this->Queue.end(),
          [](const Job& a, const Job& b) { return KeyLevel(a.Key) < KeyLevel(b.Key); });
        job = *best;
        this->Queue.erase(best);
        ++this->Running;
      }
      Finished f;
      f.LayerId = job.LayerId;
      f.Key = job.Key;
      if (job.Heights)
      {
        f.Data = vtkSmartPointer<vtkFloatArray>::New();
      }
      else
      {
        f.Data = vtkSmartPointer<vtkUnsignedCharArray>::New();
      }
      f.Ok =
        job.Layer->ReadStoredPage(KeyLevel(job.Key), KeyColumn(job.Key), KeyRow(job.Key), f.Data);
      {
        std::lock_guard<std::mutex> lock(this->Mutex);
        this->Results.push_back(std::move(f));
        --this->Running;
      }
      this->Done.notify_all();
    }
  }

  void StartWorkers(int count)
  {
    if (!this->Workers.empty())
    {
      return;
    }
    this->Stop = false;
    for (int i = 0; i < count; ++i)
    {
      this->Workers.emplace_back([this] { this->Work(); });
    }
  }

  void StopWorkers()
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Stop = true;
      this->Queue.clear();
    }
    this->Wake.notify_all();
    for (auto& t : this->Workers)
    {
      t.join();
    }
    this->Workers.clear();
    this->Results.clear();
  }

  // Ends the reading threads (they start again at the next frame): a page source is
  // reconfigured or reloaded only when no thread reads it. OpenImageIO keeps per-thread
  // records in each ImageCache a thread used; a cache rebuilt under live threads crashed a
  // reader (the soak program). The cancelled reads are asked for again.
  void LetGo()
  {
    this->StopWorkers();
    for (auto& f : this->InFlight)
    {
      f.clear();
    }
  }

  // Observer of the layers' StartEvent.
  vtkNew<vtkCallbackCommand> ReloadObserver;

  // Cancels queued reads and waits for the running ones (before settings change).
  void Drain()
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Queue.clear();
    this->Done.wait(lock, [this] { return this->Running == 0; });
    this->Results.clear();
  }
};

//------------------------------------------------------------------------------
vtkGlobePageCache::vtkGlobePageCache()
  : Internals(new vtkInternals)
{
  this->Internals->ReloadObserver->SetClientData(this->Internals.get());
  this->Internals->ReloadObserver->SetCallback([](vtkObject*, unsigned long, void* in, void*) {
    static_cast<vtkInternals*>(in)->LetGo();
  });
}

void vtkGlobePageCache::ConfigureSource(vtkGlobeLayer* layer)
{
  vtkGlobePageSource* pages = layer ? layer->GetPageSource() : nullptr;
  if (!pages ||
    (pages->GetPageSize() == this->PageSize && pages->GetBorder() == Border &&
      pages->GetCacheMemory() == this->CPUMemory))
  {
    return;
  }
  this->Internals->LetGo();
  pages->SetPageSize(this->PageSize);
  pages->SetBorder(Border);
  pages->SetCacheMemory(this->CPUMemory);
}

vtkGlobePageCache::~vtkGlobePageCache()
{
  this->Internals->StopWorkers();
}

void vtkGlobePageCache::AddFrameLayer(vtkGlobeLayer* layer)
{
  if (layer && layer->IsStreamed())
  {
    this->Internals->FrameLayers.push_back(layer);
  }
}

void vtkGlobePageCache::Flush()
{
  auto& in = *this->Internals;
  in.Drain();
  in.Waiting.clear();
  in.Deferred.clear();
  for (auto& kv : in.Layers)
  {
    kv.second.Resident.clear();
  }
  in.Layers.clear();
  in.Refused.clear();
  for (auto& a : in.Atlases)
  {
    for (size_t i = 0; i < a.Slots.size(); ++i)
    {
      a.Slots[i] = Slot();
    }
    a.Free.clear();
    for (int i = static_cast<int>(a.Slots.size()) - 1; i >= 0; --i)
    {
      a.Free.push_back(i);
    }
  }
  for (auto& f : in.InFlight)
  {
    f.clear();
  }
}

//------------------------------------------------------------------------------
void vtkGlobePageCache::BeginFrame(vtkOpenGLRenderWindow* window, bool wait)
{
  auto& in = *this->Internals;
  ++in.Frame;
  in.TouchedThisFrame.clear();
  this->BytesUploadedLastFrame = 0;

  // The worker threads end before a page source they read is reconfigured or may be
  // destroyed (a layer added, dropped or reloaded, the page size or memory changed):
  // OpenImageIO keeps per-thread records in each ImageCache a thread used, and a cache
  // rebuilt or destroyed under live threads that used it crashed the soak program (in
  // ImageCacheFile::get_imageinput, and in ~ImageCacheTile at exit). Such changes are rare;
  // new threads start at once.
  // A refused layer has no reads in flight: it neither joins nor leaves the readers' work.
  bool same = in.AllocatedPageSize == this->PageSize && in.AllocatedMemory == this->GPUMemory;
  size_t registered = 0;
  for (vtkGlobeLayer* layer : in.FrameLayers)
  {
    if (LayerState* s = in.Find(layer))
    {
      same = same && s->Loads == layer->GetNumberOfLoads();
      ++registered;
    }
    else
    {
      same = same && in.IsRefused(layer);
    }
  }
  same = same && registered == in.Layers.size();
  if (!same)
  {
    in.LetGo();
  }
  in.StartWorkers(this->NumberOfThreads);

  const int texels = this->PageSize + 2 * Border;
  if (in.AllocatedPageSize != this->PageSize || in.AllocatedMemory != this->GPUMemory)
  {
    this->Flush();
    this->ReleaseGraphicsResources(window);
    in.AllocatedPageSize = this->PageSize;
    in.AllocatedMemory = this->GPUMemory;
  }

  // Layers: drop those no longer composed or reloaded since (their slots become free).
  std::vector<vtkGlobeLayer*> listed;
  listed.swap(in.FrameLayers);
  for (auto& kv : in.Layers)
  {
    kv.second.Listed = false;
  }
  for (vtkGlobeLayer* layer : listed)
  {
    LayerState* s = in.Find(layer);
    if (s && s->Loads == layer->GetNumberOfLoads())
    {
      s->Listed = true;
    }
  }
  for (auto it = in.Layers.begin(); it != in.Layers.end();)
  {
    if (it->second.Listed)
    {
      ++it;
      continue;
    }
    Atlas& atlas = in.Atlases[it->second.Kind];
    for (auto& page : it->second.Resident)
    {
      atlas.Slots[page.second] = Slot();
      atlas.Free.push_back(page.second);
    }
    if (it->second.Table)
    {
      it->second.Table->ReleaseGraphicsResources(window);
    }
    it = in.Layers.erase(it);
    in.Refused.clear(); // its pinned slot may take a refused layer's coarsest page
  }
  for (auto it = in.Refused.begin(); it != in.Refused.end();)
  {
    it = it->second.first ? std::next(it) : in.Refused.erase(it);
  }

  // Atlases: allocated at first use, GPUMemory each, no more layers than GL allows.
  for (int kind = 0; kind < 2; ++kind)
  {
    Atlas& a = in.Atlases[kind];
    if (a.Handle || listed.empty())
    {
      continue;
    }
    bool used = false;
    for (vtkGlobeLayer* layer : listed)
    {
      used |= (layer->GetRole() == vtkGlobeLayer::Height) == (kind == Heights);
    }
    if (!used)
    {
      continue;
    }
    const double pageBytes = static_cast<double>(texels) * texels * 4.0;
    GLint maxLayers = 256;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    const int slots = std::max(2,
      std::min(static_cast<int>(this->GPUMemory * 1048576.0 / pageBytes), static_cast<int>(maxLayers)));
    a.Texels = texels;
    glGenTextures(1, &a.Handle);
    a.Texture = vtkSmartPointer<vtkTextureObject>::New();
    a.Texture->SetContext(window);
    a.Texture->AssignToExistingTexture(a.Handle, GL_TEXTURE_2D_ARRAY);
    a.Texture->SetMinificationFilter(vtkTextureObject::Linear);
    a.Texture->SetMagnificationFilter(vtkTextureObject::Linear);
    a.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    a.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    a.Texture->Activate();
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, kind == Heights ? GL_R32F : GL_RGBA8, texels, texels, slots);
    a.Texture->Deactivate();
    a.Slots.assign(slots, Slot());
    a.Free.clear();
    for (int i = slots - 1; i >= 0; --i)
    {
      a.Free.push_back(i);
    }
    glGenBuffers(1, &a.PixelBuffer);
  }

  auto upload = [&](LayerState& s, PageKey key, vtkDataArray* data, bool pinned) -> bool {
    Atlas& a = in.Atlases[s.Kind];
    if (!a.Handle)
    {
      return false;
    }
    int slot = -1;
    if (!a.Free.empty())
    {
      slot = a.Free.back();
      a.Free.pop_back();
    }
    else
    {
      // The least recently used page that the last frame did not use.
      long long oldest = in.Frame - 1;
      for (size_t i = 0; i < a.Slots.size(); ++i)
      {
        if (!a.Slots[i].Pinned && a.Slots[i].LastUsed < oldest)
        {
          oldest = a.Slots[i].LastUsed;
          slot = static_cast<int>(i);
        }
      }
      if (slot < 0)
      {
        // Every slot is in use: a coarser page still displaces the finest one in use, so the
        // levels that stay resident are the coarse ones every finer page falls back to.
        int finest = KeyLevel(key);
        for (size_t i = 0; i < a.Slots.size(); ++i)
        {
          const int level = KeyLevel(a.Slots[i].Key);
          if (!a.Slots[i].Pinned && a.Slots[i].LayerId >= 0 && level < finest)
          {
            finest = level;
            slot = static_cast<int>(i);
          }
        }
      }
      if (slot < 0)
      {
        return false;
      }
      LayerState* owner = in.FindId(a.Slots[slot].LayerId);
      if (owner)
      {
        owner->Resident.erase(a.Slots[slot].Key);
        owner->TableDirty = true;
      }
      ++this->NumberOfEvictedPages;
    }
    const size_t bytes = static_cast<size_t>(a.Texels) * a.Texels * 4;
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, a.PixelBuffer);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_DRAW);
    if (void* dst = glMapBufferRange(GL_PIXEL_UNPACK_BUFFER, 0, static_cast<GLsizeiptr>(bytes),
          GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT))
    {
      std::memcpy(dst, data->GetVoidPointer(0), bytes);
      glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
      a.Texture->Activate();
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, slot, a.Texels, a.Texels, 1,
        s.Kind == Heights ? GL_RED : GL_RGBA, s.Kind == Heights ? GL_FLOAT : GL_UNSIGNED_BYTE,
        nullptr);
      a.Texture->Deactivate();
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    a.Slots[slot].LayerId = s.Id;
    a.Slots[slot].Key = key;
    a.Slots[slot].LastUsed = in.Frame;
    a.Slots[slot].Pinned = pinned;
    s.Resident[key] = slot;
    s.TableDirty = true;
    ++this->NumberOfLoadedPages;
    this->BytesUploadedLastFrame += static_cast<long long>(bytes);
    this->BytesUploaded += static_cast<long long>(bytes);
    return true;
  };
  // New layers: their pyramid, and the coarsest page read now (a frame never shows an
  // undefined texel).
  for (vtkGlobeLayer* layer : listed)
  {
    if (in.Find(layer) || in.IsRefused(layer))
    {
      continue;
    }
    this->ConfigureSource(layer); // done before the layer's Update() already, normally
    vtkGlobePageSource* pages = layer->GetPageSource();
    LayerState s;
    s.Id = in.NextId++;
    s.Layer = layer;
    s.Loads = layer->GetNumberOfLoads();
    s.Kind = layer->GetRole() == vtkGlobeLayer::Height ? Heights : Images;
    s.Levels = pages->GetNumberOfLevels();
    if (s.Levels <= 0 || s.Levels > 63)
    {
      in.Refuse(layer); // the page source reported why
      continue;
    }
    int size0[2];
    pages->GetLevelSize(0, size0);
    for (int l = 0; l < s.Levels; ++l)
    {
      int count[2];
      pages->GetNumberOfPages(l, count);
      s.Width.push_back(std::ldexp(static_cast<double>(size0[0]), -l));
      s.Height.push_back(std::ldexp(static_cast<double>(size0[1]), -l));
      s.Columns.push_back(count[0]);
      s.Rows.push_back(count[1]);
    }
    for (int l = 0; l <= s.Levels; ++l)
    {
      s.FirstRow.push_back(FirstTableRow(l, s.Rows[0]));
    }
    s.TableWidth = s.Columns[0];
    s.TableHeight = s.FirstRow[s.Levels];
    if (s.Columns[0] > 65535 || s.Rows[0] > 65535)
    {
      // A table entry packs a page's column and row in 16 bits each.
      vtkErrorMacro(<< "Layer '" << layer->GetName() << "' has " << s.Columns[0] << " x "
                    << s.Rows[0] << " pages of " << this->PageSize
                    << " texels at level 0, more than 65535 along an axis; raise PageSize. "
                       "The layer is skipped");
      in.Refuse(layer);
      continue;
    }
    vtkSmartPointer<vtkDataArray> coarsest;
    if (s.Kind == Heights)
    {
      coarsest = vtkSmartPointer<vtkFloatArray>::New();
    }
    else
    {
      coarsest = vtkSmartPointer<vtkUnsignedCharArray>::New();
    }
    if (!layer->ReadStoredPage(s.Levels - 1, 0, 0, coarsest))
    {
      in.Refuse(layer); // the layer reported why
      continue;
    }
    LayerState& stored = in.Layers[layer] = std::move(s);
    stored.Listed = true;
    stored.Observer = LayerObserver(layer, vtkCommand::StartEvent, in.ReloadObserver);
    if (!upload(stored, MakeKey(stored.Levels - 1, 0, 0), coarsest, true))
    {
      vtkErrorMacro(<< "The GPU page cache has no room for the coarsest page of layer '"
                    << layer->GetName() << "' (" << this->GetNumberOfSlots(stored.Kind)
                    << " slots, all pinned); raise GPUMemory. The layer is skipped");
      in.Layers.erase(layer);
      in.Refuse(layer);
      continue;
    }
  }

  // A slot that the last frame did not use frees the deferred pages to be asked for again.
  in.Retrying = false;
  for (const Atlas& a : in.Atlases)
  {
    bool room = !a.Free.empty();
    for (size_t i = 0; i < a.Slots.size() && !room; ++i)
    {
      room = !a.Slots[i].Pinned && a.Slots[i].LastUsed < in.Frame - 1;
    }
    if (room)
    {
      in.Retrying = !in.Deferred.empty();
      in.Deferred.clear();
      break;
    }
  }

  // Finished reads: waited for in complete mode; uploaded within the budget.
  if (wait)
  {
    std::unique_lock<std::mutex> lock(in.Mutex);
    in.Done.wait(lock, [&in] { return in.Queue.empty() && in.Running == 0; });
  }
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    for (auto& f : in.Results)
    {
      in.Waiting.push_back(std::move(f));
    }
    in.Results.clear();
  }
  // Coarse pages first: each is the fallback of four finer ones, so when the slots run out the
  // frame still shows a level within one of what it asked for.
  std::stable_sort(in.Waiting.begin(), in.Waiting.end(),
    [](const Finished& a, const Finished& b) { return KeyLevel(a.Key) > KeyLevel(b.Key); });
  const double budget = wait || this->UploadBudget <= 0.0 ? 1e300 : this->UploadBudget * 1048576.0;
  while (!in.Waiting.empty() && this->BytesUploadedLastFrame < budget)
  {
    Finished f = std::move(in.Waiting.front());
    in.Waiting.pop_front();
    LayerState* s = in.FindId(f.LayerId);
    if (!s)
    {
      continue; // its layer went away or reloaded
    }
    in.InFlight[s->Kind].erase(vtkInternals::Tag(f.LayerId, f.Key));
    if (!f.Ok || s->Resident.count(f.Key))
    {
      continue;
    }
    if (!upload(*s, f.Key, f.Data, false))
    {
      // Every slot holds a page the last frame used: the frame keeps the ancestor.
      ++this->NumberOfDeferredPages;
      in.Deferred.insert(vtkInternals::Tag(f.LayerId, f.Key));
    }
  }

  // Page tables of layers whose residency changed.
  const int P = this->PageSize;
  for (auto& kv : in.Layers)
  {
    LayerState& s = kv.second;
    if (!s.TableDirty && s.Table && s.Table->GetContext() == window)
    {
      continue;
    }
    // Each entry first resolves its own page: (slot, level, column, row) of the page when
    // resident, else of its finest resident ancestor.
    std::vector<std::array<unsigned, 2>> found(static_cast<size_t>(s.TableWidth) * s.TableHeight);
    auto at = [&s](int l, int c, int r) {
      return static_cast<size_t>(s.FirstRow[l] + r) * s.TableWidth + c;
    };
    // Coarse to fine: a page that is not resident takes the entry of the page one level up
    // that holds its centre. A level's rows and columns beyond its pages repeat its last
    // ones, so the shader clamps to the region, not to the level's own page counts.
    for (int l = s.Levels - 1; l >= 0; --l)
    {
      for (int r = 0; r < s.FirstRow[l + 1] - s.FirstRow[l]; ++r)
      {
        for (int c = 0; c < s.TableWidth; ++c)
        {
          std::array<unsigned, 2>& t = found[at(l, c, r)];
          if (r >= s.Rows[l] || c >= s.Columns[l])
          {
            t = found[at(l, std::min(c, s.Columns[l] - 1), std::min(r, s.Rows[l] - 1))];
            continue;
          }
          auto it = s.Resident.find(MakeKey(l, c, r));
          if (it != s.Resident.end())
          {
            t = { static_cast<unsigned>(it->second) << 6 | static_cast<unsigned>(l),
              static_cast<unsigned>(c) | static_cast<unsigned>(r) << 16 };
            continue;
          }
          if (l + 1 >= s.Levels)
          {
            continue; // unreachable: the coarsest page is pinned
          }
          const double u = std::min((c + 0.5) * P / s.Width[l], 1.0 - 1e-9);
          const double v = std::min((r + 0.5) * P / s.Height[l], 1.0 - 1e-9);
          const int pc = std::min(static_cast<int>(u * s.Width[l + 1] / P), s.Columns[l + 1] - 1);
          const int pr = std::min(static_cast<int>(v * s.Height[l + 1] / P), s.Rows[l + 1] - 1);
          t = found[at(l + 1, pc, pr)];
        }
      }
    }
    // Then the texel carries its page and the page the same lookup finds one level up (the
    // region's cell of its halved column and row: what the shader's lookup at level + 1
    // reads), so trilinear filtering needs one table read, not two.
    std::vector<unsigned> table(4 * found.size());
    for (int l = 0; l < s.Levels; ++l)
    {
      const int up = std::min(l + 1, s.Levels - 1);
      for (int r = 0; r < s.FirstRow[l + 1] - s.FirstRow[l]; ++r)
      {
        for (int c = 0; c < s.TableWidth; ++c)
        {
          const size_t i = at(l, c, r);
          const auto& parent = up == l ? found[i]
                                       : found[at(up, c / 2,
                                           std::min(r / 2, s.FirstRow[up + 1] - s.FirstRow[up] - 1))];
          std::copy(found[i].begin(), found[i].end(), &table[4 * i]);
          std::copy(parent.begin(), parent.end(), &table[4 * i + 2]);
        }
      }
    }
    if (!s.Table)
    {
      s.Table = vtkSmartPointer<vtkTextureObject>::New();
    }
    s.Table->SetContext(window);
    s.Table->SetMinificationFilter(vtkTextureObject::Nearest);
    s.Table->SetMagnificationFilter(vtkTextureObject::Nearest);
    s.Table->SetWrapS(vtkTextureObject::ClampToEdge);
    s.Table->SetWrapT(vtkTextureObject::ClampToEdge);
    s.Table->SetInternalFormat(GL_RGBA32UI);
    s.Table->SetFormat(GL_RGBA_INTEGER);
    s.Table->SetDataType(GL_UNSIGNED_INT);
    s.Table->Create2DFromRaw(s.TableWidth, s.TableHeight, 4, VTK_UNSIGNED_INT, table.data());
    s.TableDirty = false;
  }
}

//------------------------------------------------------------------------------
void vtkGlobePageCache::Request(vtkGlobeLayer* layer, int level, int column, int row)
{
  auto& in = *this->Internals;
  LayerState* s = in.Find(layer);
  // Until the next BeginFrame applies a new page size, the pyramids described here are the
  // old ones: asking for their pages would read levels the page sources no longer have.
  if (!s || in.AllocatedPageSize != this->PageSize || level < 0 || level >= s->Levels ||
    column < 0 || column >= s->Columns[level] || row < 0 || row >= s->Rows[level])
  {
    return;
  }
  const PageKey key = MakeKey(level, column, row);
  const unsigned long long tag = vtkInternals::Tag(s->Id, key);
  if (!in.TouchedThisFrame.insert(tag).second)
  {
    return; // counted already this frame
  }
  auto it = s->Resident.find(key);
  if (it != s->Resident.end())
  {
    in.Atlases[s->Kind].Slots[it->second].LastUsed = in.Frame;
    ++this->NumberOfHits;
    return;
  }
  ++this->NumberOfMisses;
  if (in.Deferred.count(tag) || !in.InFlight[s->Kind].insert(tag).second)
  {
    return;
  }
  ++this->NumberOfRequestedPages;
  {
    std::lock_guard<std::mutex> lock(in.Mutex);
    in.Queue.push_back(Job{ s->Id, key, s->Layer, s->Kind == Heights });
  }
  in.Wake.notify_one();
}

bool vtkGlobePageCache::IsIdle()
{
  auto& in = *this->Internals;
  std::lock_guard<std::mutex> lock(in.Mutex);
  return in.Queue.empty() && in.Running == 0 && in.Results.empty() && in.Waiting.empty() &&
    !in.Retrying;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkGlobePageCache::GetAtlas(int kind)
{
  return kind == Heights || kind == Images ? this->Internals->Atlases[kind].Texture.Get() : nullptr;
}

vtkTextureObject* vtkGlobePageCache::GetTable(vtkGlobeLayer* layer)
{
  LayerState* s = this->Internals->Find(layer);
  return s ? s->Table.Get() : nullptr;
}

int vtkGlobePageCache::GetNumberOfLevels(vtkGlobeLayer* layer)
{
  LayerState* s = this->Internals->Find(layer);
  return s ? s->Levels : 0;
}

bool vtkGlobePageCache::GetPyramid(vtkGlobeLayer* layer, double pyramid[4])
{
  LayerState* s = this->Internals->Find(layer);
  pyramid[0] = s ? s->Width[0] : 0.0;
  pyramid[1] = s ? s->Height[0] : 0.0;
  pyramid[2] = s ? s->Levels : 0.0;
  pyramid[3] = s ? s->Rows[0] : 0.0;
  return s != nullptr;
}

int vtkGlobePageCache::GetNumberOfResidentPages()
{
  int n = 0;
  for (auto& kv : this->Internals->Layers)
  {
    n += static_cast<int>(kv.second.Resident.size());
  }
  return n;
}

int vtkGlobePageCache::GetNumberOfSlots(int kind)
{
  return kind == Heights || kind == Images
    ? static_cast<int>(this->Internals->Atlases[kind].Slots.size())
    : 0;
}

size_t vtkGlobePageCache::GetGPUMemoryUsed()
{
  size_t bytes = 0;
  for (auto& a : this->Internals->Atlases)
  {
    bytes += a.Slots.size() * static_cast<size_t>(a.Texels) * a.Texels * 4;
  }
  for (auto& kv : this->Internals->Layers)
  {
    bytes += static_cast<size_t>(kv.second.TableWidth) * kv.second.TableHeight * 16;
  }
  return bytes;
}

long long vtkGlobePageCache::GetCPUMemoryUsed()
{
  long long bytes = 0;
  for (auto& kv : this->Internals->Layers)
  {
    bytes += kv.second.Layer->GetPageSource()->GetCacheMemoryUsed();
  }
  return bytes;
}

void vtkGlobePageCache::ResetStatistics()
{
  this->NumberOfRequestedPages = this->NumberOfLoadedPages = this->NumberOfEvictedPages = 0;
  this->NumberOfMisses = this->NumberOfHits = this->NumberOfDeferredPages = 0;
  this->BytesUploadedLastFrame = this->BytesUploaded = 0;
}

void vtkGlobePageCache::ReleaseGraphicsResources(vtkWindow* window)
{
  auto& in = *this->Internals;
  // The tables and slots describe GPU state: they go with it.
  in.Drain();
  in.Waiting.clear();
  for (auto& f : in.InFlight)
  {
    f.clear();
  }
  for (auto& kv : in.Layers)
  {
    if (kv.second.Table)
    {
      kv.second.Table->ReleaseGraphicsResources(window);
    }
  }
  in.Layers.clear();
  in.Refused.clear();
  for (auto& a : in.Atlases)
  {
    if (a.Handle)
    {
      a.Texture->ReleaseGraphicsResources(window);
      glDeleteTextures(1, &a.Handle);
      glDeleteBuffers(1, &a.PixelBuffer);
    }
    a = Atlas();
  }
}

//------------------------------------------------------------------------------
void vtkGlobePageCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PageSize: " << this->PageSize << " (+" << Border << " border)\n";
  os << indent << "GPUMemory: " << this->GPUMemory << " MiB per kind\n";
  os << indent << "CPUMemory: " << this->CPUMemory << " MiB per layer\n";
  os << indent << "UploadBudget: " << this->UploadBudget << " MiB per frame\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Slots: " << this->GetNumberOfSlots(Heights) << " height, "
     << this->GetNumberOfSlots(Images) << " image\n";
  os << indent << "ResidentPages: " << this->GetNumberOfResidentPages() << "\n";
  os << indent << "Requested/Loaded/Evicted/Deferred pages: " << this->NumberOfRequestedPages
     << " / " << this->NumberOfLoadedPages << " / " << this->NumberOfEvictedPages << " / "
     << this->NumberOfDeferredPages << "\n";
  os << indent << "Hits/Misses: " << this->NumberOfHits << " / " << this->NumberOfMisses << "\n";
  os << indent << "BytesUploaded: " << this->BytesUploaded << " (last frame "
     << this->BytesUploadedLastFrame << ")\n";
}
