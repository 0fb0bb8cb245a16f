#include "vtkGlobeLayer.h"
#include "vtkGlobeGeoid.h"
#include "vtkGlobeMapProjection.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkGlobePageSource.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRasterSamples.h"
#include "vtkGlobeReprojection.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkGlobeLayer);

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr float NaNf = std::numeric_limits<float>::quiet_NaN();

/// Converts native samples (VTK rows, row 0 south) to float rows north first, turning nodata
/// samples into NaN (the void marker).
template <typename T>
void SamplesToFloat(const T* raw, int width, int height, bool hasNoData, double noData,
  std::vector<float>& out)
{
  // Compare in the raster's own type: the nodata text may round (e.g. float -3.4e38).
  T nd{};
  const bool useNoData = hasNoData && vtkGlobeRasterSamples::NoDataAs(noData, nd);
  out.resize(static_cast<size_t>(width) * height);
  for (int r = 0; r < height; ++r)
  {
    const T* row = raw + static_cast<size_t>(height - 1 - r) * width;
    float* dst = out.data() + static_cast<size_t>(r) * width;
    for (int c = 0; c < width; ++c)
    {
      dst[c] = (useNoData && row[c] == nd) ? NaNf : static_cast<float>(row[c]);
    }
  }
}

/**
 * Push-pull void fill (Gortler et al., "The Lumigraph", 1996): NaN entries of a row-major
 * width x height raster are replaced; valid entries are not touched.
 *
 * Pull: each coarser level halves the raster; a coarse cell is known when any of its (up
 * to) 2 x 2 children is known, and takes their mean. Levels are added until one is fully
 * known. Push: from the coarsest level down, every unknown cell takes the bilinear
 * interpolation of the (now complete) next-coarser level at its centre. Each filled value is
 * thus a convex combination of valid values: no overshoot, no pit, and a constant field is
 * reproduced exactly. Requires at least one valid entry.
 */
void PushPullFill(std::vector<float>& values, int width, int height)
{
  struct Level
  {
    int W, H;
    std::vector<float> V;
    std::vector<unsigned char> Known;
  };
  std::vector<Level> levels(1);
  levels[0].W = width;
  levels[0].H = height;
  levels[0].V.swap(values);
  levels[0].Known.resize(levels[0].V.size());
  bool complete = true;
  for (size_t i = 0; i < levels[0].V.size(); ++i)
  {
    levels[0].Known[i] = !std::isnan(levels[0].V[i]);
    complete = complete && levels[0].Known[i];
  }

  // Pull.
  while (!complete && (levels.back().W > 1 || levels.back().H > 1))
  {
    const Level& fine = levels.back();
    Level coarse;
    coarse.W = (fine.W + 1) / 2;
    coarse.H = (fine.H + 1) / 2;
    coarse.V.assign(static_cast<size_t>(coarse.W) * coarse.H, 0.0f);
    coarse.Known.assign(coarse.V.size(), 0);
    complete = true;
    for (int j = 0; j < coarse.H; ++j)
    {
      for (int i = 0; i < coarse.W; ++i)
      {
        double sum = 0.0;
        int n = 0;
        for (int y = 2 * j; y < std::min(2 * j + 2, fine.H); ++y)
        {
          for (int x = 2 * i; x < std::min(2 * i + 2, fine.W); ++x)
          {
            const size_t k = static_cast<size_t>(y) * fine.W + x;
            if (fine.Known[k])
            {
              sum += fine.V[k];
              ++n;
            }
          }
        }
        const size_t c = static_cast<size_t>(j) * coarse.W + i;
        if (n > 0)
        {
          coarse.V[c] = static_cast<float>(sum / n);
          coarse.Known[c] = 1;
        }
        else
        {
          complete = false;
        }
      }
    }
    levels.push_back(std::move(coarse));
  }

  // Push: fine cell centre x maps to coarse coordinate (x - 0.5) / 2.
  for (int k = static_cast<int>(levels.size()) - 2; k >= 0; --k)
  {
    Level& fine = levels[k];
    const Level& coarse = levels[k + 1];
    for (int j = 0; j < fine.H; ++j)
    {
      const double v = std::clamp(0.5 * j - 0.25, 0.0, coarse.H - 1.0);
      const int j0 = std::min(static_cast<int>(v), std::max(coarse.H - 2, 0));
      const int j1 = std::min(j0 + 1, coarse.H - 1);
      const double fv = v - j0;
      for (int i = 0; i < fine.W; ++i)
      {
        const size_t f = static_cast<size_t>(j) * fine.W + i;
        if (fine.Known[f])
        {
          continue;
        }
        const double u = std::clamp(0.5 * i - 0.25, 0.0, coarse.W - 1.0);
        const int i0 = std::min(static_cast<int>(u), std::max(coarse.W - 2, 0));
        const int i1 = std::min(i0 + 1, coarse.W - 1);
        const double fu = u - i0;
        const auto at = [&coarse](int x, int y)
        { return static_cast<double>(coarse.V[static_cast<size_t>(y) * coarse.W + x]); };
        fine.V[f] = static_cast<float>((1.0 - fv) * ((1.0 - fu) * at(i0, j0) + fu * at(i1, j0)) +
          fv * ((1.0 - fu) * at(i0, j1) + fu * at(i1, j1)));
      }
    }
  }
  values.swap(levels[0].V);
}

/// Checks an in-memory geographic pixel-edge box.
bool CheckExtent(double west, double east, double south, double north, std::string& why)
{
  char text[256];
  std::snprintf(text, sizeof(text), "the extent (west %g, east %g, south %g, north %g) ", west,
    east, south, north);
  why = text;
  if (!std::isfinite(west) || !std::isfinite(east) || !std::isfinite(south) ||
    !std::isfinite(north))
  {
    why += "is not finite";
    return false;
  }
  if (!(west < east))
  {
    why += "needs west < east";
    return false;
  }
  if (!(south < north))
  {
    why += "needs south < north";
    return false;
  }
  if (south < -90.0 || north > 90.0)
  {
    why += "has a latitude beyond +-90 degrees";
    return false;
  }
  if (east - west > 360.0 * (1.0 + 1e-12))
  {
    why += "spans more than 360 degrees of longitude";
    return false;
  }
  why.clear();
  return true;
}

bool SameDouble(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// The common end of loading heights: scale/offset, voids, range, fill. `values` holds raw
/// values with NaN for voids. Returns false (with `why`) when no post is valid.
/// Heights outside the plausible range: how many, and the one farthest out.
struct Implausible
{
  vtkIdType Count = 0;
  double Worst = 0.0;
};

bool FinishHeights(std::vector<float>& values, int width, int height, double scale, double offset,
  const double plausible[2], bool fill, vtkIdType& voids, Implausible& implausible,
  double& minimum, double& maximum, std::string& why, vtkSmartPointer<vtkDataArray>& data)
{
  voids = 0;
  implausible = Implausible();
  minimum = std::numeric_limits<double>::infinity();
  maximum = -minimum;
  for (float& v : values)
  {
    if (!std::isfinite(v))
    {
      v = NaNf; // +-Inf are voids too
      ++voids;
      continue;
    }
    // In double: 1e30 * scale must not overflow to an infinity that passes as a value.
    const double metres = static_cast<double>(v) * scale + offset;
    if (!(metres >= plausible[0] && metres <= plausible[1]))
    {
      // One corrupt post must not move the globe's spheres and clipping planes.
      if (implausible.Count == 0 || std::abs(metres) > std::abs(implausible.Worst))
      {
        implausible.Worst = metres;
      }
      ++implausible.Count;
      ++voids;
      v = NaNf;
      continue;
    }
    v = static_cast<float>(metres);
    minimum = std::min(minimum, static_cast<double>(v));
    maximum = std::max(maximum, static_cast<double>(v));
  }
  if (voids == static_cast<vtkIdType>(values.size()))
  {
    why = "it has no valid height: all " + std::to_string(voids) + " posts are nodata or NaN";
    if (implausible.Count > 0)
    {
      char text[200];
      std::snprintf(text, sizeof(text),
        " (%lld of them outside the plausible range [%g, %g] m, e.g. %g m)",
        static_cast<long long>(implausible.Count), plausible[0], plausible[1], implausible.Worst);
      why += text;
    }
    return false;
  }
  if (fill && voids > 0)
  {
    PushPullFill(values, width, height);
  }
  vtkNew<vtkFloatArray> array;
  array->SetName("Height");
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  data = array;
  return true;
}

/// The common end of loading colour: RGB(A) -> RGBA, nodata pixels transparent.
void FinishColors(const std::vector<unsigned char>& pixels, size_t n, int components,
  bool hasNoData, double noData, vtkIdType& voids, vtkSmartPointer<vtkDataArray>& data)
{
  vtkNew<vtkUnsignedCharArray> array;
  array->SetName("Color");
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(static_cast<vtkIdType>(n));
  unsigned char* out = array->GetPointer(0);
  // Nodata applies only when it is a possible 8-bit value.
  const bool useNoData =
    hasNoData && noData >= 0.0 && noData <= 255.0 && noData == std::floor(noData);
  const unsigned char nd = useNoData ? static_cast<unsigned char>(noData) : 0;
  voids = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const unsigned char* p = pixels.data() + i * components;
    out[4 * i + 0] = p[0];
    out[4 * i + 1] = p[1];
    out[4 * i + 2] = p[2];
    out[4 * i + 3] = components == 4 ? p[3] : 255;
    // As GDAL's per-dataset nodata mask: a pixel is missing when all its bands are nodata.
    if (useNoData && p[0] == nd && p[1] == nd && p[2] == nd)
    {
      out[4 * i + 3] = 0;
      ++voids;
    }
  }
  data = array;
}

bool CheckMemoryInput(int width, int height, const void* values, std::string& why)
{
  if (width <= 0 || height <= 0)
  {
    why =
      "the size (" + std::to_string(width) + " x " + std::to_string(height) + ") must be positive";
    return false;
  }
  if (!values)
  {
    why = "no values were given";
    return false;
  }
  return true;
}

/// A number from a field-data array of the reader; false when the array is missing.
bool FieldValue(vtkFieldData* fd, const char* name, int component, double& value)
{
  vtkDataArray* a = fd ? fd->GetArray(name) : nullptr;
  if (!a || a->GetNumberOfValues() <= component)
  {
    return false;
  }
  value = a->GetVariantValue(component).ToDouble();
  return true;
}

std::string FieldString(vtkFieldData* fd, const char* name)
{
  vtkStringArray* a = fd ? vtkStringArray::SafeDownCast(fd->GetAbstractArray(name)) : nullptr;
  return a && a->GetNumberOfValues() > 0 ? a->GetValue(0) : std::string();
}

/**
 * The layer's end of the pipeline: one vtkImageData input port, no output port (a sink, as a
 * writer). Its update brings the input up to date; the layer then reads the input's data.
 */
class vtkGlobeLayerInput : public vtkAlgorithm
{
public:
  static vtkGlobeLayerInput* New();
  vtkTypeMacro(vtkGlobeLayerInput, vtkAlgorithm);

  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override
  {
    if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
    {
      // The whole raster.
      vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
      if (inInfo && inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      {
        inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
          inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
      if (inInfo)
      {
        this->RequestTime(inInfo);
      }
      return 1;
    }
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);
  }

  /// The layer's UpdateTime, asked of a time-varying input.
  double UpdateTime = 0.0;

protected:
  /**
   * Asks a time-varying input for the time step UpdateTime falls in: the step's own time (the
   * last step at or before it, the first before them all), so that every time within one step
   * finds the input's data up to date (its DATA_TIME_STEP) and reads nothing; an input with a
   * continuous TIME_RANGE gets UpdateTime clamped into it.
   */
  void RequestTime(vtkInformation* inInfo)
  {
    using SDDP = vtkStreamingDemandDrivenPipeline;
    if (inInfo->Has(SDDP::TIME_STEPS()) && inInfo->Length(SDDP::TIME_STEPS()) > 0)
    {
      const double* steps = inInfo->Get(SDDP::TIME_STEPS());
      const int n = inInfo->Length(SDDP::TIME_STEPS());
      int k = 0;
      while (k + 1 < n && steps[k + 1] <= this->UpdateTime)
      {
        ++k;
      }
      inInfo->Set(SDDP::UPDATE_TIME_STEP(), steps[k]);
    }
    else if (inInfo->Has(SDDP::TIME_RANGE()) && inInfo->Length(SDDP::TIME_RANGE()) == 2)
    {
      const double* range = inInfo->Get(SDDP::TIME_RANGE());
      inInfo->Set(SDDP::UPDATE_TIME_STEP(),
        std::max(range[0], std::min(range[1], this->UpdateTime)));
    }
    else
    {
      inInfo->Remove(SDDP::UPDATE_TIME_STEP());
    }
  }

  vtkGlobeLayerInput()
  {
    this->SetNumberOfInputPorts(1);
    this->SetNumberOfOutputPorts(0);
  }
  int FillInputPortInformation(int, vtkInformation* info) override
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    return 1;
  }

private:
  vtkGlobeLayerInput(const vtkGlobeLayerInput&) = delete;
  void operator=(const vtkGlobeLayerInput&) = delete;
};
vtkStandardNewMacro(vtkGlobeLayerInput);
} // namespace

//------------------------------------------------------------------------------------------
class vtkGlobeLayer::vtkInternals
{
public:
  vtkSmartPointer<vtkGlobeGeoid> Geoid; // GeoidFileName's, shared through SharedGeoid
  bool Global = false;                    // IsGlobal, decided once per load
  enum Sources
  {
    None,
    File,   // FileName, through Reader
    Memory, // SetHeightData / SetColorData
    Input   // SetInputConnection / SetInputData
  };

  /// Everything a load depends on; Update() re-loads only when this changed.
  struct Settings
  {
    bool Loaded = false;
    unsigned long SourceGeneration = 0;
    // The file's size and modification time: a file rewritten in place is re-read by the
    // next Update(), with or without Modified().
    std::uintmax_t FileSize = 0;
    long long FileTime = 0;
    // When the algorithms upstream of the layer were last modified: a failed load is tried
    // again only when this, the file or a setting changed (one report per failure).
    vtkMTimeType UpstreamTime = 0;
    // The input data set and when it was last generated or modified upstream.
    vtkDataObject* InputData = nullptr;
    vtkMTimeType InputTime = 0;
    int Role = 0;
    double ValueScale = 1.0;
    double ValueOffset = 0.0;
    bool NoDataOverridden = false;
    bool HasNoData = false;
    double NoData = 0.0;
    bool FillVoids = true;
    double PlausibleMinimum = -VTK_DOUBLE_MAX;
    double PlausibleMaximum = VTK_DOUBLE_MAX;
    bool Streamed = false;

    bool operator==(const Settings& o) const
    {
      return this->Loaded == o.Loaded && this->SourceGeneration == o.SourceGeneration &&
        this->FileSize == o.FileSize && this->FileTime == o.FileTime &&
        this->InputData == o.InputData && this->InputTime == o.InputTime &&
        this->Role == o.Role && this->ValueScale == o.ValueScale &&
        this->ValueOffset == o.ValueOffset && this->NoDataOverridden == o.NoDataOverridden &&
        this->HasNoData == o.HasNoData && SameDouble(this->NoData, o.NoData) &&
        this->FillVoids == o.FillVoids && this->PlausibleMinimum == o.PlausibleMinimum &&
        this->PlausibleMaximum == o.PlausibleMaximum && this->UpstreamTime == o.UpstreamTime &&
        this->Streamed == o.Streamed;
    }
  };

  Settings LastLoad;
  // What the last failed attempt depended on (Loaded false when the last attempt succeeded).
  Settings LastFailure;
  vtkMTimeType FailureMTime = 0; // the layer's own Modified() asks for another try

  // Where the data comes from; every change of source bumps the generation.
  Sources Source = None;
  unsigned long SourceGeneration = 0;
  vtkNew<vtkGlobeLayerInput> Sink;
  vtkNew<vtkGlobeRasterReader> Reader; // for FileName
  int MemoryRole = Height;

  // Streaming: the page source, and the value settings its pages get (a copy taken at
  // load, so worker threads never read the layer's own members).
  vtkNew<vtkGlobePageSource> Pages;
  bool Streamed = false;
  struct PageValues
  {
    double Scale = 1.0;
    double Offset = 0.0;
    double Minimum = -VTK_DOUBLE_MAX;
    double Maximum = VTK_DOUBLE_MAX;
    bool OverriddenNoData = false;
    double NoData = 0.0;
    bool Fill = true;
    // The range of the valid heights of every page read (low > high: none yet).
    double Low = 1.0;
    double High = -1.0;
  };
  PageValues Values;
  std::mutex ValuesMutex;

  // Results.
  vtkSmartPointer<vtkDataArray> Data;
  // GetLevelData's pyramid (level 0 is Data) and the data it was made from.
  std::vector<vtkSmartPointer<vtkDataArray>> Levels;
  vtkDataArray* LevelsOf = nullptr;
  vtkMTimeType LevelsTime = 0;
  double Extent[4] = { NaN, NaN, NaN, NaN };
  double Origin[2] = { NaN, NaN };
  double PixelSize[2] = { NaN, NaN };
  std::string DefaultName;

  void SetSource(Sources source)
  {
    this->Source = source;
    ++this->SourceGeneration;
  }
};

//------------------------------------------------------------------------------------------
vtkGlobeLayer::vtkGlobeLayer()
  : Internals(new vtkInternals)
{
  // The layer reports the internal reader's failures itself (naming the file and the reason,
  // to the layer's observers): keep the reader and its executive quiet.
  vtkNew<vtkCallbackCommand> quiet;
  this->Internals->Reader->AddObserver(vtkCommand::ErrorEvent, quiet);
  this->Internals->Reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
}

vtkGlobeLayer::~vtkGlobeLayer()
{
  this->SetFileName(nullptr);
  this->SetName(nullptr);
  this->SetGeoidFileName(nullptr);
}

//------------------------------------------------------------------------------------------
namespace
{
// One geoid object per file name for the process: a 15' grid is 4 MB, and the layer set
// uploads one texture per geoid object. Held for good (few files; no weak pointers that a
// layer released on a page-reading thread could race with).
vtkSmartPointer<vtkGlobeGeoid> SharedGeoid(const std::string& fileName)
{
  static std::map<std::string, vtkSmartPointer<vtkGlobeGeoid>> geoids;
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  vtkSmartPointer<vtkGlobeGeoid>& geoid = geoids[fileName];
  if (!geoid)
  {
    geoid = vtkSmartPointer<vtkGlobeGeoid>::New();
    geoid->SetFileName(fileName.c_str());
  }
  return geoid;
}
} // namespace

void vtkGlobeLayer::SetVerticalDatumToEGM96()
{
  this->SetVerticalDatum(Geoid);
  this->SetGeoidFileName(vtkGlobeGeoid::GetEGM96FileName());
}

vtkGlobeGeoid* vtkGlobeLayer::GetGeoid()
{
  vtkInternals& in = *this->Internals;
  if (this->VerticalDatum != Geoid)
  {
    in.Geoid = nullptr;
    return nullptr;
  }
  const std::string name = this->GeoidFileName ? this->GeoidFileName : "";
  if (!in.Geoid || name != (in.Geoid->GetFileName() ? in.Geoid->GetFileName() : ""))
  {
    in.Geoid = SharedGeoid(name);
  }
  in.Geoid->Update();
  return in.Geoid;
}

double vtkGlobeLayer::GetGeoidUndulation(double lon, double lat)
{
  vtkGlobeGeoid* geoid = this->GetGeoid();
  return geoid ? geoid->GetUndulation(lon, lat) : 0.0;
}

//------------------------------------------------------------------------------------------
const char* vtkGlobeLayer::GetRoleAsString()
{
  switch (this->Role)
  {
    case Color:
      return "Color";
    case NormalMap:
      return "NormalMap";
    case Overlay:
      return "Overlay";
    case Mask:
      return "Mask";
    case NightLights:
      return "NightLights";
    default:
      return "Height";
  }
}

const char* vtkGlobeLayer::GetBlendModeAsString()
{
  switch (this->BlendMode)
  {
    case Add:
      return "Add";
    case Average:
      return "Average";
    default:
      return "Replace";
  }
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::SetFileName(const char* fileName)
{
  if ((!fileName && !this->FileName) ||
    (fileName && this->FileName && std::strcmp(fileName, this->FileName) == 0))
  {
    return;
  }
  vtkInternals& in = *this->Internals;
  delete[] this->FileName;
  this->FileName = nullptr;
  in.DefaultName.clear();
  if (fileName)
  {
    const size_t n = std::strlen(fileName) + 1;
    this->FileName = new char[n];
    std::memcpy(this->FileName, fileName, n);
    in.DefaultName = std::filesystem::path(fileName).stem().string();
    // A file replaces in-memory data and any input connection.
    in.Reader->SetFileName(fileName);
    in.Sink->SetInputConnection(in.Reader->GetOutputPort());
    in.SetSource(vtkInternals::File);
  }
  else if (in.Source == vtkInternals::File)
  {
    in.Reader->SetFileName(nullptr);
    in.Sink->SetInputConnection(nullptr);
    in.SetSource(vtkInternals::None);
  }
  this->Modified();
}

vtkGlobeRasterReader* vtkGlobeLayer::GetFileReader()
{
  return this->Internals->Reader;
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::SetInputConnection(vtkAlgorithmOutput* output)
{
  vtkInternals& in = *this->Internals;
  if (in.Source == vtkInternals::Input && output && in.Sink->GetNumberOfInputConnections(0) == 1 &&
    in.Sink->GetInputConnection(0, 0) == output)
  {
    return;
  }
  this->SetFileName(nullptr);
  in.DefaultName.clear();
  in.Sink->SetInputConnection(output);
  in.SetSource(output ? vtkInternals::Input : vtkInternals::None);
  this->Modified();
}

void vtkGlobeLayer::SetInputData(vtkDataObject* data)
{
  vtkInternals& in = *this->Internals;
  this->SetFileName(nullptr);
  in.DefaultName.clear();
  in.Sink->SetInputDataObject(data);
  in.SetSource(data ? vtkInternals::Input : vtkInternals::None);
  this->Modified();
}

vtkAlgorithmOutput* vtkGlobeLayer::GetInputConnection()
{
  vtkInternals& in = *this->Internals;
  return in.Sink->GetNumberOfInputConnections(0) > 0 ? in.Sink->GetInputConnection(0, 0) : nullptr;
}

vtkAlgorithm* vtkGlobeLayer::GetInputAlgorithm()
{
  vtkInternals& in = *this->Internals;
  return in.Sink->GetNumberOfInputConnections(0) > 0 ? in.Sink->GetInputAlgorithm(0, 0) : nullptr;
}

//------------------------------------------------------------------------------------------
const char* vtkGlobeLayer::GetName()
{
  return this->Name ? this->Name : this->Internals->DefaultName.c_str();
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::SetNoDataValue(double value)
{
  if (this->NoDataValueOverridden && this->HasNoDataValue && SameDouble(value, this->NoDataValue))
  {
    return;
  }
  this->NoDataValue = value;
  this->HasNoDataValue = true;
  this->NoDataValueOverridden = true;
  this->Modified();
}

void vtkGlobeLayer::SetHasNoDataValue(bool has)
{
  if (this->NoDataValueOverridden && this->HasNoDataValue == has)
  {
    return;
  }
  this->HasNoDataValue = has;
  this->NoDataValueOverridden = true;
  this->Modified();
}

void vtkGlobeLayer::UseFileNoDataValue()
{
  if (this->NoDataValueOverridden)
  {
    this->NoDataValueOverridden = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------------------
int* vtkGlobeLayer::GetDimensions()
{
  this->GetDimensions(this->Dimensions);
  return this->Dimensions;
}

void vtkGlobeLayer::GetDimensions(int dimensions[2])
{
  dimensions[0] = this->RasterWidth;
  dimensions[1] = this->RasterHeight;
}

vtkDataArray* vtkGlobeLayer::GetData()
{
  return this->Valid ? this->Internals->Data.Get() : nullptr;
}

//------------------------------------------------------------------------------------------
namespace
{
/// The texels of a finer level (m of them) that texel i of a coarser one (n) covers, with the
/// length of each overlap in finer texels: the area-weighted box filter along one axis.
struct Tap
{
  int Index;
  double Weight;
};

std::vector<std::vector<Tap>> Taps(int m, int n)
{
  std::vector<std::vector<Tap>> taps(n);
  const double r = static_cast<double>(m) / n;
  for (int i = 0; i < n; ++i)
  {
    const double a = i * r, b = (i + 1) * r;
    for (int k = static_cast<int>(std::floor(a)); k < m && k < b; ++k)
    {
      const double w = std::min(b, k + 1.0) - std::max(a, static_cast<double>(k));
      if (w > 1e-9)
      {
        taps[i].push_back({ k, w });
      }
    }
  }
  return taps;
}

/// The next level (nw x nh) of a level (w x h, row 0 north): float heights with voids left
/// out of the means, or unsigned char components averaged as OpenGL's mipmaps and the
/// streamed pages' levels (vtkGlobePageSource) average them.
vtkSmartPointer<vtkDataArray> Reduce(vtkDataArray* in, int w, int h, int nw, int nh)
{
  const std::vector<std::vector<Tap>> tx = Taps(w, nw), ty = Taps(h, nh);
  if (auto* heights = vtkFloatArray::SafeDownCast(in))
  {
    auto out = vtkSmartPointer<vtkFloatArray>::New();
    out->SetNumberOfValues(static_cast<vtkIdType>(nw) * nh);
    const float* v = heights->GetPointer(0);
    float* o = out->GetPointer(0);
    vtkSMPTools::For(0, nh, [&](int begin, int end) {
      for (int j = begin; j < end; ++j)
      {
        for (int i = 0; i < nw; ++i)
        {
          double sum = 0.0, weight = 0.0;
          for (const Tap& y : ty[j])
          {
            const float* row = v + static_cast<size_t>(y.Index) * w;
            for (const Tap& x : tx[i])
            {
              const float value = row[x.Index];
              if (!std::isnan(value))
              {
                sum += y.Weight * x.Weight * value;
                weight += y.Weight * x.Weight;
              }
            }
          }
          o[static_cast<size_t>(j) * nw + i] =
            weight > 0.0 ? static_cast<float>(sum / weight) : std::numeric_limits<float>::quiet_NaN();
        }
      }
    });
    return out;
  }
  auto* colors = vtkUnsignedCharArray::SafeDownCast(in);
  if (!colors)
  {
    return nullptr;
  }
  const int nc = colors->GetNumberOfComponents();
  auto out = vtkSmartPointer<vtkUnsignedCharArray>::New();
  out->SetNumberOfComponents(nc);
  out->SetNumberOfTuples(static_cast<vtkIdType>(nw) * nh);
  const unsigned char* v = colors->GetPointer(0);
  unsigned char* o = out->GetPointer(0);
  vtkSMPTools::For(0, nh, [&](int begin, int end) {
    std::vector<double> sum(nc);
    for (int j = begin; j < end; ++j)
    {
      for (int i = 0; i < nw; ++i)
      {
        std::fill(sum.begin(), sum.end(), 0.0);
        double weight = 0.0;
        for (const Tap& y : ty[j])
        {
          for (const Tap& x : tx[i])
          {
            const double k = y.Weight * x.Weight;
            const unsigned char* t = v + (static_cast<size_t>(y.Index) * w + x.Index) * nc;
            for (int c = 0; c < nc; ++c)
            {
              sum[c] += k * t[c];
            }
            weight += k;
          }
        }
        unsigned char* t = o + (static_cast<size_t>(j) * nw + i) * nc;
        for (int c = 0; c < nc; ++c)
        {
          t[c] = static_cast<unsigned char>(std::min(255.0, std::floor(sum[c] / weight + 0.5)));
        }
      }
    }
  });
  return out;
}
} // namespace

int vtkGlobeLayer::GetNumberOfLevels()
{
  if (!this->GetData() || this->Internals->Streamed)
  {
    return 0;
  }
  int levels = 1;
  while ((std::max(this->RasterWidth, this->RasterHeight) >> levels) > 0)
  {
    ++levels;
  }
  return levels;
}

void vtkGlobeLayer::GetLevelDimensions(int level, int dimensions[2])
{
  dimensions[0] = dimensions[1] = 0;
  if (level >= 0 && level < this->GetNumberOfLevels())
  {
    dimensions[0] = std::max(1, this->RasterWidth >> level);
    dimensions[1] = std::max(1, this->RasterHeight >> level);
  }
}

vtkDataArray* vtkGlobeLayer::GetLevelData(int level)
{
  vtkInternals& in = *this->Internals;
  const int levels = this->GetNumberOfLevels();
  if (level < 0 || level >= levels)
  {
    return nullptr;
  }
  vtkDataArray* data = in.Data;
  if (in.LevelsOf != data || in.LevelsTime != data->GetMTime())
  {
    in.Levels.assign(1, data);
    in.LevelsOf = data;
    in.LevelsTime = data->GetMTime();
  }
  while (static_cast<int>(in.Levels.size()) <= level)
  {
    const int l = static_cast<int>(in.Levels.size());
    int from[2], to[2];
    this->GetLevelDimensions(l - 1, from);
    this->GetLevelDimensions(l, to);
    vtkSmartPointer<vtkDataArray> next = Reduce(in.Levels.back(), from[0], from[1], to[0], to[1]);
    if (!next)
    {
      return nullptr;
    }
    in.Levels.push_back(next);
  }
  return in.Levels[level];
}

void vtkGlobeLayer::GetGeographicExtent(double extent[4])
{
  const bool geographic = this->Valid && this->ModelType == Geographic;
  for (int i = 0; i < 4; ++i)
  {
    extent[i] = geographic ? this->Internals->Extent[i] : NaN;
  }
}

double* vtkGlobeLayer::GetGeographicExtent()
{
  this->GetGeographicExtent(this->ExtentResult);
  return this->ExtentResult;
}

bool vtkGlobeLayer::GetGroundSize(double size[2])
{
  size[0] = size[1] = 0.0;
  const int w = this->GetNumberOfColumns(), h = this->GetNumberOfRows();
  if (!this->Valid || w <= 0 || h <= 0)
  {
    return false;
  }
  if (this->ModelType == Projected)
  {
    double origin[2], pixel[2];
    this->GetProjectedGeoTransform(origin, pixel);
    size[0] = pixel[0] * w;
    size[1] = pixel[1] * h;
  }
  else
  {
    double e[4];
    this->GetGeographicExtent(e);
    const double a = this->GetDatumSemiMajorAxis() > 0.0 ? this->GetDatumSemiMajorAxis() : 6378137.0;
    const double b = this->GetDatumSemiMinorAxis() > 0.0 ? this->GetDatumSemiMinorAxis() : a * (1.0 - 1.0 / 298.257223563);
    const double e2 = 1.0 - (b * b) / (a * a);
    const double phi = vtkMath::RadiansFromDegrees(0.5 * (e[2] + e[3]));
    const double w2 = 1.0 - e2 * std::sin(phi) * std::sin(phi);
    const double normal = a / std::sqrt(w2), meridian = a * (1.0 - e2) / (w2 * std::sqrt(w2));
    size[0] = vtkMath::RadiansFromDegrees(e[1] - e[0]) * normal * std::cos(phi);
    size[1] = vtkMath::RadiansFromDegrees(e[3] - e[2]) * meridian;
  }
  return size[0] > 0.0 && size[1] > 0.0;
}

void vtkGlobeLayer::GetSkirtBorder(double border[2])
{
  border[0] = border[1] = 0.0;
  double size[2];
  if (this->Role != Height || this->SkirtDistance == 0.0 || !this->GetGroundSize(size))
  {
    return;
  }
  const double distance = this->SkirtDistance > 0.0
    ? this->SkirtDistance
    : std::min(AutomaticSkirtLimit, 0.25 * std::min(size[0], size[1]));
  border[0] = distance / size[0];
  border[1] = distance / size[1];
}

double vtkGlobeLayer::ApplySkirt(const double skirt[3], double uv[2], double outside[2])
{
  outside[0] = outside[1] = 0.0;
  if (uv[0] >= 0.0 && uv[0] <= 1.0 && uv[1] >= 0.0 && uv[1] <= 1.0)
  {
    return 1.0;
  }
  if (!(skirt[0] > 0.0) && !(skirt[1] > 0.0))
  {
    return 0.0;
  }
  const double dv = std::max(0.0, std::max(-uv[1], uv[1] - 1.0));
  bool west = uv[0] < 0.0;
  double du = west ? -uv[0] : 0.0;
  if (uv[0] > 1.0)
  {
    west = skirt[2] > 0.0 && skirt[2] - uv[0] < uv[0] - 1.0;
    du = west ? skirt[2] - uv[0] : uv[0] - 1.0;
  }
  const double w = (du > 0.0 ? (skirt[0] > 0.0 ? std::max(0.0, 1.0 - du / skirt[0]) : 0.0) : 1.0) *
    (dv > 0.0 ? (skirt[1] > 0.0 ? std::max(0.0, 1.0 - dv / skirt[1]) : 0.0) : 1.0);
  uv[0] = west ? 0.0 : std::min(uv[0], 1.0);
  uv[1] = std::min(std::max(uv[1], 0.0), 1.0);
  outside[0] = du;
  outside[1] = dv;
  return w;
}

void vtkGlobeLayer::GetFeatherBorder(double border[2])
{
  border[0] = border[1] = 0.0;
  const int w = this->GetNumberOfColumns(), h = this->GetNumberOfRows();
  double skirt[2], size[2];
  this->GetSkirtBorder(skirt);
  if (!this->Valid || w <= 0 || h <= 0 || skirt[0] > 0.0)
  {
    return;
  }
  if (!(this->FeatherDistance > 0.0))
  {
    border[0] = this->FeatherWidth / w;
    border[1] = this->FeatherWidth / h;
    return;
  }
  this->GetGroundSize(size);
  border[0] = size[0] > 0.0 ? std::min(0.5, this->FeatherDistance / size[0]) : 0.0;
  border[1] = size[1] > 0.0 ? std::min(0.5, this->FeatherDistance / size[1]) : 0.0;
}

void vtkGlobeLayer::GetProjectedGeoTransform(double origin[2], double pixelSize[2])
{
  for (int i = 0; i < 2; ++i)
  {
    origin[i] = this->Valid ? this->Internals->Origin[i] : NaN;
    pixelSize[i] = this->Valid ? this->Internals->PixelSize[i] : NaN;
  }
}

bool vtkGlobeLayer::IsGlobal()
{
  return this->Valid && this->Internals->Global;
}

double vtkGlobeLayer::GetDegreesPerPixel(int axis)
{
  if (!this->Valid || this->ModelType != Geographic || axis < 0 || axis > 1)
  {
    return NaN;
  }
  return this->Internals->PixelSize[axis];
}


//------------------------------------------------------------------------------------------
void vtkGlobeLayer::Invalidate()
{
  vtkInternals& in = *this->Internals;
  this->Valid = false;
  this->DataTime = std::numeric_limits<double>::quiet_NaN();
  in.Data = nullptr;
  in.Levels.clear();
  in.LevelsOf = nullptr;
  in.Streamed = false;
  in.Global = false;
  this->ReprojectedFromEPSG = 0;
  this->ReprojectedFromCRS.clear();
  this->CRSDefinition.clear();
  this->RasterWidth = this->RasterHeight = this->NumberOfComponents = 0;
  this->NumberOfVoids = 0;
  this->NumberOfImplausibleValues = 0;
  this->ModelType = this->EPSG = 0;
  this->DatumSemiMajorAxis = this->DatumSemiMinorAxis = 0.0;
  this->MinimumValue = this->MaximumValue = 0.0;
  std::fill(in.Extent, in.Extent + 4, NaN);
  std::fill(in.Origin, in.Origin + 2, NaN);
  std::fill(in.PixelSize, in.PixelSize + 2, NaN);
  in.LastLoad = vtkInternals::Settings();
  if (!this->NoDataValueOverridden)
  {
    this->HasNoDataValue = false;
    this->NoDataValue = 0.0;
  }
}

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::Update()
{
  vtkInternals& in = *this->Internals;
  vtkInternals::Settings now;
  now.Loaded = true;
  now.SourceGeneration = in.SourceGeneration;
  now.Role = this->IsImageRole() ? Color : Height; // images load alike whatever their role
  now.ValueScale = this->ValueScale;
  now.ValueOffset = this->ValueOffset;
  now.NoDataOverridden = this->NoDataValueOverridden;
  now.HasNoData = this->NoDataValueOverridden && this->HasNoDataValue;
  now.NoData = now.HasNoData ? this->NoDataValue : 0.0;
  now.FillVoids = this->FillVoids;
  now.PlausibleMinimum = this->PlausibleRange[0];
  now.PlausibleMaximum = this->PlausibleRange[1];
  if (in.Source == vtkInternals::File)
  {
    std::error_code ec;
    now.FileSize = std::filesystem::file_size(this->FileName, ec);
    const auto time = std::filesystem::last_write_time(this->FileName, ec);
    now.FileTime = ec ? 0 : static_cast<long long>(time.time_since_epoch().count());
  }
  auto upstreamTime = [this]() -> vtkMTimeType {
    vtkAlgorithm* upstream = this->GetInputAlgorithm();
    auto* executive =
      upstream ? vtkDemandDrivenPipeline::SafeDownCast(upstream->GetExecutive()) : nullptr;
    if (!executive)
    {
      return 0;
    }
    executive->UpdatePipelineMTime();
    return executive->GetPipelineMTime();
  };
  now.UpstreamTime = upstreamTime();
  // True when the last load differs from `now` only in ValueScale and ValueOffset: the loaded
  // values (or stored pages) can be mapped instead of read again.
  const auto onlyValueMapChanged = [&]() {
    vtkInternals::Settings rescaled = in.LastLoad;
    rescaled.ValueScale = now.ValueScale;
    rescaled.ValueOffset = now.ValueOffset;
    return this->Valid && now.Role == Height && now == rescaled;
  };
  // What a failed attempt depended on; InputTime is left out: a failed run leaves no new data
  // to compare, and the upstream time is taken after the attempt's own Modified().
  const auto recordFailure = [&]() {
    in.LastFailure = now;
    in.LastFailure.InputData = nullptr;
    in.LastFailure.InputTime = 0;
    // Decided after the comparison below: a change of Streaming changes the MTime anyway.
    in.LastFailure.Streamed = false;
    in.LastFailure.UpstreamTime = upstreamTime();
    in.FailureMTime = this->GetMTime();
  };
  // A failure is reported once: nothing is tried again until something it depended on
  // changed (the source, a setting, the file on disk, an algorithm upstream).
  if (!this->Valid && in.LastFailure.Loaded && now == in.LastFailure &&
    this->GetMTime() == in.FailureMTime)
  {
    return false;
  }
  in.LastFailure = vtkInternals::Settings();
  if (in.Source == vtkInternals::None)
  {
    this->InvokeEvent(vtkCommand::StartEvent);
    ++this->NumberOfLoads;
    this->Invalidate();
    vtkErrorMacro(<< "Nothing to load: no FileName is set, no input is connected and no "
                     "in-memory data was given");
    recordFailure();
    return false;
  }
  if (in.Source == vtkInternals::File &&
    (!this->Valid || now.FileSize != in.LastLoad.FileSize ||
      now.FileTime != in.LastLoad.FileTime))
  {
    // A file rewritten in place, or one that failed and changed since, is read again.
    in.Reader->Modified();
  }
  if (in.Source == vtkInternals::File && this->Streaming != StreamingOff)
  {
    now.Streamed = this->Streaming == StreamingOn;
    if (!now.Streamed && (in.Reader->UpdateInformation(), !*in.Reader->GetLastError()))
    {
      // Auto: the header's size decides (a bad header fails in the whole-raster path below).
      int whole[6];
      in.Reader->GetOutputInformation(0)->Get(
        vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
      now.Streamed = whole[1] - whole[0] + 1 > this->StreamingThreshold ||
        whole[3] - whole[2] + 1 > this->StreamingThreshold;
    }
  }
  // A load that throws is a failed load, reported with the reason.
  const auto guarded = [this](const std::function<bool()>& load) {
    try
    {
      return load();
    }
    catch (const std::exception& e)
    {
      const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
      vtkErrorMacro(<< "Cannot load " << this->DescribeSource() << ": "
                    << (memory ? std::string("not enough memory") : std::string(e.what())));
      return false;
    }
  };
  if (now.Streamed)
  {
    if (this->Valid && now == in.LastLoad)
    {
      return true;
    }
    if (in.Streamed && onlyValueMapChanged() &&
      this->StoredPagesMap(now.ValueScale, now.ValueOffset))
    {
      in.LastLoad = now; // the stored pages stay, mapped when read
      return true;
    }
    this->InvokeEvent(vtkCommand::StartEvent); // page readers let go of this layer
    ++this->NumberOfLoads;
    this->Invalidate();
    const bool ok = guarded([this]() { return this->LoadStreamed(); });
    if (!ok)
    {
      this->Invalidate();
      recordFailure();
      return false;
    }
    this->Valid = true;
    in.Streamed = true;
    in.LastLoad = now;
    return true;
  }

  // Bring the input up to date: upstream algorithms re-execute only when they, or what they
  // depend on, were modified since they last ran.
  in.Sink->Modified();
  in.Sink->UpdateTime = this->UpdateTime;
  auto* executive = vtkStreamingDemandDrivenPipeline::SafeDownCast(in.Sink->GetExecutive());
  bool updated = false;
  try
  {
    updated = executive && executive->UpdateWholeExtent() != 0;
  }
  catch (const std::exception&)
  {
    updated = false;
  }
  vtkDataObject* input =
    in.Sink->GetNumberOfInputConnections(0) > 0 ? in.Sink->GetInputDataObject(0, 0) : nullptr;
  now.InputData = input;
  now.InputTime = input ? std::max(input->GetUpdateTime(), input->GetMTime()) : 0;
  if (this->Valid && now == in.LastLoad)
  {
    return true; // nothing the data depends on changed (e.g. only the Name)
  }
  if (!in.Streamed && onlyValueMapChanged() &&
    this->Rescale(in.LastLoad.ValueScale, in.LastLoad.ValueOffset))
  {
    in.LastLoad = now; // the heights were mapped in place, nothing read
    return true;
  }

  this->InvokeEvent(vtkCommand::StartEvent);
  ++this->NumberOfLoads;
  this->Invalidate();
  bool ok = false;
  if (!updated)
  {
    this->ReportInputFailure();
  }
  else
  {
    ok = guarded([this, input]() { return this->Load(vtkImageData::SafeDownCast(input)); });
  }
  if (!ok)
  {
    this->Invalidate();
    recordFailure();
    return false;
  }
  this->Valid = true;
  in.LastLoad = now;
  vtkInformation* dataInfo = input ? input->GetInformation() : nullptr;
  this->DataTime = dataInfo && dataInfo->Has(vtkDataObject::DATA_TIME_STEP())
    ? dataInfo->Get(vtkDataObject::DATA_TIME_STEP())
    : std::numeric_limits<double>::quiet_NaN();
  this->ValuesTime = in.Data ? in.Data->GetMTime() : 0;
  this->RescaledTime = 0;
  // After the run: an algorithm may modify itself while it executes (its error code).
  in.LastLoad.UpstreamTime = upstreamTime();
  return true;
}

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::Rescale(double fromScale, double fromOffset)
{
  auto* values = vtkFloatArray::SafeDownCast(this->Internals->Data);
  double map[2];
  if (!values || this->NumberOfImplausibleValues > 0 ||
    !ValueMap(fromScale, fromOffset, this->ValueScale, this->ValueOffset, map))
  {
    return false;
  }
  // An affine map, which commutes with the void fill's and the MIP levels' weighted means.
  const double a = map[0], b = map[1];
  // As a load computes them: from the values stored as float.
  const double lo = static_cast<float>(this->MinimumValue * a + b);
  const double hi = static_cast<float>(this->MaximumValue * a + b);
  const double minimum = std::min(lo, hi), maximum = std::max(lo, hi);
  if (!(minimum >= this->PlausibleRange[0] && maximum <= this->PlausibleRange[1]))
  {
    return false; // some heights would become voids: a load decides which
  }
  if (values->GetMTime() != this->RescaledTime)
  {
    this->ValuesTime = values->GetMTime(); // the first rescale since a load or an edit
  }
  float* v = values->GetPointer(0);
  const vtkIdType n = values->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    v[i] = static_cast<float>(static_cast<double>(v[i]) * a + b); // NaN voids stay NaN
  }
  this->MinimumValue = minimum;
  this->MaximumValue = maximum;
  values->Modified();
  this->RescaledTime = values->GetMTime();
  return true;
}

bool vtkGlobeLayer::ValueMap(
  double fromScale, double fromOffset, double toScale, double toOffset, double map[2])
{
  map[0] = 1.0;
  map[1] = 0.0;
  if (fromScale == toScale && fromOffset == toOffset)
  {
    return true;
  }
  if (fromScale == 0.0 || !std::isfinite(fromScale) || !std::isfinite(fromOffset) ||
    !std::isfinite(toScale) || !std::isfinite(toOffset))
  {
    return false;
  }
  // Raw = (v - fromOffset) / fromScale, so v' = raw * toScale + toOffset.
  map[0] = toScale / fromScale;
  map[1] = toOffset - fromOffset * map[0];
  return true;
}

bool vtkGlobeLayer::IsRescaledSince(vtkMTimeType time)
{
  vtkDataArray* data = this->Internals->Data;
  return data && this->RescaledTime != 0 && data->GetMTime() == this->RescaledTime &&
    time >= this->ValuesTime;
}

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::LoadStreamed()
{
  vtkInternals& in = *this->Internals;
  const std::string what = this->DescribeSource();
  // The header and the north row give the georeferencing; the values come page by page.
  in.Reader->UpdateInformation();
  if (*in.Reader->GetLastError())
  {
    this->ReportInputFailure();
    return false;
  }
  int whole[6];
  in.Reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  const int rows = whole[3] - whole[2] + 1;
  int north[6] = { whole[0], whole[1], whole[3], whole[3], whole[4], whole[4] };
  if (rows <= 0 || !in.Reader->UpdateExtent(north) || *in.Reader->GetLastError())
  {
    this->ReportInputFailure();
    return false;
  }
  if (!this->Load(in.Reader->GetOutput(), rows))
  {
    return false;
  }
  vtkGlobePageSource* pages = in.Pages;
  pages->SetFileName(this->FileName);
  // Opened afresh: the file may have been rewritten in place, or have failed before (the
  // page readers let go at StartEvent).
  pages->Modified();
  const int levels = pages->GetNumberOfLevels(); // opens the file (errors name it)
  if (levels <= 0)
  {
    vtkErrorMacro(<< "Cannot load " << what << " as a streamed layer: its pages cannot be read");
    return false;
  }
  if (pages->GetNumberOfColumns() != this->RasterWidth || pages->GetNumberOfRows() != this->RasterHeight)
  {
    vtkErrorMacro(<< "Cannot load " << what << " as a streamed layer: the page source reads "
                  << pages->GetNumberOfColumns() << " x " << pages->GetNumberOfRows() << " texels, the header "
                  << this->RasterWidth << " x " << this->RasterHeight);
    return false;
  }
  if ((pages->GetNumberOfComponents() == 1) != (this->Role == Height))
  {
    vtkErrorMacro(<< "Cannot load " << what << " as a streamed " << this->GetRoleAsString()
                  << " layer: it has " << pages->GetNumberOfComponents() << " channel(s); "
                  << "streamed heights need 1, streamed images 3 or 4 (set Streaming to Off)");
    return false;
  }
  {
    std::lock_guard<std::mutex> lock(in.ValuesMutex);
    in.Values.Scale = this->ValueScale;
    in.Values.Offset = this->ValueOffset;
    in.Values.Minimum = this->PlausibleRange[0];
    in.Values.Maximum = this->PlausibleRange[1];
    // Page values are floats: an overridden nodata compares as a float sample holds it.
    float noData = 0.0f;
    in.Values.OverriddenNoData = this->NoDataValueOverridden && this->HasNoDataValue &&
      vtkGlobeRasterSamples::NoDataAs(this->NoDataValue, noData);
    in.Values.NoData = noData;
    in.Values.Fill = this->FillVoids;
    in.Values.Low = 1.0;
    in.Values.High = -1.0;
  }
  in.Streamed = true; // ReadPage below needs it
  // The coarsest level is one page: its range (ReadPage records it) bounds the first frame.
  if (this->Role == Height)
  {
    vtkNew<vtkFloatArray> page;
    if (!this->ReadStoredPage(levels - 1, 0, 0, page))
    {
      in.Streamed = false;
      return false;
    }
  }
  return true;
}

double vtkGlobeLayer::GetMinimumValue()
{
  this->FoldPageRange();
  return this->MinimumValue;
}

double vtkGlobeLayer::GetMaximumValue()
{
  this->FoldPageRange();
  return this->MaximumValue;
}

void vtkGlobeLayer::FoldPageRange()
{
  vtkInternals& in = *this->Internals;
  if (!in.Streamed || this->Role != Height)
  {
    return;
  }
  std::lock_guard<std::mutex> lock(in.ValuesMutex);
  if (in.Values.Low <= in.Values.High)
  {
    // The stored pages' range, in today's ValueScale and ValueOffset.
    double map[2];
    ValueMap(in.Values.Scale, in.Values.Offset, this->ValueScale, this->ValueOffset, map);
    const double lo = in.Values.Low * map[0] + map[1], hi = in.Values.High * map[0] + map[1];
    this->MinimumValue = std::min(lo, hi);
    this->MaximumValue = std::max(lo, hi);
  }
}

bool vtkGlobeLayer::StoredPagesMap(double scale, double offset)
{
  vtkInternals& in = *this->Internals;
  std::lock_guard<std::mutex> lock(in.ValuesMutex);
  double map[2];
  if (!ValueMap(in.Values.Scale, in.Values.Offset, scale, offset, map))
  {
    return false;
  }
  if (in.Values.Low <= in.Values.High)
  {
    const double lo = in.Values.Low * map[0] + map[1], hi = in.Values.High * map[0] + map[1];
    if (!(std::min(lo, hi) >= this->PlausibleRange[0] &&
          std::max(lo, hi) <= this->PlausibleRange[1]))
    {
      return false; // pages read so far would hold implausible heights: read them again
    }
  }
  return true;
}

std::pair<double, double> vtkGlobeLayer::GetStoredValueMap()
{
  vtkInternals& in = *this->Internals;
  if (!in.Streamed)
  {
    return { this->ValueScale, this->ValueOffset };
  }
  std::lock_guard<std::mutex> lock(in.ValuesMutex);
  return { in.Values.Scale, in.Values.Offset };
}

double vtkGlobeLayer::GetStoredValueScale()
{
  return this->GetStoredValueMap().first;
}

double vtkGlobeLayer::GetStoredValueOffset()
{
  return this->GetStoredValueMap().second;
}

bool vtkGlobeLayer::IsStreamed()
{
  return this->Valid && this->Internals->Streamed;
}

vtkGlobePageSource* vtkGlobeLayer::GetPageSource()
{
  return this->Internals->Pages;
}

bool vtkGlobeLayer::ReadPage(int level, int column, int row, vtkDataArray* page)
{
  if (!this->ReadStoredPage(level, column, row, page))
  {
    return false;
  }
  auto* heights = vtkFloatArray::SafeDownCast(page);
  const auto stored = this->GetStoredValueMap();
  double map[2];
  ValueMap(stored.first, stored.second, this->ValueScale, this->ValueOffset, map);
  if (heights && (map[0] != 1.0 || map[1] != 0.0))
  {
    float* v = heights->GetPointer(0);
    for (vtkIdType i = 0, n = heights->GetNumberOfValues(); i < n; ++i)
    {
      v[i] = static_cast<float>(v[i] * map[0] + map[1]); // NaN voids stay NaN
    }
  }
  return true;
}

bool vtkGlobeLayer::ReadStoredPage(int level, int column, int row, vtkDataArray* page)
{
  vtkInternals& in = *this->Internals;
  if (!in.Streamed)
  {
    vtkErrorMacro(<< "ReadPage: " << this->DescribeSource() << " is not a streamed layer");
    return false;
  }
  if (!in.Pages->ReadPage(level, column, row, page))
  {
    return false;
  }
  auto* heights = vtkFloatArray::SafeDownCast(page);
  if (!heights)
  {
    return true; // RGBA as read
  }
  vtkInternals::PageValues v;
  {
    std::lock_guard<std::mutex> lock(in.ValuesMutex);
    v = in.Values;
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  float* values = heights->GetPointer(0);
  bool voids = false;
  double low = VTK_DOUBLE_MAX, high = -VTK_DOUBLE_MAX;
  for (vtkIdType i = 0, n = heights->GetNumberOfValues(); i < n; ++i)
  {
    const double raw = values[i];
    if (std::isnan(raw) || (v.OverriddenNoData && raw == v.NoData))
    {
      values[i] = nan;
      voids = true;
      continue;
    }
    const double h = raw * v.Scale + v.Offset;
    values[i] = h >= v.Minimum && h <= v.Maximum ? static_cast<float>(h) : nan;
    voids |= std::isnan(values[i]);
    if (!std::isnan(values[i]))
    {
      low = std::min(low, static_cast<double>(values[i]));
      high = std::max(high, static_cast<double>(values[i]));
    }
  }
  if (low <= high)
  {
    // Filled voids lie within the valid values around them: the range is final here.
    std::lock_guard<std::mutex> lock(in.ValuesMutex);
    const bool any = in.Values.Low <= in.Values.High;
    in.Values.Low = any ? std::min(in.Values.Low, low) : low;
    in.Values.High = any ? std::max(in.Values.High, high) : high;
  }
  vtkGlobePageSource* pages = in.Pages;
  if (!voids || !v.Fill)
  {
    return true;
  }
  if (level + 1 >= pages->GetNumberOfLevels())
  {
    // (A page of voids only, e.g. all sea, is filled from its parent below; only here, with
    // no parent, is there nothing to fill it from.)
    if (std::all_of(values, values + heights->GetNumberOfValues(), [](float x) { return std::isnan(x); }))
    {
      return true;
    }
    // The coarsest level is this one page: the whole push-pull fill, as for whole layers.
    const int T = pages->GetPageTexels();
    std::vector<float> page(values, values + static_cast<size_t>(T) * T);
    PushPullFill(page, T, T);
    std::copy(page.begin(), page.end(), values);
    return true;
  }
  // Push: each void takes the bilinear value of the filled level above at its centre. The
  // parent page (column / 2, row / 2) holds this page and its border within its own border.
  vtkNew<vtkFloatArray> parent;
  if (!this->ReadStoredPage(level + 1, column / 2, row / 2, parent))
  {
    return true; // the voids stay voids
  }
  const int P = pages->GetPageSize(), B = pages->GetBorder(), T = pages->GetPageTexels();
  int size[2], up[2];
  pages->GetLevelSize(level, size);
  pages->GetLevelSize(level + 1, up);
  const float* above = parent->GetPointer(0);
  for (int j = 0; j < T; ++j)
  {
    for (int i = 0; i < T; ++i)
    {
      float& out = values[static_cast<size_t>(j) * T + i];
      if (!std::isnan(out))
      {
        continue;
      }
      // Texel centre in this level -> texel coordinates in the parent page.
      const double x = (column * P + i - B + 0.5) * up[0] / size[0] - 0.5 - (column / 2) * P + B;
      const double y = (row * P + j - B + 0.5) * up[1] / size[1] - 0.5 - (row / 2) * P + B;
      const int x0 = std::clamp(static_cast<int>(std::floor(x)), 0, T - 2);
      const int y0 = std::clamp(static_cast<int>(std::floor(y)), 0, T - 2);
      const double fx = std::clamp(x - x0, 0.0, 1.0), fy = std::clamp(y - y0, 0.0, 1.0);
      double sum = 0.0, weight = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        const int dx = k & 1, dy = k >> 1;
        const float a = above[static_cast<size_t>(y0 + dy) * T + x0 + dx];
        const double w = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
        if (!std::isnan(a) && w > 0.0)
        {
          sum += w * a;
          weight += w;
        }
      }
      if (weight > 0.0)
      {
        out = static_cast<float>(sum / weight);
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------------------
std::string vtkGlobeLayer::DescribeSource()
{
  vtkInternals& in = *this->Internals;
  switch (in.Source)
  {
    case vtkInternals::File:
      return "'" + std::string(this->FileName) + "'";
    case vtkInternals::Memory:
      return in.MemoryRole == Height ? "in-memory height data" : "in-memory color data";
    default:
    {
      vtkDataObject* input =
        in.Sink->GetNumberOfInputConnections(0) > 0 ? in.Sink->GetInputDataObject(0, 0) : nullptr;
      const std::string file = FieldString(input ? input->GetFieldData() : nullptr,
        vtkGlobeRasterReader::GetFileNameArrayName());
      if (file.empty())
      {
        // A display name (ParaView's for its source, say) is better than none.
        return this->Name && *this->Name ? "'" + std::string(this->Name) + "' (the layer's input)"
                                         : std::string("the layer's input");
      }
      return "'" + file + "' (the layer's input)";
    }
  }
}

void vtkGlobeLayer::ReportInputFailure()
{
  vtkInternals& in = *this->Internals;
  if (in.Source == vtkInternals::File)
  {
    const std::string why = in.Reader->GetLastError();
    vtkErrorMacro(<< "Cannot load '" << this->FileName
                  << "': " << (why.empty() ? std::string("it could not be read") : why));
    return;
  }
  // The first reader up the pipeline that says why.
  vtkAlgorithm* algorithm = this->GetInputAlgorithm();
  for (int depth = 0; algorithm && depth < 64; ++depth)
  {
    auto* reader = vtkGlobeRasterReader::SafeDownCast(algorithm);
    if (reader && *reader->GetLastError())
    {
      vtkErrorMacro(<< "Cannot load the layer's input: '"
                    << (reader->GetFileName() ? reader->GetFileName() : "") << "' "
                    << reader->GetLastError());
      return;
    }
    algorithm = algorithm->GetNumberOfInputPorts() > 0 &&
        algorithm->GetNumberOfInputConnections(0) > 0
      ? algorithm->GetInputAlgorithm(0, 0)
      : nullptr;
  }
  vtkAlgorithm* first = this->GetInputAlgorithm();
  vtkErrorMacro(<< "Cannot load the layer's input: its pipeline failed to update"
                << (first ? std::string(" (") + first->GetClassName() + " and upstream)" : "")
                << "; see their errors");
}

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::Load(vtkImageData* image, int streamedRows)
{
  vtkInternals& in = *this->Internals;
  const std::string what = this->DescribeSource();
  const auto fail = [this, &what](const std::string& why)
  {
    vtkErrorMacro(<< "Cannot load " << what << ": " << why);
    return false;
  };
  if (this->Role == Height &&
    (!std::isfinite(this->ValueScale) || !std::isfinite(this->ValueOffset)))
  {
    char text[160];
    std::snprintf(text, sizeof(text), "ValueScale and ValueOffset must be finite (%g, %g)",
      this->ValueScale, this->ValueOffset);
    return fail(text);
  }
  if (in.Source == vtkInternals::Memory && (in.MemoryRole == Height) != (this->Role == Height))
  {
    vtkErrorMacro(<< "Cannot load " << what << " as a " << this->GetRoleAsString()
                  << " layer: the role does not match the data");
    return false;
  }
  if (!image)
  {
    return fail("it is not a vtkImageData");
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int extent[6];
  image->GetExtent(extent);
  const int width = extent[1] - extent[0] + 1;
  const int imageRows = extent[3] - extent[2] + 1;
  // Streamed: the image is the north row only, of a raster streamedRows high.
  const bool streamed = streamedRows > 0;
  const int height = streamed ? streamedRows : imageRows;
  if (width <= 0 || imageRows <= 0 || extent[5] != extent[4] || !scalars ||
    scalars->GetNumberOfTuples() != static_cast<vtkIdType>(width) * imageRows)
  {
    return fail("it is not a 2D image with point scalars (" + std::to_string(width) + " x " +
      std::to_string(height) + " x " + std::to_string(extent[5] - extent[4] + 1) + " points, " +
      (scalars ? "with" : "without") + " point scalars)");
  }
  const int channels = scalars->GetNumberOfComponents();
  if (this->Role == Height && channels != 1)
  {
    return fail("a Height layer needs a 1-channel raster, and it has " + std::to_string(channels) +
      " channels");
  }
  // A mask may be a single grey channel (1 = water); the other images are RGB or RGBA.
  const bool grey = this->Role == Mask && channels == 1;
  if (this->Role != Height && channels != 3 && channels != 4 && !grey)
  {
    return fail(std::string("a ") + this->GetRoleAsString() +
      " layer needs a 3-channel (RGB) or 4-channel (RGBA) raster" +
      (this->Role == Mask ? " or a 1-channel mask" : "") + ", and it has " +
      std::to_string(channels) + " channel" + (channels == 1 ? "" : "s"));
  }
  // The layer's own copy (float heights, or the 8-bit pixels and their RGBA) is held to the
  // memory budget of its file reader, also for in-memory data and pipeline input.
  const double copyBytes =
    static_cast<double>(width) * height * (this->Role == Height ? 4.0 : 4.0 + channels);
  const int budget = in.Reader->GetMaximumMemory();
  if (!streamed && copyBytes > budget * 1024.0 * 1024.0)
  {
    char text[400];
    std::snprintf(text, sizeof(text),
      "its %d x %d copy in the layer needs %.1f MiB, more than MaximumMemory (%d MiB) allows "
      "(the layer's file reader's setting: raise it with GetFileReader()->SetMaximumMemory)",
      width, height, copyBytes / (1024.0 * 1024.0), budget);
    return fail(text);
  }

  // Georeferencing: the grid from the image's geometry (filters that crop or resample keep it
  // right), the rest from the reader's field data.
  vtkFieldData* fd = image->GetFieldData();
  double modelType = 0.0, epsg = 0.0;
  if (!FieldValue(fd, vtkGlobeRasterReader::GetModelTypeArrayName(), 0, modelType))
  {
    return fail(std::string("it has no georeferencing: its field data has no ") +
      vtkGlobeRasterReader::GetModelTypeArrayName() +
      " array (read it with vtkGlobeRasterReader, and keep its field data through the filters)");
  }
  if (modelType != Geographic && modelType != Projected)
  {
    return fail("its model type (" + std::to_string(modelType) +
      ") is neither geographic (1) nor projected (2)");
  }
  FieldValue(fd, vtkGlobeRasterReader::GetEPSGArrayName(), 0, epsg);
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  if (!(spacing[0] > 0.0) || !(spacing[1] > 0.0) || !std::isfinite(origin[0]) ||
    !std::isfinite(origin[1]) || !std::isfinite(spacing[0]) || !std::isfinite(spacing[1]))
  {
    return fail("its spacing must be positive and its origin finite");
  }
  double t[4] = { origin[0] + (extent[0] - 0.5) * spacing[0],
    origin[1] + (extent[3] + 0.5) * spacing[1], spacing[0], spacing[1] };
  double field[4];
  bool hasField = true;
  for (int i = 0; i < 4; ++i)
  {
    hasField =
      hasField && FieldValue(fd, vtkGlobeRasterReader::GetGeoTransformArrayName(), i, field[i]);
  }
  // The reader's exact numbers when the grid is still the one it read.
  const bool sameGrid = hasField && std::abs(field[0] - t[0]) <= 1e-6 * t[2] &&
    std::abs(field[1] - t[1]) <= 1e-6 * t[3] && std::abs(field[2] - t[2]) <= 1e-12 * t[2] &&
    std::abs(field[3] - t[3]) <= 1e-12 * t[3];
  if (sameGrid)
  {
    std::copy(field, field + 4, t);
  }
  if (modelType == Geographic)
  {
    double west = t[0], east = t[0] + width * t[2];
    double north = t[1], south = t[1] - height * t[3];
    double box[4];
    bool hasBox = sameGrid;
    for (int i = 0; i < 4; ++i)
    {
      hasBox = hasBox &&
        FieldValue(fd, vtkGlobeRasterReader::GetGeographicExtentArrayName(), i, box[i]);
    }
    if (hasBox)
    {
      west = box[0];
      east = box[1];
      south = box[2];
      north = box[3];
    }
    if (south < -90.0 - t[3] || north > 90.0 + t[3] || east - west > 360.0 + t[2])
    {
      char text[200];
      std::snprintf(text, sizeof(text),
        "its geographic extent (west %g, east %g, south %g, north %g) is not a box in degrees",
        west, east, south, north);
      return fail(text);
    }
    in.Extent[0] = west;
    in.Extent[1] = east;
    in.Extent[2] = south;
    in.Extent[3] = north;
  }
  double noData = 0.0;
  const bool fileNoData =
    FieldValue(fd, vtkGlobeRasterReader::GetNoDataValueArrayName(), 0, noData);
  if (!this->NoDataValueOverridden)
  {
    this->HasNoDataValue = fileNoData;
    this->NoDataValue = fileNoData ? noData : 0.0;
  }
  const bool hasNoData = this->HasNoDataValue;
  noData = this->NoDataValue;

  // Values, row 0 north.
  const size_t n = static_cast<size_t>(width) * height;
  if (streamed)
  {
    this->NumberOfComponents = this->Role == Height ? 1 : 4;
  }
  else if (this->Role == Height)
  {
    std::vector<float> heights;
    switch (scalars->GetDataType())
    {
      vtkTemplateMacro(SamplesToFloat(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)),
        width, height, hasNoData, noData, heights));
      default:
        return fail(std::string("its sample type (") + scalars->GetDataTypeAsString() +
          ") is not supported for heights");
    }
    std::string why;
    Implausible implausible;
    if (!FinishHeights(heights, width, height, this->ValueScale, this->ValueOffset,
          this->PlausibleRange, this->FillVoids, this->NumberOfVoids, implausible,
          this->MinimumValue, this->MaximumValue, why, in.Data))
    {
      return fail(why);
    }
    this->NumberOfImplausibleValues = implausible.Count;
    if (implausible.Count > 0)
    {
      // Once per load: loads happen only when the data or a setting changed.
      const std::string who =
        this->Name ? "layer '" + std::string(this->Name) + "' (" + what + ")" : what;
      vtkWarningMacro(<< who << ": " << implausible.Count << " of " << n
                      << " heights lie outside the plausible range [" << this->PlausibleRange[0]
                      << ", " << this->PlausibleRange[1] << "] m (e.g. " << implausible.Worst
                      << " m); they are treated as voids");
    }
    this->NumberOfComponents = 1;
  }
  else
  {
    std::vector<unsigned char> pixels(n * channels);
    auto* bytes = vtkUnsignedCharArray::SafeDownCast(scalars);
    for (int r = 0; r < height; ++r)
    {
      const vtkIdType from = static_cast<vtkIdType>(height - 1 - r) * width;
      unsigned char* dst = pixels.data() + static_cast<size_t>(r) * width * channels;
      if (bytes)
      {
        std::memcpy(dst, bytes->GetPointer(from * channels), static_cast<size_t>(width) * channels);
        continue;
      }
      // Other types (a filter's output): clamped and rounded to 8 bits.
      for (int i = 0; i < width * channels; ++i)
      {
        const double v = scalars->GetComponent(from + i / channels, i % channels);
        dst[i] = static_cast<unsigned char>(std::isnan(v) ? 0.0 : std::clamp(std::round(v), 0.0, 255.0));
      }
    }
    if (grey)
    {
      std::vector<unsigned char> rgb(n * 3);
      for (size_t i = 0; i < n; ++i)
      {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = pixels[i];
      }
      pixels.swap(rgb);
    }
    FinishColors(pixels, n, grey ? 3 : channels, hasNoData, noData, this->NumberOfVoids, in.Data);
    this->NumberOfComponents = 4;
  }
  this->RasterWidth = width;
  this->RasterHeight = height;
  this->ModelType = static_cast<int>(modelType);
  this->EPSG = static_cast<int>(epsg);
  double axis = 0.0;
  if (FieldValue(fd, vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 0, axis))
  {
    this->DatumSemiMajorAxis = axis;
    FieldValue(fd, vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 1, axis);
    this->DatumSemiMinorAxis = axis;
  }
  in.Origin[0] = t[0];
  in.Origin[1] = t[1];
  in.PixelSize[0] = t[2];
  in.PixelSize[1] = t[3];
  this->ReprojectedFromEPSG = 0;
  this->ReprojectedFromCRS.clear();
  // A projected CRS without an EPSG code: its definition (the reader's GlobeCRS).
  this->CRSDefinition = this->ModelType == Projected && this->EPSG <= 0
    ? FieldString(fd, vtkGlobeRasterReader::GetCRSDefinitionArrayName())
    : std::string();
  const bool byDefinition = !this->CRSDefinition.empty();
  if (this->ModelType == Projected &&
    ((this->EPSG > 0 && !vtkGlobeMapProjection::IsSupportedEPSG(this->EPSG)) ||
      (byDefinition &&
        !vtkGlobeMapProjection::IsSupportedDefinition(this->CRSDefinition.c_str()))))
  {
    // A CRS the GPU does not project: resampled into a geographic grid, once per load.
    const std::string crs =
      byDefinition ? this->CRSDefinition : "EPSG:" + std::to_string(this->EPSG);
    const std::string named = byDefinition ? "its CRS '" + crs + "'" : crs;
    if (streamed)
    {
      return fail(named +
        " is not a projection the globe draws directly, and a streamed layer cannot be "
        "reprojected on load (set Streaming Off, or reproject the file)");
    }
    vtkGlobeReprojection::Grid grid;
    vtkSmartPointer<vtkDataArray> reprojected;
    std::string why;
    const double origin2[2] = { t[0], t[1] }, pixel2[2] = { t[2], t[3] };
    if (!vtkGlobeReprojection::ToGeographic(crs, origin2, pixel2, width, height, in.Data,
          this->Interpolation == Nearest, budget * 1024.0 * 1024.0, reprojected, grid, why))
    {
      return fail(named + " cannot be reprojected: " + why);
    }
    vtkLogF(INFO, "%s: %s is reprojected on load into a %d x %d geographic grid of %.6g x %.6g "
                  "degrees (from %d x %d texels)",
      what.c_str(), named.c_str(), grid.Width, grid.Height, grid.DLon, grid.DLat, width, height);
    in.Data = reprojected;
    this->ReprojectedFromEPSG = this->EPSG;
    this->ReprojectedFromCRS = this->CRSDefinition;
    this->CRSDefinition.clear();
    this->ModelType = Geographic;
    this->EPSG = 4326;
    this->RasterWidth = grid.Width;
    this->RasterHeight = grid.Height;
    in.Origin[0] = grid.West;
    in.Origin[1] = grid.North;
    in.PixelSize[0] = grid.DLon;
    in.PixelSize[1] = grid.DLat;
    in.Extent[0] = grid.West;
    in.Extent[1] = grid.West + grid.Width * grid.DLon;
    in.Extent[2] = grid.North - grid.Height * grid.DLat;
    in.Extent[3] = grid.North;
    // PROJ shifted the source datum: the grid is WGS 84's, as other EPSG:4326 layers.
    this->DatumSemiMajorAxis = this->DatumSemiMinorAxis = 0.0;
  }
  // Once per load: whether it wraps east-west (asked every frame).
  in.Global = (this->ModelType == Geographic || this->ModelType == Projected) &&
    vtkGlobeMapProjection::IsGlobalRaster(
      this->ModelType == Geographic, this->EPSG, in.PixelSize[0], this->RasterWidth);
  if (in.Source == vtkInternals::Input && !this->FileName)
  {
    const std::string file = FieldString(fd, vtkGlobeRasterReader::GetFileNameArrayName());
    in.DefaultName = file.empty() ? std::string() : std::filesystem::path(file).stem().string();
  }
  return true;
}

//------------------------------------------------------------------------------------------
const char* vtkGlobeLayer::GetCRSDefinition()
{
  return this->CRSDefinition.c_str();
}

const char* vtkGlobeLayer::GetReprojectedFromCRS()
{
  return this->ReprojectedFromCRS.c_str();
}

bool vtkGlobeLayer::IsReprojected()
{
  return this->ReprojectedFromEPSG != 0 || !this->ReprojectedFromCRS.empty();
}

bool vtkGlobeLayer::GetMapProjection(vtkGlobeMapProjection* projection)
{
  if (!projection || this->ModelType != Projected)
  {
    return false;
  }
  // Quiet: the callers name the layer in their own messages.
  const bool warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  // (A refused CRS leaves the projection unchanged; its message is silenced above.)
  const bool set = this->EPSG > 0 ? projection->SetFromEPSG(this->EPSG)
                                  : projection->SetFromDefinition(this->CRSDefinition.c_str());
  vtkObject::SetGlobalWarningDisplay(warnings);
  const double a = this->DatumSemiMajorAxis, b = this->DatumSemiMinorAxis;
  if (set && a > 0.0 && b > 0.0 && b <= a)
  {
    projection->SetEllipsoid(a, (a - b) / a);
  }
  return set;
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::SetMemoryImage(int role, int width, int height, int components,
  int scalarType, const void* values, const double extent[4])
{
  vtkInternals& in = *this->Internals;
  vtkNew<vtkImageData> image;
  const double dx = (extent[1] - extent[0]) / width, dy = (extent[3] - extent[2]) / height;
  image->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  image->SetSpacing(dx, dy, 1.0);
  image->SetOrigin(extent[0] + 0.5 * dx, extent[2] + 0.5 * dy, 0.0);
  image->AllocateScalars(scalarType, components);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  scalars->SetName(role == Height ? "Height" : "Color");
  // Given north first; VTK images are south first.
  const size_t row = static_cast<size_t>(width) * components * scalars->GetDataTypeSize();
  for (int r = 0; r < height; ++r)
  {
    std::memcpy(static_cast<unsigned char*>(scalars->GetVoidPointer(0)) + row * (height - 1 - r),
      static_cast<const unsigned char*>(values) + row * r, row);
  }
  vtkNew<vtkIntArray> model;
  model->SetName(vtkGlobeRasterReader::GetModelTypeArrayName());
  model->InsertNextValue(Geographic);
  image->GetFieldData()->AddArray(model);
  vtkNew<vtkIntArray> epsg;
  epsg->SetName(vtkGlobeRasterReader::GetEPSGArrayName());
  epsg->InsertNextValue(0);
  image->GetFieldData()->AddArray(epsg);
  vtkNew<vtkDoubleArray> transform;
  transform->SetName(vtkGlobeRasterReader::GetGeoTransformArrayName());
  for (double v : { extent[0], extent[3], dx, dy })
  {
    transform->InsertNextValue(v);
  }
  image->GetFieldData()->AddArray(transform);
  vtkNew<vtkDoubleArray> box;
  box->SetName(vtkGlobeRasterReader::GetGeographicExtentArrayName());
  for (int i = 0; i < 4; ++i)
  {
    box->InsertNextValue(extent[i]);
  }
  image->GetFieldData()->AddArray(box);
  in.Sink->SetInputDataObject(image);
  in.MemoryRole = role;
  in.SetSource(vtkInternals::Memory);
  this->SetRole(role);
  this->Update();
}

bool vtkGlobeLayer::StartMemoryData(const char* method, const char* what, int width, int height,
  const void* values, const double extent[4])
{
  vtkInternals& in = *this->Internals;
  // In-memory data replaces the file and any input.
  this->SetFileName(nullptr);
  in.Sink->SetInputConnection(nullptr);
  in.SetSource(vtkInternals::None);
  this->Invalidate();
  this->Modified();
  std::string why;
  if (!CheckMemoryInput(width, height, values, why) ||
    !CheckExtent(extent[0], extent[1], extent[2], extent[3], why))
  {
    vtkErrorMacro(<< method << ": rejected in-memory " << what << ": " << why);
    return false;
  }
  return true;
}

void vtkGlobeLayer::SetHeightData(
  int width, int height, const float* values, double west, double east, double south, double north)
{
  const double extent[4] = { west, east, south, north };
  if (this->StartMemoryData("SetHeightData", "height data", width, height, values, extent))
  {
    this->SetMemoryImage(Height, width, height, 1, VTK_FLOAT, values, extent);
  }
}

void vtkGlobeLayer::SetColorData(int width, int height, int components, const unsigned char* values,
  double west, double east, double south, double north)
{
  const double extent[4] = { west, east, south, north };
  if (!this->StartMemoryData("SetColorData", "color data", width, height, values, extent))
  {
    return;
  }
  if (components != 3 && components != 4)
  {
    vtkErrorMacro(<< "SetColorData: rejected in-memory color data: " << components
                  << " components per pixel; 3 (RGB) or 4 (RGBA) are needed");
    return;
  }
  this->SetMemoryImage(Color, width, height, components, VTK_UNSIGNED_CHAR, values, extent);
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& in = *this->Internals;
  static const char* const sources[] = { "(none)", "file", "in-memory data", "pipeline input" };
  os << indent << "Name: " << this->GetName() << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Source: " << sources[in.Source] << "\n";
  os << indent << "Role: " << this->GetRoleAsString() << "\n";
  os << indent << "ValueScale: " << this->ValueScale << "\n";
  os << indent << "ValueOffset: " << this->ValueOffset << "\n";
  os << indent << "NoDataValue: ";
  if (this->HasNoDataValue)
  {
    os << this->NoDataValue;
  }
  else
  {
    os << "(none)";
  }
  os << (this->NoDataValueOverridden ? " (set by the user)" : " (from the file)") << "\n";
  os << indent << "FillVoids: " << (this->FillVoids ? "On" : "Off") << "\n";
  os << indent << "Enabled: " << (this->Enabled ? "On" : "Off") << "\n";
  os << indent << "DrawOrder: " << this->DrawOrder << "\n";
  os << indent << "Opacity: " << this->Opacity << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "ValidRange: " << this->ValidRange[0] << " .. " << this->ValidRange[1] << "\n";
  os << indent << "PlausibleRange: " << this->PlausibleRange[0] << " .. " << this->PlausibleRange[1]
     << "\n";
  os << indent << "NumberOfImplausibleValues: " << this->NumberOfImplausibleValues << "\n";
  os << indent << "BlendMode: " << this->GetBlendModeAsString() << "\n";
  os << indent << "FeatherWidth: " << this->FeatherWidth << "\n";
  os << indent << "FeatherDistance: " << this->FeatherDistance << " m\n";
  os << indent << "SkirtDistance: ";
  if (this->SkirtDistance < 0.0)
  {
    os << "automatic\n";
  }
  else
  {
    os << this->SkirtDistance << " m\n";
  }
  os << indent << "ColorMatch: " << this->ColorMatch << "\n";
  os << indent << "ColorMatchWidth: " << this->ColorMatchWidth << "\n";
  os << indent << "ProjectionQualityWeight: " << (this->ProjectionQualityWeight ? "On" : "Off")
     << " (limit " << this->ProjectionQualityLimit << ")\n";
  os << indent << "Interpolation: " << (this->Interpolation == Nearest ? "Nearest" : "Linear")
     << "\n";
  os << indent << "Valid: " << (this->Valid ? "yes" : "no") << "\n";
  os << indent << "NumberOfLoads: " << this->NumberOfLoads << "\n";
  os << indent << "UpdateTime: " << this->UpdateTime << "\n";
  os << indent << "DataTime: " << this->DataTime << "\n";
  if (!this->Valid)
  {
    return;
  }
  const std::streamsize precision = os.precision(12);
  os << indent << "Size: " << this->RasterWidth << " x " << this->RasterHeight << " x "
     << this->NumberOfComponents << "\n";
  os << indent << "ModelType: "
     << (this->ModelType == Geographic ? "Geographic"
                                       : (this->ModelType == Projected ? "Projected" : "unknown"))
     << "\n";
  os << indent << "EPSG: " << this->EPSG << "\n";
  os << indent << "CRSDefinition: " << (this->CRSDefinition.empty() ? "(none)" : this->CRSDefinition)
     << "\n";
  os << indent << "ReprojectedFromCRS: "
     << (this->ReprojectedFromCRS.empty() ? "(none)" : this->ReprojectedFromCRS) << "\n";
  if (this->ModelType == Geographic)
  {
    os << indent << "GeographicExtent: " << in.Extent[0] << ", " << in.Extent[1] << ", "
       << in.Extent[2] << ", " << in.Extent[3] << (this->IsGlobal() ? " (global)" : "") << "\n";
  }
  os << indent << "Origin: " << in.Origin[0] << ", " << in.Origin[1] << "\n";
  os << indent << "PixelSize: " << in.PixelSize[0] << ", " << in.PixelSize[1] << "\n";
  os << indent << "DatumSemiAxes: " << this->DatumSemiMajorAxis << ", " << this->DatumSemiMinorAxis
     << "\n";
  os << indent << "NumberOfVoids: " << this->NumberOfVoids << "\n";
  static const char* const streaming[] = { "Off", "On", "Auto" };
  os << indent << "VerticalDatum: "
     << (this->VerticalDatum == Geoid ? "Geoid " : "Ellipsoidal")
     << (this->VerticalDatum == Geoid && this->GeoidFileName ? this->GeoidFileName : "") << "\n";
  os << indent << "Streaming: " << streaming[this->Streaming] << " (threshold "
     << this->StreamingThreshold << "; " << (this->IsStreamed() ? "streamed" : "whole") << ")\n";
  if (this->Role == Height)
  {
    os << indent << "Range: " << this->MinimumValue << " .. " << this->MaximumValue << "\n";
  }
  os.precision(precision);
}

