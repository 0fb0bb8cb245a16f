// GeoTIFF georeferencing variants that Data/ does not contain, written here with libtiff and
// libgeotiff: RasterPixelIsPoint (half-pixel shift), a south-up transformation matrix (rows
// flipped so row 0 is north), a tie point away from pixel (0, 0), angular units in radians, a
// user-defined ellipsoid, GDAL_NODATA on float, unsigned and colour rasters, unsigned 16-bit
// heights read without rescaling. And the georeferencing vtkGlobeLayer refuses, each with an
// error naming the file and the reason: rotation, geocentric model, no model type, ground
// control points only, a zero pixel size, coordinates that are not degrees, an unsupported
// angular unit.
#include "vtkGlobeTestHelpers.h"
#include "vtkDataArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeMapProjection.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <geotiff.h>
#include <geovalues.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

const std::string Temp = VTKGLOBE_TEMP_DIR;

/// What to write into a small GeoTIFF.
struct GeoTIFF
{
  int Width = 10;
  int Height = 5;
  int Channels = 1;
  int Bits = 32;
  int SampleFormat = SAMPLEFORMAT_IEEEFP;
  std::vector<double> Values; // row-major, Channels per pixel, in file order

  bool WriteModelType = true;
  int ModelType = ModelTypeGeographic;
  int RasterType = RasterPixelIsArea;
  int EPSG = 4326;
  int AngularUnits = 0; // 0: no key
  double SemiMajor = 0.0, InverseFlattening = -1.0;

  std::vector<double> TiePoints = { 0, 0, 0, 10, 50, 0 };
  std::vector<double> Scale = { 1, 1, 0 };
  std::vector<double> Matrix; // 16 values; replaces tie points + scale when set
  const char* NoData = nullptr;
  // Further GeoKeys (a user-defined projection).
  std::vector<std::pair<geokey_t, int>> ShortKeys;
  std::vector<std::pair<geokey_t, double>> DoubleKeys;
};

bool Write(const std::string& path, const GeoTIFF& g)
{
  TIFF* tif = XTIFFOpen(path.c_str(), "w");
  if (!tif)
  {
    return false;
  }
  // GDAL's nodata tag is not known to libtiff: register it on this handle.
  static const TIFFFieldInfo noDataInfo[] = { { 42113, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0,
    const_cast<char*>("GDAL_NODATA") } };
  TIFFMergeFieldInfo(tif, noDataInfo, 1);
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, g.Width);
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, g.Height);
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, g.Channels);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, g.Bits);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, g.SampleFormat);
  TIFFSetField(
    tif, TIFFTAG_PHOTOMETRIC, g.Channels >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, 1);
  if (g.Channels == 4)
  {
    const uint16_t extra = EXTRASAMPLE_UNASSALPHA; // RGBA as GDAL writes it
    TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &extra);
  }
  if (!g.Matrix.empty())
  {
    TIFFSetField(tif, TIFFTAG_GEOTRANSMATRIX, 16, g.Matrix.data());
  }
  else
  {
    TIFFSetField(
      tif, TIFFTAG_GEOTIEPOINTS, static_cast<int>(g.TiePoints.size()), g.TiePoints.data());
    if (!g.Scale.empty())
    {
      TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, g.Scale.data());
    }
  }
  if (g.NoData)
  {
    TIFFSetField(tif, 42113, g.NoData);
  }
  GTIF* gtif = GTIFNew(tif);
  if (g.WriteModelType)
  {
    GTIFKeySet(gtif, GTModelTypeGeoKey, TYPE_SHORT, 1, g.ModelType);
  }
  GTIFKeySet(gtif, GTRasterTypeGeoKey, TYPE_SHORT, 1, g.RasterType);
  GTIFKeySet(gtif, g.ModelType == ModelTypeProjected ? ProjectedCSTypeGeoKey : GeographicTypeGeoKey,
    TYPE_SHORT, 1, g.EPSG);
  if (g.AngularUnits)
  {
    GTIFKeySet(gtif, GeogAngularUnitsGeoKey, TYPE_SHORT, 1, g.AngularUnits);
  }
  if (g.SemiMajor > 0)
  {
    GTIFKeySet(gtif, GeogSemiMajorAxisGeoKey, TYPE_DOUBLE, 1, g.SemiMajor);
    GTIFKeySet(gtif, GeogInvFlatteningGeoKey, TYPE_DOUBLE, 1, g.InverseFlattening);
  }
  for (const auto& k : g.ShortKeys)
  {
    GTIFKeySet(gtif, k.first, TYPE_SHORT, 1, k.second);
  }
  for (const auto& k : g.DoubleKeys)
  {
    GTIFKeySet(gtif, k.first, TYPE_DOUBLE, 1, k.second);
  }
  GTIFWriteKeys(gtif);
  GTIFFree(gtif);

  const int bytes = g.Bits / 8;
  std::vector<unsigned char> row(static_cast<size_t>(g.Width) * g.Channels * bytes);
  bool ok = true;
  for (int r = 0; r < g.Height && ok; ++r)
  {
    for (int i = 0; i < g.Width * g.Channels; ++i)
    {
      const double v = g.Values[static_cast<size_t>(r) * g.Width * g.Channels + i];
      unsigned char* p = row.data() + static_cast<size_t>(i) * bytes;
      if (g.SampleFormat == SAMPLEFORMAT_IEEEFP)
      {
        const float f = static_cast<float>(v);
        std::memcpy(p, &f, 4);
      }
      else if (g.Bits == 16)
      {
        const uint16_t u = static_cast<uint16_t>(v);
        std::memcpy(p, &u, 2);
      }
      else
      {
        *p = static_cast<unsigned char>(v);
      }
    }
    ok = TIFFWriteScanline(tif, row.data(), r, 0) == 1;
  }
  XTIFFClose(tif);
  return ok;
}

/// 10 x 5 float heights, value = 10 * row + column (file order).
GeoTIFF Ramp()
{
  GeoTIFF g;
  for (int r = 0; r < g.Height; ++r)
  {
    for (int c = 0; c < g.Width; ++c)
    {
      g.Values.push_back(10.0 * r + c);
    }
  }
  return g;
}

std::string ExtentText(vtkGlobeLayer* layer)
{
  double e[4];
  layer->GetGeographicExtent(e);
  char text[160];
  std::snprintf(text, sizeof(text), "W %.9g E %.9g S %.9g N %.9g", e[0], e[1], e[2], e[3]);
  return text;
}

bool ExtentIs(vtkGlobeLayer* layer, double w, double e, double s, double n, double tolerance)
{
  double x[4];
  layer->GetGeographicExtent(x);
  return std::abs(x[0] - w) <= tolerance && std::abs(x[1] - e) <= tolerance &&
    std::abs(x[2] - s) <= tolerance && std::abs(x[3] - n) <= tolerance;
}

bool ErrorSaid(vtkTest::ErrorObserver* observer, const std::string& file, const std::string& words)
{
  const std::string message = observer->GetErrorMessage();
  const bool said = observer->GetError() && message.find(file) != std::string::npos &&
    message.find(words) != std::string::npos;
  const size_t start = message.find("Cannot load");
  std::string shown = message.substr(start == std::string::npos ? 0 : start);
  while (!shown.empty() && (shown.back() == '\n' || shown.back() == ' '))
  {
    shown.pop_back();
  }
  std::printf("       error: %s\n", shown.c_str());
  observer->Clear();
  return said;
}
} // namespace

int TestGlobeLayerGeoTIFF(int, char*[])
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkGlobeLayer> layer;
  layer->AddObserver(vtkCommand::ErrorEvent, observer);
  layer->SetFillVoids(false);
  const auto load = [&](const std::string& name, const GeoTIFF& g)
  {
    const std::string path = Temp + "/" + name;
    const bool written = Write(path, g);
    layer->SetFileName(path.c_str());
    return written && layer->Update();
  };
  bool ok = false;
  const auto value = [&](int row, int col)
  {
    return layer->GetData()->GetComponent(static_cast<vtkIdType>(row) * layer->GetNumberOfColumns() + col, 0);
  };

  std::printf("Raster types and transforms:\n");
  {
    GeoTIFF g = Ramp();       // tie point (0, 0) -> (10E, 50N), 1 degree pixels
    ok = load("area.tif", g); // load first: the message reads the new state
    Expect(ok && ExtentIs(layer, 10, 20, 45, 50, 0),
      "RasterPixelIsArea: the tie point is the outer corner: " + ExtentText(layer));
    g.RasterType = RasterPixelIsPoint;
    ok = load("point.tif", g);
    Expect(ok && ExtentIs(layer, 9.5, 19.5, 45.5, 50.5, 0),
      "RasterPixelIsPoint: the tie point is the first post, the box is half a pixel out: " +
        ExtentText(layer));
    g.RasterType = RasterPixelIsArea;
    g.TiePoints = { 2, 1, 0, 12, 49, 0 }; // pixel (2, 1) -> (12E, 49N): the same grid
    ok = load("tie21.tif", g);
    Expect(ok && ExtentIs(layer, 10, 20, 45, 50, 0) && value(0, 0) == 0,
      "a tie point at pixel (2, 1) gives the same box: " + ExtentText(layer));

    // South-up: row 0 of the file is the south row (positive y step in the matrix).
    GeoTIFF s = Ramp();
    s.Matrix = { 0.5, 0, 0, 20, 0, 0.5, 0, 40, 0, 0, 0, 0, 0, 0, 0, 1 };
    ok = load("southup.tif", s);
    Expect(ok && ExtentIs(layer, 20, 25, 40, 42.5, 0) && value(0, 0) == 40 && value(4, 9) == 9,
      "a south-up matrix: rows flipped so row 0 is north (value 40 = file row 4), " +
        ExtentText(layer));
    double origin[2], size[2];
    layer->GetProjectedGeoTransform(origin, size);
    Expect(origin[0] == 20 && origin[1] == 42.5 && size[0] == 0.5 && size[1] == 0.5,
      "its transform: north-west corner (20, 42.5), pixel 0.5 x 0.5 degrees");

    // Angular units in radians: the same 10..20E, 45..50N box.
    GeoTIFF r = Ramp();
    const double d = 3.14159265358979323846 / 180.0;
    r.AngularUnits = Angular_Radian;
    r.TiePoints = { 0, 0, 0, 10 * d, 50 * d, 0 };
    r.Scale = { d, d, 0 };
    ok = load("radians.tif", r);
    Expect(ok && ExtentIs(layer, 10, 20, 45, 50, 1e-12) &&
        std::abs(layer->GetDegreesPerPixel(0) - 1) < 1e-14,
      "GeogAngularUnits = radian: converted to degrees: " + ExtentText(layer));

    // A user-defined ellipsoid (Mars, IAU 2000: a = 3,396,190 m, 1/f = 169.894447224).
    GeoTIFF m = Ramp();
    m.EPSG = KvUserDefined;
    m.SemiMajor = 3396190.0;
    m.InverseFlattening = 169.894447224;
    ok = load("mars.tif", m);
    Expect(ok && layer->GetEPSG() == 0 && layer->GetDatumSemiMajorAxis() == 3396190.0 &&
        std::abs(layer->GetDatumSemiMinorAxis() - 3376200.0) < 0.01,
      "a user-defined ellipsoid: EPSG 0, semi-axes " +
        std::to_string(layer->GetDatumSemiMajorAxis()) + ", " +
        std::to_string(layer->GetDatumSemiMinorAxis()) + " m");
    m.InverseFlattening = 0.0;
    ok = load("sphere.tif", m);
    Expect(ok && layer->GetDatumSemiMinorAxis() == 3396190.0,
      "inverse flattening 0 is a sphere: semi-minor = semi-major");

    // EPSG:3031 spelled out in user-defined GeoKeys (as GDAL writes a PROJ string or a WKT
    // without its code): PROJ identifies it, and the layer is EPSG:3031.
    GeoTIFF u = Ramp();
    u.ModelType = ModelTypeProjected;
    u.EPSG = KvUserDefined;
    u.TiePoints = { 0, 0, 0, -1.0e6, 1.0e6, 0 };
    u.Scale = { 2.0e5, 2.0e5, 0 };
    u.ShortKeys = { { GeographicTypeGeoKey, 4326 }, { ProjectionGeoKey, KvUserDefined },
      { ProjCoordTransGeoKey, CT_PolarStereographic }, { ProjLinearUnitsGeoKey, Linear_Meter } };
    u.DoubleKeys = { { ProjNatOriginLatGeoKey, -71.0 }, { ProjStraightVertPoleLongGeoKey, 0.0 },
      { ProjFalseEastingGeoKey, 0.0 }, { ProjFalseNorthingGeoKey, 0.0 } };
    ok = load("user_3031.tif", u);
    Expect(ok && layer->GetModelType() == vtkGlobeLayer::Projected && layer->GetEPSG() == 3031,
      "user-defined polar stereographic GeoKeys (71 S, 0 E, WGS 84): identified as EPSG:" +
        std::to_string(layer->GetEPSG()));
    // The same with a true-scale latitude no EPSG CRS has: not identified, EPSG 0.
    u.DoubleKeys[0].second = -65.5;
    ok = load("user_stere.tif", u);
    Expect(ok && layer->GetEPSG() == 0 &&
        std::string(layer->GetCRSDefinition()).find("+proj=stere") != std::string::npos,
      "polar stereographic GeoKeys true at 65.5 S (no EPSG equivalent): EPSG " +
        std::to_string(layer->GetEPSG()) + ", by its definition '" + layer->GetCRSDefinition() +
        "'");
    vtkNew<vtkGlobeMapProjection> projection;
    Expect(layer->GetMapProjection(projection) &&
        projection->GetKind() == vtkGlobeMapProjection::PolarStereographic &&
        projection->GetLatitudeOfTrueScale() == -65.5,
      "  ... which the GPU draws: polar stereographic true at " +
        std::to_string(projection->GetLatitudeOfTrueScale()));

    // MODIS's sinusoidal grid as GDAL writes it (user-defined keys on a user-defined sphere):
    // no EPSG code, kept by definition, drawn as vtkGlobeMapProjection::Sinusoidal.
    GeoTIFF modis = Ramp();
    modis.ModelType = ModelTypeProjected;
    modis.EPSG = KvUserDefined;
    modis.TiePoints = { 0, 0, 0, -11119505.196667, 4447802.078667, 0 }; // tile h08v05
    modis.Scale = { 1111950.519667 / 8, 1111950.519667 / 4, 0 };
    modis.SemiMajor = 6371007.181;
    modis.InverseFlattening = 0.0;
    modis.ShortKeys = { { GeographicTypeGeoKey, KvUserDefined },
      { GeogGeodeticDatumGeoKey, KvUserDefined }, { GeogEllipsoidGeoKey, KvUserDefined },
      { ProjectionGeoKey, KvUserDefined }, { ProjCoordTransGeoKey, CT_Sinusoidal },
      { ProjLinearUnitsGeoKey, Linear_Meter } };
    modis.DoubleKeys = { { ProjCenterLongGeoKey, 0.0 }, { ProjFalseEastingGeoKey, 0.0 },
      { ProjFalseNorthingGeoKey, 0.0 } };
    ok = load("modis_h08v05.tif", modis);
    const std::string definition = ok ? layer->GetCRSDefinition() : "";
    Expect(ok && layer->GetModelType() == vtkGlobeLayer::Projected && layer->GetEPSG() == 0 &&
        definition.find("+proj=sinu") != std::string::npos && !layer->IsReprojected(),
      "MODIS sinusoidal GeoKeys: projected, EPSG 0, definition '" + definition + "'");
    Expect(layer->GetMapProjection(projection) &&
        projection->GetKind() == vtkGlobeMapProjection::Sinusoidal &&
        projection->GetSemiMajorAxis() == 6371007.181 && projection->GetFlattening() == 0.0,
      "  ... drawn as Sinusoidal on the 6371007.181 m sphere");
  }

  std::printf("Nodata and sample types:\n");
  {
    GeoTIFF g = Ramp();
    g.Values[3] = -9999;
    g.Values[17] = -9999;
    g.NoData = "-9999";
    ok = load("nodata_float.tif", g);
    Expect(ok && layer->GetHasNoDataValue() && layer->GetNoDataValue() == -9999 &&
        layer->GetNumberOfVoids() == 2 && std::isnan(value(0, 3)) && std::isnan(value(1, 7)) &&
        layer->GetMinimumValue() == 0,
      "float32 with GDAL_NODATA '-9999': 2 voids (NaN with FillVoids off), min 0");
    g.NoData = "nan";
    g.Values[3] = std::nan("");
    ok = load("nodata_nan.tif", g);
    Expect(ok && layer->GetHasNoDataValue() && std::isnan(layer->GetNoDataValue()) &&
        layer->GetNumberOfVoids() == 1,
      "GDAL_NODATA 'nan': the NaN post is a void, -9999 is now a value (1 void)");
    layer->SetNoDataValue(-9999);
    ok = layer->Update();
    Expect(ok && layer->GetNumberOfVoids() == 2 && layer->GetNoDataValueOverridden(),
      "SetNoDataValue(-9999) overrides the file's tag: 2 voids (NaN + -9999)");
    layer->UseFileNoDataValue();
    ok = layer->Update();
    Expect(ok && layer->GetNumberOfVoids() == 1 && std::isnan(layer->GetNoDataValue()),
      "UseFileNoDataValue(): back to the file's 'nan' (1 void)");
    layer->SetHasNoDataValue(false);
    g.Values[3] = 3;
    ok = load("nodata_off.tif", g);
    Expect(ok && layer->GetNumberOfVoids() == 0 && layer->GetMinimumValue() == -9999,
      "SetHasNoDataValue(false): the tag is ignored, -9999 is a height");
    layer->UseFileNoDataValue();

    // Unsigned 16-bit heights keep their values (OpenImageIO would rescale them to 0..1).
    GeoTIFF u = Ramp();
    u.Bits = 16;
    u.SampleFormat = SAMPLEFORMAT_UINT;
    u.Values[0] = 65535;
    u.Values[1] = 60000;
    u.NoData = "65535";
    ok = load("uint16.tif", u);
    Expect(ok && layer->GetNumberOfVoids() == 1 && value(0, 1) == 60000 &&
        layer->GetMaximumValue() == 60000,
      "uint16 heights: 60000 read as 60000 m, 65535 (nodata) a void");

    // Colour nodata: a pixel is transparent when all its channels equal the nodata value.
    GeoTIFF c;
    c.Width = 3;
    c.Height = 1;
    c.Channels = 3;
    c.Bits = 8;
    c.SampleFormat = SAMPLEFORMAT_UINT;
    c.Values = { 0, 0, 0, 0, 5, 0, 200, 100, 50 };
    c.NoData = "0";
    layer->SetRoleToColor();
    const bool loaded = load("rgb_nodata.tif", c);
    auto* rgba = vtkUnsignedCharArray::SafeDownCast(layer->GetData());
    Expect(loaded && rgba && layer->GetNumberOfVoids() == 1 && rgba->GetValue(3) == 0 &&
        rgba->GetValue(7) == 255 && rgba->GetValue(8) == 200 && rgba->GetValue(11) == 255,
      "RGB with nodata 0: (0,0,0) gets alpha 0, (0,5,0) and (200,100,50) alpha 255");

    // RGBA with straight (unassociated) alpha: colours are kept, not premultiplied.
    c.Channels = 4;
    c.NoData = nullptr;
    c.Values = { 200, 100, 50, 128, 10, 20, 30, 0, 1, 2, 3, 255 };
    ok = load("rgba.tif", c);
    rgba = vtkUnsignedCharArray::SafeDownCast(layer->GetData());
    Expect(ok && rgba && rgba->GetValue(0) == 200 && rgba->GetValue(1) == 100 &&
        rgba->GetValue(2) == 50 && rgba->GetValue(3) == 128 && rgba->GetValue(4) == 10 &&
        rgba->GetValue(7) == 0 && rgba->GetValue(11) == 255 && layer->GetNumberOfVoids() == 0,
      "RGBA: alpha 128 and 0 kept, colours not premultiplied (200, 100, 50, 128)");
    layer->SetRoleToHeight();
  }

  std::printf("Refused georeferencing:\n");
  {
    const auto refuse = [&](const std::string& name, const GeoTIFF& g, const std::string& words)
    {
      const bool loaded = load(name, g);
      Expect(!loaded && ErrorSaid(observer, Temp + "/" + name, words) && !layer->IsValid() &&
          !layer->GetData(),
        name + ": '" + words + "'");
    };
    GeoTIFF g = Ramp();
    g.Matrix = { 1, 0.1, 0, 10, 0.1, -1, 0, 50, 0, 0, 0, 0, 0, 0, 0, 1 };
    refuse("rotated.tif", g, "rotated or sheared");
    g = Ramp();
    g.ModelType = ModelTypeGeocentric;
    refuse("geocentric.tif", g, "neither geographic nor projected");
    g = Ramp();
    g.WriteModelType = false;
    refuse("nomodel.tif", g, "no GTModelTypeGeoKey");
    g = Ramp();
    g.TiePoints = { 0, 0, 0, 10, 50, 0, 9, 0, 0, 20, 50, 0, 0, 4, 0, 10, 45, 0 };
    g.Scale.clear();
    refuse("gcps.tif", g, "ground control points");
    g = Ramp();
    g.Scale = { 0, 1, 0 };
    refuse("zeroscale.tif", g, "pixel size is zero");
    g = Ramp();
    g.TiePoints = { 0, 0, 0, 575993.04, 5207152.44, 0 }; // UTM metres labelled geographic
    g.Scale = { 90, 90, 0 };
    refuse("notdegrees.tif", g, "is not a box in degrees");
    g = Ramp();
    g.AngularUnits = Angular_DMS;
    refuse("dms.tif", g, "angular unit");
  }

  return Checks.Result();
}
