#!/bin/sh
# Writes data/dem/island_utm32n.tif, the DEM of config/dem_island.ini, from the default island
# heightmap with gdal_translate (gdal-bin): nothing can be downloaded here, so the example "real"
# terrain is the island georeferenced in UTM zone 32N (EPSG:32632) near 47 N 10.3 E, at 8 m texels
# (1025^2, averaged from the 2049^2 heightmap) over the same 8200 m as the default scene.
# Heights are int16 centimetres around 228 m (band scale 0.01, offset 228), so the file also
# exercises a band's scale and offset: heightmap 0..1 -> -72..528 m, as config/default.ini maps it.
# Usage: tools/make_dem_example.sh [OUT.tif]   (run from the checkout's root)
set -eu
out=${1:-data/dem/island_utm32n.tif}
tmp="$out.tmp.$$.tif"
trap 'rm -f "$tmp"' EXIT
gdal_translate -q -of GTiff -ot Int16 -outsize 1025 1025 -r average \
  -a_srs EPSG:32632 -a_ullr 595900 5204100 604100 5195900 \
  -scale 0 65535 -30000 30000 -a_scale 0.01 -a_offset 228 \
  -co COMPRESS=DEFLATE -co PREDICTOR=2 -co ZLEVEL=9 \
  data/heightmaps/island.png "$tmp"
mv "$tmp" "$out"
echo "wrote $out"
