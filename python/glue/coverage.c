/* Binding glue of the coverage calls (not part of the core): snapping,
 * scratch lent by the caller (rastpy_scratch, else malloc), and one C
 * call per Python call, writing a whole (height, width) array of uint8,
 * uint16 or uint64 (2^-62 units), or painting the coverage into a target
 * (rast_fill_polygon_aa, rast_fill_triangles_aa,
 * rast_fill_triangles_shaded_aa). */

#include <stdlib.h>
#include <string.h>
#include "coverage.h"

static const int32_t rastpy_cov_size[3] = {1, 2, 8};

/* Where the values go: an array (target NULL: out, format, its clip) or a
 * target painted with `pixel`, or (colors not NULL) shaded with the
 * vertex colours `colors` and `shade`. */
typedef struct rastpy_cov_dest {
    void *out;
    int format;
    rast_rect clip;
    const rast_target *target;
    const void *pixel;
    const uint8_t *colors;
    const rast_shade_opts *shade;
    const rast_blend_opts *blend; /* shaded: blended (rast_fill_triangles_shaded_aa_blend) */
} rastpy_cov_dest;

static long rastpy_coverage(const rastpy_cov_dest *d, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings, int triangles,
                            const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    rast_polygon poly;
    rast_status st;
    size_t need, head;
    unsigned char *mem;
    int32_t *pts;
    void *scratch;
    long bad;
    const rast_rect *clip = d->target ? &d->target->clip : &d->clip;
    ptrdiff_t stride = 0;
    if (!d->target) {
        if (d->format < 0 || d->format > 2) return RAST_E_ARG;
        stride = (ptrdiff_t)(d->clip.x1 - d->clip.x0) * rastpy_cov_size[d->format];
    }
    if (d->colors)
        st = rast_shaded_aa_scratch_size(opts, npoints / 3, clip->x1 - clip->x0,
                                         clip->y1 - clip->y0, &need);
    else
        st = rast_coverage_scratch_size(opts, npoints, clip->x1 - clip->x0, clip->y1 - clip->y0,
                                        &need);
    if (st != RAST_OK) return st;
    /* one block: the snapped points, then (16-byte aligned) the scratch */
    head = ((size_t)npoints * sizeof(rast_point) + 15) & ~(size_t)15;
    if (need > (size_t)-1 - 1 - head) return RASTPY_E_NOMEM;
    if (sc) sc->want = head + need + 1;
    if (sc && sc->buf && head + need + 1 <= sc->size)
        mem = (unsigned char *)sc->buf;
    else if (!(mem = (unsigned char *)malloc(head + need + 1)))
        return RASTPY_E_NOMEM;
    pts = (int32_t *)(void *)mem;
    bad = rastpy_snap_points(xy, npoints, opts->subpixel_bits, pts);
    if (bad >= 0) {
        if (!sc || mem != sc->buf) free(mem);
        return bad + 1;
    }
    scratch = mem + head;
    poly.points = (const rast_point *)(void *)pts;
    poly.ring_sizes = ring_sizes ? ring_sizes : &npoints;
    poly.nrings = ring_sizes ? nrings : 1;
    if (d->colors && d->blend)
        st = rast_fill_triangles_shaded_aa_blend(d->target, poly.points, npoints / 3, d->colors,
                                                 opts, d->shade, d->blend, scratch, need);
    else if (d->colors)
        st = rast_fill_triangles_shaded_aa(d->target, poly.points, npoints / 3, d->colors, opts,
                                           d->shade, scratch, need);
    else if (d->target && triangles)
        st = rast_fill_triangles_aa(d->target, poly.points, npoints / 3, opts, d->pixel, scratch,
                                    need);
    else if (d->target)
        st = rast_fill_polygon_aa(d->target, &poly, opts, d->pixel, scratch, need);
    else if (triangles)
        st = rast_triangles_coverage(poly.points, npoints / 3, opts, clip,
                                     (rast_coverage_format)d->format, d->out, stride, scratch,
                                     need);
    else
        st = rast_polygon_coverage(&poly, opts, clip, (rast_coverage_format)d->format, d->out,
                                   stride, scratch, need);
    if (!sc || mem != sc->buf) free(mem);
    return st;
}

void rastpy_fix62_to_double(void *buf, size_t n)
{
    unsigned char *p = (unsigned char *)buf;
    size_t i;
    for (i = 0; i < n; i++, p += 8) {
        uint64_t u;
        double a;
        memcpy(&u, p, 8);
        a = (double)u * 0x1p-62;
        memcpy(p, &a, 8);
    }
}

static rastpy_cov_dest rastpy_array(void *out, int32_t height, int32_t width, int format)
{
    rastpy_cov_dest d;
    d.out = out;
    d.format = format;
    d.clip.x0 = d.clip.y0 = 0;
    d.clip.x1 = width;
    d.clip.y1 = height;
    d.target = NULL;
    d.pixel = NULL;
    d.colors = NULL;
    d.shade = NULL;
    d.blend = NULL;
    return d;
}

static rastpy_cov_dest rastpy_paint(const rast_target *target, const void *pixel)
{
    rastpy_cov_dest d = rastpy_array(NULL, 0, 0, 0);
    d.target = target;
    d.pixel = pixel;
    return d;
}

long rastpy_polygon_coverage(void *out, int32_t height, int32_t width, int format,
                             const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                             uint32_t nrings, const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    rastpy_cov_dest d = rastpy_array(out, height, width, format);
    return rastpy_coverage(&d, xy, npoints, ring_sizes, nrings, 0, opts, sc);
}

long rastpy_triangles_coverage(void *out, int32_t height, int32_t width, int format,
                               const double *xy, uint32_t ntris, const rast_coverage_opts *opts,
                               rastpy_scratch *sc)
{
    rastpy_cov_dest d = rastpy_array(out, height, width, format);
    return rastpy_coverage(&d, xy, 3 * ntris, NULL, 0, 1, opts, sc);
}

long rastpy_fill_polygon_aa(const rast_target *target, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings,
                            const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target) return RAST_E_NULL;
    d = rastpy_paint(target, pixel);
    return rastpy_coverage(&d, xy, npoints, ring_sizes, nrings, 0, opts, sc);
}

long rastpy_fill_triangles_aa(const rast_target *target, const double *xy, uint32_t ntris,
                              const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target) return RAST_E_NULL;
    d = rastpy_paint(target, pixel);
    return rastpy_coverage(&d, xy, 3 * ntris, NULL, 0, 1, opts, sc);
}

/* Shaded triangles with coverage, blended (opacity, the colours' alpha)
 * or, with blend NULL, stored. */
long rastpy_fill_triangles_shaded_aa_blend(const rast_target *target, const double *xy,
                                           uint32_t ntris, const uint8_t *colors,
                                           const rast_coverage_opts *opts,
                                           const rast_shade_opts *shade,
                                           const rast_blend_opts *blend, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target || !colors || !shade) return RAST_E_NULL;
    d = rastpy_paint(target, NULL);
    d.colors = colors;
    d.shade = shade;
    d.blend = blend;
    return rastpy_coverage(&d, xy, 3 * ntris, NULL, 0, 1, opts, sc);
}

long rastpy_fill_triangles_shaded_aa(const rast_target *target, const double *xy, uint32_t ntris,
                                     const uint8_t *colors, const rast_coverage_opts *opts,
                                     const rast_shade_opts *shade, rastpy_scratch *sc)
{
    return rastpy_fill_triangles_shaded_aa_blend(target, xy, ntris, colors, opts, shade, NULL, sc);
}
