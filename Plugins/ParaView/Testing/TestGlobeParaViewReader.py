"""The VTKGlobe plugin in pvpython: the Globe Raster Reader proxy reads Data/earth rasters with
their georeferencing, through ParaView's server manager.

- The plugin loads (LoadPlugin) and provides the proxy as paraview.simple.GlobeRasterReader.
- relief_2deg.tif (float32, EPSG:4326, 2 degree pixels): the data information ParaView computes
  on the server (extent, bounds, the range of "Values") and the field data fetched to the
  client (model type, EPSG, geotransform, geographic extent, units, source) are the README's
  and the C++ tests' numbers; every one of the 16,200 values equals ParaView's own GDAL
  reader's (vtkGDALRasterReader, an independent reading of the same file) at the same place.
- mt_rainier_90m.tif (int16 SRTM with voids): 1201 x 1201 posts of 1/1200 degree whose origin
  is (-122, 46), 9,033 voids of -32768 (GlobeNoDataValue), highest post 4,371 m.
- mt_rainier_utm10n.tif: a projected raster (EPSG:32610, metres, 90 m pixels).
- The EPSG property reaches the reader: EPSG 3413 on an EPSG:4326 GeoTIFF is contradictory, the
  read fails and the output is empty; back to 0, the same proxy reads again.
"""
import math
import os
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin

PLUGIN = os.environ["VTKGLOBE_PARAVIEW_PLUGIN"]
DATA = os.environ["VTKGLOBE_DATA_DIR"]

failures = []


def expect(condition, what):
    print("%s %s" % ("ok  " if condition else "FAIL", what))
    if not condition:
        failures.append(what)


def near(a, b, tolerance):
    return abs(a - b) <= tolerance


def field(data, name):
    """A field-data array: its string, its one number, or a tuple of all its numbers."""
    a = data.GetFieldData().GetAbstractArray(name)
    if a is None:
        return None
    if a.IsA("vtkStringArray"):
        return a.GetValue(0)
    values = tuple(a.GetComponent(k, c) for k in range(a.GetNumberOfTuples())
                   for c in range(a.GetNumberOfComponents()))
    return values if len(values) > 1 else values[0]


# As a user does: the plugin's proxies become functions of the namespace given.
LoadPlugin(PLUGIN, remote=False, ns=globals())
expect("GlobeRasterReader" in globals(),
       "LoadPlugin(%s) defines GlobeRasterReader" % os.path.basename(PLUGIN))
if failures:
    sys.exit(1)

# relief_2deg.tif: 180 x 90 pixels of 2 degrees, north-west corner (-180, 90).
relief_file = os.path.join(DATA, "earth", "relief_2deg.tif")
relief = GlobeRasterReader(FileName=relief_file)
relief.UpdatePipeline()
info = relief.GetDataInformation()
expect(info.GetDataSetTypeAsString() == "vtkImageData" and
       tuple(info.GetExtent()) == (0, 179, 0, 89, 0, 0),
       "relief_2deg.tif: %s, extent %s (180 x 90 points)"
       % (info.GetDataSetTypeAsString(), tuple(info.GetExtent())))
bounds = tuple(info.GetBounds())
expect(all(near(a, b, 1e-12) for a, b in zip(bounds, (-179, 179, -89, 89, 0, 0))),
       "bounds %s: pixel centres from (-179, -89) to (179, 89) degrees" % (bounds,))
values = relief.PointData["Values"]
expect(values is not None and near(values.GetRange()[0], -6526.5, 0.05) and
       near(values.GetRange()[1], 5211.5, 0.05),
       "'Values' range %s: the README's -6526.5 .. 5211.5 m" % (values.GetRange(),))

image = servermanager.Fetch(relief)
expect(image.GetClassName() == "vtkImageData" and image.GetNumberOfPoints() == 16200 and
       image.GetPointData().GetScalars().GetDataTypeAsString() == "float",
       "Fetch: %s, %d points, %s scalars" % (image.GetClassName(), image.GetNumberOfPoints(),
                                             image.GetPointData().GetScalars()
                                             .GetDataTypeAsString()))
expect(image.GetSpacing()[:2] == (2.0, 2.0) and image.GetOrigin()[:2] == (-179.0, -89.0),
       "spacing %s, origin %s (the centre of the south-west pixel)"
       % (image.GetSpacing()[:2], image.GetOrigin()[:2]))
expect(field(image, "GlobeModelType") == 1 and field(image, "GlobeEPSG") == 4326,
       "field data: GlobeModelType %s (geographic), GlobeEPSG %s"
       % (field(image, "GlobeModelType"), field(image, "GlobeEPSG")))
expect(field(image, "GlobeGeoTransform") == (-180.0, 90.0, 2.0, 2.0),
       "GlobeGeoTransform %s: north-west corner (-180, 90), 2 x 2 degree pixels"
       % (field(image, "GlobeGeoTransform"),))
expect(field(image, "GlobeGeographicExtent") == (-180.0, 180.0, -90.0, 90.0),
       "GlobeGeographicExtent %s" % (field(image, "GlobeGeographicExtent"),))
expect(field(image, "GlobeUnits") == "degree" and
       field(image, "GlobeGeoreferenceSource") == "GeoTIFF" and
       field(image, "GlobeFileName") == relief_file,
       "GlobeUnits '%s', GlobeGeoreferenceSource '%s', GlobeFileName the file read"
       % (field(image, "GlobeUnits"), field(image, "GlobeGeoreferenceSource")))

# ParaView's GDAL reader on the same file: cell data, row 0 south, origin at the south-west
# outer corner, so its cell (i, j) is our point (i, j).
from vtkmodules.vtkIOGDAL import vtkGDALRasterReader  # noqa: E402

gdal = vtkGDALRasterReader()
gdal.SetFileName(relief_file)
gdal.Update()
reference = gdal.GetOutput()
ref = reference.GetCellData().GetArray("Elevation")
ours = image.GetPointData().GetScalars()
differ, compared = 0, 0
if ref is not None and ref.GetNumberOfTuples() == 16200 and \
        reference.GetOrigin()[:2] == (-180.0, -90.0):
    for k in range(16200):
        compared += 1
        differ += ours.GetValue(k) != ref.GetValue(k)
expect(compared == 16200 and differ == 0,
       "all %d values equal vtkGDALRasterReader's at the same place (%d differ)"
       % (compared, differ))
# The pixel that contains (1E, 1N): column 90, row 45 from the south.
k = 45 * 180 + 90
expect(ref is not None and ours.GetValue(k) == ref.GetValue(k) and
       not math.isnan(ours.GetValue(k)),
       "spot check at (1E, 1N), point (90, 45): %.3f m" % ours.GetValue(k))

# The EPSG property reaches the reader: a contradiction fails the read...
relief.EPSG = 3413
print("(an error about contradictory georeferencing is expected here)")
relief.UpdatePipeline()
expect(relief.GetDataInformation().GetNumberOfPoints() == 0,
       "EPSG = 3413 on the EPSG:4326 file: the read fails, %d points"
       % relief.GetDataInformation().GetNumberOfPoints())
# ... and without it the same proxy reads again.
relief.EPSG = 0
relief.UpdatePipeline()
expect(relief.GetDataInformation().GetNumberOfPoints() == 16200,
       "EPSG = 0 again: %d points" % relief.GetDataInformation().GetNumberOfPoints())

# mt_rainier_90m.tif: SRTM 3" with voids.
rainier = GlobeRasterReader(FileName=os.path.join(DATA, "earth", "mt_rainier_90m.tif"))
srtm = servermanager.Fetch(rainier)
step = 1.0 / 1200.0
expect(srtm.GetDimensions() == (1201, 1201, 1) and
       near(srtm.GetSpacing()[0], step, 1e-15) and near(srtm.GetSpacing()[1], step, 1e-15),
       "mt_rainier_90m.tif: %s points, spacing %.15g degrees (1/1200)"
       % (srtm.GetDimensions(), srtm.GetSpacing()[0]))
expect(near(srtm.GetOrigin()[0], -122.0, 1e-12) and near(srtm.GetOrigin()[1], 46.0, 1e-12),
       "origin (%.12f, %.12f): the centre of the south-west post, (-122, 46)"
       % srtm.GetOrigin()[:2])
posts = srtm.GetPointData().GetScalars()
voids, highest = 0, -1e300
for k in range(posts.GetNumberOfTuples()):
    v = posts.GetValue(k)
    if v == -32768:
        voids += 1
    else:
        highest = max(highest, v)
expect(posts.GetDataTypeAsString() == "short" and voids == 9033 and highest == 4371,
       "%s posts, %d voids of -32768 (README: 9,033), highest %d m (README: 4,371)"
       % (posts.GetDataTypeAsString(), voids, highest))
expect(field(srtm, "GlobeNoDataValue") == -32768.0,
       "GlobeNoDataValue %s" % field(srtm, "GlobeNoDataValue"))

# A projected raster.
utm = servermanager.Fetch(GlobeRasterReader(
    FileName=os.path.join(DATA, "earth", "mt_rainier_utm10n.tif")))
transform = field(utm, "GlobeGeoTransform")
expect(field(utm, "GlobeModelType") == 2 and field(utm, "GlobeEPSG") == 32610 and
       field(utm, "GlobeUnits") == "metre",
       "mt_rainier_utm10n.tif: GlobeModelType %s (projected), EPSG %s, units '%s'"
       % (field(utm, "GlobeModelType"), field(utm, "GlobeEPSG"), field(utm, "GlobeUnits")))
expect(transform is not None and near(transform[0], 575993.04, 0.01) and
       near(transform[1], 5207152.44, 0.01) and near(transform[2], 90, 1e-9) and
       near(transform[3], 90, 1e-9) and utm.GetDimensions()[:2] == (876, 1252),
       "GlobeGeoTransform %s, %s points: the README's UTM tile" % (transform,
                                                                   utm.GetDimensions()[:2]))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
