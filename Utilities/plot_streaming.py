#!/usr/bin/env python3
"""Plots GlobeStreamingBenchmark's JSON with vtkChartXY (VTK and the standard library only).

    plot_streaming.py STREAMING_JSON [--images DIR]

Writes DIR/streaming-flight.png (frame time along the flight, one line per run, with the
camera's altitude on the right) and DIR/streaming-size.png (first and steady frame time, and
peak RSS, against the data's width: flat means the frame does not pay for the data size).
Default DIR: Documentation/images.
"""

import argparse
import json
import os

import plot_benchmark  # the same charts and PNG writing (this script's folder is on sys.path)

COLORS = [(31, 119, 180), (214, 39, 40), (44, 160, 44), (148, 103, 189), (255, 127, 14),
          (140, 86, 75), (127, 127, 127), (188, 189, 34)]


def add_line(chart, name_x, name_y, points, rgb, corner=None):
    """A line through the points (markers alone where there are fewer than two)."""
    from vtkmodules.vtkChartsCore import vtkChart
    table = plot_benchmark.points_table(name_x, name_y, points)
    single = len(points) < 2
    plot = chart.AddPlot(vtkChart.POINTS if single else vtkChart.LINE)
    plot.SetInputData(table, 0, 1)
    plot.SetColor(rgb[0], rgb[1], rgb[2], 255)
    if single:
        plot.SetMarkerSize(9)
    else:
        plot.SetWidth(1.5)
    if corner is not None:
        chart.SetPlotCorner(plot, corner)
    return plot


def save(view, path):
    plot_benchmark.save(view, path)
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json")
    parser.add_argument("--images", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "Documentation", "images"))
    args = parser.parse_args()
    with open(args.json) as f:
        data = json.load(f)
    os.makedirs(args.images, exist_ok=True)
    from vtkmodules.vtkChartsCore import vtkAxis

    view, chart = plot_benchmark.chart_view(
        "Flight Earth -> Rainier -> Earth: frame time (%s, %dx%d)" % (
            data.get("gl_renderer", "?"), data["window"][0], data["window"][1]), (900, 520))
    for i, run in enumerate(data["runs"]):
        add_line(chart, "frame", run["label"], list(enumerate(run["frame_ms"], 1)),
                 COLORS[i % len(COLORS)])
    blocks = data["runs"][0]["blocks"]
    altitude = add_line(chart, "frame", "camera height (km, right)",
                        [(b["frame"], b["altitude_m"] / 1000.0) for b in blocks], (0, 0, 0), corner=1)
    altitude.SetWidth(1.0)
    chart.GetAxis(vtkAxis.BOTTOM).SetTitle("frame")
    chart.GetAxis(vtkAxis.LEFT).SetTitle("frame time (ms)")
    chart.GetAxis(vtkAxis.LEFT).SetLogScale(True)
    chart.GetAxis(vtkAxis.RIGHT).SetTitle("camera height (km)")
    chart.GetAxis(vtkAxis.RIGHT).SetLogScale(True)
    save(view, os.path.join(args.images, "streaming-flight.png"))

    view, chart = plot_benchmark.chart_view("Frame time and memory against data size", (900, 520))
    for j, mode in enumerate(("streamed", "in-core")):
        runs = sorted([r for r in data["runs"] if r["mode"] == mode], key=lambda r: r["width"])
        if not runs:
            continue
        add_line(chart, "width", "%s: steady frame (ms)" % mode,
                 [(r["width"], r["steady_ms"]) for r in runs], COLORS[2 * j])
        add_line(chart, "width", "%s: first frame (ms)" % mode,
                 [(r["width"], r["first_ms"]) for r in runs], COLORS[2 * j + 1])
        add_line(chart, "width", "%s: peak RSS (MiB)" % mode,
                 [(r["width"], r["peak_rss_mib"]) for r in runs], COLORS[4 + j])
    chart.GetAxis(vtkAxis.BOTTOM).SetTitle("raster width (posts; height = width / 2)")
    chart.GetAxis(vtkAxis.BOTTOM).SetLogScale(True)
    chart.GetAxis(vtkAxis.LEFT).SetTitle("ms, MiB")
    chart.GetAxis(vtkAxis.LEFT).SetLogScale(True)
    save(view, os.path.join(args.images, "streaming-size.png"))


if __name__ == "__main__":
    main()
