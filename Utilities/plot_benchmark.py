#!/usr/bin/env python3
"""Plots GlobeBenchmark's JSON: error against frame time per scene, and the Pareto fronts.

    plot_benchmark.py BENCHMARK_JSON [--images DIR] [--markdown FILE] [--no-images]
    plot_benchmark.py --windows JSON... [--images DIR] [--no-images]

Imports only VTK and the standard library. For each scene it writes
DIR/accuracy-vs-time-<scene>.png (default DIR: Documentation/images): frame time (median, ms)
against the terrain's on-screen error (p95 px, missing and extra terrain counted as infinitely
wrong), log axes, one point set per family of settings, VTK's naive globes as their own points,
the Pareto front as a line. Settings that fail (more than 5 % of the samples uncovered, or
wrong-surface pixels in the satellite scene) are drawn on a "fails" row at the top.

The Pareto front (no other configuration is both faster and more accurate) is printed, added to
the JSON under "pareto", and, with --markdown, the report's generated tables are replaced
between the markers <!-- BEGIN GENERATED --> and <!-- END GENERATED -->.

--windows takes runs of `GlobeBenchmark --grid-only --window WxH` in several windows and puts
the automatic grid (the defaults) next to a fixed 512^2 one across them: a markdown table on stdout and
DIR/automatic-grid-<scene>.png (frame time against error, one line per grid policy through
the windows).
"""

import argparse
import json
import math
import os
import sys

FAMILY_ORDER = ["baseline", "grid", "interactive", "grid-window", "depth", "refinement", "precision",
                "composition", "effects"]
# RGB, marker style (vtkPlotPoints: 1 cross, 2 plus, 3 square, 4 circle, 5 diamond)
STYLE = {
    "baseline": ((0, 0, 0), 5),
    "grid": ((31, 119, 180), 4),
    "interactive": ((227, 119, 194), 1),
    "grid-window": ((44, 160, 44), 3),
    "depth": ((214, 39, 40), 4),
    "refinement": ((23, 190, 207), 3),
    "precision": ((148, 103, 189), 2),
    "composition": ((255, 127, 14), 5),
    "effects": ((140, 86, 75), 2),
    "naive sphere": ((127, 127, 127), 3),
    "naive mesh": ((188, 189, 34), 4),
    "fails": ((90, 90, 90), 1),
}


def label(row):
    if row["family"] == "naive":
        return "naive " + row["method"]
    return row["family"]


def error_of(row):
    """The plotted error (p95 px), or None where the configuration fails."""
    ws = row.get("wrong_surface")
    if ws and ws.get("wrong", 0) > 0:
        return None
    return row["terrain"].get("p95_all_px")


# Families whose settings change what the image shows (colour filtering, feathered borders,
# effects) rather than how accurately the same surface is drawn: plotted and tabulated, but not
# candidates for the accuracy/time front. The repeated baseline only measures drift.
NOT_CANDIDATES = ("composition", "effects")


def candidate(row):
    return row["family"] not in NOT_CANDIDATES and "repeated" not in row["setting"]


def pareto(rows):
    """Candidate rows no other candidate beats on both frame time and error."""
    ok = [r for r in rows if candidate(r) and error_of(r) is not None
          and r["frame_ms"]["median"] is not None]
    ok.sort(key=lambda r: (r["frame_ms"]["median"], error_of(r)))
    front, best = [], math.inf
    for r in ok:
        e = error_of(r)
        if e < best:
            front.append(r)
            best = e
    return front


def name(row):
    if row["family"] == "naive":
        return row["setting"]
    if row["family"] == "baseline":
        return "PGM " + row["setting"]
    return "PGM %s: %s" % (row["family"], row["setting"])


def chart_view(title, size=(900, 560)):
    """A white off-screen chart view with a legend; returns (view, chart)."""
    # VTK is imported here so --no-images works without a display.
    from vtkmodules.vtkChartsCore import vtkChartXY
    from vtkmodules.vtkViewsContext2D import vtkContextView
    import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (the chart's OpenGL backend)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

    view = vtkContextView()
    view.GetRenderer().SetBackground(1, 1, 1)
    view.GetRenderWindow().SetSize(*size)
    view.GetRenderWindow().SetOffScreenRendering(1)
    chart = vtkChartXY()
    view.GetScene().AddItem(chart)
    chart.SetShowLegend(True)
    chart.SetTitle(title)
    return view, chart


def points_table(name_x, name_y, points):
    """A two-column vtkTable of (x, y) points, the columns named for the chart's legend."""
    from vtkmodules.vtkCommonCore import vtkFloatArray
    from vtkmodules.vtkCommonDataModel import vtkTable
    table = vtkTable()
    for name in (name_x, name_y):
        column = vtkFloatArray()
        column.SetName(name)
        table.AddColumn(column)
    table.SetNumberOfRows(len(points))
    for i, (x, y) in enumerate(points):
        table.SetValue(i, 0, x)
        table.SetValue(i, 1, y)
    return table


def add_series(chart, title, points, rgb, marker, line=False):
    """(x, y) points as markers (and a line through them with line=True)."""
    from vtkmodules.vtkChartsCore import vtkChart
    table = points_table("frame ms", title, points)
    plot = chart.AddPlot(vtkChart.LINE if line else vtkChart.POINTS)
    plot.SetInputData(table, 0, 1)
    plot.SetColor(rgb[0], rgb[1], rgb[2], 255)
    if line:
        plot.SetWidth(1.5)
    if marker:
        plot.SetMarkerStyle(marker)
        plot.SetMarkerSize(10)


def time_error_axes(chart, time_title):
    """Log axes: frame time along the bottom, terrain error (p95 px) up the left."""
    from vtkmodules.vtkChartsCore import vtkAxis
    bottom = chart.GetAxis(vtkAxis.BOTTOM)
    bottom.SetTitle(time_title)
    bottom.SetLogScale(True)
    left = chart.GetAxis(vtkAxis.LEFT)
    left.SetTitle("terrain error p95 (px)")
    left.SetLogScale(True)
    return bottom, left


def plot_scene(scene, rows, front, path):
    from vtkmodules.vtkChartsCore import vtkAxis

    errors = [error_of(r) for r in rows if error_of(r) is not None]
    positive = [e for e in errors if e > 0]
    floor = min(positive) / 2 if positive else 1e-3
    top = max(positive) if positive else 1.0
    fails_y = top * 4

    groups = {}
    for r in rows:
        key = label(r)
        if error_of(r) is None:
            key = "fails"
        groups.setdefault(key, []).append(r)
    # Families' curves include the baseline (it is their default value).
    baseline = [r for r in rows if r["family"] == "baseline"]

    view, chart = chart_view("%s: terrain error against frame time" % scene["name"])
    # Bottom left: fast and accurate at once is where nothing is.
    chart.GetLegend().SetHorizontalAlignment(chart.GetLegend().LEFT)
    chart.GetLegend().SetVerticalAlignment(chart.GetLegend().BOTTOM)

    for key in FAMILY_ORDER + ["naive sphere", "naive mesh", "fails"]:
        members = groups.get(key)
        if not members:
            continue
        if key not in ("baseline", "fails") and not key.startswith("naive"):
            members = members + baseline
        pts = []
        for r in members:
            e = error_of(r)
            pts.append((r["frame_ms"]["median"], fails_y if e is None else max(e, floor)))
        pts.sort()
        rgb, marker = STYLE.get(key, ((0, 0, 0), 4))
        add_series(chart, key if key != "fails" else "fails (uncovered > 5 % or wrong surface)",
                   pts, rgb, marker)
    if front:
        add_series(chart, "Pareto front",
                   [(r["frame_ms"]["median"], max(error_of(r), floor)) for r in front],
                   (0, 0, 0), 0, line=True)

    bottom, left = time_error_axes(chart, "frame time, median (ms)")
    times = [r["frame_ms"]["median"] for r in rows if r["frame_ms"]["median"]]
    bottom.SetBehavior(vtkAxis.FIXED)
    bottom.SetRange(min(times) / 1.5, max(times) * 1.5)
    left.SetBehavior(vtkAxis.FIXED)
    left.SetRange(floor / 1.5, fails_y * 2)

    save(view, path)


def save(view, path):
    """Writes a chart view's picture to a PNG (plot_streaming.py uses it too)."""
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    view.GetRenderWindow().Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def fmt(v, f="%.2f"):
    return "–" if v is None else f % v


def q(d, key="p95", f="%.2f"):
    return "–" if not d or d.get(key) is None else f % d[key]


def markdown(data, fronts):
    m = data["machine"]
    s = data["settings"]
    out = []
    out.append("Run of %s%s: %s; %s; %s, %s CPU threads; load average %s at the start, %s at the "
               "end; %s. Window %dx%d, %d timed frames per configuration after %d warm-up "
               "(fewer for very slow ones, listed below); total %.0f s." % (
                   data["date"], " (QUICK: smoke run, not for quoting)" if s["quick"] else "",
                   m["gl_renderer"], m["gl_version"], m["cpu"], m["cpu_threads"],
                   m.get("loadavg_start", "?"), m.get("loadavg_end", "?"),
                   data.get("conditions") or "conditions not recorded", s["window"][0],
                   s["window"][1], s["frames"], s["warmup"], data["total_seconds"]))
    out.append("")
    for scene in data["scenes"]:
        rows = [r for r in data["rows"] if r["scene"] == scene["name"]]
        front_ids = {id(r) for r in fronts.get(scene["name"], [])}
        out.append("#### %s — %s" % (scene["name"], scene["description"]))
        out.append("")
        out.append("%d sample pixels (every %d px); clipping: policy [%.3g, %.3g] m, VTK's own "
                   "[%.3g, %.3g] m." % (scene["samples"], scene["sample_stride"],
                                          scene["clipping_policy_m"][0],
                                          scene["clipping_policy_m"][1],
                                          scene["clipping_vtk_m"][0], scene["clipping_vtk_m"][1]))
        out.append("")
        out.append("| family | setting | frame ms (IQR) | raster / composite GPU ms | terrain p95 px "
                   "| terrain p95 m | height p95 m | uncovered | registration p95 px | jitter p95 px "
                   "| wrong surface | GPU MB | Pareto |")
        out.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            t = r["terrain"]
            st = r["stage_ms"]
            stages = "%s / %s" % (fmt(st["raster"], "%.1f"), fmt(st["composite"], "%.1f")) if st else ""
            ws = r["wrong_surface"]
            frames = "%.1f (%.1f)" % (r["frame_ms"]["median"], r["frame_ms"]["iqr"])
            if r["frames_reduced"]:
                frames += " [%d frames]" % r["frames"]
            out.append("| %s | %s | %s | %s | %s | %s | %s | %d | %s | %s | %s | %.1f | %s |" % (
                r["family"], r["setting"], frames, stages,
                q(t["error_px"], f="%.3f"), q(t["error_m"], f="%.1f"),
                q(t["height_error_m"], f="%.1f"), t["missing"] + t["extra"],
                q(r["registration_px"]) if r["registration_px"] else "–",
                q(r["jitter_px"], f="%.3f"),
                "%d / %d" % (ws["wrong"], ws["checked"]) if ws else "",
                r["memory"]["gpu_total"] / 1048576.0, "**yes**" if id(r) in front_ids else ""))
        out.append("")
        out.append("![accuracy against time, %s](images/accuracy-vs-time-%s.png)" % (
            scene["name"], scene["name"]))
        out.append("")
        out.append("Pareto front (%s): %s." % (scene["name"], "; ".join(
            "%s %.1f ms / %s px" % (name(r), r["frame_ms"]["median"], fmt(error_of(r), "%.3g"))
            for r in fronts.get(scene["name"], []))))
        out.append("")
    if data.get("matrix"):
        grids = sorted({r["grid"] for r in data["matrix"]})
        windows = []
        for r in data["matrix"]:
            if r["window"] not in windows:
                windows.append(r["window"])
        out.append("#### Whole Earth, grid × window (Mahsman's Tables 6.2–6.4 layout)")
        out.append("")
        out.append("Median frame ms, and in brackets the PGM stage / the min-reduction (GPU ms). "
                   "Rows: grid; columns: window.")
        out.append("")
        out.append("| grid | " + " | ".join("%d×%d" % tuple(w) for w in windows) + " |")
        out.append("|---|" + "---|" * len(windows))
        for g in grids:
            cells = []
            for w in windows:
                r = next((r for r in data["matrix"] if r["grid"] == g and r["window"] == w), None)
                cells.append("–" if r is None else "%.1f (%s / %s)" % (
                    r["frame_ms"]["median"], fmt(r["stage_ms"]["pgm"]),
                    fmt(r["stage_ms"]["reduction"])))
            out.append("| %d² | %s |" % (g, " | ".join(cells)))
        out.append("")
    if data.get("notes"):
        out.append("Cut short: " + "; ".join(data["notes"]) + ".")
        out.append("")
    for c in data.get("comparisons", []):
        out.append("- " + c["statement"])
    return "\n".join(out) + "\n"


def window_rows(datas):
    """(scene, window, policy) -> row, policy "fixed" (512^2), "automatic" (the baseline: the
    mapper's defaults), "whole viewport" (the defaults with the composition over the whole
    viewport, sky included) or "sphere" (VTK's textured sphere), from runs in different
    windows."""
    table = {}
    for data in datas:
        w, h = data["settings"]["window"]
        for r in data["rows"]:
            policy = ("fixed" if r["family"] == "grid" and r["setting"] == "512^2" else
                      "automatic" if (r["family"] == "baseline" and
                                      not r["setting"].endswith("repeated last")) else
                      "whole viewport" if (r["family"] == "composition" and
                                           r["setting"] == "whole viewport") else
                      "sphere" if r["method"] == "sphere" else None)
            if policy:
                table[(r["scene"], (w, h), policy)] = r
    return table


def windows_markdown(table):
    scenes = sorted({k[0] for k in table})
    windows = sorted({k[1] for k in table}, key=lambda w: w[0] * w[1])
    out = ["| scene | window | grid | frame ms (median [q1–q3]) | terrain p95 px | ms per Mpx |"
           " PGM / textured sphere |", "|---|---|---|---|---|---|---|"]
    for s in scenes:
        for w in windows:
            sphere = table.get((s, w, "sphere"))
            for policy in ("fixed", "automatic", "whole viewport"):
                r = table.get((s, w, policy))
                if not r:
                    continue
                t = r["frame_ms"]
                ratio = ("%.1f×" % (t["median"] / sphere["frame_ms"]["median"])
                         if sphere and sphere["frame_ms"]["median"] else "–")
                out.append("| %s | %d×%d | %s %d² | %.1f [%.1f–%.1f] | %s | %.0f | %s |" % (
                    s, w[0], w[1], {"fixed": "fixed", "automatic": "automatic",
                                    "whole viewport": "automatic, whole viewport"}[policy],
                    r["grid"],
                    t["median"], t["q1"], t["q3"], fmt(error_of(r), "%.3f"),
                    t["median"] / (w[0] * w[1] / 1e6), ratio))
    return "\n".join(out) + "\n"


def plot_windows(scene, table, path):
    from vtkmodules.vtkChartsCore import vtkAxis
    view, chart = chart_view(
        "%s: the automatic grid and a fixed 512^2 grid in three windows" % scene)
    windows = sorted({k[1] for k in table if k[0] == scene}, key=lambda w: w[0] * w[1])
    every = []
    for policy, rgb, marker in (("fixed", (0, 0, 0), 5), ("automatic", (31, 119, 180), 4)):
        pts = [(table[(scene, w, policy)]["frame_ms"]["median"], error_of(table[(scene, w, policy)]))
               for w in windows
               if (scene, w, policy) in table and error_of(table[(scene, w, policy)]) is not None]
        pts = [(t, max(e, 1e-3)) for t, e in pts]
        every += pts
        if pts:
            add_series(chart, "%s grid (%s)" % (policy, ", ".join("%d×%d" % w for w in windows)),
                       pts, rgb, marker, line=True)
    bottom, left = time_error_axes(chart, "frame time, median (ms); windows from small to large")
    if every:
        bottom.SetBehavior(vtkAxis.FIXED)
        bottom.SetRange(min(t for t, _ in every) / 1.3, max(t for t, _ in every) * 1.3)
        left.SetBehavior(vtkAxis.FIXED)
        left.SetRange(min(e for _, e in every) / 1.5, max(e for _, e in every) * 1.5)
    save(view, path)


def windows_main(args):
    datas = []
    for path in args.json:
        with open(path) as f:
            datas.append(json.load(f))
    table = window_rows(datas)
    sys.stdout.write(windows_markdown(table))
    if not args.no_images:
        os.makedirs(args.images, exist_ok=True)
        for scene in sorted({k[0] for k in table}):
            path = os.path.join(args.images, "automatic-grid-%s.png" % scene)
            plot_windows(scene, table, path)
            print("wrote %s" % path)
    return 0


BEGIN = "<!-- BEGIN GENERATED (Utilities/plot_benchmark.py) -->"
END = "<!-- END GENERATED -->"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", nargs="+")
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--images", default=os.path.join(here, "..", "Documentation", "images"))
    parser.add_argument("--markdown", help="replace the generated part of this file")
    parser.add_argument("--no-images", action="store_true")
    parser.add_argument("--windows", action="store_true",
                        help="compare the automatic and fixed grids across --grid-only runs")
    args = parser.parse_args()
    if args.windows:
        return windows_main(args)
    if len(args.json) != 1:
        parser.error("one JSON file (several only with --windows)")
    args.json = args.json[0]

    with open(args.json) as f:
        data = json.load(f)
    fronts = {}
    for scene in data["scenes"]:
        rows = [r for r in data["rows"] if r["scene"] == scene["name"]]
        fronts[scene["name"]] = pareto(rows)
        print("Pareto front, %s (frame ms / terrain p95 px):" % scene["name"])
        for r in fronts[scene["name"]]:
            print("  %-50s %9.2f ms  %9.4f px" % (name(r), r["frame_ms"]["median"], error_of(r)))
        if not args.no_images:
            os.makedirs(args.images, exist_ok=True)
            path = os.path.join(args.images, "accuracy-vs-time-%s.png" % scene["name"])
            plot_scene(scene, rows, fronts[scene["name"]], path)
            print("  wrote %s" % path)

    data["pareto"] = {
        s: [{"family": r["family"], "setting": r["setting"], "method": r["method"],
             "frame_ms": r["frame_ms"]["median"], "error": error_of(r)} for r in rows]
        for s, rows in fronts.items()
    }
    with open(args.json, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")

    text = markdown(data, fronts)
    if args.markdown:
        with open(args.markdown) as f:
            doc = f.read()
        if BEGIN not in doc or END not in doc:
            sys.exit("%s has no %s ... %s markers" % (args.markdown, BEGIN, END))
        head, rest = doc.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        with open(args.markdown, "w") as f:
            f.write(head + BEGIN + "\n" + text + END + tail)
        print("updated %s" % args.markdown)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
