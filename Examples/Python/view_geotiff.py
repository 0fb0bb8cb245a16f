#!/usr/bin/python3
"""Show your own GeoTIFF on the globe, with the camera framed on its extent.

A 1-channel raster is drawn as terrain heights (metres), a 3- or 4-channel one as imagery
(--role overrides). On an Earth raster the demo's relief and imagery are drawn below it; a
raster whose GeoTIFF names another body's ellipsoid (e.g. the Moon's 1,737,400 m sphere) is
drawn alone on that body. Geographic (longitude/latitude) rasters and projected ones are drawn
as they are, without reprojection, in the projections the globe knows: equirectangular, polar
stereographic, Mercator, Web Mercator, transverse Mercator / UTM, Lambert conformal conic,
Albers, Lambert azimuthal (polar and oblique) and cylindrical equal-area (EPSG codes in
Documentation/projections.md); a raster in any other CRS that PROJ knows is reprojected to
longitude/latitude when it loads.
"""
import math
import os
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkRenderingCore import vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid, vtkGlobeLayer, vtkGlobeMapProjection

WGS84_A = 6378137.0


class LoadError(Exception):
    pass


def collect_errors(obj):
    """VTK reports through ErrorEvent; collect the messages instead of printing them."""
    messages = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        # VTK's text starts with "ERROR: In <file>, line <n>\nvtkGlobeLayer (0x...): ".
        messages.append(str(message).strip().split("): ", 1)[-1])
    obj.AddObserver(vtkCommand.ErrorEvent, on_error)
    return messages


def load(path, role):
    """The user's layer, loaded; raises LoadError with a one-line reason."""
    if not os.path.exists(path):
        raise LoadError("%s: no such file" % path)
    if not os.path.isfile(path):
        raise LoadError("%s: not a file" % path)
    with open(path, "rb") as f:
        magic = f.read(4)
    if magic not in (b"II*\x00", b"MM\x00*", b"II+\x00", b"MM\x00+"):
        raise LoadError("%s: not a GeoTIFF (not a TIFF file at all)" % path)
    layer = vtkGlobeLayer()
    messages = collect_errors(layer)
    layer.SetFileName(path)
    if role == "color":
        layer.SetRoleToColor()
    else:
        layer.SetRoleToHeight()
    ok = layer.Update()
    if not ok and role == "auto" and messages and "needs a 1-channel" in messages[-1]:
        del messages[:]
        layer.SetRoleToColor()  # more than one channel: imagery
        ok = layer.Update()
    if not ok:
        reason = messages[-1] if messages else "unknown reason"
        raise LoadError("%s: cannot be shown: %s" % (path, reason))
    if layer.GetModelType() != vtkGlobeLayer.Geographic:
        projection_of(layer, path)  # a projection the globe cannot draw is refused here
    return layer


def projection_of(layer, path=None):
    """The projected layer's map projection on the CPU: vtkGlobeMapProjection set up as the
    globe sets it up to draw the layer. Raises LoadError where the globe would refuse the layer:
    no EPSG code, a projection it does not know, a raster outside the projection's domain."""
    path = path or layer.GetFileName()
    epsg = layer.GetEPSG()
    if epsg <= 0:
        raise LoadError("%s: it is in projected coordinates without an EPSG code" % path)
    projection = vtkGlobeMapProjection()
    collect_errors(projection)  # its own message would not name the file
    if not projection.SetFromEPSG(epsg):
        # Layers in other CRSs are reprojected on load (geographic then): not reached for them.
        raise LoadError("%s: its map projection (EPSG:%d) is not one the globe draws"
                        % (path, epsg))
    a, b = layer.GetDatumSemiMajorAxis(), layer.GetDatumSemiMinorAxis()
    if 0 < b <= a:
        projection.SetEllipsoid(a, (a - b) / a)  # the file's own datum
    # The raster's middle must map to a place in the projection's domain and back to itself.
    origin, pixel = [0.0] * 2, [0.0] * 2
    layer.GetProjectedGeoTransform(origin, pixel)
    middle = (origin[0] + 0.5 * pixel[0] * layer.GetNumberOfColumns(),
              origin[1] - 0.5 * pixel[1] * layer.GetNumberOfRows())
    lonlat, back = [0.0] * 2, [0.0] * 2
    if not (projection.Inverse(middle[0], middle[1], lonlat)
            and projection.IsInValidDomain(*lonlat) and projection.Forward(*lonlat, back)
            and abs(back[0] - middle[0]) < 0.01 * pixel[0]
            and abs(back[1] - middle[1]) < 0.01 * pixel[1]):
        raise LoadError("%s: the raster lies outside the domain of its projection (EPSG:%d)"
                        % (path, epsg))
    return projection


def footprint(layer, samples=64):
    """Where the raster lies: (extent, centre), extent = [west, east, south, north] in degrees
    around its outer pixel edges, centre = (lon, lat) of its middle. A projected raster's edges
    are sampled and mapped back to longitude/latitude (east may exceed 180 across the date
    line); a pole inside the raster extends the box to that pole, and the centre is then the
    pole, on the meridian that points up the map."""
    extent = [0.0] * 4
    if layer.GetModelType() == vtkGlobeLayer.Geographic:
        layer.GetGeographicExtent(extent)
        return extent, (0.5 * (extent[0] + extent[1]), 0.5 * (extent[2] + extent[3]))
    projection = projection_of(layer)
    origin, pixel = [0.0] * 2, [0.0] * 2
    layer.GetProjectedGeoTransform(origin, pixel)
    west, north = origin
    east, south = west + layer.GetNumberOfColumns() * pixel[0], north - layer.GetNumberOfRows() * pixel[1]
    lonlat = [0.0] * 2

    def inverse(x, y):
        return tuple(lonlat) if projection.Inverse(x, y, lonlat) else None

    middle = inverse(0.5 * (west + east), 0.5 * (south + north))  # projection_of checked it
    lons, lats = [], []
    for k in range(samples + 1):
        f = k / samples
        for x, y in ((west + f * (east - west), north), (west + f * (east - west), south),
                     (west, south + f * (north - south)), (east, south + f * (north - south))):
            point = inverse(x, y)
            if point:
                # Longitudes unwrapped around the middle's, so a raster across the date line
                # gets one box.
                lons.append(middle[0] + (point[0] - middle[0] + 180.0) % 360.0 - 180.0)
                lats.append(point[1])
    extent = [min(lons), max(lons), min(lats), max(lats)]
    centre = middle
    xy = [0.0] * 2
    for pole in (90.0, -90.0):
        if (projection.Forward(middle[0], pole, xy) and west <= xy[0] <= east
                and south <= xy[1] <= north):
            extent = [-180.0, 180.0, min(extent[2], pole), max(extent[3], pole)]
            # Looking down on a pole, the picture's up is the far side of the camera's meridian:
            # put the camera on the meridian that leaves the pole down the map (north pole) or
            # up it (south pole), so that the map's up is the picture's up.
            step = 1e-3 * (north - south) * (1.0 if pole < 0 else -1.0)
            below = inverse(xy[0], xy[1] + step)
            centre = (below[0] if below else middle[0], pole)
    return extent, centre


def body_for(layer):
    """The layer's own ellipsoid when its GeoTIFF names one that is not the Earth's, else WGS84."""
    body = vtkGlobeEllipsoid()
    a, b = layer.GetDatumSemiMajorAxis(), layer.GetDatumSemiMinorAxis()
    if a > 0 and b > 0 and abs(a - WGS84_A) > 1.0e4:
        body.SetRadii(a, a, b)
        body.SetName("from %s" % os.path.basename(layer.GetFileName()))
    return body


def frame(renderer, body, extent, aspect, top=0.0, view_angle=30.0, centre=None):
    """Puts the camera straight above the middle of extent (west, east, south, north; degrees),
    or above centre (lon, lat) when given, so that the whole extent fits the view; top: the
    highest terrain (m). Returns the camera's geodetic position."""
    west, east, south, north = extent
    lon, lat = centre if centre else (0.5 * (west + east), 0.5 * (south + north))
    radius = body.GetMaximumRadius()
    # Half sizes (m) of the extent on the ground, and the view's half angles.
    half_ns = math.radians(north - south) / 2.0 * radius
    half_ew = math.radians(east - west) / 2.0 * radius * math.cos(math.radians(min(abs(south), abs(north))
                                                                           if south * north > 0 else 0.0))
    tan_v = math.tan(math.radians(view_angle) / 2.0)
    tan_h = tan_v * aspect
    if north - south > 60.0 or east - west > 60.0:
        # Too big to see from above a point: the whole body, centred on the extent.
        altitude = radius / math.sin(math.atan(tan_v)) * 1.1 - radius
    else:
        altitude = 1.15 * max(half_ns / tan_v, half_ew / tan_h) + top
    camera = (lon, lat, altitude)
    near = max(1.0, 0.5 * (altitude - top))
    far = 2.0 * math.sqrt((radius + altitude) ** 2 - radius ** 2) + 2.0 * altitude
    globe_scene.look_at(renderer, body, camera, (lon, lat, 0.0), view_angle, (near, far))
    return camera


def build(layer, size, grid, data=globe_scene.DATA, interactive=False):
    """Returns (window, renderer, body, camera)."""
    body = body_for(layer)
    mapper, actor = globe_scene.globe(body, grid)
    if body.GetName() == "WGS84":
        mapper.AddLayer(globe_scene.file_layer(os.path.join(data, "earth", "relief_2deg.tif"), "height"))
        mapper.AddLayer(globe_scene.file_layer(os.path.join(data, "earth", "world.tif"), "color"))
    mapper.AddLayer(layer)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.0, 0.0, 0.0)
    extent, centre = footprint(layer)
    top = layer.GetMaximumValue() if layer.GetRole() == vtkGlobeLayer.Height else 0.0
    camera = frame(renderer, body, extent, size[0] / size[1], max(top, 0.0), centre=centre)
    globe_scene.add_sun(renderer, body, (camera[0], camera[1], 0.0), 135.0, 45.0)
    return globe_scene.window_for(renderer, size, interactive), renderer, body, camera


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "geotiff.png")
    parser.description = __doc__
    parser.formatter_class = __import__("argparse").RawDescriptionHelpFormatter
    parser.add_argument("geotiff", help="the GeoTIFF file to show")
    parser.add_argument("--role", choices=("auto", "height", "color"), default="auto",
                        help="heights or imagery (default: auto, from the channel count)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    try:
        layer = load(args.geotiff, args.role)
        extent, _ = footprint(layer)
    except LoadError as error:
        print("error: %s" % error, file=sys.stderr)
        return 1
    projected = layer.GetModelType() != vtkGlobeLayer.Geographic
    reprojected = layer.GetReprojectedFromEPSG()
    print("%s: %dx%d %s raster%s, lon [%.6f, %.6f], lat [%.6f, %.6f]" % (
        args.geotiff, layer.GetNumberOfColumns(), layer.GetNumberOfRows(), layer.GetRoleAsString().lower(),
        " in EPSG:%d" % layer.GetEPSG() if projected else
        (" reprojected from EPSG:%d" % reprojected if reprojected else ""), *extent))
    globe_scene.require_display()
    window, _, body, camera = build(layer, size, args.grid, args.data, args.interactive)
    print("body %s; camera at lon %.4f lat %.4f, %.0f m up" % (body.GetName(), *camera))
    globe_scene.show(window, args.out, args.interactive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
