/* coco.c - glue for rastrum.coco: COCO run-length encoding (RLE) in C.
 *
 * The polygon rule itself is the core's (rast_coco_ring_toggles,
 * rast_coco_rle); here are the parts pycocotools does around it, written
 * anew from what cocoapi's maskApi.c does: the 6-bits-a-character string
 * form, encoding masks, decoding (into any strided uint8 array), merging,
 * areas, boxes and IoUs, with pycocotools' arithmetic (uint32 counts,
 * double IoUs) so that the results are the same, and the exact rule's RLE
 * straight from the core's spans.  See coco.h for the buffer convention. */
#define RAST_STATIC_LINKING_ONLY /* pycocotools' rule */
#include <stdlib.h>
#include <string.h>
#include "batch.h"
#include "coco.h"

void rastpy_free(void *p)
{
    free(p);
}

/* ---- a growing byte buffer ------------------------------------------------ */

typedef struct rastpy_bytes {
    char *p;
    size_t n, cap;
} rastpy_bytes;

static int rastpy_bytes_reserve(rastpy_bytes *b, size_t more)
{
    if (b->n + more > b->cap) {
        size_t cap = b->cap * 2 + more + 64;
        char *p = (char *)realloc(b->p, cap);
        if (!p) return 0;
        b->p = p;
        b->cap = cap;
    }
    return 1;
}

/* Append the string form of counts[0..m): each count (from the fourth on,
 * its difference from the count two before, as a signed 64-bit number) in
 * 5-bit groups, low first, 0x20 marking "more follows", the last group's
 * 0x10 its sign, each group + 48 ('0'). */
static int rastpy_rle_string(rastpy_bytes *b, const uint32_t *cnts, size_t m)
{
    size_t i;
    if (!rastpy_bytes_reserve(b, m * 7 + 1)) return 0;
    for (i = 0; i < m; i++) {
        int64_t x = (int64_t)cnts[i];
        int more = 1;
        if (i > 2) x -= (int64_t)cnts[i - 2];
        while (more) {
            int c = (int)(x & 0x1f);
            x = (x - c) / 32; /* floor: an arithmetic shift */
            more = (c & 0x10) ? x != -1 : x != 0;
            if (more) c |= 0x20;
            b->p[b->n++] = (char)(c + 48);
        }
    }
    return 1;
}

/* Parse string s[0..len) into cnts (room for len counts); the number of
 * counts, or -1 when the string is not an RLE: a character outside
 * '0'..'o', a count that does not end or takes more than 7 groups (35
 * bits: pycocotools writes at most 7 for its uint32 counts), or a count
 * outside 0..2^32 - 1 (pycocotools would wrap it; here it is refused).
 * Every shift and sum stays inside 64 bits whatever the bytes. */
static long rastpy_rle_parse(const char *s, size_t len, uint32_t *cnts)
{
    size_t p = 0, m = 0;
    while (p < len) {
        uint64_t u = 0;
        int64_t x;
        int k = 0, c = 0, more = 1;
        while (more) {
            if (p >= len || k == 7) return -1; /* a count that does not end */
            c = (unsigned char)s[p] - 48;
            if (c < 0 || c > 63) return -1;
            u |= (uint64_t)(c & 0x1f) << (5 * k);
            more = c & 0x20;
            p++;
            k++;
        }
        /* the last group's 0x10 is the sign of the 5 k-bit number */
        x = (c & 0x10) ? (int64_t)u - ((int64_t)1 << (5 * k)) : (int64_t)u;
        if (m > 2) x += (int64_t)cnts[m - 2];
        if (x < 0 || x > (int64_t)0xFFFFFFFFu) return -1;
        cnts[m++] = (uint32_t)x;
    }
    return (long)m;
}

/* All n strings parsed: counts of string k at (*cnts)[(*first)[k] ..
 * (*first)[k + 1]), each string's counts adding up to at most its h * w
 * (sizes[2k] * sizes[2k + 1], or height * width for all when sizes is
 * NULL) and at most 2^32 - 1, so that no uint32 sum of them wraps.  0, RASTPY_E_NOMEM, or RASTPY_E_RLE with *bad = k.  Every
 * function that takes RLE strings reads them here: this is the one place
 * their counts are judged. */
static long rastpy_rles(const char *strs, const size_t *offsets, uint32_t n,
                        const uint32_t *sizes, uint32_t height, uint32_t width, uint32_t **cnts,
                        size_t **first, uint32_t *bad)
{
    uint32_t k;
    size_t total = offsets[n] - offsets[0], at = 0, j;
    *cnts = (uint32_t *)malloc(total * sizeof(uint32_t) + 4);
    *first = (size_t *)malloc(((size_t)n + 1) * sizeof(size_t));
    if (!*cnts || !*first) {
        free(*cnts);
        free(*first);
        return RASTPY_E_NOMEM;
    }
    for (k = 0; k < n; k++) {
        long m = rastpy_rle_parse(strs + offsets[k], offsets[k + 1] - offsets[k], *cnts + at);
        uint64_t area = sizes ? (uint64_t)sizes[2 * k] * sizes[2 * k + 1] : (uint64_t)height * width;
        uint64_t sum = 0;
        if (area > 0xFFFFFFFFu) area = 0xFFFFFFFFu; /* COCO's counts are uint32 */
        (*first)[k] = at;
        for (j = 0; m > 0 && j < (size_t)m; j++) sum += (*cnts)[at + j];
        if (m < 0 || sum > area) {
            free(*cnts);
            free(*first);
            *bad = k;
            return RASTPY_E_RLE;
        }
        at += (size_t)m;
    }
    (*first)[n] = at;
    return 0;
}

/* ---- polygons: pycocotools' rule through the core ----------------------- */

/* pycocotools (rleFrPoly) walks every edge in fifths of a pixel, keeps a
 * toggle per column crossed and sorts them all: memory grows with the
 * vertices times the width (100 vertices zig-zagging across 1.6 million
 * columns: 160 million toggles).  The RLE depends only on which positions
 * hold an odd number of toggles, so here the positions are taken a window
 * at a time (rast_coco_ring_toggles_in): at most `budget` toggles and
 * 4 * budget positions (a parity bit each) per window, windows in
 * increasing order, each run end written as soon as its window is done.
 * Memory: the window's buffers plus the RLE string itself.
 *
 * Which run ends pycocotools writes: its counts are the differences of
 * the sorted positions with h * w among them (uint32), a difference of 0
 * joining the runs around it; worked through, the run ends are the
 * positions of odd multiplicity among toggles and h * w, except the
 * largest position of all, which always ends a run (tests/test_coco.py
 * checks this against pycocotools, and tests/c/test_coco.c the core's
 * windows against its whole call). */

typedef struct coco_emit {
    rastpy_bytes *out;
    size_t n;          /* counts written */
    uint32_t c1, c2;   /* the last two counts */
    uint64_t last;     /* the last run end */
} coco_emit;

/* Append the count that ends a run at position v (see rastpy_rle_string). */
static int coco_put(coco_emit *e, uint64_t v)
{
    uint32_t cnt = (uint32_t)(v - e->last);
    int64_t x = (int64_t)cnt;
    int more = 1;
    if (!rastpy_bytes_reserve(e->out, 8)) return 0;
    if (e->n > 2) x -= (int64_t)e->c2;
    while (more) {
        int c = (int)(x & 0x1f);
        x = (x - c) / 32;
        more = (c & 0x10) ? x != -1 : x != 0;
        if (more) c |= 0x20;
        e->out->p[e->out->n++] = (char)(c + 48);
    }
    e->c2 = e->c1;
    e->c1 = cnt;
    e->n++;
    e->last = v;
    return 1;
}

typedef struct coco_work {
    uint32_t *tog;   /* a window's toggles */
    size_t cap;      /* room in tog */
    uint64_t *bits;  /* a window's parities, one bit a position */
    uint64_t span;   /* positions a window may cover (a multiple of 64) */
} coco_work;

/* Toggles in [p0, p1) of the uint32 positions, over `laps` wraps (width
 * 0); into w->tog when `write`, else only counted.  A core status. */
static rast_status coco_window(const rast_point *pts, uint32_t n, uint32_t h, uint32_t wd,
                               uint64_t laps, uint64_t p0, uint64_t p1, coco_work *w, int write,
                               size_t *count)
{
    uint64_t L;
    size_t at = 0, got;
    for (L = 0; L < laps; L++) {
        rast_status st = rast_coco_ring_toggles_in(pts, n, (int32_t)h, (int32_t)wd, (L << 32) + p0,
                                                   (L << 32) + p1, write && w->tog ? w->tog + at : NULL,
                                                   write ? w->cap - at : 0, &got);
        if (st != RAST_OK && !(st == RAST_E_SCRATCH && !write)) return st;
        at += got;
    }
    *count = at;
    return RAST_OK;
}

static long coco_ring_rle(const rast_point *pts, uint32_t n, uint32_t h, uint32_t wd,
                          size_t budget, coco_work *w, rastpy_bytes *out)
{
    uint64_t total = (uint64_t)h * wd, endp, laps = 1, p0 = 0, step = 64, top = 0;
    coco_emit e;
    int any = 0;
    e.out = out;
    e.n = 0;
    e.c1 = e.c2 = 0;
    e.last = 0;
    if (!h) /* every position is 0: pycocotools' counts are [0] */
        return coco_put(&e, 0) ? 0 : RASTPY_E_NOMEM;
    if (wd) {
        endp = total + 1;
    } else {
        /* width 0: every column from 0 on, up to the last the ring crosses
         * (5c + 2 < its largest X), positions wrapping at 2^32 */
        int64_t maxx = 0, cols;
        uint32_t j;
        for (j = 0; j < n; j++)
            if (pts[j].x > maxx) maxx = pts[j].x;
        cols = (maxx - 2 + 4) / 5; /* ceil((maxx - 2) / 5), maxx >= 0 */
        if (cols < 0) cols = 0;
        laps = (((uint64_t)cols * h) >> 32) + 1;
        endp = laps > 1 ? (uint64_t)1 << 32 : (uint64_t)cols * h + 1;
    }
    while (p0 < endp) {
        uint64_t p1 = p0 + step > endp ? endp : p0 + step, i, nw;
        size_t cnt, k;
        int total_here = !wd && p0 == 0; /* h * w = 0 is a position too */
        rast_status st = coco_window(pts, n, h, wd, laps, p0, p1, w, 0, &cnt);
        if (st != RAST_OK) return st;
        if (cnt > budget || ((cnt || total_here) && p1 - p0 > w->span)) {
            if (p1 - p0 > 1) {
                step = (p1 - p0) / 2;
                continue;
            }
            budget = cnt; /* one position's toggles: at most 2 per edge and lap */
        }
        if (cnt > w->cap) {
            free(w->tog);
            w->tog = (uint32_t *)malloc(cnt * sizeof(uint32_t));
            w->cap = w->tog ? cnt : 0;
            if (!w->tog) return RASTPY_E_NOMEM;
        }
        if (cnt || total_here) {
            st = coco_window(pts, n, h, wd, laps, p0, p1, w, 1, &cnt);
            if (st != RAST_OK) return st;
            nw = (p1 - p0 + 63) / 64;
            memset(w->bits, 0, (size_t)nw * sizeof(uint64_t));
            for (k = 0; k < cnt; k++) {
                uint64_t v = w->tog[k] - p0;
                w->bits[v >> 6] ^= (uint64_t)1 << (v & 63);
                if (!any || w->tog[k] >= top) top = w->tog[k];
                any = 1;
            }
            if (total_here) w->bits[0] ^= 1;
            for (i = 0; i < nw; i++) {
                uint64_t word = w->bits[i];
                while (word) {
                    int b = 0;
                    uint64_t v;
                    while (!((word >> b) & 1)) b++;
                    word &= word - 1;
                    v = p0 + 64 * i + (uint64_t)b;
                    if (wd && v >= total) break; /* h * w ends the last run below */
                    if (!coco_put(&e, v)) return RASTPY_E_NOMEM;
                }
            }
        }
        p0 = p1;
        if (step < ((uint64_t)1 << 33)) step *= 2;
    }
    /* the largest position always ends a run: h * w, or (width 0) the
     * largest toggle */
    if (wd) top = total;
    if (!e.n || e.last != top)
        if (!coco_put(&e, top)) return RASTPY_E_NOMEM;
    return 0;
}

long rastpy_coco_fr_polys(const double *xy, const uint32_t *npoints, uint32_t npolys,
                          uint32_t height, uint32_t width, size_t budget, char **data,
                          size_t *offsets)
{
    rastpy_bytes out = {NULL, 0, 0};
    size_t at = 0, maxpts = 0;
    uint32_t k;
    int32_t *pts;
    long result = 0;
    coco_work w = {NULL, 0, NULL, 0};
    if (!budget) budget = (size_t)1 << 18;
    if (budget > ((size_t)1 << 26)) budget = (size_t)1 << 26;
    w.span = (((uint64_t)budget * 4 + 63) / 64) * 64;
    for (k = 0; k < npolys; k++)
        if (npoints[k] > maxpts) maxpts = npoints[k];
    pts = (int32_t *)malloc(maxpts * 2 * sizeof(int32_t) + 8);
    w.bits = (uint64_t *)malloc((size_t)(w.span / 64) * sizeof(uint64_t));
    if (!pts || !w.bits) {
        result = RASTPY_E_NOMEM;
        goto done;
    }
    offsets[0] = 0;
    for (k = 0; k < npolys; k++) {
        const double lim = (double)RAST_COCO_COORD_MAX + 1.0;
        size_t i;
        for (i = 0; i < 2 * (size_t)npoints[k]; i++) {
            /* pycocotools' upsampling, in double: (int)(5 x + 0.5) */
            double v = 5.0 * xy[2 * at + i] + 0.5;
            if (!(v > -lim && v < lim)) {
                result = (long)(at + i / 2) + 1;
                goto done;
            }
            pts[i] = (int32_t)v;
        }
        result = coco_ring_rle((const rast_point *)(void *)pts, npoints[k], height, width, budget, &w,
                               &out);
        if (result) goto done;
        offsets[k + 1] = out.n;
        at += npoints[k];
    }
done:
    free(pts);
    free(w.tog);
    free(w.bits);
    if (result) {
        free(out.p);
        *data = NULL;
    } else {
        *data = out.p;
    }
    return result;
}

/* ---- the exact rule: RLE straight from the core's spans ------------------ */

typedef struct rastpy_span {
    int32_t x0, x1;
} rastpy_span;

typedef struct rastpy_exact {
    uint32_t height, width, npolys, poly; /* poly: the polygon being collected */
    int32_t last_y;                       /* last finished row, -1: none */
    int32_t cur_y;                        /* row being collected, -1: none */
    rastpy_span *last, *cur;              /* their spans */
    size_t nlast, ncur, capspans;
    uint32_t *tog;                        /* toggles of the polygon */
    size_t ntog, captog;
    rastpy_bytes out;
    size_t *offsets;
    int nomem;
} rastpy_exact;

static void rastpy_toggle_run(rastpy_exact *e, int32_t x0, int32_t x1, int32_t y)
{
    int32_t x;
    if (e->ntog + (size_t)(x1 - x0) > e->captog) {
        size_t cap = e->captog * 2 + (size_t)(x1 - x0) + 256;
        uint32_t *t = (uint32_t *)realloc(e->tog, cap * sizeof(uint32_t));
        if (!t) {
            e->nomem = 1;
            return;
        }
        e->tog = t;
        e->captog = cap;
    }
    for (x = x0; x < x1; x++) e->tog[e->ntog++] = (uint32_t)x * e->height + (uint32_t)y;
}

/* Toggles at row y where the spans a (row y - 1) and b (row y) differ: the
 * columns covered by one of them an odd number of times. */
static void rastpy_xor_rows(rastpy_exact *e, const rastpy_span *a, size_t na,
                            const rastpy_span *b, size_t nb, int32_t y)
{
    size_t i = 0, j = 0;
    int inside = 0;
    int32_t start = 0;
    /* merge the two sorted lists of span ends; each end flips parity */
    while (i < 2 * na || j < 2 * nb) {
        int32_t xa = i < 2 * na ? (i & 1 ? a[i / 2].x1 : a[i / 2].x0) : INT32_MAX;
        int32_t xb = j < 2 * nb ? (j & 1 ? b[j / 2].x1 : b[j / 2].x0) : INT32_MAX;
        int32_t x = xa < xb ? xa : xb;
        if (xa == x) i++;
        else j++;
        inside = !inside;
        if (inside) start = x;
        else if (x > start) rastpy_toggle_run(e, start, x, y);
    }
}

/* Row cur_y is complete: its toggles against the last row. */
static void rastpy_exact_row(rastpy_exact *e)
{
    rastpy_span *t;
    if (e->cur_y < 0) return;
    if (e->last_y + 1 < e->cur_y) {
        rastpy_xor_rows(e, e->last, e->nlast, NULL, 0, e->last_y + 1);
        e->nlast = 0;
    }
    rastpy_xor_rows(e, e->last, e->nlast, e->cur, e->ncur, e->cur_y);
    t = e->last;
    e->last = e->cur;
    e->cur = t;
    e->nlast = e->ncur;
    e->ncur = 0;
    e->last_y = e->cur_y;
    e->cur_y = -1;
}

/* The polygon e->poly is complete: its RLE string. */
static void rastpy_exact_poly(rastpy_exact *e)
{
    size_t m = 0;
    uint32_t *work, *cnts;
    rastpy_exact_row(e);
    if (e->last_y >= 0) rastpy_xor_rows(e, e->last, e->nlast, NULL, 0, e->last_y + 1);
    work = (uint32_t *)malloc(e->ntog * sizeof(uint32_t) + 4);
    cnts = (uint32_t *)malloc((e->ntog + 1) * sizeof(uint32_t));
    if (!work || !cnts || e->nomem ||
        rast_coco_rle(e->tog, e->ntog, e->height * e->width, work, cnts, &m) != RAST_OK ||
        !rastpy_rle_string(&e->out, cnts, m))
        e->nomem = 1;
    free(work);
    free(cnts);
    e->offsets[++e->poly] = e->out.n;
    e->ntog = 0;
    e->nlast = e->ncur = 0;
    e->last_y = e->cur_y = -1;
}

static void rastpy_exact_span(void *user, uint32_t k, int32_t y, int32_t x0, int32_t x1)
{
    rastpy_exact *e = (rastpy_exact *)user;
    if (e->nomem) return;
    while (e->poly < k) rastpy_exact_poly(e);
    if (y != e->cur_y) rastpy_exact_row(e);
    e->cur_y = y;
    if (e->ncur == e->capspans) {
        size_t cap = e->capspans * 2 + 16;
        rastpy_span *a = (rastpy_span *)realloc(e->last, cap * sizeof *a);
        rastpy_span *b = a ? (rastpy_span *)realloc(e->cur, cap * sizeof *b) : NULL;
        if (a) e->last = a;
        if (!a || !b) {
            e->nomem = 1;
            return;
        }
        e->cur = b;
        e->capspans = cap;
    }
    e->cur[e->ncur].x0 = x0;
    e->cur[e->ncur].x1 = x1;
    e->ncur++;
}

long rastpy_coco_exact(const double *xy, size_t npoints, const uint32_t *ring_sizes,
                       size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                       uint32_t height, uint32_t width, const rast_fill_opts *opts,
                       char **data, size_t *offsets, uint32_t *failed)
{
    rastpy_exact e;
    rast_polygon *polys;
    rast_rect clip;
    int32_t *pts;
    size_t need = 0;
    long bad;
    rast_status st;
    void *scratch;
    *data = NULL;
    if ((uint64_t)height * width > 0xFFFFFFFFu || height > RAST_MAX_DIM || width > RAST_MAX_DIM)
        return RAST_E_SIZE;
    bad = rastpy_polygon_table(xy, npoints, ring_sizes, nrings, poly_rings, npolys,
                               opts->subpixel_bits, &polys, &pts);
    if (bad) return bad;
    clip.x0 = 0;
    clip.y0 = 0;
    clip.x1 = (int32_t)width;
    clip.y1 = (int32_t)height;
    memset(&e, 0, sizeof e);
    e.height = height;
    e.width = width;
    e.npolys = npolys;
    e.last_y = e.cur_y = -1;
    e.offsets = offsets;
    offsets[0] = 0;
    st = rast_polygons_scratch_size(polys, npolys, opts, &clip, &need, failed);
    scratch = st == RAST_OK ? malloc(need + 1) : NULL;
    if (st == RAST_OK && !scratch) st = (rast_status)RASTPY_E_NOMEM;
    if (st == RAST_OK)
        st = rast_fill_polygons_spans(polys, npolys, opts, &clip, rastpy_exact_span, &e, scratch,
                                      need, failed);
    if (st == RAST_OK)
        while (e.poly < npolys && !e.nomem) rastpy_exact_poly(&e);
    if (st == RAST_OK && e.nomem) st = (rast_status)RASTPY_E_NOMEM;
    free(scratch);
    free(polys);
    free(pts);
    free(e.last);
    free(e.cur);
    free(e.tog);
    if (st != RAST_OK) {
        free(e.out.p);
        return st;
    }
    *data = e.out.p;
    return 0;
}

/* ---- masks -> RLE, RLE -> masks ------------------------------------------ */

long rastpy_coco_encode(const uint8_t *mask, uint32_t height, uint32_t width, uint32_t n,
                        int64_t sy, int64_t sx, int64_t sk, char **data, size_t *offsets)
{
    rastpy_bytes out = {NULL, 0, 0};
    size_t a = (size_t)height * width;
    uint32_t *cnts = (uint32_t *)malloc((a + 1) * sizeof(uint32_t)), k, x, y;
    *data = NULL;
    if (!cnts) return RASTPY_E_NOMEM;
    offsets[0] = 0;
    for (k = 0; k < n; k++) {
        const uint8_t *plane = mask + (int64_t)k * sk;
        size_t m = 0;
        uint32_t c = 0;
        uint8_t p = 0;
        /* a run ends wherever the byte changes (pycocotools compares bytes,
         * not their truth) */
        for (x = 0; x < width; x++) {
            const uint8_t *col = plane + (int64_t)x * sx;
            if (sy == 1) {
                for (y = 0; y < height; y++) {
                    if (col[y] != p) {
                        cnts[m++] = c;
                        c = 0;
                        p = col[y];
                    }
                    c++;
                }
            } else {
                for (y = 0; y < height; y++) {
                    uint8_t v = col[(int64_t)y * sy];
                    if (v != p) {
                        cnts[m++] = c;
                        c = 0;
                        p = v;
                    }
                    c++;
                }
            }
        }
        cnts[m++] = c;
        if (!rastpy_rle_string(&out, cnts, m)) {
            free(cnts);
            free(out.p);
            return RASTPY_E_NOMEM;
        }
        offsets[k + 1] = out.n;
    }
    free(cnts);
    *data = out.p;
    return 0;
}

/* Decode n RLEs of height x width into out: pixel (y, x) of mask k at
 * out + y sy + x sx + k sk; `one` inside, 0 outside.  Every string is
 * parsed and its counts checked against height * width before anything is
 * written (RASTPY_E_RLE, with the bad one's index in the return's low
 * bits: -(1 << 20) - k... kept simple: the caller re-checks to name it). */
long rastpy_coco_decode(const char *strs, const size_t *offsets, uint32_t n, uint32_t height,
                        uint32_t width, uint8_t *out, int64_t sy, int64_t sx, int64_t sk,
                        uint8_t one)
{
    uint32_t *cnts, k, bad = 0;
    size_t *first, j;
    uint64_t area = (uint64_t)height * width;
    long st = rastpy_rles(strs, offsets, n, NULL, height, width, &cnts, &first, &bad);
    if (st) return st;
    for (k = 0; k < n; k++) {
        uint8_t *plane = out + (int64_t)k * sk;
        uint64_t p = 0;
        uint8_t v = 0;
        if (sy == 1 && sx == (int64_t)height) {
            /* column-major and contiguous: runs are memsets */
            for (j = first[k]; j < first[k + 1]; j++) {
                memset(plane + p, v, cnts[j]);
                p += cnts[j];
                v = v ? 0 : one;
            }
            memset(plane + p, 0, (size_t)(area - p));
        } else {
            uint32_t x = 0, y = 0;
            for (j = first[k]; j <= first[k + 1]; j++) {
                uint64_t c = j < first[k + 1] ? cnts[j] : area - p;
                uint8_t val = j < first[k + 1] ? v : 0;
                p += c;
                while (c) {
                    /* the rest of this column, or the run */
                    uint32_t run = height - y;
                    uint8_t *q = plane + (int64_t)x * sx + (int64_t)y * sy;
                    uint32_t i;
                    if (run > c) run = (uint32_t)c;
                    for (i = 0; i < run; i++) q[(int64_t)i * sy] = val;
                    c -= run;
                    y += run;
                    if (y == height) {
                        y = 0;
                        x++;
                    }
                }
                v = v ? 0 : one;
            }
        }
    }
    free(cnts);
    free(first);
    return 0;
}

/* ---- merge, area, boxes, IoU (pycocotools' arithmetic) -------------------- */

/* A cursor over the runs of one RLE, as pycocotools' merge and IoU walk
 * them: `left` pixels remain of run i - 1, whose value is v (runs
 * alternate from 0). */
typedef struct rastpy_runs {
    const uint32_t *c;
    size_t m, i;
    uint32_t left;
    int v;
} rastpy_runs;

static void rastpy_runs_start(rastpy_runs *r, const uint32_t *c, size_t m)
{
    r->c = c;
    r->m = m;
    r->i = 1;
    r->left = m ? c[0] : 0;
    r->v = 0;
}

/* Take n pixels (n <= left); at the end of a run, step to the next that
 * is not empty (a count of 0 inside a string is no run: pycocotools'
 * loop would end there, short of the mask's end). */
static void rastpy_runs_take(rastpy_runs *r, uint32_t n)
{
    r->left -= n;
    while (!r->left && r->i < r->m) {
        r->left = r->c[r->i++];
        r->v = !r->v;
    }
}

/* Took nothing while one cursor is spent and the other is not: counts
 * that do not add up to the same total (pycocotools loops forever). */
static int rastpy_runs_stuck(const rastpy_runs *a, const rastpy_runs *b, uint32_t took)
{
    return took == 0 && (uint64_t)a->left + b->left != 0 &&
           ((a->left == 0 && a->i >= a->m) || (b->left == 0 && b->i >= b->m));
}

long rastpy_coco_merge(const char *strs, const size_t *offsets, uint32_t n,
                       const uint32_t *sizes, int intersect, char **data, size_t *offsets_out,
                       uint32_t *size_out)
{
    uint32_t *cnts, *acc, *tmp, h, w, bad = 0, i;
    size_t *first, m, cap, total;
    rastpy_bytes out = {NULL, 0, 0};
    long st;
    *data = NULL;
    offsets_out[0] = 0;
    if (n == 0) {
        size_out[0] = size_out[1] = 0;
        offsets_out[1] = 0;
        return 0;
    }
    st = rastpy_rles(strs, offsets, n, sizes, 0, 0, &cnts, &first, &bad);
    if (st) return st;
    total = first[n];
    cap = total + 2;
    acc = (uint32_t *)malloc(cap * sizeof(uint32_t));
    tmp = (uint32_t *)malloc(cap * sizeof(uint32_t));
    if (!acc || !tmp) {
        st = RASTPY_E_NOMEM;
        goto done;
    }
    h = sizes[0];
    w = sizes[1];
    m = first[1] - first[0];
    memcpy(acc, cnts, m * sizeof(uint32_t));
    for (i = 1; i < n; i++) {
        const uint32_t *B = cnts + first[i];
        size_t bm = first[i + 1] - first[i], mm = 0;
        uint64_t cc = 0, ct = 1; /* 64 bits: two run ends pass 2^32 past 2^31 pixels */
        uint32_t c;
        int v = 0, vp;
        rastpy_runs ra, rb;
        if (sizes[2 * i] != h || sizes[2 * i + 1] != w) {
            h = w = 0;
            m = 0;
            break;
        }
        rastpy_runs_start(&ra, acc, m);
        rastpy_runs_start(&rb, B, bm);
        while (ct > 0) {
            c = ra.left < rb.left ? ra.left : rb.left;
            cc += c;
            rastpy_runs_take(&ra, c);
            rastpy_runs_take(&rb, c);
            ct = (uint64_t)ra.left + rb.left;
            vp = v;
            v = intersect ? (ra.v && rb.v) : (ra.v || rb.v);
            if (v != vp || ct == 0) {
                if (mm == cap) { /* counts that do not add up: pycocotools loops */
                    st = RASTPY_E_RLE;
                    goto done;
                }
                tmp[mm++] = (uint32_t)cc; /* a run of one h * w mask */
                cc = 0;
            }
            if (rastpy_runs_stuck(&ra, &rb, c)) {
                st = RASTPY_E_RLE;
                goto done;
            }
        }
        memcpy(acc, tmp, mm * sizeof(uint32_t));
        m = mm;
    }
    if (!rastpy_rle_string(&out, acc, m)) {
        st = RASTPY_E_NOMEM;
        goto done;
    }
    offsets_out[1] = out.n;
    size_out[0] = h;
    size_out[1] = w;
    *data = out.p;
    out.p = NULL;
done:
    free(out.p);
    free(acc);
    free(tmp);
    free(cnts);
    free(first);
    return st;
}

long rastpy_coco_area(const char *strs, const size_t *offsets, uint32_t n,
                      const uint32_t *sizes, uint32_t *out)
{
    uint32_t *cnts, k, bad = 0;
    size_t *first, j;
    long st = rastpy_rles(strs, offsets, n, sizes, 0, 0, &cnts, &first, &bad);
    if (st) return st;
    for (k = 0; k < n; k++) {
        uint32_t a = 0;
        for (j = first[k] + 1; j < first[k + 1]; j += 2) a += cnts[j];
        out[k] = a;
    }
    free(cnts);
    free(first);
    return 0;
}

static void rastpy_bbox1(const uint32_t *cnts, size_t m, uint32_t h, uint32_t w, double *bb)
{
    uint32_t xs = w, ys = h, xe = 0, ye = 0, cc = 0;
    size_t j;
    int any = 0;
    m = m / 2 * 2;
    if (m == 0 || h == 0) {
        bb[0] = bb[1] = bb[2] = bb[3] = 0;
        return;
    }
    for (j = 0; j < m; j++) {
        uint32_t start = cc, y0, x0, y1, x1;
        cc += cnts[j];
        if (j % 2 == 0 || cnts[j] == 0) continue;
        any = 1;
        y0 = start % h;
        x0 = (start - y0) / h;
        y1 = (cc - 1) % h;
        x1 = (cc - 1 - y1) / h;
        if (x0 < xs) xs = x0;
        if (x1 > xe) xe = x1;
        if (x0 < x1) {
            ys = 0;
            ye = h - 1;
        } else {
            if (y0 < ys) ys = y0;
            if (y1 > ye) ye = y1;
        }
    }
    if (!any) { /* only runs of 0 ones: no pixel, the empty box */
        bb[0] = bb[1] = bb[2] = bb[3] = 0;
        return;
    }
    bb[0] = xs;
    bb[2] = (uint32_t)(xe - xs + 1);
    bb[1] = ys;
    bb[3] = (uint32_t)(ye - ys + 1);
}

long rastpy_coco_bbox(const char *strs, const size_t *offsets, uint32_t n,
                      const uint32_t *sizes, double *out)
{
    uint32_t *cnts, k, bad = 0;
    size_t *first;
    long st = rastpy_rles(strs, offsets, n, sizes, 0, 0, &cnts, &first, &bad);
    if (st) return st;
    for (k = 0; k < n; k++)
        rastpy_bbox1(cnts + first[k], first[k + 1] - first[k], sizes[2 * k], sizes[2 * k + 1],
                     out + 4 * (size_t)k);
    free(cnts);
    free(first);
    return 0;
}

void rastpy_coco_bb_iou(const double *dt, const double *gt, uint32_t m, uint32_t n,
                        const uint8_t *iscrowd, double *o)
{
    uint32_t g, d;
    for (g = 0; g < n; g++) {
        const double *G = gt + (size_t)g * 4;
        double ga = G[2] * G[3];
        int crowd = iscrowd != NULL && iscrowd[g];
        for (d = 0; d < m; d++) {
            const double *D = dt + (size_t)d * 4;
            double da = D[2] * D[3], wd, hd, i, u, a, b;
            o[(size_t)g * m + d] = 0;
            a = D[2] + D[0];
            b = G[2] + G[0];
            wd = (a < b ? a : b) - (D[0] > G[0] ? D[0] : G[0]);
            if (wd <= 0) continue;
            a = D[3] + D[1];
            b = G[3] + G[1];
            hd = (a < b ? a : b) - (D[1] > G[1] ? D[1] : G[1]);
            if (hd <= 0) continue;
            i = wd * hd;
            u = crowd ? da : da + ga - i;
            o[(size_t)g * m + d] = i / u;
        }
    }
}

long rastpy_coco_iou(const char *dstrs, const size_t *doffsets, const uint32_t *dsizes,
                     uint32_t m, const char *gstrs, const size_t *goffsets,
                     const uint32_t *gsizes, uint32_t n, const uint8_t *iscrowd, double *o)
{
    uint32_t *dc, *gc, bad = 0, g, d;
    size_t *df, *gf;
    double *db = NULL, *gb = NULL;
    long st = rastpy_rles(dstrs, doffsets, m, dsizes, 0, 0, &dc, &df, &bad);
    if (st) return st;
    st = rastpy_rles(gstrs, goffsets, n, gsizes, 0, 0, &gc, &gf, &bad);
    if (st) {
        free(dc);
        free(df);
        return st;
    }
    db = (double *)calloc((size_t)m * 4 + 1, sizeof(double));
    gb = (double *)calloc((size_t)n * 4 + 1, sizeof(double));
    if (!db || !gb) {
        st = RASTPY_E_NOMEM;
        goto done;
    }
    for (d = 0; d < m; d++) rastpy_bbox1(dc + df[d], df[d + 1] - df[d], dsizes[2 * d], dsizes[2 * d + 1], db + 4 * d);
    for (g = 0; g < n; g++) rastpy_bbox1(gc + gf[g], gf[g + 1] - gf[g], gsizes[2 * g], gsizes[2 * g + 1], gb + 4 * g);
    rastpy_coco_bb_iou(db, gb, m, n, iscrowd, o);
    for (g = 0; g < n; g++)
        for (d = 0; d < m; d++) {
            const uint32_t *A = dc + df[d], *B = gc + gf[g];
            size_t ka = df[d + 1] - df[d], kb = gf[g + 1] - gf[g], j;
            uint32_t c;
            uint64_t ct = 1, in = 0, un = 0; /* 64 bits: right past 2^31 pixels */
            int crowd;
            rastpy_runs ra, rb;
            if (!(o[(size_t)g * m + d] > 0)) continue;
            crowd = iscrowd != NULL && iscrowd[g];
            if (dsizes[2 * d] != gsizes[2 * g] || dsizes[2 * d + 1] != gsizes[2 * g + 1]) {
                o[(size_t)g * m + d] = -1;
                continue;
            }
            rastpy_runs_start(&ra, A, ka);
            rastpy_runs_start(&rb, B, kb);
            while (ct > 0) {
                c = ra.left < rb.left ? ra.left : rb.left;
                if (ra.v || rb.v) {
                    un += c;
                    if (ra.v && rb.v) in += c;
                }
                rastpy_runs_take(&ra, c);
                rastpy_runs_take(&rb, c);
                ct = (uint64_t)ra.left + rb.left;
                if (rastpy_runs_stuck(&ra, &rb, c)) {
                    st = RASTPY_E_RLE; /* counts that do not add up */
                    goto done;
                }
            }
            if (in == 0) un = 1;
            else if (crowd) {
                un = 0;
                for (j = 1; j < ka; j += 2) un += A[j];
            }
            o[(size_t)g * m + d] = (double)in / (double)un;
        }
done:
    free(db);
    free(gb);
    free(dc);
    free(df);
    free(gc);
    free(gf);
    return st;
}

long rastpy_coco_fr_counts(const uint32_t *counts, const size_t *offsets, uint32_t n,
                           char **data, size_t *offsets_out)
{
    rastpy_bytes out = {NULL, 0, 0};
    uint32_t k;
    offsets_out[0] = 0;
    for (k = 0; k < n; k++) {
        if (!rastpy_rle_string(&out, counts + offsets[k], offsets[k + 1] - offsets[k])) {
            free(out.p);
            *data = NULL;
            return RASTPY_E_NOMEM;
        }
        offsets_out[k + 1] = out.n;
    }
    *data = out.p;
    return 0;
}
