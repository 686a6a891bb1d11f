/*
 * fuzz_seedfill.c - rast_flood_fill and rast_boundary_fill (and
 * rast_seed_stack_size) in every format, on images of 1 to 4 values, with
 * clips, seeds in and out of the target and the clip, both
 * connectivities, and stacks from none to enough (tiny ones force the
 * fixed-memory fallback).
 *
 * Oracle: errors exactly for bad input (a seed outside the target or a
 * connectivity not 4 or 8: RAST_E_ARG; a misaligned stack: RAST_E_ALIGN;
 * a NULL stack of non-zero size: RAST_E_NULL), with nothing written;
 * otherwise every byte of the target and its guards equals a breadth-first
 * search written here from the header's definitions (the region of the
 * seed, confined to the clip, painted with the value), and nothing after
 * the stack changes.  Any stack size gives the same bytes.
 */
#include "fuzz.h"

#define SF_MAXDIM 32

static fz_target ft;
static unsigned char expect[sizeof ft.mem], mixed[sizeof ft.mem];
static fz_scratch stack;
static int32_t queue[SF_MAXDIM * SF_MAXDIM];
static unsigned char seen[SF_MAXDIM * SF_MAXDIM];

static unsigned char *row(fz_target *t, unsigned char *mem, int32_t y)
{
    return mem + ((const unsigned char *)t->t.pixels - t->mem) + (ptrdiff_t)y * t->stride;
}

/* A pixel as an integer, the header's comparison: whole bytes, MONO1 its bit. */
static uint32_t get(fz_target *t, unsigned char *mem, int32_t x, int32_t y)
{
    const unsigned char *p = row(t, mem, y);
    uint32_t v = 0;
    int32_t k;
    if (t->t.format == RAST_FORMAT_MONO1) return (uint32_t)(p[x / 8] >> (7 - x % 8)) & 1u;
    for (k = 0; k < t->bpp; k++) v = v << 8 | p[(ptrdiff_t)x * t->bpp + k];
    return v;
}

static void put(fz_target *t, unsigned char *mem, int32_t x, int32_t y, const unsigned char *value)
{
    unsigned char *p = row(t, mem, y);
    if (t->t.format == RAST_FORMAT_MONO1) {
        unsigned char bit = (unsigned char)(0x80u >> (x % 8));
        p[x / 8] = (unsigned char)(value[0] ? (p[x / 8] | bit) : (p[x / 8] & ~bit));
        return;
    }
    memcpy(p + (ptrdiff_t)x * t->bpp, value, (size_t)t->bpp);
}

/* The value bytes as get() reads a pixel holding them. */
static uint32_t as_pixel(const fz_target *t, const unsigned char *value)
{
    uint32_t v = 0;
    int32_t k;
    if (t->t.format == RAST_FORMAT_MONO1) return value[0] != 0;
    for (k = 0; k < t->bpp; k++) v = v << 8 | value[k];
    return v;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    unsigned char palette[4][4], value[4], edge[4];
    int32_t w, h, x, y, sx, sy, conn, npal, boundary, k, stack_mode, misalign, null_stack, bad;
    rast_format f;
    rast_rect clip;
    size_t need = 0, bytes;
    rast_status st;
    void *mem;
    int32_t limited;
    uint64_t limit, work = 0, region = 0, changed = 0;

    w = 1 + fz_below(&in, SF_MAXDIM);
    h = 1 + fz_below(&in, SF_MAXDIM);
    f = (rast_format)fz_below(&in, RAST_FORMAT_COUNT_);
    clip = fz_clip(&in, w, h);
    boundary = fz_below(&in, 2);
    conn = fz_u8(&in) < 250 ? (fz_below(&in, 2) ? 8 : 4) : fz_below(&in, 10);
    sx = fz_u8(&in) < 240 ? fz_below(&in, w) : fz_below(&in, w + 8) - 4;
    sy = fz_u8(&in) < 240 ? fz_below(&in, h) : fz_below(&in, h + 8) - 4;
    npal = 1 + fz_below(&in, 4);
    for (k = 0; k < 4; k++) {
        int32_t b;
        for (b = 0; b < 4; b++) palette[k][b] = (unsigned char)fz_u8(&in);
    }
    /* the fill value and the boundary: mostly palette colours */
    {
        uint32_t m = fz_u8(&in);
        if (m < 200) memcpy(value, palette[m % 4], 4);
        else
            for (k = 0; k < 4; k++) value[k] = (unsigned char)fz_u8(&in);
        m = fz_u8(&in);
        if (m < 200) memcpy(edge, palette[m % 4], 4);
        else
            for (k = 0; k < 4; k++) edge[k] = (unsigned char)fz_u8(&in);
    }
    stack_mode = fz_below(&in, 4);
    misalign = fz_u8(&in) == 1;
    null_stack = fz_u8(&in) == 1;

    fz_target_init(&ft, w, h, f, &clip);
    for (y = 0; y < h; y++) {
        uint32_t bits = 0;
        for (x = 0; x < w; x++) {
            if (x % 4 == 0) bits = fz_u8(&in);
            put(&ft, ft.mem, x, y, palette[(bits >> (2 * (x % 4))) % (uint32_t)npal]);
        }
    }
    memcpy(ft.before, ft.mem, sizeof ft.mem);

    FZ_ASSERT(rast_seed_stack_size(ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &need) == RAST_OK);
    if (need > FZ_SCRATCH_MAX - 64) need = FZ_SCRATCH_MAX - 64;
    bytes = stack_mode == 0 ? need : stack_mode == 1 ? 0 : stack_mode == 2 ? 16u * (size_t)fz_below(&in, 4)
                                                                            : (size_t)fz_below(&in, 200);
    mem = fz_scratch_init(&stack, bytes + 8);
    if (misalign && bytes) mem = (unsigned char *)mem + 4;
    if (null_stack && bytes) mem = NULL;
    /* rast_seed_fill_limited (issue 18), with no limit or one that may cut
     * the fill short. */
    limited = fz_below(&in, 3);
    limit = limited == 2 ? (uint64_t)fz_below(&in, 2 * w * h + 8) : UINT64_MAX;
    if (limited)
        st = rast_seed_fill_limited(&ft.t, sx, sy, value, boundary ? edge : NULL, conn, mem, bytes,
                                    limit, &work);
    else if (boundary)
        st = rast_boundary_fill(&ft.t, sx, sy, value, edge, conn, mem, bytes);
    else
        st = rast_flood_fill(&ft.t, sx, sy, value, conn, mem, bytes);
    fz_scratch_check(&stack);

    bad = (sx < 0 || sy < 0 || sx >= w || sy >= h) || (conn != 4 && conn != 8) || (null_stack && bytes) ||
          (misalign && bytes && !null_stack);
    if (bad) {
        FZ_ASSERT(st == RAST_E_ARG || st == RAST_E_NULL || st == RAST_E_ALIGN);
        FZ_ASSERT(((sx < 0 || sy < 0 || sx >= w || sy >= h) || (conn != 4 && conn != 8)) ? 1 : st != RAST_E_ARG);
        if (st == RAST_E_NULL) FZ_ASSERT(null_stack && bytes);
        if (st == RAST_E_ALIGN) FZ_ASSERT(misalign && bytes && !null_stack);
        FZ_ASSERT(fz_untouched(&ft));
        return 0;
    }
    FZ_ASSERT(st == RAST_OK || (st == RAST_E_WORK && limited == 2));

    /* the reference: breadth-first from the seed over the cut clip */
    memcpy(expect, ft.before, sizeof expect);
    if (fz_in_rect(&ft.cut, sx, sy)) {
        uint32_t seedv = get(&ft, ft.before, sx, sy), fillv = as_pixel(&ft, value), edgev = as_pixel(&ft, edge);
        int32_t head = 0, tail = 0;
#define INSIDE(px) (boundary ? ((px) != edgev && (px) != fillv) : ((px) == seedv && fillv != seedv))
        memset(seen, 0, sizeof seen);
        if (INSIDE(seedv)) {
            queue[tail++] = sy * SF_MAXDIM + sx;
            seen[sy * SF_MAXDIM + sx] = 1;
        }
        while (head < tail) {
            int32_t p = queue[head++], px = p % SF_MAXDIM, py = p / SF_MAXDIM, dx, dy;
            put(&ft, expect, px, py, value);
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++) {
                    int32_t qx = px + dx, qy = py + dy;
                    if ((dx == 0 && dy == 0) || (conn == 4 && dx != 0 && dy != 0)) continue;
                    if (!fz_in_rect(&ft.cut, qx, qy) || seen[qy * SF_MAXDIM + qx]) continue;
                    if (!INSIDE(get(&ft, ft.before, qx, qy))) continue;
                    seen[qy * SF_MAXDIM + qx] = 1;
                    queue[tail++] = qy * SF_MAXDIM + qx;
                }
        }
#undef INSIDE
        region = (uint64_t)tail;
    }
    if (st == RAST_E_WORK) {
        /* Stopped: only pixels of the region got the value, at most
         * `limit` of them (one unit of work each), and the region was
         * more work than that. */
        memcpy(mixed, ft.before, sizeof mixed);
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                if (get(&ft, ft.mem, x, y) != get(&ft, ft.before, x, y)) {
                    put(&ft, mixed, x, y, value);
                    changed++;
                }
        FZ_ASSERT(memcmp(mixed, ft.mem, sizeof mixed) == 0);
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                if (get(&ft, ft.mem, x, y) != get(&ft, ft.before, x, y))
                    FZ_ASSERT(get(&ft, expect, x, y) == get(&ft, ft.mem, x, y));
        FZ_ASSERT(changed <= limit && work <= limit && region > changed);
        return 0;
    }
    FZ_ASSERT(memcmp(expect, ft.mem, sizeof expect) == 0);
    if (limited) {
        FZ_ASSERT(work <= limit && work >= region);
        if (stack_mode == 0 && bytes == need && !misalign) FZ_ASSERT(work == region);
    }
    return 0;
}
