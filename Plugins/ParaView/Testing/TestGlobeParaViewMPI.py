"""The Globe Raster Reader under MPI: 2 ranks of pvbatch --symmetric (mpirun), each running this
script.

- There are 2 ranks (run without mpirun, the test fails).
- Each rank reads its own piece of relief_2deg.tif (the reader announces
  CAN_PRODUCE_SUB_EXTENT, so the executive splits the raster by extent): no piece is empty, each
  lies inside the whole extent and holds, at every point, the value ParaView's GDAL reader
  (vtkGDALRasterReader, read on that rank) has there.
- The ranks' pieces together cover the whole raster.
- ParaView's data information on each rank describes that rank's piece (pvbatch --symmetric
  gathers nothing: each process is its own client); reduced over the ranks (MPI), the extents
  and value ranges give TestGlobeParaViewReader's one-process numbers: extent 0..179 x 0..89,
  range -6526.54 .. 5211.51, and the points add up to 16,200 plus the boundary column the two
  pieces share.
- The globe under IceT: the scene of TestGlobeParaViewRepresentation (globe_scene.py) rendered
  by both ranks, whose yellow sphere and wavelet slice are distributed (each rank holds a part,
  the parts add up), equals that test's 1-rank picture (globe-1rank.png) within VTK's
  regression threshold, and matches the same baseline: IceT's depth compositing puts the other
  ranks' geometry in front of and behind the globe as one process does.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi4py import MPI  # noqa: E402
from paraview.simple import LoadPlugin, SaveScreenshot  # noqa: E402
import globe_scene  # noqa: E402
from vtkmodules.vtkIOGDAL import vtkGDALRasterReader

from globe_scene import PLUGIN, DATA, failures  # noqa: E402

comm = MPI.COMM_WORLD


def expect(condition, what):
    globe_scene.expect(condition, what, "rank %d: " % comm.rank)


expect(comm.size == 2, "%d MPI ranks" % comm.size)
LoadPlugin(PLUGIN, remote=False, ns=globals())
relief_file = os.path.join(DATA, "earth", "relief_2deg.tif")
relief = GlobeRasterReader(FileName=relief_file)  # noqa: F821 (defined by LoadPlugin)
relief.UpdatePipeline()

# This rank's piece, against GDAL's reading of the same file (cell (i, j) = our point (i, j)).
piece = relief.GetClientSideObject().GetOutput()
extent = piece.GetExtent()
gdal = vtkGDALRasterReader()
gdal.SetFileName(relief_file)
gdal.Update()
ref = gdal.GetOutput().GetCellData().GetArray("Elevation")
values = piece.GetPointData().GetScalars()
inside = extent[0] >= 0 and extent[1] <= 179 and extent[2] >= 0 and extent[3] <= 89
differ, compared = 0, 0
if piece.GetNumberOfPoints() > 0 and values is not None:
    width = extent[1] - extent[0] + 1
    for j in range(extent[2], extent[3] + 1):
        for i in range(extent[0], extent[1] + 1):
            compared += 1
            ours = values.GetValue((j - extent[2]) * width + (i - extent[0]))
            differ += ours != ref.GetValue(j * 180 + i)
expect(piece.GetNumberOfPoints() > 0 and inside and compared == piece.GetNumberOfPoints()
       and differ == 0,
       "piece extent %s, %d points, %d compared with GDAL's, %d differ"
       % (extent, piece.GetNumberOfPoints(), compared, differ))
points = comm.allreduce(piece.GetNumberOfPoints())

# Together the pieces cover the raster.
extents = comm.allgather(extent if piece.GetNumberOfPoints() > 0 else None)
covered = set()
for e in extents:
    if e is not None:
        covered.update((i, j) for i in range(e[0], e[1] + 1) for j in range(e[2], e[3] + 1))
expect(len(covered) == 16200 and all(0 <= i < 180 and 0 <= j < 90 for i, j in covered),
       "the pieces %s cover %d of the 16,200 points" % (extents, len(covered)))

# ParaView's data information: this rank's piece; reduced over the ranks, the whole raster.
info = relief.GetDataInformation()
array = relief.PointData["Values"]
local_range = array.GetRange() if array is not None else (float("inf"), float("-inf"))
expect(tuple(info.GetExtent()) == tuple(extent) and info.GetNumberOfPoints() == piece.GetNumberOfPoints(),
       "data information: this rank's piece, extent %s, %d points"
       % (tuple(info.GetExtent()), info.GetNumberOfPoints()))
lo = comm.allreduce(local_range[0], op=MPI.MIN)
hi = comm.allreduce(local_range[1], op=MPI.MAX)
union = [comm.allreduce(extent[k], op=MPI.MIN if k % 2 == 0 else MPI.MAX) for k in range(6)]
shared = 90 if comm.size == 2 else 0  # one boundary column of 90 points between the 2 pieces
expect(tuple(union) == (0, 179, 0, 89, 0, 0) and points == 16200 + shared and
       abs(lo + 6526.538) < 1e-3 and abs(hi - 5211.506) < 1e-3,
       "reduced over the ranks: extent %s, %d points (16,200 and the shared column), range "
       "(%.3f, %.3f)" % (tuple(union), points, lo, hi))

# The globe scene on 2 ranks, composited by IceT.
scene = globe_scene.build(globals(), DATA)
for name in ("limb", "slice"):
    local = scene[name].GetDataInformation().GetNumberOfPoints()
    points = comm.allgather(local)
    expect(comm.size == 2 and all(0 < p < sum(points) for p in points),
           "the %s is distributed: %s points on the ranks" % (name, points))
OUTPUT = os.environ["VTKGLOBE_PARAVIEW_OUTPUT"]
two = os.path.join(OUTPUT, "globe-2rank.png")
SaveScreenshot(two, scene["view"], ImageResolution=globe_scene.SIZE)  # rank 0 writes it
comm.Barrier()
if comm.rank == 0:
    one = os.path.join(OUTPUT, "globe-1rank.png")
    to_one = globe_scene.image_error(two, one) if os.path.exists(one) else float("inf")
    to_baseline = globe_scene.image_error(two, globe_scene.BASELINE)
    threshold = globe_scene.THRESHOLD
    expect(to_one <= threshold and to_baseline <= threshold,
           "the 2-rank picture against the 1-rank one: error %.4f; against the baseline: %.4f "
           "(threshold %.2f)" % (to_one, to_baseline, threshold))
globe_scene.close(scene["view"])

total = comm.allreduce(len(failures))
print("rank %d: %d failure(s) on all ranks" % (comm.rank, total))
# Not sys.exit: pvbatch must reach MPI_Finalize, or mpiexec reports an abnormal end. An
# exception ends the script with pvbatch's exit code 1 on every rank.
if total:
    raise AssertionError("%d failure(s)" % total)
