#!/bin/sh
# run.sh - the display example on an emulated Cortex-M (make display-qemu).
#
# Builds examples/display_rgb565.c with the whole core (the single-file
# build, build/single/rastrum.c) for Cortex-M0 (Thumb, -Os), links it for
# QEMU's mps2-an385 board with newlib's semihosting stdio, runs it under
# qemu-system-arm, and checks that its frame hash equals the one the same
# example prints on this machine.  Prints the image's sizes and the RAM it
# used (static and stack high-water).  Then the same for the firmware
# examples, each under its own configuration header.
#
#   tools/qemu-m/run.sh OUTDIR
set -eu
out=${1:-build/qemu-m}
mkdir -p "$out"
for tool in arm-none-eabi-gcc qemu-system-arm; do
  command -v "$tool" >/dev/null 2>&1 || { echo "display-qemu: $tool not installed"; exit 1; }
done
cflags="-std=c99 -pedantic -Wall -Wextra -Werror -Os -mcpu=cortex-m0 -mthumb -ffunction-sections -fdata-sections"
# The startup code is the platform's (a vector table needs the stack's
# address as a function pointer): GNU C, not ISO.
arm-none-eabi-gcc $(echo "$cflags" | sed 's/-std=c99 -pedantic/-std=gnu99/') -c tools/qemu-m/startup.c \
  -o "$out/startup.o"
arm-none-eabi-gcc $cflags -DDISPLAY_NO_FILES -Ibuild/single examples/display_rgb565.c build/single/rastrum.c \
  "$out/startup.o" -T tools/qemu-m/mps2.ld -nostartfiles --specs=rdimon.specs \
  -Wl,--gc-sections -Wl,-Map,"$out/display_rgb565.map" -o "$out/display_rgb565.elf"
arm-none-eabi-size "$out/display_rgb565.elf" | sed 's/^/  /'
timeout 120 qemu-system-arm -M mps2-an385 -nographic -monitor none -serial none \
  -semihosting-config enable=on,target=native -kernel "$out/display_rgb565.elf" > "$out/qemu.log" 2>&1 || {
  cat "$out/qemu.log"; echo "display-qemu: the program failed under qemu"; exit 1; }
sed 's/^/  /' "$out/qemu.log"
./build/display_rgb565 "$out/pc.ppm" > "$out/pc.log"
m=$(sed -n 's/^frame hash: //p' "$out/qemu.log")
p=$(sed -n 's/^frame hash: //p' "$out/pc.log")
if [ -n "$m" ] && [ "$m" = "$p" ]; then
  echo "display-qemu: frame hash $m on cortex-m (qemu mps2-an385) = $p on this machine: 1 passed, 0 failed"
else
  echo "display-qemu: frame hash '$m' on cortex-m != '$p' on this machine"; exit 1
fi

# The firmware examples (examples/firmware_*.c), each with the library cut
# by its own configuration header, on the same board: the picture hash
# each prints must equal the one the same program prints on this machine.
for app in firmware_min firmware_tri firmware_lines firmware_gauge; do
  def="-DFIRMWARE_PRINT -DRAST_CONFIG_HEADER=\"${app}_conf.h\""
  # shellcheck disable=SC2086
  arm-none-eabi-gcc $cflags $def -Iexamples -Ibuild/single "examples/$app.c" build/single/rastrum.c \
    "$out/startup.o" -T tools/qemu-m/mps2.ld -nostartfiles --specs=rdimon.specs \
    -Wl,--gc-sections -o "$out/$app.elf"
  # shellcheck disable=SC2086
  ${CC:-cc} -std=c99 -O2 $def -Iexamples -Ibuild/single "examples/$app.c" build/single/rastrum.c \
    -o "$out/$app-pc"
  timeout 60 qemu-system-arm -M mps2-an385 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -kernel "$out/$app.elf" > "$out/$app.log" 2>&1 || {
    cat "$out/$app.log"; echo "display-qemu: $app failed under qemu"; exit 1; }
  m=$(sed -n 's/^ok, picture hash //p' "$out/$app.log")
  p=$("$out/$app-pc" | sed -n 's/^ok, picture hash //p')
  if [ -n "$m" ] && [ "$m" = "$p" ]; then
    echo "display-qemu: $app picture hash $m on cortex-m = $p on this machine: 1 passed, 0 failed"
  else
    echo "display-qemu: $app picture hash '$m' on cortex-m != '$p' on this machine"; exit 1
  fi
done
