"""Smoke test of the benchmark and its plots (never a timed test): runs
`GlobeBenchmark --quick --no-matrix` and Utilities/plot_benchmark.py into a temporary folder and
checks that the JSON parses with every scene, family and measurement present, that each scene has
a Pareto front, and that each plot was written. It asserts nothing about times or errors.

    smoke_benchmark.py GLOBE_BENCHMARK PLOT_SCRIPT WORK_DIR
"""
import json
import os
import subprocess
import sys


def main():
    benchmark, plot, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "benchmark-smoke.json")
    images = os.path.join(work, "benchmark-smoke-images")
    # From scratch: nothing of an earlier run can pass for this one.
    old = [path] + ([os.path.join(images, n) for n in os.listdir(images)] if os.path.isdir(images) else [])
    for f in old:
        if os.path.exists(f):
            os.remove(f)
    subprocess.run([benchmark, "--quick", "--no-matrix", "--json", path], check=True)
    subprocess.run([sys.executable, plot, path, "--images", images], check=True,
                   stdout=subprocess.DEVNULL)
    with open(path) as f:
        data = json.load(f)
    problems = []
    scenes = [s["name"] for s in data["scenes"]]
    if scenes != ["earth", "rainier", "everest", "satellite"]:
        problems.append("scenes %s" % scenes)
    for scene in scenes:
        rows = [r for r in data["rows"] if r["scene"] == scene]
        families = {r["family"] for r in rows}
        for family in ("baseline", "grid", "grid-window", "depth", "composition", "effects", "naive"):
            if family not in families:
                problems.append("%s: no %s rows" % (scene, family))
        for r in rows:
            if not (r["frame_ms"]["median"] and r["frame_ms"]["median"] > 0):
                problems.append("%s %s: no frame time" % (scene, r["setting"]))
            if r["terrain"]["samples"] <= 0 or r["jitter_px"] is None:
                problems.append("%s %s: no terrain or jitter samples" % (scene, r["setting"]))
            if r["method"] == "pgm" and r["memory"]["gpu_layers"] is None:
                problems.append("%s %s: no memory" % (scene, r["setting"]))
        if not any(r["registration_px"] for r in rows):
            problems.append("%s: no registration measured" % scene)
        if scene == "satellite" and not all(r["wrong_surface"] for r in rows):
            problems.append("satellite: wrong-surface count missing")
        if not data.get("pareto", {}).get(scene):
            problems.append("%s: no Pareto front" % scene)
        png = os.path.join(images, "accuracy-vs-time-%s.png" % scene)
        if not os.path.exists(png) or os.path.getsize(png) < 1000:
            problems.append("%s: no plot" % png)
    for p in problems:
        print("FAILED:", p)
    print("benchmark smoke run: %d rows, %d problems" % (len(data["rows"]), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
