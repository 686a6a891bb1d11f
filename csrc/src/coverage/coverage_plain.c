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

typedef struct rast__pl {
    const rast_point *pt; /* vertex v starts edge v, which ends at vertex next[v] */
    const uint64_t *key;  /* v's place in the order (x, then y): one integer */
    const uint32_t *next;
    uint32_t *st; /* the sweep's edges, lowest first */
    uint32_t nst;
    uint64_t budget;
} rast__pl;

/* edge k's left and right end (in the order of the keys) */
static void rast__pl_ends(const rast__pl *s, uint32_t k, rast_point *l, rast_point *r)
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
            while (a < mid && b < end) dst[k++] = key[src[b]] < key[src[a]] ? src[b++] : src[a++];
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
    if ((p.x < r.x && p.x < t.x && q.x < r.x && q.x < t.x) ||
        (p.x > r.x && p.x > t.x && q.x > r.x && q.x > t.x) ||
        (p.y < r.y && p.y < t.y && q.y < r.y && q.y < t.y) ||
        (p.y > r.y && p.y > t.y && q.y > r.y && q.y > t.y))
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
    uint32_t lo = 0, hi = s->nst;
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
    if (lo > 0 && !rast__pl_apart(s, s->st[lo - 1], k)) return 0;
    if (lo + 1 < s->nst && !rast__pl_apart(s, k, s->st[lo + 1])) return 0;
    return 1;
}

/* Edge k out of the sweep at its right end: 0 if its neighbours meet */
static int rast__pl_remove(rast__pl *s, uint32_t k)
{
    uint32_t i = 0;
    while (i < s->nst && s->st[i] != k) i++;
    if ((s->budget -= s->nst + 1) > ((uint64_t)1 << 62) || i == s->nst) return 0;
    if (i > 0 && i + 1 < s->nst && !rast__pl_apart(s, s->st[i - 1], s->st[i + 1])) return 0;
    memmove(s->st + i, s->st + i + 1, (size_t)(s->nst - i - 1) * sizeof(uint32_t));
    s->nst--;
    return 1;
}

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

int rast__cov_plain(const rast_polygon *poly, uint32_t npoints, rast__arena arena)
{
    const int64_t lim = RAST_COORD_MAX;
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
    uint32_t r, i, base, n = 0, pos = 0, neg = 0;
    int fast;
    if (!pt || !key || !next || !prev || !ord || !tmp || !run || !first || !box || !dir || npoints == 0)
        return 0;
    for (r = 0, base = 0; r < poly->nrings; base += poly->ring_sizes[r], r++) {
        /* the ring's vertices, each once (edges of length 0 dropped) */
        const uint32_t size = poly->ring_sizes[r];
        first[r] = n;
        for (i = 0; i < size; i++) {
            rast_point a = poly->points[base + i], b = poly->points[base + (i + 1 < size ? i + 1 : 0)];
            if (a.x == b.x && a.y == b.y) continue;
            if (a.x < -lim || a.x > lim || a.y < -lim || a.y > lim) return 0;
            if (n == first[r]) {
                box[4 * r] = box[4 * r + 2] = a.x;
                box[4 * r + 1] = box[4 * r + 3] = a.y;
            }
            if (a.x < box[4 * r]) box[4 * r] = a.x;
            if (a.y < box[4 * r + 1]) box[4 * r + 1] = a.y;
            if (a.x > box[4 * r + 2]) box[4 * r + 2] = a.x;
            if (a.y > box[4 * r + 3]) box[4 * r + 3] = a.y;
            pt[n] = a;
            key[n] = (uint64_t)(a.x + lim + 1) << 32 | (uint64_t)(a.y + lim + 1);
            next[n] = n + 1;
            prev[n] = n - 1;
            n++;
        }
        if (n - first[r] < 3) return 0;
        next[n - 1] = first[r];
        prev[first[r]] = n - 1;
    }
    first[poly->nrings] = n;
    s.pt = pt;
    s.key = key;
    s.next = next;
    s.st = tmp; /* the sweep's array takes tmp's room once the vertices are sorted */
    s.nst = 0;
    s.budget = (uint64_t)npoints * 64 + ((uint64_t)1 << 20);
    fast = rast__pl_convex(pt, first, box, poly->nrings, dir);
    if (!fast) fast = rast__pl_star(pt, first, box, poly->nrings);
    if (fast) return fast > 0; /* (conditions 1 to 3 decided) */
    for (i = 0; i < n; i++) ord[i] = i;
    rast__pl_sort(key, ord, tmp, run, n);
    for (i = 0; i + 1 < n; i++) /* condition 1 */
        if (key[ord[i]] == key[ord[i + 1]]) return 0;
    for (i = 0; i < n; i++) { /* condition 2: at each vertex, its edges that end, then those that start */
        const uint32_t v = ord[i], in = prev[v];
        const int in_ends = key[in] < key[v], out_ends = key[next[v]] < key[v];
        if (in_ends && !rast__pl_remove(&s, in)) return 0;
        if (out_ends && !rast__pl_remove(&s, v)) return 0;
        if (!in_ends && !rast__pl_insert(&s, in)) return 0;
        if (!out_ends && !rast__pl_insert(&s, v)) return 0;
    }
    if (poly->nrings > 1 && (uint64_t)poly->nrings * n > s.budget) return 0;
    for (r = 0; r < poly->nrings; r++) { /* condition 3 */
        uint32_t k, low = first[r];
        int64_t w0 = 0, w1;
        const rast_point p = pt[first[r]];
        for (k = 0; k < poly->nrings; k++) /* (0 from a ring whose box p is outside) */
            if (k != r && p.x >= box[4 * k] && p.y >= box[4 * k + 1] && p.x <= box[4 * k + 2] &&
                p.y <= box[4 * k + 3])
                w0 += rast__pl_winding(&s, first[k], first[k + 1], p);
        for (k = first[r] + 1; k < first[r + 1]; k++) /* the ring's lowest vertex (x, then y) */
            if (key[k] < key[low]) low = k;
        /* at its lowest vertex a ring turns the way it goes round (not 0:
         * both neighbours lie after it, so on one line they would overlap) */
        w1 = w0 + (rast__cross3(pt[prev[low]], pt[low], pt[next[low]]) > 0 ? 1 : -1);
        if (w0 < -1 || w0 > 1 || w1 < -1 || w1 > 1) return 0;
        pos |= w0 == 1 || w1 == 1;
        neg |= w0 == -1 || w1 == -1;
    }
    return !(pos && neg);
}
