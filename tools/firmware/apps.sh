#!/bin/sh
# apps.sh - what typical firmware links of rastrum (make firmware-check).
#
# Links each example application for Cortex-M0 (Thumb, -Os,
# -ffunction-sections -fdata-sections -Wl,--gc-sections) with the one-file
# library (build/single/rastrum.c) compiled under the application's own
# configuration header (examples/NAME_conf.h, or none), and prints the
# bytes of rastrum's code in the linked image: the sizes of the .text*
# input sections of rastrum.o that the linker kept, read from the link map
# (tools/firmware/mapsize.awk), with rastrum's read-only data (tables,
# strings) beside them.  The firmware_* apps link with a bare vector table
# and reset (entry.c, -nostartfiles); the display example, which prints,
# with QEMU's semihosting startup (tools/qemu-m).  Fails if firmware_min
# needs more than 4096 bytes of rastrum's code.
#
#   tools/firmware/apps.sh OUTDIR
set -eu
out=${1:-build/fw/apps}
cc=arm-none-eabi-gcc
command -v "$cc" >/dev/null 2>&1 || { echo "firmware apps: $cc not installed"; exit 1; }
rm -rf "$out"; mkdir -p "$out"
cpu="-mcpu=cortex-m0 -mthumb"
cflags="-std=c99 -pedantic -Wall -Wextra -Werror -Os $cpu -ffunction-sections -fdata-sections"
gnu=$(echo "$cflags" | sed 's/-std=c99 -pedantic/-std=gnu99/')
ld="$cpu -T tools/qemu-m/mps2.ld -nostartfiles -Wl,--gc-sections"
$cc $gnu -c tools/firmware/entry.c -o "$out/entry.o"
$cc $gnu -c tools/qemu-m/startup.c -o "$out/startup.o"
status=0

# link NAME CONF SRC STARTUP SPECS: build NAME from SRC with rastrum under
# CONF (a header in examples/, or "-" for none); print its line.
link() {
  name=$1 conf=$2 src=$3 start=$4 specs=$5
  d="$out/$name"; mkdir -p "$d"
  def=""
  [ "$conf" = - ] || def="-DRAST_CONFIG_HEADER=\"$conf\""
  # shellcheck disable=SC2086
  $cc $cflags $def -Iexamples -I"$out" -Ibuild/single -c build/single/rastrum.c -o "$d/rastrum.o"
  # shellcheck disable=SC2086
  $cc $cflags -DDISPLAY_NO_FILES -Iexamples -Ibuild/single -c "$src" -o "$d/app.o"
  # shellcheck disable=SC2086
  $cc $ld $specs -Wl,-Map,"$d/$name.map" "$d/app.o" "$d/rastrum.o" "$out/$start" -o "$d/$name.elf"
  set -- $(awk -v obj=rastrum.o -f tools/firmware/mapsize.awk "$d/$name.map")
  text=$1 ro=$2
  printf '%s cortex-m0: %d B\n' "$name" "$text"
  printf '  (rastrum .text in the linked image; + %d B of its read-only data; config %s)\n' \
    "$ro" "$conf"
}

link firmware_min firmware_min_conf.h examples/firmware_min.c entry.o "--specs=nano.specs --specs=nosys.specs"
min=$text
link firmware_tri firmware_tri_conf.h examples/firmware_tri.c entry.o "--specs=nano.specs --specs=nosys.specs"
link firmware_lines firmware_lines_conf.h examples/firmware_lines.c entry.o "--specs=nano.specs --specs=nosys.specs"
link firmware_gauge firmware_gauge_conf.h examples/firmware_gauge.c entry.o "--specs=nano.specs --specs=nosys.specs"
link display_rgb565 display_rgb565_conf.h examples/display_rgb565.c startup.o "--specs=rdimon.specs"
link display_rgb565_full - examples/display_rgb565.c startup.o "--specs=rdimon.specs"

# Every public function referenced (an application calling the whole
# API): the core as linked, with every feature, and with the features the
# core had before anti-aliasing (no coverage, no anti-aliased shading:
# those calls not referenced, RAST_CONFIG_AA_METHODS 0).
api() {
  sed -n 's/^RAST_API .*[ *]\(rast_[a-z0-9_]*\)(.*/\1/p' csrc/include/rastrum.h | grep -Ev "$1" |
    awk 'BEGIN { print "#define RAST_STATIC_LINKING_ONLY"; print "#include \"rastrum.h\""
                 print "typedef void (*fn)(void);"
                 print "volatile fn keep[] = {" }
         { printf "    (fn)%s,\n", $1 }
         END { print "};"; print "int main(void) { return keep[0] != 0; }" }'
}
api '^$' > "$out/all_api.c"
api 'coverage|_aa|aa_method' > "$out/pre_aa_api.c"
printf '#define RAST_CONFIG_AA_METHODS 0u\n' > "$out/pre_aa_conf.h"
link whole_api - "$out/all_api.c" entry.o "--specs=nano.specs --specs=nosys.specs"
link whole_api_pre_aa pre_aa_conf.h "$out/pre_aa_api.c" entry.o "--specs=nano.specs --specs=nosys.specs"

# Like for like with the core as it was before anti-aliasing, 64-bit
# vertices, COCO and polygon batches (git c261dda, whose whole core linked
# 49,794 B this way): its 31 public calls, today's library with the newer
# features left out by configuration.
old_api='rast_algorithm_info rast_boundary_fill rast_draw_line rast_draw_polyline
rast_draw_polyline_spans rast_fill_bounds rast_fill_polygon rast_fill_polygon_gouraud
rast_fill_polygon_opaque rast_fill_polygon_spans rast_fill_rect_gouraud rast_fill_triangles
rast_fill_triangles_shaded rast_fill_triangles_spans rast_flood_fill rast_format_bytes
rast_format_stride rast_line_pixels rast_pack_color rast_point_in_triangle
rast_polygon_gouraud_scratch_size rast_render_bands rast_render_bands_spans
rast_scene_scratch_size rast_scratch_size rast_seed_stack_size rast_status_str
rast_target_init rast_tri_algorithm_info rast_tri_scratch_size rast_version_number'
printf '%s\n' $old_api | awk 'BEGIN { print "#include \"rastrum.h\""; print "typedef void (*fn)(void);"
                                      print "volatile fn keep[] = {" }
                                { printf "    (fn)%s,\n", $1 }
                                END { print "};"; print "int main(void) { return keep[0] != 0; }" }' > "$out/api_0_1.c"
printf '#define RAST_CONFIG_AA_METHODS 0u\n#define RAST_CONFIG_POLYGON64 0\n' > "$out/api_0_1_conf.h"
link api_0_1 api_0_1_conf.h "$out/api_0_1.c" entry.o "--specs=nano.specs --specs=nosys.specs"

if [ "$min" -gt 4096 ]; then
  echo "firmware apps: firmware_min needs $min B of rastrum code, more than 4096"; status=1
fi
exit "$status"
