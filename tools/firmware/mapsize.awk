# mapsize.awk - bytes an object brings into a linked image, from a GNU ld
# map (-Wl,-Map): the sum of its input sections kept in the image (those
# listed after "Linker script and memory map", not the discarded ones),
# split into code (.text*) and read-only data (.rodata*).
#   awk -v obj=rastrum.o -f mapsize.awk app.map   -> "TEXT RODATA"
/^Linker script and memory map/ { inmap = 1; next }
!inmap { next }
# an input section: " .text.name  0xADDR  0xSIZE  file", or the name alone
# on its line and the rest on the next
/^ \.[A-Za-z_]/ {
    if (NF >= 4) { sec = $1; size = $3; file = $4 } else { pending = $1; next }
    add(sec, size, file); next
}
pending != "" && /^ +0x[0-9a-f]+ +0x[0-9a-f]+ / {
    add(pending, $2, $3); pending = ""; next
}
{ pending = "" }
function add(sec, size, file,    n) {
    n = length(obj)
    if (substr(file, length(file) - n + 1) != obj) return
    if (sec ~ /^\.text/) text += hex(size)
    else if (sec ~ /^\.rodata/) ro += hex(size)
}
function hex(s,    v, i) {
    v = 0; s = tolower(substr(s, 3))
    for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
    return v
}
END { printf "%d %d\n", text, ro }
