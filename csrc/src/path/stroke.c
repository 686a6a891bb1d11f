/*
 * stroke.c - a path's stroke as rings to fill non-zero (rast_path_stroke;
 * the contract is in rastrum.h under "strokes", the user's page
 * docs/paths.md).
 *
 * Pieces.  Each subpath's flattened polyline (curves at `tolerance`,
 * path/flatten.c, consecutive equal points dropped) gives, with d = b - a
 * a segment's vector and o = N(d) its offset (below): the parallelogram
 * P = a - o, b - o, b + o, a + o; at a vertex v between d1 and d2, on the
 * outer side, p1 = -+N(d1), p2 = -+N(d2): the join J, bevel v, v + s,
 * v + e; miter v, v + s, tip, v + e; round v, v + s, arc vertices, v + e,
 * where (s, e) is (p1, p2) for a counter-clockwise turn (cross(d1, d2) >
 * 0, exact) and (p2, p1) for a clockwise one, so that the sweep s -> e
 * runs counter-clockwise over the outer side; caps C: square b - o, b + x
 * - o, b + x + o, b + o (x: half the width beyond the end), round the half
 * disc b - o, arc, b + o.  Each piece turns counter-clockwise in (x, y)
 * (positive shoelace area) and is star-shaped about v (or b): its
 * vertices' angles about v strictly increase over less than a turn (arc
 * vertices that would not advance are dropped).  So each piece has
 * winding number 1 inside and 0 outside, the sum over pieces is >= 1
 * exactly on their union and 0 elsewhere.  No J where the turn is
 * straight on (d1, d2 the same direction), where the rounded offsets cross
 * (cross(s, e) <= 0) with a bevel, a miter or a turn of less than a
 * quarter, and at a turn back (d2 opposite to d1) with a bevel or miter; a
 * round turn back's J is the half disc v - o1, arc, v + o1.
 *
 * Rings, not pieces.  The pieces are not emitted: one ring per open
 * subpath (and per dash) goes along the right side forward, a - o, b - o
 * for every segment, round the end's cap, back along the left side, b +
 * o, a + o, and round the start's cap; a closed subpath gives two rings,
 * the right side forward and the left side backward (opposite senses: the
 * outer and inner outlines).  At a vertex v, between v -+ o1 and v -+ o2,
 * the side on J's outer side takes J's points strictly between v + s and
 * v + e (its arc, counter-clockwise, or its miter's tip), the other side
 * the pivot v; with no J both sides take the pivot (none where straight
 * on, o1 = o2).  A cap's points strictly between b - o and b + o are C's.
 * A subpath of one point is its dot (below), a ring of its own.
 *
 * Proof that the non-zero region is the same.  Read rings and pieces as
 * sums of directed edges (chains); a point's winding number is additive
 * over chains.  A piece's boundary, P's: (a - o -> b - o) + (b - o -> b +
 * o) + (b + o -> a + o) + (a + o -> a - o); the sides' edges are the
 * rings', so subtract them: what is left of the pieces at v is E = (v -
 * o1 -> v + o1) + (v + o2 -> v - o2) + J, of the ring R at v the two local
 * paths.  Write Z(p, q) = (p -> v) + (v -> q) + (q -> p): for q = 2v - p
 * (p, v, q on a line, v the midpoint: offsets are exact negatives, N(-d)
 * = -N(d)), Z is a flat triangle; its edges cancel pairwise once p -> q
 * is cut at v, so it adds 0 to every point's winding number off its line
 * and, edge by edge, to every filler's crossings (a scanline's crossing of
 * p -> q, half-open in y, is that of p -> v or of v -> q, at the same
 * abscissa).  A spike (p -> q) + (q -> p) likewise.  Case J on the right
 * (t > 0, s = -o1, e = -o2): R = (v - o1 -> mid -> v - o2) + (v + o2 -> v
 * -> v + o1); J = (v -> v - o1 -> mid -> v - o2 -> v); so R - E = (v + o2
 * -> v) + (v -> v + o1) + (v + o1 -> v - o1) + (v - o2 -> v + o2) + (v -
 * o1 -> v) + (v -> v - o2) = Z(v - o1, v + o1) + Z(v + o2, v - o2)
 * rearranged (each Z's three edges are among these six).  Case J on the
 * left (t < 0): the mirror image, the left side made backward from v + o2
 * through mid to v + o1 = J's v + s .. v + e.  No J: R = (v - o1 -> v ->
 * v - o2) + (v + o2 -> v -> v + o1), R - E = Z(v - o1, v + o1) + Z(v +
 * o2, v - o2) again.  A round turn back (o2 = -o1): R = (v - o1 -> arc ->
 * v + o1) + (v - o1 -> v -> v + o1), J = (v - o1 -> arc -> v + o1 -> v -
 * o1), E = 2 (v - o1 -> v + o1) + J, R - E = (v - o1 -> v -> v + o1) - (v
 * - o1 -> v + o1) = a flat Z.  Straight on: o1 = o2 (N depends on the
 * direction only: q in the offset below is the same for d and k d), E =
 * 0, R adds nothing.  Ends: the open ring's cap path b - o -> C's points
 * -> b + o is C's boundary plus (b + o -> b - o), which cancels P's end
 * edge; a butt cap is that edge.  A closed subpath's two rings meet every
 * vertex as above, the closing one at the start included.  Dropped equal
 * points are zero-length edges.  So, at every point off the flat
 * triangles' lines, the rings' winding number EQUALS the pieces' sum:
 * >= 1 exactly on their union, 0 elsewhere, and every filler draws the
 * same region, crossings, U-turns, tiny segments and dashes included
 * (tests/c/test_stroke.c checks it against the old pieces,
 * tests/c/stroke_pieces.h, at the filler's grid).  The rings are not
 * simple: at an inner join the two sides' offsets overlap near v
 * (winding 2 there, as P1 and P2 overlapped), and must for an exact
 * region, because the union's corner, the offsets' intersection, is not
 * on the grid (but see "Inner joins").  Areas:
 * an open ring's shoelace area is the pieces' (>= 0); a closed subpath's
 * inner ring turns clockwise.  Count: the size pass runs the same code.
 *
 * Inner joins (RAST__STROKE_MEET, path.h: the binding's outline).  At a
 * join past the checks above (t != 0, the offsets not crossed) with the
 * inner offsets i1, i2 (o1, o2 where t > 0, -o1, -o2 where t < 0), the
 * inner side's local path v + i1 -> v -> v + i2 may be replaced by the
 * inner edges' meeting point X alone: the ring then goes a + i1 -> X ->
 * b + i2 (or from and to the neighbouring joins' points).  Proof, for the
 * exact X (on both inner edges' lines): the new chain minus the old is,
 * edge by edge (X splits a + i1 -> v + i1 and v + i2 -> b + i2, collinear
 * pieces adding as intervals, whatever the neighbours did to the same
 * edges), minus the boundary of the quadrilateral Q = X, v + i1, v, v +
 * i2, whose winding number is -1, 0 or 1 inside its convex hull and 0
 * outside.  st_meet() takes X only where Q's corners lie in both
 * segments' parallelograms P1 and P2 (convex, so Q's hull does): there
 * the pieces' sum is >= 2.  A point in the quadrilaterals of r joins lies
 * in the r + 1 or more parallelograms of their segments, so its sum is >=
 * r + 1 and stays >= 1 (non-zero); elsewhere nothing changes: the non-zero
 * region is still exactly the pieces' union.  (Q's corners within P1 and
 * P2 is what "X within both segments' reach" must mean: X within P1
 * alone, h tan(phi/2) <= L1, misses v + i2, which reaches h sin(phi)
 * back, past a when L1 is between the two, phi < 90 degrees; |X - v| =
 * h / cos(phi/2) <= L1, L2 implies both.)  X is rounded to nearest per
 * coordinate, as every other point: each of the two edges through it
 * moves by at most sqrt(2)/2 u at X and less along it, so the region is
 * the union's within sqrt(2)/2 u of those edges (tests/c/
 * test_stroke_meet.c checks sample points against the pivot's outline).
 * No loop at such a join (the ring no longer crosses itself there): an
 * exact "area" fill does not pay its sweep there, an accumulator does not
 * count the overlap.  A closed subpath's first vertex keeps its pivot (its
 * ring began with v + i2); a build for size keeps it everywhere.
 *
 * Storing.  The left side is made forward but needed backward: it is
 * stored downwards from the end of the room (the size pass's count, or any
 * room rast__path_stroke_into is given; the rings after it have not been
 * written yet), then moved after the right side; an outer arc on the left
 * is reversed in place.  The right side's next slot and the left's stay
 * apart while the points so far are fewer than the room; past it, the
 * pass stores nothing more and ends RAST_E_SCRATCH.  No heap.
 *
 * Speed.  The round parts' first quarter circle is made once per call
 * (kept in the state when m <= ST_CQ) and walked by quadrant and index, no
 * division per point; the few small helpers a point passes through are
 * inlined (RAST__HOT).  The outline is the same point for point.
 *
 * The offset N(d), proven.  The ideal offset is (-dy, dx) h / L, h =
 * w / 2, L = |d|.  Each coordinate's magnitude is c = w |a| / (2 L) (a =
 * dy or dx) and c^2 = w^2 a^2 / (4 L^2); with q = floor(w^2 a^2 / L^2) =
 * floor((2c)^2) (128-bit product, one division), r = floor(sqrt(q)) =
 * floor(2c) (floor(sqrt(floor(x))) = floor(sqrt(x))), and (r + 1) >> 1 =
 * floor((floor(2c) + 1) / 2) = floor(c + 1/2): c rounded to nearest,
 * exactly.  So each coordinate is off by <= 1/2 u, the offset point by <=
 * sqrt(2)/2 u, and N(-d) = -N(d) exactly (signs applied to magnitudes).
 * The rings' other polygonal vertices are sums of a path vertex and such
 * offsets: within sqrt(2)/2 u of the ideal.  Square caps reuse o turned a
 * quarter (x = (o.y, -o.x)): within sqrt(2) u.
 *
 * The miter.  The limit: SVG's ratio 1/sin(theta/2) <= L, that is
 * L^2 (1 + cos phi) >= 2, phi the turn (cos phi = u1.u2 for the unit
 * directions); decided with unit normals N at width 2^30 (exact to
 * 2^-30 relative) in 128 bits: a ratio within ~2^-28 of the limit may go
 * either way.  The tip: v + (p1 + p2) H / (H + p1.p2), H = h^2, which is
 * the offsets' intersection for exact p1, p2 of length h; with the
 * rounded ones it moves by less than (L + 1) u for a ratio <= L.
 *
 * Round parts, proven.  The circle of radius h is drawn through the
 * points h ((m^2 - k^2), 2 k m) / (m^2 + k^2), k = 0 .. m - 1, and their
 * quarter turns (4m points, exactly on the circle before rounding: the
 * rational parametrisation t = k/m, angle 2 atan(t)).  Angle steps are
 * 2 (atan((k+1)/m) - atan(k/m)) <= 2/m, so a chord is within h (2/m)^2 / 8
 * = w / (4 m^2) of its arc, and the rounding adds < 3/4 u (as flatten.c,
 * step 3): the polygon is within w / (4 m^2) + 3/4 u of the circle both
 * ways, <= T (the tolerance, in u) iff w <= m^2 (4T - 3); this file takes
 * m = ceil(sqrt(ceil(w / (4T - 3)))), at most max(1, floor(w / 4)).  That
 * cap keeps neighbouring points >= 2 u apart, so their rounded positions
 * still advance in angle (cross products about the centre stay > 0; the
 * drop rule above then never fires for w >= 8); where it binds (w <
 * 8 / (4T - 3), so w < 8), m >= 1 and the error is at most h (1 - cos
 * (pi/4)) + 3/4 < 2 u for w < 8 with m = 1, w / (4 m^2) + 3/4 < 2 u else:
 * hence max(T, 2 u).  A sector's ends v + s, v + e are offsets as above;
 * its arc points are the circle's points strictly between them.
 *
 * Round parts straddling the circle (RAST__STROKE_ARCS, path.h: the
 * binding's outline).  The same points scaled by 1 + 1/(4 m^2) (exact
 * rationals, then rounded): radius R = h (1 + 1/(4 m^2)), each vertex
 * h / (4 m^2) = w / (8 m^2) outside the circle; a chord of angle step <=
 * 2/m comes nearest the centre at its middle, R cos(1/m) >= R (1 -
 * 1/(2 m^2)) = h (1 - 1/(4 m^2) - 1/(8 m^4)), so within w / (8 m^2) (1 +
 * 1/(2 m^2)) inside it.  With the rounding's 3/4 u the polygon is within T
 * of the circle both ways iff w (2 m^2 + 1) <= 4 m^4 (4T - 3): m the least
 * such (from m^2 >= w / (2 (4T - 3)) up), about 1/sqrt(2) of the m above,
 * at most max(1, floor(w / 4)) as above; where that cap binds the error is
 * below 2 u as above (h / (4 m^2) more, < 1/4 u for w >= 8, h / 4 < 1 u
 * with m = 1 for w < 8).  The points keep their angles, so the sweeps,
 * the drop rule and the proofs above hold as they are; a circle point's
 * coordinate is at most round(R), which st_arc_room() reads from the
 * first quarter's point 0.
 *
 * Dashes.  A segment's length is rounded to whole units, Lr = round(L)
 * (>= 1), and the point at s along it is a + round(d s / Lr) per
 * coordinate: exactly a at s = 0 and b at s = Lr, within 1/2 u per
 * coordinate of the segment.  The pattern's position thus drifts by at
 * most 1/2 u per segment against the exact arc length.
 *
 * Ranges.  Points and offsets are within +-2^27, differences within
 * +-2^29; w^2 < 2^54, a^2 < 2^58: 128-bit products, quotients below 2^58.
 * Every outline vertex is checked against RAST_COORD_MAX as it is made.
 */
#include "path.h"
#include "../base/wide.h"

#define ST_MAXDASH 65536u
/* round parts: the first quarter circle's points kept in the stroker's
 * state (on the stack: 8 ST_CQ bytes) when m <= ST_CQ, else made each time
 * (64: widths to about 64 px at 1/256 px; a build for size keeps 128 B) */
#ifndef ST_CQ
#ifdef __OPTIMIZE_SIZE__
#define ST_CQ 16u
#else
#define ST_CQ 64u
#endif
#endif

/* ---- the output: counted (pts NULL) or stored ---------------------------- */
typedef struct st_vec {
    int64_t x, y;
} st_vec;

/* Two streams of points make a ring: the right side forward ("R", stored
 * in order at the front) and the left side, made forward too ("L") but
 * stored downwards from `top` (the size pass's count: room the rings
 * after this one have not taken yet), so that it lies backward in memory;
 * st_left_flush() moves it down after the front.  A point equal to the
 * last one of its stream is dropped (a zero-length edge). */
#define ST_R 0
#define ST_L 1

typedef struct st_out {
    rast_point *pts;
    uint32_t *sizes;
    uint64_t np, nr; /* points (both streams) and rings so far */
    uint64_t top;    /* stored: room for points (the count's np, or more) */
    uint64_t maxr;   /* stored: room for ring sizes */
    uint64_t nl;     /* left points held at pts[top - nl .. top) */
    st_vec last[2];
    int has[2];
    rast_status err;
} st_out;

static void st_ring_begin(st_out *o)
{
    if (o->pts && o->nr >= o->maxr && o->err == RAST_OK) o->err = RAST_E_SCRATCH;
    if (o->pts && o->err == RAST_OK) o->sizes[o->nr] = 0;
    o->nr++;
    o->has[ST_R] = 0;
}

RAST__HOT void st_emit(st_out *o, int64_t x, int64_t y, int side)
{
    if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX || y < -RAST_COORD_MAX || y > RAST_COORD_MAX) {
        if (o->err == RAST_OK) o->err = RAST_E_RANGE;
        return;
    }
    if (o->has[side] && o->last[side].x == x && o->last[side].y == y) return;
    o->has[side] = 1;
    o->last[side].x = x;
    o->last[side].y = y;
    if (o->np >= RAST_MAX_POINTS) {
        if (o->err == RAST_OK) o->err = RAST_E_TOO_MANY;
        return;
    }
    /* the right side's next slot np - nl and the left's top - 1 - nl stay
     * apart and in the room while np < top (nl <= np) */
    if (o->pts && o->np >= o->top && o->err == RAST_OK) o->err = RAST_E_SCRATCH;
    if (o->pts && o->err == RAST_OK) {
        rast_point *q = side == ST_R ? &o->pts[o->np - o->nl] : &o->pts[o->top - 1 - o->nl];
        q->x = (int32_t)x;
        q->y = (int32_t)y;
        if (side == ST_R) o->sizes[o->nr - 1]++;
    }
    o->np++;
    if (side == ST_L) o->nl++;
}

static void st_put(st_out *o, int64_t x, int64_t y)
{
    st_emit(o, x, y, ST_R);
}

static void st_left_begin(st_out *o)
{
    o->nl = 0;
    o->has[ST_L] = 0;
}

/* The left points made since there were nl0 of them, in memory order
 * reversed (an arc made counter-clockwise that the left side, made
 * forward, takes clockwise). */
static void st_left_reverse(st_out *o, uint64_t nl0)
{
    if (o->pts && o->err == RAST_OK) {
        rast_point *a = o->pts + (o->top - o->nl), *b = o->pts + (o->top - nl0) - 1;
        for (; a < b; a++, b--) {
            rast_point t = *a;
            *a = *b;
            *b = t;
        }
    }
}

/* The left side (backward in memory) after the front: in the current ring
 * (open subpaths), or as a ring of its own (closed ones: the second ring). */
static void st_left_flush(st_out *o, int own_ring)
{
    if (own_ring) st_ring_begin(o);
    if (o->pts && o->err == RAST_OK) {
        memmove(o->pts + (o->np - o->nl), o->pts + (o->top - o->nl), (size_t)o->nl * sizeof(rast_point));
        o->sizes[o->nr - 1] += (uint32_t)o->nl;
    }
    o->nl = 0;
    o->has[ST_R] = 0;
}

/* ---- arithmetic ----------------------------------------------------------- */
/* Is r = floor(c + 1/2), c = wa / (2 sqrt(l2)) >= 0, wa2 = wa^2?  That is
 * r - 1/2 <= c < r + 1/2, squared: (2r - 1)^2 l2 <= wa2 (r >= 1; r = 0:
 * nothing) and wa2 < (2r + 1)^2 l2, exactly in 128 bits (r <= 2^29 + 1,
 * so (2r + 1)^2 < 2^61; l2 < 2^59). */
#ifndef __OPTIMIZE_SIZE__ /* a build for size takes the construction alone (~400 B less) */
static int st_off_is(int64_t r, uint64_t l2, rast__i128 wa2)
{
    int64_t hi = 2 * r + 1, lo = 2 * r - 1;
    if (r < 0 || rast__i128_cmp(wa2, rast__i128_mul(hi * hi, (int64_t)l2)) >= 0) return 0;
    return r == 0 || rast__i128_cmp(rast__i128_mul(lo * lo, (int64_t)l2), wa2) <= 0;
}
#endif

/* round(w |a| / (2 sqrt(l2))) with a's sign (the file's comment), lf =
 * floor(sqrt(l2)) >= 1.  The guess round(w |a| / (2 lf)) is the answer or
 * next to it but for short segments (lf <= L < lf + 1: it is off by less
 * than w / (2 lf) + 1); st_off_is() decides, exactly, which, and the
 * file's construction (floor(w^2 a^2 / l2), a 128-bit division and a
 * root) is left for the guesses it refuses: the same value either way. */
static int64_t st_off_coord(int64_t a, uint64_t l2, uint32_t lf, int64_t w)
{
    int64_t q, r;
    uint64_t mag = a < 0 ? (uint64_t)(-a) : (uint64_t)a;
#ifndef __OPTIMIZE_SIZE__
    int64_t wa = w * (int64_t)mag; /* < 2^30 2^29 */
    rast__i128 wa2 = rast__i128_mul(wa, wa);
    r = (wa + (int64_t)lf) / (2 * (int64_t)lf);
    if (st_off_is(r, l2, wa2)) return a < 0 ? -r : r;
    if (st_off_is(r - 1, l2, wa2)) return a < 0 ? 1 - r : r - 1;
    if (st_off_is(r + 1, l2, wa2)) return a < 0 ? -r - 1 : r + 1;
#else
    (void)lf;
#endif
    {
        rast__i128 num = rast__i128_mul(w * w, (int64_t)(mag * mag));
        rast__wide_floordiv(num, (int64_t)l2, &q, &r);
        r = (int64_t)((rast__isqrt_floor((uint64_t)q) + 1) >> 1);
    }
    return a < 0 ? -r : r;
}

/* N(d): the left offset (-dy, dx) w / (2 |d|), rounded per coordinate. */
static st_vec st_normal(st_vec d, int64_t w)
{
    uint64_t l2 = (uint64_t)(d.x * d.x) + (uint64_t)(d.y * d.y);
#ifndef __OPTIMIZE_SIZE__
    uint32_t lf = rast__isqrt_floor(l2);
#else
    uint32_t lf = 0;
#endif
    st_vec o;
    o.x = st_off_coord(-d.y, l2, lf, w);
    o.y = st_off_coord(d.x, l2, lf, w);
    return o;
}

RAST__HOT int64_t st_cross(st_vec a, st_vec b)
{
    return a.x * b.y - a.y * b.x;
}

/* floor(num / den + 1/2) for den > 0 */
static int64_t st_round_div128(rast__i128 num, int64_t den)
{
    int64_t q, r;
    num = rast__i128_add(rast__i128_shl(num, 1), rast__i128_from(den));
    rast__wide_floordiv(num, 2 * den, &q, &r);
    return q;
}

static int64_t st_round_div(int64_t num, int64_t den)
{
    return rast__floordiv(2 * num + den, 2 * den);
}

/* ---- the stroker's state ------------------------------------------------------ */
typedef struct st_ctx {
    const rast_stroke_style *style;
    int64_t w;
    uint32_t m; /* round parts: 4m points on the circle */
    int cached; /* cq holds the first quarter's points (m <= ST_CQ) */
    int meet;   /* RAST__STROKE_MEET (path.h) */
    int wide;   /* RAST__STROKE_ARCS (path.h): the circle's points at radius h (1 + 1/(4 m^2)) */
    int32_t cq[2 * ST_CQ];
    st_out out;
    /* the pen: one open or closed polyline */
    uint32_t n;           /* distinct points so far */
    st_vec p0, prev, dfirst, dprev, ofirst, oprev, hint;
    int has_hint;
} st_ctx;

#ifndef __OPTIMIZE_SIZE__
/* The first quarter's point k on the wider circle (RAST__STROKE_ARCS):
 * h (4m^2 + 1) / (4m^2) ((m^2 - k^2), 2km) / (m^2 + k^2), rounded (out of
 * line: the walk's inlined st_quarter_point() stays small). */
static st_vec st_quarter_wide(const st_ctx *c, uint32_t k)
{
    int64_t m = c->m, kk = k, den = 8 * m * m * (m * m + kk * kk), big = c->w * (4 * m * m + 1); /* < 2^58, 2^56 */
    st_vec p;
    p.x = st_round_div128(rast__i128_mul(big, m * m - kk * kk), den);
    p.y = st_round_div128(rast__i128_mul(big, 2 * kk * m), den);
    return p;
}
#endif

/* The first quarter's point k (0 .. m - 1), relative to the centre. */
RAST__HOT st_vec st_quarter_point(const st_ctx *c, uint32_t k)
{
    st_vec p;
    if (c->cached) {
        p.x = c->cq[2 * k];
        p.y = c->cq[2 * k + 1];
    } else {
        int64_t m = c->m, kk = k, den = 2 * (m * m + kk * kk);
#ifndef __OPTIMIZE_SIZE__
        if (c->wide) return st_quarter_wide(c, k);
#endif
        p.x = st_round_div(c->w * (m * m - kk * kk), den);
        p.y = st_round_div(c->w * (2 * kk * m), den);
    }
    return p;
}

/* The circle's point q m + k (quadrant q, 0 .. 3, and k < m), relative to
 * the centre: the first quarter's point k turned q quarters. */
RAST__HOT st_vec st_circle_qk(const st_ctx *c, uint32_t q, uint32_t k)
{
    st_vec p = st_quarter_point(c, k), r;
    switch (q & 3u) {
    case 0: r = p; break;
    case 1: r.x = -p.y; r.y = p.x; break;
    case 2: r.x = -p.x; r.y = -p.y; break;
    default: r.x = p.y; r.y = -p.x; break;
    }
    return r;
}

/* The circle's point j (0 .. 4m - 1), relative to the centre. */
static st_vec st_circle_point(const st_ctx *c, uint32_t j)
{
    return st_circle_qk(c, j / c->m, j % c->m);
}

/* A walk round the circle's points: the point j = q m + k and its index
 * parts, stepped without a division. */
typedef struct st_walk {
    uint32_t q, k;
    st_vec p;
} st_walk;

static void st_walk_at(const st_ctx *c, st_walk *wk, uint32_t j)
{
    wk->q = j / c->m;
    wk->k = j % c->m;
    wk->p = st_circle_qk(c, wk->q, wk->k);
}

RAST__HOT void st_walk_next(const st_ctx *c, st_walk *wk)
{
    if (++wk->k == c->m) {
        wk->k = 0;
        wk->q = (wk->q + 1) & 3u;
    }
    wk->p = st_circle_qk(c, wk->q, wk->k);
}

RAST__HOT int st_in_sweep(st_vec s, st_vec p, st_vec e)
{
    return st_cross(s, p) > 0 && st_cross(p, e) > 0;
}

/* The first of the circle's points strictly counter-clockwise after s
 * within a half turn (cross(s, p) > 0, the point before it not): a guess
 * from s's quadrant and a binary search in it, then steps to the exact
 * answer (the guess only saves time). */
static uint32_t st_after(const st_ctx *c, st_vec s)
{
    uint32_t m = c->m, n4 = 4 * m, q, lo, hi, g, k;
    if (s.x > 0 && s.y >= 0)
        q = 0;
    else if (s.x <= 0 && s.y > 0)
        q = 1;
    else if (s.x < 0 && s.y <= 0)
        q = 2;
    else
        q = 3;
    lo = 0;
    hi = m; /* the first k < m in the quadrant after s, else m */
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (st_cross(s, st_circle_qk(c, q, mid)) > 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    g = (q * m + lo) % n4;
    for (k = 0; k < n4; k++) {
        if (st_cross(s, st_circle_point(c, g)) > 0) {
            uint32_t b = (g + n4 - 1) % n4;
            if (st_cross(s, st_circle_point(c, b)) <= 0) break;
            g = b;
        } else {
            g = (g + 1) % n4;
        }
    }
    return g;
}

#ifndef __OPTIMIZE_SIZE__ /* a build for size emits every arc point through st_emit (~1 KB less) */
/* Can an arc about v (at most the circle's 4m points) skip st_emit's
 * checks (and walk the first quarter's points kept in the state)?  Its points are within the range (each coordinate of the
 * circle's points is a rounding of at most h, so at most round(h) =
 * floor((w + 1) / 2) from v's), fewer than RAST_MAX_POINTS and the room
 * (stored: np + 4m <= top) make, and no error is pending. */
static int st_arc_room(const st_ctx *c, st_vec v)
{
    const st_out *o = &c->out;
    int64_t r, n4 = 4 * (int64_t)c->m;
    if (!c->cached || o->err != RAST_OK || o->np + (uint64_t)n4 > RAST_MAX_POINTS) return 0;
    r = c->cq[0]; /* the radius rounded, the largest coordinate: round(h) or round(h (1 + 1/(4m^2))) */
    if (o->pts && o->np + (uint64_t)n4 > o->top) return 0;
    return v.x - r >= -RAST_COORD_MAX && v.x + r <= RAST_COORD_MAX && v.y - r >= -RAST_COORD_MAX &&
           v.y + r <= RAST_COORD_MAX;
}
#endif

/* The circle's points strictly between s and e counter-clockwise (the
 * sweep s -> e at most a half turn, or past it by a rounding's angle),
 * each advancing in angle.
 *
 * Only the points the sweep needs are visited.  The circle's points
 * strictly advance in angle (above), so those in the open sweep (the
 * intersection of the half turns after s and before e, two arcs of a half
 * turn each: one arc) are consecutive, and they are among the half turn
 * H after s, which starts at st_after(s).  A sweep under a half turn
 * (cross(s, e) > 0) is an initial part of H: empty if H's first point is
 * not in it; a longer one leaves out at most H's first points (within a
 * rounding's angle of s), stepped over.  The points are those the
 * whole circle's scan took, in the same order. */
static void st_arc(st_ctx *c, st_vec v, st_vec s, st_vec e, int side)
{
    uint32_t n4 = 4 * c->m, t;
    st_vec last = s;
    st_walk wk;
    st_walk_at(c, &wk, st_after(c, s));
    if (!st_in_sweep(s, wk.p, e)) {
        if (st_cross(s, e) > 0) return; /* under a half turn: nothing in it */
        for (t = 1; t < n4 && !st_in_sweep(s, wk.p, e); t++) st_walk_next(c, &wk);
    }
#ifndef __OPTIMIZE_SIZE__
    if (st_arc_room(c, v)) { /* st_emit's checks made once for the arc */
        st_out *o = &c->out;
        rast_point *q = NULL;
        uint64_t kept = 0;
        int down = side == ST_L;
        /* the walk by quadrant qd and index k, the point the first
         * quarter's (a, b) = cq[k] turned: x = sx a', y = sy b' with (a',
         * b') = (a, b) in quadrants 0 and 2, (b, a) in 1 and 3 */
        uint32_t m = c->m, k = wk.k, qd = wk.q, ix = qd & 1u;
        int64_t sx = qd == 1 || qd == 2 ? -1 : 1, sy = qd >= 2 ? -1 : 1;
        int half = st_cross(s, e) > 0;
        st_vec p = wk.p;
        if (o->pts) q = down ? o->pts + (o->top - 1 - o->nl) : o->pts + (o->np - o->nl);
        /* Under a half turn (cross(s, e) > 0, angle phi from s), cross(s,
         * p) > 0 holds for every point the walk meets before its stop:
         * the first point is in the sweep (above), the angle from s grows
         * by less than a quarter a step, and the first point past phi
         * fails cross(p, e) > 0 (angles phi .. phi + pi); so the test of
         * e alone stops where st_in_sweep() stops. */
        for (t = 0; t < n4 && (half ? st_cross(p, e) > 0 : st_in_sweep(s, p, e)); t++) {
            if (st_cross(last, p) > 0) {
                int64_t x = v.x + p.x, y = v.y + p.y;
                /* only the first can equal the side's last point: the
                 * others differ from the one before (cross > 0) */
                if (kept || !o->has[side] || o->last[side].x != x || o->last[side].y != y) {
                    if (q) {
                        q->x = (int32_t)x;
                        q->y = (int32_t)y;
                        q = down ? q - 1 : q + 1;
                    }
                    kept++;
                }
                last = p;
            }
            if (++k == m) {
                k = 0;
                qd = (qd + 1) & 3u;
                ix = qd & 1u;
                sx = qd == 1 || qd == 2 ? -1 : 1;
                sy = qd >= 2 ? -1 : 1;
            }
            p.x = sx * c->cq[2 * k + ix];
            p.y = sy * c->cq[2 * k + 1 - ix];
        }
        if (kept) {
            o->has[side] = 1;
            o->last[side].x = v.x + last.x;
            o->last[side].y = v.y + last.y;
            o->np += kept;
            if (down)
                o->nl += kept;
            else if (o->pts)
                o->sizes[o->nr - 1] += (uint32_t)kept;
        }
        return;
    }
#endif
    for (t = 0; t < n4 && st_in_sweep(s, wk.p, e); t++) {
        if (st_cross(last, wk.p) > 0) {
            st_emit(&c->out, v.x + wk.p.x, v.y + wk.p.y, side);
            last = wk.p;
        }
        st_walk_next(c, &wk);
    }
}

static st_vec st_neg(st_vec a)
{
    a.x = -a.x;
    a.y = -a.y;
    return a;
}

/* A cap's points strictly between b - o and b + o (the ring's own points
 * on either side), the path arriving at b along d (o = N(d)). */
static void st_cap(st_ctx *c, st_vec b, st_vec d)
{
    st_vec o = st_normal(d, c->w), x;
    if (c->style->cap == RAST_CAP_SQUARE) {
        x.x = o.y;
        x.y = -o.x;
        st_put(&c->out, b.x + x.x - o.x, b.y + x.y - o.y);
        st_put(&c->out, b.x + x.x + o.x, b.y + x.y + o.y);
    } else if (c->style->cap == RAST_CAP_ROUND) {
        st_arc(c, b, st_neg(o), o, ST_R); /* the half disc beyond b */
    }
}

/* A zero-length subpath at p: a ring of its own. */
static void st_dot(st_ctx *c, st_vec p)
{
    if (c->style->cap == RAST_CAP_ROUND) {
        uint32_t n4 = 4 * c->m, j;
        st_vec last = st_circle_point(c, n4 - 1);
        st_walk wk;
        st_walk_at(c, &wk, 0);
        st_ring_begin(&c->out);
        for (j = 0; j < n4; j++, st_walk_next(c, &wk)) {
            if (st_cross(last, wk.p) > 0) {
                st_put(&c->out, p.x + wk.p.x, p.y + wk.p.y);
                last = wk.p;
            }
        }
    } else if (c->style->cap == RAST_CAP_SQUARE) {
        st_vec d, o;
        if (c->has_hint) {
            d = c->hint;
        } else {
            d.x = 1;
            d.y = 0;
        }
        o = st_normal(d, c->w);
        d.x = -o.y;
        d.y = o.x; /* d turned back: -x of st_cap() */
        st_ring_begin(&c->out);
        st_put(&c->out, p.x + d.x - o.x, p.y + d.y - o.y);
        st_put(&c->out, p.x - d.x - o.x, p.y - d.y - o.y);
        st_put(&c->out, p.x - d.x + o.x, p.y - d.y + o.y);
        st_put(&c->out, p.x + d.x + o.x, p.y + d.y + o.y);
    }
}

/* Is SVG's ratio 1/sin(theta/2) within the limit?  L^2 (1 + u1.u2) >= 2
 * with unit normals at 2^29 (the file's comment). */
static int st_miter_ok(const st_ctx *c, st_vec d1, st_vec d2)
{
    const int64_t W = (int64_t)1 << 30; /* h = 2^29 */
    st_vec u1 = st_normal(d1, W), u2 = st_normal(d2, W);
    int64_t dot = u1.x * u2.x + u1.y * u2.y; /* ~ 2^58 cos phi */
    int64_t l = c->style->miter_limit;
    rast__i128 lhs = rast__i128_mul(l * l, ((int64_t)1 << 58) + dot);
    rast__i128 rhs, diff;
    rhs.hi = (uint64_t)1 << 27; /* 2^91 = 2 * 2^58 * 2^32 */
    rhs.lo = 0;
    diff = rast__i128_add(lhs, rast__i128_neg(rhs));
    return (int64_t)diff.hi >= 0;
}

/* The pivot v on both sides: a join with no piece J (the file's comment). */
static void st_pivot(st_ctx *c, st_vec v)
{
    st_emit(&c->out, v.x, v.y, ST_R);
    st_emit(&c->out, v.x, v.y, ST_L);
}

/* A segment's end points at p (offset o): p - o on the right side, p + o
 * on the left, but for the side `skip` (ST_R, ST_L, or -1: none). */
#ifdef __OPTIMIZE_SIZE__
RAST__APART void st_ends(st_ctx *c, st_vec p, st_vec o, int skip) /* one copy: smaller */
#else
RAST__HOT void st_ends(st_ctx *c, st_vec p, st_vec o, int skip)
#endif
{
    if (skip != ST_R) st_emit(&c->out, p.x - o.x, p.y - o.y, ST_R);
    if (skip != ST_L) st_emit(&c->out, p.x + o.x, p.y + o.y, ST_L);
}

/* The miter's tip relative to v, (p1 + p2) H / (H + p1.p2), H = w^2 / 4,
 * rounded; 0 if H + p1.p2 <= 0 (the file's comment). */
static int st_tip(const st_ctx *c, st_vec p1, st_vec p2, st_vec *tip)
{
    int64_t den = c->w * c->w + 4 * (p1.x * p2.x + p1.y * p2.y);
    if (den <= 0) return 0;
    tip->x = st_round_div128(rast__i128_mul(p1.x + p2.x, c->w * c->w), den);
    tip->y = st_round_div128(rast__i128_mul(p1.y + p2.y, c->w * c->w), den);
    return 1;
}

#ifndef __OPTIMIZE_SIZE__ /* RAST__STROKE_MEET: the binding's outline only (path.h) */
/* Is a <= num / den <= b for den > 0? */
static int st_within(int64_t num, int64_t den, int64_t a, int64_t b)
{
    return num >= a * den && num <= b * den;
}

/* The inner side's meeting point (RAST__STROKE_MEET, path.h; the file's
 * comment "Inner joins"): with t = cross(d1, d2) != 0 and the inner
 * offsets i1, i2 (o1, o2 for a turn counter-clockwise, -o1, -o2 else),
 * the inner edges' lines v + i1 + tau d1 and v + i2 + kappa d2 meet at X
 * = v + i1 + tau d1, tau = cross(i2 - i1, d2) / t, kappa = cross(i2 -
 * i1, d1) / t.  Returns 1 and X - v rounded per coordinate if the
 * quadrilateral v, v + i1, X, v + i2 lies in both segments'
 * parallelograms P1 = {v + a d1 + m o1: -1 <= a <= 0, |m| <= 1} and P2 =
 * {v + b d2 + n o2: 0 <= b <= 1, |n| <= 1} (each convex: its corners
 * suffice, v is in both): X in P1 iff -1 <= tau <= 0, in P2 iff 0 <=
 * kappa <= 1; v + i2 = v + a d1 + m o1 with a = cross(i2, o1) / D1, m =
 * cross(d1, i2) / D1, D1 = cross(d1, o1) (> 0 needed: o1 to the left of
 * d1); v + i1 likewise in P2.  Exact in 64 bits: offsets within 2^27,
 * differences within 2^29, so each cross product is below 2^58 and each
 * bound times a denominator below 2^60; d1 tau's numerator d1 cross(i2 -
 * i1, d2) is below 2^87 (128 bits), the quotient within |d1|. */
static int st_meet(st_vec d1, st_vec d2, st_vec o1, st_vec o2, int64_t t, st_vec *x)
{
    st_vec i1 = t > 0 ? o1 : st_neg(o1), i2 = t > 0 ? o2 : st_neg(o2), di;
    int64_t T = t, A, K, D1 = st_cross(d1, o1), D2 = st_cross(d2, o2);
    di.x = i2.x - i1.x;
    di.y = i2.y - i1.y;
    A = st_cross(di, d2);
    K = st_cross(di, d1);
    if (T < 0) {
        T = -T;
        A = -A;
        K = -K;
    }
    if (D1 <= 0 || D2 <= 0 || !st_within(A, T, -1, 0) || !st_within(K, T, 0, 1)) return 0;
    if (!st_within(st_cross(i2, o1), D1, -1, 0) || !st_within(st_cross(d1, i2), D1, -1, 1)) return 0;
    if (!st_within(st_cross(i1, o2), D2, 0, 1) || !st_within(st_cross(d2, i1), D2, -1, 1)) return 0;
    x->x = i1.x + st_round_div128(rast__i128_mul(d1.x, A), T);
    x->y = i1.y + st_round_div128(rast__i128_mul(d1.y, A), T);
    return 1;
}
#endif

/* A join at v between d1 (arriving, offset o1) and d2 (leaving, o2): the
 * arriving segment's end points v -+ o1, then the points strictly between
 * v - o1 and v - o2 on the right side and between v + o1 and v + o2 on
 * the left (made forward), then, if `next`, the leaving segment's start
 * points v -+ o2 (not at a closed subpath's start: its ring began with
 * them).  The outer side takes the piece J's points strictly between v +
 * s and v + e (arc or miter tip), the inner side the pivot v, or
 * (RAST__STROKE_MEET, `next`) the inner edges' meeting point alone in
 * place of v + i1, v, v + i2 where st_meet() allows. */
static void st_join(st_ctx *c, st_vec v, st_vec d1, st_vec d2, st_vec o1, st_vec o2, int next)
{
    int64_t t = st_cross(d1, d2), dot = d1.x * d2.x + d1.y * d2.y;
    st_vec p1, p2, s, e, in = v;
    int kind = c->style->join, outer = ST_R, skip = -1, body;
    /* body: 0 nothing (straight on: o1 = o2), 1 the pivot on both sides, 2
     * a round turn back (o2 = -o1: half a disc), 3 the piece J */
    if (t == 0) {
        body = dot > 0 ? 0 : kind == RAST_JOIN_ROUND ? 2 : 1;
    } else {
        if (t > 0) { /* turning counter-clockwise: the outer side is -o, the right */
            p1 = st_neg(o1);
            p2 = st_neg(o2);
            s = p1;
            e = p2;
        } else {
            p1 = o1;
            p2 = o2;
            s = p2;
            e = p1;
            outer = ST_L;
        }
        /* Rounded offsets may cross: near a straight line there is then no
         * gap to fill; near a turn back the sweep passes a half turn by a
         * rounding's angle, which a round join still draws star-shaped (its
         * arc points in both half planes), a bevel or miter not at all. */
        body = st_cross(s, e) <= 0 && (dot >= 0 || kind != RAST_JOIN_ROUND) ? 1 : 3;
#ifndef __OPTIMIZE_SIZE__
        if (body == 3 && c->meet && next && st_meet(d1, d2, o1, o2, t, &in)) {
            in.x += v.x;
            in.y += v.y;
            skip = outer == ST_R ? ST_L : ST_R;
        }
#endif
    }
    st_ends(c, v, o1, skip);
    if (body == 1) {
        st_pivot(c, v);
    } else if (body == 2) {
        st_arc(c, v, st_neg(o1), o1, ST_R);
        st_emit(&c->out, v.x, v.y, ST_L);
    } else if (body == 3) {
        st_emit(&c->out, in.x, in.y, outer == ST_R ? ST_L : ST_R);
        if (kind == RAST_JOIN_ROUND) {
            uint64_t nl0 = c->out.nl;
            st_arc(c, v, s, e, outer);
            if (outer == ST_L) st_left_reverse(&c->out, nl0);
        } else if (kind == RAST_JOIN_MITER && st_miter_ok(c, d1, d2)) {
            st_vec tip;
            if (st_tip(c, p1, p2, &tip)) st_emit(&c->out, v.x + tip.x, v.y + tip.y, outer);
        }
    }
    if (next) st_ends(c, v, o2, skip);
}

/* ---- the pen: one polyline, points streamed in -------------------------- */
static void st_pen_begin(st_ctx *c)
{
    c->n = 0;
}

static void st_pen_point(st_ctx *c, st_vec q)
{
    st_vec d, o;
    if (c->n == 0) {
        c->p0 = c->prev = q;
        c->n = 1;
        return;
    }
    if (q.x == c->prev.x && q.y == c->prev.y) return;
    d.x = q.x - c->prev.x;
    d.y = q.y - c->prev.y;
    o = st_normal(d, c->w);
    if (c->n == 1) {
        st_ring_begin(&c->out);
        st_left_begin(&c->out);
        c->dfirst = d;
        c->ofirst = o;
        st_ends(c, c->prev, o, -1);
    } else { /* the segment before ends, this one starts, at the join */
        st_join(c, c->prev, c->dprev, d, c->oprev, o, 1);
    }
    c->dprev = d;
    c->oprev = o;
    c->prev = q;
    c->n++;
}

static void st_pen_end(st_ctx *c, int closed)
{
    if (c->n == 0) return;
    if (c->n == 1) {
        st_dot(c, c->p0);
    } else if (closed) { /* two rings: the right side, the left one */
        st_vec d;
        d.x = c->p0.x - c->prev.x;
        d.y = c->p0.y - c->prev.y;
        if (d.x || d.y) {
            st_vec o = st_normal(d, c->w);
            st_join(c, c->prev, c->dprev, d, c->oprev, o, 1);
            c->dprev = d;
            c->oprev = o;
        }
        st_join(c, c->p0, c->dprev, c->dfirst, c->oprev, c->ofirst, 0);
        st_left_flush(&c->out, 1);
    } else { /* one ring: right side, end cap, left side back, start cap */
        st_ends(c, c->prev, c->oprev, -1);
        st_cap(c, c->prev, c->dprev);
        st_left_flush(&c->out, 0);
        st_cap(c, c->p0, st_neg(c->dfirst));
    }
    c->n = 0;
}

/* ---- the path's subpaths, flattened on the fly --------------------------- */
typedef struct st_it {
    const rast_path *path;
    int32_t tol;
    uint32_t k, pi;     /* next verb, next point */
    rast_point start, cur;
    rast_point q[4];
    int d;
    uint32_t i, n;      /* a curve in progress: next i (<= n) */
    int closed, drew;
} st_it;

/* Position at the next subpath's start *p0; 0 at the path's end. */
static int st_sub_start(st_it *it, st_vec *p0)
{
    const rast_path *path = it->path;
    it->closed = 0;
    it->drew = 0;
    it->i = it->n = 0;
    for (;;) {
        int v;
        if (it->k >= path->nverbs) return 0;
        v = path->verbs[it->k];
        if (v == RAST_PATH_MOVE) {
            it->start = it->cur = path->points[it->pi++];
            it->k++;
            break;
        }
        if (v != RAST_PATH_CLOSE) {
            it->cur = it->start; /* a drawing verb after CLOSE */
            break;
        }
        it->k++; /* a CLOSE of nothing */
    }
    p0->x = it->start.x;
    p0->y = it->start.y;
    return 1;
}

/* The subpath's next point; 0 at its end (it->closed set by CLOSE). */
static int st_sub_next(st_it *it, st_vec *p)
{
    const rast_path *path = it->path;
    rast_point w;
    int v;
    if (it->i && it->i <= it->n) {
        w = it->i == it->n ? it->q[it->d] : rast__curve_point(it->q, it->d, it->i, it->n);
        it->i++;
        if (it->i > it->n) it->cur = it->q[it->d];
        p->x = w.x;
        p->y = w.y;
        return 1;
    }
    if (it->k >= path->nverbs) return 0;
    v = path->verbs[it->k];
    if (v == RAST_PATH_MOVE) return 0;
    it->k++;
    it->drew = 1;
    if (v == RAST_PATH_CLOSE) {
        it->closed = 1;
        it->cur = it->start;
        return 0;
    }
    if (v == RAST_PATH_LINE) {
        it->cur = path->points[it->pi++];
        p->x = it->cur.x;
        p->y = it->cur.y;
        return 1;
    }
    {
        int j;
        it->d = v;
        it->q[0] = it->cur;
        for (j = 1; j <= v; j++) it->q[j] = path->points[it->pi++];
        it->n = rast__curve_edges(it->q, v, it->tol);
        it->i = 1;
    }
    return st_sub_next(it, p);
}

/* ---- dashes ----------------------------------------------------------------- */
typedef struct st_dash {
    uint32_t i;    /* entry (of 2 ndash when ndash is odd) */
    int64_t left;  /* units left in it */
} st_dash;

static int64_t st_dash_len(const rast_stroke_style *s, uint32_t i)
{
    return s->dash[i % s->ndash];
}

static uint32_t st_dash_count(const rast_stroke_style *s)
{
    return s->ndash & 1u ? 2 * s->ndash : s->ndash;
}

static st_dash st_dash_start(const rast_stroke_style *s)
{
    uint32_t n = st_dash_count(s), i;
    int64_t period = 0, off;
    st_dash st;
    for (i = 0; i < n; i++) period += st_dash_len(s, i);
    off = s->dash_offset % period;
    if (off < 0) off += period;
    i = 0;
    while (off > st_dash_len(s, i) || (off == st_dash_len(s, i) && off > 0)) {
        off -= st_dash_len(s, i);
        i = (i + 1) % n;
    }
    st.i = i;
    st.left = st_dash_len(s, i) - off;
    return st;
}

/* Walk one subpath's points through the pattern.  mode 0: all of it;
 * mode 1: as 0 but the first dash (on at the start) is held back; mode 2:
 * only the points up to the end of the first dash (the held one), fed to
 * a pen already drawing.  Returns 1 if the held first dash ended. */
static int st_dash_walk(st_ctx *c, st_it *it, st_vec start, st_dash ds, int mode, int *on_at_end)
{
    const rast_stroke_style *s = c->style;
    uint32_t n = st_dash_count(s);
    int holding = mode == 1, first_ended = 0;
    st_vec a = start, b;
    int on = !(ds.i & 1u);
    if (on && mode == 0) {
        st_pen_begin(c);
        st_pen_point(c, a);
    }
    for (;;) {
        int more = st_sub_next(it, &b);
        st_vec d;
        int64_t lr, pos = 0;
        if (!more) {
            if (!it->closed || (start.x == a.x && start.y == a.y)) break;
            b = start; /* walk the closing segment, then stop */
            more = 2;
        }
        d.x = b.x - a.x;
        d.y = b.y - a.y;
        if (!d.x && !d.y) continue;
        {
            uint64_t l2 = (uint64_t)(d.x * d.x) + (uint64_t)(d.y * d.y);
            lr = (int64_t)((rast__isqrt_floor(4 * l2) + 1) >> 1);
            if (lr < 1) lr = 1;
        }
        c->hint = d;
        c->has_hint = 1;
        for (;;) {
            st_vec p;
            if (ds.left > lr - pos) {
                ds.left -= lr - pos;
                if (on && !holding) st_pen_point(c, b);
                break;
            }
            pos += ds.left;
            p.x = a.x + st_round_div(d.x * pos, lr);
            p.y = a.y + st_round_div(d.y * pos, lr);
            if (on) {
                if (holding) {
                    holding = 0;
                    first_ended = 1;
                } else {
                    st_pen_point(c, p);
                    st_pen_end(c, 0);
                    if (mode == 2) return 1;
                }
            } else {
                st_pen_begin(c);
                st_pen_point(c, p);
            }
            ds.i = (ds.i + 1) % n;
            ds.left = st_dash_len(s, ds.i);
            on = !on;
        }
        a = b;
        if (more == 2) break;
    }
    *on_at_end = on && !holding;
    if (holding) return 0;
    return first_ended;
}

static void st_stroke_subpath(st_ctx *c, st_it *it, st_vec p0)
{
    const rast_stroke_style *s = c->style;
    c->has_hint = 0;
    if (!s->dash || !s->ndash) {
        st_vec p;
        st_pen_begin(c);
        st_pen_point(c, p0);
        while (st_sub_next(it, &p)) st_pen_point(c, p);
        if (c->n == 1 && !it->drew) c->n = 0; /* a MOVE alone */
        st_pen_end(c, it->closed);
        return;
    }
    {
        st_it saved = *it;
        st_dash ds = st_dash_start(s);
        int on0 = !(ds.i & 1u), on_end = 0, ended;
        /* is the subpath closed?  walk it once uncounted to know: cheap
         * enough, and it keeps the pen's order simple */
        st_it probe = *it;
        st_vec p;
        int closed, any = 0;
        while (st_sub_next(&probe, &p))
            if (p.x != p0.x || p.y != p0.y) any = 1;
        closed = probe.closed;
        if (!any) { /* zero length: a dot where the pattern is on */
            if (probe.drew && on0) {
                st_pen_begin(c);
                st_pen_point(c, p0);
                st_pen_end(c, 0);
            }
            *it = probe;
            return;
        }
        if (!closed || !on0) {
            ended = st_dash_walk(c, it, p0, ds, 0, &on_end);
            if (on_end) st_pen_end(c, 0);
            (void)ended;
            return;
        }
        ended = st_dash_walk(c, it, p0, ds, 1, &on_end);
        if (!ended) { /* one dash all round: the closed subpath */
            st_it again = saved;
            st_pen_begin(c);
            st_pen_point(c, p0);
            while (st_sub_next(&again, &p)) st_pen_point(c, p);
            st_pen_end(c, 1);
            *it = again;
            return;
        }
        if (!on_end) {
            st_pen_begin(c);
            st_pen_point(c, p0);
        }
        {
            st_it again = saved;
            int dummy;
            if (!st_dash_walk(c, &again, p0, ds, 2, &dummy)) st_pen_end(c, 0);
        }
    }
}

/* ---- entry points ------------------------------------------------------------- */
static rast_status st_check_style(const rast_stroke_style *s)
{
    uint32_t k;
    int any = 0;
    if (!s) return RAST_E_NULL;
    if (s->width < 1 || s->width > RAST_COORD_MAX) return RAST_E_ARG;
    if (s->tolerance < 1 || s->tolerance > RAST_COORD_MAX) return RAST_E_ARG;
    if (s->join < 0 || s->join > RAST_JOIN_BEVEL || s->cap < 0 || s->cap > RAST_CAP_SQUARE)
        return RAST_E_ARG;
    if (s->miter_limit < 65536) return RAST_E_ARG;
    if (s->ndash) {
        if (!s->dash) return RAST_E_NULL;
        if (s->ndash > ST_MAXDASH) return RAST_E_ARG;
        for (k = 0; k < s->ndash; k++) {
            if (s->dash[k] < 0) return RAST_E_ARG;
            if (s->dash[k]) any = 1;
        }
        if (!any) return RAST_E_ARG;
    }
    return RAST_OK;
}

static rast_status st_stroke_run(const rast_path *path, const rast_stroke_style *style, unsigned flags,
                                 st_out *out)
{
    rast__flat f;
    st_ctx c;
    st_it it;
    st_vec p0;
    uint64_t need;
    rast_status st = st_check_style(style);
    if (st != RAST_OK) return st;
    memset(&f, 0, sizeof f);
    st = rast__path_flatten(path, style->tolerance, &f); /* checks the path */
    if (st != RAST_OK) return st;
    memset(&c, 0, sizeof c);
    c.style = style;
    c.w = style->width;
#ifndef __OPTIMIZE_SIZE__
    c.meet = (flags & RAST__STROKE_MEET) != 0;
#else
    (void)flags; /* a build for size: the exact outline only (path.h) */
#endif
    need = ((uint64_t)c.w + 4 * (uint64_t)style->tolerance - 4) / (4 * (uint64_t)style->tolerance - 3);
    c.m = rast__isqrt_ceil(need);
#ifndef __OPTIMIZE_SIZE__
    if (flags & RAST__STROKE_ARCS) { /* the least m with w (2m^2 + 1) <= 4 m^4 (4T - 3) ("Round parts") */
        int64_t t4 = 4 * (int64_t)style->tolerance - 3;
        c.wide = 1;
        c.m = rast__isqrt_ceil((need + 1) / 2); /* m^2 >= w / (2 (4T - 3)): m^2 >= need / 2 */
        if (c.m < 1) c.m = 1;
        for (;;) {
            int64_t m2 = (int64_t)c.m * c.m; /* m^2 <= need / 2 + 2m: 4 m^4 < 2^55 */
            if (rast__i128_cmp(rast__i128_mul(c.w, 2 * m2 + 1), rast__i128_mul(4 * m2 * m2, t4)) <= 0) break;
            c.m++;
        }
    }
#endif
    if (c.m > (uint32_t)(c.w / 4)) c.m = (uint32_t)(c.w / 4);
    if (c.m < 1) c.m = 1;
    if (c.m <= ST_CQ) { /* the first quarter's points, made once */
        uint32_t k;
        for (k = 0; k < c.m; k++) {
            st_vec p = st_quarter_point(&c, k);
            c.cq[2 * k] = (int32_t)p.x;
            c.cq[2 * k + 1] = (int32_t)p.y;
        }
        c.cached = 1;
    }
    c.out = *out;
    memset(&it, 0, sizeof it);
    it.path = path;
    it.tol = style->tolerance;
    while (st_sub_start(&it, &p0)) {
        st_stroke_subpath(&c, &it, p0);
        if (c.out.err != RAST_OK) return c.out.err;
    }
    *out = c.out;
    return RAST_OK;
}

/* The outline, counted (points NULL) or stored into the room given (path.h). */
rast_status rast__path_stroke_run(const rast_path *path, const rast_stroke_style *style, unsigned flags,
                                  rast_point *points, uint32_t max_points, uint32_t *ring_sizes,
                                  uint32_t max_rings, uint32_t *npoints, uint32_t *nrings)
{
    st_out o;
    rast_status st;
    if (!npoints || !nrings || (points && !ring_sizes)) return RAST_E_NULL;
    memset(&o, 0, sizeof o);
    if (points) {
        o.pts = points;
        o.top = max_points;
        o.sizes = ring_sizes;
        o.maxr = max_rings;
    }
    st = st_stroke_run(path, style, flags, &o);
    if (st != RAST_OK) return st;
    *npoints = (uint32_t)o.np;
    *nrings = (uint32_t)o.nr;
    return RAST_OK;
}

rast_status rast_path_stroke_size(const rast_path *path, const rast_stroke_style *style,
                                  uint32_t *npoints, uint32_t *nrings)
{
    return rast__path_stroke_run(path, style, 0, NULL, 0, NULL, 0, npoints, nrings);
}

/* One storing pass into the room given (path.h): no count first. */
rast_status rast__path_stroke_into(const rast_path *path, const rast_stroke_style *style, rast_point *points,
                                   uint32_t max_points, uint32_t *ring_sizes, uint32_t max_rings,
                                   uint32_t *npoints, uint32_t *nrings)
{
    if (!points || !ring_sizes) return RAST_E_NULL;
    return rast__path_stroke_run(path, style, 0, points, max_points, ring_sizes, max_rings, npoints, nrings);
}

rast_status rast_path_stroke(const rast_path *path, const rast_stroke_style *style,
                             rast_point *points, uint32_t max_points, uint32_t *ring_sizes,
                             uint32_t max_rings, rast_polygon *polygon)
{
    uint32_t np, nr;
    rast_status st = rast_path_stroke_size(path, style, &np, &nr);
    if (st != RAST_OK) return st;
    if (!points || !ring_sizes || !polygon) return RAST_E_NULL;
    if (np > max_points || nr > max_rings) return RAST_E_SCRATCH;
    /* the room the count gave: the pass below meets no error (the same
     * path, the same code) and fills it exactly */
    st = rast__path_stroke_into(path, style, points, np, ring_sizes, nr, &np, &nr);
    if (st != RAST_OK) return st;
    polygon->points = points;
    polygon->ring_sizes = ring_sizes;
    polygon->nrings = nr;
    return RAST_OK;
}
