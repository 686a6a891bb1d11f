/*
 * edge.c - exact edge setup: where an edge first crosses a sample row, and
 * the integer DDA that walks it down (see rast__edge in internal.h).  The
 * bodies are inline functions in internal.h, which the triangle fillers
 * use directly; these are the out-of-line copies the polygon fillers
 * call.
 */
#include "internal.h"

void rast__edge_start(rast__edge *ed, rast_point top, rast_point bottom,
                      int32_t dir, int32_t first, int32_t end, const rast__grid *g)
{
    rast__edge_start_inline(ed, top, bottom, dir, first, end, g);
}

int rast__edge_setup(rast__edge *ed, rast_point a, rast_point b,
                     const rast__grid *g, int32_t row_lo, int32_t row_hi)
{
    return rast__edge_setup_inline(ed, a, b, g, row_lo, row_hi);
}

#include <string.h>

#include "aet.h"

typedef char rast__pt_word_check[sizeof(rast_point) == 8 ? 1 : -1];

/* A point's 8 bytes as one word (equal words: equal points). */
static inline uint64_t rast__pt_word(const rast_point *p)
{
    uint64_t w;
    memcpy(&w, p, sizeof w);
    return w;
}

/* A point's word (rast__pt_word) as a key whose order as an unsigned
 * number is the points' by y, then x: each coordinate's sign bit flipped,
 * y in the high half. */
static inline uint64_t rast__pt_key(uint64_t w)
{
    const uint32_t one = 1;
    unsigned char little;
    memcpy(&little, &one, 1);
    w ^= UINT64_C(0x8000000080000000);
    return little ? w : (w >> 32) | (w << 32); /* (big-endian: x the high half) */
}

/* A segment's slot in a table of 2^bits: the words of its ends mixed by
 * two odd multipliers, the top bits of the product taken (every bit of
 * both words reaches them). */
static inline uint32_t rast__seg_hash(uint64_t a, uint64_t b, int32_t bits)
{
    const uint64_t h = ((a * UINT64_C(0x9E3779B97F4A7C15)) ^ b) * UINT64_C(0xC2B2AE3D27D4EB4F);
    return (uint32_t)(h >> (64 - bits));
}

int32_t rast__segs_cancel(const rast_point *pts, const uint32_t *ring_sizes, uint32_t npoints,
                          int evenodd, rast__arena *arena, rast__seg **out, uint32_t *copies)
{
    const rast__arena keep = *arena;
    const int32_t N = (int32_t)npoints, quarter = N / 4;
    rast__seg *seg;
    int32_t *slot, i, m = 0, left = 0, rs = 0, re = 0, tbits = 1, fresh = 0;
    uint32_t ring = 0, mask, sum = 0;
    if (npoints == 0 || npoints > (uint32_t)INT32_MAX / 4) return -1;
    while (((int64_t)1 << tbits) < (int64_t)N * 2) tbits++;
    mask = ((uint32_t)1 << tbits) - 1;
    seg = (rast__seg *)rast__take(arena, (size_t)npoints * sizeof *seg);
    slot = (int32_t *)rast__take(arena, ((size_t)1 << tbits) * sizeof *slot);
    if (!seg || !slot) {
        *arena = keep;
        return -1;
    }
    memset(slot, 0xFF, ((size_t)1 << tbits) * sizeof *slot); /* -1: free */
    /* equal segments summed into the first (the table at most half full),
     * and `left`, the crossing edges that stay (the first's |n| summed),
     * kept as it goes: each edge still to come takes at most one off it,
     * so a polygon whose edges do not cancel is given up as soon as even
     * that would leave more than half.  A segment's ends are hashed and
     * compared as words (rast__pt_word), not coordinate by coordinate. */
    for (i = 0; i < N; i++) {
        uint64_t wp, wq, kp, kq, wa, wb;
        int fwd, cross;
        uint32_t h;
        int32_t s;
        /* a quarter of the way, fewer than one edge in 64 met again (i -
         * fresh of them): taken for edges that are not a mesh's, and given
         * up (the bound below waits for three quarters of the edges, and
         * hashing them was a fifteenth of 10,000 random triangles' ss4).
         * A mesh meets its edges again from its first cells on in its
         * own order, and about N / 32 of them by then shuffled; either
         * way the caller's fill is the same. */
        if (i == quarter && (int64_t)(i - fresh) * 64 < (int64_t)N) {
            *arena = keep;
            return -1;
        }
        while (i == re) { /* the next ring (empty ones skipped) */
            rs = re;
            re += ring_sizes ? (int32_t)ring_sizes[ring++] : 3;
        }
        wp = rast__pt_word(&pts[i]);
        wq = rast__pt_word(&pts[i + 1 == re ? rs : i + 1]);
        kp = rast__pt_key(wp);
        kq = rast__pt_key(wq);
        fwd = kp < kq;
        cross = (kp ^ kq) >> 32 != 0;
        wa = fwd ? wp : wq;
        wb = fwd ? wq : wp;
        memcpy(&seg[i].a, &wa, sizeof wa);
        memcpy(&seg[i].b, &wb, sizeof wb);
        h = rast__seg_hash(wa, wb, tbits);
        while ((s = slot[h]) >= 0 && (rast__pt_word(&seg[s].a) != wa || rast__pt_word(&seg[s].b) != wb))
            h = (h + 1) & mask;
        if (s < 0) {
            slot[h] = i;
            seg[i].n = fwd ? 1 : -1;
            fresh++;
            left += cross;
            if (((int64_t)left - ((int64_t)N - 1 - i)) * 2 > (int64_t)N) {
                *arena = keep;
                return -1;
            }
        } else {
            const int32_t was = seg[s].n, now = was + (fwd ? 1 : -1);
            seg[s].n = now;
            seg[i].n = 0;
            if (cross) left += (now < 0 ? -now : now) - (was < 0 ? -was : was);
        }
    }
    if ((int64_t)left * 2 > (int64_t)N) {
        *arena = keep;
        return -1;
    }
    /* those at 0 gone (even-odd: those at an even count), the rest's
     * copies in n's sign */
    for (i = 0; i < N; i++) {
        int32_t n = seg[i].n;
        if (evenodd) n = n & 1 ? (n < 0 ? -1 : 1) : 0;
        if (n != 0 && seg[i].a.y != seg[i].b.y) {
            seg[m] = seg[i];
            seg[m].n = n;
            sum += (uint32_t)(n < 0 ? -n : n);
            m++;
        }
    }
    *out = seg;
    *copies = sum;
    return m;
}

int32_t rast__segs_edges(const rast__seg *seg, int32_t m, const rast__grid *g, int32_t row0,
                         int32_t row1, rast__edge *aet, int32_t *bucket)
{
    int32_t i, k, nedges = 0;
    for (i = 0; i < m; i++)
        for (k = 0; k < (seg[i].n < 0 ? -seg[i].n : seg[i].n); k++) {
            rast__edge *ed = &aet[nedges];
            if (seg[i].n > 0 ? rast__edge_setup(ed, seg[i].a, seg[i].b, g, row0, row1)
                             : rast__edge_setup(ed, seg[i].b, seg[i].a, g, row0, row1)) {
                ed->next = nedges++;
                bucket[ed->row - row0 + 1]++;
            }
        }
    return nedges;
}
