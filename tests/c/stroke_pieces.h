/*
 * stroke_pieces.h - the stroker as it was before one ring per subpath
 * (csrc/src/path/stroke.c at c0c86d8, renamed sp_*): one ring per PIECE,
 * a parallelogram per segment, a star-shaped sector per join, a cap per
 * open end, each with winding number 1 inside.  Their union is the
 * reference the new outline's non-zero region must equal bit for bit
 * (tests/c/test_stroke.c, test_rings_equal_pieces).  Frozen: do not
 * change it with stroke.c.
 */
#ifndef RAST_STROKE_PIECES_H
#define RAST_STROKE_PIECES_H

#include "path/path.h"
#include "base/wide.h"


#define SP_MAXDASH 65536u

/* ---- the output: counted (pts NULL) or stored -------------------------- */
typedef struct sp_out {
    rast_point *pts;
    uint32_t *sizes;
    uint64_t np, nr;
    rast_status err;
} sp_out;

static void sp_ring_begin(sp_out *o)
{
    if (o->pts) o->sizes[o->nr] = 0;
    o->nr++;
}

static void sp_put(sp_out *o, int64_t x, int64_t y)
{
    if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX || y < -RAST_COORD_MAX || y > RAST_COORD_MAX) {
        if (o->err == RAST_OK) o->err = RAST_E_RANGE;
        return;
    }
    if (o->np >= RAST_MAX_POINTS) {
        if (o->err == RAST_OK) o->err = RAST_E_TOO_MANY;
        return;
    }
    if (o->pts && o->err == RAST_OK) {
        o->pts[o->np].x = (int32_t)x;
        o->pts[o->np].y = (int32_t)y;
        o->sizes[o->nr - 1]++;
    }
    o->np++;
}

/* ---- arithmetic ----------------------------------------------------------- */
static uint32_t sp_isqrt_floor(uint64_t v)
{
    uint32_t c = rast__isqrt_ceil(v);
    return (uint64_t)c * c > v ? c - 1 : c;
}

/* round(w |a| / (2 sqrt(l2))) with a's sign (the file's comment). */
static int64_t sp_off_coord(int64_t a, uint64_t l2, int64_t w)
{
    int64_t q, r;
    uint64_t mag = a < 0 ? (uint64_t)(-a) : (uint64_t)a;
    rast__i128 num = rast__i128_mul(w * w, (int64_t)(mag * mag));
    rast__wide_floordiv(num, (int64_t)l2, &q, &r);
    mag = (sp_isqrt_floor((uint64_t)q) + 1) >> 1;
    return a < 0 ? -(int64_t)mag : (int64_t)mag;
}

typedef struct sp_vec {
    int64_t x, y;
} sp_vec;

/* N(d): the left offset (-dy, dx) w / (2 |d|), rounded per coordinate. */
static sp_vec sp_normal(sp_vec d, int64_t w)
{
    uint64_t l2 = (uint64_t)(d.x * d.x) + (uint64_t)(d.y * d.y);
    sp_vec o;
    o.x = sp_off_coord(-d.y, l2, w);
    o.y = sp_off_coord(d.x, l2, w);
    return o;
}

static int64_t sp_cross(sp_vec a, sp_vec b)
{
    return a.x * b.y - a.y * b.x;
}

/* floor(num / den + 1/2) for den > 0 */
static int64_t sp_round_div128(rast__i128 num, int64_t den)
{
    int64_t q, r;
    num = rast__i128_add(rast__i128_shl(num, 1), rast__i128_from(den));
    rast__wide_floordiv(num, 2 * den, &q, &r);
    return q;
}

static int64_t sp_round_div(int64_t num, int64_t den)
{
    return rast__floordiv(2 * num + den, 2 * den);
}

/* ---- the stroker's state ------------------------------------------------------ */
typedef struct sp_ctx {
    const rast_stroke_style *style;
    int64_t w;
    uint32_t m; /* round parts: 4m points on the circle */
    sp_out out;
    /* the pen: one open or closed polyline */
    uint32_t n;           /* distinct points so far */
    sp_vec p0, prev, dfirst, dprev, hint;
    int has_hint;
} sp_ctx;

/* The circle's point j (0 .. 4m - 1), relative to the centre. */
static sp_vec sp_circle_point(const sp_ctx *c, uint32_t j)
{
    int64_t m = c->m, k = (int64_t)(j % c->m), den = 2 * (m * m + k * k);
    sp_vec p, r;
    p.x = sp_round_div(c->w * (m * m - k * k), den);
    p.y = sp_round_div(c->w * (2 * k * m), den);
    switch ((j / c->m) & 3u) {
    case 0: r = p; break;
    case 1: r.x = -p.y; r.y = p.x; break;
    case 2: r.x = -p.x; r.y = -p.y; break;
    default: r.x = p.y; r.y = -p.x; break;
    }
    return r;
}

static int sp_in_sweep(sp_vec s, sp_vec p, sp_vec e)
{
    return sp_cross(s, p) > 0 && sp_cross(p, e) > 0;
}

/* The first of the circle's points strictly counter-clockwise after s
 * within a half turn (cross(s, p) > 0, the point before it not): a guess
 * from s's quadrant and a binary search in it, then steps to the exact
 * answer (the guess only saves time). */
static uint32_t sp_after(const sp_ctx *c, sp_vec s)
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
        if (sp_cross(s, sp_circle_point(c, q * m + mid)) > 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    g = (q * m + lo) % n4;
    for (k = 0; k < n4; k++) {
        if (sp_cross(s, sp_circle_point(c, g)) > 0) {
            uint32_t b = (g + n4 - 1) % n4;
            if (sp_cross(s, sp_circle_point(c, b)) <= 0) break;
            g = b;
        } else {
            g = (g + 1) % n4;
        }
    }
    return g;
}

/* The circle's points strictly between s and e counter-clockwise (the
 * sweep s -> e at most a half turn, or past it by a rounding's angle),
 * each advancing in angle.
 *
 * Only the points the sweep needs are visited.  The circle's points
 * strictly advance in angle (above), so those in the open sweep (the
 * intersection of the half turns after s and before e, two arcs of a half
 * turn each: one arc) are consecutive, and they are among the half turn
 * H after s, which starts at sp_after(s).  A sweep under a half turn
 * (cross(s, e) > 0) is an initial part of H: empty if H's first point is
 * not in it; a longer one leaves out at most H's first points (within a
 * rounding's angle of s), stepped over.  The points are those the
 * whole circle's scan took, in the same order. */
static void sp_arc(sp_ctx *c, sp_vec v, sp_vec s, sp_vec e)
{
    uint32_t n4 = 4 * c->m, j = sp_after(c, s), t;
    sp_vec last = s, p = sp_circle_point(c, j);
    if (!sp_in_sweep(s, p, e)) {
        if (sp_cross(s, e) > 0) return; /* under a half turn: nothing in it */
        for (t = 1; t < n4 && !sp_in_sweep(s, p, e); t++) {
            j = (j + 1) % n4;
            p = sp_circle_point(c, j);
        }
    }
    for (t = 0; t < n4 && sp_in_sweep(s, p, e); t++) {
        if (sp_cross(last, p) > 0) {
            sp_put(&c->out, v.x + p.x, v.y + p.y);
            last = p;
        }
        j = (j + 1) % n4;
        p = sp_circle_point(c, j);
    }
}

static void sp_piece4(sp_ctx *c, sp_vec a, sp_vec b, sp_vec o)
{
    sp_ring_begin(&c->out);
    sp_put(&c->out, a.x - o.x, a.y - o.y);
    sp_put(&c->out, b.x - o.x, b.y - o.y);
    sp_put(&c->out, b.x + o.x, b.y + o.y);
    sp_put(&c->out, a.x + o.x, a.y + o.y);
}

/* The half disc beyond b, the path arriving along d (offset o = N(d)). */
static void sp_half_disc(sp_ctx *c, sp_vec b, sp_vec o)
{
    sp_vec mo;
    mo.x = -o.x;
    mo.y = -o.y;
    sp_ring_begin(&c->out);
    sp_put(&c->out, b.x - o.x, b.y - o.y);
    sp_arc(c, b, mo, o);
    sp_put(&c->out, b.x + o.x, b.y + o.y);
}

/* A cap at b, the path arriving along d. */
static void sp_cap(sp_ctx *c, sp_vec b, sp_vec d)
{
    sp_vec o = sp_normal(d, c->w), x;
    if (c->style->cap == RAST_CAP_SQUARE) {
        x.x = o.y;
        x.y = -o.x;
        sp_ring_begin(&c->out);
        sp_put(&c->out, b.x - o.x, b.y - o.y);
        sp_put(&c->out, b.x + x.x - o.x, b.y + x.y - o.y);
        sp_put(&c->out, b.x + x.x + o.x, b.y + x.y + o.y);
        sp_put(&c->out, b.x + o.x, b.y + o.y);
    } else if (c->style->cap == RAST_CAP_ROUND) {
        sp_half_disc(c, b, o);
    }
}

/* A zero-length subpath at p. */
static void sp_dot(sp_ctx *c, sp_vec p)
{
    if (c->style->cap == RAST_CAP_ROUND) {
        uint32_t n4 = 4 * c->m, j;
        sp_vec last = sp_circle_point(c, n4 - 1);
        sp_ring_begin(&c->out);
        for (j = 0; j < n4; j++) {
            sp_vec q = sp_circle_point(c, j);
            if (sp_cross(last, q) > 0) {
                sp_put(&c->out, p.x + q.x, p.y + q.y);
                last = q;
            }
        }
    } else if (c->style->cap == RAST_CAP_SQUARE) {
        sp_vec d, o;
        if (c->has_hint) {
            d = c->hint;
        } else {
            d.x = 1;
            d.y = 0;
        }
        o = sp_normal(d, c->w);
        d.x = -o.y;
        d.y = o.x; /* d turned back: -x of sp_cap() */
        sp_ring_begin(&c->out);
        sp_put(&c->out, p.x + d.x - o.x, p.y + d.y - o.y);
        sp_put(&c->out, p.x - d.x - o.x, p.y - d.y - o.y);
        sp_put(&c->out, p.x - d.x + o.x, p.y - d.y + o.y);
        sp_put(&c->out, p.x + d.x + o.x, p.y + d.y + o.y);
    }
}

/* Is SVG's ratio 1/sin(theta/2) within the limit?  L^2 (1 + u1.u2) >= 2
 * with unit normals at 2^29 (the file's comment). */
static int sp_miter_ok(const sp_ctx *c, sp_vec d1, sp_vec d2)
{
    const int64_t W = (int64_t)1 << 30; /* h = 2^29 */
    sp_vec u1 = sp_normal(d1, W), u2 = sp_normal(d2, W);
    int64_t dot = u1.x * u2.x + u1.y * u2.y; /* ~ 2^58 cos phi */
    int64_t l = c->style->miter_limit;
    rast__i128 lhs = rast__i128_mul(l * l, ((int64_t)1 << 58) + dot);
    rast__i128 rhs, diff;
    rhs.hi = (uint64_t)1 << 27; /* 2^91 = 2 * 2^58 * 2^32 */
    rhs.lo = 0;
    diff = rast__i128_add(lhs, rast__i128_neg(rhs));
    return (int64_t)diff.hi >= 0;
}

/* A join at v between d1 (arriving) and d2 (leaving). */
static void sp_join(sp_ctx *c, sp_vec v, sp_vec d1, sp_vec d2)
{
    int64_t t = sp_cross(d1, d2);
    sp_vec o1 = sp_normal(d1, c->w), o2 = sp_normal(d2, c->w), p1, p2, s, e;
    int kind = c->style->join;
    if (t == 0) {
        if (d1.x * d2.x + d1.y * d2.y > 0) return; /* straight on */
        if (kind == RAST_JOIN_ROUND) sp_half_disc(c, v, o1); /* a turn back: half a disc */
        return;                                       /* miter, bevel: nothing */
    }
    if (t > 0) { /* turning counter-clockwise: the outer side is -o */
        p1.x = -o1.x;
        p1.y = -o1.y;
        p2.x = -o2.x;
        p2.y = -o2.y;
    } else {
        p1 = o1;
        p2 = o2;
    }
    if (t > 0) { /* the outer arc runs counter-clockwise from p1 to p2 */
        s = p1;
        e = p2;
    } else {
        s = p2;
        e = p1;
    }
    /* Rounded offsets may cross: near a straight line there is then no
     * gap to fill; near a turn back the sweep passes a half turn by a
     * rounding's angle, which a round join still draws star-shaped (its
     * arc points in both half planes), a bevel or miter not at all. */
    if (sp_cross(s, e) <= 0 && (d1.x * d2.x + d1.y * d2.y >= 0 || kind != RAST_JOIN_ROUND)) return;
    sp_ring_begin(&c->out);
    sp_put(&c->out, v.x, v.y);
    sp_put(&c->out, v.x + s.x, v.y + s.y);
    if (kind == RAST_JOIN_ROUND) {
        sp_arc(c, v, s, e);
    } else if (kind == RAST_JOIN_MITER && sp_miter_ok(c, d1, d2)) {
        /* tip = v + (p1 + p2) H / (H + p1.p2), H = w^2 / 4 */
        int64_t den = c->w * c->w + 4 * (p1.x * p2.x + p1.y * p2.y);
        if (den > 0) {
            int64_t tx = sp_round_div128(rast__i128_mul(p1.x + p2.x, c->w * c->w), den);
            int64_t ty = sp_round_div128(rast__i128_mul(p1.y + p2.y, c->w * c->w), den);
            sp_put(&c->out, v.x + tx, v.y + ty);
        }
    }
    sp_put(&c->out, v.x + e.x, v.y + e.y);
}

/* ---- the pen: one polyline, points streamed in -------------------------- */
static void sp_pen_begin(sp_ctx *c)
{
    c->n = 0;
}

static void sp_pen_point(sp_ctx *c, sp_vec q)
{
    sp_vec d;
    if (c->n == 0) {
        c->p0 = c->prev = q;
        c->n = 1;
        return;
    }
    if (q.x == c->prev.x && q.y == c->prev.y) return;
    d.x = q.x - c->prev.x;
    d.y = q.y - c->prev.y;
    sp_piece4(c, c->prev, q, sp_normal(d, c->w));
    if (c->n == 1)
        c->dfirst = d;
    else
        sp_join(c, c->prev, c->dprev, d);
    c->dprev = d;
    c->prev = q;
    c->n++;
}

static void sp_pen_end(sp_ctx *c, int closed)
{
    if (c->n == 0) return;
    if (c->n == 1) {
        sp_dot(c, c->p0);
    } else if (closed) {
        sp_vec d;
        d.x = c->p0.x - c->prev.x;
        d.y = c->p0.y - c->prev.y;
        if (d.x || d.y) {
            sp_piece4(c, c->prev, c->p0, sp_normal(d, c->w));
            sp_join(c, c->prev, c->dprev, d);
            c->dprev = d;
        }
        sp_join(c, c->p0, c->dprev, c->dfirst);
    } else {
        sp_vec back;
        back.x = -c->dfirst.x;
        back.y = -c->dfirst.y;
        sp_cap(c, c->p0, back);
        sp_cap(c, c->prev, c->dprev);
    }
    c->n = 0;
}

/* ---- the path's subpaths, flattened on the fly --------------------------- */
typedef struct sp_it {
    const rast_path *path;
    int32_t tol;
    uint32_t k, pi;     /* next verb, next point */
    rast_point start, cur;
    rast_point q[4];
    int d;
    uint32_t i, n;      /* a curve in progress: next i (<= n) */
    int closed, drew;
} sp_it;

/* Position at the next subpath's start *p0; 0 at the path's end. */
static int sp_sub_start(sp_it *it, sp_vec *p0)
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
static int sp_sub_next(sp_it *it, sp_vec *p)
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
    return sp_sub_next(it, p);
}

/* ---- dashes ----------------------------------------------------------------- */
typedef struct sp_dash {
    uint32_t i;    /* entry (of 2 ndash when ndash is odd) */
    int64_t left;  /* units left in it */
} sp_dash;

static int64_t sp_dash_len(const rast_stroke_style *s, uint32_t i)
{
    return s->dash[i % s->ndash];
}

static uint32_t sp_dash_count(const rast_stroke_style *s)
{
    return s->ndash & 1u ? 2 * s->ndash : s->ndash;
}

static sp_dash sp_dash_start(const rast_stroke_style *s)
{
    uint32_t n = sp_dash_count(s), i;
    int64_t period = 0, off;
    sp_dash st;
    for (i = 0; i < n; i++) period += sp_dash_len(s, i);
    off = s->dash_offset % period;
    if (off < 0) off += period;
    i = 0;
    while (off > sp_dash_len(s, i) || (off == sp_dash_len(s, i) && off > 0)) {
        off -= sp_dash_len(s, i);
        i = (i + 1) % n;
    }
    st.i = i;
    st.left = sp_dash_len(s, i) - off;
    return st;
}

/* Walk one subpath's points through the pattern.  mode 0: all of it;
 * mode 1: as 0 but the first dash (on at the start) is held back; mode 2:
 * only the points up to the end of the first dash (the held one), fed to
 * a pen already drawing.  Returns 1 if the held first dash ended. */
static int sp_dash_walk(sp_ctx *c, sp_it *it, sp_vec start, sp_dash ds, int mode, int *on_at_end)
{
    const rast_stroke_style *s = c->style;
    uint32_t n = sp_dash_count(s);
    int holding = mode == 1, first_ended = 0;
    sp_vec a = start, b;
    int on = !(ds.i & 1u);
    if (on && mode == 0) {
        sp_pen_begin(c);
        sp_pen_point(c, a);
    }
    for (;;) {
        int more = sp_sub_next(it, &b);
        sp_vec d;
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
            lr = (int64_t)((sp_isqrt_floor(4 * l2) + 1) >> 1);
            if (lr < 1) lr = 1;
        }
        c->hint = d;
        c->has_hint = 1;
        for (;;) {
            sp_vec p;
            if (ds.left > lr - pos) {
                ds.left -= lr - pos;
                if (on && !holding) sp_pen_point(c, b);
                break;
            }
            pos += ds.left;
            p.x = a.x + sp_round_div(d.x * pos, lr);
            p.y = a.y + sp_round_div(d.y * pos, lr);
            if (on) {
                if (holding) {
                    holding = 0;
                    first_ended = 1;
                } else {
                    sp_pen_point(c, p);
                    sp_pen_end(c, 0);
                    if (mode == 2) return 1;
                }
            } else {
                sp_pen_begin(c);
                sp_pen_point(c, p);
            }
            ds.i = (ds.i + 1) % n;
            ds.left = sp_dash_len(s, ds.i);
            on = !on;
        }
        a = b;
        if (more == 2) break;
    }
    *on_at_end = on && !holding;
    if (holding) return 0;
    return first_ended;
}

static void sp_stroke_subpath(sp_ctx *c, sp_it *it, sp_vec p0)
{
    const rast_stroke_style *s = c->style;
    c->has_hint = 0;
    if (!s->dash || !s->ndash) {
        sp_vec p;
        sp_pen_begin(c);
        sp_pen_point(c, p0);
        while (sp_sub_next(it, &p)) sp_pen_point(c, p);
        if (c->n == 1 && !it->drew) c->n = 0; /* a MOVE alone */
        sp_pen_end(c, it->closed);
        return;
    }
    {
        sp_it saved = *it;
        sp_dash ds = sp_dash_start(s);
        int on0 = !(ds.i & 1u), on_end = 0, ended;
        /* is the subpath closed?  walk it once uncounted to know: cheap
         * enough, and it keeps the pen's order simple */
        sp_it probe = *it;
        sp_vec p;
        int closed, any = 0;
        while (sp_sub_next(&probe, &p))
            if (p.x != p0.x || p.y != p0.y) any = 1;
        closed = probe.closed;
        if (!any) { /* zero length: a dot where the pattern is on */
            if (probe.drew && on0) {
                sp_pen_begin(c);
                sp_pen_point(c, p0);
                sp_pen_end(c, 0);
            }
            *it = probe;
            return;
        }
        if (!closed || !on0) {
            ended = sp_dash_walk(c, it, p0, ds, 0, &on_end);
            if (on_end) sp_pen_end(c, 0);
            (void)ended;
            return;
        }
        ended = sp_dash_walk(c, it, p0, ds, 1, &on_end);
        if (!ended) { /* one dash all round: the closed subpath */
            sp_it again = saved;
            sp_pen_begin(c);
            sp_pen_point(c, p0);
            while (sp_sub_next(&again, &p)) sp_pen_point(c, p);
            sp_pen_end(c, 1);
            *it = again;
            return;
        }
        if (!on_end) {
            sp_pen_begin(c);
            sp_pen_point(c, p0);
        }
        {
            sp_it again = saved;
            int dummy;
            if (!sp_dash_walk(c, &again, p0, ds, 2, &dummy)) sp_pen_end(c, 0);
        }
    }
}

/* ---- entry points ------------------------------------------------------------- */
static rast_status sp_check_style(const rast_stroke_style *s)
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
        if (s->ndash > SP_MAXDASH) return RAST_E_ARG;
        for (k = 0; k < s->ndash; k++) {
            if (s->dash[k] < 0) return RAST_E_ARG;
            if (s->dash[k]) any = 1;
        }
        if (!any) return RAST_E_ARG;
    }
    return RAST_OK;
}

static rast_status sp_stroke_run(const rast_path *path, const rast_stroke_style *style, sp_out *out)
{
    rast__flat f;
    sp_ctx c;
    sp_it it;
    sp_vec p0;
    uint64_t need;
    rast_status st = sp_check_style(style);
    if (st != RAST_OK) return st;
    memset(&f, 0, sizeof f);
    st = rast__path_flatten(path, style->tolerance, &f); /* checks the path */
    if (st != RAST_OK) return st;
    memset(&c, 0, sizeof c);
    c.style = style;
    c.w = style->width;
    need = ((uint64_t)c.w + 4 * (uint64_t)style->tolerance - 4) / (4 * (uint64_t)style->tolerance - 3);
    c.m = rast__isqrt_ceil(need);
    if (c.m > (uint32_t)(c.w / 4)) c.m = (uint32_t)(c.w / 4);
    if (c.m < 1) c.m = 1;
    c.out = *out;
    memset(&it, 0, sizeof it);
    it.path = path;
    it.tol = style->tolerance;
    while (sp_sub_start(&it, &p0)) {
        sp_stroke_subpath(&c, &it, p0);
        if (c.out.err != RAST_OK) return c.out.err;
    }
    *out = c.out;
    return RAST_OK;
}

static rast_status sp_path_stroke_size(const rast_path *path, const rast_stroke_style *style,
                                  uint32_t *npoints, uint32_t *nrings)
{
    sp_out o;
    rast_status st;
    if (!npoints || !nrings) return RAST_E_NULL;
    memset(&o, 0, sizeof o);
    st = sp_stroke_run(path, style, &o);
    if (st != RAST_OK) return st;
    *npoints = (uint32_t)o.np;
    *nrings = (uint32_t)o.nr;
    return RAST_OK;
}

static rast_status sp_path_stroke(const rast_path *path, const rast_stroke_style *style,
                             rast_point *points, uint32_t max_points, uint32_t *ring_sizes,
                             uint32_t max_rings, rast_polygon *polygon)
{
    sp_out o;
    uint32_t np, nr;
    rast_status st = sp_path_stroke_size(path, style, &np, &nr);
    if (st != RAST_OK) return st;
    if (!points || !ring_sizes || !polygon) return RAST_E_NULL;
    if (np > max_points || nr > max_rings) return RAST_E_SCRATCH;
    memset(&o, 0, sizeof o);
    o.pts = points;
    o.sizes = ring_sizes;
    st = sp_stroke_run(path, style, &o);
    if (st != RAST_OK) return st;
    polygon->points = points;
    polygon->ring_sizes = ring_sizes;
    polygon->nrings = nr;
    return RAST_OK;
}

#endif
