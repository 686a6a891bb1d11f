/*
 * coverage_small.c - "area" and "accumulate" of one small convex ring
 * painted through a painter (the anti-aliased fills: a tiny polygon a
 * call, Canvas.fill_polygon in a loop, issue 33), without the engines'
 * setup: no edge records, no sort, no bands, one row of cells.
 *
 * A convex ring (entry/coverage.c's test) is plain (coverage_plain.c):
 * its winding number is 0 outside and +1 or -1 inside, so the
 * accumulation of its edges is its exact coverage, for "area" and
 * "accumulate" alike, under either rule (docs/coverage.md).  Each pixel
 * gets the level floor(a M + 1/2), M = 255, of its exact area a, as the
 * 128-bit sums of the engines give it away from a tie; here a is summed
 * in 64 bits, the signed area right of each edge's piece in each cell
 * (FreeType's cover and area in one word a column, run along the row),
 * on a grid of 2^-K pixel (K = 26) relative to the ring's pixel box.
 * Only the crossings of an edge with the row lines (abscissae) and with
 * the column lines (ordinates) are rounded, down, by less than one unit;
 * a pixel's value is then off by less than 2^(K + 4) units of 2^-(2K + 1)
 * pixel per edge in its row (the columns left of it: the two ends of the
 * edge's run there; its own cell: the piece's height and its abscissae).
 * Where some level lies within that bound of a tie (times M, and the
 * engines' own 2^-50) the call declines before it has painted a pixel,
 * and the engines take the ring: the levels are theirs, bit for bit.
 *
 * Bounds: a pixel box of at most RAST__CS_DIM pixels a side, S <= 16
 * (so that K - S >= 10), at most RAST__CS_EDGES vertices.  Ordinates
 * and abscissae from the box's corner are below 2^(K + 5) = 2^31, so a
 * product of two differences (a crossing's numerator) is below 2^62; a
 * piece's part dt (f0 + f1) is below 2^53, a row's running sum below
 * 2^54 (a convex ring's pieces of one sign cover a column's height
 * once), a level's numerator below 2^62.  Not in size-optimised builds.
 */
#include "coverage.h"
#include "../base/bits.h" /* rast__ctz64 */
#include "../painters/paint.h" /* rast__gray8_blend_rows */

#if !defined(__OPTIMIZE_SIZE__)

#if defined(__SSE2__) && !defined(RAST_NO_SIMD)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__CS_SSE2 1
#endif

#define RAST__CS_K 26
#define RAST__CS_ONE ((int64_t)1 << RAST__CS_K)
/* A box at most this wide has its rows' levels made column by column
 * (rast__cov_small) */
#define RAST__CS_NARROW 12
#define RAST__CS_FULL ((int64_t)1 << (2 * RAST__CS_K + 1)) /* a pixel's area, in the cells' units */

/* An edge, top end first, in units of 2^-K pixel from the box's corner;
 * s its direction (+1 down). */
typedef struct rast__cs_edge {
    int64_t x0, y0, x1, y1, dx, dy;
    int32_t s;
} rast__cs_edge;

int rast__cov_small_fits(const rast_polygon *poly, int32_t s, rast_rect *box)
{
    uint32_t n;
    int32_t b[4]; /* x0, x1, y0, y1 */
    if (poly->nrings != 1 || s > 16 || (n = poly->ring_sizes[0]) < 3 || n > RAST__CS_EDGES) return 0;
    rast__pts_extent(poly->points, n, b);
    /* the pixels the ring reaches (|coordinates| < 2^27: no overflow) */
    box->x0 = b[0] >> s;
    box->y0 = b[2] >> s;
    box->x1 = (int32_t)(((int64_t)b[1] + ((int64_t)1 << s) - 1) >> s);
    box->y1 = (int32_t)(((int64_t)b[3] + ((int64_t)1 << s) - 1) >> s);
    return box->x1 - box->x0 <= RAST__CS_DIM && box->y1 - box->y0 <= RAST__CS_DIM;
}

/* The piece from (f0, t0) to (f1, t1) (abscissae from column c's left,
 * ordinates from the row's top), sign s: its area right of it in cell c,
 * the whole height in every cell right of c (acc[c + 1] holds the rest,
 * for the running sum). */
RAST__HOT void rast__cs_add(int64_t *acc, int64_t c, int64_t f0, int64_t f1, int64_t t0, int64_t t1, int32_t s)
{
    const int64_t dt = t1 - t0, a = dt * (f0 + f1), whole = dt * (2 * RAST__CS_ONE);
    acc[c] += s > 0 ? whole - a : a - whole;
    acc[c + 1] += s > 0 ? a : -a;
}

/* floor(a / b), b > 0. */
static int64_t rast__cs_floor(int64_t a, int64_t b)
{
    int64_t q, r;
    rast__floordivmod(a, b, &q, &r);
    return q;
}

/* A stepper of floor(a + k q / d) for k = 0, 1, ... (d > 0): v, the
 * remainder rem over d (0 <= rem < d), the step's whole part and rest. */
typedef struct rast__cs_step {
    int64_t v, rem, q, qr, d;
} rast__cs_step;

/* v = a + floor(num / d), stepping by step / d. */
RAST__HOT void rast__cs_step_init(rast__cs_step *st, int64_t a, int64_t num, int64_t step, int64_t d)
{
    rast__floordivmod(num, d, &st->v, &st->rem);
    st->v += a;
    rast__floordivmod(step, d, &st->q, &st->qr);
    st->d = d;
}

RAST__HOT void rast__cs_step_next(rast__cs_step *st)
{
    st->v += st->q;
    st->rem += st->qr;
    if (st->rem >= st->d) {
        st->rem -= st->d;
        st->v++;
    }
}

/* The cells of one row that the pieces of one direction's edges have
 * written: lo .. hi, and hi + 1 (the rest of a piece's height; lo > hi:
 * none). */
typedef struct rast__cs_cols {
    int32_t lo, hi;
} rast__cs_cols;

/* Edge e into the rows of cells acc (a row every `stride` words, the
 * first the box's top): each row's piece split at the column lines it
 * crosses.  The abscissae at the row lines and the ordinates at the
 * column lines, floor(.) of their exact values, by two steppers (a
 * division or two an edge, not one a crossing).  s is e->s, a constant
 * in each of rast__cs_walk's two copies, with the steppers inlined
 * (GCC had kept rast__cs_step_init out of line: the loop family's walk
 * 1.5% fewer instructions in all). */
RAST__HOT void rast__cs_walk_s(int64_t *acc, int32_t stride, const rast__cs_edge *e, rast__cs_cols *cols,
                               const int32_t s)
{
    const int64_t adx = e->dx < 0 ? -e->dx : e->dx;
    int64_t r = e->y0 >> RAST__CS_K, xa = e->x0, ya = e->y0;
    /* the next column line the edge crosses, and its ordinate there */
    int64_t cx = (xa >> RAST__CS_K) + (e->dx > 0);
    rast__cs_step xr, ty = {0, 0, 0, 0, 1};
    int have_t = 0;
    rast__cs_step_init(&xr, e->x0, e->dx * (((r + 1) << RAST__CS_K) - e->y0), e->dx * RAST__CS_ONE, e->dy);
    for (;; r++) {
        const int64_t rt = r << RAST__CS_K, yb = e->y1 < rt + RAST__CS_ONE ? e->y1 : rt + RAST__CS_ONE;
        const int64_t xb = yb == e->y1 ? e->x1 : xr.v, cb = xb >> RAST__CS_K, tb = yb - rt;
        int64_t *row = acc + r * stride;
        const int64_t c0 = xa >> RAST__CS_K;
        int64_t c = c0, f = xa - (c << RAST__CS_K), t = ya - rt, tx;
        if (c != cb && !have_t) { /* the first column line crossed */
            rast__cs_step_init(&ty, e->y0, ((cx << RAST__CS_K) - e->x0) * (e->dx > 0 ? e->dy : -e->dy),
                                  RAST__CS_ONE * e->dy, adx);
            have_t = 1;
        }
        for (; c < cb; c++) { /* going right: the lines c + 1 .. cb */
            tx = ty.v - rt;
            if (tx > tb) tx = tb;
            if (tx < t) tx = t;
            rast__cs_add(row, c, f, RAST__CS_ONE, t, tx, s);
            t = tx;
            f = 0;
            rast__cs_step_next(&ty);
        }
        for (; c > cb; c--) { /* going left: the lines c .. cb + 1 */
            tx = ty.v - rt;
            if (tx > tb) tx = tb;
            if (tx < t) tx = t;
            rast__cs_add(row, c, f, 0, t, tx, s);
            t = tx;
            f = RAST__CS_ONE;
            rast__cs_step_next(&ty);
        }
        rast__cs_add(row, cb, f, xb - (cb << RAST__CS_K), t, tb, s);
        if (cols) {
            rast__cs_cols *k = &cols[2 * r + (s < 0)];
            const int32_t lo = (int32_t)(c0 < cb ? c0 : cb), hi = (int32_t)(c0 < cb ? cb : c0);
            k->lo = lo < k->lo ? lo : k->lo;
            k->hi = hi > k->hi ? hi : k->hi;
        }
        if (yb == e->y1) return;
        xa = xb;
        ya = yb;
        rast__cs_step_next(&xr);
    }
}

static void rast__cs_walk(int64_t *acc, int32_t stride, const rast__cs_edge *e, rast__cs_cols *cols)
{
    if (e->s > 0)
        rast__cs_walk_s(acc, stride, e, cols, 1);
    else
        rast__cs_walk_s(acc, stride, e, cols, -1);
}

/* Where a row's levels not 0 lie: bit c for column c of the box
 * (RAST__CS_DIM <= 64), set without a branch (a scan for the ends after
 * the row mispredicted: 7% of the call's time; a count and the ends kept
 * a column cost ~9 instructions, a bit 4; "area" and "accumulate" take
 * them from the row's levels after, rast__cs_runs); the hand-on finds the
 * first, the end of its run and whether it is the only one from them. */
static inline uint64_t rast__cs_bit(int32_t c, unsigned l)
{
    return (uint64_t)(l != 0) << c;
}

/* The level of running sum v, floor(255 v + 1/2), and in *near bit
 * 2K + 1 set when its fraction lies within win of a tie
 * (0 or 1), without a branch: the fraction x of num - win - 1 is at least
 * FULL - 2 win - 1 exactly when x + 2 win + 1 (< 2 FULL) reaches FULL,
 * so the bit of the sum is OR'ed in (2 instructions, not a compare and
 * its flag's 4).  A pixel outside (a = 0) or whole
 * (FULL <= a < FULL + 16 2^(K + 4): at most RAST__CS_EDGES edges in its
 * row, each off by less than 2^(K + 4)) has the fraction 1/2 (2^(2K))
 * plus less than 2^(K + 16), never within win (< 2^(K + 17)) of 0 or 1:
 * no tie; its level is 0, or 255: 255 a + 1/2 < 255 FULL + 2^(K + 28)
 * + FULL / 2 < 256 FULL, so the level is never 256 (no min(., 255)).
 * v is the pixel's area a, not -a: the edges' signs are minus the ring's
 * turn times their direction (rast__cov_small; entry/coverage.c,
 * rast__cov_convex), so the running sums are a inside, with no |v| taken
 * (3 instructions a column, ~210 a call of the loop family); a sum whose
 * exact value is 0 may come out negative, by less than 16 2^(K + 4):
 * 255 v + FULL / 2 (modulo 2^64) is then still in (0, FULL / 2), level 0,
 * its fraction 1/2 less than 2^(K + 16), not within win of a tie. */
static inline unsigned rast__cs_level(int64_t v, uint64_t win, uint64_t *near)
{
    const uint64_t num = (uint64_t)v * 255 + RAST__CS_FULL / 2;
    *near |= ((num - win - 1) & (RAST__CS_FULL - 1)) + 2 * win + 1;
    return (unsigned)(num >> (2 * RAST__CS_K + 1));
}

/* u[r] for the box's rows r < h of levels lv (w a row, w <= RAST__CS_DIM
 * <= 32): bit c set where level c is not 0.  With SSE2 from 16 levels a
 * step (a compare and a mask: ~8 instructions a row, where a bit set as
 * each level is made was 5 a column); lv is readable and written (0) 16
 * bytes past its last row. */
static void rast__cs_runs(const unsigned char *lv, int32_t w, int32_t h, uint64_t *u)
{
    int32_t r;
#ifdef RAST__CS_SSE2
    const __m128i z = _mm_setzero_si128();
    const uint32_t keep = (uint32_t)(((uint64_t)1 << w) - 1);
    for (r = 0; r < h; r++, lv += w) {
        uint32_t zero = (uint32_t)_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128((const __m128i *)(const void *)lv), z));
        if (w > 16)
            zero |= (uint32_t)_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128((const __m128i *)(const void *)(lv + 16)), z))
                    << 16;
        u[r] = ~zero & keep;
    }
#else
    int32_t c;
    for (r = 0; r < h; r++, lv += w) {
        uint64_t run = 0;
        for (c = 0; c < w; c++) run |= rast__cs_bit(c, lv[c]);
        u[r] = run;
    }
#endif
}

/* p[0 .. n) = l, n > 0, by words of 8 bytes: up to 7 more bytes written
 * (lv's columns further right, written after, or its 8 spare bytes). */
static inline void rast__cs_fill(unsigned char *p, int32_t n, unsigned l)
{
    const uint64_t word = (uint64_t)l * 0x0101010101010101u;
    int32_t i;
    for (i = 0; i < n; i += 8) memcpy(p + i, &word, 8);
}

/* The box's levels lv[] (a row of its width after another), every one
 * decided, and where each row's lie (u[]): its rows inside o's clip
 * handed on.  A row whose levels not 0 are one run (none 0 between its
 * first and last) too short for a stretch of RAST__COV_FULL_MIN 255s goes
 * straight to the painter's levels entry, the one call rast__cov_row_done
 * makes of it, without its scan (~150 instructions a row of the loop
 * family's, a third of the hand-on, issue 33); any other, through it. */
static void rast__cs_hand_on(const unsigned char *lv, const uint64_t *u, const rast_rect *box,
                             const rast__cov_out *o)
{
    const int32_t w = box->x1 - box->x0;
    const int32_t x0 = box->x0 > o->clip.x0 ? box->x0 : o->clip.x0;
    const int32_t x1 = box->x1 < o->clip.x1 ? box->x1 : o->clip.x1;
    const int32_t y0 = box->y0 > o->clip.y0 ? box->y0 : o->clip.y0;
    const int32_t y1 = box->y1 < o->clip.y1 ? box->y1 : o->clip.y1;
    const rast__painter *p = o->paint;
    rast__cov_out row = *o;
    int32_t y;
    row.clip.x0 = x0;
    row.clip.x1 = x1;
    for (y = y0; x0 < x1 && y < y1; y++) {
        const uint64_t bits = u[y - box->y0];
        const unsigned char *l = lv + (y - box->y0) * w;
        uint64_t run;
        int32_t a, b, lo, n;
        if (!bits) continue;
        lo = (int32_t)rast__ctz64(bits);
        run = bits >> lo;
        n = (int32_t)rast__ctz64(~run); /* (the run's length: under 64) */
        a = box->x0 + lo > x0 ? box->x0 + lo : x0;
        b = box->x0 + lo + n < x1 ? box->x0 + lo + n : x1;
        if (!(run >> n) && (!p->full || b - a < RAST__COV_FULL_MIN)) {
            if (a < b) p->levels(p->user, y, a, b, l + (a - box->x0));
        } else {
            row.base = (unsigned char *)l + (x0 - box->x0);
            rast__cov_row_done(&row, y);
        }
    }
}

/* The solid gray8 painter's fast kind (rast__painter::bytes: the
 * target's bytes, stride and value) takes the box's levels lv whole, its
 * rows inside o's clip blended at once (rast__gray8_blend_rows: a level 0
 * leaves a pixel as it is, 255 sets the value, as the runs' levels and
 * full entries do), no run looked for and no painter's call a row: the
 * hand-on and the rows' calls were ~1,000 instructions of the loop
 * family's ~6,800 a call (issue 33).  0 for any other painter. */
static int rast__cs_direct(const unsigned char *lv, const rast_rect *box, const rast__cov_out *o)
{
    const rast__painter *p = o->paint;
    const int32_t w = box->x1 - box->x0;
    const int32_t x0 = box->x0 > o->clip.x0 ? box->x0 : o->clip.x0;
    const int32_t x1 = box->x1 < o->clip.x1 ? box->x1 : o->clip.x1;
    const int32_t y0 = box->y0 > o->clip.y0 ? box->y0 : o->clip.y0;
    const int32_t y1 = box->y1 < o->clip.y1 ? box->y1 : o->clip.y1;
    if (!p->bytes) return 0;
    if (x0 < x1 && y0 < y1)
        rast__gray8_blend_rows(p->bytes, p->stride, p->value, x0, x1, y0, y1,
                               lv + (ptrdiff_t)(y0 - box->y0) * w + (x0 - box->x0), w);
    return 1;
}

int rast__cov_small(const rast_polygon *poly, int32_t s, int32_t turn, const rast__cov_out *o,
                    const rast_rect *box)
{
    rast__cs_edge e[RAST__CS_EDGES];
    /* (+ 16: rast__cs_fill's last word, rast__cs_runs's last read) */
    unsigned char lv[RAST__CS_DIM * RAST__CS_DIM + 16];
    int64_t acc[RAST__CS_DIM * (RAST__CS_DIM + 2)];
    rast__cs_cols cols[2 * RAST__CS_DIM];
    int32_t m[RAST__CS_DIM + 1]; /* the edges a row meets, as differences from the row above */
    uint64_t runs[RAST__CS_DIM];
    const rast_point *p = poly->points;
    const uint32_t n = poly->ring_sizes[0];
    const int32_t w = box->x1 - box->x0, h = box->y1 - box->y0, sh = RAST__CS_K - s;
    const int64_t bx = (int64_t)box->x0 * ((int64_t)1 << s), by = (int64_t)box->y0 * ((int64_t)1 << s);
    const int stretches = w > RAST__CS_NARROW;
    uint32_t i, ne = 0;
    int32_t r, c, mr;
    if (w <= 0 || h <= 0) return 1; /* no area: nothing to paint */
    for (i = 0; i < n; i++) { /* the edges not horizontal, top end first */
        const rast_point a = p[i], b = p[i + 1 < n ? i + 1 : 0];
        const int down = a.y < b.y;
        const rast_point t = down ? a : b, u = down ? b : a;
        if (a.y == b.y) continue;
        e[ne].x0 = (int64_t)((uint64_t)(t.x - bx) << sh);
        e[ne].y0 = (int64_t)((uint64_t)(t.y - by) << sh);
        e[ne].x1 = (int64_t)((uint64_t)(u.x - bx) << sh);
        e[ne].y1 = (int64_t)((uint64_t)(u.y - by) << sh);
        e[ne].dx = e[ne].x1 - e[ne].x0;
        e[ne].dy = e[ne].y1 - e[ne].y0;
        e[ne].s = down ? -turn : turn; /* (the running sums inside: + the area) */
        ne++;
    }
    memset(acc, 0, (size_t)h * (size_t)(w + 2) * sizeof(acc[0]));
    memset(m, 0, (size_t)(h + 1) * sizeof(m[0]));
    for (r = 0; stretches && r < 2 * h; r++) {
        cols[r].lo = RAST__CS_DIM + 2;
        cols[r].hi = -1;
    }
    for (i = 0; i < ne; i++) {
        /* its rows: y0 >> K to the last r with r 2^K < y1 (0 <= y0 < y1 <= h 2^K) */
        rast__cs_walk(acc, w + 2, &e[i], stretches ? cols : NULL);
        m[e[i].y0 >> RAST__CS_K]++;
        m[((e[i].y1 - 1) >> RAST__CS_K) + 1]--;
    }
    for (r = 0, mr = 0; r < h; r++) {
        const int64_t *cells = acc + r * (w + 2);
        unsigned char *lr = lv + r * w;
        /* the window round a tie: M times the row's edges' bound, and the
         * engines' own error (below 2^-50 pixel: 2^3 units) */
        const uint64_t win = 255 * (uint64_t)(mr += m[r]) * ((uint64_t)1 << (RAST__CS_K + 4)) + 4096;
        int64_t v = 0;
        uint64_t near = 0;
        if (!stretches) { /* a narrow box: column by column */
            for (c = 0; c < w; c++) {
                v += cells[c];
                lr[c] = (unsigned char)rast__cs_level(v, win, &near);
            }
        } else {
            /* The cells each direction's pieces wrote, first the one
             * further left, as one stretch when they meet: every other
             * cell of the row is 0, so the running sum, the level and the
             * tie test are the same on each column between stretches,
             * made once. */
            const rast__cs_cols *k = &cols[2 * r];
            int32_t seg[4], ns, j;
            c = k[1].lo < k[0].lo;
            seg[0] = k[c].lo;
            seg[1] = k[c].hi + 2;
            seg[2] = k[1 - c].lo;
            seg[3] = k[1 - c].hi + 2;
            if (seg[2] <= seg[1]) {
                seg[1] = seg[3] > seg[1] ? seg[3] : seg[1];
                ns = 2;
            } else {
                ns = 4;
            }
            for (c = 0, j = 0; j <= ns; j += 2) {
                const int32_t s0 = j < ns && seg[j] < w ? seg[j] : w, s1 = j < ns && seg[j + 1] < w ? seg[j + 1] : w;
                if (c < s0) { /* columns c .. s0 - 1: v */
                    rast__cs_fill(lr + c, s0 - c, rast__cs_level(v, win, &near));
                    c = s0;
                }
                for (; c < s1; c++) {
                    v += cells[c];
                    lr[c] = (unsigned char)rast__cs_level(v, win, &near);
                }
            }
        }
        if (near >> (2 * RAST__CS_K + 1)) return 0;
    }
    if (rast__cs_direct(lv, box, o)) return 1;
    memset(lv + h * w, 0, 16);
    rast__cs_runs(lv, w, h, runs);
    rast__cs_hand_on(lv, runs, box, o);
    return 1;
}

/* The uint8 level of c samples inside of k x k, floor(255 c / k^2 + 1/2)
 * (docs/coverage.md; what rast__cov_level gives for c 2^(62 - 2 kb)):
 * floor((255 c + 8) / 16) for "ss4", floor((255 c + 2) / 4) for "ss2".
 * Constant tables: made by rast__cov_level at each call they were ~270
 * instructions of the loop family's ~6,000 a call. */
static const unsigned char rast__cs_level4[17] = {0,   16,  32,  48,  64,  80,  96,  112, 128,
                                                  143, 159, 175, 191, 207, 223, 239, 255};
static const unsigned char rast__cs_level2[5] = {0, 64, 128, 191, 255};

/* A pixel row's levels from its row of differences d[] over the fine
 * columns (k = 2 or 4 a pixel): the level of the magnitude of each
 * pixel's k running sums; in *u the bits of the levels not 0, unless u
 * is NULL (rast__cs_direct's painter needs none: a constant where this
 * is inlined, so the bits' 4 instructions a column are gone there). */
static inline void rast__cs_counts(const signed char *d, int32_t w, int32_t k, const unsigned char *level,
                                      unsigned char *lv, uint64_t *u)
{
    uint64_t run = 0;
    int32_t v = 0, c, sum;
    for (c = 0; c < w; c++, d += k) {
        /* the k running sums: k v plus each difference times the sums it reaches */
        if (k == 4) {
            sum = 4 * v + 4 * d[0] + 3 * d[1] + 2 * d[2] + d[3];
            v += d[0] + d[1] + d[2] + d[3];
        } else {
            sum = 2 * v + 2 * d[0] + d[1];
            v += d[0] + d[1];
        }
        lv[c] = level[sum < 0 ? -sum : sum];
        if (u) run |= rast__cs_bit(c, lv[c]);
    }
    if (u) *u = run;
}

/* "ss2" and "ss4" (k = 2^kb) of the same rings: the binary rule on the
 * grid k times finer (coverage_ss.c; docs/semantics.md: a sample row y is
 * crossed by the edges with y0 <= y < y1, a sample is inside when a
 * crossing lies at or left of it and the other right of it), counted per
 * pixel.  A convex ring's sample row has no crossing or two, the left one
 * of one direction all down the ring and the right one of the other; so
 * one row of differences per pixel row, each crossing's direction added
 * at the first sample column at or right of it, summed along gives that
 * direction times the samples inside each fine column, and the pixel's
 * count is the magnitude of its k columns' sum.  The samples sit on the
 * fixed grid when S > kb: fine column I's at I 2^(S - kb) (+ 2^(S - kb - 1)
 * for centres).  Each edge's first sample column on its sample rows,
 * ceil((x - offset) / step) of its exact abscissa x there, by a stepper. */
void rast__cov_small_ss(const rast_polygon *poly, int32_t s, int32_t kb, rast_sample sample,
                        const rast__cov_out *o, const rast_rect *box)
{
    signed char d[RAST__CS_DIM * (RAST__CS_DIM * 4 + 2)];
    unsigned char lv[RAST__CS_DIM * RAST__CS_DIM];
    uint64_t u[RAST__CS_DIM];
    const rast_point *p = poly->points;
    const uint32_t n = poly->ring_sizes[0];
    const int32_t w = box->x1 - box->x0, h = box->y1 - box->y0, k = 1 << kb, fw = w * k + 2;
    const int64_t st = (int64_t)1 << (s - kb), off = sample == RAST_SAMPLE_CENTER ? st / 2 : 0;
    const int64_t bx = (int64_t)box->x0 * ((int64_t)1 << s), by = (int64_t)box->y0 * ((int64_t)1 << s);
    const unsigned char *level = kb == 2 ? rast__cs_level4 : rast__cs_level2;
    uint32_t i;
    int32_t r;
    if (w <= 0 || h <= 0) return;
    memset(d, 0, (size_t)h * (size_t)fw);
    for (i = 0; i < n; i++) {
        const rast_point a = p[i], b = p[i + 1 < n ? i + 1 : 0];
        const int down = a.y < b.y;
        const int64_t x0 = (down ? a.x : b.x) - bx, y0 = (down ? a.y : b.y) - by;
        const int64_t dx = (down ? b.x : a.x) - bx - x0, dy = (down ? b.y : a.y) - by - y0;
        const signed char sg = down ? 1 : -1;
        int64_t jr, j1;
        rast__cs_step ix;
        if (a.y == b.y) continue;
        /* its sample rows: J st + off in [y0, y0 + dy) */
        jr = -rast__cs_floor(-(y0 - off), st);
        j1 = -rast__cs_floor(-(y0 + dy - off), st);
        if (jr >= j1) continue;
        /* the first sample column at or right of x = x0 + dx (y - y0) / dy:
         * ceil((x0 dy + dx (y - y0) - off dy) / (st dy)) */
        rast__cs_step_init(&ix, 0, x0 * dy + dx * (jr * st + off - y0) - off * dy + st * dy - 1, dx * st, st * dy);
        for (; jr < j1; jr++) {
            int64_t col = ix.v;
            if (col < 0) col = 0;
            if (col > w * k) col = w * k;
            d[(jr >> kb) * fw + col] = (signed char)(d[(jr >> kb) * fw + col] + sg);
            rast__cs_step_next(&ix);
        }
    }
    if (o->paint->bytes) { /* (rast__cs_direct's painter) */
        for (r = 0; r < h; r++) {
            if (kb == 2)
                rast__cs_counts(d + r * fw, w, 4, level, lv + r * w, NULL);
            else
                rast__cs_counts(d + r * fw, w, 2, level, lv + r * w, NULL);
        }
        (void)rast__cs_direct(lv, box, o);
        return;
    }
    for (r = 0; r < h; r++) {
        if (kb == 2)
            rast__cs_counts(d + r * fw, w, 4, level, lv + r * w, &u[r]);
        else
            rast__cs_counts(d + r * fw, w, 2, level, lv + r * w, &u[r]);
    }
    rast__cs_hand_on(lv, u, box, o);
}

#else
typedef int rast__cov_small_unused; /* (ISO C: a translation unit declares something) */
#endif
