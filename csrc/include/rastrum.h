/*
 * rastrum.h - integer-only, exact polygon and triangle fillers.
 *
 * This is the one public header. Everything a user of librastrum.a,
 * librastrum.so or of the csrc/ sources dropped into a firmware build needs
 * is declared here.
 *
 * ---------------------------------------------------------------------------
 * Conventions (the contract every algorithm keeps; docs/semantics.md)
 * ---------------------------------------------------------------------------
 *
 * Space.  x grows to the right, y grows DOWN.  Pixel (i, j) is column i,
 *         row j and owns the square [i, i+1) x [j, j+1).
 *
 * Samples. A pixel is inside a shape iff its sample point is.  The sample of
 *         pixel (i, j) is (i + o, j + o) with the sample offset o = 1/2
 *         (RAST_SAMPLE_CENTER, pixel centres, the default of GPUs) or o = 0
 *         (RAST_SAMPLE_CORNER, integer points, as the textbook and OpenCV).
 *
 * Units.  Vertices are fixed-point integers in units of 1/2^S pixel, where
 *         S = rast_fill_opts.subpixel_bits (0 <= S <= RAST_MAX_SUBPIXEL_BITS).
 *         Snapping real coordinates to this grid (v_fixed = floor(v*2^S + 1/2))
 *         is the caller's job and the only approximation: from the fixed-point
 *         vertices on, every result is exact.
 *
 * Range.  |x| and |y| of every vertex must be <= RAST_COORD_MAX (fixed-point
 *         units, whatever S is; so S = 8 allows +-524287 pixels, S = 0 allows
 *         +-134217727 pixels).  Inside this range no intermediate product can
 *         overflow int64_t.  A vertex outside it makes the call return
 *         RAST_E_RANGE before anything is written.  The polygon fills also
 *         take 64-bit vertices (rast_point64): S up to 32 and +-2^28 pixels
 *         at every S (RAST_COORD64_MAX(S); the range table under "limits").
 *
 * Edges.  A ring is closed: its edges are (P_k, P_k+1) with P_n = P_0.
 *         A non-horizontal edge (x0,y0)->(x1,y1) crosses sample row yc iff
 *         min(y0,y1) <= yc < max(y0,y1) (top closed, bottom open).
 *         Horizontal edges never cross.  The crossing abscissa is the exact
 *         rational X = x0 + (yc - y0)(x1 - x0)/(y1 - y0); its direction is +1
 *         if y1 > y0, else -1.
 *
 * Rules.  The winding number of sample (xc, yc) is the sum of the directions
 *         of the crossings with X <= xc (spans are left closed, right open).
 *         The sample is inside iff the winding number is odd
 *         (RAST_RULE_EVENODD) or non-zero (RAST_RULE_NONZERO).  Even-odd
 *         ignores orientation; non-zero sums it, so under non-zero a hole
 *         must run the other way round from its outer ring (the textbook's
 *         outer rings counter-clockwise, holes clockwise).
 *
 * Consequences: polygons sharing an edge never both own a sample and never
 * both miss one (watertight); results do not depend on the starting vertex,
 * the ring order, or (even-odd) ring direction; translating the vertices by
 * whole pixels translates the pixels.
 *
 * Memory.  The library never allocates.  Calls that need work memory take a
 * caller-provided `scratch` buffer (aligned to RAST_SCRATCH_ALIGN) whose size
 * rast_scratch_size() computes, or RAST_AET_SCRATCH_BOUND() bounds at compile
 * time.  No global state: every function is thread-safe when its arguments
 * are not shared for writing.
 *
 * Safety. No function writes outside target->clip (itself inside the
 * target), whatever the geometry.  Bad arguments return a negative
 * rast_status and write nothing.
 *
 * ---------------------------------------------------------------------------
 * API tiers and the order of this header
 * ---------------------------------------------------------------------------
 *
 * Stable: everything up to "What may change" at the end, by topic:
 * conventions and units (limits, status codes, geometry), targets and pixel
 * formats, polygons, triangles, lines, coverage and anti-aliasing, shading,
 * scenes drawn band by band, region fill, paths.  Within a major version these
 * keep their names, signatures, layouts and meaning (new enumerators and
 * calls may be added).
 * May change: what follows RAST_STATIC_LINKING_ONLY (declared only when
 * the includer defines it first, as lz4.h's LZ4_STATIC_LINKING_ONLY): the
 * scratch bounds that spell out the fillers' internal layouts, and the
 * building blocks of one consumer (pycocotools' rule).
 * A build may also leave features out (pay for what you call: a
 * RAST_CONFIG_HEADER of the application's own; docs/c.md); a call naming
 * a left-out feature gets the status an unknown value gets.
 */
#ifndef RASTRUM_H
#define RASTRUM_H

#ifndef RAST_CDEF /* the cffi build preprocesses this header with RAST_CDEF */
#include <stddef.h>
#include <stdint.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* RAST_API marks the public symbols; the shared library is built with
 * -fvisibility=hidden so that nothing else is exported. */
#ifndef RAST_API
#if defined(RAST_CDEF)
#define RAST_API
#elif defined(__GNUC__) && __GNUC__ >= 4
#define RAST_API __attribute__((visibility("default")))
#else
#define RAST_API
#endif
#endif

/* ---- version ------------------------------------------------------------
 * MAJOR changes break the API or the ABI, MINOR adds to them, PATCH fixes
 * behaviour without changing them.  The shared library's soname carries
 * MAJOR (librastrum.so.MAJOR). */
#define RAST_VERSION_MAJOR 0
#define RAST_VERSION_MINOR 1
#define RAST_VERSION_PATCH 0
#define RAST_VERSION_NUMBER \
    (RAST_VERSION_MAJOR * 10000 + RAST_VERSION_MINOR * 100 + RAST_VERSION_PATCH)

/* ==========================================================================
 * Conventions and units: limits, status codes, geometry
 * ========================================================================== */

/* ---- limits ---------------------------------------------------------------
 * Constants are enumerators so that both C and the cffi layer see them. */
enum {
    /* Largest |coordinate| of a vertex, in fixed-point units (1/2^S pixel).
     * Internally coordinates are doubled (so that a sample at o = 1/2 is an
     * integer), differences reach 2^29 and a crossing numerator is a sum of
     * two products below 2^58: comfortably inside int64_t. */
    RAST_COORD_MAX = 134217727, /* 2^27 - 1 */
    /* Largest subpixel precision S. */
    RAST_MAX_SUBPIXEL_BITS = 16,
    /* Largest target width or height, in pixels. */
    RAST_MAX_DIM = 1073741823, /* 2^30 - 1 */
    /* Largest number of vertices in one call (keeps every size in range). */
    RAST_MAX_POINTS = 16777216, /* 2^24 */
    /* Alignment, in bytes, that a scratch buffer must have. */
    RAST_SCRATCH_ALIGN = 8,
    /* Bytes of scratch per edge (twice: edge table and AET) and per visible
     * row (a bucket head) for the "aet" filler. */
    RAST_AET_EDGE_BYTES = 48,
    RAST_AET_ROW_BYTES = 4,
    /* Largest subpixel precision S of the 64-bit vertices (rast_point64). */
    RAST_MAX_SUBPIXEL_BITS64 = 32,
    /* Largest |coordinate| of a 64-bit vertex in PIXELS, exclusive: a
     * rast_point64 coordinate v (units 1/2^S pixel) must satisfy
     * |v| <= 2^(S + RAST_COORD64_PIXEL_BITS) - 1 (RAST_COORD64_MAX(S)). */
    RAST_COORD64_PIXEL_BITS = 28
};

/* Largest |coordinate| of a 64-bit vertex at subpixel precision s, in
 * fixed-point units: 2^(s + 28) - 1, just under 2^28 pixels (268,435,456)
 * at every s in 0..RAST_MAX_SUBPIXEL_BITS64.
 *
 * Range table (pixels each side of the origin, exclusive bound):
 *
 *     vertices        S          |coordinate| in pixels     grid step
 *     rast_point      0          < 2^27 = 134,217,728       1
 *     rast_point      8          < 2^19 = 524,288           1/256
 *     rast_point      16         < 2^11 = 2,048             1/65536
 *     rast_point64    0..32      < 2^28 = 268,435,456       1/2^S
 *     rast_point64    24         < 2^28                     1/16,777,216
 *     rast_point64    32         < 2^28                     1/4,294,967,296
 *
 * With 32-bit vertices S + log2(range) <= 27; with 64-bit vertices every
 * S up to 32 keeps the whole 2^28-pixel range (internally up to 2^61 units,
 * products in 128 bits). */
#define RAST_COORD64_MAX(s) (((int64_t)1 << ((s) + RAST_COORD64_PIXEL_BITS)) - 1)

/* Scratch bytes that always suffice for the "aet" algorithm with `npoints`
 * vertices and a clip `height` rows high; usable to size a static array:
 *     static uint64_t work[RAST_AET_SCRATCH_BOUND(64, 240) / 8]; */
#define RAST_AET_SCRATCH_BOUND(npoints, height)                  \
    ((size_t)(npoints) * 2 * RAST_AET_EDGE_BYTES +               \
     ((size_t)(height) + 1) * RAST_AET_ROW_BYTES + RAST_SCRATCH_ALIGN)

/* ---- status codes ----------------------------------------------------------
 * Every function returns one of these (RAST_OK = 0, errors negative), except
 * the three that return a version or a string.  rast_status_str() gives the
 * message.  The list lives once, here, as an X-macro. */
#define RAST_STATUS_LIST(X)                                                    \
    X(RAST_OK, 0, "ok")                                                        \
    X(RAST_E_NULL, -1, "a required pointer argument is NULL")                  \
    X(RAST_E_ARG, -2, "invalid argument")                                      \
    X(RAST_E_RANGE, -3, "a coordinate is outside +-RAST_COORD_MAX (64-bit vertices: +-RAST_COORD64_MAX(S))") \
    X(RAST_E_SUBPIXEL, -4, "subpixel_bits is outside 0..RAST_MAX_SUBPIXEL_BITS") \
    X(RAST_E_SIZE, -5, "width, height or stride is invalid")                   \
    X(RAST_E_FORMAT, -6, "unknown pixel format")                               \
    X(RAST_E_ALGORITHM, -7, "unknown algorithm")                               \
    X(RAST_E_RULE, -8, "fill rule not supported by this algorithm")            \
    X(RAST_E_SCRATCH, -9, "scratch buffer too small")                          \
    X(RAST_E_ALIGN, -10, "scratch buffer is not aligned to RAST_SCRATCH_ALIGN") \
    X(RAST_E_TOO_MANY, -11, "more than RAST_MAX_POINTS vertices")             \
    X(RAST_E_WIDE, -12, "not offered for 64-bit vertices (rast_polygon64: algorithm aet, exact rounding, exact or conservative boundary)") \
    X(RAST_E_WORK, -13, "seed fill stopped: work limit reached or the target changed during the call")

#define RAST__STATUS_ENUM(name, value, text) name = value,
typedef enum rast_status { RAST_STATUS_LIST(RAST__STATUS_ENUM) RAST_STATUS_END_ = 1 } rast_status;
#undef RAST__STATUS_ENUM

/* The runtime version, RAST_VERSION_NUMBER of the library actually linked. */
RAST_API int rast_version_number(void);

/* The message of a status code; "unknown status" for a value not listed.
 * The string is static: never free it. */
RAST_API const char *rast_status_str(rast_status status);

/* ---- geometry: points, rectangles, polygons, spans ------------------------ */

/* A coordinate in fixed point: units of 1/2^S pixel, S the call's
 * subpixel_bits (see Units).  |value| <= RAST_COORD_MAX. */
typedef int32_t rast_fixed;

/* A coordinate of the 64-bit vertices: units of 1/2^S pixel, S up to
 * RAST_MAX_SUBPIXEL_BITS64, |value| <= RAST_COORD64_MAX(S). */
typedef int64_t rast_fixed64;

/* A vertex in fixed point: units of 1/2^S pixel. */
typedef struct rast_point {
    rast_fixed x;
    rast_fixed y;
} rast_point;

/* A pixel rectangle, half open: columns x0 <= i < x1, rows y0 <= j < y1. */
typedef struct rast_rect {
    int32_t x0, y0, x1, y1;
} rast_rect;

/* A polygon: one or more closed rings whose vertices follow each other in
 * `points`: ring 0 is points[0 .. ring_sizes[0]), ring 1 the next
 * ring_sizes[1] points, and so on.  A ring of fewer than 3 points encloses
 * nothing (its edges cancel) and is allowed.  The library only reads it. */
typedef struct rast_polygon {
    const rast_point *points;
    const uint32_t *ring_sizes;
    uint32_t nrings;
} rast_polygon;

/* A vertex with 64-bit fixed-point coordinates: units of 1/2^S pixel for
 * S up to RAST_MAX_SUBPIXEL_BITS64 = 32, |x|, |y| <= RAST_COORD64_MAX(S)
 * (see the range table above).  The precision path for callers whose
 * coordinates are floats at GIS scale: at S = 32 snapping moves a vertex
 * by at most 2^-33 pixel. */
typedef struct rast_point64 {
    rast_fixed64 x;
    rast_fixed64 y;
} rast_point64;

/* A polygon of 64-bit vertices, laid out as rast_polygon. */
typedef struct rast_polygon64 {
    const rast_point64 *points;
    const uint32_t *ring_sizes;
    uint32_t nrings;
} rast_polygon64;

/* A span of samples in row y, columns x0 <= i < x1 (x0 < x1 always). */
typedef void (*rast_span_fn)(void *user, int32_t y, int32_t x0, int32_t x1);

/* ==========================================================================
 * Targets and pixel formats
 * ========================================================================== */

/* ---- targets and pixel formats ------------------------------------------ */

/* Pixel formats: bytes of one pixel, in memory order. */
typedef enum rast_format {
    RAST_FORMAT_GRAY8 = 0,    /* 1 byte; also a 0/1 mask */
    RAST_FORMAT_RGB888 = 1,   /* 3 bytes: R, G, B */
    RAST_FORMAT_RGBA8888 = 2, /* 4 bytes: R, G, B, A */
    RAST_FORMAT_COUNT16 = 3,  /* 2 bytes, a native uint16_t: a fill adds 1 to
                                 each pixel it covers (saturating at 65535) and
                                 ignores the pixel value; overdraw made visible */
    RAST_FORMAT_RGB565 = 4,   /* 2 bytes, a native uint16_t: R in bits 15-11,
                                 G in 10-5, B in 4-0 (TFT displays); pixels
                                 and stride 2-byte aligned */
    RAST_FORMAT_MONO1 = 5,    /* 1 bit, 8 pixels a byte, MSB first: pixel x is
                                 bit 7 - x%8 of byte x/8 of its row (e-paper);
                                 a pixel value is 1 byte, "on" iff not 0 */
    RAST_FORMAT_COUNT_ = 6
} rast_format;

/* A target: a view of caller-owned memory.  pixels points at pixel (0, 0);
 * row j starts `stride` bytes after row j-1 (stride >= width * bytes per
 * pixel; it may be larger, for padding or for a sub-view of a larger image).
 * Nothing outside `clip` is ever read or written; rast_target_init sets the
 * clip to the whole target, and a caller may narrow it (to draw into a band
 * or a window).  A clip that reaches past the target is cut to it.
 * RAST_FORMAT_MONO1 is the exception at the bit level: a byte holding both
 * clip pixels and others is read and written back with the others' bits
 * unchanged (so two threads must not draw into clips sharing a byte). */
typedef struct rast_target {
    void *pixels;
    int32_t width;
    int32_t height;
    int32_t stride;
    rast_format format;
    rast_rect clip;
} rast_target;

/* Bytes of one pixel value of `format` into *bytes (1, 2, 3 or 4): what a
 * `pixel` or `background` argument holds, in the format's own encoding.
 * It is also the memory of one pixel, except for RAST_FORMAT_MONO1, which
 * packs 8 pixels into a byte (see rast_format_stride); its value is one
 * byte, 0 (off) or not 0 (on).
 * RAST_E_FORMAT for an unknown format, RAST_E_NULL if bytes is NULL. */
RAST_API rast_status rast_format_bytes(rast_format format, int32_t *bytes);

/* The fewest bytes a row of `width` pixels of `format` takes, into *bytes:
 * width * bytes per pixel, or ceil(width / 8) for RAST_FORMAT_MONO1 (the
 * smallest valid stride).  Errors: RAST_E_NULL, RAST_E_FORMAT, RAST_E_SIZE
 * (width outside 0..RAST_MAX_DIM, or a row past INT32_MAX bytes). */
RAST_API rast_status rast_format_stride(rast_format format, int32_t width, int32_t *bytes);

/* The pixel value of `format` for the 8-bit colour rgba[0..3] (R, G, B,
 * A), into `pixel` (rast_format_bytes bytes), as the shaded fills store
 * colours: GRAY8 takes R; RGB888 R, G, B; RGBA8888 all four; RGB565 the
 * top 5, 6 and 5 bits of R, G and B (truncation: (R >> 3) << 11 |
 * (G >> 2) << 5 | B >> 3, as a native uint16_t); MONO1 the top bit of R
 * (on iff R >= 128).  Errors: RAST_E_NULL, RAST_E_FORMAT (unknown, or
 * COUNT16, which has no colour). */
RAST_API rast_status rast_pack_color(rast_format format, const uint8_t *rgba, void *pixel);

/* Describe caller-owned memory as a target (see rast_target); clip = whole.
 * width and height in 0..RAST_MAX_DIM pixels, stride in bytes with
 * stride >= rast_format_stride(format, width) and stride * height fitting
 * a ptrdiff_t.
 * pixels may be NULL only when width or height is 0.  RAST_FORMAT_COUNT16
 * and RAST_FORMAT_RGB565 pixels are uint16_t: pixels and stride must be
 * multiples of 2 bytes.  RAST_FORMAT_MONO1 rows need stride >=
 * ceil(width / 8) (rast_format_stride); a fill changes only the bits of
 * the pixels it covers, never the padding bits after column width - 1.
 * Errors: RAST_E_NULL (t, or pixels of a non-empty target), RAST_E_SIZE
 * (also a misaligned 16-bit target), RAST_E_FORMAT; *t is untouched on
 * error. */
RAST_API rast_status rast_target_init(rast_target *t, void *pixels,
                                      int32_t width, int32_t height,
                                      int32_t stride, rast_format format);

/* ==========================================================================
 * Polygons: options, fills, 64-bit vertices, batches
 * ========================================================================== */

/* ---- polygon options ------------------------------------------------------ */

typedef enum rast_fill_rule {
    RAST_RULE_EVENODD = 0, /* inside iff the winding number is odd */
    RAST_RULE_NONZERO = 1  /* inside iff the winding number is not 0 */
} rast_fill_rule;

typedef enum rast_sample {
    RAST_SAMPLE_CORNER = 0, /* samples at (i, j): o = 0 */
    RAST_SAMPLE_CENTER = 1  /* samples at (i + 1/2, j + 1/2): o = 1/2 */
} rast_sample;

/* Polygon algorithms.  All are exact: they give the same pixels. They
 * differ in speed and in work memory (rast_scratch_size()). */
typedef enum rast_algorithm {
    RAST_ALGO_AET = 0,      /* active edge table + bucket edge table (seed 001 3.4) */
    RAST_ALGO_XSCAN = 1,    /* every edge intersected per row, sorted, paired (001 3.4.1) */
    RAST_ALGO_EDGEFILL = 2, /* complement right of each crossing on a mask (001 3.5) */
    RAST_ALGO_FENCE = 3,    /* the same, complementing only up to a fence (001 3.5) */
    RAST_ALGO_EDGEFLAG = 4, /* flag crossings, then sweep each row (003) */
    RAST_ALGO_CROSSING = 5, /* per sample: crossing number (003) */
    RAST_ALGO_WINDING = 6,  /* per sample: winding number, the exact angle sum (003) */
    RAST_ALGO_COUNT_ = 7
} rast_algorithm;

/* Where a crossing falls among the samples of its row.
 * RAST_ROUND_EXACT is DESIGN section 1: a crossing at X counts for sample
 * column i iff X <= i + o.
 * RAST_ROUND_TEXTBOOK reproduces the textbook's worked examples (Example
 * 3-1, Figure 3-19), which round each crossing to the nearest sample column,
 * halves going right: a crossing counts for column i iff
 * floor(X - o + 1/2) <= i, that is iff X < i + o + 1/2.  Rows are as in the
 * exact rule.  The book uses it with o = 0.  It is still watertight (the
 * rounding depends on the edge and the row only) but it is not the exact
 * partition: a pixel whose sample is outside may be filled.  Never the
 * default. */
typedef enum rast_rounding {
    RAST_ROUND_EXACT = 0,
    RAST_ROUND_TEXTBOOK = 1
} rast_rounding;

/* Which pixels the boundary adds to the fill.
 * RAST_BOUNDARY_EXACT: none; the fill is the exact partition (the default).
 * RAST_BOUNDARY_CLOSED: the fill plus the library's outline, the pixels
 *   rast_draw_line() draws for every edge of every ring (same S and sample
 *   offset; lines ignore the rounding mode); what OpenCV and Pillow users
 *   expect of a filled polygon.
 * RAST_BOUNDARY_CONSERVATIVE: the fill plus every pixel whose open square
 *   (i, i+1) x (j, j+1) meets an edge (a closed segment) of the polygon;
 *   for a polygon without zero-area parts that is every pixel its interior
 *   touches, what GDAL's ALL_TOUCHED users expect.  Zero-area parts (a
 *   spike, an edge walked back and forth, two rings cancelling under
 *   even-odd) still touch the pixels they cross.
 * Neither of the last two is watertight: neighbours share their outline. */
typedef enum rast_boundary {
    RAST_BOUNDARY_EXACT = 0,
    RAST_BOUNDARY_CLOSED = 1,
    RAST_BOUNDARY_CONSERVATIVE = 2
} rast_boundary;

/* How to turn vertices into samples.  Zero-initialised means: AET,
 * even-odd, S = 0, samples at integer points, exact rounding, no boundary. */
typedef struct rast_fill_opts {
    rast_algorithm algorithm;
    rast_fill_rule rule;
    int32_t subpixel_bits; /* S, 0..RAST_MAX_SUBPIXEL_BITS */
    rast_sample sample;
    rast_rounding rounding;
    rast_boundary boundary;
} rast_fill_opts;

/* ---- polygon fills ---------------------------------------------------------- */

/* Name ("aet", ...) and supported fill rules of an algorithm: bit r of
 * *rules is set iff rast_fill_rule r is supported.  Either output pointer
 * may be NULL.  RAST_E_ALGORITHM for an unknown algorithm. */
RAST_API rast_status rast_algorithm_info(rast_algorithm algorithm,
                                         const char **name, uint32_t *rules);

/* Scratch bytes that a fill with `opts` needs for a polygon of `npoints`
 * vertices (all rings together) drawn into a clip `width` x `height`
 * pixels.  The size grows with the vertices and the rows (with the clip's
 * pixels for the mask algorithms edgefill, fence and edgeflag: see
 * RAST_EDGEFILL_SCRATCH_BOUND), never with the coordinates.  For those
 * three, a size that would not fit a size_t is given as SIZE_MAX.  Errors: RAST_E_NULL, RAST_E_ALGORITHM, RAST_E_SIZE,
 * RAST_E_TOO_MANY. */
RAST_API rast_status rast_scratch_size(const rast_fill_opts *opts,
                                       uint32_t npoints, int32_t width,
                                       int32_t height, size_t *bytes);

/* Fill a polygon with one pixel value: every pixel of target->clip whose
 * sample is inside (see Conventions) gets the `pixel` value
 * (rast_format_bytes bytes in the format's own encoding: memory order; a
 * native uint16_t for RGB565; 0 or not 0 for MONO1); other pixels are not
 * touched.  RAST_FORMAT_COUNT16 adds 1 to each inside pixel instead
 * (saturating at 65535) and ignores `pixel`, which may then be NULL.  Geometry outside the clip is clipped, not an error.
 * `scratch` (aligned to RAST_SCRATCH_ALIGN, `scratch_bytes` long) must hold
 * rast_scratch_size(opts, npoints, clip width, clip height) bytes; its
 * contents on entry are ignored and on return are undefined.
 * Errors, all returned before anything is written: RAST_E_NULL,
 * RAST_E_RANGE, RAST_E_SUBPIXEL, RAST_E_ALGORITHM, RAST_E_RULE,
 * RAST_E_FORMAT, RAST_E_SCRATCH, RAST_E_ALIGN, RAST_E_TOO_MANY, RAST_E_ARG
 * (a bad sample or rule value). */
RAST_API rast_status rast_fill_polygon(const rast_target *target,
                                       const rast_polygon *polygon,
                                       const rast_fill_opts *opts,
                                       const void *pixel, void *scratch,
                                       size_t scratch_bytes);

/* Like rast_fill_polygon, but every pixel of target->clip is written exactly
 * once: `pixel` where the sample is inside, `background` elsewhere.  The
 * clip's previous contents do not matter, so an uninitialised buffer becomes
 * a complete image in one pass (a mask without a separate clear; a band of
 * rows streamed to a display).  Scratch and errors as rast_fill_polygon;
 * RAST_E_NULL also for a NULL background, RAST_E_FORMAT for a
 * RAST_FORMAT_COUNT16 target (a count has no background).  On error
 * nothing is written. */
RAST_API rast_status rast_fill_polygon_opaque(const rast_target *target,
                                              const rast_polygon *polygon,
                                              const rast_fill_opts *opts,
                                              const void *pixel,
                                              const void *background,
                                              void *scratch,
                                              size_t scratch_bytes);

/* The same coverage as rast_fill_polygon, handed to `span` instead of
 * painted: for each row from top to bottom, the inside samples of the row
 * within `clip`, as spans with x0 < x1 in increasing x order that neither
 * overlap nor touch.  This is the call for firmware that pushes spans to a
 * display controller.  The clip's coordinates must lie in
 * -RAST_MAX_DIM..RAST_MAX_DIM (else RAST_E_SIZE); they may be negative.
 * Scratch and errors as rast_fill_polygon (sized for the clip). */
RAST_API rast_status rast_fill_polygon_spans(const rast_polygon *polygon,
                                             const rast_fill_opts *opts,
                                             const rast_rect *clip,
                                             rast_span_fn span, void *user,
                                             void *scratch,
                                             size_t scratch_bytes);

/* The part of `clip` that a fill of `polygon` with `opts` can paint: every
 * pixel that rast_fill_polygon, rast_fill_polygon_opaque's `pixel` or
 * rast_fill_polygon_spans gives the polygon (with a boundary mode, its
 * edges' pixels too) lies in *bounds, a rectangle inside *clip; it is
 * empty (x0 == x1 and y0 == y1) when there are none.  With the exact
 * boundary it is the box the fillers work in; with the others, the
 * vertices' pixel hull grown by one pixel each side.
 * What it is for: a fill with its clip (target->clip, or the span clip) set
 * to *bounds paints the same pixels and needs only
 * rast_scratch_size(opts, npoints, bounds width, bounds height) bytes of
 * scratch.  For the mask algorithms (edgefill, fence, edgeflag), whose
 * scratch grows with the clip's pixels, that is the polygon's box instead
 * of the clip: a small polygon in a huge clip needs little.  (An opaque
 * fill so cut leaves the pixels outside *bounds to its caller: they are
 * all background.)  The clip's coordinates must lie in
 * -RAST_MAX_DIM..RAST_MAX_DIM; x1 < x0 or y1 < y0 is an empty clip.
 * Errors: RAST_E_NULL, RAST_E_RANGE, RAST_E_TOO_MANY, RAST_E_SIZE (the
 * clip), and the option errors of rast_scratch_size; nothing is written
 * to *bounds on error. */
RAST_API rast_status rast_fill_bounds(const rast_fill_opts *opts,
                                      const rast_polygon *polygon,
                                      const rast_rect *clip,
                                      rast_rect *bounds);

/* ---- 64-bit vertices (poly64.c) ------------------------------------------------
 * The same fills on rast_polygon64: vertices in units of 1/2^S pixel with
 * S = opts->subpixel_bits in 0..RAST_MAX_SUBPIXEL_BITS64 (32) and every
 * |coordinate| <= RAST_COORD64_MAX(S) = 2^(S+28) - 1, that is under 2^28
 * pixels whatever S is.  The rule is the Conventions' rule, exactly, on
 * these vertices: a polygon of rast_point vertices gives the same pixels
 * through either path (same S, same values).  Internally the doubled
 * coordinates reach 2^61 and the first crossing of an edge is a 128-bit
 * numerator (two 64-bit halves, portable C99); the row-to-row walk stays
 * in 64 bits, so a 64-bit fill costs about what a 32-bit one does.
 *
 * What is offered: algorithm RAST_ALGO_AET with either rule, rounding
 * RAST_ROUND_EXACT, boundary RAST_BOUNDARY_EXACT or
 * RAST_BOUNDARY_CONSERVATIVE (GDAL's ALL_TOUCHED; see rast_boundary).
 * Any other algorithm, RAST_ROUND_TEXTBOOK or RAST_BOUNDARY_CLOSED:
 * RAST_E_WIDE.  S outside 0..32: RAST_E_SUBPIXEL.  A coordinate past
 * RAST_COORD64_MAX(S): RAST_E_RANGE.  All checked before anything is
 * written.  Scratch: rast_scratch_size64 (what the AET needs, an edge
 * record per vertex twice and a bucket per clip row, plus the boundary's
 * records in conservative mode: it grows with the vertices and the rows,
 * never with the coordinates). */

/* Scratch bytes of a 64-bit fill with `opts` (checked as the fill checks
 * them: RAST_E_NULL, RAST_E_ALGORITHM, RAST_E_ARG, RAST_E_RULE,
 * RAST_E_SUBPIXEL, RAST_E_WIDE) for `npoints` vertices and a clip
 * `width` x `height` (RAST_E_SIZE, RAST_E_TOO_MANY). */
RAST_API rast_status rast_scratch_size64(const rast_fill_opts *opts, uint32_t npoints,
                                         int32_t width, int32_t height, size_t *bytes);

/* rast_fill_polygon for 64-bit vertices. */
RAST_API rast_status rast_fill_polygon64(const rast_target *target,
                                         const rast_polygon64 *polygon,
                                         const rast_fill_opts *opts, const void *pixel,
                                         void *scratch, size_t scratch_bytes);

/* rast_fill_polygon_opaque for 64-bit vertices. */
RAST_API rast_status rast_fill_polygon64_opaque(const rast_target *target,
                                                const rast_polygon64 *polygon,
                                                const rast_fill_opts *opts,
                                                const void *pixel, const void *background,
                                                void *scratch, size_t scratch_bytes);

/* rast_fill_polygon_spans for 64-bit vertices. */
RAST_API rast_status rast_fill_polygon64_spans(const rast_polygon64 *polygon,
                                               const rast_fill_opts *opts,
                                               const rast_rect *clip, rast_span_fn span,
                                               void *user, void *scratch,
                                               size_t scratch_bytes);

/* rast_fill_bounds for 64-bit vertices: the part of `clip` a fill of
 * `polygon` with `opts` can paint (the exact fill's box, or with the
 * conservative boundary the vertices' pixel hull grown by a pixel).
 * Errors: those of rast_scratch_size64's options, RAST_E_NULL,
 * RAST_E_RANGE, RAST_E_TOO_MANY, RAST_E_SIZE (the clip). */
RAST_API rast_status rast_fill_bounds64(const rast_fill_opts *opts,
                                        const rast_polygon64 *polygon,
                                        const rast_rect *clip, rast_rect *bounds);

/* ---- polygon batches ------------------------------------------------------
 * Many polygons in one call, each with its own index (a GIS layer burnt
 * value by value, the instances of a label image, N masks): polygons[k]
 * for k = 0 .. n-1, all with the same `opts`, drawn in order.  Each
 * polygon is drawn once, with the clip cut to its rast_fill_bounds, so the
 * scratch is that of the largest polygon's own box (the mask algorithms)
 * or edges (the others), never the clip's: memory grows with the batch's
 * largest polygon and the visible rows of its box, not with the batch.
 * The clip is a band or window as for rast_fill_polygon_spans: rendering a
 * batch band by band (clip = the band) gives the pixels of rendering it
 * whole.
 *
 * Errors, all before the first span: everything rast_fill_bounds and
 * rast_fill_polygon_spans check, for every polygon; RAST_E_SCRATCH when a
 * polygon's need exceeds scratch_bytes; RAST_E_NULL for polygons (n > 0),
 * opts, clip, span; RAST_E_ALIGN for a misaligned scratch.  When `failed`
 * is not NULL and the error belongs to one polygon, *failed is set to its
 * index (else it is left untouched). */

/* A span of polygon `index` in row y, columns x0 <= i < x1 (x0 < x1). */
typedef void (*rast_batch_span_fn)(void *user, uint32_t index, int32_t y, int32_t x0,
                                   int32_t x1);

/* Scratch bytes with which rast_fill_polygons_spans draws the batch in
 * `clip`: the largest rast_scratch_size of one polygon cut to its bounds.
 * Errors as rast_fill_polygons_spans' checks (with *failed). */
RAST_API rast_status rast_polygons_scratch_size(const rast_polygon *polygons, uint32_t n,
                                                const rast_fill_opts *opts,
                                                const rast_rect *clip, size_t *bytes,
                                                uint32_t *failed);

/* Draw the batch (see above): for k = 0 .. n-1, the spans polygon k gives
 * in `clip` (as rast_fill_polygon_spans gives them: rows top to bottom, in
 * each row increasing x), handed to `span` with k.  `scratch` aligned to
 * RAST_SCRATCH_ALIGN, at least rast_polygons_scratch_size bytes. */
RAST_API rast_status rast_fill_polygons_spans(const rast_polygon *polygons, uint32_t n,
                                              const rast_fill_opts *opts,
                                              const rast_rect *clip, rast_batch_span_fn span,
                                              void *user, void *scratch, size_t scratch_bytes,
                                              uint32_t *failed);

/* The same two for a batch of 64-bit polygons (rast_polygon64, see
 * rast_fill_polygon64: algorithm aet, S up to 32, RAST_E_WIDE for what is
 * not offered), each polygon's clip cut to rast_fill_bounds64. */
RAST_API rast_status rast_polygons64_scratch_size(const rast_polygon64 *polygons, uint32_t n,
                                                  const rast_fill_opts *opts,
                                                  const rast_rect *clip, size_t *bytes,
                                                  uint32_t *failed);
RAST_API rast_status rast_fill_polygons64_spans(const rast_polygon64 *polygons, uint32_t n,
                                                const rast_fill_opts *opts,
                                                const rast_rect *clip,
                                                rast_batch_span_fn span, void *user,
                                                void *scratch, size_t scratch_bytes,
                                                uint32_t *failed);

/* ==========================================================================
 * Triangles
 * ========================================================================== */

/* Triangle algorithms.  All give the same pixels as the polygon fillers
 * give the triangle as a one-ring polygon (either rule). */
typedef enum rast_tri_algorithm {
    RAST_TRI_EDGE = 0,     /* bounding box + incremental edge functions (000, 002, 004) */
    RAST_TRI_SWEEP = 1,    /* split at the middle vertex, exact DDA for both ends (000, 002) */
    RAST_TRI_EDGEFLAG = 2, /* SpanLeft/SpanRight arrays per row, then fill (001 3.3) */
    RAST_TRI_COUNT_ = 3
} rast_tri_algorithm;

/* Options of a triangle batch; zero-initialised as rast_fill_opts. */
typedef struct rast_tri_opts {
    rast_tri_algorithm algorithm;
    int32_t subpixel_bits; /* S, 0..RAST_MAX_SUBPIXEL_BITS */
    rast_sample sample;
    rast_rounding rounding;
    rast_boundary boundary;
} rast_tri_opts;

/* ---- triangles --------------------------------------------------------------
 * A batch is `ntris` triangles, tris[3k], tris[3k+1], tris[3k+2], in fixed
 * point as polygon vertices (same units and range).  Each triangle owns
 * exactly the samples the polygon fill of its one ring owns, in either
 * winding order; a degenerate triangle (collinear or repeated vertices) owns
 * none and is not an error.  Triangles of a mesh that share edges therefore
 * cover every sample of its area exactly once. */

/* Name of a triangle algorithm ("edge", "sweep", "edgeflag").
 * RAST_E_ALGORITHM for an unknown one. */
RAST_API rast_status rast_tri_algorithm_info(rast_tri_algorithm algorithm,
                                             const char **name);

/* Scratch bytes a triangle batch with `opts` needs for a clip `width` x
 * `height` pixels; independent of the number of triangles ("edge" and
 * "sweep" need none in the exact boundary mode, "edgeflag" two int32_t per
 * row).  Errors: RAST_E_NULL, RAST_E_SUBPIXEL, RAST_E_ALGORITHM,
 * RAST_E_SIZE, RAST_E_ARG. */
RAST_API rast_status rast_tri_scratch_size(const rast_tri_opts *opts,
                                           int32_t width, int32_t height,
                                           size_t *bytes);

/* Fill `ntris` triangles, one after the other, each writing `pixel` over
 * the pixels of target->clip it owns (RAST_FORMAT_COUNT16: adding 1, so a
 * pixel owned by k triangles gets k).  Geometry outside the clip is
 * clipped, not an error; ntris may be 0 (tris may then be NULL).
 * Scratch as rast_fill_polygon, sized by rast_tri_scratch_size() for the
 * clip.  Every vertex of the batch is checked before the first triangle is
 * drawn.  Errors, all before anything is written: RAST_E_NULL,
 * RAST_E_RANGE, RAST_E_SUBPIXEL, RAST_E_ALGORITHM, RAST_E_FORMAT,
 * RAST_E_SIZE (a bad target), RAST_E_SCRATCH, RAST_E_ALIGN, RAST_E_ARG.
 * `pixel` may be NULL for RAST_FORMAT_COUNT16. */
RAST_API rast_status rast_fill_triangles(const rast_target *target,
                                         const rast_point *tris, uint32_t ntris,
                                         const rast_tri_opts *opts,
                                         const void *pixel, void *scratch,
                                         size_t scratch_bytes);

/* The same coverage handed to `span`: for each triangle in turn, its rows
 * from top to bottom, each row's spans in increasing x (x0 < x1).  Spans of
 * different triangles may overlap only in a non-exact boundary mode.
 * The clip as for rast_fill_polygon_spans. */
RAST_API rast_status rast_fill_triangles_spans(const rast_point *tris,
                                               uint32_t ntris,
                                               const rast_tri_opts *opts,
                                               const rast_rect *clip,
                                               rast_span_fn span, void *user,
                                               void *scratch,
                                               size_t scratch_bytes);

/* Point-in-triangle predicates (seeds 003, 004), all in exact integers. */
typedef enum rast_predicate {
    RAST_PRED_SAMESIDE = 0,    /* p on the same side of each edge as the third vertex */
    RAST_PRED_CROSS = 1,       /* the three cross products have one sign */
    RAST_PRED_AREA = 2,        /* |A(pab)| + |A(pbc)| + |A(pca)| == |A(abc)| */
    RAST_PRED_BARYCENTRIC = 3, /* all barycentric coordinates >= 0 */
    RAST_PRED_OWNER = 4,       /* the fill's own rule: top-left, as every filler */
    RAST_PRED_COUNT_ = 5
} rast_predicate;

/* ---- predicates --------------------------------------------------------------
 * Is point p inside triangle t[0..2] (fixed point, any units; coordinates
 * within +-RAST_COORD_MAX)?  *inside gets 1 or 0.  The methods agree
 * inside and outside a non-degenerate triangle and differ only on its
 * boundary:
 *  - SAMESIDE, CROSS, AREA, BARYCENTRIC: the closed triangle; a point on
 *    an edge or a vertex is inside.  These four give the same answer for
 *    every p and t (they are four computations of one set).
 *  - OWNER: the fills' rule (Conventions) evaluated at a sample placed
 *    exactly at p: p is inside iff rast_fill_triangles() of t would own a
 *    sample there.  On the boundary that is top-left: points of a left
 *    edge or of a horizontal top edge are in, of a right edge or of a
 *    horizontal bottom edge out, a vertex as its row's crossings say; so
 *    triangles sharing an edge never both own a point and never both miss
 *    one.
 * A degenerate triangle (zero area: collinear or repeated vertices)
 * contains no point under every method.  (The seeds' formulas taken
 * literally would not: SAMESIDE's "v1 . v2 >= 0" accepts the whole plane,
 * CROSS and AREA the whole line through the vertices (the plane when all
 * three coincide); the closed tests check the area first.  OWNER needs no
 * check: the crossings cancel.)
 * Either winding order.  Exact: no rounding, no overflow in range.
 * Errors: RAST_E_NULL, RAST_E_RANGE, RAST_E_ARG (unknown method). */
RAST_API rast_status rast_point_in_triangle(rast_point p, const rast_point *t,
                                            rast_predicate method, int *inside);

/* ==========================================================================
 * Lines
 * ========================================================================== */

/* Line algorithms (see rast_draw_line for the pixels a line owns). */
typedef enum rast_line_algorithm {
    RAST_LINE_BRESENHAM = 0, /* integer error term; exactly the defined pixels */
    RAST_LINE_DDA = 1,       /* fixed-point DDA (16 fraction bits): may differ */
    RAST_LINE_COUNT_ = 2
} rast_line_algorithm;

typedef struct rast_line_opts {
    rast_line_algorithm algorithm;
    int32_t subpixel_bits; /* S of the endpoints */
    rast_sample sample;
} rast_line_opts;

/* ---- lines -------------------------------------------------------------------
 * The pixels of the segment a -> b (fixed point, units 1/2^S, sample offset
 * o, coordinates as polygon vertices), with dx = bx - ax, dy = by - ay:
 *  - x-major (|dx| >= |dy|, also a = b): one pixel in each column i whose
 *    sample abscissa i + o lies in [min(ax, bx), max(ax, bx)] (in pixels);
 *    its row is the j whose sample ordinate j + o is nearest the line's
 *    y(x) = ay + (x - ax) dy / dx at x = i + o (ay when dx = 0), halfway
 *    going down: j = floor(y(i + o) - o + 1/2);
 *  - y-major (|dy| > |dx|): the same with x and y swapped: one pixel in each
 *    row j with j + o in [min(ay, by), max(ay, by)], column
 *    i = floor(x(j + o) - o + 1/2), halfway going right.
 * With o = 1/2 the pixel is the one containing the line's point; with o = 0
 * and integer endpoints (S = 0) this is Bresenham's classic line, both
 * endpoints included.  The set depends on the segment, not its direction:
 * a -> b and b -> a give the same pixels. */

/* Draw the segment a -> b with `pixel` (COUNT16: adding 1) into the clip.
 * RAST_LINE_BRESENHAM draws exactly the pixels defined above, with an
 * integer error term (add and compare per pixel).
 * RAST_LINE_DDA is the textbook's float DDA made integer, for comparison:
 * the same major pixels, walked from a; the minor coordinate y is kept
 * with 16 fraction bits of a pixel, starts at the line's exact value at
 * the first sample rounded half up, and grows each step by the slope
 * dminor/|dmajor| rounded half up; the pixel is floor(y - o + 1/2) of that
 * y.  Only the slope's rounding differs from the exact line: after k steps
 * y is off by at most (k + 1)/2^17 pixel, so lines under 2^16 pixels are
 * never more than one pixel off; ties may go either way, and b -> a may
 * differ from a -> b.
 * Both clip exactly without walking off-clip pixels: a huge line costs
 * what its visible part costs.
 * Errors before any write: RAST_E_NULL (target, opts, or pixel where the
 * format needs one), RAST_E_RANGE, RAST_E_SUBPIXEL, RAST_E_ALGORITHM,
 * RAST_E_ARG (a bad sample value), RAST_E_FORMAT, RAST_E_SIZE. */
RAST_API rast_status rast_draw_line(const rast_target *target, rast_point a,
                                    rast_point b, const rast_line_opts *opts,
                                    const void *pixel);

/* Draw segments points[k] -> points[k+1] for k < npoints - 1, and with
 * `closed` non-zero also points[npoints-1] -> points[0] (an outline: seed
 * 002's "three lines make a triangle").  Each segment is drawn whole, so a
 * shared vertex is written once per segment (COUNT16 shows it).  Errors as
 * rast_draw_line; RAST_E_TOO_MANY past RAST_MAX_POINTS. */
RAST_API rast_status rast_draw_polyline(const rast_target *target,
                                        const rast_point *points,
                                        uint32_t npoints, int closed,
                                        const rast_line_opts *opts,
                                        const void *pixel);

/* The pixels of the segment a -> b inside `clip` (coordinates within
 * +-RAST_MAX_DIM, else RAST_E_SIZE; a clip of +-RAST_MAX_DIM holds every
 * line), in order from a to b, as xy[2k] (x), xy[2k+1] (y).  *count gets
 * the number of pixels (at most 2^28 + 1); if it is more than `capacity`
 * pixels, nothing is written to xy and RAST_E_SCRATCH is returned (call
 * again with more).  xy may be NULL when capacity is 0.  Other errors:
 * RAST_E_NULL (opts, clip, count), RAST_E_RANGE, RAST_E_SUBPIXEL,
 * RAST_E_ALGORITHM, RAST_E_ARG. */
RAST_API rast_status rast_line_pixels(rast_point a, rast_point b,
                                      const rast_line_opts *opts,
                                      const rast_rect *clip, int32_t *xy,
                                      size_t capacity, size_t *count);

/* ---- lines as spans ---------------------------------------------------------
 * The pixels rast_draw_polyline would draw (same segments, same algorithm),
 * inside `clip`, handed to `span` instead of painted: for each segment in
 * turn, from points[k] to points[k+1], one span per run of its pixels in a
 * row (x-major segments) or per pixel (y-major ones).  Spans of different
 * segments may overlap (a shared vertex is in both).  The clip as for
 * rast_fill_polygon_spans.  Errors as rast_draw_polyline, before any span:
 * RAST_E_NULL (opts, clip, span, or points when npoints > 0),
 * RAST_E_RANGE, RAST_E_SUBPIXEL, RAST_E_ALGORITHM, RAST_E_ARG,
 * RAST_E_SIZE, RAST_E_TOO_MANY. */
RAST_API rast_status rast_draw_polyline_spans(const rast_point *points, uint32_t npoints,
                                              int closed, const rast_line_opts *opts,
                                              const rast_rect *clip, rast_span_fn span,
                                              void *user);

/* ==========================================================================
 * Coverage and anti-aliasing
 * ========================================================================== */

/* ---- anti-aliased coverage (coverage*.c; DESIGN section 1a) ------------------
 * The binary rule (Conventions) says, per pixel, inside or outside.
 * Coverage says how much: the coverage of pixel (i, j) is the area a of
 * the part of its square [i, i+1) x [j, j+1) that is inside under the fill
 * rule, on the snapped (fixed-point) vertices; 0 <= a <= 1.  It is defined
 * by the region, not by its edges: where contours overlap, cross
 * themselves or coincide, the region is what the winding number says
 * (signed-area accumulation, as FreeType, AGG and Blend2D do it, is not:
 * see RAST_AA_ACCUMULATE).  Methods:
 *
 *  - RAST_AA_AREA: a itself, for both rules, with overlaps, self
 *    intersections, coincident edges and holes.  Delivered as
 *    floor(a M + 1/2) (M = 255 for RAST_COVERAGE_U8, 65535 for _U16), or
 *    as a fixed-point number (RAST_COVERAGE_FIX62).  Bound: the value
 *    computed, a', satisfies |a' - a| <= (n + m + 1) 2^-58, where n is the
 *    number of edges crossing the pixel's row (the strip j <= y < j + 1)
 *    and m the number of pairs of them that cross each other inside it.
 *    So the level delivered is floor(a M + 1/2) except where a M + 1/2 is
 *    within (n + m + 1) 2^-42 of an integer (a tie, to 2^-20 of a level
 *    while n + m < 2^22), where it may be the level below or above; it is
 *    always within 1/2 + (n + m + 1) 2^-42 of a M.  (How: each pixel row
 *    is cut at its vertices' ordinates and at its edges' crossings, so
 *    that in each piece the edges do not cross and the winding number is
 *    constant between neighbours; the inside trapezoids' areas are summed
 *    per column in 128-bit integers, with ordinates and abscissae on a
 *    grid of 2^-60 pixel.  Between the vertices of a row its crossings
 *    come off a heap, each touching the two edges that cross; each vertex
 *    inside a row costs a pass over the row's edges.  Memory grows with
 *    the edges and one row.)
 *  - RAST_AA_SS2 .. RAST_AA_SS16 (K = 2, 4, 8, 16): the binary rule on a
 *    grid K times finer: sub-sample (s, t), 0 <= s, t < K, of pixel (i, j)
 *    sits at (i + (s + o)/K, j + (t + o)/K), o the sample offset (1/2 or
 *    0); with `count` of them inside the value is
 *    floor(count M / K^2 + 1/2), exactly (FIX62: count 2^62 / K^2).  The
 *    vertices are scaled by K exactly, so |v| * 2^max(0, log2(K) - S)
 *    must stay within RAST_COORD_MAX (else RAST_E_RANGE), and the clip
 *    times K within +-RAST_MAX_DIM (else RAST_E_SIZE).
 *  - RAST_AA_ACCUMULATE: signed-area accumulation (FreeType, font-rs):
 *    every edge adds its signed area to the cells it crosses, and a pixel
 *    gets min(|w|, 1) (non-zero) or |w| folded mod 2 (even-odd) of the
 *    accumulated w.  Equal to RAST_AA_AREA (same rounding) where no two
 *    parts of the region overlap; NOT exact where contours overlap (a ring
 *    drawn twice doubles its edge pixels under non-zero), cross, or where
 *    triangles of a batch overlap.
 *
 * A triangle batch is ONE region: the union of its triangles (each is
 * oriented the same way and the batch filled non-zero), so a mesh drawn in
 * one call has no seams and overlapping triangles are not counted twice.
 *
 * Output: every pixel of `clip` is written, row y at out + (y - clip->y0)
 * * stride bytes, column x at index x - clip->x0 of that row, as uint8_t,
 * uint16_t or uint64_t (`stride` a multiple of that size, >= its size
 * times the clip width).  The clip's coordinates must lie within
 * +-RAST_MAX_DIM; geometry outside it is clipped, not an error. */
typedef enum rast_aa_method {
    RAST_AA_AREA = 0,
    RAST_AA_SS2 = 1,
    RAST_AA_SS4 = 2,
    RAST_AA_SS8 = 3,
    RAST_AA_SS16 = 4,
    RAST_AA_ACCUMULATE = 5,
    RAST_AA_COUNT_ = 6
} rast_aa_method;

typedef enum rast_coverage_format {
    RAST_COVERAGE_U8 = 0,   /* uint8_t, floor(a 255 + 1/2) */
    RAST_COVERAGE_U16 = 1,  /* uint16_t, floor(a 65535 + 1/2) */
    RAST_COVERAGE_FIX62 = 2 /* uint64_t, a in units of 2^-62 (0 .. 2^62),
                               truncated; for callers that want a real number */
} rast_coverage_format;

/* Zero-initialised means: area, even-odd, S = 0, samples at integer
 * points (only the ssK methods use the sample offset). */
typedef struct rast_coverage_opts {
    rast_aa_method method;
    rast_fill_rule rule;   /* ignored by the triangle calls (a union) */
    int32_t subpixel_bits; /* S, 0..RAST_MAX_SUBPIXEL_BITS */
    rast_sample sample;
} rast_coverage_opts;

/* Name of a method ("area", "ss2", "ss4", "ss8", "ss16", "accumulate").
 * RAST_E_ARG for an unknown one. */
RAST_API rast_status rast_aa_method_info(rast_aa_method method, const char **name);

/* Scratch bytes a coverage call with `opts` needs for `npoints` vertices
 * (a triangle batch: 3 per triangle) and a clip `width` x `height`: for
 * area and accumulate, 372 bytes per vertex and 74 per clip column (never
 * the rows; a band of four rows of cells, for long edges); for ssK, the
 * AET's scratch on the K-times finer clip (rast_scratch_size), 5 bytes, a
 * bit and K^2/8 bytes per clip column,
 * 8 per level of count (K^2 + 1) and a copy of the vertices.  Errors: RAST_E_NULL, RAST_E_ARG (method, rule or sample),
 * RAST_E_SUBPIXEL, RAST_E_SIZE, RAST_E_TOO_MANY. */
RAST_API rast_status rast_coverage_scratch_size(const rast_coverage_opts *opts,
                                                uint32_t npoints, int32_t width,
                                                int32_t height, size_t *bytes);

/* The coverage of `polygon` (rules as rast_fill_polygon, both for every
 * method) for every pixel of `clip`, into `out` (see Output above).
 * Errors, all before anything is written: RAST_E_NULL, RAST_E_ARG (method,
 * rule, sample, format, stride), RAST_E_SUBPIXEL, RAST_E_RANGE,
 * RAST_E_TOO_MANY, RAST_E_SIZE (the clip), RAST_E_SCRATCH, RAST_E_ALIGN.
 * Never writes outside the clip's rows and columns of `out`. */
RAST_API rast_status rast_polygon_coverage(const rast_polygon *polygon,
                                           const rast_coverage_opts *opts,
                                           const rast_rect *clip,
                                           rast_coverage_format format, void *out,
                                           ptrdiff_t stride, void *scratch,
                                           size_t scratch_bytes);

/* The same for the union of `ntris` triangles tris[3k..3k+2] (see above);
 * opts->rule is ignored.  ntris may be 0 (tris may then be NULL; every
 * clip pixel gets 0).  Errors as rast_polygon_coverage. */
RAST_API rast_status rast_triangles_coverage(const rast_point *tris, uint32_t ntris,
                                             const rast_coverage_opts *opts,
                                             const rast_rect *clip,
                                             rast_coverage_format format, void *out,
                                             ptrdiff_t stride, void *scratch,
                                             size_t scratch_bytes);

/* Coverage handed to a callback instead of written (a display driver that
 * blends): for each row of the clip from the top, its runs of pixels with
 * coverage not 0, in increasing x, as `span`(user, y, x0, x1, values) with
 * values[i - x0] the uint8_t value (floor(a 255 + 1/2), 1..255) of pixel
 * (i, y), x0 <= i < x1.  The values are those rast_polygon_coverage writes
 * with RAST_COVERAGE_U8; `values` is valid during the call only.  Scratch:
 * rast_coverage_scratch_size() for the clip (it counts the row buffer).
 * Errors as rast_polygon_coverage, RAST_E_NULL also for span, all before
 * the first span. */
typedef void (*rast_coverage_span_fn)(void *user, int32_t y, int32_t x0, int32_t x1,
                                      const uint8_t *values);
RAST_API rast_status rast_polygon_coverage_spans(const rast_polygon *polygon,
                                                 const rast_coverage_opts *opts,
                                                 const rast_rect *clip,
                                                 rast_coverage_span_fn span, void *user,
                                                 void *scratch, size_t scratch_bytes);

/* The same for the union of a triangle batch (as rast_triangles_coverage):
 * its rows' runs of coverage not 0 handed to `span`, the values those
 * rast_triangles_coverage writes with RAST_COVERAGE_U8.  ntris may be 0
 * (tris may then be NULL: nothing is handed on).  Scratch as
 * rast_triangles_coverage (rast_coverage_scratch_size() for 3 ntris
 * vertices and the clip).  Errors as rast_triangles_coverage, RAST_E_NULL
 * also for span, all before the first span. */
RAST_API rast_status rast_triangles_coverage_spans(const rast_point *tris, uint32_t ntris,
                                                   const rast_coverage_opts *opts,
                                                   const rast_rect *clip,
                                                   rast_coverage_span_fn span, void *user,
                                                   void *scratch, size_t scratch_bytes);

/* ---- coverage on 64-bit vertices (coverage64.c) --------------------------
 * rast_polygon_coverage with RAST_AA_AREA on a rast_polygon64: vertices in
 * units of 1/2^S pixel, S = opts->subpixel_bits in 0..RAST_MAX_SUBPIXEL_BITS64
 * (32), every |coordinate| <= RAST_COORD64_MAX(S) (under 2^28 pixels), as
 * rast_fill_polygon64 takes them.  Both rules, overlaps, self
 * intersections, coincident edges, holes; the clip, the output layout and
 * the formats as rast_polygon_coverage (every pixel of `clip` written).
 * Bound: the value computed, a', satisfies |a' - a| <= (n + m + 1) 2^-50,
 * n the edges crossing the pixel's row, m the pairs of them crossing
 * inside it; RAST_COVERAGE_FIX62 is a' rounded to 2^-62, U8/U16
 * floor(a' M + 1/2) (so floor(a M + 1/2) except within (n + m + 1) 2^-34
 * of a tie).  Cost: per row, the edges spanning it sorted once per vertex
 * or crossing inside the row, one 128-bit division per edge end and per
 * column an edge crosses; the output per cell an edge touched, the cells
 * between them written as runs (no per-cell arithmetic).  Only
 * opts->method RAST_AA_AREA: any other, RAST_E_WIDE.
 *
 * Scratch (rast_coverage64_scratch_size): 188 bytes per vertex and 32 per
 * clip column (and one bit), plus alignment.  Errors, all before anything is written:
 * RAST_E_NULL, RAST_E_WIDE (method), RAST_E_ARG (rule, format, stride),
 * RAST_E_SUBPIXEL, RAST_E_RANGE, RAST_E_TOO_MANY, RAST_E_SIZE (a clip
 * coordinate past +-RAST_MAX_DIM), RAST_E_SCRATCH, RAST_E_ALIGN.  An empty
 * clip writes nothing. */
RAST_API rast_status rast_coverage64_scratch_size(const rast_coverage_opts *opts,
                                                  uint32_t npoints, int32_t width,
                                                  int32_t height, size_t *bytes);
RAST_API rast_status rast_polygon_coverage64(const rast_polygon64 *polygon,
                                             const rast_coverage_opts *opts,
                                             const rast_rect *clip,
                                             rast_coverage_format format, void *out,
                                             ptrdiff_t stride, void *scratch,
                                             size_t scratch_bytes);

/* ---- anti-aliased fills: coverage painted into a target (coverage_paint.c) ---
 * rast_fill_polygon and rast_fill_triangles with coverage instead of the
 * binary rule: each pixel of target->clip whose coverage level
 * c = floor(a 255 + 1/2) (the RAST_COVERAGE_U8 value of `opts`' method,
 * exactly as rast_polygon_coverage / rast_triangles_coverage give it) is
 * not 0 is painted with `pixel` weighted by c; pixels with c = 0 are not
 * touched.  Per format:
 *  - GRAY8, RGB888, RGBA8888: every byte (channel) d of the pixel becomes
 *    floor((s c + d (255 - c) + 127) / 255), s the value's byte: the
 *    nearest integer to the exact source-over mix (never a tie); c = 255
 *    writes s.  RGBA8888's A byte is mixed like the others (the value's
 *    alpha is stored, as by rast_fill_polygon, not applied as opacity).
 *  - RGB565: the same formula on each of R, G, B in their own levels
 *    (0..31, 0..63, 0..31), the value's bits over the pixel's.
 *  - MONO1: a threshold: the pixel gets the value iff c >= 128 (more than
 *    half the pixel covered); else untouched.
 *  - COUNT16: 1 added (saturating) wherever c > 0; `pixel` ignored (may
 *    be NULL).
 * A triangle batch is one region (its union), so a mesh drawn in one call
 * has no seams and no double blending.  Scratch: rast_coverage_scratch_size
 * (opts, npoints, clip width, clip height) (3 vertices per triangle).
 * Errors, all before anything is written: those of rast_polygon_coverage
 * (RAST_E_ARG for a bad method, rule or sample), and those of the target
 * (RAST_E_NULL, RAST_E_SIZE, RAST_E_FORMAT; RAST_E_NULL for a NULL pixel
 * except COUNT16).  The binary entry points are unchanged. */
RAST_API rast_status rast_fill_polygon_aa(const rast_target *target,
                                          const rast_polygon *polygon,
                                          const rast_coverage_opts *opts, const void *pixel,
                                          void *scratch, size_t scratch_bytes);
RAST_API rast_status rast_fill_triangles_aa(const rast_target *target,
                                            const rast_point *tris, uint32_t ntris,
                                            const rast_coverage_opts *opts, const void *pixel,
                                            void *scratch, size_t scratch_bytes);

/* ---- opacity: source-over with a colour's alpha (blend.c) -------------------
 * The fills above write (or weight by coverage) a pixel VALUE; these take
 * an 8-bit RGBA colour rgba[0..3] (straight: R, G, B not multiplied by A)
 * and apply its alpha A_s, times an opacity level o, source-over, to a
 * GRAY8 (R), RGB888, RGB565 (the top 5/6/5 bits of R, G, B, as
 * rast_pack_color) or RGBA8888 target; other formats: RAST_E_FORMAT.
 * Per pixel, with c its coverage level out of C (binary fills: c = C = 255
 * inside; uint8 coverage: C = 255; uint16 coverage: C = 65535):
 *  - the alpha level  A = floor(A_s o c / (255 C) + 1/2): the product
 *    (A_s / 255) (o / 255) (c / C) to the nearest of the levels 0..255,
 *    rounded once (never a tie: 255^2 and 255 * 65535 are odd); A = 0
 *    leaves the pixel untouched;
 *  - GRAY8, RGB888, RGB565 (each field in its own levels) and
 *    premultiplied RGBA8888 (opts->premultiplied = 1; A's byte a mixed
 *    with source 255): each channel d becomes
 *    floor((s A + d (255 - A) + 127) / 255), s the colour's channel: the
 *    nearest level to the exact mix (as rast_fill_polygon_aa's blend).
 *  - straight RGBA8888 (premultiplied = 0): with a the pixel's alpha,
 *    alpha becomes floor((255 A + a (255 - A) + 127) / 255), and each of
 *    R, G, B floor(n / m + 1/2) with n = s A 255 + d a (255 - A) and
 *    m = 255 A + a (255 - A): the exact straight colour of the exact
 *    source-over result, rounded half up.
 * With A_s = o = 255 and a uint8 coverage, A = c: the blend equals
 * rast_fill_polygon_aa's for every format but straight RGBA8888 over a
 * pixel whose alpha is below 255 (there rast_fill_polygon_aa mixes the
 * bytes, as a value, not a colour). */
typedef struct rast_blend_opts {
    int32_t opacity;       /* o, 0..255 (255: the colour's alpha as it is) */
    int32_t premultiplied; /* RGBA8888 targets: 0 straight, 1 premultiplied;
                              the other formats ignore it */
} rast_blend_opts;

/* `rgba` through a coverage image onto target->clip (cut to the target):
 * pixel (x, y) of the clip at level `coverage` + (y - clip.y0) * stride
 * bytes, element x - clip.x0 of that row (uint8_t for RAST_COVERAGE_U8,
 * uint16_t for RAST_COVERAGE_U16: what rast_polygon_coverage writes for
 * that clip).  opts NULL: o = 255, straight.  Errors, before anything is
 * written: those of the target, RAST_E_FORMAT (not one of the four
 * formats), RAST_E_NULL (rgba; coverage with a non-empty clip), RAST_E_ARG
 * (o outside 0..255, premultiplied not 0 or 1, format FIX62 or unknown,
 * stride below the clip's row or not a multiple of the element),
 * RAST_E_ALIGN (a uint16 image not 2-byte aligned). */
RAST_API rast_status rast_blend_coverage(const rast_target *target, const void *coverage,
                                         rast_coverage_format format, ptrdiff_t stride,
                                         const uint8_t *rgba, const rast_blend_opts *opts);

/* Linear light: rast_blend_coverage mixing decoded values instead of
 * stored levels, through the caller's tables (no float in the core, no
 * table linked by callers that do not use it).  dec8[k] is the linear
 * value of level k of 255 (docs/opacity.md: round(2^24 decode(k / 255)),
 * decode the sRGB curve or a power law), dec6 and dec5 those of RGB565's
 * 6- and 5-bit fields (k / 63, k / 31); each table strictly increasing and
 * at most 2^24.  A as above; where A > 0 each colour channel becomes the
 * level k whose dec[k] is nearest the exact linear mix, the lower level on
 * a tie: GRAY8, RGB888, RGB565 (s the colour's top bits)
 * (dec[s] A + dec[d] (255 - A)) / 255; straight RGBA8888, with a the
 * pixel's alpha, (dec[s] A 255 + dec[d] a (255 - A)) / m, m as above, and
 * alpha as above (alpha is linear).  s = d keeps d; A = 255 gives s.
 * Errors: rast_blend_coverage's, RAST_E_NULL (gamma), RAST_E_ARG (a table
 * not strictly increasing or above 2^24; premultiplied = 1, whose stored
 * products of alpha and an encoded level have no linear value). */
typedef struct rast_gamma {
    uint32_t dec8[256];
    uint32_t dec6[64];
    uint32_t dec5[32];
} rast_gamma;

RAST_API rast_status rast_blend_coverage_linear(const rast_target *target, const void *coverage,
                                                rast_coverage_format format, ptrdiff_t stride,
                                                const uint8_t *rgba, const rast_blend_opts *opts,
                                                const rast_gamma *gamma);

/* rast_fill_polygon's pixels (c = 255) blended with `rgba` as above; each
 * pixel at most once.  Scratch and errors: rast_fill_polygon's, and those
 * of rast_blend_coverage's colour and options. */
RAST_API rast_status rast_fill_polygon_blend(const rast_target *target,
                                             const rast_polygon *polygon,
                                             const rast_fill_opts *opts, const uint8_t *rgba,
                                             const rast_blend_opts *blend, void *scratch,
                                             size_t scratch_bytes);

/* rast_fill_polygon_aa / rast_fill_triangles_aa with `rgba` blended as
 * above at each pixel's uint8 coverage level (a triangle batch: its union,
 * each pixel blended once).  Scratch and errors as those, with
 * rast_blend_coverage's for the colour and options. */
RAST_API rast_status rast_fill_polygon_aa_blend(const rast_target *target,
                                                const rast_polygon *polygon,
                                                const rast_coverage_opts *opts,
                                                const uint8_t *rgba,
                                                const rast_blend_opts *blend, void *scratch,
                                                size_t scratch_bytes);
RAST_API rast_status rast_fill_triangles_aa_blend(const rast_target *target,
                                                  const rast_point *tris, uint32_t ntris,
                                                  const rast_coverage_opts *opts,
                                                  const uint8_t *rgba,
                                                  const rast_blend_opts *blend, void *scratch,
                                                  size_t scratch_bytes);

/* ==========================================================================
 * Shading: Gouraud triangles, rectangles, polygons
 * ========================================================================== */

/* ---- shaded triangles (Gouraud, flat; optional depth) ------------------------
 * The same batch and the same coverage as rast_fill_triangles (every
 * algorithm, rounding and boundary mode: a shaded call writes exactly the
 * pixels the unshaded one writes, less those a depth test rejects), but
 * each pixel gets a colour interpolated from its triangle's three vertex
 * colours.
 *
 * Interpolation.  At the sample point p of a pixel, with the triangle's
 * snapped vertices v0, v1, v2 and the edge functions (twice the signed
 * areas) w0 = area(p, v1, v2), w1 = area(v0, p, v2), w2 = area(v0, v1, p),
 * a quantity with vertex values c0, c1, c2 has the exact rational value
 *     v = (w0 c0 + w1 c1 + w2 c2) / (w0 + w1 + w2)
 * (the barycentric interpolation, seeds 002-004; the triangle's plane
 * equation, seed 001 section 3.3.5).  Each channel is interpolated on its
 * own and stored as rast_pack_color stores a colour (RGBA8888 stores the
 * interpolated alpha; nothing is blended).  A sample outside its triangle
 * (textbook rounding, boundary modes) gets the plane's value there,
 * clamped to 0..255 (depth: to int32_t).  A degenerate triangle has no
 * plane: its pixels (boundary modes only) get vertex 0's values. */
typedef enum rast_precision {
    /* floor(v + 1/2), exactly: rational arithmetic in integers (128-bit
     * products in two halves where int64_t would overflow) - the reference */
    RAST_PRECISION_EXACT = 0,
    /* fixed point with F = fraction_bits: the value at one corner of the
     * triangle's box and the steps per column and per row rounded to
     * 1/2^F, then additions only; a pixel is floor(value + 1/2) of the
     * stepped value.  Off by a level or more where the steps' rounding
     * errors add up (bench/bench_shade.py measures how far, per F).  A
     * triangle whose steps do not fit 32 bits (slivers) is done exactly. */
    RAST_PRECISION_FIXED = 1,
    /* flat: the whole triangle in vertex 0's colour (seed 001 3.1.3);
     * depth, if asked for, is still interpolated, exactly */
    RAST_PRECISION_FLAT = 2
} rast_precision;

/* Zero-initialised means exact. */
typedef struct rast_shade_opts {
    rast_precision precision;
    int32_t fraction_bits; /* F for RAST_PRECISION_FIXED, 1..16; else ignored */
} rast_shade_opts;

/* Fill `ntris` triangles as rast_fill_triangles does, shading each pixel.
 * colors: 3 * ntris vertex colours of 4 bytes, R, G, B, A, in the order of
 *   the vertices (vertex m of triangle k at colors[4 * (3k + m)]); a format
 *   uses the channels rast_pack_color reads (GRAY8 and MONO1: R; RGB888 and
 *   RGB565: R, G, B; RGBA8888: all) and ignores the others.  Colours are
 *   interpolated in 8-bit levels, then packed (RGB565: top bits; MONO1: on
 *   iff the level is >= 128).  COUNT16 has no colour: RAST_E_FORMAT.
 * z, zbuf: depth, both NULL (no depth: nothing depth-related is computed)
 *   or both given.  z holds 3 * ntris vertex depths (any int32_t), zbuf the
 *   depth of every pixel of the target, target->width * target->height
 *   int32_t, row j at zbuf + j * width.  A pixel is written iff its
 *   interpolated depth (same precision as the colour; exact for FLAT) is
 *   less than zbuf there (smaller is nearer; equal fails), and zbuf then
 *   takes that depth.  Start zbuf at INT32_MAX to accept everything once.
 *   Only pixels of the clip are read or written.
 * Scratch as rast_fill_triangles (rast_tri_scratch_size).
 * Errors, all before anything is written: those of rast_fill_triangles,
 * RAST_E_NULL (shade; colors with ntris > 0; exactly one of z and zbuf),
 * RAST_E_FORMAT (COUNT16), RAST_E_ARG (an unknown precision, or
 * fraction_bits outside 1..16 for FIXED). */
RAST_API rast_status rast_fill_triangles_shaded(const rast_target *target,
                                                const rast_point *tris, uint32_t ntris,
                                                const uint8_t *colors, const int32_t *z,
                                                int32_t *zbuf, const rast_tri_opts *opts,
                                                const rast_shade_opts *shade,
                                                void *scratch, size_t scratch_bytes);

/* ---- Gouraud rectangles (shade_rect.c; seed 001 section 3.2.3) -------------
 * An axis-aligned rectangle with corners p0 and p1 (fixed point, units and
 * range as polygon vertices) and a colour at each corner, interpolated
 * bilinearly.  `colors` holds 4 RGBA colours (16 bytes), for the corners
 * (p0.x, p0.y), (p1.x, p0.y), (p1.x, p1.y), (p0.x, p1.y) in that order
 * (p0 need not be the top left: a colour stays with its corner).
 *
 * Pixels: exactly those rast_fill_polygon gives the rectangle's ring with
 * the same subpixel_bits, sample and rounding (the left and top sides in,
 * the right and bottom sides out: 左闭右开，下闭上开), so rectangles sharing
 * a side never both own a pixel.  p0.x == p1.x or p0.y == p1.y: nothing.
 *
 * Colour of a pixel whose sample is (xs, ys), with u = (xs - p0.x) /
 * (p1.x - p0.x) and v = (ys - p0.y) / (p1.y - p0.y) exact rationals, in
 * [0, 1] (u a little below 0 or above 1 under textbook rounding, see
 * below), per channel:
 *     c = (1-u)(1-v) c0 + u (1-v) c1 + u v c2 + (1-u) v c3
 *  - RAST_PRECISION_EXACT: floor(c + 1/2), exactly (rationals; integer
 *    quotient and remainder stepped along the row), clamped to 0..255
 *    (RAST_ROUND_TEXTBOOK owns a first column whose sample lies up to half
 *    a pixel left of the rectangle: u < 0 there, c extrapolated).
 *  - RAST_PRECISION_FIXED, F = fraction_bits (1..16), round(x) =
 *    floor(x + 1/2), one = 2^F: the textbook's stepping.  With the top
 *    left corner at (X0, Y0), width W and height H in pixels (corners put
 *    in order, colours following them) and b0, a0 the offsets of the
 *    rectangle's first sample row and column from Y0 and X0 (whatever the
 *    clip), the left side's colour at row k (0 = the first row) is
 *    L_k = round(L(b0) one) + k round((c3 - c0) one / H), the right side's
 *    R_k the same from c1 to c2, and in that row the pixel m columns right
 *    of the first has C = L_k + round((R_k - L_k) a0 / W)
 *    + m round((R_k - L_k) / W), written as clamp(floor((C + one/2) / one),
 *    0, 255).  Not exact: the increments are
 *    rounded (the error grows with the size and shrinks with F).
 *  - RAST_PRECISION_FLAT: c0 everywhere (seed 001's flat shading: one
 *    vertex's colour).
 * Each colour is stored as rast_pack_color stores it (GRAY8 and MONO1
 * take R, RGB565 the top bits; COUNT16 has no colour: RAST_E_FORMAT).
 *
 * opts: subpixel_bits, sample and rounding as for triangles; the algorithm
 * is not used (a rectangle needs none); boundary must be
 * RAST_BOUNDARY_EXACT.  Needs no scratch.  Never writes outside the clip.
 * Errors, before anything is written: RAST_E_NULL, RAST_E_SUBPIXEL,
 * RAST_E_ARG (bad sample, rounding, boundary, precision or fraction_bits),
 * RAST_E_RANGE (a coordinate past RAST_COORD_MAX, or a side longer than
 * RAST_GOURAUD_RECT_MAX_SIZE units, which keeps every product of the exact
 * interpolation inside int64_t), RAST_E_SIZE and RAST_E_FORMAT (a bad
 * target; RAST_FORMAT_COUNT16 has no colour). */
enum {
    RAST_GOURAUD_RECT_MAX_SIZE = 67108863 /* 2^26 - 1, input units */
};
RAST_API rast_status rast_fill_rect_gouraud(const rast_target *target, rast_point p0,
                                            rast_point p1, const uint8_t *colors,
                                            const rast_tri_opts *opts,
                                            const rast_shade_opts *shade);

/* ---- polygons with a colour per vertex (shade_poly.c; seed 001 3.4) ---------
 * The active edge table fill with Gouraud colours, edge then span: the
 * pixels are exactly rast_fill_polygon's with the same options (either
 * rule, holes, self-intersections), and the colour of a pixel is defined
 * row by row.  Its row's sample ordinate yc is crossed by the run's two
 * bounding edges: with the row's crossings sorted by exact abscissa (ties
 * by the index in polygon->points of the edge's first vertex, the edge
 * from vertex k to vertex k+1 of its ring having index k), under even-odd
 * the crossings 2k and 2k+1, under non-zero the crossing where the winding
 * number leaves 0 and the one where it returns to 0 (crossings in between
 * do not shade).  Each bounding edge, from vertex a to vertex b, has at yc
 * the exact colour ca + (yc - ya)(cb - ca)/(yb - ya) (linear along the
 * edge) at its exact crossing abscissa X (Conventions).  Along the run the
 * colour is linear in x between the left crossing (Xl, cl) and the right
 * one (Xr, cr): c = cl + (xs - Xl)(cr - cl)/(Xr - Xl) at the sample
 * abscissa xs, and the pixel gets floor(c + 1/2) per channel, exactly
 * (128-bit integers; no rounding before the last step), clamped to 0..255
 * (RAST_ROUND_TEXTBOOK owns a sample up to half a pixel left of Xl, where
 * the line is extrapolated).
 * For a triangle this is the same colour as the barycentric (plane)
 * interpolation: both are the unique affine function through the three
 * vertex colours, evaluated exactly.
 *
 * `colors`: 4 RGBA bytes per vertex, in the order of polygon->points.
 * opts: algorithm must be RAST_ALGO_AET (RAST_E_ALGORITHM), boundary
 * RAST_BOUNDARY_EXACT; rule, subpixel_bits, sample and rounding as for
 * rast_fill_polygon.  shade->precision: RAST_PRECISION_EXACT, or
 * RAST_PRECISION_FLAT (vertex 0's colour everywhere, seed 001's flat
 * shading); RAST_PRECISION_FIXED is not offered here (RAST_E_ARG).
 * Colours are stored as rast_pack_color stores them (COUNT16:
 * RAST_E_FORMAT).
 * Scratch: rast_polygon_gouraud_scratch_size() for the clip (the AET's and
 * 8 bytes per vertex).  Errors as rast_fill_polygon, all before anything
 * is written.  Never writes outside the clip. */
RAST_API rast_status rast_polygon_gouraud_scratch_size(uint32_t npoints, int32_t width,
                                                       int32_t height, size_t *bytes);
RAST_API rast_status rast_fill_polygon_gouraud(const rast_target *target,
                                               const rast_polygon *polygon,
                                               const uint8_t *colors,
                                               const rast_fill_opts *opts,
                                               const rast_shade_opts *shade,
                                               void *scratch, size_t scratch_bytes);

/* ---- anti-aliased shaded triangles (shade_aa.c) -------------------------------
 * rast_fill_triangles_shaded with coverage instead of the binary rule: a
 * triangle batch's union coverage (as rast_fill_triangles_aa) times a
 * Gouraud colour per pixel.  For each pixel of target->clip whose coverage
 * level c (the RAST_COVERAGE_U8 value rast_triangles_coverage gives with
 * `opts`) is not 0:
 *  - the colour: if the binary rule gives the pixel's sample point (at the
 *    offset opts->sample, S = opts->subpixel_bits, exact rounding) to a
 *    triangle, exactly the colour rast_fill_triangles_shaded writes there
 *    (the last such triangle in batch order: its interpolation at the
 *    sample, shade->precision); else (a silhouette pixel) the last
 *    non-degenerate triangle in batch order whose closed region meets the
 *    pixel's closed square [i, i+1] x [j, j+1] (there is one wherever
 *    c > 0), its interpolation evaluated at the sample point (outside the
 *    triangle: the plane's value) with the same rounding, clamped to
 *    0..255 per channel;
 *  - that colour, packed as rast_fill_triangles_shaded packs it (GRAY8,
 *    MONO1: R; RGB565: top bits), is blended with c as rast_fill_polygon_aa
 *    blends a value (channel floor((s c + d (255 - c) + 127) / 255); MONO1
 *    written iff c >= 128).
 * Pixels with c = 0 are not touched.  A mesh drawn in one call has no
 * seams: its coverage is that of the union.
 * shade->precision: RAST_PRECISION_EXACT or RAST_PRECISION_FLAT (vertex
 * 0's colour for every pixel of a triangle); FIXED is not offered
 * (RAST_E_ARG).  No depth.
 * Memory: the colours of a band of min(16, clip height) rows, 4 bytes a
 * pixel, beside the coverage scratch of that band:
 * rast_shaded_aa_scratch_size.  The clip is done band by band (each
 * band recomputes the coverage and colours of the triangles that reach
 * it); given more scratch, the bands grow (doubling, up to the clip's
 * height) while it holds them: fewer bands, less work, the same pixels.
 * Errors, all before anything is written: those of
 * rast_fill_triangles_aa, RAST_E_NULL (shade; colors with ntris > 0),
 * RAST_E_FORMAT (COUNT16), RAST_E_ARG (a precision other than EXACT and
 * FLAT). */
RAST_API rast_status rast_shaded_aa_scratch_size(const rast_coverage_opts *opts, uint32_t ntris,
                                                 int32_t width, int32_t height, size_t *bytes);
RAST_API rast_status rast_fill_triangles_shaded_aa(const rast_target *target,
                                                   const rast_point *tris, uint32_t ntris,
                                                   const uint8_t *colors,
                                                   const rast_coverage_opts *opts,
                                                   const rast_shade_opts *shade,
                                                   void *scratch, size_t scratch_bytes);

/* An anti-aliased Gouraud polygon (docs/coverage.md "Shaded polygons"):
 * the polygon's coverage c (rast_fill_polygon_aa's: opts->method, rule,
 * subpixel_bits, sample) times a colour per pixel, blended as
 * rast_fill_triangles_shaded_aa blends it.  The colour (4 channels, one
 * per vertex in `colors`, the rings' vertices in order):
 *  - where rast_fill_polygon_gouraud (RAST_ALGO_AET, the same rule,
 *    subpixel_bits and sample, exact rounding and boundary) paints the
 *    pixel, exactly its colour (edge, then span, rounded half up);
 *  - elsewhere (c > 0, the sample outside: the boundary meets the pixel's
 *    closed square), the colour at the point nearest the sample of the
 *    edges (of non-zero length) that meet the closed square, each edge's
 *    colour interpolated linearly from its first vertex's to its
 *    second's and rounded half up; of the first edge in ring order among
 *    the nearest.  A rectangle given as its four corners so gets the
 *    bilinear colour at its point nearest the sample.
 * shade->precision: RAST_PRECISION_EXACT, or RAST_PRECISION_FLAT (vertex
 * 0's colour for every pixel).  Pixels with c = 0 are not touched.
 * Memory: for a band of min(16, clip height) rows, the coverage scratch,
 * 12 bytes a pixel and rast_polygon_gouraud_scratch_size's:
 * rast_polygon_gouraud_aa_scratch_size (more scratch: bigger bands, the
 * same pixels).  Errors, all before anything is written: those of
 * rast_fill_polygon_aa and rast_fill_polygon_gouraud's polygon (NULL
 * colors with vertices), RAST_E_FORMAT (COUNT16), RAST_E_ARG (a precision
 * other than EXACT and FLAT). */
RAST_API rast_status rast_polygon_gouraud_aa_scratch_size(const rast_coverage_opts *opts,
                                                          uint32_t npoints, int32_t width,
                                                          int32_t height, size_t *bytes);
RAST_API rast_status rast_fill_polygon_gouraud_aa(const rast_target *target,
                                                  const rast_polygon *polygon,
                                                  const uint8_t *colors,
                                                  const rast_coverage_opts *opts,
                                                  const rast_shade_opts *shade, void *scratch,
                                                  size_t scratch_bytes);

/* ---- shaded fills with opacity (blend.c; docs/opacity.md) -------------------
 * rast_fill_triangles_shaded (no depth) and rast_fill_triangles_shaded_aa
 * with each pixel's colour blended source-over instead of stored: the same
 * pixels, and at each the same interpolated colour, every channel (alpha
 * too, on every format) interpolated as those interpolate R, G and B.
 * With s that colour (RGB565: its top bits, as rast_pack_color), alpha its
 * interpolated alpha level, o = blend->opacity and c the pixel's coverage
 * level (255 for the binary fill), the pixel is mixed exactly as
 * rast_blend_coverage mixes a colour s of alpha `alpha` at level c (one
 * rounding to A = round(alpha o c / 255^2), then each channel; straight or
 * premultiplied RGBA8888 as blend->premultiplied; A = 0 leaves the pixel).
 * blend NULL: o = 255, straight.  o = 255 with alpha 255 at every vertex
 * gives the stored fill's pixels on GRAY8, RGB888 and RGB565 (and on
 * RGBA8888 over opaque pixels).  Only the four formats of
 * rast_blend_coverage.  Scratch as rast_fill_triangles_shaded /
 * rast_shaded_aa_scratch_size.  Errors, all before anything is written:
 * those of rast_blend_coverage's target and options (RAST_E_FORMAT for a
 * format other than the four, RAST_E_ARG for o outside 0..255 or
 * premultiplied not 0 or 1), then those of the unblended call. */
RAST_API rast_status rast_fill_triangles_shaded_blend(const rast_target *target,
                                                      const rast_point *tris, uint32_t ntris,
                                                      const uint8_t *colors,
                                                      const rast_tri_opts *opts,
                                                      const rast_shade_opts *shade,
                                                      const rast_blend_opts *blend,
                                                      void *scratch, size_t scratch_bytes);
RAST_API rast_status rast_fill_triangles_shaded_aa_blend(const rast_target *target,
                                                         const rast_point *tris, uint32_t ntris,
                                                         const uint8_t *colors,
                                                         const rast_coverage_opts *opts,
                                                         const rast_shade_opts *shade,
                                                         const rast_blend_opts *blend,
                                                         void *scratch, size_t scratch_bytes);

/* rast_fill_rect_gouraud and rast_fill_polygon_gouraud blended the same
 * way: the same pixels, at each the same interpolated colour (every
 * channel, alpha too; RAST_PRECISION_FLAT: corner / vertex 0's colour,
 * alpha too), mixed at c = 255 exactly as rast_blend_coverage mixes a
 * colour of that alpha (A = round(alpha o / 255); straight or
 * premultiplied RGBA8888 as blend->premultiplied; A = 0 leaves the pixel).
 * blend NULL: o = 255, straight.  o = 255 with alpha 255 at every corner
 * (vertex) gives the stored fill's pixels on GRAY8, RGB888 and RGB565
 * (and on RGBA8888 over opaque pixels).  Only the four formats of
 * rast_blend_coverage.  Scratch (the polygon's) as the stored fill's.
 * Errors, all before anything is written: those of rast_blend_coverage's
 * target and options, then those of the stored fill. */
RAST_API rast_status rast_fill_rect_gouraud_blend(const rast_target *target, rast_point p0,
                                                  rast_point p1, const uint8_t *colors,
                                                  const rast_tri_opts *opts,
                                                  const rast_shade_opts *shade,
                                                  const rast_blend_opts *blend);
RAST_API rast_status rast_fill_polygon_gouraud_blend(const rast_target *target,
                                                     const rast_polygon *polygon,
                                                     const uint8_t *colors,
                                                     const rast_fill_opts *opts,
                                                     const rast_shade_opts *shade,
                                                     const rast_blend_opts *blend,
                                                     void *scratch, size_t scratch_bytes);
/* rast_fill_polygon_gouraud_aa blended the same way, at each pixel's
 * coverage level c as rast_fill_triangles_shaded_aa_blend (A =
 * round(alpha o c / 255^2)). */
RAST_API rast_status rast_fill_polygon_gouraud_aa_blend(const rast_target *target,
                                                        const rast_polygon *polygon,
                                                        const uint8_t *colors,
                                                        const rast_coverage_opts *opts,
                                                        const rast_shade_opts *shade,
                                                        const rast_blend_opts *blend,
                                                        void *scratch, size_t scratch_bytes);

/* ==========================================================================
 * Scenes, band by band
 * ========================================================================== */

/* ---- scenes, rendered band by band --------------------------------------------
 * A scene is an array of primitives drawn in order, each over the ones
 * before it.  rast_render_bands cuts the clip into bands of `band_rows`
 * rows and draws every primitive into each band in turn, so the work memory
 * is that of one primitive in one band: it grows with the primitive's
 * vertices and the band's rows and width, never with the coordinates (a
 * polygon reaching y = +-2^27 costs what one inside the band costs).  The
 * pixels are exactly those of drawing each primitive in order into the
 * whole clip: every filler clips exactly, rows are independent.
 *
 * Bounded memory, no partial image.  When a primitive's scratch for a band
 * does not fit `scratch_bytes`, its band is halved (and halved again, down
 * to one row) and drawn in parts, as FreeType's rasteriser does.  Before
 * anything is written, every primitive is checked (as its own entry point
 * checks it) and its scratch for a one-row band compared with
 * `scratch_bytes`: so the call either draws the whole scene or returns an
 * error having written nothing.  That check is the only one: the bands
 * then run each primitive's filler without reading its vertices for
 * their range again.  The scene's arrays must not change during the call. */
typedef enum rast_prim_kind {
    RAST_PRIM_POLYGON = 0,   /* `polygon` with `fill` (rast_fill_polygon) */
    RAST_PRIM_TRIANGLES = 1, /* `count` triangles at `points` with `tri`
                                (rast_fill_triangles) */
    RAST_PRIM_POLYLINE = 2,  /* `count` points at `points`, `closed`, with
                                `line` (rast_draw_polyline) */
    RAST_PRIM_POLYGON64 = 3, /* `polygon64` with `fill` (rast_fill_polygon64) */
    RAST_PRIM_COUNT_ = 4
} rast_prim_kind;

/* One primitive; only the fields of its kind are read.  `pixel` is the
 * value (target format bytes; NULL allowed for RAST_FORMAT_COUNT16 and for
 * the spans call, which hands the primitive to its callback instead).  The
 * library only reads it and what it points to. */
typedef struct rast_prim {
    rast_prim_kind kind;
    rast_polygon polygon;          /* RAST_PRIM_POLYGON */
    const rast_point *points;      /* RAST_PRIM_TRIANGLES, RAST_PRIM_POLYLINE */
    uint32_t count;                /* triangles, or polyline points */
    int32_t closed;                /* RAST_PRIM_POLYLINE: non-zero closes it */
    const rast_fill_opts *fill;    /* RAST_PRIM_POLYGON */
    const rast_tri_opts *tri;      /* RAST_PRIM_TRIANGLES */
    const rast_line_opts *line;    /* RAST_PRIM_POLYLINE */
    const void *pixel;
    rast_polygon64 polygon64;      /* RAST_PRIM_POLYGON64 */
    /* RAST_PRIM_POLYGON, RAST_PRIM_TRIANGLES: NULL (zero-initialised) draws
     * the binary fill with `fill` / `tri`; otherwise the anti-aliased one
     * with these coverage options (rast_fill_polygon_aa,
     * rast_fill_triangles_aa; `fill` / `tri` are then not read), its
     * scratch rast_coverage_scratch_size for the band.  rast_render_bands
     * paints it, rast_render_bands_coverage hands on its values;
     * rast_render_bands_spans and the other kinds refuse a non-NULL aa
     * (RAST_E_ARG). */
    const struct rast_coverage_opts *aa;
} rast_prim;

/* A span of primitive `prim` (a pointer into the caller's array) in row y,
 * columns x0 <= i < x1. */
typedef void (*rast_prim_span_fn)(void *user, const rast_prim *prim, int32_t y,
                                  int32_t x0, int32_t x1);

/* What a band render did (optional output): the number of bands of
 * band_rows rows the clip was cut into, how many times a primitive's band
 * was halved to fit the scratch, and the most scratch bytes any primitive
 * asked for in the band it was drawn in (<= scratch_bytes). */
typedef struct rast_band_stats {
    uint32_t bands;
    uint32_t splits;
    size_t peak_scratch;
} rast_band_stats;

/* Scratch bytes that draw every primitive of the scene in a band of
 * `band_rows` rows and `width` columns without halving: the largest need of
 * one primitive (polygons: rast_scratch_size, rast_scratch_size64; triangles:
 * rast_tri_scratch_size; polylines: none; anti-aliased ones, prim->aa:
 * rast_coverage_scratch_size).  band_rows = 1 gives the least
 * scratch with which rast_render_bands succeeds.  n may be 0 (prims may
 * then be NULL).  Errors: RAST_E_NULL, RAST_E_ARG (an unknown kind,
 * band_rows < 1), RAST_E_SIZE (width or band_rows past RAST_MAX_DIM, or a
 * negative width), and those of
 * the scratch functions. */
RAST_API rast_status rast_scene_scratch_size(const rast_prim *prims, uint32_t n,
                                             int32_t band_rows, int32_t width,
                                             size_t *bytes);

/* Draw the scene into target->clip band by band (see above): each band is
 * the clip narrowed to rows [y, y + band_rows), top to bottom.  Pixels as
 * drawing the primitives in order with their own entry points.  `scratch`
 * aligned to RAST_SCRATCH_ALIGN; `stats` may be NULL.  Errors, all before
 * anything is written: those of each primitive's entry point,
 * RAST_E_ARG (an unknown kind, band_rows < 1, aa on a kind other than
 * polygon and triangles), RAST_E_SCRATCH (some primitive does not fit even
 * a one-row band).  Anti-aliased primitives blend into what the ones
 * before them drew, band by band: the same pixels as one full call (a
 * pixel's coverage depends on its row alone). */
RAST_API rast_status rast_render_bands(const rast_target *target, const rast_prim *prims,
                                       uint32_t n, int32_t band_rows, void *scratch,
                                       size_t scratch_bytes, rast_band_stats *stats);

/* The same coverage handed to `span` (firmware pushing spans to a display
 * with a framebuffer of a band, or none): band by band, in each band the
 * primitives in order, each primitive's spans as its own spans call gives
 * them.  The clip as for rast_fill_polygon_spans; errors as
 * rast_render_bands, RAST_E_NULL also for clip or span, RAST_E_ARG for an
 * anti-aliased primitive (a span carries no coverage: use
 * rast_render_bands_coverage), all before the first span. */
RAST_API rast_status rast_render_bands_spans(const rast_prim *prims, uint32_t n,
                                             const rast_rect *clip, int32_t band_rows,
                                             rast_prim_span_fn span, void *user,
                                             void *scratch, size_t scratch_bytes,
                                             rast_band_stats *stats);

/* The same with coverage (a display driver that blends, band by band):
 * as rast_render_bands_spans, each span handed to `span` with `values`:
 * NULL for a binary primitive's span (every pixel of it fully the
 * primitive's), and for an anti-aliased one (prim->aa) the uint8 levels
 * 1..255 of its pixels x0..x1-1, the runs rast_polygon_coverage_spans /
 * rast_triangles_coverage_spans give for the band (valid during the call
 * only).  Errors as rast_render_bands_spans (an anti-aliased primitive is
 * accepted here), RAST_E_SIZE also for an anti-aliased primitive in a clip
 * wider than RAST_MAX_DIM, all before the first span. */
typedef void (*rast_prim_coverage_fn)(void *user, const rast_prim *prim, int32_t y, int32_t x0,
                                      int32_t x1, const uint8_t *values);
RAST_API rast_status rast_render_bands_coverage(const rast_prim *prims, uint32_t n,
                                                const rast_rect *clip, int32_t band_rows,
                                                rast_prim_coverage_fn span, void *user,
                                                void *scratch, size_t scratch_bytes,
                                                rast_band_stats *stats);

/* ==========================================================================
 * Region fill (seed fills)
 * ========================================================================== */

/* ---- region fill -------------------------------------------------------------
 * Seed fill (seed 001 section 3.6): starting at the seed pixel (x, y),
 * write `value` over a connected region of target->clip.  Pixels are
 * connected through their 4 side neighbours (connectivity 4) or also
 * their 4 corner neighbours (connectivity 8).  Values are compared as
 * whole pixels: all bytes of the format in memory order (RAST_FORMAT_RGB565
 * and RAST_FORMAT_COUNT16 a native uint16_t, COUNT16 written as a value,
 * not counted); RAST_FORMAT_MONO1 its bit, a value byte being on iff it is
 * not 0.
 *
 * The region is confined to the clip: pixels outside it are never read or
 * written and connect nothing.  A seed outside the target is an error
 * (RAST_E_ARG); a seed inside the target but outside the clip fills
 * nothing and returns RAST_OK.
 *
 * `stack` (aligned to RAST_SCRATCH_ALIGN, `stack_bytes` long, contents
 * ignored and undefined on return; may be NULL when stack_bytes is 0) holds
 * the span fill's pending row ranges, 16 bytes each.  With less than
 * rast_seed_stack_size() the fill may run out of it; then it goes on in
 * fixed memory and still fills exactly the region (only slower: about 6
 * units of work per pixel on a maze of one-pixel corridors, against 1
 * with enough stack; the proven worst case is far larger, see
 * rast_seed_fill_limited).  Any size is correct, 0 included.  If another
 * writer changes the target during the call, see rast_seed_fill_limited:
 * the call stays in the clip and returns, RAST_OK or RAST_E_WORK.
 *
 * Errors, returned before anything is written: RAST_E_NULL (target,
 * value, or boundary for rast_boundary_fill), RAST_E_SIZE and
 * RAST_E_FORMAT (a bad target), RAST_E_ARG (connectivity not 4 or 8; the
 * seed outside the target), RAST_E_ALIGN (a misaligned stack), and
 * RAST_E_NULL for a NULL stack of non-zero size.  Never writes outside
 * the clip. */

/* Bytes of stack with which rast_flood_fill and rast_boundary_fill never
 * need their fixed-memory fallback, for a clip `width` x `height`: 16
 * bytes for each range the span fill can have pending at once, at most 2
 * per run of the clip plus 2 (a worst case: most regions need far less;
 * SIZE_MAX when it does not fit a size_t).  Errors: RAST_E_NULL,
 * RAST_E_SIZE (a side outside 0..RAST_MAX_DIM). */
RAST_API rast_status rast_seed_stack_size(int32_t width, int32_t height, size_t *bytes);

/* Flood fill (interior-defined region): every pixel connected to the seed
 * through pixels equal to the seed's value (its value before the call)
 * gets `value`.  If `value` equals the seed's value nothing changes and
 * nothing is written (RAST_OK). */
RAST_API rast_status rast_flood_fill(const rast_target *target, int32_t x, int32_t y,
                                     const void *value, int connectivity, void *stack,
                                     size_t stack_bytes);

/* Boundary fill (boundary-defined region): every pixel connected to the
 * seed through pixels that are neither the `boundary` value nor `value`
 * gets `value`; the textbook's BoundaryFill, where a pixel already of the
 * fill value counts as done, so it stops the fill like the boundary.
 * With boundary == value (an outline drawn in the fill colour, the usual
 * use) that is exactly every pixel connected to the seed through pixels
 * not of the boundary value.  A seed of the boundary value or of `value`
 * fills nothing (RAST_OK). */
RAST_API rast_status rast_boundary_fill(const rast_target *target, int32_t x, int32_t y,
                                        const void *value, const void *boundary,
                                        int connectivity, void *stack, size_t stack_bytes);

/* Either fill with a limit on its work: `boundary` NULL is rast_flood_fill,
 * else rast_boundary_fill.  A unit of work is a pixel written, or a step
 * of the fixed-memory fallback (a move, or a contour step per group).  The
 * span fill (enough stack) does at most one unit per pixel of the region;
 * the fallback a few per pixel on the inputs measured (bench/maze.c: 6.5
 * on a maze of one-pixel corridors), but its proven bound is O(area^3),
 * which max_work lets a caller cut short.  If the work would pass max_work, the fill stops there and
 * returns RAST_E_WORK, the region partly filled.  *work (when `work` is
 * not NULL) gets the units done; 0 on an error before the fill.
 *
 * A target that changes during the call (another thread, an interrupt or
 * DMA writing the pixels): every fill still writes only `value`, only to
 * clip pixels it has just read as inside, never a run past the clip, and
 * stops with RAST_E_WORK once it has written more pixels than the clip
 * holds, or the fallback has made more than `area` moves without a write
 * or a contour walk longer than 4 (area + 1) (none of which can happen on
 * an unchanging target); the pixels then filled are unspecified.  So a
 * call's time is bounded by a function of the clip's area whatever
 * another writer does: O(area) with enough stack, O(area^3) steps (and
 * max_work) with the fallback.  Other errors as rast_flood_fill. */
RAST_API rast_status rast_seed_fill_limited(const rast_target *target, int32_t x, int32_t y,
                                           const void *value, const void *boundary,
                                           int connectivity, void *stack, size_t stack_bytes,
                                           uint64_t max_work, uint64_t *work);

/* ==========================================================================
 * Paths: curves flattened within a stated tolerance (path/flatten.c)
 * ========================================================================== */

/* ---- paths -------------------------------------------------------------------
 * A path is a list of verbs, each taking the next points of `points` in
 * order: MOVE 1 (starts a subpath at it), LINE 1 (a line to it), QUAD 2
 * (the control point, then the end: a quadratic Bezier from the current
 * point), CUBIC 3 (two control points, then the end), CLOSE 0 (ends the
 * subpath; the current point goes back to the subpath's start).  Points
 * are fixed point, units of 1/2^S pixel (Units above), |x|, |y| <=
 * RAST_COORD_MAX.  As in SVG, the first verb must be MOVE, and a drawing
 * verb right after CLOSE starts a new subpath at the closed one's start.
 * The library only reads it.  npoints must be exactly the points the
 * verbs take.  (Arcs: SVG's elliptical arcs are cubics in the Python
 * layer, rastrum.Path.arc_to; docs/paths.md.) */
typedef enum rast_path_verb {
    RAST_PATH_MOVE = 0,
    RAST_PATH_LINE = 1,
    RAST_PATH_QUAD = 2,
    RAST_PATH_CUBIC = 3,
    RAST_PATH_CLOSE = 4,
    RAST_PATH_VERB_COUNT_ = 5
} rast_path_verb;

typedef struct rast_path {
    const uint8_t *verbs;     /* rast_path_verb values */
    uint32_t nverbs;
    const rast_point *points; /* may be NULL when npoints is 0 */
    uint32_t npoints;
} rast_path;

/* Flattening.  Each subpath becomes one ring of a rast_polygon (rings are
 * closed, so an open subpath is closed by its fill, as SVG fills it): its
 * start, then for each LINE its end, for each curve the curve's points at
 * t = i/n, i = 1 .. n, rounded to the grid (floor(v + 1/2) per
 * coordinate; i = n is the end, exact).  A MOVE alone gives a ring of one
 * point, which encloses nothing.
 *
 * The bound.  `tolerance` is in the points' units (1/2^S pixel), 1 <=
 * tolerance <= RAST_COORD_MAX.  Every point of each true curve is within
 * `tolerance` (Euclidean distance) of the flattened polyline and every
 * point of the polyline within `tolerance` of the true curve (the
 * Hausdorff distance is at most `tolerance`), the rounding of the
 * flattened vertices to the grid included; so the filled region differs
 * from the true one only within `tolerance` of its boundary.  n follows
 * the curve's flatness (Wang's formula, proven in path/flatten.c):
 * n = ceil(sqrt(c m / (4 tolerance - 3))), m = ceil(sqrt(dd)), dd the
 * largest squared second difference of the control points, c = 3
 * (cubic) or 1 (quadratic); n <= 47,726 at any tolerance in range, and a
 * straight "curve" (evenly spaced collinear control points) is one edge.
 * Integer only; every product fits (128-bit intermediates, portable C99,
 * for cubics with n > 1024). */

/* The sizes of a flattened path: *npoints vertices in *nrings rings (one
 * per subpath).  Errors: RAST_E_NULL (path, npoints, nrings; verbs with
 * nverbs > 0; points with npoints > 0), RAST_E_ARG (an unknown verb, a
 * first verb other than MOVE, npoints not the verbs' count, a tolerance
 * outside 1..RAST_COORD_MAX), RAST_E_RANGE (a point past
 * RAST_COORD_MAX), RAST_E_TOO_MANY (more than RAST_MAX_POINTS flattened
 * vertices).  Nothing is written on error. */
RAST_API rast_status rast_path_flatten_size(const rast_path *path, int32_t tolerance,
                                            uint32_t *npoints, uint32_t *nrings);

/* Flatten `path` (see above) into caller memory: the vertices into
 * points[0 .. *npoints), one ring size per subpath into ring_sizes, and
 * *polygon made to describe them, ready for every polygon and coverage
 * entry point (fill it non-zero or even-odd as the path means).  The
 * vertices lie in the control points' hull, so they are in range.
 * Errors: those of rast_path_flatten_size, RAST_E_NULL (points,
 * ring_sizes or polygon NULL), RAST_E_SCRATCH (max_points or max_rings
 * below the sizes); nothing is written on error. */
RAST_API rast_status rast_path_flatten(const rast_path *path, int32_t tolerance,
                                       rast_point *points, uint32_t max_points,
                                       uint32_t *ring_sizes, uint32_t max_rings,
                                       rast_polygon *polygon);

/* ---- strokes (path/stroke.c) ------------------------------------------------
 * The outline of a path drawn with a width, as rings to fill NON-ZERO:
 * one ring per open subpath and per dash (the right side forward, the
 * end's cap, the left side back, the start's cap), two per closed subpath
 * (the right side, the left side, opposite senses), one per dot.  Its
 * winding number is, off a set of measure zero, the sum of the pieces'
 * (a parallelogram per segment, a join per vertex between two segments, a
 * cap per open end, each turning counter-clockwise and star-shaped about
 * a point): >= 1 exactly on their union, so the non-zero rule of every
 * filler ("area" included) draws exactly the union, where a stroke
 * crosses itself too (proof in path/stroke.c).  A join's inner side goes
 * through the vertex, so a ring overlaps itself there.  SVG's semantics: a
 * subpath's curves are flattened at `tolerance` first (rast_path_flatten);
 * zero-length segments are dropped; a subpath of length zero ("M p L p",
 * "M p Z") gives a disc (round cap), a square (square cap, turned as its
 * dash runs, else axis-aligned) or nothing (butt); a MOVE alone gives
 * nothing; a closed subpath is joined all round, no caps.  Joins: miter
 * (the offsets' intersection, bevelled where SVG's ratio 1/sin(theta/2),
 * theta the angle between the segments, exceeds miter_limit), round (the
 * circular sector on the outer side), bevel; a turn back (theta = 0) is
 * bevelled (round: a half disc).  Caps: butt, round (a half disc), square
 * (half the width beyond the end).
 *
 * Dashes: dash[0 .. ndash) lengths in the points' units (>= 0, not all 0;
 * an odd count is repeated, as SVG), on, off, on, ...; dash_offset (any
 * sign) is where along the pattern the path starts.  The pattern runs on
 * along the whole path, every subpath restarting it at dash_offset; a dash
 * crossing a vertex keeps the join; a closed subpath whose start is inside
 * a dash joins its last dash to its first; a dash of length 0 is a dot (its
 * caps).  Segment lengths are rounded to whole units (the pattern drifts
 * by at most 1/2 unit per segment); a dash's ends on a segment are rounded
 * to the grid.
 *
 * The bound (proof in path/stroke.c).  With u = 1 unit and h = width / 2:
 * every vertex of a segment's piece, a bevel or a square cap is within
 * sqrt(2)/2 u of the ideal one (the offsets are h times the exact unit
 * normal, rounded: an integer square root rounded to nearest); a miter's
 * tip within (miter_limit + 1) u; a round join or cap is a polygon within
 * max(tolerance, 2 u) of the ideal circular arc (both ways).  The miter
 * limit is decided with unit normals exact to 2^-29.
 *
 * Limits: 1 <= width <= RAST_COORD_MAX, 1 <= tolerance <= RAST_COORD_MAX,
 * 65536 <= miter_limit (16.16 fixed point: 65536 is 1.0) <= 2^31 - 1,
 * ndash <= 65536.  Integer only, no heap, no state between calls. */
typedef enum rast_stroke_join {
    RAST_JOIN_MITER = 0,
    RAST_JOIN_ROUND = 1,
    RAST_JOIN_BEVEL = 2
} rast_stroke_join;

typedef enum rast_stroke_cap {
    RAST_CAP_BUTT = 0,
    RAST_CAP_ROUND = 1,
    RAST_CAP_SQUARE = 2
} rast_stroke_cap;

typedef struct rast_stroke_style {
    int32_t width;         /* units of 1/2^S pixel, as the points */
    int32_t join;          /* rast_stroke_join */
    int32_t cap;           /* rast_stroke_cap */
    int32_t miter_limit;   /* SVG's ratio, 16.16 fixed point (4.0: 262144) */
    int32_t tolerance;     /* curves and round parts, in units */
    const int32_t *dash;   /* NULL or ndash == 0: solid */
    uint32_t ndash;
    int32_t dash_offset;
} rast_stroke_style;

/* The sizes of the stroke's outline: *npoints vertices in *nrings rings.
 * Errors: RAST_E_NULL (path, style, npoints, nrings; dash with ndash > 0;
 * as rast_path_flatten_size for the path), RAST_E_ARG (the path's, and a
 * style outside the limits above, a negative dash length, all lengths 0),
 * RAST_E_RANGE (a point past RAST_COORD_MAX, or an outline vertex there:
 * keep width and miter tips inside the range), RAST_E_TOO_MANY (more than
 * RAST_MAX_POINTS outline vertices).  Nothing is written on error. */
RAST_API rast_status rast_path_stroke_size(const rast_path *path, const rast_stroke_style *style,
                                           uint32_t *npoints, uint32_t *nrings);

/* Build the outline into caller memory, as rast_path_flatten does: points,
 * ring sizes, *polygon made to describe them (fill it RAST_RULE_NONZERO).
 * Errors: those of rast_path_stroke_size, RAST_E_NULL (points, ring_sizes
 * or polygon NULL), RAST_E_SCRATCH (max_points or max_rings below the
 * sizes); nothing is written on error. */
RAST_API rast_status rast_path_stroke(const rast_path *path, const rast_stroke_style *style,
                                      rast_point *points, uint32_t max_points,
                                      uint32_t *ring_sizes, uint32_t max_rings,
                                      rast_polygon *polygon);

#ifdef __cplusplus
}
#endif

#endif /* RASTRUM_H */

/* ==========================================================================
 * What may change: RAST_STATIC_LINKING_ONLY
 *
 * Declared only when the includer defines RAST_STATIC_LINKING_ONLY before
 * including this header (as lz4.h's LZ4_STATIC_LINKING_ONLY): calls and
 * constants that spell out the library's internals or serve one consumer,
 * and may change in a minor release.  Link statically (or pin the exact
 * version) when using them.
 *  - the scratch bounds of the polygon algorithms other than the AET: they
 *    are the fillers' internal layouts (RAST_AET_SCRATCH_BOUND, the AET's,
 *    is stable, and rast_scratch_size is exact for every algorithm);
 *  - pycocotools' polygon rule (the building blocks of rastrum.coco).
 * ========================================================================== */
#if defined(RAST_STATIC_LINKING_ONLY) && !defined(RASTRUM_H_STATIC_LINKING_ONLY)
#define RASTRUM_H_STATIC_LINKING_ONLY

#ifdef __cplusplus
extern "C" {
#endif

/* The same for the other polygon algorithms (rast_scratch_size gives the
 * exact figure; these are never less).  For a clip `width` x `height`:
 *  - xscan: an edge record (32 bytes) and a crossing key (4) per vertex;
 *  - edgefill, fence: the mask, ONE BIT per clip pixel in 64-bit words;
 *  - edgeflag: the same bits (its flags; all even-odd needs), plus one
 *    counter per clip pixel for non-zero's direction sums, of 1 byte up to
 *    511 vertices, 2 up to 131071, 4 beyond (rast_scratch_size cannot see
 *    the rule, so it always counts them);
 *  - crossing, winding: two edge records (32 bytes each) per vertex. */
#define RAST_XSCAN_SCRATCH_BOUND(npoints) \
    ((size_t)(npoints) * 36 + 2 * RAST_SCRATCH_ALIGN)
#define RAST_EDGEFILL_SCRATCH_BOUND(width, height) \
    ((size_t)(height) * (((size_t)(width) + 63) / 64) * 8)
#define RAST_FENCE_SCRATCH_BOUND(width, height) RAST_EDGEFILL_SCRATCH_BOUND(width, height)
#define RAST_EDGEFLAG_SCRATCH_BOUND(npoints, width, height)                      \
    (RAST_EDGEFILL_SCRATCH_BOUND(width, height) +                               \
     (size_t)(width) * (size_t)(height) *                                       \
         ((npoints) <= 511 ? 1u : (npoints) <= 131071 ? 2u : 4u) + RAST_SCRATCH_ALIGN)
#define RAST_POINTWISE_SCRATCH_BOUND(npoints) \
    ((size_t)(npoints) * 64 + RAST_SCRATCH_ALIGN)

/* ---- pycocotools' polygon rule (coco.c) --------------------------------------
 * Not the exact rule: the rule with which pycocotools (cocoapi maskApi.c,
 * rleFrPoly) turns a COCO polygon into a mask, reproduced bit for bit in
 * integers so that training masks equal the evaluation's.  Masks are
 * column-major, as COCO's run-length encoding (RLE) stores them: pixel
 * (row y, column x) of an height x width mask is position x * height + y.
 *
 * Input: the ring's vertices upsampled by 5 and rounded as pycocotools
 * rounds them, X = (int)(5 * x + 0.5) in C double arithmetic (truncation
 * toward zero), within +-RAST_COCO_COORD_MAX (about +-1.67 million
 * pixels); the ring is closed (the last vertex joins the first).
 * The rule: each edge is walked one fifth of a pixel at a time along its
 * longer axis, its other coordinate rounded as pycocotools' doubles round
 * it (reproduced exactly, ties included); where the walk steps from
 * X = 5c + 2 to 5c + 3, column c (0 <= c < width) gets a toggle at row
 * ceil((Y - 2) / 5) clamped to 0..height, Y the smaller of the two steps'
 * Y; a pixel is inside iff an odd number of its column's toggles are at or
 * above it.  Rings of 0, 1 or 2 points draw nothing.  Width 0 is
 * pycocotools' too: its unsigned width - 1 wraps, so every column c >= 0
 * takes toggles (counts past the empty mask, as pycocotools gives them).
 */
enum {
    RAST_COCO_COORD_MAX = 8388607 /* 2^23 - 1, in fifths of a pixel */
};

/* The toggle positions (x * height + row, row in 0..height) of one ring
 * under pycocotools' rule, in no particular order, into toggles[0..*count).
 * *count always gets the number of toggles (at most npoints * width); if it
 * is more than `capacity`, nothing is written and RAST_E_SCRATCH returned
 * (call again with more).  toggles may be NULL when capacity is 0.
 * height * width must fit 32 bits (COCO's counts are uint32).  Errors,
 * before anything is written: RAST_E_NULL, RAST_E_SIZE (a negative side or
 * height * width > 2^32 - 1), RAST_E_TOO_MANY, RAST_E_RANGE. */
RAST_API rast_status rast_coco_ring_toggles(const rast_point *points, uint32_t npoints,
                                            int32_t height, int32_t width, uint32_t *toggles,
                                            size_t capacity, size_t *count);

/* The toggles of rast_coco_ring_toggles whose position x * height + row,
 * as an exact integer (pycocotools' uint32 wraps only the value written,
 * which happens with width 0), lies in [first, end): a ring's toggles a
 * window at a time, so that memory follows the window and not npoints *
 * width (rastrum.coco builds each RLE this way).  *count gets the number in
 * the window; capacity, RAST_E_SCRATCH and the errors as there.
 * rast_coco_ring_toggles is this call with first 0 and end 2^64 - 1. */
RAST_API rast_status rast_coco_ring_toggles_in(const rast_point *points, uint32_t npoints,
                                               int32_t height, int32_t width, uint64_t first,
                                               uint64_t end, uint32_t *toggles, size_t capacity,
                                               size_t *count);

/* The run-length counts of the mask that toggles[0..count) (positions, any
 * order, any multiplicity) give a mask of `total` pixels, as pycocotools
 * makes them: the differences of the sorted positions with `total` among
 * them (uint32), a difference of 0 joining the runs either side of it.
 * When no position passes `total` these are COCO's canonical runs of the
 * positions of odd multiplicity: zeros first (a count of 0 when the mask
 * starts inside), then alternately ones and zeros, no other count 0; one
 * count (`total`) for an empty mask.  toggles is sorted in place (and
 * `scratch`, count uint32_t, used as work memory); counts must hold
 * count + 1 values; *ncounts gets how many were written.  Errors:
 * RAST_E_NULL. */
RAST_API rast_status rast_coco_rle(uint32_t *toggles, size_t count, uint32_t total,
                                   uint32_t *scratch, uint32_t *counts, size_t *ncounts);

#ifdef __cplusplus
}
#endif

#endif /* RAST_STATIC_LINKING_ONLY */
