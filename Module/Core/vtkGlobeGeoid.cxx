#include "vtkGlobeGeoid.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkGlobeGeoid);

struct vtkGlobeGeoid::vtkInternals
{
  vtkSmartPointer<vtkFloatArray> Values;
  std::string ReadName;        // the file the grid came from
  vtkMTimeType ReadTime = 0;   // this object's MTime when it was read
};

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

double BigEndianDouble(const unsigned char* b)
{
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i)
  {
    v = (v << 8) | b[i];
  }
  double d;
  std::memcpy(&d, &v, 8);
  return d;
}

std::uint32_t BigEndian32(const unsigned char* b)
{
  return (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) |
    std::uint32_t(b[3]);
}
} // namespace

vtkGlobeGeoid::vtkGlobeGeoid()
  : Internals(new vtkInternals)
{
}

vtkGlobeGeoid::~vtkGlobeGeoid()
{
  this->SetFileName(nullptr);
}

const char* vtkGlobeGeoid::GetEGM96FileName()
{
  // Looked up once (thread-safe); $PROJ_DATA and $PROJ_LIB may list several folders.
  static const std::string found = []() {
    std::vector<std::string> folders;
    for (const char* variable : { "PROJ_DATA", "PROJ_LIB" })
    {
      std::stringstream list(std::getenv(variable) ? std::getenv(variable) : "");
      for (std::string folder; std::getline(list, folder, ':');)
      {
        if (!folder.empty())
        {
          folders.push_back(folder);
        }
      }
    }
    folders.push_back("/usr/share/proj");
    for (const std::string& folder : folders)
    {
      const std::string path = folder + "/egm96_15.gtx";
      if (std::ifstream(path).good())
      {
        return path;
      }
    }
    return std::string();
  }();
  return found.c_str();
}

bool vtkGlobeGeoid::Update()
{
  vtkInternals& in = *this->Internals;
  const std::string name = this->FileName ? this->FileName : "";
  if (name == in.ReadName && this->GetMTime() <= in.ReadTime)
  {
    return this->Valid;
  }
  in.ReadName = name;
  this->Valid = this->Read(this->FileName);
  in.ReadTime = this->GetMTime();
  return this->Valid;
}

bool vtkGlobeGeoid::Read(const char* fileName)
{
  vtkInternals& in = *this->Internals;
  in.Values = nullptr;
  this->Columns = this->Rows = 0;
  this->Global = false;
  if (!fileName || !*fileName)
  {
    vtkErrorMacro(<< "No geoid file name (EGM96 is /usr/share/proj/egm96_15.gtx from Debian's "
                     "proj-data)");
    return false;
  }
  std::ifstream file(fileName, std::ios::binary);
  if (!file)
  {
    vtkErrorMacro(<< "Geoid file " << fileName << " cannot be opened");
    return false;
  }
  unsigned char header[40];
  if (!file.read(reinterpret_cast<char*>(header), 40))
  {
    vtkErrorMacro(<< "Geoid file " << fileName << " is shorter than a GTX header (40 bytes)");
    return false;
  }
  const double south = BigEndianDouble(header);
  double west = BigEndianDouble(header + 8);
  if (west >= 180.0)
  {
    west -= 360.0; // as PROJ reads such grids (e.g. 0..360 regional grids for Alaska)
  }
  const double dLat = BigEndianDouble(header + 16), dLon = BigEndianDouble(header + 24);
  const std::uint32_t rows = BigEndian32(header + 32), columns = BigEndian32(header + 36);
  if (!(std::abs(south) <= 90.0) || !std::isfinite(west) || !(dLat > 0.0) || !(dLon > 0.0) ||
    rows < 2 || columns < 2 || rows > 100000 || columns > 100000 ||
    south + (rows - 1) * dLat > 90.0 + 1e-9 || dLon * (columns - 1) > 360.0 + 1e-9)
  {
    vtkErrorMacro(<< "Geoid file " << fileName << " has no GTX grid header (south " << south
                  << ", west " << west << ", spacing " << dLat << " x " << dLon << ", "
                  << rows << " rows x " << columns << " columns)");
    return false;
  }
  const size_t count = static_cast<size_t>(rows) * columns;
  // The header's size against the file's, before allocating (a 40-byte file may claim 40 GB).
  std::error_code error;
  const auto fileBytes = std::filesystem::file_size(fileName, error);
  if (error || fileBytes < 40 + 4 * count)
  {
    vtkErrorMacro(<< "Geoid file " << fileName << " is truncated: " << rows << " x " << columns
                  << " values need " << count * 4 + 40 << " bytes");
    return false;
  }
  std::string bytes(count * 4, '\0');
  if (!file.read(&bytes[0], static_cast<std::streamsize>(bytes.size())))
  {
    vtkErrorMacro(<< "Geoid file " << fileName << " is truncated: " << rows << " x " << columns
                  << " values need " << count * 4 + 40 << " bytes");
    return false;
  }
  // A grid one whole turn wide wraps; a repeated 360-degree column goes.
  const double span = dLon * columns;
  int keep = static_cast<int>(columns);
  if (std::abs(span - 360.0 - dLon) < 1e-6 * dLon)
  {
    keep = static_cast<int>(columns) - 1;
  }
  this->Global = std::abs(dLon * keep - 360.0) < 1e-6 * dLon;
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetNumberOfValues(static_cast<vtkIdType>(rows) * keep);
  const auto* raw = reinterpret_cast<const unsigned char*>(bytes.data());
  double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
  for (std::uint32_t j = 0; j < rows; ++j)
  {
    for (int i = 0; i < keep; ++i)
    {
      const std::uint32_t bits = BigEndian32(raw + 4 * (static_cast<size_t>(j) * columns + i));
      float v;
      std::memcpy(&v, &bits, 4);
      if (!std::isfinite(v) || std::abs(v + 88.8888f) < 1e-3f || std::abs(v) > 1000.0f)
      {
        v = std::numeric_limits<float>::quiet_NaN();
      }
      else
      {
        lo = std::min(lo, static_cast<double>(v));
        hi = std::max(hi, static_cast<double>(v));
      }
      values->SetValue(static_cast<vtkIdType>(j) * keep + i, v);
    }
  }
  if (lo > hi)
  {
    vtkErrorMacro(<< "Geoid file " << fileName << " has no node with a value");
    return false;
  }
  this->Rows = static_cast<int>(rows);
  this->Columns = keep;
  this->Origin[0] = west;
  this->Origin[1] = south;
  this->Spacing[0] = dLon;
  this->Spacing[1] = dLat;
  this->Range[0] = lo;
  this->Range[1] = hi;
  // Steepest slope between neighbouring nodes, on the smallest WGS84 radius (a bound).
  const double metresPerDegree = 6356752.314 * 3.14159265358979323846 / 180.0;
  double slope = 0.0;
  for (int j = 0; j < this->Rows; ++j)
  {
    const double lat = south + j * dLat;
    const double dx = dLon * metresPerDegree * std::max(std::cos(lat * 3.14159265358979323846 / 180.0), 1e-3);
    for (int i = 0; i < keep; ++i)
    {
      const double v = values->GetValue(static_cast<vtkIdType>(j) * keep + i);
      if (i + 1 < keep || this->Global)
      {
        const double e = values->GetValue(static_cast<vtkIdType>(j) * keep + (i + 1) % keep);
        if (std::isfinite(v) && std::isfinite(e))
        {
          slope = std::max(slope, std::abs(e - v) / dx);
        }
      }
      if (j + 1 < this->Rows)
      {
        const double n = values->GetValue(static_cast<vtkIdType>(j + 1) * keep + i);
        if (std::isfinite(v) && std::isfinite(n))
        {
          slope = std::max(slope, std::abs(n - v) / (dLat * metresPerDegree));
        }
      }
    }
  }
  this->MaximumSlope = slope;
  in.Values = values;
  return true;
}

double vtkGlobeGeoid::GetUndulation(double lon, double lat)
{
  vtkInternals& in = *this->Internals;
  if (!this->Update() || !std::isfinite(lon) || !std::isfinite(lat) || std::abs(lat) > 90.0)
  {
    return NaN;
  }
  double x = (lon - this->Origin[0]) / this->Spacing[0];
  const double y = (lat - this->Origin[1]) / this->Spacing[1];
  if (this->Global)
  {
    x = std::fmod(x, this->Columns);
    x = x < 0.0 ? x + this->Columns : x;
  }
  else if (x < 0.0 || x > this->Columns - 1)
  {
    return NaN;
  }
  if (y < -1e-9 || y > this->Rows - 1 + 1e-9)
  {
    return NaN;
  }
  const int i0 = std::min(static_cast<int>(std::floor(x)), this->Columns - 1);
  const int j0 = std::min(std::max(static_cast<int>(std::floor(y)), 0), this->Rows - 2);
  const double fx = x - i0, fy = std::min(std::max(y - j0, 0.0), 1.0);
  const int i1 = this->Global ? (i0 + 1) % this->Columns : std::min(i0 + 1, this->Columns - 1);
  auto at = [&](int i, int j) {
    return static_cast<double>(in.Values->GetValue(static_cast<vtkIdType>(j) * this->Columns + i));
  };
  return (1.0 - fy) * ((1.0 - fx) * at(i0, j0) + fx * at(i1, j0)) +
    fy * ((1.0 - fx) * at(i0, j0 + 1) + fx * at(i1, j0 + 1));
}

vtkFloatArray* vtkGlobeGeoid::GetValues()
{
  return this->Update() ? this->Internals->Values.Get() : nullptr;
}

void vtkGlobeGeoid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Valid: " << this->Valid << "\n";
  os << indent << "Grid: " << this->Columns << " x " << this->Rows << " nodes from (" << this->Origin[0]
     << ", " << this->Origin[1] << "), spacing " << this->Spacing[0] << " x " << this->Spacing[1]
     << (this->Global ? " (global)" : "") << "\n";
  os << indent << "Range: " << this->Range[0] << " .. " << this->Range[1] << " m\n";
  os << indent << "MaximumSlope: " << this->MaximumSlope << "\n";
}
