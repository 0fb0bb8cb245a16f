#!/usr/bin/env bash
# How the seed corpus of Testing/Fuzz/corpus/ was made (run once; the files are committed):
# small crops and reductions of Data/'s rasters in the layouts readers meet (strips, tiles,
# DEFLATE, LZW, JPEG, BigTIFF, overviews, int16 with nodata, float64, projected, the Moon),
# the crafted bad files TestGlobeRasterReaderHardening and TestGlobeRasterReader write (the
# small ones: up to 4 KiB), and for the world-file target the same images split into
# image + world file + .prj (FuzzWorldFile.cxx describes the layout).
#
#   bash Testing/Fuzz/make_corpus.sh BUILD_DIR
#
# Needs GDAL's command-line tools (Debian: gdal-bin; a tool for making the seeds only, not a
# dependency of the project), and BUILD_DIR's Core tests run once (their Temporary/ files).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:?usage: make_corpus.sh BUILD_DIR}"
temp="$build/Testing/Cxx/Temporary"
corpus="$root/Testing/Fuzz/corpus"
data="$root/Data"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

t() { gdal_translate -q "$@"; }
mkdir -p "$work/seeds"
s="$work/seeds"
t -outsize 32 16 "$data/earth/relief_2deg.tif" "$s/relief_32x16.tif"
t -outsize 32 16 -ot Float64 "$data/earth/relief_2deg.tif" "$s/relief_float64.tif"
t -outsize 48 24 -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co COMPRESS=DEFLATE \
  -co PREDICTOR=3 "$data/earth/relief_2deg.tif" "$s/relief_tiled_deflate.tif"
t -outsize 64 32 -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co COMPRESS=DEFLATE \
  "$data/earth/relief_2deg.tif" "$s/relief_overviews.tif"
gdaladdo -q --config COMPRESS_OVERVIEW DEFLATE --config GDAL_TIFF_OVR_BLOCKSIZE 64 -r average \
  "$s/relief_overviews.tif" 2 4
t -outsize 32 16 -co BIGTIFF=YES "$data/earth/relief_2deg.tif" "$s/relief_bigtiff.tif"
t -srcwin 590 590 24 24 -co COMPRESS=LZW "$data/earth/mt_everest_90m.tif" "$s/everest_int16_lzw.tif"
t -srcwin 0 0 20 20 "$data/earth/mt_rainier_utm10n.tif" "$s/rainier_utm_nodata.tif"
t -outsize 32 16 -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co COMPRESS=JPEG \
  "$data/earth/world.tif" "$s/world_jpeg.tif"
t -outsize 24 24 -co COMPRESS=DEFLATE "$data/earth/world_north_polar_3413.tif" "$s/polar_3413.tif"
t -outsize 32 16 "$data/moon/moon_1024x512.tif" "$s/moon.tif"
t -srcwin 200 150 16 12 -co INTERLEAVE=BAND "$data/earth/boston-inset-wgs84.tif" "$s/boston_band.tif"
t -srcwin 200 150 16 12 -b 1 -b 2 -b 3 -b 1 -co ALPHA=YES "$data/earth/nyc-inset-wgs84.tif" "$s/nyc_rgba.tif"
t -outsize 32 16 -ot UInt16 -scale -11000 9000 0 65535 "$data/earth/relief_2deg.tif" "$s/relief_uint16.tif"
# A file cut short: its strips point past the end.
head -c 1500 "$s/relief_32x16.tif" > "$s/relief_cut.tif"
for f in "$temp"/*.tif "$temp"/*.png; do
  if [ "$(stat -c %s "$f")" -le 4096 ]; then
    cp "$f" "$s/test_$(basename "$f")"
  fi
done
for target in RasterReader Layer PageSource; do
  rm -rf "$corpus/$target"
  mkdir -p "$corpus/$target"
  cp "$s"/* "$corpus/$target/"
done

# World-file seeds: flags, the two lengths, world file, .prj, image.
w="$corpus/WorldFile"
rm -rf "$w"
mkdir -p "$w"
wgs84='GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",SPHEROID["WGS_1984",6378137.0,298.257223563]],PRIMEM["Greenwich",0.0],UNIT["Degree",0.0174532925199433]]'
utm10="$(gdalsrsinfo -o wkt_esri EPSG:32610 | tr -d '\n')"
compose() { # OUT FLAGS WORLD PRJ IMAGE
  python3 - "$@" <<'PY'
import struct, sys
out, flags, world, prj, image = sys.argv[1:]
world = world.encode(); prj = prj.encode()
with open(image, 'rb') as f:
    pixels = f.read()
with open(out, 'wb') as f:
    f.write(struct.pack('<BHH', int(flags), len(world), len(prj)) + world + prj + pixels)
PY
}
t -of PNG -outsize 32 16 -co WORLDFILE=NO "$data/earth/world.tif" "$work/world.png"
t -outsize 32 16 -co PROFILE=BASELINE "$data/earth/relief_2deg.tif" "$work/relief_plain.tif"
t -of PNG -srcwin 0 0 16 16 -ot Byte -scale "$data/earth/mt_rainier_utm10n.tif" "$work/rainier.png"
deg='11.25\n0\n0\n-11.25\n-174.375\n84.375\n'
compose "$w/png_degrees_prj" 1 "$(printf "$deg")" "$wgs84" "$work/world.png"
compose "$w/png_degrees_noprj" 5 "$(printf "$deg")" "" "$work/world.png"
compose "$w/png_degrees_epsg_wld" 15 "$(printf "$deg")" "" "$work/world.png"
compose "$w/tif_degrees_prj" 0 "$(printf "$deg")" "$wgs84" "$work/relief_plain.tif"
compose "$w/png_utm_prj" 1 "$(printf '30\n0\n0\n-30\n560015\n5190015\n')" "$utm10" "$work/rainier.png"
compose "$w/png_utm_contradicts_epsg" 3 "$(printf '30\n0\n0\n-30\n560015\n5190015\n')" "$utm10" "$work/rainier.png"
compose "$w/png_rotated" 5 "$(printf '1\n0.5\n0.5\n-1\n0\n0\n')" "" "$work/world.png"
compose "$w/png_short_world" 5 "$(printf '1\n0\n0\n')" "" "$work/world.png"
compose "$w/tif_south_up" 4 "$(printf '11.25\n0\n0\n11.25\n-174.375\n-84.375\n')" "" "$work/relief_plain.tif"
for f in "$temp"/reader_*.png; do
  base="${f%.png}"
  world=""; prj=""; flags=1
  [ -f "$base.pgw" ] && world="$(cat "$base.pgw")"
  if [ -f "$base.prj" ]; then prj="$(cat "$base.prj")"; else flags=5; fi
  compose "$w/test_$(basename "$base")" "$flags" "$world" "$prj" "$f"
done
du -sh "$corpus"/*
