/*
 * config.h - which features a build keeps: pay only for what you call.
 *
 * An application that wants a smaller library names the features it uses in
 * a header of its own and compiles the library with
 *     -DRAST_CONFIG_HEADER='"my_rast_conf.h"'
 * (or defines the macros below with -D).  Nothing in the library is edited.
 * Every macro is a bit mask of a public enum's values (bit v: value v kept),
 * or 0/1; a macro left undefined keeps everything, so the default build
 * (no header, no -D) is the whole library.  The header is included after
 * rastrum.h, so it may use the enumerators:
 *
 *     #define RAST_CONFIG_ALGORITHMS (1u << RAST_ALGO_AET)
 *     #define RAST_CONFIG_FORMATS    (1u << RAST_FORMAT_RGB565)
 *     #define RAST_CONFIG_BOUNDARIES 0u
 *     #define RAST_CONFIG_AA_METHODS 0u
 *     #define RAST_CONFIG_SHADING    0
 *     #define RAST_CONFIG_POLYGON64  0
 *
 * A feature left out is cut where the library refers to it (a row of a
 * table, a branch of a dispatch), so that the linker's --gc-sections drops
 * its code; a call that names it gets the status an unknown value of the
 * same argument gets:
 *   RAST_CONFIG_ALGORITHMS       rast_algorithm bits: RAST_E_ALGORITHM
 *   RAST_CONFIG_TRI_ALGORITHMS   rast_tri_algorithm bits: RAST_E_ALGORITHM
 *   RAST_CONFIG_LINE_ALGORITHMS  rast_line_algorithm bits: RAST_E_ALGORITHM
 *   RAST_CONFIG_FORMATS          rast_format bits: RAST_E_FORMAT
 *   RAST_CONFIG_BOUNDARIES       bits of RAST_BOUNDARY_CLOSED and _CONSERVATIVE
 *                                (RAST_BOUNDARY_EXACT is always kept): RAST_E_ARG
 *   RAST_CONFIG_AA_METHODS       rast_aa_method bits; 0 leaves out anti-aliasing
 *                                (and the formats' coverage blending): RAST_E_ARG
 *   RAST_CONFIG_SHADING          0 leaves out the formats' shaded stores
 *                                (Gouraud fills, also anti-aliased): RAST_E_FORMAT
 *   RAST_CONFIG_POLYGON64        0 leaves out 64-bit vertices (rast_polygon64):
 *                                RAST_E_WIDE
 * The entry points an application does not call cost nothing either way:
 * the linker drops them.  What a kept feature computes never depends on
 * the configuration.
 */
#ifndef RAST_CONFIG_H
#define RAST_CONFIG_H

#ifdef RAST_CONFIG_HEADER
#include RAST_CONFIG_HEADER
#endif

#ifndef RAST_CONFIG_ALGORITHMS
#define RAST_CONFIG_ALGORITHMS 0xFFFFFFFFu
#endif
#ifndef RAST_CONFIG_TRI_ALGORITHMS
#define RAST_CONFIG_TRI_ALGORITHMS 0xFFFFFFFFu
#endif
#ifndef RAST_CONFIG_LINE_ALGORITHMS
#define RAST_CONFIG_LINE_ALGORITHMS 0xFFFFFFFFu
#endif
#ifndef RAST_CONFIG_FORMATS
#define RAST_CONFIG_FORMATS 0xFFFFFFFFu
#endif
#ifndef RAST_CONFIG_BOUNDARIES
#define RAST_CONFIG_BOUNDARIES 0xFFFFFFFFu
#endif
#ifndef RAST_CONFIG_AA_METHODS
#define RAST_CONFIG_AA_METHODS 0xFFFFFFFFu
#endif
#ifndef RAST_CONFIG_SHADING
#define RAST_CONFIG_SHADING 1
#endif
#ifndef RAST_CONFIG_POLYGON64
#define RAST_CONFIG_POLYGON64 1
#endif

/* Is value v (an enumerator, or a value already checked against its enum's
 * count) kept in mask m?  A constant when v is: the compiler folds the
 * test, and a table row or branch it guards refers to nothing when it is
 * 0.  The default mask (all bits) is a constant 1 for any v, so that the
 * default build's checks cost nothing. */
#define RAST__HAS(m, v)                                                        \
    ((unsigned long)(m) == 0xFFFFFFFFul ||                                     \
     ((unsigned)(v) < 32u && (((unsigned long)(m) >> (unsigned)(v)) & 1u)))

/* A boundary mode other than RAST_BOUNDARY_EXACT is kept. */
#define RAST__BOUNDARY_MODES                                                   \
    (RAST__HAS(RAST_CONFIG_BOUNDARIES, RAST_BOUNDARY_CLOSED) ||                \
     RAST__HAS(RAST_CONFIG_BOUNDARIES, RAST_BOUNDARY_CONSERVATIVE))
#define RAST__BOUNDARY_KEPT(b)                                                 \
    ((b) == RAST_BOUNDARY_EXACT || RAST__HAS(RAST_CONFIG_BOUNDARIES, (b)))

#endif /* RAST_CONFIG_H */
