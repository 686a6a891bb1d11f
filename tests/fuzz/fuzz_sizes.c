/*
 * fuzz_sizes.c - the entry points that describe rather than draw:
 * rast_scratch_size, rast_tri_scratch_size, rast_scene_scratch_size,
 * rast_target_init, rast_format_bytes, rast_algorithm_info,
 * rast_tri_algorithm_info, rast_status_str, rast_version_number; with
 * arguments at and past every limit.  Oracle: the status is the documented
 * one (each bad argument alone gives its own code), an error leaves the
 * output untouched, a scratch size is never more than the bound macro of
 * rastrum.h says and never shrinks when the vertices, the width or the
 * height grow, and a scene needs the most any one of its primitives needs.
 */
#define RAST_STATIC_LINKING_ONLY /* the other algorithms' scratch bounds */
#include "fuzz.h"

/* An int32 at or near a limit, or anything. */
static int32_t fz_dim(fz_in *in, int32_t limit)
{
    switch (fz_u8(in) % 8) {
    case 0: return 0;
    case 1: return limit;
    case 2: return limit + 1;
    case 3: return -1 - fz_below(in, 3);
    case 4: return limit - fz_below(in, 4);
    case 5: return (int32_t)fz_u32(in);
    default: return fz_below(in, 1000);
    }
}

static uint32_t fz_count_arg(fz_in *in)
{
    switch (fz_u8(in) % 6) {
    case 0: return 0;
    case 1: return RAST_MAX_POINTS;
    case 2: return RAST_MAX_POINTS + 1;
    case 3: return fz_u32(in);
    default: return (uint32_t)fz_below(in, 5000);
    }
}

/* Options with, sometimes, one field out of its range. */
static rast_fill_opts fz_opts_maybe_bad(fz_in *in)
{
    rast_fill_opts o = fz_fill_opts(in);
    switch (fz_u8(in) % 12) {
    case 0: o.algorithm = (rast_algorithm)(RAST_ALGO_COUNT_ + fz_below(in, 3)); break;
    case 1: o.rule = (rast_fill_rule)(2 + fz_below(in, 3)); break;
    case 2: o.subpixel_bits = fz_u8(in) & 1 ? -1 : RAST_MAX_SUBPIXEL_BITS + 1; break;
    case 3: o.sample = (rast_sample)2; break;
    case 4: o.rounding = (rast_rounding)2; break;
    case 5: o.boundary = (rast_boundary)3; break;
    default: break;
    }
    return o;
}

static int opts_error(const rast_fill_opts *o, int tri, rast_status *code)
{
    uint32_t rules = 0;
    int n = 0;
    if ((unsigned)o->algorithm >= (tri ? RAST_TRI_COUNT_ : RAST_ALGO_COUNT_)) n++, *code = RAST_E_ALGORITHM;
    if (!tri && (unsigned)o->rule > RAST_RULE_NONZERO) n++, *code = RAST_E_ARG;
    if (!tri && n == 0 && rast_algorithm_info(o->algorithm, NULL, &rules) == RAST_OK &&
        !(rules & (1u << o->rule)))
        n++, *code = RAST_E_RULE;
    if (o->subpixel_bits < 0 || o->subpixel_bits > RAST_MAX_SUBPIXEL_BITS) n++, *code = RAST_E_SUBPIXEL;
    if ((unsigned)o->sample > 1 || (unsigned)o->rounding > 1 || (unsigned)o->boundary > 2)
        n++, *code = RAST_E_ARG;
    return n;
}

/* The bound macros of rastrum.h, in 64 bits (none of them overflows there
 * for arguments in range). */
static uint64_t bound(rast_algorithm a, uint64_t np, uint64_t w, uint64_t h)
{
    switch (a) {
    case RAST_ALGO_AET: return RAST_AET_SCRATCH_BOUND(np, h);
    case RAST_ALGO_XSCAN: return RAST_XSCAN_SCRATCH_BOUND(np);
    case RAST_ALGO_EDGEFILL: return RAST_EDGEFILL_SCRATCH_BOUND(w, h);
    case RAST_ALGO_FENCE: return RAST_FENCE_SCRATCH_BOUND(w, h);
    case RAST_ALGO_EDGEFLAG: return RAST_EDGEFLAG_SCRATCH_BOUND(np, w, h);
    default: return RAST_POINTWISE_SCRATCH_BOUND(np);
    }
}

static void check_scratch(fz_in *in)
{
    rast_fill_opts o = fz_opts_maybe_bad(in);
    uint32_t np = fz_count_arg(in);
    int32_t w = fz_dim(in, RAST_MAX_DIM), h = fz_dim(in, RAST_MAX_DIM);
    rast_status code = RAST_OK, st;
    size_t bytes = 12345, more;
    int n = opts_error(&o, 0, &code);
    if (w < 0 || h < 0 || w > RAST_MAX_DIM || h > RAST_MAX_DIM) n++, code = RAST_E_SIZE;
    if (np > RAST_MAX_POINTS) n++, code = RAST_E_TOO_MANY;
    st = rast_scratch_size(&o, np, w, h, &bytes);
    if (n) {
        FZ_ASSERT(st != RAST_OK && bytes == 12345);
        if (n == 1) FZ_ASSERT(st == code);
        return;
    }
    FZ_ASSERT(st == RAST_OK);
    if (o.boundary == RAST_BOUNDARY_EXACT && sizeof(size_t) >= 8)
        FZ_ASSERT((uint64_t)bytes <= bound(o.algorithm, np, (uint64_t)w, (uint64_t)h));
    if (np < RAST_MAX_POINTS) {
        FZ_ASSERT(rast_scratch_size(&o, np + 1, w, h, &more) == RAST_OK && more >= bytes);
    }
    if (w < RAST_MAX_DIM) {
        FZ_ASSERT(rast_scratch_size(&o, np, w + 1, h, &more) == RAST_OK && more >= bytes);
    }
    if (h < RAST_MAX_DIM) {
        FZ_ASSERT(rast_scratch_size(&o, np, w, h + 1, &more) == RAST_OK && more >= bytes);
    }
    if (h > 0) { /* the scene of one polygon needs what the polygon needs */
        static const uint32_t none = 0;
        rast_prim p;
        size_t scene = 0;
        memset(&p, 0, sizeof p);
        p.kind = RAST_PRIM_POLYGON;
        p.fill = &o;
        p.polygon.ring_sizes = &none;
        p.polygon.nrings = 0;
        FZ_ASSERT(rast_scene_scratch_size(&p, 1, h, w, &scene) == RAST_OK);
        FZ_ASSERT(rast_scratch_size(&o, 0, w, h, &more) == RAST_OK && scene == more);
    }
}

static void check_tri_scratch(fz_in *in)
{
    rast_fill_opts fo = fz_opts_maybe_bad(in);
    rast_tri_opts o;
    int32_t w = fz_dim(in, RAST_MAX_DIM), h = fz_dim(in, RAST_MAX_DIM);
    rast_status code = RAST_OK, st;
    size_t bytes = 12345, more;
    int n;
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_tri_algorithm)(fo.algorithm % (RAST_TRI_COUNT_ + 1));
    o.subpixel_bits = fo.subpixel_bits;
    o.sample = fo.sample;
    o.rounding = fo.rounding;
    o.boundary = fo.boundary;
    fo.algorithm = (rast_algorithm)o.algorithm;
    fo.rule = RAST_RULE_EVENODD;
    n = opts_error(&fo, 1, &code);
    if (w < 0 || h < 0 || w > RAST_MAX_DIM || h > RAST_MAX_DIM) n++, code = RAST_E_SIZE;
    st = rast_tri_scratch_size(&o, w, h, &bytes);
    if (n) {
        FZ_ASSERT(st != RAST_OK && bytes == 12345);
        if (n == 1) FZ_ASSERT(st == code);
        return;
    }
    FZ_ASSERT(st == RAST_OK);
    if (w < RAST_MAX_DIM) FZ_ASSERT(rast_tri_scratch_size(&o, w + 1, h, &more) == RAST_OK && more >= bytes);
    if (h < RAST_MAX_DIM) FZ_ASSERT(rast_tri_scratch_size(&o, w, h + 1, &more) == RAST_OK && more >= bytes);
}

static void check_target(fz_in *in)
{
    static uint16_t mem[64];
    int32_t w = fz_dim(in, RAST_MAX_DIM), h = fz_dim(in, RAST_MAX_DIM);
    int64_t tight = (int64_t)w * (1 + fz_below(in, 4));
    int32_t stride = fz_u8(in) < 128 ? fz_dim(in, INT32_MAX - 1)
                     : tight > INT32_MAX ? INT32_MAX : (int32_t)tight;
    rast_format f = (rast_format)fz_below(in, RAST_FORMAT_COUNT_ + 2);
    uint32_t kind = fz_u8(in) % 3;
    void *pixels = kind == 0 ? NULL : kind == 1 ? (void *)mem : (void *)((unsigned char *)mem + 1);
    rast_target t, before;
    rast_status code = RAST_OK, st;
    int32_t bpp = 0;
    int n = 0;
    memset(&t, 0x5C, sizeof t);
    before = t;
    if ((unsigned)f >= RAST_FORMAT_COUNT_) {
        n++, code = RAST_E_FORMAT;
    } else if ((unsigned)f > RAST_FORMAT_COUNT16) { /* a later format: its own rules */
        st = rast_target_init(&t, pixels, w, h, stride, f);
        if (st != RAST_OK) FZ_ASSERT(memcmp(&t, &before, sizeof t) == 0);
        return;
    } else {
        FZ_ASSERT(rast_format_bytes(f, &bpp) == RAST_OK);
        FZ_ASSERT(bpp == (f == RAST_FORMAT_GRAY8 ? 1 : f == RAST_FORMAT_RGB888 ? 3
                          : f == RAST_FORMAT_RGBA8888 ? 4 : 2));
        if (w < 0 || h < 0 || w > RAST_MAX_DIM || h > RAST_MAX_DIM || stride < 0 ||
            (int64_t)stride < (int64_t)w * bpp || (uint64_t)stride * (uint64_t)h > (uint64_t)PTRDIFF_MAX)
            n++, code = RAST_E_SIZE;
        else if (f == RAST_FORMAT_COUNT16 && (stride % 2 || kind == 2))
            n++, code = RAST_E_SIZE;
        if (!pixels && w > 0 && h > 0) n++, code = RAST_E_NULL;
    }
    st = rast_target_init(&t, pixels, w, h, stride, f);
    if (n) {
        FZ_ASSERT(st != RAST_OK && memcmp(&t, &before, sizeof t) == 0);
        if (n == 1) FZ_ASSERT(st == code);
        return;
    }
    FZ_ASSERT(st == RAST_OK);
    FZ_ASSERT(t.pixels == pixels && t.width == w && t.height == h && t.stride == stride && t.format == f);
    FZ_ASSERT(t.clip.x0 == 0 && t.clip.y0 == 0 && t.clip.x1 == w && t.clip.y1 == h);
}

static void check_info(fz_in *in)
{
    int32_t v = (int32_t)fz_u32(in), bpp = -5;
    const char *name = NULL;
    uint32_t rules = 0;
    FZ_ASSERT(rast_status_str((rast_status)v) != NULL);
    FZ_ASSERT(rast_version_number() == RAST_VERSION_NUMBER);
    FZ_ASSERT(rast_format_bytes((rast_format)v, &bpp) ==
              ((unsigned)v < RAST_FORMAT_COUNT_ ? RAST_OK : RAST_E_FORMAT));
    FZ_ASSERT(((unsigned)v < RAST_FORMAT_COUNT_) == (bpp != -5));
    FZ_ASSERT(rast_algorithm_info((rast_algorithm)v, &name, &rules) ==
              ((unsigned)v < RAST_ALGO_COUNT_ ? RAST_OK : RAST_E_ALGORITHM));
    if ((unsigned)v < RAST_ALGO_COUNT_) FZ_ASSERT(name && (rules & 1u)); /* even-odd: all */
    name = NULL;
    FZ_ASSERT(rast_tri_algorithm_info((rast_tri_algorithm)v, &name) ==
              ((unsigned)v < RAST_TRI_COUNT_ ? RAST_OK : RAST_E_ALGORITHM));
    FZ_ASSERT(((unsigned)v < RAST_TRI_COUNT_) == (name != NULL));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    switch (fz_u8(&in) % 4) {
    case 0: check_scratch(&in); break;
    case 1: check_tri_scratch(&in); break;
    case 2: check_target(&in); break;
    default: check_info(&in); break;
    }
    return 0;
}
