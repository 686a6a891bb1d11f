/*
 * coverage_plain.c - is a polygon "plain", so that "area" may take it by
 * the accumulation (rast__cov_acc) and skip the test of every row?
 *
 * The accumulation gives each pixel the integral a of the winding number
 * w over it, and the rule turns a into the pixel's coverage exactly when w
 * takes, on the pixel, values in one interval [i, i + 1] (coverage_acc.c).
 * That holds on every pixel when every face of the plane (a connected part
 * of the complement of the rings) has w in {0, 1}, or every one in {0, -1}
 * (w = 0 outside).  A polygon is plain, on its snapped vertices with its
 * edges of length 0 dropped, when
 *   1. each ring has 3 edges or more, and each point where an edge ends
 *      ends exactly two: the two edges of a ring at one of its vertices
 *      (no vertex shared by rings, or visited twice by one);
 *   2. no two edges meet, except two consecutive edges of a ring at their
 *      shared vertex and there only (no crossing, no vertex on another
 *      edge, no overlap);
 *   3. for every ring, the winding number of the other rings at its first
 *      vertex, w0, and w0 + s (s = +1 or -1, its own winding number just
 *      inside it) are both in {0, 1}, or for every ring both in {0, -1}.
 * By 1 and 2 the rings are disjoint simple closed curves; every bounded
 * face lies along one of them, whose two sides have w0 and w0 + s, so 3
 * bounds every face's w.
 *
 * 1: the vertices sorted (x, then y), no two equal.  2: a sweep over the
 * vertices in that order with a sorted array of the edges that the sweep
 * line crosses (Shamos and Hoey): at a vertex its edges that end there
 * leave, then those that start there enter.  Two edges that meet where
 * they must not are next to each other in the array at some step before
 * the first such point, so only neighbours are tested, each pair exactly
 * by orientations (products of differences below 2^28: 64 bits).  3: the winding number by crossings,
 * one ring against the others.  Any answer "no" only costs the faster
 * way; so does a polygon whose work here would exceed a budget linear in
 * its size (a sweep line crossing most edges at once).
 */
#include "coverage.h"

/* (x86: the parts' boxes and copies compared four coordinates a step) */
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__PL_SSE2 1
#endif
/* (size-optimised builds: the sweep as it was, smaller: every vertex by
 * rast__pl_remove and rast__pl_insert, each edge found by a search) */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__PL_FAST 1
#else
#define RAST__PL_FAST 0
#endif

typedef struct rast__pl {
    const rast_point *pt; /* vertex v starts edge v, which ends at vertex next[v] */
    const uint64_t *key;  /* v's place in the order (x, then y): one integer */
    const uint32_t *next, *prev;
    uint32_t *st; /* the sweep's edges, lowest first */
    uint32_t *pos; /* pos[k]: edge k's place in st[] while it is there */
    uint32_t nst;
    uint64_t budget;
#if !defined(__OPTIMIZE_SIZE__) /* (size-optimised builds: condition 3 by rast__pl_faces only) */
    /* faces: condition 3 in the sweep (rast__pl_apart_all), its answer in
     * pn (bit 0: a side +1, bit 1: a side -1, bit 2: a side beyond) */
    int faces;
    uint32_t pn;
#endif
} rast__pl;

/* edge k's left and right end (in the order of the keys) */
static inline void rast__pl_ends(const rast__pl *s, uint32_t k, rast_point *l, rast_point *r)
{
    const uint32_t n = s->next[k];
    const int fwd = s->key[k] < s->key[n];
    *l = s->pt[fwd ? k : n];
    *r = s->pt[fwd ? n : k];
}

/* v[0..n) sorted by key.  v holds the rings' vertices in order, which
 * come in runs (a convex ring: one up, one down in x): the runs, those
 * going down turned round, merged two by two (tmp: room for n; run:
 * room for n + 1). */
static void rast__pl_sort(const uint64_t *key, uint32_t *v, uint32_t *tmp, uint32_t *run, uint32_t n)
{
    uint32_t nr = 0, i = 0, *src = v, *dst = tmp, *t;
    while (i < n) {
        uint32_t j = i + 1, a, b;
        run[nr++] = i;
        if (j < n && key[v[j]] < key[v[i]]) {
            while (j < n && key[v[j]] < key[v[j - 1]]) j++;
            for (a = i, b = j - 1; a < b; a++, b--) {
                uint32_t x = v[a];
                v[a] = v[b];
                v[b] = x;
            }
        } else {
            while (j < n && key[v[j]] >= key[v[j - 1]]) j++;
        }
        i = j;
    }
    run[nr] = n;
    while (nr > 1) {
        uint32_t r, m = 0;
        for (r = 0; r < nr; r += 2) {
            uint32_t a = run[r], mid = run[r + 1], b = mid, end = r + 2 <= nr ? run[r + 2] : n, k = a;
            if (!RAST__PL_FAST) {
                while (a < mid && b < end) dst[k++] = key[src[b]] < key[src[a]] ? src[b++] : src[a++];
            } else if (a < mid && b < end) { /* (the two heads' keys kept: one key read a step) */
                uint32_t x = src[a], y = src[b];
                uint64_t kx = key[x], ky = key[y];
                for (;;) {
                    if (ky < kx) {
                        dst[k++] = y;
                        if (++b == end) break;
                        ky = key[y = src[b]];
                    } else {
                        dst[k++] = x;
                        if (++a == mid) break;
                        kx = key[x = src[a]];
                    }
                }
            }
            while (a < mid) dst[k++] = src[a++];
            while (b < end) dst[k++] = src[b++];
            run[m++] = run[r];
        }
        run[m] = n;
        nr = m;
        t = src;
        src = dst;
        dst = t;
    }
    if (src != v) memcpy(v, src, (size_t)n * sizeof(uint32_t));
}

/* Is c on segment [a, b], given that the three are on one line? */
static int rast__pl_within(rast_point a, rast_point b, rast_point c)
{
    return (a.x < b.x ? a.x <= c.x && c.x <= b.x : b.x <= c.x && c.x <= a.x) &&
           (a.y < b.y ? a.y <= c.y && c.y <= b.y : b.y <= c.y && c.y <= a.y);
}

/* Are segments pq and rt's boxes apart in y (then they do not meet, nor
 * share an end)? */
static inline int rast__pl_yapart(rast_point p, rast_point q, rast_point r, rast_point t)
{
    return (p.y < r.y && p.y < t.y && q.y < r.y && q.y < t.y) || (p.y > r.y && p.y > t.y && q.y > r.y && q.y > t.y);
}

/* 1 when edges j and k may be where they are (condition 2), 0 if not */
static int rast__pl_apart(const rast__pl *s, uint32_t j, uint32_t k)
{
    rast_point p = s->pt[j], q = s->pt[s->next[j]], r = s->pt[k], t = s->pt[s->next[k]];
    int64_t d1, d2, d3, d4;
    if (s->next[j] == k || s->next[k] == j) { /* consecutive: V shared; folded back? */
        rast_point v = s->next[j] == k ? q : p, a = s->next[j] == k ? p : q, b = s->next[j] == k ? t : r;
        return rast__cross3(v, a, b) != 0 ||
               ((int64_t)a.x - v.x) * ((int64_t)b.x - v.x) + ((int64_t)a.y - v.y) * ((int64_t)b.y - v.y) < 0;
    }
    /* (in y first: two neighbours in the sweep share abscissae, and the
     * lower one, j, lies most often below k's box) */
    if (rast__pl_yapart(p, q, r, t) || (p.x < r.x && p.x < t.x && q.x < r.x && q.x < t.x) ||
        (p.x > r.x && p.x > t.x && q.x > r.x && q.x > t.x))
        return 1; /* boxes apart */
    d1 = rast__cross3(r, t, p);
    d2 = rast__cross3(r, t, q);
    d3 = rast__cross3(p, q, r);
    d4 = rast__cross3(p, q, t);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
    if ((d1 == 0 && rast__pl_within(r, t, p)) || (d2 == 0 && rast__pl_within(r, t, q)) ||
        (d3 == 0 && rast__pl_within(p, q, r)) || (d4 == 0 && rast__pl_within(p, q, t)))
        return 0;
    return 1;
}

/* Edge k into the sweep at its left end: 0 if it meets an edge there */
static int rast__pl_insert(rast__pl *s, uint32_t k)
{
    rast_point l, r, ml, mr;
    uint32_t lo = 0, hi = s->nst, i;
    rast__pl_ends(s, k, &l, &r);
    while (lo < hi) { /* the first edge above k */
        uint32_t mid = lo + (hi - lo) / 2;
        int64_t o;
        rast__pl_ends(s, s->st[mid], &ml, &mr);
        o = rast__cross3(ml, mr, l);
        /* o = 0: l is on m (m's left end is not after l, its right end
         * after it).  If l is m's left end, k's partner there, k goes by
         * its other end; else, or if they overlap, k ends next to m, where
         * rast__pl_apart finds that they meet. */
        if (o == 0 && ml.x == l.x && ml.y == l.y) o = rast__cross3(ml, mr, r);
        if (o > 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    if ((s->budget -= s->nst - lo + 1) > ((uint64_t)1 << 62)) return 0;
    memmove(s->st + lo + 1, s->st + lo, (size_t)(s->nst - lo) * sizeof(uint32_t));
    s->st[lo] = k;
    s->nst++;
    for (i = lo; RAST__PL_FAST && i < s->nst; i++) s->pos[s->st[i]] = i;
    if (lo > 0 && !rast__pl_apart(s, s->st[lo - 1], k)) return 0;
    if (lo + 1 < s->nst && !rast__pl_apart(s, k, s->st[lo + 1])) return 0;
    return 1;
}

/* Edge k out of the sweep at its right end: 0 if its neighbours meet */
static int rast__pl_remove(rast__pl *s, uint32_t k)
{
    uint32_t i = 0;
    if (RAST__PL_FAST)
        i = s->pos[k] < s->nst && s->st[s->pos[k]] == k ? s->pos[k] : s->nst;
    else
        while (i < s->nst && s->st[i] != k) i++;
    if ((s->budget -= s->nst + 1) > ((uint64_t)1 << 62) || i == s->nst) return 0;
    if (i > 0 && i + 1 < s->nst && !rast__pl_apart(s, s->st[i - 1], s->st[i + 1])) return 0;
    memmove(s->st + i, s->st + i + 1, (size_t)(s->nst - i - 1) * sizeof(uint32_t));
    s->nst--;
    for (; RAST__PL_FAST && i < s->nst; i++) s->pos[s->st[i]] = i;
    return 1;
}

#if !defined(__OPTIMIZE_SIZE__) /* (size-optimised builds: every vertex by rast__pl_remove and rast__pl_insert) */
#define RAST__PL_PASS 1
/* At a vertex where edge `in` ends and edge `out` starts (a chain: most
 * vertices of a curve's flattening), out takes in's place, then meets the
 * tests of its two neighbours (in's), which are the tests that
 * rast__pl_remove and rast__pl_insert would make: in's two neighbours do
 * not become neighbours.  That is out's place in the order: until the
 * first point where two edges meet wrongly (if any), the array is the
 * edges' order along the sweep line, every pair that has been neighbours
 * tested; no edge but in and out has an end at the vertex (condition 1)
 * or passes through it (it would meet in there, and the one of them next
 * to in was tested); so the edges below in are below the vertex, those
 * above above, and out, which starts there, lies between them.  The
 * first wrong meeting is found at or before its point (Shamos and Hoey),
 * the same as with the search.  0 if an edge meets one where it must
 * not.  (A paragraph of text: the search and two moves cost 10 M
 * instructions of 43 M more; checking the place by the search's test,
 * 5.6 M of 61 M.) */
static int rast__pl_pass(rast__pl *s, uint32_t in, uint32_t out)
{
    const uint32_t i = s->pos[in];
    if ((s->budget -= i + 1) > ((uint64_t)1 << 62) || i >= s->nst || s->st[i] != in) return 0;
    const rast_point l = s->pt[out], r = s->pt[s->next[out]];
    s->st[i] = out;
    s->pos[out] = i;
    /* (most neighbours lie apart in y: that test here, the rest by the call) */
    if (i > 0) {
        const uint32_t m = s->st[i - 1];
        if (!rast__pl_yapart(s->pt[m], s->pt[s->next[m]], l, r) && !rast__pl_apart(s, m, out)) return 0;
    }
    if (i + 1 < s->nst) {
        const uint32_t m = s->st[i + 1];
        if (!rast__pl_yapart(l, r, s->pt[m], s->pt[s->next[m]]) && !rast__pl_apart(s, out, m)) return 0;
    }
    return 1;
}

#else
#define RAST__PL_PASS 0
#define rast__pl_pass(s, in, out) 0
#endif

/* The winding number of the ring of vertices [k0, k1) at p, not on it */
static int64_t rast__pl_winding(const rast__pl *s, uint32_t k0, uint32_t k1, rast_point p)
{
    int64_t w = 0;
    uint32_t k;
    for (k = k0; k < k1; k++) {
        rast_point a = s->pt[k], b = s->pt[s->next[k]];
        if (a.y <= p.y && p.y < b.y && rast__cross3(a, b, p) > 0) w++;
        if (b.y <= p.y && p.y < a.y && rast__cross3(a, b, p) < 0) w--;
    }
    return w;
}

/* Are boxes a and b (x0, y0, x1, y1) apart, with no point in common? */
static int rast__pl_boxes_apart(const int32_t *a, const int32_t *b)
{
    return a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1];
}

/* Is p strictly inside the strictly convex ring of vertices pt[f .. f +
 * n), turning the way d says (1 or -1)?  A binary search of the ring's
 * fan of triangles round its first vertex. */
static int rast__pl_inside(const rast_point *pt, uint32_t f, uint32_t n, int64_t d, rast_point p)
{
    const rast_point v0 = pt[f];
    uint32_t lo = 1, hi = n - 1;
    if (d * rast__cross3(v0, pt[f + 1], p) <= 0 || d * rast__cross3(v0, pt[f + n - 1], p) >= 0) return 0;
    while (hi - lo > 1) { /* the fan's wedge (v_lo, v_hi) round v0 that holds p */
        const uint32_t mid = lo + (hi - lo) / 2;
        if (d * rast__cross3(v0, pt[f + mid], p) >= 0)
            lo = mid;
        else
            hi = mid;
    }
    return d * rast__cross3(pt[f + lo], pt[f + hi], p) > 0;
}

/* Is box a (x0, y0, x1, y1) strictly inside box b? */
static int rast__pl_box_in(const int32_t *a, const int32_t *b)
{
    return b[0] < a[0] && b[1] < a[1] && b[2] > a[2] && b[3] > a[3];
}

/* Is every ring strictly convex, turning once (so simple), and every two
 * rings apart: their boxes apart, or one ring strictly inside the other
 * (the four corners of its box, or else all its vertices: the outer ring
 * is convex)?  Then conditions 1 and 2 hold, with no sort and no sweep (a
 * disc with holes of 320 vertices: 0.2 M instructions less), and each
 * ring's w0 is the sum of the orientations of the rings round it, so
 * condition 3 is decided here too: 1 plain, -1 not.  0 answers nothing:
 * the sweep decides.  Rings r: vertices pt[first[r] .. first[r + 1]),
 * boxes box[4 r ..]; ring orientations into dir[] (1 or -1). */
#define RAST__PL_CONVEX_RINGS 64
static int rast__pl_convex(const rast_point *pt, const uint32_t *first, const int32_t *box, uint32_t nrings,
                           int32_t *dir)
{
    uint32_t r, q, i, pos = 0, neg = 0;
    if (nrings > RAST__PL_CONVEX_RINGS) return 0;
    for (r = 0; r < nrings; r++) { /* strictly convex, one turn */
        const uint32_t f = first[r], n = first[r + 1] - f;
        int64_t sg = 0;
        uint32_t turns = 0;
        rast_point a = pt[f + n - 2], b = pt[f + n - 1];
        for (i = 0; i < n; i++) { /* the turn at b, from a to c */
            const rast_point c = pt[f + i];
            const int64_t t = rast__cross3(a, b, c), dy0 = (int64_t)b.y - a.y, dy1 = (int64_t)c.y - b.y;
            if (t == 0 || (sg && (t > 0) != (sg > 0))) return 0;
            sg = t;
            /* the direction passes angle 0 going round (-y for a clockwise ring) */
            turns += t > 0 ? (dy0 < 0 && dy1 >= 0) : (dy0 > 0 && dy1 <= 0);
            a = b;
            b = c;
        }
        if (turns != 1) return 0;
        dir[r] = sg > 0 ? 1 : -1;
    }
    for (r = 0; r < nrings; r++)
        for (q = r + 1; q < nrings; q++) {
            const int32_t *a = box + 4 * r, *b = box + 4 * q;
            uint32_t in, out, fo, no;
            rast_point c[4];
            if (rast__pl_boxes_apart(a, b)) continue;
            if (rast__pl_box_in(b, a))
                in = q, out = r;
            else if (rast__pl_box_in(a, b))
                in = r, out = q;
            else
                return 0;
            fo = first[out];
            no = first[out + 1] - fo;
            for (i = 0; i < 4; i++) { /* the inner box's corners */
                c[i].x = box[4 * in + 2 * (i & 1)];
                c[i].y = box[4 * in + 1 + (i & 2)];
                if (!rast__pl_inside(pt, fo, no, dir[out], c[i])) break;
            }
            if (i < 4) /* not all inside: the ring's vertices, each */
                for (i = first[in]; i < first[in + 1]; i++)
                    if (!rast__pl_inside(pt, fo, no, dir[out], pt[i])) return 0;
        }
    for (r = 0; r < nrings; r++) { /* condition 3: w0 from the rings whose boxes hold r's */
        int64_t w0 = 0, w1;
        for (q = 0; q < nrings; q++)
            if (q != r && rast__pl_box_in(box + 4 * r, box + 4 * q)) w0 += dir[q];
        w1 = w0 + dir[r];
        if (w0 < -1 || w0 > 1 || w1 < -1 || w1 > 1) return -1;
        pos |= w0 == 1 || w1 == 1;
        neg |= w0 == -1 || w1 == -1;
    }
    return pos && neg ? -1 : 1;
}

/* Is every ring star-shaped round the mean of its vertices c (each edge
 * turns strictly one way round c, by less than half a turn, and the ring
 * goes round c once), and every two rings' boxes apart?  Then each ray
 * from c meets its ring once: the ring is simple, its vertices distinct,
 * and conditions 1 and 2 hold with no sort and no sweep (the star of 200
 * spikes: 0.4 M instructions less, a tenth of "area"'s time on it).
 * Every w0 is 0, so condition 3 is decided here too: 1 plain (every ring
 * turning one way), -1 not.  0 answers nothing: the sweep decides.  Rings
 * and boxes as rast__pl_convex's. */
static int rast__pl_star(const rast_point *pt, const uint32_t *first, const int32_t *box, uint32_t nrings)
{
    uint32_t r, q, i, pos = 0, neg = 0;
    if (nrings > RAST__PL_CONVEX_RINGS) return 0;
    for (r = 0; r < nrings; r++)
        for (q = r + 1; q < nrings; q++)
            if (!rast__pl_boxes_apart(box + 4 * r, box + 4 * q)) return 0;
    for (r = 0; r < nrings; r++) {
        const uint32_t f = first[r], n = first[r + 1] - f;
        int64_t sx = 0, sy = 0, sg;
        uint32_t turns = 0;
        rast_point c, a;
        for (i = 0; i < n; i++) {
            sx += pt[f + i].x;
            sy += pt[f + i].y;
        }
        c.x = (int32_t)(sx / (int64_t)n); /* (any point will do: the test is exact for it) */
        c.y = (int32_t)(sy / (int64_t)n);
        a = pt[f + n - 1];
        sg = rast__cross3(c, a, pt[f]);
        for (i = 0; i < n; i++) { /* the edge from a to b, round c */
            const rast_point b = pt[f + i];
            const int64_t t = rast__cross3(c, a, b), ay = (int64_t)a.y - c.y, by = (int64_t)b.y - c.y;
            if (t == 0 || (t > 0) != (sg > 0)) return 0;
            /* crossing the ray from c towards +x, the way the ring turns */
            turns += sg > 0 ? (ay < 0 && by >= 0) : (by < 0 && ay >= 0);
            a = b;
        }
        if (turns != 1) return 0;
        pos |= sg > 0;
        neg |= sg < 0;
    }
    /* condition 3: w0 = 0 for every ring (boxes apart), w1 its orientation */
    return pos && neg ? -1 : 1;
}

/* Ring points p[0..size), each vertex once (edges of length 0 dropped),
 * into pt[] from n on, with their keys, next[] and prev[] (round the
 * ring); its box into box[0..4) (x0, y0, x1, y1).  Returns the new count;
 * n when the ring has fewer than 3 vertices, or a coordinate is out of
 * range.  box NULL: the ring's box is known and in range (the parts'
 * test: a third of this function's instructions fewer). */
static uint32_t rast__pl_ring(const rast_point *p, uint32_t size, rast_point *pt, uint64_t *key, uint32_t *next,
                              uint32_t *prev, uint32_t n, int32_t *box)
{
    const int64_t lim = RAST_COORD_MAX;
    const uint32_t f = n;
    uint32_t i;
    for (i = 0; i < size; i++) {
        rast_point a = p[i], b = p[i + 1 < size ? i + 1 : 0];
        if (a.x == b.x && a.y == b.y) continue;
        if (RAST__PL_FAST && !box) {
            /* (box and range known) */
        } else if (a.x < -lim || a.x > lim || a.y < -lim || a.y > lim) {
            return f;
        } else if (n == f) {
            box[0] = box[2] = a.x;
            box[1] = box[3] = a.y;
        } else {
            if (a.x < box[0]) box[0] = a.x;
            if (a.y < box[1]) box[1] = a.y;
            if (a.x > box[2]) box[2] = a.x;
            if (a.y > box[3]) box[3] = a.y;
        }
        pt[n] = a;
        key[n] = (uint64_t)(a.x + lim + 1) << 32 | (uint64_t)(a.y + lim + 1);
        next[n] = n + 1;
        prev[n] = n - 1;
        n++;
    }
    if (n - f < 3) return f;
    next[n - 1] = f;
    prev[f] = n - 1;
    return n;
}

#if !defined(__OPTIMIZE_SIZE__)
/* Condition 3 in the sweep, at a vertex where two edges start, the lower
 * at st[lo]: the edges below it, each +1 or -1 by the way its ring goes
 * along it (the way the order rises or not), sum to the winding number
 * just below the vertex, w0, up to a sign common to the polygon (a ray
 * down the sweep line, taken in the order (x, then y): it passes through
 * no vertex), and w0 plus the lower edge's is the winding number between
 * the two edges.  At a ring's least vertex w0 is the other rings' (none
 * of its own edges is below it): condition 3; at the other vertices
 * where two edges start, the sides of faces too, which condition 3
 * bounds when it holds (checked there as well, it changes no answer).
 * (Each ring against the others by crossings, rast__pl_faces, cost a
 * map's coasts, 128 rings, 1.8 M instructions.) */
static void rast__pl_sides(rast__pl *s, uint32_t lo)
{
    int64_t w0 = 0, w1;
    uint32_t i;
    s->budget -= lo;
    for (i = 0; i < lo; i++) {
        const uint32_t k = s->st[i];
        w0 += s->key[k] < s->key[s->next[k]] ? 1 : -1;
    }
    w1 = w0 + (s->key[s->st[lo]] < s->key[s->next[s->st[lo]]] ? 1 : -1);
    s->pn |= (w0 == 1 || w1 == 1) | (uint32_t)(w0 == -1 || w1 == -1) << 1 |
             (uint32_t)(w0 < -1 || w0 > 1 || w1 < -1 || w1 > 1) << 2;
}
#endif

/* Conditions 1 and 2 (above) for the vertices ord[0..n) (whole rings),
 * sorted here (tmp, run: room for n, n + 1): 1 when they hold.  The sweep
 * starts empty. */
static int rast__pl_apart_all(rast__pl *s, uint32_t *ord, uint32_t *tmp, uint32_t *run, uint32_t n)
{
    uint32_t i;
    rast__pl_sort(s->key, ord, tmp, run, n);
    for (i = 0; !RAST__PL_FAST && i + 1 < n; i++) /* condition 1 (else in the sweep's loop) */
        if (s->key[ord[i]] == s->key[ord[i + 1]]) return 0;
    s->st = tmp; /* the sweep's array takes tmp's room once the vertices are sorted, */
    s->pos = run; /* its places run's (each edge's, set as it enters) */
    s->nst = 0;
    for (i = 0; i < n; i++) { /* condition 2: at each vertex, its edges that end, then those that start */
        const uint32_t v = ord[i], in = s->prev[v];
        const uint64_t kv = s->key[v];
        const int in_ends = s->key[in] < kv, out_ends = s->key[s->next[v]] < kv;
        if (RAST__PL_FAST && i > 0 && s->key[ord[i - 1]] == kv) return 0; /* condition 1 */
        if (RAST__PL_PASS && in_ends != out_ends) {
            if (!rast__pl_pass(s, in_ends ? in : v, in_ends ? v : in)) return 0;
            continue;
        }
        if (in_ends && !rast__pl_remove(s, in)) return 0;
        if (out_ends && !rast__pl_remove(s, v)) return 0;
        if (!in_ends && !rast__pl_insert(s, in)) return 0;
        if (!out_ends && !rast__pl_insert(s, v)) return 0;
#if !defined(__OPTIMIZE_SIZE__)
        if (s->faces && !in_ends && !out_ends) rast__pl_sides(s, s->pos[in] < s->pos[v] ? s->pos[in] : s->pos[v]);
#endif
    }
    return 1;
}

/* Condition 3 for the rings rg[0..nr) (rings apart: conditions 1 and 2
 * hold), each against the others of rg: 1 when it holds.  Ring r's
 * vertices: [first[r], end[r]). */
static int rast__pl_faces(const rast__pl *s, const uint32_t *first, const uint32_t *end, const int32_t *box,
                          const uint32_t *rg, uint32_t nr)
{
    uint32_t a, b, pos = 0, neg = 0;
    for (a = 0; a < nr; a++) {
        const uint32_t r = rg[a];
        uint32_t k, low = first[r];
        int64_t w0 = 0, w1;
        const rast_point p = s->pt[first[r]];
        for (b = 0; b < nr; b++) { /* (0 from a ring whose box p is outside) */
            const uint32_t q = rg[b];
            if (q != r && p.x >= box[4 * q] && p.y >= box[4 * q + 1] && p.x <= box[4 * q + 2] &&
                p.y <= box[4 * q + 3])
                w0 += rast__pl_winding(s, first[q], end[q], p);
        }
        for (k = first[r] + 1; k < end[r]; k++) /* the ring's lowest vertex (x, then y) */
            if (s->key[k] < s->key[low]) low = k;
        /* at its lowest vertex a ring turns the way it goes round (not 0:
         * both neighbours lie after it, so on one line they would overlap) */
        w1 = w0 + (rast__cross3(s->pt[s->prev[low]], s->pt[low], s->pt[s->next[low]]) > 0 ? 1 : -1);
        if (w0 < -1 || w0 > 1 || w1 < -1 || w1 > 1) return 0;
        pos |= w0 == 1 || w1 == 1;
        neg |= w0 == -1 || w1 == -1;
    }
    return !(pos && neg);
}

#if !defined(__OPTIMIZE_SIZE__)
/* rast__cov_plain; faces: condition 3 in the sweep (rast__pl_sides) */
static int rast__pl_plain(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int faces)
#else
int rast__cov_plain(const rast_polygon *poly, uint32_t npoints, rast__arena arena)
#endif
{
    rast__pl s;
    rast_point *pt = (rast_point *)rast__take(&arena, (size_t)npoints * sizeof(rast_point));
    uint64_t *key = (uint64_t *)rast__take(&arena, (size_t)npoints * sizeof(uint64_t));
    uint32_t *next = (uint32_t *)rast__take(&arena, (size_t)npoints * sizeof(uint32_t));
    uint32_t *prev = (uint32_t *)rast__take(&arena, (size_t)npoints * sizeof(uint32_t));
    uint32_t *ord = (uint32_t *)rast__take(&arena, (size_t)npoints * sizeof(uint32_t));
    uint32_t *tmp = (uint32_t *)rast__take(&arena, (size_t)npoints * sizeof(uint32_t));
    uint32_t *run = (uint32_t *)rast__take(&arena, ((size_t)npoints + 1) * sizeof(uint32_t));
    uint32_t *first = (uint32_t *)rast__take(&arena, ((size_t)poly->nrings + 1) * sizeof(uint32_t));
    int32_t *box = (int32_t *)rast__take(&arena, (size_t)poly->nrings * 4 * sizeof(int32_t));
    int32_t *dir = (int32_t *)rast__take(&arena, (size_t)poly->nrings * sizeof(int32_t));
    uint32_t r, i, n = 0;
    int fast;
    if (!pt || !key || !next || !prev || !ord || !tmp || !run || !first || !box || !dir || npoints == 0)
        return 0;
    for (r = 0, i = 0; r < poly->nrings; i += poly->ring_sizes[r], r++) { /* the vertices, ring by ring */
        first[r] = n;
        n = rast__pl_ring(poly->points + i, poly->ring_sizes[r], pt, key, next, prev, n, box + 4 * r);
        if (n == first[r]) return 0;
    }
    first[poly->nrings] = n;
    s.pt = pt;
    s.key = key;
    s.next = next;
    s.prev = prev;
    s.nst = 0;
    s.budget = (uint64_t)npoints * 64 + ((uint64_t)1 << 20);
#if !defined(__OPTIMIZE_SIZE__)
    s.faces = faces && poly->nrings > 1;
    s.pn = 0;
#endif
    fast = rast__pl_convex(pt, first, box, poly->nrings, dir);
    if (!fast) fast = rast__pl_star(pt, first, box, poly->nrings);
    if (fast) return fast > 0; /* (conditions 1 to 3 decided) */
    for (i = 0; i < n; i++) ord[i] = i;
    if (!rast__pl_apart_all(&s, ord, tmp, run, n)) return 0;
#if !defined(__OPTIMIZE_SIZE__)
    if (s.faces) return s.budget < ((uint64_t)1 << 62) && (s.pn == 1 || s.pn == 2);
#endif
    if (poly->nrings > 1 && (uint64_t)poly->nrings * n > s.budget) return 0;
    for (r = 0; r < poly->nrings; r++) ord[r] = r; /* condition 3: every ring against every other */
    return rast__pl_faces(&s, first, first + 1, box, ord, poly->nrings);
}

#if !defined(__OPTIMIZE_SIZE__)
int rast__cov_plain(const rast_polygon *poly, uint32_t npoints, rast__arena arena)
{
    return rast__pl_plain(poly, npoints, arena, 0);
}
#endif

#if !defined(__OPTIMIZE_SIZE__)
/* ---- plain parts -----------------------------------------------------------
 *
 * A polygon that is not plain as a whole may be plain in parts: a part is
 * a set of its rings, and two rings whose pixel boxes (the columns and
 * rows of pixels their boxes reach, ends included) share a pixel are in
 * one part (the parts: the connected sets of that relation).  A ring's
 * winding number is 0 outside its box, so on a pixel of a part's boxes
 * the winding number is that of the part's rings alone, and no pixel is
 * in two parts' boxes.  A part for which conditions 1 to 3 hold among its
 * own rings (its own sign: the parts share no pixel) gives each of its
 * pixels a winding number that takes two values, 0 and that sign, so the
 * accumulation of its edges there is the pixel's coverage.  When every part
 * is plain, so is every pixel: the polygon goes to the accumulation (text
 * set in lines whose glyphs' boxes meet nowhere: a paragraph); else the
 * edges of the other parts are marked (RAST__HZ_BAD), and "area" takes
 * the rows that none of them reaches by the accumulation, in bands
 * (rast__cov_area_marked, coverage_area.c).
 * Parts of a few rings each are tested a few vertices at a time, by their
 * chains (rast__pl_chains, below; else sorted and swept by edges): the
 * test's cost is about linear in the vertices (a paragraph of glyphs,
 * 75,051 vertices: its 477 parts 8.5 M instructions, 15.5 M by edges and
 * 31 M before rast__pl_pass lost its search; the whole polygon's sort and
 * sweep took 62 M).  The rings' boxes come first, from their points; a
 * part's vertices are read only when it is tested. */
#define RAST__PL_PAIRS 4 /* box pairs tried per vertex (and 4,096): more, no parts */
/* A part of more rings is taken as not plain, untested (a map's countries
 * share their borders: sorted for nothing) */
#define RAST__PL_PART_RINGS 16

/* ---- a part by x-monotone chains -----------------------------------------
 *
 * Conditions 1 to 3 for a part's rings without sorting its vertices: each
 * ring cut at its extremes in the order (x, then y) into chains along which
 * that order rises (each chain's vertices in that order, as one integer
 * each: rast__pl_ring's key, the point read back from it); the sweep's
 * events are the extremes only (at a least vertex two chains of a ring
 * start, at a greatest two end), and the sweep keeps the chains, not the
 * edges, in their order along the sweep line.  Two chains next to each
 * other are walked together in that order from where they became
 * neighbours: each vertex of either strictly on its side of the other's
 * edge there (the lower's below, the upper's above; orientations of
 * integers below 2^28, exact in 64 bits); between two such vertices the
 * chains are segments, so they do not meet.  As in the sweep by edges
 * (Shamos and Hoey, coverage_plain.c's top), two chains that meet where
 * they must not are neighbours just before the first such point, and
 * their walk reaches it or the vertex after it: a chain that starts
 * between them there would be above the upper and below the lower.  The
 * exceptions are the two chains of a ring at the extreme they share:
 * there they must leave (or arrive) in two directions (else they overlap:
 * folded back).  No two extremes at one point, and no chain's vertex at
 * one where a chain starts (condition 1 as it bears on the sweep; the
 * rest is the walks').  Condition 3 at each ring's least vertex as it
 * enters: the chains below it, each +1 or -1 by the way its ring goes
 * along it, are w0 up to a sign common to the part; w0 and w1 = w0 plus
 * the lower new chain's are the two sides (the windings along a ray down
 * the sweep line, which passes through no other vertex).  The work: a few
 * operations a vertex for the chains, two orientations a vertex for the
 * walks, and the chains that the sweep holds for each extreme (a budget;
 * beyond it, or beyond the room, the sweep by edges decides). */

/* rast__pl_chains' room for m vertices and m / 4 + 8 chains (84 bytes a
 * chain, with room for the arrays' alignment) */
#define RAST__PC_FIXED(m) ((size_t)(m) * 16 + 16 * 2 * RAST_SCRATCH_ALIGN + 8)
#define RAST__PC_ROOM(m) (RAST__PC_FIXED(m) + ((size_t)(m) / 4 + 8) * 84)

/* (b - a) x (c - a) for vertices as keys (rast__pl_ring's: x and y, each
 * plus a constant, in the high and low 32 bits) */
static inline int64_t rast__pk_cross(uint64_t a, uint64_t b, uint64_t c)
{
    const int64_t ax = (int64_t)(a >> 32), ay = (int64_t)(uint32_t)a;
    return ((int64_t)(b >> 32) - ax) * ((int64_t)(uint32_t)c - ay) -
           ((int64_t)(uint32_t)b - ay) * ((int64_t)(c >> 32) - ax);
}

typedef struct rast__pc {
    uint64_t *ck;         /* the chains' vertices, chain by chain, each chain's followed by UINT64_MAX */
    uint32_t *cs, *ce;    /* chain c: ck[cs[c] .. ce[c]] */
    uint32_t *ep;         /* the chain that ends where c ends */
    int32_t *sg;          /* +1 when its ring goes along it the way the order rises, else -1 */
    uint32_t *act, *wa, *wb, *cur; /* the sweep's chains, lowest first; pair i's walk (act[i], act[i + 1]): next vertices */
    uint32_t na;
} rast__pc;

/* Point q's key (x and y, each plus lim + 1, in the high and low 32 bits) */
static inline uint64_t rast__pk_key(rast_point q, int64_t lim)
{
    return (uint64_t)(q.x + lim + 1) << 32 | (uint64_t)(q.y + lim + 1);
}

/* The chain down c, its keys ck[cs[c] .. end) in the ring's order,
 * reversed (stored up), and ended there */
static void rast__pc_down(rast__pc *w, uint32_t c, uint32_t end)
{
    uint64_t *lo = w->ck + w->cs[c], *hi = w->ck + end - 1;
    w->ce[c] = end - 1;
    for (; lo < hi; lo++, hi--) {
        const uint64_t x = *lo;
        *lo = *hi;
        *hi = x;
    }
}

/* Neighbours i and i + 1 walked up to key k (their vertices at or before
 * it): 0 if they meet where they must not */
static int rast__pc_walk(rast__pc *w, uint32_t i, uint64_t k)
{
    const uint64_t *ck = w->ck;
    const uint32_t a = w->act[i], b = w->act[i + 1];
    uint32_t ia = w->wa[i], ib = w->wb[i];
    for (;;) {
        const uint64_t ka = ck[ia], kb = ck[ib];
        if (ka < kb) {
            if (ka > k) break;
            if (rast__pk_cross(ck[ib - 1], kb, ka) >= 0) return 0; /* a's vertex not below b */
            ia++;
        } else if (kb < ka) {
            if (kb > k) break;
            if (rast__pk_cross(ck[ia - 1], ka, kb) <= 0) return 0; /* b's vertex not above a */
            ib++;
        } else { /* one point: only the end that a and b share */
            if (ka > k) break;
            if (ia != w->ce[a] || ib != w->ce[b] || w->ep[a] != b) return 0;
            ia++;
            ib++;
        }
    }
    w->wa[i] = w->cur[a] = ia;
    w->wb[i] = w->cur[b] = ib;
    return 1;
}

/* Conditions 1 to 3 for the rings rg[0..nr) of poly (ring q's points from
 * poly->points + pfirst[q], its least in the order (x, then y) the
 * lv[q]-th, the first when it repeats; m of them in all, their coordinates
 * in range):
 * 1 when they hold, 0 when not, -1 undecided (room or budget: the sweep
 * by edges then).  blk: the room.  per: the budget, per vertex, of the
 * chains the sweep holds at its events (each costs a step, ~12
 * instructions; the sweep by edges ~460 a vertex on a map's coasts). */
static int rast__pl_chains(const rast_polygon *poly, const uint32_t *pfirst, const uint32_t *lv, const int32_t *rg,
                           uint32_t nr, uint32_t m, uint32_t per, rast__arena blk)
{
    const int64_t lim = RAST_COORD_MAX;
    const size_t cmax = blk.left > RAST__PC_FIXED(m) ? (blk.left - RAST__PC_FIXED(m)) / 84 : 0;
    rast__pc w;
    uint64_t *ek;
    /* extreme t at key ek[t], of chains ea[t] and eb[t]; er[t]: UINT32_MAX
     * where they end, 1 at a ring's least vertex (its first extreme in the
     * order: condition 3 there, any number of rings), 0 at its other starts */
    uint32_t *ea, *eb, *er, *eix, *etmp, *erun;
    uint32_t g, i, nc = 0, ne = 0, nv = 0, pos = 0, neg = 0;
    uint64_t budget = (uint64_t)m * per + 256;
    if (cmax < 2) return -1;
    w.ck = (uint64_t *)rast__take(&blk, ((size_t)m + 2 * cmax) * sizeof(uint64_t));
    ek = (uint64_t *)rast__take(&blk, cmax * sizeof(uint64_t));
    w.cs = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    w.ce = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    w.ep = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    w.sg = (int32_t *)rast__take(&blk, cmax * sizeof(int32_t));
    w.act = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    w.wa = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    w.wb = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    w.cur = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    ea = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    eb = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    er = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    eix = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    etmp = (uint32_t *)rast__take(&blk, cmax * sizeof(uint32_t));
    erun = (uint32_t *)rast__take(&blk, (cmax + 1) * sizeof(uint32_t));
    if (!w.ck || !ek || !w.cs || !w.ce || !w.ep || !w.sg || !w.act || !w.wa || !w.wb || !w.cur || !ea ||
        !eb || !er || !eix || !etmp || !erun)
        return -1;
    for (g = 0; g < nr; g++) { /* each ring's chains, from its least vertex, and its extremes */
        const rast_point *p = poly->points + pfirst[rg[g]];
        const uint32_t size = poly->ring_sizes[rg[g]], cb = nc;
        const rast_point *q = p + lv[rg[g]] + 1, *qe = p + size;
        const uint64_t least = size ? rast__pk_key(p[lv[rg[g]]], lim) : 0;
        uint32_t n = 0, up = 1, round = 0;
        uint64_t last;
        if (nc + 2 > cmax) return -1;
        w.cs[nc] = nv;
        w.sg[nc] = 1;
        w.ck[nv++] = last = least;
        /* the keys round the ring from it, back to it, an edge of length 0
         * dropped: a chain up (the ring's way) while they rise, then one
         * down (stored up: reversed when it ends) while they fall */
        for (;;) {
            uint64_t k;
            if (q == qe) { /* (from the least to the ring's end, then from its start back to the least) */
                if (round++) break;
                q = p;
                qe = p + lv[rg[g]] + 1;
                continue;
            }
            k = rast__pk_key(*q++, lim);
            if (k == last) continue;
            n++;
            if (up ? k > last : k < last) {
                w.ck[nv++] = k;
            } else if (up) { /* last the greatest: nc and nc + 1 end there */
                w.ce[nc] = nv - 1;
                w.ep[nc] = nc + 1;
                w.ck[nv++] = UINT64_MAX;
                w.cs[nc + 1] = nv;
                w.ep[nc + 1] = nc;
                w.sg[nc + 1] = -1;
                w.ck[nv++] = last;
                w.ck[nv++] = k;
                up = 0;
                ek[ne] = last;
                ea[ne] = nc;
                eb[ne] = nc + 1;
                er[ne++] = UINT32_MAX;
            } else { /* last the least after: nc + 1 and the next up start there */
                rast__pc_down(&w, nc + 1, nv);
                w.ck[nv++] = UINT64_MAX;
                ek[ne] = last;
                ea[ne] = nc + 1;
                eb[ne] = nc + 2;
                er[ne++] = 0;
                nc += 2;
                if (nc + 2 > cmax) return -1;
                w.cs[nc] = nv;
                w.sg[nc] = 1;
                w.ck[nv++] = last;
                w.ck[nv++] = k;
                up = 1;
            }
            last = k;
        }
        if (n < 3) return 0;
        rast__pc_down(&w, nc + 1, nv); /* (n >= 3: the last chain goes down to the least) */
        w.ck[nv++] = UINT64_MAX;
        ek[ne] = least;
        ea[ne] = nc + 1;
        eb[ne] = cb;
        er[ne++] = 1;
        nc += 2;
    }
    for (i = 0; i < ne; i++) eix[i] = i;
    if (ne > 16) {
        rast__pl_sort(ek, eix, etmp, erun, ne);
    } else { /* (a few: in place) */
        for (i = 1; i < ne; i++) {
            const uint32_t x = eix[i];
            uint32_t j = i;
            for (; j > 0 && ek[eix[j - 1]] > ek[x]; j--) eix[j] = eix[j - 1];
            eix[j] = x;
        }
    }
    w.na = 0;
    for (i = 0; i < ne; i++) {
        const uint32_t e = eix[i], a = ea[e], b = eb[e];
        const uint64_t k = ek[e];
        uint32_t j, at;
        if (i + 1 < ne && ek[eix[i + 1]] == k) return 0; /* two extremes at one point */
        if ((budget -= w.na + 1) > ((uint64_t)1 << 62)) return -1;
        for (j = 0; j + 1 < w.na; j++) /* (a pair with no vertex up to k: as it was) */
            if ((w.ck[w.wa[j]] <= k || w.ck[w.wb[j]] <= k) && !rast__pc_walk(&w, j, k)) return 0;
        if (er[e] == UINT32_MAX) { /* a and b end here: neighbours (their walk met at the end), out */
            for (at = 0; at < w.na && w.act[at] != a && w.act[at] != b; at++) {
            }
            if (at + 1 >= w.na || (w.act[at + 1] != a && w.act[at + 1] != b)) return 0;
            for (j = at; j + 2 < w.na; j++) {
                w.act[j] = w.act[j + 2];
                w.wa[j] = w.wa[j + 2];
                w.wb[j] = w.wb[j + 2];
            }
            w.na -= 2;
            if (at > 0 && at < w.na) { /* new neighbours at = k */
                w.wa[at - 1] = w.cur[w.act[at - 1]];
                w.wb[at - 1] = w.cur[w.act[at]];
            }
        } else { /* a and b start here: in at their place, the lower first */
            const int64_t o = rast__pk_cross(k, w.ck[w.cs[a] + 1], w.ck[w.cs[b] + 1]);
            const uint32_t lo = o > 0 ? a : b, hi = o > 0 ? b : a;
            int64_t w0 = 0, w1;
            if (o == 0) return 0; /* folded back */
            for (at = 0; at < w.na; at++) {
                const uint32_t x = w.act[at], c = w.cur[x];
                int64_t d;
                if (w.ck[c - 1] == k || (d = rast__pk_cross(w.ck[c - 1], w.ck[c], k)) == 0) return 0; /* on it */
                if (d < 0) break;
                w0 += w.sg[x];
            }
            for (j = w.na; j-- > at;) {
                w.act[j + 2] = w.act[j];
                if (j + 1 < w.na) { /* (pair j's walk: pair j + 2's now) */
                    w.wa[j + 2] = w.wa[j];
                    w.wb[j + 2] = w.wb[j];
                }
            }
            w.na += 2;
            w.act[at] = lo;
            w.act[at + 1] = hi;
            w.cur[lo] = w.wa[at] = w.cs[lo] + 1;
            w.cur[hi] = w.wb[at] = w.cs[hi] + 1;
            if (at > 0) {
                w.wa[at - 1] = w.cur[w.act[at - 1]];
                w.wb[at - 1] = w.cur[lo];
            }
            if (at + 2 < w.na) {
                w.wa[at + 1] = w.cur[hi];
                w.wb[at + 1] = w.cur[w.act[at + 2]];
            }
            if (er[e]) { /* the ring's least vertex: condition 3 */
                w1 = w0 + w.sg[lo];
                if (w0 < -1 || w0 > 1 || w1 < -1 || w1 > 1) return 0;
                pos |= w0 == 1 || w1 == 1;
                neg |= w0 == -1 || w1 == -1;
            }
        }
    }
    return w.na == 0 && !(pos && neg);
}


static uint32_t rast__pl_root(uint32_t *par, uint32_t r)
{
    while (par[r] != r) {
        par[r] = par[par[r]];
        r = par[r];
    }
    return r;
}

/* The edges of e[0..nedges) (rast__cov_edges_polygon's, ring by ring)
 * marked from rast__cov_parts_test's table at the start of arena's room:
 * those of the plain rings `mark` = RAST__HZ_PLAIN, or those of the others
 * when `mark` is RAST__HZ_BAD.  -1 when marked; 0 when the table's edges
 * are not e[]'s (nothing marked). */
int rast__cov_parts_mark(rast__arena arena, uint32_t nr, rast__cedge *e, uint32_t nedges, int32_t mark)
{
    const int32_t *rows = (const int32_t *)rast__take(&arena, RAST__COV_RING_ROWS(nr));
    uint32_t r, a, eb = 0;
    if (!rows) return 0;
    for (r = 0; r < nr; r++) eb += (uint32_t)(rows[3 * r + 2] < 0 ? ~rows[3 * r + 2] : rows[3 * r + 2]);
    if (eb != nedges) return 0;
    for (r = 0, eb = 0; r < nr; r++) {
        const int32_t c = rows[3 * r + 2];
        const uint32_t ne = (uint32_t)(c < 0 ? ~c : c);
        if ((c >= 0) == (mark == RAST__HZ_PLAIN))
            for (a = eb; a < eb + ne; a++) e[a].hz |= mark;
        eb += ne;
    }
    return -1;
}

int rast__cov_plain_parts(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int32_t sb,
                          rast__cedge *e, uint32_t nedges)
{
    const int t = rast__cov_parts_test(poly, npoints, arena, sb);
    if (t < 0) rast__cov_parts_mark(arena, poly->nrings, e, nedges, RAST__HZ_PLAIN);
    return t > 0;
}

int rast__cov_parts_marked(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int32_t sb,
                           rast__cedge *e, uint32_t nedges)
{
    const int t = rast__cov_parts_test(poly, npoints, arena, sb);
    return t < 0 ? rast__cov_parts_mark(arena, poly->nrings, e, nedges, RAST__HZ_BAD) : t;
}

/* Is part rid[a..b) the part from rid[ra] on moved by one vector: as many
 * rings, of the same sizes, every point of each less the one in the
 * other at the same place the same?  (The order of rid: the rings'.)
 * pf[q]: ring q's first point in poly->points. */
static int rast__pl_same(const rast_polygon *poly, const uint32_t *pf, const int32_t *rkey, const int32_t *rid,
                         uint32_t nr, uint32_t ra, uint32_t a, uint32_t b)
{
    const uint32_t c = b - a;
    const rast_point *p0 = poly->points + pf[rid[a]], *q0 = poly->points + pf[rid[ra]];
    const uint32_t dx = (uint32_t)p0->x - (uint32_t)q0->x, dy = (uint32_t)p0->y - (uint32_t)q0->y;
    uint32_t i, j;
    if (ra + c > nr || rkey[rid[ra + c - 1]] != rkey[rid[ra]] || (ra + c < nr && rkey[rid[ra + c]] == rkey[rid[ra]]))
        return 0;
    for (i = 0; i < c; i++) {
        const uint32_t qa = (uint32_t)rid[a + i], qr = (uint32_t)rid[ra + i], size = poly->ring_sizes[qa];
        const rast_point *p = poly->points + pf[qa], *q = poly->points + pf[qr];
        if (poly->ring_sizes[qr] != size) return 0;
        j = 0;
#if defined(RAST__PL_SSE2)
        { /* four points a step: q's plus (dx, dy) against p's, modulo 2^32 too */
            const __m128i d = _mm_set_epi32((int32_t)dy, (int32_t)dx, (int32_t)dy, (int32_t)dx);
            for (; j + 4 <= size; j += 4) {
                const __m128i ua = _mm_loadu_si128((const __m128i *)(const void *)(p + j));
                const __m128i ub = _mm_loadu_si128((const __m128i *)(const void *)(p + j + 2));
                const __m128i va = _mm_add_epi32(_mm_loadu_si128((const __m128i *)(const void *)(q + j)), d);
                const __m128i vb = _mm_add_epi32(_mm_loadu_si128((const __m128i *)(const void *)(q + j + 2)), d);
                if (_mm_movemask_epi8(_mm_and_si128(_mm_cmpeq_epi32(ua, va), _mm_cmpeq_epi32(ub, vb))) != 0xFFFF) return 0;
            }
        }
#endif
        for (; j < size; j++) /* (differences below 2^29: modulo 2^32, the same test) */
            if ((uint32_t)p[j].x - (uint32_t)q[j].x != dx || (uint32_t)p[j].y - (uint32_t)q[j].y != dy) return 0;
    }
    return 1;
}

/* A part tested before of which part rid[a..b) is a moved copy
 * (rast__pl_same: a paragraph's glyphs, set again and again, each word a
 * part; 62% of its vertices): its first place in rid, whose answers are
 * this part's (conditions 1 to 3, and the tests' budgets, see only the
 * order of the points and differences of them, which a move by integers
 * keeps), else -1 and the part put in the table tab[0 .. mask] (-1
 * empty) by a hash of its rings' sizes and boxes less its first ring's
 * (box: x0, y0, x1, y1 a ring), which rings of one shape share. */
static int32_t rast__pl_again(const rast_polygon *poly, const uint32_t *pf, const int32_t *box, const int32_t *rkey,
                              const int32_t *rid, uint32_t nr, uint32_t a, uint32_t b, int32_t *tab, uint32_t mask)
{
    const int32_t *b0 = box + 4 * rid[a];
    uint64_t hv = b - a;
    uint32_t i, h;
    for (i = a; i < b; i++) {
        const int32_t *bx = box + 4 * rid[i];
        hv = (hv + poly->ring_sizes[rid[i]]) * UINT64_C(0x9E3779B97F4A7C15);
        hv = (hv + (uint32_t)(bx[0] - b0[0]) + ((uint64_t)(uint32_t)(bx[1] - b0[1]) << 32)) *
             UINT64_C(0xC2B2AE3D27D4EB4F);
        hv = (hv + (uint32_t)(bx[2] - b0[0]) + ((uint64_t)(uint32_t)(bx[3] - b0[1]) << 32)) *
             UINT64_C(0x9E3779B97F4A7C15);
    }
    for (h = (uint32_t)(hv >> 40) & mask; tab[h] >= 0; h = (h + 1) & mask)
        if (rast__pl_same(poly, pf, rkey, rid, nr, (uint32_t)tab[h], a, b)) return tab[h];
    tab[h] = (int32_t)a;
    return -1;
}

int rast__cov_parts_test(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int32_t sb)
{
    const int64_t lim = RAST_COORD_MAX, P = (int64_t)1 << sb;
    const uint32_t nr = poly->nrings;
    rast__pl s;
    int32_t *rows = (int32_t *)rast__take(&arena, RAST__COV_RING_ROWS(nr)); /* (first: rast__cov_parts_marked's table) */
    uint32_t *first = (uint32_t *)rast__take(&arena, (size_t)nr * sizeof(uint32_t));
    uint32_t *end = (uint32_t *)rast__take(&arena, (size_t)nr * sizeof(uint32_t));
    int32_t *box = (int32_t *)rast__take(&arena, (size_t)nr * 4 * sizeof(int32_t));
    int32_t *pbox = (int32_t *)rast__take(&arena, (size_t)nr * 4 * sizeof(int32_t));
    uint32_t *nv = (uint32_t *)rast__take(&arena, (size_t)nr * sizeof(uint32_t));
    uint32_t *lv = (uint32_t *)rast__take(&arena, (size_t)nr * sizeof(uint32_t));
    uint32_t *par = (uint32_t *)rast__take(&arena, (size_t)nr * sizeof(uint32_t));
    int32_t *rid = (int32_t *)rast__take(&arena, (size_t)nr * sizeof(int32_t));
    int32_t *rtmp = (int32_t *)rast__take(&arena, (size_t)nr * sizeof(int32_t));
    int32_t *rkey = (int32_t *)rast__take(&arena, (size_t)nr * sizeof(int32_t));
    uint32_t *pf = (uint32_t *)rast__take(&arena, (size_t)nr * sizeof(uint32_t));
    int32_t *tab;
    rast_point *pt;
    uint64_t *key;
    uint32_t *next, *prev, *ord, *tmp, *run;
    rast__arena blk, room;
    uint32_t r, i, a, b, base, nc = 0, most = 0, all = 1, tmask;
    uint64_t pairs = (uint64_t)npoints * RAST__PL_PAIRS + 4096, tested = 0;
    int32_t xmin = INT32_MAX, xmax = INT32_MIN, ymin = INT32_MAX, ymax = INT32_MIN;
    if (!rows || !first || !end || !box || !pbox || !lv || !par || !nv || !rid || !rtmp || !rkey || !pf || nr < 2)
        return 0;
    for (r = 0, base = 0; r < nr; base += poly->ring_sizes[r], r++) { /* each ring's box */
        const rast_point *p = poly->points + base;
        const uint32_t size = poly->ring_sizes[r];
        int32_t *bx = box + 4 * r, x0 = size ? p[0].x : 0, y0 = size ? p[0].y : 0, x1 = x0, y1 = y0;
        int32_t ly = y0; /* the least vertex's ordinate (in the order x, then y) */
        uint32_t lvr = 0;
        first[r] = pf[r] = base;
        nv[r] = size; /* (its vertices, at most; none: a part alone, not plain) */
#if defined(RAST__PL_SSE2)
        if (size >= 4) { /* the box two points a step, then its least vertex: on x0's vertical, the least y first */
            __m128i lo = _mm_loadu_si128((const __m128i *)(const void *)p), hi = lo;
            int32_t t[4];
            for (i = 2; i + 2 <= size; i += 2) {
                const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(p + i));
                const __m128i ml = _mm_cmpgt_epi32(lo, v), mh = _mm_cmpgt_epi32(v, hi);
                lo = _mm_xor_si128(lo, _mm_and_si128(_mm_xor_si128(lo, v), ml));
                hi = _mm_xor_si128(hi, _mm_and_si128(_mm_xor_si128(hi, v), mh));
            }
            for (; i < size; i++) { /* (the last point: no pair) */
                x0 = p[i].x < x0 ? p[i].x : x0;
                y0 = p[i].y < y0 ? p[i].y : y0;
                x1 = p[i].x > x1 ? p[i].x : x1;
                y1 = p[i].y > y1 ? p[i].y : y1;
            }
            _mm_storeu_si128((__m128i *)(void *)t, lo);
            x0 = t[0] < x0 ? t[0] : x0;
            x0 = t[2] < x0 ? t[2] : x0;
            y0 = t[1] < y0 ? t[1] : y0;
            y0 = t[3] < y0 ? t[3] : y0;
            _mm_storeu_si128((__m128i *)(void *)t, hi);
            x1 = t[0] > x1 ? t[0] : x1;
            x1 = t[2] > x1 ? t[2] : x1;
            y1 = t[1] > y1 ? t[1] : y1;
            y1 = t[3] > y1 ? t[3] : y1;
            for (i = 0, ly = INT32_MAX; i < size; i++)
                if (p[i].x == x0 && p[i].y < ly) {
                    lvr = i;
                    ly = p[i].y;
                }
        } else
#endif
            for (i = 1; i < size; i++) {
                const int32_t x = p[i].x, y = p[i].y;
                if (x <= x0 && (x < x0 || y < ly)) { /* (its least vertex, the first when it repeats: rast__pl_chains) */
                    lvr = i;
                    ly = y;
                }
                x0 = x < x0 ? x : x0;
                y0 = y < y0 ? y : y0;
                x1 = x > x1 ? x : x1;
                y1 = y > y1 ? y : y1;
            }
        lv[r] = lvr;
        if (x0 < -lim || x1 > lim || y0 < -lim || y1 > lim) return 0;
        bx[0] = x0;
        bx[1] = y0;
        bx[2] = x1;
        bx[3] = y1;
        for (i = 0; i < 4; i++) pbox[4 * r + i] = (int32_t)rast__floordiv(bx[i], P);
        xmin = pbox[4 * r] < xmin ? pbox[4 * r] : xmin;
        xmax = pbox[4 * r + 2] > xmax ? pbox[4 * r + 2] : xmax;
        ymin = pbox[4 * r + 1] < ymin ? pbox[4 * r + 1] : ymin;
        ymax = pbox[4 * r + 3] > ymax ? pbox[4 * r + 3] : ymax;
    }
    { /* the parts: every two boxes that share a pixel.  The boxes in bands
       * of rows (between two bands no box reaches both rows: a line of
       * text each), then by left column: a box is tried against those
       * after it in its band up to its right column (a line's, not every
       * line's: text, 1,449 rings, 31,900 pairs tried by column alone, 639
       * so).  The key: band c, column x, c W + x (W the columns' span),
       * when below 2^31 and the rows' span is at most 4 a ring (and
       * 1,024), else the column (one band).  The pixel boxes copied in
       * the key's order, sx[4 a ..] ring rid[a]'s (its key, its top row,
       * its key's right end, its bottom row; one with no vertices rows
       * INT32_MAX to INT32_MIN, which meets none), in room past the
       * arena's, used here only, with the rows' bands. */
        rast__arena past = arena;
        int32_t *sx = (int32_t *)rast__take(&past, (size_t)nr * 4 * sizeof(int32_t));
        const uint64_t wx = (uint64_t)((int64_t)xmax - xmin) + 1, hy = (uint64_t)((int64_t)ymax - ymin) + 1;
        int32_t *bd = hy <= (uint64_t)nr * 4 + 1024 ? (int32_t *)rast__take(&past, (size_t)hy * sizeof(int32_t)) : NULL;
        uint64_t cw = 0;
        if (!sx) return 0;
        if (bd) { /* each row's band: bd[y - ymin], from the boxes that reach rows y and y + 1 */
            uint32_t y, c = 0;
            int32_t reach = 0;
            memset(bd, 0, (size_t)hy * sizeof(int32_t));
            for (r = 0; r < nr; r++)
                if (pbox[4 * r + 3] > pbox[4 * r + 1]) {
                    bd[pbox[4 * r + 1] - ymin]++;
                    bd[pbox[4 * r + 3] - ymin]--;
                }
            for (y = 0; y < (uint32_t)hy; y++) {
                reach += bd[y];
                bd[y] = (int32_t)c;
                c += reach == 0;
            }
            cw = (uint64_t)c * wx <= (uint64_t)INT32_MAX ? wx : 0;
        }
        for (r = 0; r < nr; r++) {
            const uint64_t band = cw ? (uint64_t)bd[pbox[4 * r + 1] - ymin] : 0;
            rid[r] = (int32_t)r;
            par[r] = r;
            rkey[r] = (int32_t)(band * cw + (uint64_t)((int64_t)pbox[4 * r] - xmin));
        }
        rast__cov_radix_sort(rid, rtmp, rkey, nr);
        for (a = 0; a < nr; a++) {
            const int32_t *p = pbox + 4 * rid[a];
            const int e = nv[rid[a]] != 0;
            sx[4 * a] = rkey[rid[a]];
            sx[4 * a + 1] = e ? p[1] : INT32_MAX;
            sx[4 * a + 2] = rkey[rid[a]] + (p[2] - p[0]);
            sx[4 * a + 3] = e ? p[3] : INT32_MIN;
        }
        for (a = 0; a < nr; a++) {
            const int32_t x1 = sx[4 * a + 2], y0 = sx[4 * a + 1], y1 = sx[4 * a + 3];
            if (y0 > y1) continue;
            for (b = a + 1; b < nr && sx[4 * b] <= x1; b++)
                if (sx[4 * b + 1] <= y1 && y0 <= sx[4 * b + 3])
                    par[rast__pl_root(par, (uint32_t)rid[a])] = rast__pl_root(par, (uint32_t)rid[b]);
            if (b - a - 1 >= pairs) return 0; /* (the pairs tried: a budget) */
            pairs -= b - a - 1;
        }
    }
    for (r = 0; r < nr; r++) rtmp[r] = -1; /* each part's number, by its root */
    for (r = 0; r < nr; r++) {
        const uint32_t t = rast__pl_root(par, r);
        if (rtmp[t] < 0) rtmp[t] = (int32_t)nc++;
        rkey[r] = rtmp[t];
        rid[r] = (int32_t)r;
    }
    rast__cov_radix_sort(rid, rtmp, rkey, nr); /* the rings part by part */
    for (a = 0; a < nr; a = b) { /* the vertices of the parts to test, the most in one */
        uint32_t m = 0;
        for (b = a; b < nr && rkey[rid[b]] == rkey[rid[a]]; b++) m += nv[rid[b]];
        if (b - a <= RAST__PL_PART_RINGS && nv[rid[a]]) {
            tested += m;
            most = m > most ? m : most;
        }
    }
    if (tested * 2 < npoints) return 0; /* (most vertices in parts not tested: not worth it) */
    for (tmask = 16; tmask < 2 * nc;) tmask <<= 1; /* (the parts' table: rast__pl_again) */
    tab = (int32_t *)rast__take(&arena, (size_t)tmask * sizeof(int32_t));
    if (!tab) return 0;
    memset(tab, 0xFF, (size_t)tmask * sizeof(int32_t));
    tmask--;
    /* one room for either test of a part: the sweep by edges' arrays, or
     * the chains' (rast__pl_chains) */
    blk.left = 2 * rast__align((size_t)most * sizeof(uint64_t)) + 5 * rast__align((size_t)most * sizeof(uint32_t)) +
               rast__align(((size_t)most + 1) * sizeof(uint32_t));
    room = arena; /* (the chains' room for most / 4 chains when there is room: else as it comes) */
    blk.p = (unsigned char *)rast__take(&room, blk.left + RAST__PC_ROOM(most));
    if (blk.p)
        blk.left += RAST__PC_ROOM(most);
    else
        blk.p = (unsigned char *)rast__take(&arena, blk.left);
    if (!blk.p) return 0;
    room = blk;
    pt = (rast_point *)rast__take(&room, (size_t)most * sizeof(rast_point));
    key = (uint64_t *)rast__take(&room, (size_t)most * sizeof(uint64_t));
    next = (uint32_t *)rast__take(&room, (size_t)most * sizeof(uint32_t));
    prev = (uint32_t *)rast__take(&room, (size_t)most * sizeof(uint32_t));
    ord = (uint32_t *)rast__take(&room, (size_t)most * sizeof(uint32_t));
    tmp = (uint32_t *)rast__take(&room, (size_t)most * sizeof(uint32_t));
    run = (uint32_t *)rast__take(&room, ((size_t)most + 1) * sizeof(uint32_t));
    if (!pt || !key || !next || !prev || !ord || !tmp || !run) return 0;
    s.pt = pt;
    s.key = key;
    s.next = next;
    s.prev = prev;
    s.nst = 0;
    s.budget = (uint64_t)npoints * 64 + ((uint64_t)1 << 20);
    s.faces = 0;
    s.pn = 0;
    for (a = 0; a < nr; a = b) { /* each part: conditions 1 to 3 among its rings, its vertices loaded */
        uint32_t n = 0, ok = nv[rid[a]] != 0, m = 0;
        int32_t again;
        int by;
        for (b = a; b < nr && rkey[rid[b]] == rkey[rid[a]]; b++) m += nv[rid[b]];
        ok = ok && b - a <= RAST__PL_PART_RINGS;
        again = ok ? rast__pl_again(poly, pf, box, rkey, rid, nr, a, b, tab, tmask) : -1;
        if (again >= 0) /* (a moved copy of a part tested: its answer) */
            by = (int)nv[rid[again]];
        else /* (-1: by the sweep of edges) */
            by = ok ? rast__pl_chains(poly, first, lv, rid + a, b - a, m, 4, blk) : 0;
        if (by >= 0) {
            for (i = a; i < b; i++) nv[rid[i]] = (uint32_t)by;
            all &= (uint32_t)by;
            continue;
        }
        for (i = a; i < b && ok; i++) {
            const uint32_t q = (uint32_t)rid[i];
            const uint32_t f = n;
            n = rast__pl_ring(poly->points + first[q], poly->ring_sizes[q], pt, key, next, prev, n, NULL);
            first[q] = f; /* (the ring's points read: now its vertices') */
            end[q] = n;
            ok = n > f; /* (3 or more) */
        }
        for (i = 0; i < n && ok; i++) ord[i] = i;
        ok = ok && rast__pl_apart_all(&s, ord, tmp, run, n);
        if (ok && b - a > 1) { /* (one ring: w0 = 0, the sign its own) */
            const uint64_t cost = (uint64_t)(b - a) * (n + b - a);
            ok = cost < s.budget && rast__pl_faces(&s, first, end, box, (const uint32_t *)(const void *)(rid + a), b - a);
            s.budget -= ok ? cost : 0;
        }
        for (i = a; i < b; i++) nv[rid[i]] = ok; /* (each ring's answer) */
        all &= ok;
    }
    if (all) return 1;
    for (r = 0, b = 0; r < nr; r++) b |= nv[r]; /* (a plain part: else nothing marked) */
    if (!b) return 0;
    for (r = 0, base = 0; r < nr; base += poly->ring_sizes[r], r++) { /* the table */
        const rast_point *p = poly->points + base;
        const uint32_t size = poly->ring_sizes[r];
        int32_t y = size ? p[size - 1].y : 0;
        uint32_t ne = 0; /* its edges in e[]: those not horizontal */
        i = 0;
#if defined(RAST__PL_SSE2)
        if (size >= 3) { /* the edges into points 1 to size - 1 two a step: -1 in a lane where y is the same */
            __m128i eq = _mm_setzero_si128();
            int32_t t[4];
            for (i = 1; i + 2 <= size; i += 2)
                eq = _mm_add_epi32(eq, _mm_cmpeq_epi32(_mm_loadu_si128((const __m128i *)(const void *)(p + i)),
                                                       _mm_loadu_si128((const __m128i *)(const void *)(p + i - 1))));
            _mm_storeu_si128((__m128i *)(void *)t, eq);
            /* (t[1], t[3]: the y lanes, minus the equal ones; and the edge into point 0) */
            ne = (i - 1) + (uint32_t)(t[1] + t[3]) + (p[0].y != y);
            y = p[i - 1].y;
        }
#endif
        for (; i < size; y = p[i++].y) ne += p[i].y != y;
        /* the ring's rows (its edges' rows: floor(y0 / P) to ceil(y1 / P)
         * - 1), its edges, not plain as ~ */
        rows[3 * r] = (int32_t)rast__floordiv(box[4 * r + 1], P);
        rows[3 * r + 1] = (int32_t)-rast__floordiv(-(int64_t)box[4 * r + 3], P) - 1;
        rows[3 * r + 2] = nv[r] ? (int32_t)ne : ~(int32_t)ne;
        /* and its columns, after the three a ring: floor(x0 / P) to
         * ceil(x1 / P) - 1, those where its winding number may not be 0
         * (rast__cov_parts_boxes) */
        rows[3 * nr + 2 * r] = (int32_t)rast__floordiv(box[4 * r], P);
        rows[3 * nr + 2 * r + 1] = (int32_t)-rast__floordiv(-(int64_t)box[4 * r + 2], P) - 1;
    }
    return -1;
}

/* Do pixel boxes [b[0], b[2]] x [b[1], b[3]] (columns, rows) and c's
 * meet? */
static int rast__pl_meet(const int32_t *b, const int32_t *c)
{
    return b[0] <= c[2] && c[0] <= b[2] && b[1] <= c[3] && c[1] <= b[3];
}

int rast__cov_parts_boxes(rast__arena arena, uint32_t nr, unsigned char *in, int32_t *bx, int32_t most)
{
    const int32_t *rows = (const int32_t *)rast__take(&arena, RAST__COV_RING_ROWS(nr));
    const int32_t *cols = rows ? rows + 3 * (size_t)nr : NULL;
    uint64_t all = 0, bad = 0;
    int32_t nb = 0, k, q, rb[4];
    uint32_t r, rounds = 0;
    int grew = 1;
    if (!rows) return -1;
    for (r = 0; r < nr; r++) { /* each ring not plain a box (in[r] 1), or left out (RAST__PARTS_NONE) */
        const int32_t c = rows[3 * r + 2], ne = c < 0 ? ~c : c;
        all += (uint32_t)ne;
        in[r] = 0;
        if (c >= 0 || !ne) continue;
        bad += (uint32_t)ne;
        in[r] = RAST__PARTS_NONE; /* (its winding number 0 off its edges, all on one vertical) */
        if (cols[2 * r] > cols[2 * r + 1]) continue;
        if (nb >= most) return -1;
        bx[4 * nb] = cols[2 * r];
        bx[4 * nb + 1] = rows[3 * r];
        bx[4 * nb + 2] = cols[2 * r + 1];
        bx[4 * nb + 3] = rows[3 * r + 1];
        in[r] = (unsigned char)(++nb); /* (box nb - 1 for now: numbered at the end) */
    }
    while (grew) {
        /* two boxes that meet made one, until none do */
        for (k = 0; k < nb; k++)
            for (q = k + 1; q < nb; q++)
                if (rast__pl_meet(bx + 4 * k, bx + 4 * q)) {
                    int32_t i;
                    for (i = 0; i < 2; i++) {
                        bx[4 * k + i] = bx[4 * q + i] < bx[4 * k + i] ? bx[4 * q + i] : bx[4 * k + i];
                        bx[4 * k + 2 + i] = bx[4 * q + 2 + i] > bx[4 * k + 2 + i] ? bx[4 * q + 2 + i] : bx[4 * k + 2 + i];
                    }
                    for (i = 0; i < 4; i++) bx[4 * q + i] = bx[4 * (nb - 1) + i];
                    nb--;
                    k = -1; /* (box k grew: every pair again) */
                    break;
                }
        /* each ring left that meets a box: in it, the box grown to hold it */
        grew = 0;
        for (r = 0; r < nr; r++) {
            const int32_t c = rows[3 * r + 2];
            if (in[r] || !c || c == -1 || cols[2 * r] > cols[2 * r + 1]) continue; /* (-1: ~0, no edges) */
            rb[0] = cols[2 * r];
            rb[1] = rows[3 * r];
            rb[2] = cols[2 * r + 1];
            rb[3] = rows[3 * r + 1];
            for (k = 0; k < nb; k++)
                if (rast__pl_meet(rb, bx + 4 * k)) {
                    int32_t i;
                    for (i = 0; i < 2; i++) {
                        bx[4 * k + i] = rb[i] < bx[4 * k + i] ? rb[i] : bx[4 * k + i];
                        bx[4 * k + 2 + i] = rb[2 + i] > bx[4 * k + 2 + i] ? rb[2 + i] : bx[4 * k + 2 + i];
                    }
                    in[r] = 1;
                    grew = 1;
                    break;
                }
        }
        if (grew && ++rounds > RAST__PARTS_ROUNDS) return -1;
    }
    /* each ring in a box: the box's number + 1; the edges in boxes */
    for (r = 0; r < nr; r++) {
        const int32_t c = rows[3 * r + 2];
        if (!in[r] || in[r] == RAST__PARTS_NONE) continue;
        bad += (uint32_t)(c < 0 ? 0 : c); /* (those not plain counted above) */
        rb[0] = cols[2 * r];
        rb[1] = rows[3 * r];
        rb[2] = cols[2 * r + 1];
        rb[3] = rows[3 * r + 1];
        for (k = 0; k < nb && !rast__pl_meet(rb, bx + 4 * k); k++) {
        }
        if (k == nb) return -1; /* (cannot be: its box is in one) */
        in[r] = (unsigned char)(k + 1);
    }
    return bad * 2 <= all ? nb : -1;
}
/* ---- shared borders --------------------------------------------------------
 *
 * A map's countries share their borders: two rings run along one segment
 * the opposite ways.  Two such edges add nothing to the winding number
 * anywhere (a ray crosses both or neither, the opposite ways), so the
 * polygon with each such pair dropped has the winding number of the
 * original off its edges, and the same coverage under either rule.  The
 * edges that remain still end at each point as many as start there; where
 * each point starts one of them, they join into rings one way only.  When
 * that polygon is plain (rast__pb_plain), its accumulation is the
 * coverage of the original (docs/coverage.md): a map of 289 countries,
 * 10,365 vertices, keeps the 5,010 edges of its coasts, 128 rings (1.5 M
 * instructions here, 1.6 M the test of what is left, 2.3 M swept, 4.0 M
 * its accumulation: 8.7 M for "area", 9.4 M swept, 9.8 M before).  Else "area"
 * goes on as before.  The room: the points kept and their rings' sizes
 * (8 and 4/3 bytes an edge for 3/4 of the edges) stay taken for the
 * accumulation, whose own room is then 32 bytes an edge kept; the
 * tables here about 29 bytes a point at most, all within what "area"
 * counts for the polygon (36 a point past the edges' records). */

/* The hash of the segment between keys lo < hi (or of a point: lo = hi):
 * its slot in a table of 2^k <= 2^25 the bits from 40 up, its tag bits 24
 * to 30 (a slot holds an edge, below 2^24, and its segment's tag) */
static inline uint64_t rast__pb_hash(uint64_t lo, uint64_t hi)
{
    return lo * UINT64_C(0x9E3779B97F4A7C15) + hi * UINT64_C(0xC2B2AE3D27D4EB4F);
}

/* A table of 2^k >= 3n / 2 int32 slots, all -1, into *size; NULL when
 * there is no room */
static int32_t *rast__pb_table(rast__arena *a, uint32_t n, uint32_t *size)
{
    int32_t *t;
    *size = 16;
    while (*size < n + n / 2) *size <<= 1;
    t = (int32_t *)rast__take(a, (size_t)*size * sizeof(int32_t));
    if (t) memset(t, 0xFF, (size_t)*size * sizeof(int32_t));
    return t;
}

/* Is the polygon that rast__cov_borders keeps (np points, each ring's
 * vertices distinct from the next's) plain?  By its chains
 * (rast__pl_chains) as one part of all its rings, else (room or budget)
 * by the sweep of edges (rast__pl_plain, condition 3 in it): the map of
 * rast__cov_borders' comment, 5,010 points in 128 rings, 1.6 M
 * instructions (the extremes' sort 0.2 M), 2.3 M swept.  Its budget is 16
 * chains' steps a vertex, not the parts' 4: the map's coasts take 4.0 a
 * vertex (at 4, cbench_scale's map seeds 0-3 left 52 to 64 of about
 * 20,300 steps), and at 16 the chains given up cost less than the sweep. */
static int rast__pb_plain(const rast_polygon *kept, uint32_t np, rast__arena arena)
{
    rast__arena room = arena;
    const uint32_t nr = kept->nrings;
    uint32_t *pf = (uint32_t *)rast__take(&room, (size_t)nr * sizeof(uint32_t));
    uint32_t *lv = (uint32_t *)rast__take(&room, (size_t)nr * sizeof(uint32_t));
    int32_t *rg = (int32_t *)rast__take(&room, (size_t)nr * sizeof(int32_t));
    uint32_t r, i, base;
    if (pf && lv && rg) {
        int t;
        for (r = 0, base = 0; r < nr; base += kept->ring_sizes[r], r++) {
            const rast_point *p = kept->points + base;
            uint32_t l = 0;
            for (i = 1; i < kept->ring_sizes[r]; i++) /* (its least vertex in the order (x, then y), the first) */
                if (p[i].x < p[l].x || (p[i].x == p[l].x && p[i].y < p[l].y)) l = i;
            pf[r] = base;
            lv[r] = l;
            rg[r] = (int32_t)r;
        }
        t = rast__pl_chains(kept, pf, lv, rg, nr, np, 16, room);
        if (t >= 0) return t;
    }
    return rast__pl_plain(kept, np, arena, 1);
}

int rast__cov_borders(const rast_polygon *poly, uint32_t npoints, rast__arena *arena, rast_polygon *out)
{
    const int64_t lim = RAST_COORD_MAX;
    const rast_point *const p = poly->points;
    const uint32_t cap = npoints / 4 * 3; /* (more edges left: not worth it, nor room for the accumulation) */
    rast_point *pts = (rast_point *)rast__take(arena, (size_t)cap * sizeof(rast_point));
    uint32_t *sizes = (uint32_t *)rast__take(arena, ((size_t)cap / 3 + 1) * sizeof(uint32_t));
    rast__arena room = *arena;
    uint32_t *nx = (uint32_t *)rast__take(&room, (size_t)npoints * sizeof(uint32_t));
    signed char *net = (signed char *)rast__take(&room, npoints);
    uint32_t size, mask, r, i, base, m = 0, nr = 0, np = 0;
    int32_t *slot = rast__pb_table(&room, npoints, &size);
    uint64_t *sk, *ek;
    if (!pts || !sizes || !nx || !net || !slot || npoints < 64) return 0;
    mask = size - 1;
    /* each segment's count, from its lesser end to its greater minus the
     * other way, at its first edge's slot */
    for (r = 0, base = 0; r < poly->nrings; base += poly->ring_sizes[r], r++) {
        const uint32_t n = poly->ring_sizes[r];
        uint64_t a = n ? rast__pk_key(p[base], lim) : 0;
        for (i = base; i < base + n; i++) {
            const uint32_t j = i + 1 < base + n ? i + 1 : base;
            const uint64_t b = rast__pk_key(p[j], lim), lo = a < b ? a : b, hi = a < b ? b : a;
            const uint64_t hh = rast__pb_hash(lo, hi);
            const int32_t tag = (int32_t)(hh >> 24 & 0x7F) << 24;
            uint32_t h = (uint32_t)(hh >> 40) & mask;
            for (nx[i] = j; a != b; h = (h + 1) & mask) {
                const int32_t v = slot[h];
                if (v < 0) {
                    slot[h] = (int32_t)i | tag;
                    net[i] = a < b ? 1 : -1;
                    break;
                }
                if ((v & 0x7F000000) == tag) { /* (the tags equal: the segments may be) */
                    const uint32_t k = (uint32_t)v & 0xFFFFFFu;
                    const uint64_t ka = rast__pk_key(p[k], lim), kb = rast__pk_key(p[nx[k]], lim);
                    if ((ka == lo && kb == hi) || (ka == hi && kb == lo)) {
                        net[k] = (signed char)(net[k] + (a < b ? 1 : -1));
                        if (net[k] > 2 || net[k] < -2) return 0; /* (not plain whatever the rest) */
                        break;
                    }
                }
            }
            a = b;
        }
    }
    /* the edges that remain: their ends' keys, sk[0 .. m) where each
     * starts and ek[] where it ends */
    sk = (uint64_t *)rast__take(&room, (size_t)cap * sizeof(uint64_t));
    ek = (uint64_t *)rast__take(&room, (size_t)cap * sizeof(uint64_t));
    if (!sk || !ek) return 0;
    for (i = 0; i < size; i++) {
        const int32_t k = slot[i] & 0xFFFFFF;
        uint64_t a, b;
        if (slot[i] < 0 || net[k] == 0) continue;
        if (net[k] > 1 || net[k] < -1 || m == cap) return 0;
        a = rast__pk_key(p[k], lim);
        b = rast__pk_key(p[nx[k]], lim);
        sk[m] = (net[k] > 0) == (a < b) ? a : b;
        ek[m++] = (net[k] > 0) == (a < b) ? b : a;
    }
    /* each point's edge that starts there (slot's room again: m <= n) */
    for (size = 16; size < m + m / 2;) size <<= 1;
    mask = size - 1;
    memset(slot, 0xFF, (size_t)size * sizeof(int32_t));
    for (i = 0; i < m; i++) {
        uint32_t h = (uint32_t)(rast__pb_hash(sk[i], sk[i]) >> 40) & mask;
        for (; slot[h] >= 0; h = (h + 1) & mask)
            if (sk[slot[h]] == sk[i]) return 0; /* two edges start at one point */
        slot[h] = (int32_t)i;
    }
    /* the rings: from each edge not yet taken (ek[] 0: no key is), the
     * edge that starts where it ends, until the first comes again */
    for (i = 0; i < m; i++) {
        uint32_t j = i, n = 0;
        if (!ek[i]) continue;
        for (;;) {
            const uint64_t b = ek[j];
            uint32_t h = (uint32_t)(rast__pb_hash(b, b) >> 40) & mask;
            ek[j] = 0;
            pts[np].x = (int32_t)((int64_t)(sk[j] >> 32) - lim - 1);
            pts[np++].y = (int32_t)((int64_t)(uint32_t)sk[j] - lim - 1);
            n++;
            for (; slot[h] >= 0 && sk[slot[h]] != b; h = (h + 1) & mask) {
            }
            if (slot[h] < 0) return 0; /* (no edge starts there: cannot be) */
            j = (uint32_t)slot[h];
            if (j == i) break;
            if (!ek[j]) return 0; /* (cannot be either) */
        }
        if (n < 3 || nr == cap / 3 + 1) return 0;
        sizes[nr++] = n;
    }
    out->points = pts;
    out->ring_sizes = sizes;
    out->nrings = nr;
    return np < npoints && rast__pb_plain(out, np, *arena);
}
#endif
