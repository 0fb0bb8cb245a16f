#!/usr/bin/python3
"""Stream a raster far larger than memory onto the Earth: pages load as the view needs them.

Give it any georeferenced raster; one that is larger than a few thousand posts a side should
be prepared first (tiled, with nodata-aware levels; keeps the georeferencing):

    bash Utilities/globe.sh prepare big_world.tif big_world_prepared.tif
    bash Utilities/globe.sh python Examples/Python/stream_raster.py big_world_prepared.tif

A 1-channel raster is drawn as heights, a 3- or 4-channel one as imagery (--role overrides),
over the demo's 2-degree relief. Offscreen, the frames render without waiting for the disk, and
the script reports each frame's page statistics until the picture is final
(vtkGlobeMapper.IsStreamingIdle), then writes the PNG. Interactive, a timer renders again while
pages are still coming in. Documentation/streaming.md explains the page cache.
"""
import argparse
import os
import sys
import time

from vtkmodules.vtkRenderingCore import vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid, vtkGlobeLayer, vtkGlobePageSource


def parse_view(parser, text):
    try:
        lon, lat, height = (float(v) for v in text.split(","))
        return lon, lat, height
    except ValueError:
        parser.error("--view needs lon,lat,height (degrees, degrees, metres), got %r" % text)


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "stream.png", grid=256)
    parser.description = __doc__
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("raster", help="the raster to stream (GeoTIFF, or an image with a world file)")
    parser.add_argument("--role", choices=("auto", "height", "color"), default="auto",
                        help="heights or imagery (default: from the channel count)")
    parser.add_argument("--view", default="-121.76,46.85,400000",
                        help="camera over lon,lat at height (m), looking down (default: %(default)s)")
    parser.add_argument("--gpu", type=float, default=120.0,
                        help="GPU page cache per data kind, MiB (default: %(default)s)")
    parser.add_argument("--page", type=int, default=256, help="page size in texels (default: %(default)s)")
    parser.add_argument("--frames", type=int, default=200,
                        help="offscreen: most frames to render before giving up (default: %(default)s)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    view = parse_view(parser, args.view)

    if not os.path.isfile(args.raster):
        print("error: %s: the file does not exist" % args.raster, file=sys.stderr)
        return 1
    layer = vtkGlobeLayer()
    layer.SetFileName(args.raster)
    layer.SetStreamingToOn()  # the default (Auto) streams only rasters over 8192 a side
    layer.GetPageSource().SetPageSize(args.page)  # the page cache's size (set below)
    role = args.role
    if role == "auto":
        probe = vtkGlobePageSource()
        probe.SetFileName(args.raster)
        role = "height" if probe.GetNumberOfComponents() == 1 else "color"
    if role == "height":
        layer.SetRoleToHeight()
    else:
        layer.SetRoleToColor()
    if not layer.Update():
        print("error: %s cannot be streamed (see the message above)" % args.raster, file=sys.stderr)
        return 1
    print("%s: %dx%d %s, %d levels of %d-texel pages" % (
        args.raster, layer.GetNumberOfColumns(), layer.GetNumberOfRows(), role,
        layer.GetPageSource().GetNumberOfLevels(), layer.GetPageSource().GetPageSize()))

    globe_scene.require_display()
    body = vtkGlobeEllipsoid()
    mapper, actor = globe_scene.globe(body, args.grid)
    mapper.AddLayer(globe_scene.file_layer("%s/earth/relief_2deg.tif" % args.data, "height"))
    mapper.AddLayer(layer)
    cache = mapper.GetPageCache()
    cache.SetGPUMemory(args.gpu)
    cache.SetPageSize(args.page)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.02, 0.02, 0.05)
    window = globe_scene.window_for(renderer, size, args.interactive)
    globe_scene.look_at(renderer, body, view, (view[0], view[1], 0.0), 40.0)

    if args.interactive:
        def refine():
            # Frames never wait for the disk: render again until the picture is final.
            if not mapper.IsStreamingIdle():
                window.Render()

        globe_scene.show(window, args.out, True, on_timer=refine)
        return 0

    print("frame      ms  resident  loaded  evicted  uploaded")
    for frame in range(args.frames):
        start = time.perf_counter()
        window.Render()
        ms = 1000.0 * (time.perf_counter() - start)
        print("%5d %7.1f %9d %7d %8d %8.1fM" % (
            frame + 1, ms, cache.GetNumberOfResidentPages(), cache.GetNumberOfLoadedPages(),
            cache.GetNumberOfEvictedPages(), cache.GetBytesUploaded() / 2.0 ** 20))
        if mapper.IsStreamingIdle():
            print("final after %d frames" % (frame + 1))
            break
        time.sleep(0.01)  # the page readers run on their own threads
    else:
        print("not final after %d frames (a cache smaller than the view needs?)" % args.frames)
    print("GPU page cache %.2f MiB (atlas %g MiB per kind, and page tables); all layers %.2f MiB; "
          "CPU page cache %.1f MiB" % (
              cache.GetGPUMemoryUsed() / 2.0 ** 20, args.gpu,
              mapper.GetLayerSet().GetTextureMemory() / 2.0 ** 20,
              cache.GetCPUMemoryUsed() / 2.0 ** 20))
    globe_scene.show(window, args.out, False)
    return 0


if __name__ == "__main__":
    sys.exit(main())
