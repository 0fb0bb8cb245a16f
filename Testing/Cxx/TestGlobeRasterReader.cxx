// vtkGlobeRasterReader: the information pass (whole extent, spacing, origin, scalar type) without
// reading pixels; every pixel of every data set of Data/ against OpenImageIO's direct read, in
// VTK's orientation (row 0 south); the georeferencing field data of each data set (the numbers
// of Data/README.md); world files (.pgw + .prj, .tfw alone, SetEPSG, a geographic .prj without
// EPSG); progress events; and bad input, each failing through the executive with an error that
// names the file and the reason.
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkGlobeRasterReader.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkGlobeTestHelpers.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

using vtkGlobeTest::Printf;

const std::string Data = VTKGLOBE_DATA_DIR;
const std::string Temp = VTKGLOBE_TEMP_DIR;

double FieldNumber(vtkImageData* image, const char* name, int i = 0)
{
  vtkDataArray* a = image->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > i ? a->GetTuple1(i) : std::nan("");
}

std::string FieldText(vtkImageData* image, const char* name)
{
  auto* a = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray(name));
  return a && a->GetNumberOfValues() > 0 ? a->GetValue(0) : std::string("(none)");
}

bool Near(double a, double b, double tolerance)
{
  return std::abs(a - b) <= tolerance;
}

void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

void WriteBytes(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::vector<char> ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// An image written with OpenImageIO: pixel (c, r) of channel k = 10 r + c + 100 k (file order).
bool WriteImage(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type)
{
  auto out = OIIO::ImageOutput::create(path);
  if (!out)
  {
    return false;
  }
  OIIO::ImageSpec spec(width, height, channels, type);
  std::vector<float> pixels(static_cast<size_t>(width) * height * channels);
  for (int r = 0; r < height; ++r)
  {
    for (int c = 0; c < width; ++c)
    {
      for (int k = 0; k < channels; ++k)
      {
        pixels[(static_cast<size_t>(r) * width + c) * channels + k] =
          static_cast<float>(10 * r + c + 100 * k);
      }
    }
  }
  // 8-bit output takes floats as 0..1.
  const float unit = type == OIIO::TypeDesc::UINT8 ? 255.0f : 1.0f;
  for (float& v : pixels)
  {
    v /= unit;
  }
  return out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) &&
    out->close();
}

/// Every pixel of the reader's output against OpenImageIO's read of the file (native type for
/// one channel, 8 bits otherwise), output row j = file row height - 1 - j. Returns mismatches.
long CompareWithOIIO(const std::string& file, vtkImageData* image, std::string& note)
{
  auto in = OIIO::ImageInput::open(file);
  if (!in)
  {
    note = "OpenImageIO cannot open it";
    return -1;
  }
  const OIIO::ImageSpec spec = in->spec();
  const OIIO::TypeDesc type = spec.nchannels == 1
    ? (spec.format == OIIO::TypeDesc::HALF ? OIIO::TypeDesc(OIIO::TypeDesc::FLOAT) : spec.format)
    : OIIO::TypeDesc(OIIO::TypeDesc::UINT8);
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  in = OIIO::ImageInput::open(file, &config);
  const size_t pixel = type.size() * spec.nchannels;
  const size_t row = pixel * spec.width;
  std::vector<unsigned char> reference(row * spec.height);
  if (!in->read_image(0, 0, 0, spec.nchannels, type, reference.data()))
  {
    note = "OpenImageIO cannot read it";
    return -1;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (dims[0] != spec.width || dims[1] != spec.height || !scalars ||
    scalars->GetNumberOfComponents() != spec.nchannels ||
    static_cast<size_t>(scalars->GetDataTypeSize()) != type.size())
  {
    note = "sizes or types differ";
    return -1;
  }
  const auto* out = static_cast<const unsigned char*>(scalars->GetVoidPointer(0));
  long mismatches = 0;
  for (int j = 0; j < spec.height; ++j)
  {
    mismatches += std::memcmp(out + row * j, reference.data() + row * (spec.height - 1 - j), row) != 0;
  }
  note = Printf("%d x %d x %d %s", spec.width, spec.height, spec.nchannels, type.c_str());
  return mismatches;
}

/// Records the progress values of an algorithm.
class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Values.push_back(*static_cast<double*>(data));
  }
  std::vector<double> Values;
};

struct Expected
{
  const char* File;
  int ModelType;
  int EPSG;
  double Corner[2]; // north-west outer corner
  double Pixel[2];
  double Tolerance; // on the corner
  const char* Units;
  bool HasNoData;
  double NoData;
  double SemiMajor; // 0: no datum array
  double SemiMinor;
};
} // namespace

int TestGlobeRasterReader(int, char*[])
{
  std::printf("Information pass (no pixels read):\n");
  {
    vtkNew<vtkGlobeRasterReader> reader;
    reader->SetFileName((Data + "/earth/mt_rainier_90m.tif").c_str());
    vtkNew<ProgressRecorder> progress;
    reader->AddObserver(vtkCommand::ProgressEvent, progress);
    reader->UpdateInformation();
    vtkInformation* info = reader->GetOutputInformation(0);
    int extent[6] = { -1, -1, -1, -1, -1, -1 };
    double spacing[3] = { 0, 0, 0 }, origin[3] = { 0, 0, 0 };
    info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    info->Get(vtkDataObject::SPACING(), spacing);
    info->Get(vtkDataObject::ORIGIN(), origin);
    vtkInformation* scalarInfo = vtkDataObject::GetActiveFieldInformation(
      info, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
    const double step = 1.0 / 1200.0;
    Expect(extent[0] == 0 && extent[1] == 1200 && extent[2] == 0 && extent[3] == 1200 &&
        extent[4] == 0 && extent[5] == 0,
      Printf("mt_rainier_90m.tif WHOLE_EXTENT 0..%d x 0..%d", extent[1], extent[3]));
    Expect(Near(spacing[0], step, 1e-15) && Near(spacing[1], step, 1e-15),
      Printf("SPACING %.15g x %.15g degrees (1/1200)", spacing[0], spacing[1]));
    // The origin is the centre of the south-west pixel: west + 1/2 pixel, north - 1201 + 1/2.
    const double west = -122.0 - 0.5 * step, north = 47.0 + 0.5 * step;
    Expect(Near(origin[0], west + 0.5 * step, 1e-12) &&
        Near(origin[1], north - 1201 * step + 0.5 * step, 1e-12),
      Printf("ORIGIN (%.12f, %.12f): the centre of the south-west pixel", origin[0], origin[1]));
    Expect(scalarInfo && scalarInfo->Get(vtkDataObject::FIELD_ARRAY_TYPE()) == VTK_SHORT &&
        scalarInfo->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()) == 1,
      "scalar type short (int16, native), 1 component");
    Expect(progress->Values.empty() && reader->GetOutput()->GetNumberOfPoints() == 0,
      "no progress and no points: no pixels were read");

    // A file whose directory is intact but half of whose tiles are gone: the header pass
    // succeeds, only the pixels fail.
    const std::vector<char> world = ReadBytes(Data + "/earth/world.tif");
    WriteBytes(Temp + "/reader_world_half.tif",
      std::vector<char>(world.begin(), world.begin() + world.size() / 2));
    vtkNew<vtkGlobeRasterReader> half;
    vtkNew<vtkTest::ErrorObserver> errors;
    half->AddObserver(vtkCommand::ErrorEvent, errors);
    half->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    half->SetFileName((Temp + "/reader_world_half.tif").c_str());
    half->UpdateInformation();
    half->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    Expect(!errors->GetError() && extent[1] == 2047 && extent[3] == 1023,
      "world.tif cut in half: the information pass succeeds (2048 x 1024), pixels unread");
    half->Update();
    Expect(errors->GetError() && std::string(half->GetLastError()).find("corrupt or truncated") !=
        std::string::npos,
      std::string("... and Update() fails: ") + half->GetLastError());
  }

  std::printf("Data/: pixels against OpenImageIO, georeferencing field data:\n");
  const double srtm = 1.0 / 1200.0;
  const Expected sets[] = {
    // These two spell the WGS 84 ellipsoid out in their keys.
    { "earth/world.tif", 1, 4326, { -180, 90 }, { 0.17578125, 0.17578125 }, 0, "degree", false, 0,
      6378137, 6356752.314245 },
    { "earth/relief_2deg.tif", 1, 4326, { -180, 90 }, { 2, 2 }, 0, "degree", false, 0, 6378137,
      6356752.314245 },
    { "earth/mt_rainier_90m.tif", 1, 4326, { -122.0 - 0.5 * srtm, 47.0 + 0.5 * srtm },
      { srtm, srtm }, 1e-9, "degree", true, -32768, 0 },
    { "earth/mt_everest_90m.tif", 1, 4326, { 86.0 - 0.5 * srtm, 28.0 + 0.5 * srtm },
      { srtm, srtm }, 1e-9, "degree", true, -32768, 0 },
    { "earth/mt_rainier_utm10n.tif", 2, 32610, { 575993.04, 5207152.44 }, { 90, 90 }, 0.01,
      "metre", true, -32768, 0 },
    { "earth/world_north_polar_3413.tif", 2, 3413, { -4000000, 4000000 }, { 7812.5, 7812.5 },
      1e-6, "metre", false, 0, 0 },
    { "earth/nyc-inset-wgs84.tif", 1, 4326, { -74.104568, 40.788410 }, { 0.000225615, 0 }, 1e-6,
      "degree", false, 0, 0 },
    { "earth/boston-inset-wgs84.tif", 1, 4326, { -71.498418, 42.614315 }, { 0.001848699, 0 },
      1e-6, "degree", false, 0, 0 },
    { "moon/moon_1024x512.tif", 1, 0, { -180, 90 }, { 0.3515625, 0.3515625 }, 0, "degree", false,
      0, 1737400, 1737400 },
  };
  for (const Expected& e : sets)
  {
    const std::string file = Data + "/" + e.File;
    vtkNew<vtkGlobeRasterReader> reader;
    vtkNew<vtkTest::ErrorObserver> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    std::string note;
    const long mismatches = CompareWithOIIO(file, image, note);
    Expect(!errors->GetError() && mismatches == 0,
      Printf("%s: %s, every row equal to OpenImageIO's (flipped: row 0 south), %ld rows differ",
        e.File, note.c_str(), mismatches));
    const double t[4] = { FieldNumber(image, "GlobeGeoTransform", 0),
      FieldNumber(image, "GlobeGeoTransform", 1), FieldNumber(image, "GlobeGeoTransform", 2),
      FieldNumber(image, "GlobeGeoTransform", 3) };
    // The inset sizes are given to 9 decimals in Data/README.md.
    const double pixelTolerance = e.Pixel[1] == 0 ? 1e-9 : 1e-15;
    const double py = e.Pixel[1] == 0 ? e.Pixel[0] : e.Pixel[1];
    Expect(FieldNumber(image, "GlobeModelType") == e.ModelType &&
        FieldNumber(image, "GlobeEPSG") == e.EPSG && Near(t[0], e.Corner[0], e.Tolerance) &&
        Near(t[1], e.Corner[1], e.Tolerance) && Near(t[2], e.Pixel[0], pixelTolerance) &&
        Near(t[3], py, pixelTolerance) && FieldText(image, "GlobeUnits") == e.Units,
      Printf("    model %g, EPSG %g, NW corner (%.9f, %.9f), pixel %.12g x %.12g %s", FieldNumber(image, "GlobeModelType"),
        FieldNumber(image, "GlobeEPSG"), t[0], t[1], t[2], t[3],
        FieldText(image, "GlobeUnits").c_str()));
    const bool hasNoData = image->GetFieldData()->GetArray("GlobeNoDataValue") != nullptr;
    Expect(hasNoData == e.HasNoData && (!e.HasNoData || FieldNumber(image, "GlobeNoDataValue") == e.NoData),
      Printf("    nodata %s", hasNoData ? std::to_string(FieldNumber(image, "GlobeNoDataValue")).c_str() : "none"));
    const bool hasDatum = image->GetFieldData()->GetArray("GlobeDatumSemiAxes") != nullptr;
    Expect(hasDatum == (e.SemiMajor > 0) &&
        (!hasDatum || (FieldNumber(image, "GlobeDatumSemiAxes", 0) == e.SemiMajor &&
                        Near(FieldNumber(image, "GlobeDatumSemiAxes", 1), e.SemiMinor, 1e-6))),
      hasDatum ? Printf("    datum semi-axes %.6f, %.6f m", FieldNumber(image, "GlobeDatumSemiAxes", 0),
                   FieldNumber(image, "GlobeDatumSemiAxes", 1))
               : std::string("    no datum semi-axes (not spelled out in the file)"));
    // The image's own geometry says the same: origin = corner + half a pixel, y up.
    int dims[3];
    image->GetDimensions(dims);
    const double* origin = image->GetOrigin();
    const double* spacing = image->GetSpacing();
    Expect(Near(origin[0], t[0] + 0.5 * t[2], 1e-9 * t[2]) &&
        Near(origin[1], t[1] - dims[1] * t[3] + 0.5 * t[3], 1e-9 * t[3]) &&
        spacing[0] == t[2] && spacing[1] == t[3],
      "    origin and spacing agree with the field data (south-west pixel centre)");
    if (e.ModelType == 1)
    {
      const double box[4] = { FieldNumber(image, "GlobeGeographicExtent", 0),
        FieldNumber(image, "GlobeGeographicExtent", 1),
        FieldNumber(image, "GlobeGeographicExtent", 2),
        FieldNumber(image, "GlobeGeographicExtent", 3) };
      Expect(box[0] == t[0] && Near(box[1], t[0] + dims[0] * t[2], 1e-9) &&
          Near(box[2], t[1] - dims[1] * t[3], 1e-9) && box[3] == t[1],
        Printf("    geographic extent W %.9f E %.9f S %.9f N %.9f", box[0], box[1], box[2], box[3]));
    }
    else
    {
      Expect(!image->GetFieldData()->GetArray("GlobeGeographicExtent"),
        "    no geographic extent for a projected raster");
    }
  }

  std::printf("World files:\n");
  {
    // An RGB PNG + .pgw + .prj (UTM 10N, EPSG authority in the WKT).
    const std::string png = Temp + "/reader_utm.png";
    Expect(WriteImage(png, 16, 8, 3, OIIO::TypeDesc::UINT8), "wrote a 16 x 8 RGB PNG");
    WriteText(Temp + "/reader_utm.pgw", "30\n0\n0\n-30\n500015\n5200005\n");
    WriteText(Temp + "/reader_utm.prj",
      "PROJCS[\"WGS 84 / UTM zone 10N\",GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS "
      "84\",6378137,298.257223563,AUTHORITY[\"EPSG\",\"7030\"]],AUTHORITY[\"EPSG\",\"6326\"]],"
      "PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433],AUTHORITY[\"EPSG\",\"4326\"]],"
      "PROJECTION[\"Transverse_Mercator\"],PARAMETER[\"central_meridian\",-123],"
      "UNIT[\"metre\",1,AUTHORITY[\"EPSG\",\"9001\"]],AUTHORITY[\"EPSG\",\"32610\"]]");
    vtkNew<vtkGlobeRasterReader> reader;
    vtkNew<vtkTest::ErrorObserver> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(png.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    std::string note;
    const long mismatches = CompareWithOIIO(png, image, note);
    Expect(!errors->GetError() && mismatches == 0 &&
        image->GetPointData()->GetScalars()->GetComponent(0, 0) == 70,
      Printf("PNG pixels equal OpenImageIO's, row 0 south (red of (0, 0) = file row 7 = %g)",
        image->GetPointData()->GetScalars()->GetComponent(0, 0)));
    Expect(FieldNumber(image, "GlobeModelType") == 2 && FieldNumber(image, "GlobeEPSG") == 32610 &&
        FieldNumber(image, "GlobeGeoTransform", 0) == 500000 &&
        FieldNumber(image, "GlobeGeoTransform", 1) == 5200020 &&
        FieldNumber(image, "GlobeGeoTransform", 2) == 30 &&
        FieldNumber(image, "GlobeGeoTransform", 3) == 30 &&
        FieldText(image, "GlobeUnits") == "metre" &&
        FieldText(image, "GlobeGeoreferenceSource") == "world file + .prj",
      Printf(".pgw + .prj: projected EPSG %g, NW corner (%.2f, %.2f) (centre 500015, 5200005 "
             "minus half a pixel), 30 m pixels, %s, from '%s'",
        FieldNumber(image, "GlobeEPSG"), FieldNumber(image, "GlobeGeoTransform", 0),
        FieldNumber(image, "GlobeGeoTransform", 1), FieldText(image, "GlobeUnits").c_str(),
        FieldText(image, "GlobeGeoreferenceSource").c_str()));

    // The same PNG with EPSG:3031 as a WKT without any AUTHORITY (as a PROJ string converts):
    // PROJ identifies it.
    WriteText(Temp + "/reader_utm.pgw", "1000\n0\n0\n-1000\n-1500000\n1500000\n");
    WriteText(Temp + "/reader_utm.prj",
      "PROJCS[\"unknown\",GEOGCS[\"unknown\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,"
      "298.257223563]],PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433]],"
      "PROJECTION[\"Polar_Stereographic\"],PARAMETER[\"latitude_of_origin\",-71],"
      "PARAMETER[\"central_meridian\",0],PARAMETER[\"false_easting\",0],"
      "PARAMETER[\"false_northing\",0],UNIT[\"metre\",1]]");
    {
      vtkNew<vtkGlobeRasterReader> identified;
      identified->SetFileName(png.c_str());
      identified->Update();
      vtkImageData* out = identified->GetOutput();
      Expect(!*identified->GetLastError() && FieldNumber(out, "GlobeEPSG") == 3031 &&
          FieldText(out, "GlobeGeoreferenceSource") == "world file + .prj",
        Printf(".pgw + a .prj WKT without AUTHORITY for Antarctic polar stereographic: EPSG %g "
               "(%s)",
          FieldNumber(out, "GlobeEPSG"), identified->GetLastError()));
    }
    // Web Mercator as a PROJ string in the .prj (a common way to write it): identified too.
    WriteText(Temp + "/reader_utm.pgw", "2504688.5425\n0\n0\n-2504688.5425\n-18785164.07\n8766409.9\n");
    WriteText(Temp + "/reader_utm.prj",
      "+proj=merc +a=6378137 +b=6378137 +lat_ts=0 +lon_0=0 +x_0=0 +y_0=0 +k=1 +units=m "
      "+nadgrids=@null +wktext +no_defs\n");
    {
      vtkNew<vtkGlobeRasterReader> identified;
      identified->SetFileName(png.c_str());
      identified->Update();
      vtkImageData* out = identified->GetOutput();
      Expect(!*identified->GetLastError() && FieldNumber(out, "GlobeModelType") == 2 &&
          FieldNumber(out, "GlobeEPSG") == 3857,
        Printf(".pgw + a .prj holding a Web Mercator PROJ string: projected, EPSG %g",
          FieldNumber(out, "GlobeEPSG")));
    }
    std::remove((Temp + "/reader_utm.prj").c_str());

    // A float TIFF + .tfw in degrees, no .prj: WGS 84 assumed.
    const std::string tif = Temp + "/reader_degrees.tif";
    Expect(WriteImage(tif, 16, 8, 1, OIIO::TypeDesc::FLOAT), "wrote a 16 x 8 float TIFF");
    WriteText(Temp + "/reader_degrees.tfw", "0.25\n0.0\n0.0\n-0.25\n10.125\n49.875\n");
    reader->SetFileName(tif.c_str());
    reader->Update();
    image = reader->GetOutput();
    Expect(!errors->GetError() && FieldNumber(image, "GlobeModelType") == 1 &&
        FieldNumber(image, "GlobeEPSG") == 4326 && FieldNumber(image, "GlobeGeographicExtent", 0) == 10 &&
        FieldNumber(image, "GlobeGeographicExtent", 1) == 14 &&
        FieldNumber(image, "GlobeGeographicExtent", 2) == 48 &&
        FieldNumber(image, "GlobeGeographicExtent", 3) == 50 &&
        image->GetPointData()->GetScalars()->GetComponent(0, 0) == 70 &&
        image->GetPointData()->GetScalars()->GetDataType() == VTK_FLOAT,
      Printf(".tfw alone, numbers in degrees: geographic WGS 84 assumed ('%s'), box 10..14 E, "
             "48..50 N, float values, (0, 0) = %g",
        FieldText(image, "GlobeGeoreferenceSource").c_str(),
        image->GetPointData()->GetScalars()->GetComponent(0, 0)));

    // The same image with metres in its world file: SetEPSG gives the projection.
    WriteText(Temp + "/reader_degrees.tfw", "1000\n0\n0\n-1000\n-3999500\n3999500\n");
    reader->SetEPSG(3413);
    reader->Modified(); // the world file changed under the same image name
    reader->Update();
    image = reader->GetOutput();
    Expect(!errors->GetError() && FieldNumber(image, "GlobeModelType") == 2 &&
        FieldNumber(image, "GlobeEPSG") == 3413 &&
        FieldNumber(image, "GlobeGeoTransform", 0) == -4000000 &&
        FieldText(image, "GlobeUnits") == "metre",
      Printf(".tfw in metres + SetEPSG(3413): projected EPSG %g, '%s', units %s",
        FieldNumber(image, "GlobeEPSG"), FieldText(image, "GlobeGeoreferenceSource").c_str(),
        FieldText(image, "GlobeUnits").c_str()));
    reader->SetEPSG(0);

    // A geographic .prj without an EPSG authority (a planetary body): EPSG 0, its sphere.
    WriteText(Temp + "/reader_degrees.tfw", "0.25\n0.0\n0.0\n-0.25\n10.125\n49.875\n");
    WriteText(Temp + "/reader_degrees.prj",
      "GEOGCS[\"Moon 2000\",DATUM[\"D_Moon_2000\",SPHEROID[\"Moon_2000_IAU_IAG\",1737400.0,0.0]],"
      "PRIMEM[\"Reference_Meridian\",0.0],UNIT[\"Degree\",0.0174532925199433]]");
    reader->Modified();
    reader->Update();
    image = reader->GetOutput();
    Expect(!errors->GetError() && FieldNumber(image, "GlobeModelType") == 1 &&
        FieldNumber(image, "GlobeEPSG") == 0 &&
        FieldNumber(image, "GlobeDatumSemiAxes", 0) == 1737400 &&
        FieldNumber(image, "GlobeDatumSemiAxes", 1) == 1737400 &&
        FieldNumber(image, "GlobeGeographicExtent", 0) == 10,
      "a geographic .prj without EPSG (Moon 2000): geographic, EPSG 0, sphere 1,737,400 m");
    std::remove((Temp + "/reader_degrees.prj").c_str());
  }

  std::printf("Progress:\n");
  for (const char* name : { "earth/mt_everest_90m.tif", "earth/relief_2deg.tif" })
  {
    vtkNew<vtkGlobeRasterReader> reader;
    vtkNew<ProgressRecorder> progress;
    reader->AddObserver(vtkCommand::ProgressEvent, progress);
    reader->SetFileName((Data + "/" + name).c_str());
    reader->Update();
    const std::vector<double>& v = progress->Values;
    bool increasing = !v.empty();
    int between = 0;
    for (size_t i = 0; i < v.size(); ++i)
    {
      increasing = increasing && (i == 0 || v[i] >= v[i - 1]);
      between += v[i] > 0.0 && v[i] < 1.0;
    }
    std::string list;
    for (double x : v)
    {
      list += Printf(" %.3f", x);
    }
    // Chunks are about a twentieth of the rows, rounded up to whole rows of tiles (this file
    // has 256-row tiles: 5 chunks).
    Expect(increasing && between >= 4 && v.back() == 1.0,
      Printf("%s: %zu ProgressEvents, %d strictly between 0 and 1, non-decreasing, last 1:%s",
        name, v.size(), between, list.c_str()));
  }

  std::printf("Bad input (each an error through the executive naming the file and reason):\n");
  {
    struct Bad
    {
      std::string File;
      std::vector<std::string> Words;
      std::string What;
      int EPSG;
    };
    // Fixtures.
    const std::vector<char> everest = ReadBytes(Data + "/earth/mt_everest_90m.tif");
    WriteBytes(Temp + "/reader_head.tif", std::vector<char>(everest.begin(), everest.begin() + 12));
    std::vector<char> garbage(4096);
    for (size_t i = 0; i < garbage.size(); ++i)
    {
      garbage[i] = static_cast<char>((i * 7919 + 13) & 0xff);
    }
    WriteBytes(Temp + "/reader_garbage.png", garbage);
    WriteImage(Temp + "/reader_plain.png", 16, 8, 3, OIIO::TypeDesc::UINT8);
    WriteImage(Temp + "/reader_rotated.png", 16, 8, 3, OIIO::TypeDesc::UINT8);
    WriteText(Temp + "/reader_rotated.pgw", "0.25\n0.01\n0.01\n-0.25\n10.125\n49.875\n");
    WriteImage(Temp + "/reader_metres.png", 16, 8, 3, OIIO::TypeDesc::UINT8);
    WriteText(Temp + "/reader_metres.pgw", "30\n0\n0\n-30\n500015\n5200005\n");
    WriteImage(Temp + "/reader_short.png", 16, 8, 3, OIIO::TypeDesc::UINT8);
    WriteText(Temp + "/reader_short.pgw", "0.25\n0\n0\n");
    // A copy of a GeoTIFF with a world file that disagrees with its tags.
    WriteBytes(Temp + "/reader_disagree.tif", ReadBytes(Data + "/earth/relief_2deg.tif"));
    WriteText(Temp + "/reader_disagree.tfw", "2\n0\n0\n-2\n-178\n89\n");
    // ... and one whose world file agrees (not an error).
    WriteBytes(Temp + "/reader_agree.tif", ReadBytes(Data + "/earth/relief_2deg.tif"));
    WriteText(Temp + "/reader_agree.tfw", "2\n0\n0\n-2\n-179\n89\n");
    // The UTM GeoTIFF with a .prj saying WGS 84 geographic.
    WriteBytes(Temp + "/reader_utm_prj.tif", ReadBytes(Data + "/earth/mt_rainier_utm10n.tif"));
    WriteText(Temp + "/reader_utm_prj.prj", "GEOGCS[\"WGS 84\",AUTHORITY[\"EPSG\",\"4326\"]]");
    // A geographic .prj carrying a projected code.
    WriteImage(Temp + "/reader_geog_utm.png", 16, 8, 3, OIIO::TypeDesc::UINT8);
    WriteText(Temp + "/reader_geog_utm.pgw", "0.25\n0\n0\n-0.25\n10.125\n49.875\n");
    WriteText(Temp + "/reader_geog_utm.prj", "GEOGCS[\"WGS 84\",AUTHORITY[\"EPSG\",\"32610\"]]");

    const std::vector<Bad> bad = {
      { Temp + "/reader_missing.tif", { "does not exist" }, "a missing file", 0 },
      { Temp + "/reader_head.tif", { "cannot be opened as an image" },
        "mt_everest_90m.tif cut after 12 bytes", 0 },
      { Temp + "/reader_garbage.png", { "cannot be opened as an image" }, "4 KiB of garbage", 0 },
      { Temp + "/reader_plain.png", { "not a TIFF file", "no world file", ".pgw", ".pngw" },
        "a PNG without georeferencing or world file", 0 },
      { Temp + "/reader_rotated.pgw", { "cannot be opened as an image" },
        "a world file given as the image", 0 },
      { Temp + "/reader_rotated.png", { "rotated or sheared", "reader_rotated.pgw" },
        "a rotated world file", 0 },
      { Temp + "/reader_short.png", { "does not hold six numbers" }, "a world file of 3 numbers",
        0 },
      { Temp + "/reader_metres.png", { "are not degrees", "no .prj" },
        "a world file in metres without any projection", 0 },
      { Temp + "/reader_disagree.tif", { "contradictory", "reader_disagree.tfw", "GeoTIFF tags" },
        "a world file disagreeing with the GeoTIFF tags", 0 },
      { Temp + "/reader_utm_prj.tif", { "contradictory", "EPSG:4326", "EPSG:32610" },
        "a .prj (EPSG:4326) disagreeing with the GeoTIFF tags (EPSG:32610)", 0 },
      { Temp + "/reader_geog_utm.png", { "contradictory", "geographic", "EPSG:32610", "projected" },
        "a geographic .prj with a projected EPSG code", 0 },
      { Data + "/earth/relief_2deg.tif", { "contradictory", "EPSG:4326", "SetEPSG", "EPSG:3413" },
        "SetEPSG(3413) on an EPSG:4326 GeoTIFF", 3413 },
      { Temp + "/reader_metres.png", { "EPSG:999999", "PROJ's database" },
        "SetEPSG(999999), unknown to PROJ", 999999 },
    };
    for (const Bad& b : bad)
    {
      vtkNew<vtkGlobeRasterReader> reader;
      vtkNew<vtkTest::ErrorObserver> errors;
      vtkNew<vtkTest::ErrorObserver> executiveErrors;
      reader->AddObserver(vtkCommand::ErrorEvent, errors);
      reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
      reader->SetFileName(b.File.c_str());
      reader->SetEPSG(b.EPSG);
      const int updated = reader->GetExecutive()->Update();
      const std::string message = errors->GetErrorMessage();
      bool said = errors->GetError() && message.find(b.File) != std::string::npos;
      for (const std::string& w : b.Words)
      {
        said = said && message.find(w) != std::string::npos;
      }
      const size_t start = message.find("Cannot read");
      std::printf("       error: %s", message.substr(start == std::string::npos ? 0 : start).c_str());
      Expect(!updated && said && executiveErrors->GetError() &&
          reader->GetErrorCode() != vtkErrorCode::NoError &&
          reader->GetOutput()->GetNumberOfPoints() == 0 && *reader->GetLastError(),
        b.What + ": the update fails, the executive reports it, error code " +
          vtkErrorCode::GetStringFromErrorCode(reader->GetErrorCode()) + ", no points");
    }

    {
      // Pieces (what each MPI rank of pvbatch asks for): the executive splits the raster by
      // extent; each piece holds exactly the whole read's values there, the pieces cover it.
      vtkNew<vtkGlobeRasterReader> whole;
      whole->SetFileName((Data + "/earth/relief_2deg.tif").c_str());
      whole->Update();
      vtkImageData* all = whole->GetOutput();
      int covered = 0, differ = 0, empty = 0, shared = 0;
      std::vector<int> seen(180 * 90, 0);
      std::string extents;
      for (int piece = 0; piece < 3; ++piece)
      {
        vtkNew<vtkGlobeRasterReader> part;
        part->SetFileName((Data + "/earth/relief_2deg.tif").c_str());
        part->UpdatePiece(piece, 3, 0);
        vtkImageData* out = part->GetOutput();
        int e[6];
        out->GetExtent(e);
        extents += Printf(" %d..%d x %d..%d", e[0], e[1], e[2], e[3]);
        empty += out->GetNumberOfPoints() == 0 ? 1 : 0;
        for (int j = e[2]; j <= e[3] && out->GetNumberOfPoints() > 0; ++j)
        {
          for (int i = e[0]; i <= e[1]; ++i)
          {
            const double ours = out->GetScalarComponentAsDouble(i, j, 0, 0);
            differ += ours != all->GetScalarComponentAsDouble(i, j, 0, 0) ? 1 : 0;
            shared += seen[j * 180 + i]++ > 0 ? 1 : 0;
          }
        }
      }
      for (int v : seen)
      {
        covered += v > 0 ? 1 : 0;
      }
      Expect(empty == 0 && differ == 0 && covered == 180 * 90,
        Printf("relief_2deg.tif as 3 pieces (%s): none empty, %d points differ from the whole "
               "read, %d of 16,200 covered (%d shared by neighbouring pieces)",
          extents.c_str(), differ, covered, shared));
    }

    vtkNew<vtkGlobeRasterReader> reader;
    vtkNew<vtkTest::ErrorObserver> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName((Temp + "/reader_agree.tif").c_str());
    reader->Update();
    Expect(!errors->GetError() && reader->GetOutput()->GetNumberOfPoints() == 180 * 90 &&
        reader->GetErrorCode() == vtkErrorCode::NoError,
      "a world file agreeing with the GeoTIFF tags is not an error");
    reader->SetFileName((Temp + "/reader_missing.tif").c_str());
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->Update();
    Expect(errors->GetError() && reader->GetOutput()->GetNumberOfPoints() == 0,
      "a failure after a success leaves no stale points");
  }

  return Checks.Result();
}
