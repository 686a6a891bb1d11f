/*
 * shade_rect.c - Gouraud rectangles: four corner colours, interpolated
 * bilinearly at every sample (seed 001, section 3.2.3, Figure 3-12).
 *
 * The pixels are exactly those of the rectangle's polygon fill (left and
 * top sides in, right and bottom sides out).  In internal units (doubled
 * fixed point, see internal.h) the rectangle is [x0, x0 + W) x
 * [y0, y0 + H) with W, H > 0 once its corners are put in order, and a
 * sample at offsets a = xs - x0, b = ys - y0 (0 <= a < W, 0 <= b < H) has
 * the exact colour N / D with D = W H and
 *     N = W ((H - b) c0 + b c3) + a ((H - b)(c1 - c0) + b (c2 - c3)),
 * c0..c3 the colours at (x0, y0), (x1, y0), (x1, y1), (x0, y1).  N is a
 * convex combination of the corners times D: 0 <= N <= 255 D.  With W, H
 * below 2^27 (RAST_GOURAUD_RECT_MAX_SIZE in input units) D < 2^54 and
 * every product stays below 2^62.
 *
 * Exact: along a row N grows by unit * slope per pixel, so the value
 * floor(N / D + 1/2) is kept as a quotient and a remainder in [0, D) (an
 * integer DDA per channel; no division per pixel).
 *
 * Fixed (the textbook's stepping, in F fraction bits): the left and right
 * sides' colours L and R are stepped per row and the colour C from L to R
 * per pixel, each increment rounded half up to 1/2^F; see the header for
 * the exact recipe the tests replay.
 */
#include "shade_run.h"

static rast_status rast__rect_check(const rast_target *target, rast_point p0, rast_point p1,
                                    const uint8_t *colors, const rast_tri_opts *opts,
                                    const rast_shade_opts *shade, rast__grid *g,
                                    rast_rect *clip)
{
    rast_status st;
    if (!target || !colors || !opts || !shade) return RAST_E_NULL;
    st = rast__grid_init(g, opts->subpixel_bits, opts->sample, opts->rounding, opts->boundary);
    if (st != RAST_OK) return st;
    if (opts->boundary != RAST_BOUNDARY_EXACT) return RAST_E_ARG;
    if ((unsigned)shade->precision > RAST_PRECISION_FLAT) return RAST_E_ARG;
    if (shade->precision == RAST_PRECISION_FIXED &&
        (shade->fraction_bits < 1 || shade->fraction_bits > 16))
        return RAST_E_ARG;
    if (p0.x < -RAST_COORD_MAX || p0.x > RAST_COORD_MAX || p0.y < -RAST_COORD_MAX ||
        p0.y > RAST_COORD_MAX || p1.x < -RAST_COORD_MAX || p1.x > RAST_COORD_MAX ||
        p1.y < -RAST_COORD_MAX || p1.y > RAST_COORD_MAX)
        return RAST_E_RANGE;
    if ((int64_t)p1.x - p0.x > RAST_GOURAUD_RECT_MAX_SIZE ||
        (int64_t)p0.x - p1.x > RAST_GOURAUD_RECT_MAX_SIZE ||
        (int64_t)p1.y - p0.y > RAST_GOURAUD_RECT_MAX_SIZE ||
        (int64_t)p0.y - p1.y > RAST_GOURAUD_RECT_MAX_SIZE)
        return RAST_E_RANGE;
    st = rast__target_check(target, clip);
    if (st != RAST_OK) return st;
    return rast__shade_format(target);
}

/* The bilinear Gouraud painter: what the rectangle's pixels get. */
typedef struct rast__rect_shade {
    const rast_target *target;
    rast__rgba_out out;     /* stored, or blended (rast_fill_rect_gouraud_blend) */
    const uint8_t *colors;  /* as given: FLAT paints corner p0's */
    const rast__grid *g;
    rast_precision prec;
    int32_t F;              /* FIXED: fraction bits */
    int32_t c[4][4];        /* corner k, channel ch, with the corners put in order */
    int64_t X0, Y0, W, H, D;
    int64_t col0, rowtop;   /* the rectangle's first column and row, unclipped */
} rast__rect_shade;

/* Columns [r0, r1) of row j, all inside the rectangle's pixels. */
static void rast__rect_span(const rast__rect_shade *s, int64_t j, int64_t r0, int64_t r1)
{
    const rast__grid *g = s->g;
    const int64_t X0 = s->X0, Y0 = s->Y0, W = s->W, H = s->H, D = s->D;
    unsigned char *p = (unsigned char *)s->target->pixels + (ptrdiff_t)j * s->target->stride;
    unsigned char run[4 * RAST__SHADE_RUN];
    int64_t b = j * g->unit + g->off - Y0;          /* 0 <= b < H */
    /* 0 <= a < W, except under textbook rounding, which owns a first
     * column whose sample is up to unit/2 left of X0 (a < 0): there the
     * bilinear value is extrapolated and may leave 0..255 */
    int64_t a = r0 * g->unit + g->off - X0;
    int64_t i, n = r1 - r0;
    int32_t x = (int32_t)r0, fill = 0, ch;

    /* After each pixel's colour: store the run when it is full or the row
     * ends. */
#define RAST__RECT_EMIT()                                               \
    do {                                                                \
        if (++fill == RAST__SHADE_RUN || i + 1 == n) {                   \
            rast__put_rgba(&s->out, p, x, fill, run);                      \
            x += fill;                                                  \
            fill = 0;                                                   \
        }                                                               \
    } while (0)
    if (s->prec == RAST_PRECISION_FLAT) {
        rast__put_rgba_flat(&s->out, p, x, (int32_t)n, s->colors); /* corner p0, as given */
        return;
    }
    if (s->prec == RAST_PRECISION_EXACT) {
        int64_t q[4], r[4], sq[4], sr[4];
        for (ch = 0; ch < 4; ch++) {
            int64_t slope = (H - b) * (s->c[1][ch] - s->c[0][ch]) + b * (s->c[2][ch] - s->c[3][ch]);
            int64_t t = W * ((H - b) * s->c[0][ch] + b * s->c[3][ch]) + a * slope + D / 2;
            int64_t step = (int64_t)g->unit * slope;
            q[ch] = rast__floordiv(t, D); /* t < 0 only for a < 0 */
            r[ch] = t - q[ch] * D;
            sq[ch] = rast__floordiv(step, D);
            sr[ch] = step - sq[ch] * D;
        }
        for (i = 0; i < n; i++) {
            for (ch = 0; ch < 4; ch++) {
                run[4 * fill + ch] = (unsigned char)(q[ch] < 0 ? 0 : q[ch] > 255 ? 255 : q[ch]);
                q[ch] += sq[ch];
                r[ch] += sr[ch];
                if (r[ch] >= D) {
                    r[ch] -= D;
                    q[ch]++;
                }
            }
            RAST__RECT_EMIT();
        }
        return;
    }
    /* Fixed: see the header.  k rows below the rectangle's first row,
     * m columns right of its first column (unclipped, so that a clip
     * does not change a value). */
    {
        const int32_t F = s->F;
        int64_t first_b = s->rowtop * g->unit + g->off - Y0;
        int64_t first_a = s->col0 * g->unit + g->off - X0;
        int64_t krow = j - s->rowtop, m0 = r0 - s->col0;
        int64_t cf[4], dc[4], half = ((int64_t)1 << F) >> 1, bias = (int64_t)1 << 41;
        for (ch = 0; ch < 4; ch++) {
            const int32_t *c0 = s->c[0], *c1 = s->c[1], *c2 = s->c[2], *c3 = s->c[3];
            int64_t one = (int64_t)1 << F;
            int64_t L = rast__floordiv(2 * (c0[ch] * H + first_b * (c3[ch] - c0[ch])) * one + H, 2 * H) +
                        krow * rast__floordiv(2 * (int64_t)g->unit * (c3[ch] - c0[ch]) * one + H, 2 * H);
            int64_t R = rast__floordiv(2 * (c1[ch] * H + first_b * (c2[ch] - c1[ch])) * one + H, 2 * H) +
                        krow * rast__floordiv(2 * (int64_t)g->unit * (c2[ch] - c1[ch]) * one + H, 2 * H);
            int64_t first = L + rast__floordiv(2 * (R - L) * first_a + W, 2 * W);
            dc[ch] = rast__floordiv(2 * (R - L) * g->unit + W, 2 * W);
            cf[ch] = first + m0 * dc[ch];
        }
        for (i = 0; i < n; i++) {
            for (ch = 0; ch < 4; ch++) {
                /* floor((C + one/2) / one) by a shift of the value made
                 * non-negative by a multiple of one (|C| < 2^40) */
                int64_t t = (int64_t)((uint64_t)(cf[ch] + half + bias) >> F) - (bias >> F);
                run[4 * fill + ch] = (unsigned char)(t < 0 ? 0 : t > 255 ? 255 : t);
                cf[ch] += dc[ch];
            }
            RAST__RECT_EMIT();
        }
    }
#undef RAST__RECT_EMIT
}

/* The painter's full entry. */
static void rast__rect_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__rect_shade *s = (const rast__rect_shade *)user;
    int32_t k;
    for (k = 0; k < n; k++) rast__rect_span(s, y, xs[2 * k], xs[2 * k + 1]);
}

/* rast_fill_rect_gouraud with each run's colours to bput (NULL: stored),
 * as paint.h says. */
rast_status rast__fill_rect_shaded(const rast_target *target, rast_point p0, rast_point p1,
                                   const uint8_t *colors, const rast_tri_opts *opts,
                                   const rast_shade_opts *shade, rast__rgba_put_fn bput,
                                   const void *bctx)
{
    rast__grid g;
    rast_rect clip;
    rast__rect_shade s;
    rast__painter paint;
    int32_t ch, k;
    rast_status st;

    st = rast__rect_check(target, p0, p1, colors, opts, shade, &g, &clip);
    if (st != RAST_OK) return st;
    if (p0.x == p1.x || p0.y == p1.y) return RAST_OK;

    /* Corners in order: (X0, Y0) top left, W and H positive.  Flipping a
     * side swaps the colours attached to it, never a colour's place. */
    {
        static const int swap_x[4] = {1, 0, 3, 2}, swap_y[4] = {3, 2, 1, 0};
        int32_t flip_x = p1.x < p0.x, flip_y = p1.y < p0.y;
        for (k = 0; k < 4; k++) {
            int32_t src = k;
            if (flip_x) src = swap_x[src];
            if (flip_y) src = swap_y[src];
            for (ch = 0; ch < 4; ch++) s.c[k][ch] = colors[4 * src + ch];
        }
        s.X0 = 2 * (int64_t)(flip_x ? p1.x : p0.x);
        s.Y0 = 2 * (int64_t)(flip_y ? p1.y : p0.y);
        s.W = 2 * ((int64_t)p1.x - p0.x);
        s.H = 2 * ((int64_t)p1.y - p0.y);
        if (s.W < 0) s.W = -s.W;
        if (s.H < 0) s.H = -s.H;
    }
    s.target = target;
    rast__rgba_out_init(&s.out, target, bput, bctx);
    s.colors = colors;
    s.g = &g;
    s.prec = shade->precision;
    s.F = shade->precision == RAST_PRECISION_FIXED ? shade->fraction_bits : 0;
    s.D = s.W * s.H;
    s.col0 = rast__cross_col(s.X0, 1, &g);
    s.rowtop = rast__row_at_or_after(s.Y0, &g);
    memset(&paint, 0, sizeof paint);
    paint.full = rast__rect_row;
    paint.user = &s;
    /* The rectangle filler feeds it the rectangle polygon's pixels. */
    rast__rect_fill(s.X0, s.Y0, s.W, s.H, &g, &clip, &paint);
    return RAST_OK;
}

rast_status rast_fill_rect_gouraud(const rast_target *target, rast_point p0, rast_point p1,
                                   const uint8_t *colors, const rast_tri_opts *opts,
                                   const rast_shade_opts *shade)
{
    return rast__fill_rect_shaded(target, p0, p1, colors, opts, shade, NULL, NULL);
}
