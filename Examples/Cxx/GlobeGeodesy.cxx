// GlobeGeodesy: geodetic <-> body-fixed conversions for named places on the Earth, Mars and
// the Moon, or for the coordinates you give.
//
//   GlobeGeodesy                                   the table of named places
//   GlobeGeodesy [--body Earth|Mars|Moon] LON LAT HEIGHT    geodetic -> Cartesian
//   GlobeGeodesy [--body Earth|Mars|Moon] --inverse X Y Z   Cartesian -> geodetic
//
// Heights are above the body's reference ellipsoid (no geoid is modelled).
#include "vtkGlobeEllipsoid.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace
{
struct Place
{
  const char* Body;
  const char* Name;
  double Lon, Lat, Height;
};

// Coordinates from public sources; heights are the usual quoted summit/surface values.
const Place Places[] = {
  { "Earth", "Null Island (0, 0)", 0.0, 0.0, 0.0 },
  { "Earth", "North Pole", 0.0, 90.0, 0.0 },
  { "Earth", "Mount Everest summit", 86.9250, 27.98810, 8848.86 },
  { "Earth", "Mount Rainier summit", -121.7603, 46.8523, 4392.0 },
  { "Earth", "Dead Sea shore", 35.50, 31.50, -430.0 },
  { "Earth", "Geostationary orbit over 75 W", -75.0, 0.0, 35786000.0 },
  { "Mars", "Olympus Mons summit", -133.8, 18.65, 21229.0 },
  { "Mars", "Hellas Planitia floor", 70.5, -42.4, -7152.0 },
  { "Moon", "Apollo 11 landing site", 23.47314, 0.67416, -1924.0 },
  { "Moon", "Shackleton crater (south pole)", 129.78, -89.67, -4200.0 },
};

bool SetBody(vtkGlobeEllipsoid* e, const std::string& body)
{
  if (body == "Earth" || body == "WGS84")
  {
    e->SetToWGS84();
  }
  else if (body == "Mars")
  {
    e->SetToMars();
  }
  else if (body == "Moon")
  {
    e->SetToMoon();
  }
  else
  {
    std::fprintf(stderr, "Unknown body '%s': use Earth, Mars or Moon.\n", body.c_str());
    return false;
  }
  return true;
}

bool ParseNumber(const char* text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

void PrintTable(vtkGlobeEllipsoid* e)
{
  std::printf("%-8s %-32s %11s %10s %12s | %15s %15s %15s | %s\n", "body", "place", "lon (deg)",
    "lat (deg)", "height (m)", "x (m)", "y (m)", "z (m)", "round trip (m)");
  for (const Place& p : Places)
  {
    SetBody(e, p.Body);
    double xyz[3], llh[3], back[3];
    e->GeodeticToCartesian(p.Lon, p.Lat, p.Height, xyz);
    e->CartesianToGeodetic(xyz, llh);
    e->GeodeticToCartesian(llh, back);
    const double trip = std::sqrt((back[0] - xyz[0]) * (back[0] - xyz[0]) +
      (back[1] - xyz[1]) * (back[1] - xyz[1]) + (back[2] - xyz[2]) * (back[2] - xyz[2]));
    std::printf("%-8s %-32s %11.5f %10.5f %12.2f | %15.3f %15.3f %15.3f | %.1e\n", p.Body, p.Name,
      llh[0], llh[1], llh[2], xyz[0], xyz[1], xyz[2], trip);
  }
  std::printf("\nBodies:\n");
  for (const char* body : { "Earth", "Mars", "Moon" })
  {
    SetBody(e, body);
    const double* r = e->GetRadii();
    char shape[64] = "a sphere";
    if (e->GetFlattening() != 0.0)
    {
      std::snprintf(shape, sizeof(shape), "flattening 1/%.6f", 1.0 / e->GetFlattening());
    }
    std::printf("  %-6s %-6s a = %.3f m, b = %.3f m, c = %.3f m, %s\n", body, e->GetName(), r[0],
      r[1], r[2], shape);
  }
}
} // namespace

int main(int argc, char* argv[])
{
  vtkNew<vtkGlobeEllipsoid> ellipsoid;
  std::string body = "Earth";
  bool inverse = false;
  double values[3];
  int count = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::printf("usage: %s [--body Earth|Mars|Moon] [--inverse] [A B C]\n"
                  "  no coordinates: print conversions for named places\n"
                  "  A B C: longitude (deg), latitude (deg), height (m) -> x, y, z (m)\n"
                  "  --inverse A B C: x, y, z (m) -> longitude, latitude, height\n",
        argv[0]);
      return 0;
    }
    if (arg == "--body" && i + 1 < argc)
    {
      body = argv[++i];
    }
    else if (arg == "--inverse")
    {
      inverse = true;
    }
    else if (count < 3 && ParseNumber(argv[i], values[count]))
    {
      ++count;
    }
    else
    {
      std::fprintf(stderr, "Unexpected argument '%s' (see --help).\n", argv[i]);
      return 2;
    }
  }
  if (!SetBody(ellipsoid, body))
  {
    return 2;
  }
  if (count == 0)
  {
    PrintTable(ellipsoid);
    return 0;
  }
  if (count != 3)
  {
    std::fprintf(stderr, "Give three coordinates (see --help).\n");
    return 2;
  }
  double out[3];
  if (inverse)
  {
    ellipsoid->CartesianToGeodetic(values, out);
    std::printf("%s: lon %.9f deg, lat %.9f deg, height %.4f m\n", body.c_str(), out[0], out[1], out[2]);
  }
  else
  {
    if (std::abs(values[1]) > 90.0)
    {
      std::fprintf(stderr, "Latitude %g is outside [-90, 90].\n", values[1]);
      return 2;
    }
    ellipsoid->GeodeticToCartesian(values, out);
    std::printf("%s: x %.4f m, y %.4f m, z %.4f m\n", body.c_str(), out[0], out[1], out[2]);
  }
  return 0;
}
