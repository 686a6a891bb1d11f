/*
 * coco.c - pycocotools' polygon rule (rleFrPoly in cocoapi's maskApi.c),
 * in integers, as a named mode of its own: RLE toggles and column-major
 * run-length counts (rastrum.h, "COCO masks").
 *
 * The rule, as pycocotools computes it (facts, rewritten here):
 *  1. vertices are upsampled by 5 and rounded, X = (int)(5x + 0.5) (the
 *     caller does this in double, as pycocotools does; these functions get
 *     the integers);
 *  2. each edge A -> B is walked one unit at a time along its major axis
 *     (|dx| >= |dy|: x, else y), from the endpoint with the smaller major
 *     coordinate (m0 its minor coordinate, d the major length, delta the
 *     signed minor difference), the minor coordinate at step t being
 *     trunc(m0 + s*t + 0.5) with s = delta/d, all in double;
 *  3. where the walk steps from x = 5c + 2 to 5c + 3 (either way), column c
 *     (0 <= c < width) gets a toggle at row ceil((yd - 2)/5) clamped to
 *     0..height, yd the smaller y of the two points;
 *  4. a pixel is inside iff an odd number of its column's toggles are at or
 *     above its row (column-major positions c*height + row; a toggle at row
 *     height ends the column).
 *
 * Exactness.  The minor coordinate is the exact floor((2 m0 d + 2 delta t
 * + d) / (2d)) except where m0 + delta t / d + 1/2 is an integer E (a tie):
 * for coordinates within RAST_COCO_COORD_MAX the double error is below
 * 2^-26.4 (|q| = |delta t / d| <= d <= 2^24, |m0| < 2^23: s, s*t, the sum
 * and the + 0.5 each round once, (|q| 2^-52 + 2 * 2^25 * 2^-53) < 2^-26.4)
 * while a non-integer E is at least 1/(2d) >= 2^-25 from every integer.
 * At a tie the double result is E or just below it, so this file computes
 * it as IEEE binary64 does (round to nearest, ties to even) in 128-bit
 * fixed point: rast__coco_tie.  Negative minor coordinates (where trunc
 * and floor differ) never matter: they only ever meet toggles at row 0
 * or columns below 0.  The walk's steps are never walked one by one: the
 * column crossings are solved for directly.
 */

#include "../base/internal.h"

/* ---- IEEE binary64 at a tie, in 128-bit fixed point ------------------------ */

/* Fixed point with COCO_F fraction bits: values here stay below 2^26 in
 * magnitude and their doubles' last bits at or above 2^-77. */
#define COCO_F 80

typedef struct coco_fix {
    uint64_t hi, lo; /* magnitude * 2^COCO_F */
    int neg;
} coco_fix;

static int coco_msb(uint64_t hi, uint64_t lo)
{
    int p = 0;
    uint64_t v = hi ? hi : lo;
    while (v >>= 1) p++;
    return hi ? p + 64 : p;
}

/* Round the magnitude to 53 significant bits, to nearest, ties to even;
 * `sticky` says that non-zero bits follow below the fixed point's last. */
static void coco_round53(coco_fix *x, int sticky)
{
    int p, sh;
    uint64_t lowhi, lowlo, halfhi, halflo, qhi, qlo;
    int cmp;
    if (!x->hi && !x->lo) return;
    p = coco_msb(x->hi, x->lo);
    if (p <= 52) return;
    sh = p - 52; /* 1 .. 127 */
    /* low = x mod 2^sh, half = 2^(sh - 1), q = x >> sh */
    if (sh >= 64) {
        lowhi = sh == 64 ? 0 : x->hi & ((~(uint64_t)0) >> (128 - sh));
        lowlo = x->lo;
        qhi = 0;
        qlo = sh == 64 ? x->hi : x->hi >> (sh - 64);
    } else {
        lowhi = 0;
        lowlo = x->lo & ((~(uint64_t)0) >> (64 - sh));
        qlo = (x->lo >> sh) | (x->hi << (64 - sh));
        qhi = x->hi >> sh;
    }
    if (sh - 1 >= 64) {
        halfhi = (uint64_t)1 << (sh - 1 - 64);
        halflo = 0;
    } else {
        halfhi = 0;
        halflo = (uint64_t)1 << (sh - 1);
    }
    cmp = lowhi != halfhi ? (lowhi > halfhi ? 1 : -1) : lowlo != halflo ? (lowlo > halflo ? 1 : -1) : 0;
    if (cmp == 0 && sticky) cmp = 1;
    if (cmp > 0 || (cmp == 0 && (qlo & 1))) {
        qlo++;
        if (!qlo) qhi++;
    }
    /* back to the fixed point: q << sh */
    if (sh >= 64) {
        x->hi = qlo << (sh - 64);
        x->lo = 0;
    } else {
        x->hi = (qhi << sh) | (qlo >> (64 - sh));
        x->lo = qlo << sh;
    }
}

/* Signed sum (exact; magnitudes stay far below 2^127). */
static coco_fix coco_add(coco_fix a, coco_fix b)
{
    coco_fix r;
    if (a.neg == b.neg) {
        r.lo = a.lo + b.lo;
        r.hi = a.hi + b.hi + (r.lo < a.lo);
        r.neg = a.neg;
    } else {
        int a_big = a.hi != b.hi ? a.hi > b.hi : a.lo >= b.lo;
        coco_fix big = a_big ? a : b, small = a_big ? b : a;
        r.lo = big.lo - small.lo;
        r.hi = big.hi - small.hi - (big.lo < small.lo);
        r.neg = big.neg;
    }
    if (!r.hi && !r.lo) r.neg = 0;
    return r;
}

static coco_fix coco_int(int64_t v)
{
    coco_fix r;
    uint64_t m = v < 0 ? 0 - (uint64_t)v : (uint64_t)v; /* < 2^26 */
    r.hi = m << (COCO_F - 64);
    r.lo = 0;
    r.neg = v < 0;
    return r;
}

/* floor(double(double(m0 + double(double(delta / d) * t)) + 0.5)) as x86-64
 * computes it (no fused multiply-add), for |delta| <= d < 2^25,
 * 0 <= t <= d, |m0| < 2^23. */
static int64_t rast__coco_tie(int64_t m0, int64_t delta, int64_t d, int64_t t)
{
    coco_fix s, p, half;
    uint64_t a = delta < 0 ? (uint64_t)-delta : (uint64_t)delta, r = 0, limb[4], q[4], cur;
    int i;
    /* s = |delta| * 2^80 / d by 32-bit limbs, and its sticky bit */
    limb[0] = (a << 16) >> 32; /* bits 96..127 of |delta| << 80 */
    limb[1] = (a << 16) & 0xFFFFFFFFu;
    limb[2] = 0;
    limb[3] = 0;
    for (i = 0; i < 4; i++) {
        cur = (r << 32) | limb[i];
        q[i] = cur / (uint64_t)d;
        r = cur % (uint64_t)d;
    }
    s.hi = (q[0] << 32) | q[1];
    s.lo = (q[2] << 32) | q[3];
    s.neg = delta < 0;
    coco_round53(&s, r != 0);
    /* p = s * t exactly (< 2^106), then rounded */
    {
        uint64_t ut = (uint64_t)t, l0 = (s.lo & 0xFFFFFFFFu) * ut, l1 = (s.lo >> 32) * ut;
        uint64_t lo = l0 + (l1 << 32), carry = lo < l0;
        p.lo = lo;
        p.hi = s.hi * ut + (l1 >> 32) + carry;
        p.neg = s.neg && (p.hi || p.lo);
    }
    coco_round53(&p, 0);
    p = coco_add(coco_int(m0), p);
    coco_round53(&p, 0);
    half.hi = (uint64_t)1 << (COCO_F - 1 - 64);
    half.lo = 0;
    half.neg = 0;
    p = coco_add(p, half);
    coco_round53(&p, 0);
    {
        /* floor of the fixed point value */
        uint64_t ip = p.hi >> (COCO_F - 64);
        int frac = (p.hi & ((~(uint64_t)0) >> (128 - COCO_F))) != 0 || p.lo != 0;
        return p.neg ? -(int64_t)ip - frac : (int64_t)ip;
    }
}

/* The walk's minor coordinate at step t (see the file comment). */
static int64_t coco_minor(int64_t m0, int64_t delta, int64_t d, int64_t t)
{
    int64_t n = 2 * delta * t + d, q = rast__floordiv(n, 2 * d);
    if (n - q * 2 * d == 0) return rast__coco_tie(m0, delta, d, t);
    return m0 + q;
}

static uint32_t coco_toggle_row(int64_t yd, int32_t height)
{
    int64_t y = rast__floordiv(yd + 2, 5); /* ceil((yd - 2) / 5) */
    return (uint32_t)(y < 0 ? 0 : y > height ? height : y);
}

/* Columns c in 0..width-1 with lo <= 5c + 2 < hi, as [*c0, *c1). */
static void coco_columns(int64_t lo, int64_t hi, int32_t width, int64_t *c0, int64_t *c1)
{
    int64_t a = rast__ceildiv(lo - 2, 5), b = rast__ceildiv(hi - 2, 5);
    *c0 = a < 0 ? 0 : a;
    /* width 0: pycocotools' unsigned width - 1 wraps, and every column
     * from 0 on takes toggles */
    *c1 = width && b > width ? width : b;
    if (*c1 < *c0) *c1 = *c0;
}

/* One edge as the walk sees it: x-major (`xmajor`) from (xs, ys) with
 * minor difference `delta` over `d` steps, or y-major likewise; toggles in
 * columns [c0, c1). */
typedef struct coco_edge {
    int xmajor;
    int64_t xs, ys, delta, d, c0, c1;
} coco_edge;

/* The edge from a to b; 0 when it makes no toggle (dx = dy = 0). */
static int coco_edge_of(rast_point a, rast_point b, int32_t width, coco_edge *e)
{
    int64_t dx = (int64_t)b.x - a.x, dy = (int64_t)b.y - a.y;
    int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    e->xmajor = adx >= ady;
    if (e->xmajor) {
        /* x-major: from the smaller x */
        if (!adx) return 0;
        e->xs = dx >= 0 ? a.x : b.x;
        e->ys = dx >= 0 ? a.y : b.y;
        e->delta = dx >= 0 ? dy : -dy;
        e->d = adx;
        coco_columns(e->xs, e->xs + adx, width, &e->c0, &e->c1);
    } else {
        /* y-major: from the smaller y */
        int64_t lo, hi;
        e->xs = dy >= 0 ? a.x : b.x;
        e->ys = dy >= 0 ? a.y : b.y;
        e->delta = dy >= 0 ? dx : -dx;
        e->d = ady;
        lo = e->delta < 0 ? e->xs + e->delta : e->xs;
        hi = e->delta < 0 ? e->xs : e->xs + e->delta;
        coco_columns(lo, hi, width, &e->c0, &e->c1);
    }
    return e->c1 > e->c0;
}

/* The toggle's row in column c (c0 <= c < c1). */
static uint32_t coco_edge_row(const coco_edge *e, int64_t c, int32_t height)
{
    if (e->xmajor) {
        /* v = minor at t and t + 1 */
        int64_t t = 5 * c + 2 - e->xs, v0 = coco_minor(e->ys, e->delta, e->d, t),
                v1 = coco_minor(e->ys, e->delta, e->d, t + 1);
        return coco_toggle_row(v0 < v1 ? v0 : v1, height);
    } else {
        /* u = minor(t) moves by at most one per step, monotonically; find
         * the step (t, t + 1) where it passes between 5c + 2 and 5c + 3 */
        int64_t xs = e->xs, delta = e->delta, d = e->d;
        int64_t u = 5 * c + 3, k = 2 * d * (u - xs) - d, t;
        /* exact minor(t) >= u  iff  2 delta t >= k */
        if (delta > 0) {
            t = rast__ceildiv(k, 2 * delta); /* first t with exact >= u */
            if (2 * delta * t == k && coco_minor(xs, delta, d, t) < u) t++;
        } else {
            /* first t with exact minor(t) < u: 2 delta t < k */
            int64_t f = -delta;
            t = rast__floordiv(-k, 2 * f) + 1;
            if (-k == 2 * f * (t - 1) && coco_minor(xs, delta, d, t - 1) < u) t--;
        }
        return coco_toggle_row(e->ys + t - 1, height);
    }
}

rast_status rast_coco_ring_toggles_in(const rast_point *points, uint32_t npoints, int32_t height,
                                      int32_t width, uint64_t first, uint64_t end, uint32_t *toggles,
                                      size_t capacity, size_t *count)
{
    /* columns beyond any the walk reaches (|X| < 2^23: c < 2^21) */
    const uint64_t far = (uint64_t)1 << 40;
    uint64_t h = (uint64_t)(height < 0 ? 0 : height);
    int64_t ca, cb; /* columns that can hold a position in [first, end) */
    uint32_t j;
    size_t n = 0;
    int pass;
    if (!count || (npoints && !points)) return RAST_E_NULL;
    if (height < 0 || width < 0 || (uint64_t)height * (uint64_t)width > 0xFFFFFFFFu)
        return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    for (j = 0; j < npoints; j++)
        if (points[j].x < -RAST_COCO_COORD_MAX || points[j].x > RAST_COCO_COORD_MAX ||
            points[j].y < -RAST_COCO_COORD_MAX || points[j].y > RAST_COCO_COORD_MAX)
            return RAST_E_RANGE;
    if (end <= first) {
        ca = cb = 0;
    } else if (!h) {
        /* every position is 0 */
        ca = 0;
        cb = first ? 0 : (int64_t)far;
    } else {
        /* column c holds positions c h .. c h + h: the ones past ca and
         * before cb - 1 lie wholly inside [first, end) */
        uint64_t a = first / h + (first % h != 0), b = (end - 1) / h + 1;
        ca = (int64_t)(a > far ? far : a) - 1;
        cb = (int64_t)(b > far ? far : b);
    }
    /* Pass 0 counts, pass 1 writes (when they fit). */
    for (pass = 0; pass < 2; pass++) {
        for (j = 0; j < npoints; j++) {
            coco_edge e;
            int64_t c, lo, hi;
            if (!coco_edge_of(points[j], points[j + 1 < npoints ? j + 1 : 0], width, &e)) continue;
            lo = e.c0 > ca ? e.c0 : ca;
            hi = e.c1 < cb ? e.c1 : cb;
            if (lo >= hi) continue;
            if (!pass) {
                /* the columns at the ends may hold their toggle outside */
                n += (size_t)(hi - lo);
                for (c = lo; c < hi; c = c == lo && hi - 1 > lo ? hi - 1 : hi) {
                    uint64_t pos;
                    if (c != ca && c != cb - 1) continue;
                    pos = (uint64_t)c * h + coco_edge_row(&e, c, height);
                    if (pos < first || pos >= end) n--;
                }
                continue;
            }
            if (e.xmajor) {
                /* coco_edge_row stepped: t = 5c + 2 - xs grows by 5 a
                 * column, the numerators 2 delta t + d (at t and t + 1) by
                 * 10 delta; quotients and remainders by 2d kept without a
                 * division (a remainder of 0 is a tie, taken exactly) */
                int64_t d2 = 2 * e.d, t = 5 * lo + 2 - e.xs, q0, r0, q1, r1, a, b;
                rast__floordivmod(2 * e.delta * t + e.d, d2, &q0, &r0);
                rast__floordivmod(2 * e.delta * (t + 1) + e.d, d2, &q1, &r1);
                rast__floordivmod(10 * e.delta, d2, &a, &b);
                for (c = lo; c < hi; c++, t += 5) {
                    int64_t v0 = r0 ? e.ys + q0 : rast__coco_tie(e.ys, e.delta, e.d, t);
                    int64_t v1 = r1 ? e.ys + q1 : rast__coco_tie(e.ys, e.delta, e.d, t + 1);
                    uint64_t pos = (uint64_t)c * h + coco_toggle_row(v0 < v1 ? v0 : v1, height);
                    if (pos >= first && pos < end) toggles[n++] = (uint32_t)pos;
                    q0 += a;
                    r0 += b;
                    if (r0 >= d2) {
                        r0 -= d2;
                        q0++;
                    }
                    q1 += a;
                    r1 += b;
                    if (r1 >= d2) {
                        r1 -= d2;
                        q1++;
                    }
                }
                continue;
            }
            for (c = lo; c < hi; c++) {
                uint64_t pos = (uint64_t)c * h + coco_edge_row(&e, c, height);
                /* pycocotools' uint32 position (it wraps when width is 0) */
                if (pos >= first && pos < end) toggles[n++] = (uint32_t)pos;
            }
        }
        if (!pass) {
            *count = n;
            if (n > capacity) return RAST_E_SCRATCH;
            if (n && !toggles) return RAST_E_NULL;
            n = 0;
        }
    }
    return RAST_OK;
}

rast_status rast_coco_ring_toggles(const rast_point *points, uint32_t npoints, int32_t height,
                                   int32_t width, uint32_t *toggles, size_t capacity,
                                   size_t *count)
{
    return rast_coco_ring_toggles_in(points, npoints, height, width, 0, ~(uint64_t)0, toggles,
                                     capacity, count);
}

/* Insertion sort: a few toggles. */
static void coco_isort(uint32_t *v, size_t count)
{
    size_t i;
    for (i = 1; i < count; i++) {
        uint32_t x = v[i];
        size_t k = i;
        while (k && v[k - 1] > x) {
            v[k] = v[k - 1];
            k--;
        }
        v[k] = x;
    }
}

rast_status rast_coco_rle(uint32_t *toggles, size_t count, uint32_t total, uint32_t *scratch,
                          uint32_t *counts, size_t *ncounts)
{
    size_t i, m = 0;
    const uint32_t prev = 0;
    if (!ncounts || !counts || (count && (!toggles || !scratch))) return RAST_E_NULL;
    if (count) {
        size_t h[256], k;
        uint32_t *src = toggles, *dst = scratch, *t;
        int shift;
        if (count < 48) {
            coco_isort(toggles, count);
        } else {
            /* by 8-bit digits, least significant first, between the two
             * buffers (a digit that all share moves nothing) */
            for (shift = 0; shift < 32; shift += 8) {
                size_t sum = 0;
                memset(h, 0, sizeof h);
                for (k = 0; k < count; k++) h[(src[k] >> shift) & 255]++;
                if (h[(src[0] >> shift) & 255] == count) continue;
                for (k = 0; k < 256; k++) {
                    size_t c = h[k];
                    h[k] = sum;
                    sum += c;
                }
                for (k = 0; k < count; k++) dst[h[(src[k] >> shift) & 255]++] = src[k];
                t = src;
                src = dst;
                dst = t;
            }
            toggles = src;
        }
    }
    /* pycocotools' runs: the differences of the sorted positions and
     * `total` (uint32), a difference of 0 joining the runs around it.
     * With every position <= total (width > 0) these are the runs of the
     * positions of odd multiplicity; with width 0 they are pycocotools'
     * counts past the empty mask. */
    {
        size_t j = 0, k = count + 1;
        int put = 0; /* total taken */
        uint32_t p = 0, a0;
        /* the j-th value of the sorted toggles with total merged in */
#define COCO_NEXT(out)                                                        \
    do {                                                                      \
        if (!put && (i >= count || toggles[i] > total)) {                     \
            (out) = total;                                                    \
            put = 1;                                                          \
        } else {                                                              \
            (out) = toggles[i++];                                             \
        }                                                                     \
    } while (0)
        i = 0;
        COCO_NEXT(a0);
        counts[m++] = a0 - prev;
        p = a0;
        for (j = 1; j < k;) {
            uint32_t v, d;
            COCO_NEXT(v);
            d = v - p;
            p = v;
            j++;
            if (d > 0) {
                counts[m++] = d;
            } else if (j < k) {
                COCO_NEXT(v);
                counts[m - 1] += v - p;
                p = v;
                j++;
            }
        }
#undef COCO_NEXT
    }
    *ncounts = m;
    return RAST_OK;
}
