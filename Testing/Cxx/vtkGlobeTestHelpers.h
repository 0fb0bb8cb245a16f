// Small helpers shared by the C++ tests: a worst-case tracker that prints what it measured,
// and the dense point sets the geodesy tests sweep.
#ifndef vtkGlobeTestHelpers_h
#define vtkGlobeTestHelpers_h

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace vtkGlobeTest
{
/// Keeps the worst value of one error measure and where it happened.
struct Worst
{
  std::string What;
  std::string Unit;
  double Value = 0.0;
  std::string Where;
  bool Bad = false; // a NaN was seen

  Worst(const std::string& what, const std::string& unit)
    : What(what)
    , Unit(unit)
  {
  }
  void Add(double error, const std::string& where)
  {
    if (std::isnan(error))
    {
      if (!this->Bad)
      {
        this->Where = where;
      }
      this->Bad = true;
      return;
    }
    if (error > this->Value)
    {
      this->Value = error;
      this->Where = where;
    }
  }
  /// Prints the worst case and returns true when it is within the bound.
  bool Check(double bound) const
  {
    const bool ok = !this->Bad && this->Value <= bound;
    std::printf("  %-46s worst %-11.3e %-4s bound %-9.2e %s  at %s\n", this->What.c_str(),
      this->Value, this->Unit.c_str(), bound, ok ? "ok  " : "FAIL",
      this->Bad ? "(NaN seen)" : this->Where.c_str());
    return ok;
  }
};

inline std::string Format(const char* format, double a, double b, double c)
{
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c);
  return buffer;
}

/// Longitudes (deg) of the sweeps: a grid plus the date line, the prime meridian and
/// values one ulp-ish away from them.
inline std::vector<double> SweepLongitudes()
{
  std::vector<double> v = { -180.0, -179.9999999, -90.0, -1e-9, 0.0, 1e-9, 90.0, 179.9999999,
    180.0 };
  for (double lon = -172.5; lon < 180.0; lon += 15.0)
  {
    v.push_back(lon);
  }
  return v;
}

/// Latitudes (deg): both poles, next to them, the equator and a grid.
inline std::vector<double> SweepLatitudes()
{
  std::vector<double> v = { -90.0, -89.9999999, -45.0, 0.0, 45.0, 89.9999999, 90.0 };
  for (double lat = -87.5; lat < 90.0; lat += 7.5)
  {
    v.push_back(lat);
  }
  return v;
}

/// Heights (m) from the deepest trench to 1e11 m, and some inside the body.
inline std::vector<double> SweepHeights()
{
  return { -6.0e6, -3.0e6, -1.0e6, -1.1e4, -430.0, 0.0, 1.0, 8848.86, 1.0e5, 4.0e5, 3.6e7,
    1.0e9, 1.0e11 };
}

/// Body-fixed points near and at the centre and on the polar axis (m).
inline std::vector<std::vector<double>> CentralPoints(unsigned seed)
{
  std::vector<std::vector<double>> v = { { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 1.0 },
    { 0.0, 0.0, -1.0 }, { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 1e3, 0.0, 0.0 },
    { 0.0, 0.0, 3e4 }, { 0.0, 0.0, 4.2e4 }, { 0.0, 0.0, 4.4e4 }, { 4.2e4, 0.0, 0.0 },
    { 4.4e4, 0.0, 0.0 }, { 0.0, 0.0, 5e4 }, { 5e4, 0.0, 0.0 }, { 0.0, 0.0, 6356752.0 },
    { 0.0, 0.0, -7e6 }, { 0.0, 0.0, 1e11 }, { 1e-3, 1e-3, 1e-3 } };
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-5e4, 5e4);
  for (int i = 0; i < 400; ++i)
  {
    v.push_back({ u(rng), u(rng), u(rng) });
  }
  return v;
}

inline double WrapPi(double a)
{
  return std::remainder(a, 2.0 * 3.14159265358979323846);
}

inline double Distance(const double a[3], const double b[3])
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
    (a[2] - b[2]) * (a[2] - b[2]));
}

inline double Norm(const double a[3])
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/// WGS84's radii of curvature at a latitude (degrees): along the parallel (the prime
/// vertical's times cos(lat)) and along the meridian, in metres.
inline void WGS84Radii(double lat, double& parallel, double& meridian)
{
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
  const double phi = lat * 3.14159265358979323846 / 180.0;
  const double w2 = 1.0 - e2 * std::sin(phi) * std::sin(phi);
  parallel = a / std::sqrt(w2) * std::cos(phi);
  meridian = a * (1.0 - e2) / (w2 * std::sqrt(w2));
}

/// Angle between two vectors of any length, accurate for tiny angles: atan2(|a x b|, a . b).
inline double Angle(const double a[3], const double b[3])
{
  const double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
    a[0] * b[1] - a[1] * b[0] };
  return std::atan2(Norm(c), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}
/// A test's list of checks: each is printed "ok"/"FAIL" with what it asserts; failures counted.
struct Checklist
{
  int Failures = 0;
  void Expect(bool condition, const std::string& what)
  {
    std::printf("  %-4s %s\n", condition ? "ok" : "FAIL", what.c_str());
    this->Failures += condition ? 0 : 1;
  }
  /// Prints the count and gives the test's exit code.
  int Result() const
  {
    std::printf("%d failure(s)\n", this->Failures);
    return this->Failures == 0 ? 0 : 1;
  }
};

/// The process's resident memory (VmRSS) in MiB; 0 where /proc is not there.
inline double ResidentMiB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmRSS:", 0) == 0)
    {
      return std::stod(line.substr(6)) / 1024.0;
    }
  }
  return 0.0;
}

/// A world file (.tfw, .pgw, ...) for a global w x h image in plate carree: WGS 84 degrees.
inline void WriteGlobalWorldFile(const std::string& path, int w, int h)
{
  std::ofstream f(path);
  f.precision(17);
  f << 360.0 / w << "\n0\n0\n" << -180.0 / h << "\n" << -180.0 + 180.0 / w << "\n"
    << 90.0 - 90.0 / h << "\n";
}

/// printf into a std::string (up to 1023 characters).
inline std::string Printf(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline std::string Printf(const char* format, ...)
{
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return buffer;
}
} // namespace vtkGlobeTest

#endif
