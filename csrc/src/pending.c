/*
 * pending.c - entry points declared in rastrum.h whose files have not
 * landed yet.  Each returns RAST_E_ARG.  This file goes when it is empty.
 */
#include "internal.h"

/* triangles (tri_*.c) */
rast_status rast_tri_algorithm_info(rast_tri_algorithm algorithm, const char **name)
{
    (void)algorithm; (void)name;
    return RAST_E_ALGORITHM;
}

rast_status rast_tri_scratch_size(const rast_tri_opts *opts, int32_t width, int32_t height,
                                  size_t *bytes)
{
    (void)opts; (void)width; (void)height; (void)bytes;
    return RAST_E_ARG;
}

rast_status rast_fill_triangles(const rast_target *target, const rast_point *tris, uint32_t ntris,
                                const rast_tri_opts *opts, const void *pixel, void *scratch,
                                size_t scratch_bytes)
{
    (void)target; (void)tris; (void)ntris; (void)opts; (void)pixel; (void)scratch; (void)scratch_bytes;
    return RAST_E_ARG;
}

rast_status rast_fill_triangles_spans(const rast_point *tris, uint32_t ntris,
                                      const rast_tri_opts *opts, const rast_rect *clip,
                                      rast_span_fn span, void *user, void *scratch,
                                      size_t scratch_bytes)
{
    (void)tris; (void)ntris; (void)opts; (void)clip; (void)span; (void)user; (void)scratch;
    (void)scratch_bytes;
    return RAST_E_ARG;
}
