/*
 * coverage_ss.c - k x k supersampling ("ss2" .. "ss16"): the binary rule
 * (DESIGN section 1) on a grid k times finer, counted per pixel.
 *
 * The fine grid's pixel (I, J) is pixel (I / k, J / k) of the output and
 * its sample sits at ((I + o) / k, (J + o) / k): exactly sub-sample
 * (I mod k, J mod k) of section 1a.  The polygon arrives on that grid
 * already (coverage.c scales its vertices by k exactly); the exact AET
 * walk (aet.h) hands each row's edges, in order, to rast__ss_row_ends, or
 * (many short edges) the walk of keys here (rast__ss_sweep) takes their
 * runs itself, and a row of counters (one output row) adds them up.
 *
 * The counters are kept as differences (count[i] = d[0] + ... + d[i]), so
 * a run costs at most four additions whatever its length, and a bit per
 * column marks the differences not 0.  Flushing an output row walks only
 * the marked columns: between two of them the count is constant, and its
 * value is written as one run (a memset for uint8_t).  A row costs its
 * runs plus a pass over its pixels at memset speed.  (A uint8_t row with
 * many runs' ends is summed column by column instead, where it has marks:
 * rast__ss_flush_dense.)
 */
#include "coverage.h"
#include "../base/aet.h"
#include "../base/bits.h"
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__SS_DELTA 1
#else
#define RAST__SS_DELTA 0
#endif

typedef struct rast__ss {
    const rast__cov_out *o;
    int32_t *d;      /* the output row's counts as differences, clip
                        columns, two more at the end (a run ending at the
                        clip's right edge touches d[w + 1], with 0) */
    uint64_t *mark;  /* bit i: d[i] or d[i + 1] may not be 0 (i <= w) */
    uint64_t *level; /* the value of each count 0..k^2 */
    int32_t kbits;
    int32_t fx0, fx1, fy0; /* the fine clip's columns and first row */
    int32_t row;           /* the output row (clip-relative); -1 before the first */
    int32_t next;          /* the first output row (clip-relative) not written yet */
    int32_t ends;          /* runs' ends in the output row so far */
    int32_t evenodd;       /* the rule */
    int32_t clip;          /* 0: every crossing within the clip's columns */
    int32_t dense;         /* 1: uint8_t rows, all summed, no marks (rast__ss_dense);
                              -1: to be told by rast__ss_sweep from the records */
    int32_t bytes;         /* 1: d[] holds a byte a fine column (rast__ss_flush_bytes) */
} rast__ss;

/* Pixels [k0, k1) of a clip row get value v. */
static inline void rast__ss_run(rast_coverage_format f, unsigned char *row, int32_t k0,
                                int32_t k1, uint64_t v)
{
    int32_t k;
    if (f == RAST_COVERAGE_U8) {
        if (k1 - k0 > 16) {
            memset(row + k0, (int)v, (size_t)(k1 - k0));
        } else {
            for (k = k0; k < k1; k++) row[k] = (unsigned char)v;
        }
    } else if (f == RAST_COVERAGE_U16) {
        uint16_t *p = (uint16_t *)(void *)row;
        for (k = k0; k < k1; k++) p[k] = (uint16_t)v;
    } else {
        uint64_t *p = (uint64_t *)(void *)row;
        for (k = k0; k < k1; k++) p[k] = v;
    }
}

#if RAST__SS_DELTA
/* k = 4: 16 counts c (0 .. 16) in bytes to their uint8_t levels,
 * rast__cov_level's floor((255 c + 8) / 16) = 16 c - (c > 8)
 * (rast__ss_u8x16's; 16 x 16 is 0 modulo 2^8). */
static inline __m128i rast__ss_level16(__m128i n)
{
    return _mm_add_epi8(_mm_and_si128(_mm_slli_epi16(n, 4), _mm_set1_epi8((char)0xF0)),
                        _mm_cmpgt_epi8(n, _mm_set1_epi8(8)));
}

/* 4 differences at d summed along after the running count *run (in
 * every lane), which moves on past them, and cleared: the levels of
 * their counts, rast__cov_level's floor((255 c + half) >> sh). */
static inline __m128i rast__ss_sum4(int32_t *d, __m128i *run, __m128i half, __m128i sh)
{
    __m128i v = _mm_loadu_si128((const __m128i *)(const void *)d);
    _mm_storeu_si128((__m128i *)(void *)d, _mm_setzero_si128());
    v = _mm_add_epi32(v, _mm_slli_si128(v, 4));
    v = _mm_add_epi32(v, _mm_slli_si128(v, 8));
    v = _mm_add_epi32(v, *run);
    *run = _mm_shuffle_epi32(v, 0xFF);
    return _mm_srl_epi32(_mm_add_epi32(_mm_sub_epi32(_mm_slli_epi32(v, 8), v), half), sh);
}

/* The last lane of 16 bytes in every lane. */
static inline __m128i rast__ss_last8(__m128i v)
{
    v = _mm_unpackhi_epi8(v, v);
    v = _mm_shufflehi_epi16(v, 0xFF);
    return _mm_unpackhi_epi64(v, v);
}

/* 4 int32_t at d, cleared, and-ed with m (their bytes written out in
 * the caller, not a loop over an array, which the compiler kept in
 * memory). */
static inline __m128i rast__ss_take4(int32_t *d, __m128i m)
{
    const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)d);
    _mm_storeu_si128((__m128i *)(void *)d, _mm_setzero_si128());
    return _mm_and_si128(v, m);
}

/* rast__ss_flush_dense's sums in SSE2, 16 columns a step from column a
 * while they are before b: the counts (running on from *count) summed
 * along, the differences cleared as they are read, their uint8_t levels
 * worked out, not looked up: rast__cov_level's floor((255 c +
 * 2^(2 kb - 1)) / 2^(2 kb)) for a count c of 0 .. 2^(2 kb) samples.
 * k = 4: the differences modulo 2^8, 16 in a vector, summed along in
 * bytes (rast__delta_sum16): every sum along the row is a pixel's count,
 * 0 .. 16, so the sums modulo 2^8 are the counts (34 instructions a step
 * where the int32_t sums below took 94 and a memset).  Else 4 int32_t at
 * a time (at most 255 x 256: no lane spills).  Returns the first column
 * not done, *count the count before it. */
static int32_t rast__ss_dense16(int32_t *d, unsigned char *row, int32_t a, int32_t b,
                                int32_t kb, int32_t *count)
{
    int32_t i = a;
    if (kb == 2) {
        const __m128i low = _mm_set1_epi32(0xFF);
        __m128i run = _mm_set1_epi8((char)*count), n;
        for (; i + 16 <= b; i += 16) {
            n = _mm_packus_epi16(
                _mm_packs_epi32(rast__ss_take4(d + i, low), rast__ss_take4(d + i + 4, low)),
                _mm_packs_epi32(rast__ss_take4(d + i + 8, low), rast__ss_take4(d + i + 12, low)));
            n = _mm_add_epi8(rast__delta_sum16(n), run);
            run = rast__ss_last8(n);
            _mm_storeu_si128((__m128i *)(void *)(row + i), rast__ss_level16(n));
        }
        *count = _mm_cvtsi128_si32(run) & 0xFF;
    } else {
        const __m128i half = _mm_set1_epi32(1 << (2 * kb - 1)), sh = _mm_cvtsi32_si128(2 * kb);
        __m128i run = _mm_set1_epi32(*count);
        for (; i + 16 <= b; i += 16) {
            const __m128i l0 = rast__ss_sum4(d + i, &run, half, sh),
                          l1 = rast__ss_sum4(d + i + 4, &run, half, sh),
                          l2 = rast__ss_sum4(d + i + 8, &run, half, sh),
                          l3 = rast__ss_sum4(d + i + 12, &run, half, sh);
            _mm_storeu_si128((__m128i *)(void *)(row + i),
                             _mm_packus_epi16(_mm_packs_epi32(l0, l1), _mm_packs_epi32(l2, l3)));
        }
        *count = _mm_cvtsi128_si32(run);
    }
    return i;
}
#endif

/* Write the output row: a marked column i is where a run's end changed
 * d[i] and d[i + 1] (rast__ss_end), so the count is constant from one
 * marked column's successor to the next marked column. */
/* A uint8_t row with many runs' ends (one a column in 8 or more): each
 * 64 columns with a mark summed pixel by pixel (no branch a column),
 * those without one a memset of their count, constant there. */
static void rast__ss_flush_dense(rast__ss *ss, unsigned char *row, int32_t w, int32_t words)
{
    const uint64_t *level = ss->level;
    int32_t *d = ss->d;
    int32_t k, i, count = 0;
    for (k = 0; k < words; k++) {
        const int32_t a = k * 64, b = a + 64 < w ? a + 64 : w;
        if (a >= w) {
            /* the marks of column w (a run's end at the clip's edge) */
        } else if (ss->dense || ss->mark[k]) {
            /* 16 columns a step (rast__ss_dense16, clearing them), then
             * four (the counts one after the other in registers), the
             * differences of those cleared at once */
            int32_t z = a; /* (the differences before z cleared already) */
            i = a;
#if RAST__SS_DELTA
            z = i = rast__ss_dense16(d, row, a, b, ss->kbits, &count);
#endif
            for (; i + 4 <= b; i += 4) {
                const int32_t c0 = count + d[i], c1 = c0 + d[i + 1], c2 = c1 + d[i + 2];
                count = c2 + d[i + 3];
                row[i] = (unsigned char)level[c0];
                row[i + 1] = (unsigned char)level[c1];
                row[i + 2] = (unsigned char)level[c2];
                row[i + 3] = (unsigned char)level[count];
            }
            for (; i < b; i++) {
                count += d[i];
                row[i] = (unsigned char)level[count];
            }
            if (z < b) memset(d + z, 0, (size_t)(b - z) * sizeof *d);
        } else { /* constant, but for a mark at a - 1 */
            count += d[a];
            d[a] = 0;
            memset(row + a, (int)level[count], (size_t)(b - a));
        }
        ss->mark[k] = 0;
    }
    /* what is left of d: column w's, a run's end at the clip's right edge
     * (d[w + 1] stays 0: such an end is at a column's start) */
    d[w] = 0;
}

#if RAST__SS_DELTA
/* Four pixels' bytes D0 .. D3 (a 32-bit lane each, rast__ss_flush_bytes):
 * their sum T (the change of S over the pixel: the lane's top byte once
 * summed along it) returned in the lane, and U = 4 D0 + 3 D1 + 2 D2 + D3
 * (the pixel's count less 4 S before it: the sum of the sums along the
 * lane) into *u, each modulo 2^8 in the lane's low byte. */
static inline __m128i rast__ss_tu(__m128i v, __m128i *u)
{
    __m128i t;
    v = _mm_add_epi8(v, _mm_slli_epi32(v, 8));
    v = _mm_add_epi8(v, _mm_slli_epi32(v, 16));
    t = _mm_add_epi8(v, _mm_srli_epi32(v, 16));
    *u = _mm_and_si128(_mm_add_epi8(t, _mm_srli_epi32(t, 8)), _mm_set1_epi32(0xFF));
    return _mm_srli_epi32(v, 24);
}

/* k = 4, uint8_t rows, many runs' ends (rast__ss_sweep_rows): the output
 * row from d[] read as bytes D, one a fine column (4 w + 1 of them: the
 * clip's columns and its right edge), each counting the runs that start
 * there less those that end there, on all 4 fine rows (modulo 2^8: a
 * run's end is one byte's addition, where d[]'s two differences and a
 * mark were 8 instructions).  Their running sum S (0 .. 4: the fine rows
 * on which the column is inside), summed over a pixel's 4 columns, is
 * its count of samples (0 .. 16): 4 S before the pixel plus its U
 * (rast__ss_tu), 16 pixels a step, the S after each the running sum of
 * their T; the level rast__ss_level16's.  16 pixels with no end take the
 * running sum's count, 4 S; the bytes are cleared as they are read; the
 * last pixels of a row (fewer than 16) a column at a time.  (Summing
 * every column along the row took 40% more; bytes A and F a pixel, its
 * ends' count and their columns' sum, summed in half the instructions
 * but cost two more bytes' additions and a column's split an end: more
 * in all on the star.) */
static void rast__ss_flush_bytes(rast__ss *ss)
{
    const rast__cov_out *o = ss->o;
    const int32_t y = o->clip.y0 + ss->row, w = o->clip.x1 - o->clip.x0, n = 4 * w;
    const __m128i zero = _mm_setzero_si128();
    unsigned char *row = rast__cov_row(o, y), *c = (unsigned char *)(void *)ss->d;
    __m128i run = zero; /* S before the pixel, in every byte */
    unsigned char sum;
    int32_t i, p;
    for (i = 0; i + 64 <= n; i += 64) {
        __m128i *q = (__m128i *)(void *)(c + i);
        __m128i v0 = _mm_loadu_si128(q), v1 = _mm_loadu_si128(q + 1), v2 = _mm_loadu_si128(q + 2),
                v3 = _mm_loadu_si128(q + 3), u0, u1, u2, u3, t, s;
        t = _mm_or_si128(_mm_or_si128(v0, v1), _mm_or_si128(v2, v3));
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(t, zero)) == 0xFFFF) {
            /* (S <= 4: 4 S fits its byte, no bit shifted into the next) */
            _mm_storeu_si128((__m128i *)(void *)(row + i / 4),
                             rast__ss_level16(_mm_slli_epi16(run, 2)));
            continue;
        }
        _mm_storeu_si128(q, zero);
        _mm_storeu_si128(q + 1, zero);
        _mm_storeu_si128(q + 2, zero);
        _mm_storeu_si128(q + 3, zero);
        v0 = rast__ss_tu(v0, &u0);
        v1 = rast__ss_tu(v1, &u1);
        v2 = rast__ss_tu(v2, &u2);
        v3 = rast__ss_tu(v3, &u3);
        /* (T and U 0 .. 255 in 32-bit lanes: packed as they are) */
        t = _mm_packus_epi16(_mm_packs_epi32(v0, v1), _mm_packs_epi32(v2, v3));
        s = _mm_add_epi8(rast__delta_sum16(t), run); /* S after each pixel */
        run = rast__ss_last8(s);
        /* the count 4 (S after - T) + U, each byte's true value 0 .. 16 */
        t = _mm_sub_epi8(s, t);
        t = _mm_add_epi8(t, t);
        t = _mm_add_epi8(_mm_add_epi8(t, t),
                         _mm_packus_epi16(_mm_packs_epi32(u0, u1), _mm_packs_epi32(u2, u3)));
        _mm_storeu_si128((__m128i *)(void *)(row + i / 4), rast__ss_level16(t));
    }
    /* the last pixels (fewer than 16), a column at a time */
    sum = (unsigned char)_mm_cvtsi128_si32(run);
    for (p = i / 4; p < w; p++) {
        int32_t count = 0, u;
        for (u = 0; u < 4; u++) {
            sum = (unsigned char)(sum + c[4 * p + u]);
            c[4 * p + u] = 0;
            count += sum;
        }
        row[p] = (unsigned char)ss->level[count];
    }
    c[n] = 0; /* (the clip's right edge: no pixel's) */
    ss->next = ss->row + 1;
    rast__cov_row_done(o, y);
}
#endif

static void rast__ss_flush(rast__ss *ss)
{
    const rast__cov_out *o = ss->o;
    const rast_coverage_format f = o->format;
    const int32_t y = o->clip.y0 + ss->row;
    const uint64_t *level = ss->level;
    unsigned char *row = rast__cov_row(o, y);
    int32_t *d = ss->d;
    int32_t w = o->clip.x1 - o->clip.x0, words = w / 64 + 1, k, at = 0, count = 0;
#if RAST__SS_DELTA
    if (ss->bytes) {
        rast__ss_flush_bytes(ss);
        return;
    }
#endif
    if (f == RAST_COVERAGE_U8 && (ss->dense || (int64_t)ss->ends * 8 >= w)) {
        rast__ss_flush_dense(ss, row, w, words);
        ss->ends = 0;
        ss->next = ss->row + 1;
        rast__cov_row_done(o, y);
        return;
    }
    ss->ends = 0;
    for (k = 0; k < words; k++) {
        uint64_t m = ss->mark[k];
        ss->mark[k] = 0;
        while (m) {
            int32_t i = k * 64 + (int32_t)rast__ctz64(m);
            m &= m - 1;
            rast__ss_run(f, row, at, i, level[count]);
            count += d[i];
            d[i] = 0;
            if (i < w) rast__ss_run(f, row, i, i + 1, level[count]);
            count += d[i + 1];
            d[i + 1] = 0;
            at = i + 1;
        }
    }
    rast__ss_run(f, row, at, w, level[0]);
    ss->next = ss->row + 1;
    rast__cov_row_done(o, y);
}

/* Runs of clip-relative fine row y come next: flush the output row before
 * when it is another. */
static void rast__ss_row(rast__ss *ss, int32_t y)
{
    int32_t row = y >> ss->kbits;
    if (row != ss->row) {
        if (ss->row >= 0) rast__ss_flush(ss);
        rast__cov_zero_rows(ss->o, ss->o->clip.y0 + ss->next, ss->o->clip.y0 + row);
        ss->row = row;
    }
}

/* Run [x0, x1) of a fine row, clip-relative fine columns (x0 <= x1): its
 * two ends counted (rast__ss_end; an empty run's two cancel), and marked
 * unless `mark` is NULL (rast__ss_dense). */
static inline void rast__ss_pair(int32_t *d, uint64_t *mark, int32_t kb, int32_t x0, int32_t x1)
{
    const int32_t K = (int32_t)1 << kb, c0 = x0 >> kb, c1 = x1 >> kb;
    const int32_t f0 = x0 & (K - 1), f1 = x1 & (K - 1);
    d[c0] += K - f0;
    d[c0 + 1] += f0;
    d[c1] -= K - f1;
    d[c1 + 1] -= f1;
    if (mark) {
        mark[c0 >> 6] |= (uint64_t)1 << (c0 & 63);
        mark[c1 >> 6] |= (uint64_t)1 << (c1 & 63);
    }
}

/* Column x of a fine row as a run's end: clamped to the clip's columns
 * [fx0, fx1] with `clamp` (a run wholly outside gets two ends that
 * cancel), relative to fx0. */
static inline int32_t rast__ss_at(int32_t x, int32_t fx0, int32_t fx1, int clamp)
{
    return (clamp ? (x < fx0 ? fx0 : x > fx1 ? fx1 : x) : x) - fx0;
}

#if defined(__OPTIMIZE_SIZE__)
/* (A build for size: a fine row at a time, rast__ss_row_ends.) */
/* Edges e[0] and e[1] bound one run of a row (a pair of opposite
 * directions, or of an even-odd row): the run added, both edges stepped;
 * 1 when they are out of order after it (with the last abscissa *last
 * before them), *last set to e[1]'s.  (rast__ss_nz's and rast__ss_eo's
 * step.) */
static inline int rast__ss_run2(rast__edge *e, int32_t *d, uint64_t *mark, int32_t kb, int32_t fx0,
                                int32_t fx1, int clamp, int32_t *last)
{
    int swapped;
    rast__ss_pair(d, mark, kb, rast__ss_at(e[0].x, fx0, fx1, clamp), rast__ss_at(e[1].x, fx0, fx1, clamp));
    rast__edge_step(&e[0]);
    rast__edge_step(&e[1]);
    swapped = (e[0].x < *last) | (e[1].x < e[0].x);
    *last = e[1].x;
    return swapped;
}

/* The runs of a non-zero row (rast__ss_row_ends), their ends clamped
 * with `clamp`, and the edges stepped.  1 when two edges changed places. */
RAST__HOT int rast__ss_nz(rast__edge *aet, int32_t n, int32_t *d, uint64_t *mark, int32_t kb,
                              int32_t fx0, int32_t fx1, int clamp)
{
    int32_t i = 0, w = 0, x0 = 0, last = INT32_MIN, swapped = 0;
    /* Pairs of edges of opposite directions, while they come: the winding
     * number is back to 0 after each, so each pair bounds one run (most
     * rows of most polygons are only such pairs); from the first pair
     * that is not, edge by edge, the winding number counted from 0. */
    for (; i + 1 < n && aet[i].dir + aet[i + 1].dir == 0; i += 2)
        swapped |= rast__ss_run2(&aet[i], d, mark, kb, fx0, fx1, clamp, &last);
    for (; i < n; i++) {
        /* (clamped, not yet relative to fx0: taken off at a run only) */
        const int32_t x = rast__ss_at(aet[i].x, fx0, fx1, clamp) + fx0;
        if (w == 0) x0 = x;
        w += aet[i].dir;
        if (w == 0) rast__ss_pair(d, mark, kb, x0 - fx0, x - fx0);
        rast__edge_step(&aet[i]);
        swapped |= aet[i].x < last;
        last = aet[i].x;
    }
    return swapped;
}

/* The runs of an even-odd row, between edges 2k and 2k + 1, as
 * rast__ss_nz. */
RAST__HOT int rast__ss_eo(rast__edge *aet, int32_t n, int32_t *d, uint64_t *mark, int32_t kb,
                              int32_t fx0, int32_t fx1, int clamp)
{
    int32_t i, last = INT32_MIN, swapped = 0;
    for (i = 0; i + 1 < n; i += 2)
        swapped |= rast__ss_run2(&aet[i], d, mark, kb, fx0, fx1, clamp, &last);
    if (i < n) { /* an odd edge out bounds no run */
        rast__edge_step(&aet[i]);
        swapped |= aet[i].x < last;
    }
    return swapped;
}

/* Fine row y's runs, from its active edges in order, and the edges
 * stepped to the next row, in one pass (the walk's order hook, given no
 * run function): even-odd, runs between edges 2k and 2k + 1; non-zero,
 * from where the winding number leaves 0 to where it comes back.  The
 * row's numbers are held in locals.  Clamping each end to the clip clamps
 * the run; it is skipped when every crossing of the polygon is known to
 * lie within the clip's columns (rast__ss_inside), as it mostly does.
 * (A build for size; one for speed walks an output row's fine rows in
 * one pass, rast__ss_sweep_rows.) */
static void rast__ss_row_ends(void *user, int32_t y, rast__edge *aet, int32_t n)
{
    rast__ss *ss = (rast__ss *)user;
    const int32_t kb = ss->kbits, fx0 = ss->fx0, fx1 = ss->fx1, clip = ss->clip;
    int32_t *d = ss->d;
    uint64_t *mark = ss->dense ? NULL : ss->mark;
    int swapped;
    rast__ss_row(ss, y - ss->fy0);
    ss->ends += n;
    swapped = ss->evenodd ? rast__ss_eo(aet, n, d, mark, kb, fx0, fx1, clip)
                          : rast__ss_nz(aet, n, d, mark, kb, fx0, fx1, clip);
    if (swapped) rast__aet_sort(aet, n);
}

/* The walk of the edge table aet[0 .. nedges) (rast__aet_prepare's, or
 * rast__ss_cancel's; bucket[] its rows' counts, edges[] the room for
 * the table grouped by row): aet.h's rast__aet_sweep, the order hook
 * rast__ss_row_ends (a build for speed: rast__ss_sweep_rows, below). */
static void rast__ss_sweep_records(rast__ss *ss, rast__edge *edges, rast__edge *aet,
                                   int32_t *bucket, int32_t nedges, int32_t row0, int32_t row1)
{
    rast__aet_sweep(edges, aet, bucket, nedges, row0, row1,
                    ss->evenodd ? RAST_RULE_EVENODD : RAST_RULE_NONZERO, NULL, rast__ss_row_ends,
                    ss);
}
#else
/* ---- an output row's fine rows in one pass over the AET -------------------
 * Long edges (a star's, a circle's): where no edge joins or ends within
 * some fine rows of an output row (a segment: all K of them, at most 4,
 * on most rows), one pass over the AET takes each edge through them all,
 * its DDA in registers, and counts its runs' ends on each of them into
 * the output row's counters (the same whichever fine row an end is on),
 * where a pass a fine row loaded and stored every edge's DDA K times and
 * paid a call and a row's set-up each time.  The runs are the rule's on a
 * fine row (docs/semantics.md, docs/coverage.md) when the AET is in order
 * of column on it: the pass checks that on each fine row; where it is not
 * (two edges crossed, or met where a tie put them the other way), the
 * pass is undone (the edges stepped back, the same ends counted with the
 * opposite sign) and the segment's fine rows are walked one at a time,
 * the AET sorted before each (then in order).  A build for size keeps the
 * walk a fine row at a time (aet.h's rast__aet_sweep, rast__ss_row_ends). */
#define RAST__SS_SEG 4 /* fine rows at most in a segment */
/* Rows looked ahead to order two edges of one column joining the AET */
#define RAST__SS_AHEAD 16

/* Edge *ed stepped back one row: rast__edge_step undone (its remainder
 * wrapped iff e + dr >= q). */
static inline void rast__ss_unstep(rast__edge *ed)
{
    const int64_t e = ed->e + ed->dr, carry = e >= ed->q;
    ed->x -= ed->step + (int32_t)carry;
    ed->e = e - (ed->q & -carry);
}

/* A run's end at clip-relative fine column x (0 .. w) counted with sign
 * sg (+1 a run's start, -1 its end): into byte x of `bytes` when `into`
 * (rast__ss_flush_bytes), else as rast__ss_pair counts each, marked
 * unless `mark` is NULL. */
static inline void rast__ss_end(int32_t *d, uint64_t *mark, unsigned char *bytes, int into,
                                int32_t kb, int32_t x, int32_t sg)
{
    const uint32_t K = (uint32_t)1 << kb, c = (uint32_t)x >> kb, f = (uint32_t)x & (K - 1);
    if (into) {
        bytes[(uint32_t)x] = (unsigned char)(bytes[(uint32_t)x] + sg);
        return;
    }
    d[c] += sg * (int32_t)(K - f);
    d[c + 1] += sg * (int32_t)f;
    if (mark) mark[c >> 6] |= (uint64_t)1 << (c & 63);
}

/* Fine row t of an edge's DDA in locals (x, e; dr, q, step): its
 * crossing into xs[t], then stepped (rast__edge_step). */
#define RAST__SS_STEP(t)                                                                          \
    do {                                                                                          \
        const int64_t v_ = e - dr, c_ = v_ < 0;                                                  \
        xs[t] = x;                                                                                \
        x += step + (int32_t)c_;                                                                  \
        e = v_ + (q & -c_);                                                                       \
    } while (0)

/* Edge *ed's crossings of nr fine rows (nr <= RAST__SS_SEG) into xs[],
 * relative to fx0, the edge stepped past them (its DDA in locals; four
 * rows written out, which a compiler at -O2 does not unroll). */
RAST__HOT void rast__ss_rows(rast__edge *ed, int32_t nr, int32_t *xs, int32_t fx0)
{
    const int64_t dr = ed->dr, q = ed->q;
    const int32_t step = ed->step;
    int64_t e = ed->e;
    int32_t x = ed->x - fx0, t;
    if (nr == 4) {
        RAST__SS_STEP(0);
        RAST__SS_STEP(1);
        RAST__SS_STEP(2);
        RAST__SS_STEP(3);
    } else if (nr == 3) {
        RAST__SS_STEP(0);
        RAST__SS_STEP(1);
        RAST__SS_STEP(2);
    } else if (nr == 2) {
        RAST__SS_STEP(0);
        RAST__SS_STEP(1);
    } else if (nr == 1) {
        RAST__SS_STEP(0);
    } else {
        for (t = 0; t < nr; t++) RAST__SS_STEP(t);
    }
    ed->x = x + fx0;
    ed->e = e;
}

/* Clip-relative fine column x clamped to the clip's columns [0, w] with
 * `clamp` (rast__ss_at). */
static inline int32_t rast__ss_in(int32_t x, int32_t w, int clamp)
{
    return clamp ? (x < 0 ? 0 : x > w ? w : x) : x;
}

/* Row t of a pair of edges of opposite directions (or an even-odd pair),
 * crossings a[t] and b[t]: the run between them, [min, max) whichever
 * edge is left (their order within the pair changes no sample), counted
 * with sign sg; `bad` set (or, within the clip, every crossing in [0, w],
 * `neg` made negative) when it starts left of last[t], the end of the run
 * before it on its row, which its end then becomes. */
#define RAST__SS_PAIR(t)                                                                          \
    do {                                                                                          \
        const int32_t lo_ = a[t] < b[t] ? a[t] : b[t], hi_ = a[t] < b[t] ? b[t] : a[t];          \
        if (clamp)                                                                                \
            bad |= lo_ < last[t];                                                                 \
        else                                                                                      \
            neg |= lo_ - last[t];                                                                 \
        last[t] = hi_;                                                                            \
        rast__ss_end(d, mark, bytes, into, kb, rast__ss_in(lo_, w, clamp), sg);                         \
        rast__ss_end(d, mark, bytes, into, kb, rast__ss_in(hi_, w, clamp), -sg);                        \
    } while (0)

/* The edges aet[0 .. n) after a segment's pairs (rast__ss_multi): edge
 * by edge, the winding number counted from 0 (the same edges bound the
 * runs on every row, in the same order), each crossing checked against
 * last[t], the one before it on its row (even-odd: an odd edge out, no
 * run); 1 when one is out of order.  Apart: rare (rings that overlap,
 * a run over more than two edges), and its loops over the rows would
 * keep the pairs' numbers in memory. */
RAST__APART int rast__ss_rest(rast__edge *aet, int32_t n, int32_t nr, int32_t *d, uint64_t *mark,
                              unsigned char *bytes, int into, int32_t kb, int32_t fx0, int32_t fx1,
                              int clamp, int evenodd, int32_t sg, int32_t *last)
{
    int32_t b[RAST__SS_SEG], x0[RAST__SS_SEG] = {0, 0, 0, 0};
    const int32_t w = fx1 - fx0;
    int32_t i, wind = 0, t;
    int bad = 0;
    for (i = 0; i < n; i++) {
        rast__ss_rows(&aet[i], nr, b, fx0);
        for (t = 0; t < nr; t++) {
            bad |= b[t] < last[t];
            last[t] = b[t];
        }
        if (evenodd) continue;
        if (wind == 0)
            for (t = 0; t < nr; t++) x0[t] = b[t];
        wind += aet[i].dir;
        if (wind == 0)
            for (t = 0; t < nr; t++) {
                rast__ss_end(d, mark, bytes, into, kb, rast__ss_in(x0[t], w, clamp), sg);
                rast__ss_end(d, mark, bytes, into, kb, rast__ss_in(b[t], w, clamp), -sg);
            }
    }
    return bad;
}

/* The runs of nr fine rows (a segment) of the n edges aet[] counted with
 * sign sg, every edge stepped past them: on each row the rule's runs
 * (rast__ss_nz's, rast__ss_eo's) as if the AET were in order of column
 * there, but for the order within a pair; 1 when it was not on one of
 * the rows (the counts then wrong).  Pairs of opposite directions (all
 * pairs, even-odd) while they come, then rast__ss_rest. */
RAST__HOT int rast__ss_multi(rast__edge *aet, int32_t n, int32_t nr, int32_t *d, uint64_t *mark,
                             unsigned char *bytes, int into, int32_t kb, int32_t fx0, int32_t fx1, int clamp,
                             int evenodd, int32_t sg)
{
    int32_t last[RAST__SS_SEG], a[RAST__SS_SEG], b[RAST__SS_SEG];
    const int32_t w = fx1 - fx0;
    int32_t i = 0, t, neg = 0;
    int bad = 0;
    last[0] = last[1] = last[2] = last[3] = clamp ? INT32_MIN : 0;
    for (; i + 1 < n && (evenodd || aet[i].dir + aet[i + 1].dir == 0); i += 2) {
        rast__ss_rows(&aet[i], nr, a, fx0);
        rast__ss_rows(&aet[i + 1], nr, b, fx0);
        if (nr == 4) {
            RAST__SS_PAIR(0);
            RAST__SS_PAIR(1);
            RAST__SS_PAIR(2);
            RAST__SS_PAIR(3);
        } else if (nr == 3) {
            RAST__SS_PAIR(0);
            RAST__SS_PAIR(1);
            RAST__SS_PAIR(2);
        } else if (nr == 2) {
            RAST__SS_PAIR(0);
            RAST__SS_PAIR(1);
        } else if (nr == 1) {
            RAST__SS_PAIR(0);
        } else {
            for (t = 0; t < nr; t++) RAST__SS_PAIR(t);
        }
    }
    if (i < n) { /* (a copy of last[]: its own stays in registers) */
        int32_t l[RAST__SS_SEG];
        l[0] = last[0];
        l[1] = last[1];
        l[2] = last[2];
        l[3] = last[3];
        bad |= rast__ss_rest(aet + i, n - i, nr, d, mark, bytes, into, kb, fx0, fx1, clamp, evenodd,
                             sg, l);
    }
    return bad | (neg < 0);
}

/* The copies of the pass (apart: each compiled with its constants, its
 * numbers in registers), k = 4, non-zero, within the clip: its ends
 * into bytes, four rows or any; into d[] with marks, four rows. */
RAST__APART int rast__ss_multi_b4(rast__edge *aet, int32_t n, unsigned char *bytes, int32_t fx0,
                                  int32_t fx1)
{
    return rast__ss_multi(aet, n, RAST__SS_SEG, NULL, NULL, bytes, 1, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_b3(rast__edge *aet, int32_t n, unsigned char *bytes, int32_t fx0,
                                  int32_t fx1)
{
    return rast__ss_multi(aet, n, 3, NULL, NULL, bytes, 1, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_b2(rast__edge *aet, int32_t n, unsigned char *bytes, int32_t fx0,
                                  int32_t fx1)
{
    return rast__ss_multi(aet, n, 2, NULL, NULL, bytes, 1, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_b1(rast__edge *aet, int32_t n, unsigned char *bytes, int32_t fx0,
                                  int32_t fx1)
{
    return rast__ss_multi(aet, n, 1, NULL, NULL, bytes, 1, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_m4(rast__edge *aet, int32_t n, int32_t *d, uint64_t *mark,
                                  int32_t fx0, int32_t fx1)
{
    return rast__ss_multi(aet, n, 4, d, mark, NULL, 0, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_m3(rast__edge *aet, int32_t n, int32_t *d, uint64_t *mark,
                                  int32_t fx0, int32_t fx1)
{
    return rast__ss_multi(aet, n, 3, d, mark, NULL, 0, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_m2(rast__edge *aet, int32_t n, int32_t *d, uint64_t *mark,
                                  int32_t fx0, int32_t fx1)
{
    return rast__ss_multi(aet, n, 2, d, mark, NULL, 0, 2, fx0, fx1, 0, 0, 1);
}

RAST__APART int rast__ss_multi_m1(rast__edge *aet, int32_t n, int32_t *d, uint64_t *mark,
                                  int32_t fx0, int32_t fx1)
{
    return rast__ss_multi(aet, n, 1, d, mark, NULL, 0, 2, fx0, fx1, 0, 0, 1);
}

/* A segment's pass (its ends into bytes when ss->bytes, else into d[]
 * with `mark`), with the rule, the clamp, the marks and the rows as
 * constants in the commonest cases' copies. */
static int rast__ss_segment(const rast__ss *ss, rast__edge *aet, int32_t n, int32_t nr,
                            uint64_t *mark)
{
    const int32_t kb = ss->kbits, fx0 = ss->fx0, fx1 = ss->fx1;
    int32_t *d = ss->d;
    unsigned char *bytes = ss->bytes ? (unsigned char *)(void *)d : NULL;
    if (kb == 2 && !ss->clip && !ss->evenodd) {
        if (bytes)
            return nr == 4   ? rast__ss_multi_b4(aet, n, bytes, fx0, fx1)
                   : nr == 3 ? rast__ss_multi_b3(aet, n, bytes, fx0, fx1)
                   : nr == 2 ? rast__ss_multi_b2(aet, n, bytes, fx0, fx1)
                             : rast__ss_multi_b1(aet, n, bytes, fx0, fx1);
        if (mark)
            return nr == 4   ? rast__ss_multi_m4(aet, n, d, mark, fx0, fx1)
                   : nr == 3 ? rast__ss_multi_m3(aet, n, d, mark, fx0, fx1)
                   : nr == 2 ? rast__ss_multi_m2(aet, n, d, mark, fx0, fx1)
                             : rast__ss_multi_m1(aet, n, d, mark, fx0, fx1);
    }
    return rast__ss_multi(aet, n, nr, d, mark, bytes, bytes != NULL, kb, fx0, fx1, ss->clip,
                          ss->evenodd, 1);
}

/* A segment's pass undone (rare): the edges stepped back to its first
 * row, the same ends counted again with the opposite sign (a mark more
 * changes no count), the edges stepped back again. */
RAST__APART void rast__ss_undo(const rast__ss *ss, rast__edge *aet, int32_t n, int32_t nr)
{
    int32_t i, t;
    for (i = 0; i < n; i++)
        for (t = 0; t < nr; t++) rast__ss_unstep(&aet[i]);
    (void)rast__ss_multi(aet, n, nr, ss->d, NULL, (unsigned char *)(void *)ss->d, ss->bytes,
                         ss->kbits, ss->fx0, ss->fx1, ss->clip, ss->evenodd, -1);
    for (i = 0; i < n; i++)
        for (t = 0; t < nr; t++) rast__ss_unstep(&aet[i]);
}

/* 1 when edge *u goes before edge *v in the AET of row j (both cross
 * it): left of it, or in the same column and left of it on the first
 * row after where their columns differ (looked at up to RAST__SS_AHEAD
 * rows on, while both cross them).  Two edges that do not cross are so
 * in the order of their columns on every row (rast__ss_multi's test);
 * two edges from one vertex (a star's spikes) are often in one column on
 * their first row, where the columns alone left the one right of the
 * other, and the segment's pass was undone on 46 rows of the star. */
static int rast__ss_before(const rast__edge *u, const rast__edge *v, int32_t j)
{
    rast__edge p, r;
    int32_t k;
    if (u->x != v->x) return u->x < v->x;
    p = *u;
    r = *v;
    k = (u->end < v->end ? u->end : v->end) - j - 1;
    for (k = k < RAST__SS_AHEAD ? k : RAST__SS_AHEAD; k > 0 && p.x == r.x; k--) {
        rast__edge_step(&p);
        rast__edge_step(&r);
    }
    return p.x < r.x;
}

/* The k edges add[] that start on row j joined to the n of aet[] (room
 * for n + k), in the order rast__ss_before tells (insertion, then a merge
 * from the back); more than 16 as aet.h joins them (in the order of
 * their columns alone).  Returns n + k. */
static int32_t rast__ss_join(rast__edge *aet, int32_t n, rast__edge *add, int32_t k, int32_t j)
{
    const int32_t total = n + k;
    int32_t i, m = total;
    if (k > 16) {
        return k <= RAST__AET_KEYS ? rast__aet_join_keys(aet, n, add, k)
                                   : rast__aet_join(aet, n, add, k);
    }
    for (i = 1; i < k; i++) {
        const rast__edge v = add[i];
        int32_t s = i;
        for (; s > 0 && rast__ss_before(&v, &add[s - 1], j); s--) add[s] = add[s - 1];
        add[s] = v;
    }
    for (n--, k--; k >= 0;) {
        if (n >= 0 && rast__ss_before(&add[k], &aet[n], j))
            aet[--m] = aet[n--];
        else
            aet[--m] = add[k--];
    }
    return total;
}

/* The walk of the edge table aet[0 .. nedges) as rast__ss_sweep_records
 * (aet.h's rast__aet_sweep: the table grouped by first row into edges[],
 * a row's new edges joined to the AET, those that end dropped), a
 * segment at a time (above). */
static void rast__ss_sweep_rows(rast__ss *ss, rast__edge *edges, rast__edge *aet,
                                int32_t *bucket, int32_t nedges, int32_t row0, int32_t row1)
{
    const int32_t kb = ss->kbits;
    uint64_t *mark = ss->dense ? NULL : ss->mark;
    int32_t j = row0, first = 0, n = 0, soonest = row1, k;
#if RAST__SS_DELTA
    /* (d[] holds 4 w + 8 bytes: 4 w + 1 fine columns' counts fit) */
    ss->bytes = ss->dense && kb == 2 && ss->o->format == RAST_COVERAGE_U8;
#endif
    rast__aet_group(edges, aet, bucket, nedges, row0, row1);
    while (j < row1) {
        const int32_t last = bucket[j - row0];
        int32_t b, nr;
        if (last != first) { /* the row's new edges join */
            for (k = first; k < last; k++) soonest = edges[k].end < soonest ? edges[k].end : soonest;
            n = rast__ss_join(aet, n, &edges[first], last - first, j);
            first = last;
        }
        if (n == 0) {
            j++;
            continue;
        }
        /* the segment [j, b): to the output row's end, the first row an
         * edge does not cross, the next row an edge joins on */
        b = ss->fy0 + ((((j - ss->fy0) >> kb) + 1) << kb);
        b = b < soonest ? b : soonest;
        b = b < j + RAST__SS_SEG ? b : j + RAST__SS_SEG;
        for (k = j + 1; k < b && bucket[k - row0] == first; k++) {
        }
        b = k;
        nr = b - j;
        rast__ss_row(ss, j - ss->fy0);
        ss->ends += n * nr;
        if (rast__ss_segment(ss, aet, n, nr, mark)) {
            /* out of order on one of its rows: a row at a time, each
             * sorted first (then in order) */
            rast__ss_undo(ss, aet, n, nr);
            for (k = j; k < b; k++) {
                rast__aet_sort(aet, n);
                (void)rast__ss_segment(ss, aet, n, 1, mark);
            }
        }
        j = b;
        if (soonest == b) { /* those that end here dropped (those before the
                               first that does stay where they are) */
            int32_t m;
            soonest = row1;
            for (k = 0; k < n && aet[k].end != b; k++)
                soonest = aet[k].end < soonest ? aet[k].end : soonest;
            for (m = k; k < n; k++) {
                if (aet[k].end == b) continue;
                soonest = aet[k].end < soonest ? aet[k].end : soonest;
                aet[m++] = aet[k];
            }
            n = m;
        }
    }
}
#endif

static int rast__ss_dense_of(uint64_t sum, int32_t lo, int32_t hi, const rast__ss *ss);

#if defined(__OPTIMIZE_SIZE__)
#define rast__ss_sweep(ss, edges, aet, bucket, nedges, row0, row1, xlo, xhi) \
    rast__ss_sweep_records(ss, edges, aet, bucket, nedges, row0, row1)
#else
/* The walk with an AET of keys: each active edge a 64-bit key, its
 * column over its index in the edge table, where its record stays from
 * the row it joins to its end (rather than aet.h's sweep, whose AET of
 * 48-byte records was merged and compacted on nearly every fine row of a
 * paragraph of text, the records moved each time: a quarter of the
 * fill).  A row: one pass over the keys that takes each edge's crossing
 * into the runs, steps the edge, and writes its key back unless it ends,
 * the next row's new edges' keys (sorted) merged in as it goes.  The
 * records the keys point at stay where the setup wrote them, those of a
 * row mostly neighbours (a ring's edges one after another). */

/* Edge *e's crossing of a non-zero row (the row's edges in order of
 * column) into its runs: w the winding number, a run from where it
 * leaves 0 to where it comes back (x0 the run's start, clamped and
 * relative to fx0). */
RAST__HOT void rast__ss_cross(const rast__edge *e, int32_t *w, int32_t *x0, int32_t *d,
                              uint64_t *mark, int32_t kb, int32_t fx0, int32_t fx1, int clamp)
{
    const int32_t x = rast__ss_at(e->x, fx0, fx1, clamp);
    if (*w == 0) *x0 = x;
    *w += e->dir;
    if (*w == 0) rast__ss_pair(d, mark, kb, *x0, x);
}

/* The key of the edge at byte `at` of the table (column x): ordered as
 * the columns.  (A byte offset, not an index: the record's address is
 * then one addition, rast__ss_edge_at.) */
static inline uint64_t rast__ss_key(int32_t x, uint32_t at)
{
    return ((uint64_t)((uint32_t)x ^ 0x80000000u) << 32) | at;
}

static inline rast__edge *rast__ss_edge_at(rast__edge *edges, uint32_t at)
{
    return (rast__edge *)(void *)((unsigned char *)edges + at);
}

/* The edge at byte `at` of edges[] stepped, its key written at out[*m]
 * unless it ends (y1 its end), its column checked against *last (the
 * last kept); before it, the next row's new edges' keys that come before
 * it (*nk the next of them, in order, ending in a sentinel above every
 * key: the merge that joins them to the AET, done as the keys are
 * written anyway).  A new key is at or after the key written before it
 * (else it would have gone before that one), so it hides no swap. */
RAST__HOT int rast__ss_keep(rast__edge *edges, uint32_t at, uint64_t *out, int32_t *m, int32_t y1,
                            int32_t *last, const uint64_t **nk)
{
    rast__edge *e = rast__ss_edge_at(edges, at);
    uint64_t key;
    int sw;
    rast__edge_step(e);
    if (e->end == y1) return 0;
    key = rast__ss_key(e->x, at);
    while (**nk < key) out[(*m)++] = *(*nk)++;
    sw = e->x < *last;
    *last = e->x;
    out[(*m)++] = key;
    return sw;
}

/* Fine row y's pass over the n keys act[] of the AET (edges[]: the edge
 * table): the runs, every edge stepped, its key written to out[] unless
 * it ends on the row (y1 = y + 1), with the next row's new keys nk[0 ..
 * kn) (in order, nk[kn] a sentinel above every key) merged in.  Returns
 * how many are in out[]; *swapped 1 when two changed places.  Pairs of
 * edges of opposite directions, while they come, each bound a run (the
 * winding number is back to 0 after each: most rows of most polygons
 * are only such pairs; all pairs, even-odd); from the first pair that is
 * not, edge by edge. */
RAST__HOT int32_t rast__ss_pass(const uint64_t *act, int32_t n, uint64_t *out, const uint64_t *nk,
                                int32_t kn, rast__edge *edges, int32_t y1, int32_t *d,
                                uint64_t *mark, int32_t kb, int32_t fx0, int32_t fx1, int clamp,
                                int evenodd, int *swapped)
{
    const uint64_t *const nk_end = nk + kn;
    int32_t i, m = 0, w = 0, x0 = 0, last = INT32_MIN, sw = 0;
    for (i = 0; i + 1 < n; i += 2) {
        const uint32_t a = (uint32_t)act[i], b = (uint32_t)act[i + 1];
        const rast__edge *l = rast__ss_edge_at(edges, a), *r = rast__ss_edge_at(edges, b);
        if (!evenodd && l->dir + r->dir != 0) break;
        rast__ss_pair(d, mark, kb, rast__ss_at(l->x, fx0, fx1, clamp),
                      rast__ss_at(r->x, fx0, fx1, clamp));
        sw |= rast__ss_keep(edges, a, out, &m, y1, &last, &nk);
        sw |= rast__ss_keep(edges, b, out, &m, y1, &last, &nk);
    }
    for (; i < n; i++) { /* (even-odd: an odd edge out, no run) */
        const uint32_t at = (uint32_t)act[i];
        if (!evenodd) rast__ss_cross(rast__ss_edge_at(edges, at), &w, &x0, d, mark, kb, fx0, fx1, clamp);
        sw |= rast__ss_keep(edges, at, out, &m, y1, &last, &nk);
    }
    while (nk < nk_end) out[m++] = *nk++; /* (after every key kept) */
    *swapped = sw;
    return m;
}

/* The k keys in[0 .. k) sorted: runs of 16 by insertion (a row's new
 * edges come mostly in order), then merged in pairs of runs twice as
 * long, between key[] and tmp[] (room for k each); returns the array
 * that holds them in order. */
static uint64_t *rast__ss_keys(const uint64_t *in, int32_t k, uint64_t *key, uint64_t *tmp)
{
    int32_t i, wd;
    for (i = 0; i < k; i++) {
        const uint64_t v = in[i];
        int32_t to = i;
        for (; to > (i & ~15) && key[to - 1] > v; to--) key[to] = key[to - 1];
        key[to] = v;
    }
    for (wd = 16; wd < k; wd *= 2) {
        uint64_t *t;
        for (i = 0; i < k; i += 2 * wd) {
            const int32_t mid = i + wd < k ? i + wd : k, hi = i + 2 * wd < k ? i + 2 * wd : k;
            int32_t a = i, b = mid, o = i;
            while (a < mid && b < hi) tmp[o++] = key[b] < key[a] ? key[b++] : key[a++];
            while (a < mid) tmp[o++] = key[a++];
            while (b < hi) tmp[o++] = key[b++];
        }
        t = key;
        key = tmp;
        tmp = t;
    }
    return key;
}

/* One fine row's pass with the rule, the clamp and the marks as constants
 * in each copy. */
static int32_t rast__ss_row_pass(rast__ss *ss, const uint64_t *act, int32_t n, uint64_t *out,
                                 const uint64_t *nk, int32_t kn, rast__edge *edges, int32_t y1,
                                 int *sw)
{
    const int32_t kb = ss->kbits, fx0 = ss->fx0, fx1 = ss->fx1;
    int32_t *d = ss->d;
    uint64_t *mark = ss->dense ? NULL : ss->mark;
    if (ss->evenodd || ss->clip)
        return rast__ss_pass(act, n, out, nk, kn, edges, y1, d, mark, kb, fx0, fx1, ss->clip,
                             ss->evenodd, sw);
    /* (the commonest case) */
    return mark ? rast__ss_pass(act, n, out, nk, kn, edges, y1, d, mark, kb, fx0, fx1, 0, 0, sw)
                : rast__ss_pass(act, n, out, nk, kn, edges, y1, d, NULL, kb, fx0, fx1, 0, 0, sw);
}

/* The counts of edges starting on each of `rows` rows (bucket[r + 1] for
 * row r, bucket[0] = 0) made where each row's run starts in a table
 * grouped by row (their running sum, in a register: through memory,
 * each row waited for the store of the one before). */
static void rast__ss_starts(int32_t *bucket, int32_t rows)
{
    int32_t j, run = 0;
    for (j = 0; j <= rows; j++) {
        run += bucket[j];
        bucket[j] = run;
    }
}

/* The walk of the edge table, as rast__ss_sweep_records: with the keys
 * when edges join and end on most rows (4 or more a row on average: at
 * most nedges active, written by each row's pass to a second array with
 * the next row's new ones merged in, where the merge of them into the
 * AET in a pass of its own, its comparisons mispredicted, was a tenth of
 * the time of text), else (long edges: a star's, a circle's) with the
 * records, which pays no key a row and an edge and moves the records on
 * few rows.  [xlo, xhi]: bounds of the crossings' columns (a crossing
 * outside them is found, and then costs only the sort at once). */
static void rast__ss_sweep(rast__ss *ss, rast__edge *edges, rast__edge *aet, int32_t *bucket,
                           int32_t nedges, int32_t row0, int32_t row1, int64_t xlo, int64_t xhi)
{
    /* The records stay in aet[], where the setup wrote them (grouping
     * them by first row into edges[], 48 bytes an edge written and read
     * again, was a tenth of the time of text: 1.6 MB past the caches);
     * edges[]'s room (nedges records of 48 bytes, 6 words each, 2 <=
     * nedges) holds their keys grouped by first row (read from the
     * records in order: reading each record's column when its row came
     * waited for it) and a word after them, the keys of this row and of
     * the next (nedges words each) and a row's new keys sorted (twice
     * their number, and a sentinel). */
    uint64_t *at = (uint64_t *)(void *)edges, *act = at + nedges + 1, *out = act + nedges,
             *add = out + nedges;
    int32_t j, e, first = 0, n = 0, sorted = 0;
    uint64_t sum = 0;
    if (nedges < 2 * ((int64_t)row1 - row0) ||
        (uint64_t)nedges * sizeof(rast__edge) > UINT32_MAX) {
        if (ss->dense < 0) {
            for (e = 0; e < nedges; e++) sum += (uint32_t)(aet[e].end - aet[e].row);
            ss->dense = rast__ss_dense_of(sum, row0, row1, ss);
        }
        rast__ss_sweep_rows(ss, edges, aet, bucket, nedges, row0, row1);
        return;
    }
    /* the keys grouped by first row (rast__aet_group's counting sort):
     * bucket[r - row0] is then where row r's run ends */
    rast__ss_starts(bucket, row1 - row0);
    at[nedges] = 0;
    if (xhi - xlo < 65536 && row1 - row0 < 65536) {
        /* and sorted within each row, all at once, without a comparison
         * (each row's dozen by insertion mispredicted where each stops:
         * a tenth of the time of text): an element an edge, its column
         * over xlo (16 bits: [xlo, xhi] holds every crossing), its row
         * over row0 (16 bits) and its index, put in order of column by
         * two passes of 8 bits (stable: equal columns stay in the order
         * of the records, as the keys' offsets order them), then by row
         * (stable) as it becomes its key in at[]; when a column is not
         * within 65,536 of xlo after all (bad), as before */
        uint32_t h0[256], h1[256];
        uint32_t bad = 0;
        memset(h0, 0, sizeof h0);
        memset(h1, 0, sizeof h1);
        for (e = 0; e < nedges; e++) {
            const uint32_t xr = (uint32_t)((int64_t)aet[e].x - xlo);
            sum += (uint32_t)(aet[e].end - aet[e].row);
            bad |= xr;
            act[e] = (uint64_t)(xr & 0xFFFFu) << 48 | (uint64_t)(aet[e].row - row0) << 32 |
                     (uint32_t)e;
            h0[xr & 255]++;
            h1[(xr >> 8) & 255]++;
        }
        sorted = bad < 65536;
        if (sorted) {
            uint32_t s0 = 0, s1 = 0, k;
            for (k = 0; k < 256; k++) {
                const uint32_t c0 = h0[k], c1 = h1[k];
                h0[k] = s0;
                h1[k] = s1;
                s0 += c0;
                s1 += c1;
            }
            for (e = 0; e < nedges; e++) out[h0[(act[e] >> 48) & 255]++] = act[e];
            for (e = 0; e < nedges; e++) act[h1[out[e] >> 56]++] = out[e];
            for (e = 0; e < nedges; e++) {
                const uint64_t v = act[e];
                at[bucket[(v >> 32) & 0xFFFF]++] =
                    rast__ss_key((int32_t)(xlo + (int64_t)(v >> 48)),
                                 (uint32_t)((size_t)(uint32_t)v * sizeof(rast__edge)));
            }
        } else {
            sum = 0; /* (counted again below) */
        }
    }
    if (!sorted) {
        for (e = 0; e < nedges; e++) {
            sum += (uint32_t)(aet[e].end - aet[e].row);
            at[bucket[aet[e].row - row0]++] =
                rast__ss_key(aet[e].x, (uint32_t)((size_t)e * sizeof(rast__edge)));
        }
    }
    /* the choice of flush from the fine rows the edges cross, summed over
     * the visible rows (the same ratio as the heights over the height),
     * read here with the rest of each record (a pass of its own over
     * 1.3 MB of text's records was 3% of its time) */
    if (ss->dense < 0) ss->dense = rast__ss_dense_of(sum, row0, row1, ss);
    for (j = row0; j < row1; j++) {
        uint64_t *nk, *t, keep = 0;
        int32_t kn;
        int swapped;
        if (n == 0) { /* none active: the row's new edges, if any */
            const int32_t k = bucket[j - row0] - first;
            if (!k) continue;
            memcpy(act, sorted ? at + first : rast__ss_keys(at + first, k, add, add + k),
                   (size_t)k * sizeof *act);
            n = k;
            first += k;
        }
        /* the next row's new edges' keys, sorted, merged in by the pass
         * (a sentinel after them: in at[], the next row's first key kept
         * aside) */
        kn = j + 1 < row1 ? bucket[j + 1 - row0] - first : 0;
        if (sorted) {
            nk = at + first;
            keep = nk[kn];
        } else {
            nk = rast__ss_keys(at + first, kn, add, add + kn + 1);
        }
        nk[kn] = UINT64_MAX;
        rast__ss_row(ss, j - ss->fy0);
        ss->ends += n;
        n = rast__ss_row_pass(ss, act, n, out, nk, kn, aet, j + 1, &swapped);
        if (sorted) nk[kn] = keep;
        first += kn;
        t = act;
        act = out;
        out = t;
        if (swapped) { /* insertion sort of the keys */
            int32_t i, s;
            for (i = 1; i < n; i++) {
                const uint64_t v = act[i];
                for (s = i; s > 0 && act[s - 1] > v; s--) act[s] = act[s - 1];
                act[s] = v;
            }
        }
    }
}
#endif

/* 1 when the polygon's output rows are expected to hold many runs' ends
 * (one a column in 4 or more): its edges' heights summed (the crossings
 * of all fine rows) times k over its height (k fine rows an output row).
 * Such rows are written by rast__ss_flush_dense whole, and then the runs
 * need no marks (a mark costs about as much as a run's end; with fewer
 * ends, summing every column costs more than the marks save).  Only for
 * uint8_t rows, which that flush writes; the choice changes no value. */
/* The test itself, from the edges' heights summed (sum) and the least
 * and greatest y of their ends (lo, hi). */
static int rast__ss_dense_of(uint64_t sum, int32_t lo, int32_t hi, const rast__ss *ss)
{
    /* sum / (hi - lo) k 4 >= w (both sides below 2^63) */
    return ss->o->format == RAST_COVERAGE_U8 && hi > lo &&
           sum / (uint64_t)((int64_t)hi - lo) * ((uint64_t)4 << ss->kbits) >=
               (uint64_t)(ss->fx1 - ss->fx0) >> ss->kbits;
}

#if defined(__OPTIMIZE_SIZE__)
/* (a build for size: from the rings, before the walk's setup, which saves
 * the setup's call and the walk's, inlined in rast__aet_walk) */
static int rast__ss_dense(const rast_polygon *poly, const rast__ss *ss)
{
    const rast_point *p = poly->points;
    uint64_t sum = 0;
    int32_t lo, hi;
    uint32_t k, i, base;
    if (ss->o->format != RAST_COVERAGE_U8 || !poly->nrings) return 0;
    lo = hi = p[0].y;
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        const uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++) {
            const int32_t ya = p[base + i].y, yb = p[base + (i + 1 == n ? 0 : i + 1)].y;
            sum += (uint64_t)(ya < yb ? (int64_t)yb - ya : (int64_t)ya - yb);
            if (ya < lo) lo = ya;
            if (ya > hi) hi = ya;
        }
    }
    return rast__ss_dense_of(sum, lo, hi, ss);
}
#else
#endif

/* 1 when every crossing of the polygon (points on the fine grid, S
 * fraction bits) lies within the fine clip's columns: the crossing of a
 * row is the first column at or right of a point of an edge, so within a
 * column of the points' extent. */
static int rast__ss_inside(const rast_point *pts, uint32_t npoints, int32_t s,
                           const rast__ss *ss)
{
    int32_t lo, hi;
    uint32_t i;
    if (npoints == 0) return 1;
    lo = hi = pts[0].x;
    for (i = 1; i < npoints; i++) {
        if (pts[i].x < lo) lo = pts[i].x;
        if (pts[i].x > hi) hi = pts[i].x;
    }
    /* every crossing's column lies in [floor(lo / 2^S) - 1,
     * floor(hi / 2^S) + 1] */
    return (int64_t)lo >= ((int64_t)ss->fx0 + 1) * ((int64_t)1 << s) &&
           (int64_t)hi < ((int64_t)ss->fx1 - 1) * ((int64_t)1 << s);
}

/* 64-bit words of a fine row's bits (triangle batches), one spare. */
static size_t rast__ss_bitwords(int32_t width, int32_t kbits)
{
    return ((size_t)width << kbits) / 64 + 1;
}

size_t rast__cov_ss_scratch(uint32_t npoints, int32_t kbits, int32_t width, int32_t height)
{
    if ((int64_t)width << kbits > RAST_MAX_DIM || (int64_t)height << kbits > RAST_MAX_DIM)
        return (size_t)-1;
    /* The triangles' records (rast__cov_ss_tris) take less than the AET's
     * edge tables (two edge records per vertex); the k fine rows of bits
     * are theirs alone. */
    return rast__size_add(
        rast__size_add(rast__aet_scratch(npoints, width << kbits, height << kbits),
                       rast__align(rast__ss_bitwords(width, kbits) * 8 << kbits)),
        rast__size_add(rast__align(rast__size_mul((size_t)width + 2, sizeof(int32_t))),
                       rast__size_add(rast__align(((size_t)width / 64 + 1) * 8),
                                      ((size_t)1 << (2 * kbits)) * 8 + 8)));
}

/* The counters out of the arena, cleared, and the fine clip (*fine). */
static rast_status rast__ss_begin(rast__ss *ss, int32_t kbits, const rast__cov_out *o,
                                  rast__arena *arena, rast_rect *fine)
{
    int32_t k, w = o->clip.x1 - o->clip.x0;
    ss->o = o;
    ss->kbits = kbits;
    ss->evenodd = 0; /* (triangle batches: non-zero, clamped, marked) */
    ss->clip = 1;
    ss->dense = 0;
    ss->bytes = 0;
    ss->row = -1;
    ss->next = 0;
    ss->ends = 0;
    ss->d = (int32_t *)rast__take(arena, ((size_t)w + 2) * sizeof(int32_t));
    ss->mark = (uint64_t *)rast__take(arena, ((size_t)w / 64 + 1) * 8);
    ss->level = (uint64_t *)rast__take(arena, (((size_t)1 << (2 * kbits)) + 1) * sizeof(uint64_t));
    if (!ss->d || !ss->mark || !ss->level) return RAST_E_SCRATCH;
    memset(ss->d, 0, ((size_t)w + 2) * sizeof(int32_t));
    memset(ss->mark, 0, ((size_t)w / 64 + 1) * 8);
    /* count / k^2 is exactly count 2^(62 - 2 kbits) / 2^62 */
    for (k = 0; k <= (int32_t)1 << (2 * kbits); k++)
        ss->level[k] = rast__cov_level(o->format, (uint64_t)k << (62 - 2 * kbits));
    fine->x0 = ss->fx0 = o->clip.x0 * ((int32_t)1 << kbits);
    fine->y0 = ss->fy0 = o->clip.y0 * ((int32_t)1 << kbits);
    fine->x1 = ss->fx1 = o->clip.x1 * ((int32_t)1 << kbits);
    fine->y1 = o->clip.y1 * ((int32_t)1 << kbits);
    return RAST_OK;
}

/* The last output rows: the one being counted, then zeros to the clip's end. */
static void rast__ss_finish(rast__ss *ss)
{
    if (ss->row >= 0) rast__ss_flush(ss);
    rast__cov_zero_rows(ss->o, ss->o->clip.y0 + ss->next, ss->o->clip.y1);
}

/* A painter's output (its rows handed on as runs, rast__cov_row_done)
 * narrowed to the pixels the polygon's crossings can reach, a pixel
 * either side (so that rast__ss_inside still holds): the rows' counters,
 * flushes and scans then cost those columns, not the clip's width (400
 * tiny polygons a call each on a 512-wide canvas spent 60% of their
 * instructions scanning rows of 0).  The columns left out hold 0: no run
 * reaches them.  0 when no column is left (nothing to hand on). */
static int rast__ss_narrow(const rast_point *pts, uint32_t npoints, int32_t s, int32_t kbits,
                           const rast__cov_out *o, rast__cov_out *sub)
{
    int64_t lo, hi, p0, p1;
    uint32_t i;
    *sub = *o;
    if (!o->paint || npoints == 0) return 1;
    lo = hi = pts[0].x;
    for (i = 1; i < npoints; i++) {
        lo = pts[i].x < lo ? pts[i].x : lo;
        hi = pts[i].x > hi ? pts[i].x : hi;
    }
    /* crossings in fine columns [floor(lo / 2^S) - 1, floor(hi / 2^S) + 1]
     * (rast__ss_inside), their pixels widened by one */
    p0 = rast__floordiv(rast__floordiv(lo, (int64_t)1 << s) - 1, (int64_t)1 << kbits) - 1;
    p1 = rast__floordiv(rast__floordiv(hi, (int64_t)1 << s) + 1, (int64_t)1 << kbits) + 2;
    if (p0 > o->clip.x0) sub->clip.x0 = (int32_t)(p0 < o->clip.x1 ? p0 : o->clip.x1);
    if (p1 < o->clip.x1) sub->clip.x1 = (int32_t)(p1 > o->clip.x0 ? p1 : o->clip.x0);
    return sub->clip.x0 < sub->clip.x1;
}

#if RAST__SS_DELTA
/* ---- winding deltas on the fine grid (SSE2 builds for speed) --------------
 * As the binary fill's deltas (fillers/aet.c, the edge flag method's
 * idea): every edge walks its fine rows with its own DDA (the same
 * crossings, to the bit) and adds its direction (1 under even-odd) to a
 * byte counter at its crossing's column, clamped to [0, w] (a crossing
 * left of the clip counts for every sample of the row, one right of it
 * for none); then each fine row's counters are summed along, 16 at once,
 * the running sum modulo 2^8 telling each sample in or out (even-odd:
 * odd; non-zero: not 0, exact when no row has more than 510 crossings: a
 * row's crossings sum to 0, so a winding number is at most half of them
 * in magnitude), into the fine row's bits, and an output row's k rows of
 * bits are counted as a triangle batch's (rast__ss_bits_row).  No sort,
 * no key, no merge: a crossing costs an addition, a fine row a pass over
 * its counters (text: 137,000 crossings on 2,048 rows of 129 vectors, the
 * keys' walk 60 instructions a crossing).  The walk is fillers/aet.c's
 * (rast__delta_walk, base/aet.h), its counters rows of samples here, the
 * rows in bands of whole output rows. */

static void rast__ss_bits_row(rast__ss *ss, int32_t R, uint64_t *bits, size_t wpr, int32_t k0,
                              int32_t k1);

/* The 64 counters at c or-ed together, 16 lanes: all 0 when none is set. */
static inline __m128i rast__ss_or64(const unsigned char *c)
{
    const __m128i a = _mm_loadu_si128((const __m128i *)(const void *)c),
                  b = _mm_loadu_si128((const __m128i *)(const void *)(c + 16)),
                  d = _mm_loadu_si128((const __m128i *)(const void *)(c + 32)),
                  e = _mm_loadu_si128((const __m128i *)(const void *)(c + 48));
    return _mm_or_si128(_mm_or_si128(a, b), _mm_or_si128(d, e));
}

/* 16 counters at c summed along (modulo 2^8) after the running sum
 * *sum (in every lane), which moves on past them, and cleared: the lanes
 * inside (even-odd: odd; non-zero: not 0) as 16 bits. */
static inline uint32_t rast__ss_delta16(unsigned char *c, __m128i *sum, int evenodd)
{
    const __m128i zero = _mm_setzero_si128();
    __m128i v = _mm_add_epi8(rast__delta_take16(c), *sum), t;
    /* the last lane's sum in every lane */
    t = _mm_unpackhi_epi8(v, v);
    t = _mm_shufflehi_epi16(t, 0xFF);
    *sum = _mm_unpackhi_epi64(t, t);
    /* (even-odd: bit 0 of each lane to its bit 7) */
    return evenodd ? (uint32_t)_mm_movemask_epi8(_mm_slli_epi16(v, 7))
                   : (uint32_t)_mm_movemask_epi8(_mm_cmpeq_epi8(v, zero)) ^ 0xFFFFu;
}

/* A fine row's counters (stride bytes, a multiple of 64; columns [0, w)
 * the clip's) summed along into its row of bits (a word of 64 columns
 * at a time, set where inside; words of no crossing and outside left as
 * they are, 0), the counters cleared; [*lo, *hi] grows over the words
 * written. */
RAST__HOT void rast__ss_delta_row(unsigned char *row, int32_t stride, int32_t w, int evenodd,
                                  uint64_t *bits, int32_t *lo, int32_t *hi)
{
    __m128i sum = _mm_setzero_si128(); /* the running sum, modulo 2^8, in every lane */
    int32_t k;
    for (k = 0; k < stride; k += 64) {
        uint64_t m;
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(rast__ss_or64(row + k), _mm_setzero_si128())) ==
            0xFFFF) {
            /* no crossing: every column as the one before */
            const int in = evenodd ? _mm_movemask_epi8(_mm_slli_epi16(sum, 7)) != 0
                                   : _mm_movemask_epi8(_mm_cmpeq_epi8(sum, _mm_setzero_si128())) == 0;
            if (!in) continue;
            m = ~(uint64_t)0;
        } else {
            m = (uint64_t)rast__ss_delta16(row + k, &sum, evenodd);
            m |= (uint64_t)rast__ss_delta16(row + k + 16, &sum, evenodd) << 16;
            m |= (uint64_t)rast__ss_delta16(row + k + 32, &sum, evenodd) << 32;
            m |= (uint64_t)rast__ss_delta16(row + k + 48, &sum, evenodd) << 48;
        }
        if (w - k < 64) m &= w - k > 0 ? ~(uint64_t)0 >> (64 - (w - k)) : 0; /* (past the clip) */
        if (m) {
            bits[k >> 6] = m;
            *lo = (k >> 6) < *lo ? k >> 6 : *lo;
            *hi = (k >> 6) > *hi ? k >> 6 : *hi;
        }
    }
}

/* k = 4, uint8_t levels: the inside lanes of 16 summed counters (their
 * running sum *sum moved on past them as rast__ss_delta16's) added to
 * *acc's bytes, 1 each (even-odd: bit 0; non-zero: *acc counts down
 * from 4 at the lanes outside, those equal to 0). */
static inline void rast__ss_count16(unsigned char *c, __m128i *sum, __m128i *acc, int evenodd)
{
    __m128i v = _mm_add_epi8(rast__delta_take16(c), *sum), t;
    t = _mm_unpackhi_epi8(v, v);
    t = _mm_shufflehi_epi16(t, 0xFF);
    *sum = _mm_unpackhi_epi64(t, t);
    *acc = _mm_add_epi8(*acc, evenodd ? _mm_and_si128(v, _mm_set1_epi8(1))
                                      : _mm_cmpeq_epi8(v, _mm_setzero_si128()));
}

/* Four vectors of inside counts, a byte a sample column (0 .. 4, the
 * four fine rows'), to 16 pixels' uint8_t levels: each pixel's 4 columns
 * summed (c, 0 .. 16) and its level (rast__ss_level16). */
static inline __m128i rast__ss_levels16(__m128i a, __m128i b, __m128i c, __m128i d)
{
    const __m128i low = _mm_set1_epi32(0xFF);
    __m128i n;
    a = _mm_add_epi8(a, _mm_srli_epi32(a, 16));
    b = _mm_add_epi8(b, _mm_srli_epi32(b, 16));
    c = _mm_add_epi8(c, _mm_srli_epi32(c, 16));
    d = _mm_add_epi8(d, _mm_srli_epi32(d, 16));
    a = _mm_and_si128(_mm_add_epi8(a, _mm_srli_epi32(a, 8)), low);
    b = _mm_and_si128(_mm_add_epi8(b, _mm_srli_epi32(b, 8)), low);
    c = _mm_and_si128(_mm_add_epi8(c, _mm_srli_epi32(c, 8)), low);
    d = _mm_and_si128(_mm_add_epi8(d, _mm_srli_epi32(d, 8)), low);
    n = _mm_packus_epi16(_mm_packs_epi32(a, b), _mm_packs_epi32(c, d));
    return rast__ss_level16(n);
}

/* k = 4, uint8_t levels: output row R (clip-relative) straight from its
 * four fine rows of counters at fr (stride bytes apart, the clip's
 * columns first), 64 columns (16 pixels) at a time, the counters cleared:
 * the prefix sums and the count of the 4 x 4 samples of each pixel in
 * one pass, no rows of bits.  64 columns with no counter set are the
 * running sums' constant.  A row none of whose counters is set is left
 * to be zeroed (as rast__ss_bits_row's with no bit set). */
static void rast__ss_delta_row4(rast__ss *ss, int32_t R, unsigned char *fr, int32_t stride)
{
    const rast__cov_out *o = ss->o;
    const int evenodd = ss->evenodd;
    const int32_t W = o->clip.x1 - o->clip.x0, y = o->clip.y0 + R;
    const __m128i zero = _mm_setzero_si128(), four = _mm_set1_epi8(evenodd ? 0 : 4);
    __m128i sum[4];
    unsigned char *row = NULL;
    int32_t k, u;
    for (u = 0; u < 4; u++) sum[u] = zero;
    for (k = 0; k < stride; k += 64) {
        const int32_t base = k >> 2, n = W - base < 16 ? W - base : 16;
        __m128i any = zero, lv;
        for (u = 0; u < 4; u++)
            any = _mm_or_si128(any, rast__ss_or64(fr + (size_t)u * (size_t)stride + (size_t)k));
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(any, zero)) == 0xFFFF) {
            /* every column as the one before: 4 samples a fine row inside */
            __m128i a = four;
            if (!row) continue; /* (0, as every pixel before) */
            for (u = 0; u < 4; u++)
                a = _mm_add_epi8(a, evenodd ? _mm_and_si128(sum[u], _mm_set1_epi8(1))
                                            : _mm_cmpeq_epi8(sum[u], zero));
            lv = rast__ss_level16(_mm_slli_epi16(a, 2)); /* (at most 16 in a byte) */
        } else {
            __m128i a0 = four, a1 = four, a2 = four, a3 = four;
            for (u = 0; u < 4; u++) {
                unsigned char *c = fr + (size_t)u * (size_t)stride + (size_t)k;
                rast__ss_count16(c, &sum[u], &a0, evenodd);
                rast__ss_count16(c + 16, &sum[u], &a1, evenodd);
                rast__ss_count16(c + 32, &sum[u], &a2, evenodd);
                rast__ss_count16(c + 48, &sum[u], &a3, evenodd);
            }
            if (n <= 0) continue; /* (column w: a crossing right of the clip) */
            lv = rast__ss_levels16(a0, a1, a2, a3);
            if (!row) {
                rast__cov_zero_rows(o, o->clip.y0 + ss->next, y);
                ss->next = R + 1;
                row = rast__cov_row(o, y);
                memset(row, 0, (size_t)base);
            }
        }
        if (n >= 16) {
            _mm_storeu_si128((__m128i *)(void *)(row + base), lv);
        } else if (n > 0) {
            unsigned char tmp[16];
            _mm_storeu_si128((__m128i *)(void *)tmp, lv);
            memcpy(row + base, tmp, (size_t)n);
        }
    }
    if (row) rast__cov_row_done(o, y);
}

/* Edge *d through the fine rows [j0, j1) of a band (rast__delta_walk,
 * base/aet.h: the clip's columns from fx0, w of them, cut when `clamp`),
 * on a copy in locals (a byte store may alias the record: its DDA would
 * be stored and loaded again at every row); 1 when it goes on past the
 * band, its DDA then left on row j1. */
RAST__HOT int rast__ss_delta_edge(rast__edge *d, unsigned char *buf, int32_t j0, int32_t j1,
                            int32_t stride, int32_t fx0, int32_t w, int evenodd, int clamp)
{
    rast__edge l = *d;
    const unsigned char dir = (unsigned char)(evenodd ? 1 : l.dir);
    if (clamp) rast__delta_walk(&l, buf, j0, j1, stride, fx0, w, dir, 1, 1);
    else rast__delta_walk(&l, buf, j0, j1, stride, fx0, w, dir, 1, 0);
    if (l.end <= j1) return 0;
    d->x = l.x;
    d->e = l.e;
    return 1;
}

/* The walk by deltas of the edge table t (npoints records of room in
 * t->edges, free once the records are set up in t->aet) when it pays:
 * many short edges (at least 2 a fine row), the fine rows' words of 64
 * counters at most 4 a crossing, and it can:
 * the counters of a band of output rows, the rows of bits of one and an
 * index an edge twice fit, and (non-zero) no row has more than 510
 * crossings.  The rows go in bands of at most 32 output rows (their
 * counters within the caches), each walking the edges that reach it:
 * those that joined before and go on (a list), then its new ones (the
 * edges grouped by the band they start in).  Returns 1 when done, 0
 * (nothing done, the records as they were) when not. */
static int rast__ss_delta(rast__ss *ss, const rast__aet_tab *t, uint32_t npoints,
                          rast__arena *arena)
{
    const int32_t kb = ss->kbits, K = (int32_t)1 << kb, w = ss->fx1 - ss->fx0;
    const int32_t rows = t->row1 - t->row0, nedges = t->nedges, clamp = ss->clip;
    const size_t room = (size_t)npoints * sizeof(rast__edge);
    rast__edge *const ed = t->aet;
    int32_t *link, *act, *start;
    unsigned char *buf;
    int32_t stride, e, hb, bb, nbands, r0, r1, R, Rb, band, nact = 0;
    int64_t crossings = 0;
    size_t wpr, idx;
    uint64_t *bits;
    /* (many short edges, as the keys' walk takes them: long ones, a
     * star's or a circle's, cost their rows less in the AET) */
    if (w <= 0 || w >= INT32_MAX - 128 || nedges < 2 * (int64_t)rows) return 0;
    stride = (w + 1 + 63) & ~63;
    /* the room: the edges' indices grouped by band, the list of those
     * going on, a band's starts (or the rows' ends), then the counters
     * of a band of 2^bb output rows, at most 32 (within the caches) */
    r0 = (t->row0 - ss->fy0) >> kb;
    r1 = ((t->row1 - 1 - ss->fy0) >> kb) + 1;
    idx = rast__align(((size_t)2 * (size_t)nedges + 2 * (size_t)rows + 4) * sizeof(int32_t));
    if (idx >= room) return 0;
    for (bb = 5; bb >= 0 && (size_t)stride << (bb + kb) > room - idx; bb--) {
    }
    if (bb < 0) return 0;
    hb = (int32_t)1 << (bb + kb);
    link = (int32_t *)(void *)t->edges; /* link[e]: the next edge of e's band, or -1 */
    act = link + nedges;
    start = act + nedges; /* start[b]: band b's first edge, or -1 */
    nbands = ((r1 - r0 - 1) >> bb) + 1;
    /* one pass over the records: the crossings, each band's count of
     * new edges, and (non-zero, more than 511 edges: the most crossings
     * on a row, edges started less ended, the starts from the buckets,
     * bucket[r - row0 + 1] row r's) the rows' ends, into start[] */
    {
        const int most = !ss->evenodd && nedges > 511;
        int32_t *const ends = start + nbands + 1;
        memset(start, 0xFF, ((size_t)nbands + 1) * sizeof(int32_t));
        if (most) memset(ends, 0, ((size_t)rows + 1) * sizeof(int32_t));
        for (e = 0; e < nedges; e++) {
            crossings += ed[e].end - ed[e].row;
            const int32_t band_of = (((ed[e].row - ss->fy0) >> kb) - r0) >> bb;
            link[e] = start[band_of];
            start[band_of] = e;
            if (most) ends[ed[e].end - t->row0]++;
        }
        if ((int64_t)rows * (stride / 64) > 4 * crossings) return 0;
        if (most) {
            int32_t run = 0, y;
            for (y = 1; y <= rows; y++) {
                run += t->bucket[y] - ends[y - 1];
                if (run > 510) return 0;
            }
        }
    }
    wpr = rast__ss_bitwords(w >> kb, kb);
    bits = (uint64_t *)rast__take(arena, (size_t)K * wpr * 8);
    if (!bits) return 0;
    memset(bits, 0, (size_t)K * wpr * 8);
    buf = (unsigned char *)(void *)t->edges + idx;
    memset(buf, 0, (size_t)hb * (size_t)stride);
    for (Rb = r0, band = 0; Rb < r1; Rb += hb >> kb, band++) {
        const int32_t Re = r1 - Rb > hb >> kb ? Rb + (hb >> kb) : r1;
        const int32_t j0 = ss->fy0 + (Rb << kb), j1 = ss->fy0 + (Re << kb);
        int32_t i, m = 0;
        /* those going on, kept when they go on past this band; then the
         * band's new ones */
        for (i = 0; i < nact; i++)
            if (rast__ss_delta_edge(&ed[act[i]], buf, j0, j1, stride, ss->fx0, w, ss->evenodd,
                                    clamp))
                act[m++] = act[i];
        for (i = start[band]; i >= 0; i = link[i])
            if (rast__ss_delta_edge(&ed[i], buf, j0, j1, stride, ss->fx0, w, ss->evenodd, clamp))
                act[m++] = i;
        nact = m;
        for (R = Rb; R < Re; R++) {
            int32_t lo = INT32_MAX, hi = -1, u;
            if (kb == 2 && ss->o->format == RAST_COVERAGE_U8) {
                rast__ss_delta_row4(ss, R, buf + (size_t)((R - Rb) * K) * (size_t)stride, stride);
                continue;
            }
            for (u = 0; u < K; u++)
                rast__ss_delta_row(buf + (size_t)((R - Rb) * K + u) * (size_t)stride, stride, w,
                                   ss->evenodd, bits + (size_t)u * wpr, &lo, &hi);
            if (lo <= hi) rast__ss_bits_row(ss, R, bits, wpr, lo, hi);
        }
    }
    return 1;
}
#endif

static int rast__ss_cancel(rast__ss *ss, const rast_point *pts, const uint32_t *ring_sizes,
                           uint32_t npoints, const rast__grid *g, const rast_rect *fine,
                           rast__arena *arena);

rast_status rast__cov_ss(const rast_polygon *poly, uint32_t npoints, int32_t s,
                         int32_t kbits, rast_fill_rule rule, rast_sample sample,
                         const rast__cov_out *out, rast__arena *arena)
{
    rast__ss ss;
    rast__grid g;
    rast_rect fine;
#if !defined(__OPTIMIZE_SIZE__)
    rast__aet_tab t;
#endif
    rast__cov_out sub;
    const rast__cov_out *o = &sub;
    rast_status st = rast__grid_init(&g, s, sample, RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT);
    if (st == RAST_OK && !rast__ss_narrow(poly->points, npoints, s, kbits, out, &sub))
        return RAST_OK;
    if (st == RAST_OK) st = rast__ss_begin(&ss, kbits, o, arena, &fine);
    if (st != RAST_OK) return st;
    ss.evenodd = rule == RAST_RULE_EVENODD;
    ss.clip = !rast__ss_inside(poly->points, npoints, s, &ss);
    /* many small rings (a mesh's cells, at most 8 vertices a ring on
     * average): their shared edges may cancel (rast__ss_cancel) */
    if (npoints <= 8 * (uint64_t)poly->nrings &&
        rast__ss_cancel(&ss, poly->points, poly->ring_sizes, npoints, &g, &fine, arena)) {
        rast__ss_finish(&ss);
        return RAST_OK;
    }
#if defined(__OPTIMIZE_SIZE__)
    ss.dense = rast__ss_dense(poly, &ss);
    st = rast__aet_walk(poly, npoints, &g, rule, &fine, arena, NULL, rast__ss_row_ends, &ss,
                        NULL);
    if (st != RAST_OK) return st;
#else
    st = rast__aet_prepare(poly, npoints, &g, &fine, arena, NULL, &t);
    if (st != RAST_OK) return st;
#if RAST__SS_DELTA
    if (t.row0 < t.row1 && rast__ss_delta(&ss, &t, npoints, arena)) {
        rast__ss_finish(&ss);
        return RAST_OK;
    }
#endif
    if (t.row0 < t.row1) {
        ss.dense = -1; /* (from the records, rast__ss_sweep) */
        /* (the crossings' columns: rast__ss_inside's) */
        rast__ss_sweep(&ss, t.edges, t.aet, t.bucket, t.nedges, t.row0, t.row1,
                       rast__floordiv(t.minx, (int64_t)1 << s) - 1,
                       rast__floordiv(t.maxx, (int64_t)1 << s) + 1);
    }
#endif
    rast__ss_finish(&ss);
    return RAST_OK;
}

/* ---- triangle batches: shared edges cancel -------------------------------
 * Every triangle turned the same way, the batch's winding number is the
 * sum of the triangles' and the union is where it is not 0.  An edge a->b
 * of one triangle and b->a of another (a mesh's inner edges) cross the
 * same rows at the same columns in opposite directions: their parts of
 * the winding cancel at every sample, and both can go.  When most edges
 * go so (a mesh: only its outline is left), what is left is walked as a
 * polygon under the non-zero rule (the AET), at the cost of its outline;
 * else the triangles are walked each on its own (below). */

/* The edges of `pts` (rings of ring_sizes[0 .. nrings), or, with
 * ring_sizes NULL, triangles) less those that cancel, walked into
 * the counts (the rule ss->evenodd's) when at most half of them are left;
 * returns 1 then, else 0 with the arena as it was.  The winding number
 * is the sum of the edges' parts, so the cancelled ones change it
 * nowhere: non-zero keeps |n| copies of a segment, even-odd n mod 2 (the
 * parity).  (Its memory, the segments, the table and the AET's for at
 * most npoints / 2 edges, is less than the AET's for npoints edges that
 * the scratch holds.) */
static int rast__ss_cancel(rast__ss *ss, const rast_point *pts, const uint32_t *ring_sizes,
                           uint32_t npoints, const rast__grid *g, const rast_rect *fine,
                           rast__arena *arena)
{
    const rast__arena keep = *arena;
    rast__seg *seg;
    rast__edge *edges, *aet;
    int32_t *bucket, i, m, nedges, row0, row1, miny = INT32_MAX, maxy = INT32_MIN;
    uint32_t copies;
    uint64_t sum = 0;
    int64_t r;
    /* the segments that stay (base/edge.c: equal ones summed, a batch that
     * is not a mesh given up on the way), their rows and the fine rows
     * they cross, for the counts' density */
    m = rast__segs_cancel(pts, ring_sizes, npoints, ss->evenodd, arena, &seg, &copies);
    if (m < 0) return 0;
    for (i = 0; i < m; i++) {
        const int32_t n = seg[i].n;
        miny = seg[i].a.y < miny ? seg[i].a.y : miny;
        maxy = seg[i].b.y > maxy ? seg[i].b.y : maxy;
        sum += (uint64_t)((int64_t)seg[i].b.y - seg[i].a.y) * (uint64_t)(n < 0 ? -n : n);
    }
    if (m == 0) return 1;
    ss->dense = rast__ss_dense_of(sum, miny, maxy, ss);
    r = rast__row_at_or_after(2 * (int64_t)miny, g);
    row0 = r > fine->y0 ? (int32_t)r : fine->y0;
    r = rast__row_at_or_after(2 * (int64_t)maxy, g);
    row1 = r < fine->y1 ? (int32_t)r : fine->y1;
    if (row0 >= row1) return 1;
    if (!rast__aet_tables(arena, copies, row0, row1, &edges, &aet, &bucket)) {
        *arena = keep; /* (it fits: the walk of all edges then says so) */
        return 0;
    }
    nedges = rast__segs_edges(seg, m, g, row0, row1, aet, bucket);
    /* (the clip's columns: a crossing outside them, if any, is found on
     * the way) */
    rast__ss_sweep(ss, edges, aet, bucket, nedges, row0, row1, (int64_t)fine->x0 - 1,
                   (int64_t)fine->x1 + 1);
    return 1;
}

/* ---- triangle batches ----------------------------------------------------
 * The union of the triangles, each walked on its own: a sample is inside
 * the union (non-zero, every triangle turned the same way) iff it is inside
 * one of them, since the winding number is the sum of the triangles' and
 * each is 0 or 1.  On a fine row each active triangle's run [x of one edge,
 * x of the other) sets bits in a row of bits; the row's runs of set bits
 * then go into the counts.  No sort of edges by column (the AET's cost
 * when many triangles overlap): a fine row costs its triangles and a pass
 * over the words they touched.  The k fine rows of an output row, or of
 * a band of up to RAST__SS_BAND of them while fewer than 256 triangles
 * are active, are walked together, a triangle at a time (rows of bits
 * for each). */

/* Output rows walked together when few triangles are active, their runs
 * straight into the bits.  Size-optimised builds keep the smaller walk
 * of before: an output row at a time, every run through the pending
 * ones (the same bits, the same pixels). */
#if defined(__OPTIMIZE_SIZE__)
#define RAST__SS_BAND 1
#define RAST__SS_DIRECT 0
#else
#define RAST__SS_BAND 32
#define RAST__SS_DIRECT 1
#endif
/* Bands of more than 8 output rows only while their rows of bits stay
 * within 32 KiB (a first-level cache): 32 rows of a 512-pixel canvas at
 * k = 4 (33 KiB, 1,056 bytes a row).  A triangle's record is read and
 * written, and its walk set up, once a band: bands of 32 rows took 4%
 * (tri3k) and 5% (tri10k) fewer instructions than bands of 8, 11% less
 * time on tri3k (CHANGELOG, session 16). */
#define RAST__SS_BAND_BYTES 32768
/* A pile's skips in a loop of their own (rast__ss_skips) and words of
 * bits told empty or full before they are counted: not in a build for
 * size (the walk's own test skips the same triangles, the count gives
 * the same values). */
#define RAST__SS_QUICK RAST__SS_DIRECT
/* Triangles ahead of the setup whose records' cache lines are fetched
 * (rast__cov_ss_tris): compilers that have __builtin_prefetch, not in a
 * build for size. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define RAST__SS_PREFETCH 8
#else
#define RAST__SS_PREFETCH 0
#endif

/* A triangle on the fine grid, what its walk reads on every output row
 * (the table of them is walked once per output row: the smaller, the
 * fewer bytes read): edge 0 from its top to its bottom vertex and edge 1
 * the other edge crossing the current row (rast__edge's fields that
 * change or step), the current row, and whether the edge below the
 * middle vertex (kept apart, in `low`) is still to come. */
typedef struct rast__ss_tri {
    int64_t e[2], dr[2], q[2];
    int64_t drk[2]; /* the edges' growth over k rows (rast__ss_jump); -1: not
                       worked out yet, -2: too far to take */
    int32_t x[2], step[2], end[2], stepk[2];
    int32_t row, next;
    int32_t c0, c1; /* every run's columns within [c0, c1] (the vertices'
                       columns, clipped) */
    int32_t flip;   /* 1: edge 1 is the left one (else edge 0, or both the
                       same: no run) */
    int32_t clamp;  /* 1: a run may reach outside the clip's columns */
    int32_t lim;    /* output rows skipped whole (rast__cov_ss_tris) while
                       they end at or before it: edge 0's end and the
                       lower edge's start; INT32_MIN until both edges'
                       growth over k rows is worked out (rast__ss_jump) */
} rast__ss_tri;

/* Edge k of triangle r (held in *ed) moved k rows on: one step of the
 * DDA with the growth of k rows, K dr = c q + drk (0 <= drk < q), whole
 * columns K step + c (worked out once); 0 when they do not fit. */
static inline int rast__ss_jump(rast__ss_tri *r, int k, rast__edge *ed, int32_t K)
{
    int64_t e;
    if (r->drk[k] < 0) { /* (one test on the way taken once worked out) */
        if (r->drk[k] == -1) {
            const int64_t n = (int64_t)K * ed->dr, whole = (int64_t)K * ed->step + n / ed->q;
            r->drk[k] = whole > -((int64_t)1 << 29) && whole < ((int64_t)1 << 29) ? n % ed->q : -2;
            r->stepk[k] = (int32_t)(r->drk[k] == -2 ? 0 : whole);
        }
        if (r->drk[k] == -2) return 0;
        if ((r->drk[0] | r->drk[1]) >= 0)
            r->lim = r->next && r->end[1] < r->end[0] ? r->end[1] : r->end[0];
    }
    e = ed->e - r->drk[k];
    ed->x += r->stepk[k] + (int32_t)(e < 0);
    ed->e = e + (ed->q & -(int64_t)(e < 0));
    return 1;
}

static inline void rast__ss_get(const rast__ss_tri *t, int k, rast__edge *ed)
{
    ed->e = t->e[k];
    ed->dr = t->dr[k];
    ed->q = t->q[k];
    ed->x = t->x[k];
    ed->step = t->step[k];
    ed->end = t->end[k];
}

static inline void rast__ss_set(rast__ss_tri *t, int k, const rast__edge *ed)
{
    t->e[k] = ed->e;
    t->dr[k] = ed->dr;
    t->q[k] = ed->q;
    t->x[k] = ed->x;
    t->step[k] = ed->step;
    t->end[k] = ed->end;
}

/* Triangle t (vertices turned one way, not degenerate) with its vertices
 * sorted by y into v[] and their rows, cut to [lo, hi), into row[];
 * 0 when it crosses none of those rows. */
static int rast__ss_tri_rows(const rast_point *t, const rast__grid *g, int32_t lo, int32_t hi,
                             rast_point *v, int32_t *row)
{
    rast_point x;
    int32_t k;
    v[0] = t[0];
    v[1] = t[1];
    v[2] = t[2];
    if (v[0].y > v[1].y) { x = v[0]; v[0] = v[1]; v[1] = x; }
    if (v[1].y > v[2].y) { x = v[1]; v[1] = v[2]; v[2] = x; }
    if (v[0].y > v[1].y) { x = v[0]; v[0] = v[1]; v[1] = x; }
    for (k = 0; k < 3; k++) {
        int64_t r = rast__row_at_or_after(2 * (int64_t)v[k].y, g);
        row[k] = (int32_t)(r < lo ? lo : r > hi ? hi : r);
    }
    return row[0] < row[2];
}

/* The first of the rows [lo, hi) triangle t crosses into *first (its
 * vertices' least row, as rast__ss_tri_rows' row[0], without sorting
 * them); 0 when it crosses none of them. */
static int rast__ss_tri_first(const rast_point *t, const rast__grid *g, int32_t lo, int32_t hi,
                              int32_t *first)
{
    const int32_t a = t[0].y < t[1].y ? t[0].y : t[1].y, b = t[0].y < t[1].y ? t[1].y : t[0].y;
    int64_t r0 = rast__row_at_or_after(2 * (int64_t)(a < t[2].y ? a : t[2].y), g),
            r2 = rast__row_at_or_after(2 * (int64_t)(b > t[2].y ? b : t[2].y), g);
    r0 = r0 < lo ? lo : r0 > hi ? hi : r0;
    r2 = r2 < lo ? lo : r2 > hi ? hi : r2;
    *first = (int32_t)r0;
    return r0 < r2;
}

/* Its edges into *r and *low, from rast__ss_tri_rows' v[] and row[]. */
static void rast__ss_tri_setup(rast__ss_tri *r, rast__edge *low, const rast_point *v,
                               const int32_t *row, const rast__grid *g, int32_t fx0, int32_t fx1)
{
    rast__edge ed;
#if RAST__SS_DIRECT
    /* a crossing's column lies between its edge's ends' columns (the
     * first at or right of a point, as for rows); the middle vertex right
     * of the long edge (clockwise on screen) puts that edge on the left */
    const int32_t xa = v[0].x < v[1].x ? v[0].x : v[1].x, xb = v[0].x < v[1].x ? v[1].x : v[0].x;
    const int64_t c0 = rast__row_at_or_after(2 * (int64_t)(xa < v[2].x ? xa : v[2].x), g),
                  c1 = rast__row_at_or_after(2 * (int64_t)(xb > v[2].x ? xb : v[2].x), g);
    r->clamp = c0 < fx0 || c1 > fx1;
    r->c0 = (int32_t)(c0 < fx0 ? fx0 : c0 > fx1 ? fx1 : c0);
    r->c1 = (int32_t)(c1 < fx0 ? fx0 : c1 > fx1 ? fx1 : c1);
    r->flip = rast__cross3(v[0], v[1], v[2]) < 0;
#else
    (void)fx0;
    (void)fx1;
#endif
    /* the long edge's rows are the short edges' rows, one after the other */
    rast__edge_start_tri(&ed, v[0], v[2], 1, row[0], row[2], g);
    rast__ss_set(r, 0, &ed);
    r->row = row[0];
    r->drk[0] = r->drk[1] = -1;
    r->lim = INT32_MIN;
    r->next = row[0] < row[1] && row[1] < row[2];
    if (row[0] < row[1]) {
        rast__edge_start_tri(&ed, v[0], v[1], 1, row[0], row[1], g);
        if (r->next) rast__edge_start_tri(low, v[1], v[2], 1, row[1], row[2], g);
    } else {
        rast__edge_start_tri(&ed, v[1], v[2], 1, row[1], row[2], g);
    }
    rast__ss_set(r, 1, &ed);
}

/* Set bits [a, b) (a < b) of a row of words. */
static inline void rast__ss_bits(uint64_t *bits, int32_t a, int32_t b)
{
    int32_t ka = a >> 6, kb = (b - 1) >> 6, k;
    uint64_t ma = ~(uint64_t)0 << (a & 63), mb = ~(uint64_t)0 >> (63 - ((b - 1) & 63));
    if (ka == kb) {
        bits[ka] |= ma & mb;
        return;
    }
    bits[ka] |= ma;
    for (k = ka + 1; k < kb; k++) bits[k] = ~(uint64_t)0;
    bits[kb] |= mb;
}

/* Set bits [a, b) (a < b) of a row of words as rast__ss_bits does: where
 * the words' bytes are in little-endian order (bit i of the row is bit
 * i mod 8 of its byte i / 8) a run of at most 57 bits is one OR of the 8
 * bytes from a's, when they lie within the row (a < lim, 64 wpr - 56 for
 * rows of wpr words: its bits past b are 0, so the bytes it reaches
 * past the run's keep their values). */
static inline void rast__ss_bits_run(uint64_t *bits, int32_t a, int32_t b, int32_t lim)
{
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    if ((lim == INT32_MAX || b - a <= 57) && a < lim) {
        unsigned char *p = (unsigned char *)bits + (a >> 3);
        uint64_t x;
        memcpy(&x, p, 8);
        x |= (((uint64_t)1 << (b - a)) - 1) << (a & 7);
        memcpy(p, &x, 8);
        return;
    }
#else
    (void)lim;
#endif
    rast__ss_bits(bits, a, b);
}

/* n fine rows of a triangle, its run on each [L's column, R's column)
 * (with `clamp`, between the two, clipped to [fx0, fx1]) set in its row
 * of bits (the first at `row`, wpr words apart), both edges stepped;
 * `narrow`: the runs are mostly short (rast__ss_bits_run); 2: all are,
 * at most 57 columns and starting before the row's last 56 (the
 * triangle's columns told so: rast__ss_bits_run's one OR, its tests
 * taken out). */
RAST__HOT void rast__ss_walk(rast__edge *L, rast__edge *R, int32_t n, uint64_t *row, size_t wpr,
                             int32_t fx0, int32_t fx1, int clamp, int narrow)
{
    /* (copies in locals, their columns relative to fx0) */
    rast__edge l = *L, r = *R;
    const int32_t w = fx1 - fx0, lim = (int32_t)wpr * 64 - 56;
    l.x -= fx0;
    r.x -= fx0;
    for (; n > 0; n--, row += wpr) {
        int32_t a = l.x, b = r.x;
        if (clamp) {
            const int32_t t = a < b ? a : b;
            b = a < b ? b : a;
            a = t < 0 ? 0 : t;
            b = b > w ? w : b;
        }
        if (a < b) {
            if (narrow == 2)
                rast__ss_bits_run(row, a, b, INT32_MAX);
            else if (narrow)
                rast__ss_bits_run(row, a, b, lim);
            else
                rast__ss_bits(row, a, b);
        }
        rast__edge_step(&l);
        rast__edge_step(&r);
    }
    L->e = l.e;
    R->e = r.e;
    L->x = l.x + fx0;
    R->x = r.x + fx0;
}

/* The samples of word k of the K rows of bits (wpr words apart) counted
 * a pixel at a time (64 / K pixels a word, K bits each a row), the words
 * cleared: each row's bits summed within each pixel's K bits (the SWAR
 * popcount, to K-bit lanes), then the rows' sums added in lanes twice as
 * wide, the even pixels' in *ev and the odd ones' in *od (a lane of 2K
 * bits holds K^2); *any, *all: the OR and the AND of the words. */
RAST__HOT void rast__ss_word(uint64_t *bits, size_t wpr, int32_t k, int32_t kb, uint64_t *ev,
                                 uint64_t *od, uint64_t *any, uint64_t *all)
{
    const int32_t K = (int32_t)1 << kb;
    const uint64_t me = kb == 1   ? (uint64_t)0x3333333333333333u
                        : kb == 2 ? (uint64_t)0x0F0F0F0F0F0F0F0Fu
                        : kb == 3 ? (uint64_t)0x00FF00FF00FF00FFu
                                  : (uint64_t)0x0000FFFF0000FFFFu;
    uint64_t e = 0, o = 0, a = 0, l = ~(uint64_t)0;
    int32_t t;
    for (t = 0; t < K; t++) {
        uint64_t x = bits[(size_t)t * wpr + (size_t)k];
        bits[(size_t)t * wpr + (size_t)k] = 0;
        a |= x;
        l &= x;
        x = x - ((x >> 1) & (uint64_t)0x5555555555555555u);
        if (kb >= 2) x = (x & (uint64_t)0x3333333333333333u) + ((x >> 2) & (uint64_t)0x3333333333333333u);
        if (kb >= 3) x = (x + (x >> 4)) & (uint64_t)0x0F0F0F0F0F0F0F0Fu;
        if (kb >= 4) x = (x + (x >> 8)) & (uint64_t)0x00FF00FF00FF00FFu;
        e += x & me;
        o += (x >> K) & me;
    }
    *ev = e;
    *od = o;
    *any = a;
    *all = l;
}

#if RAST__SS_DELTA
/* k = 4, uint8_t levels: the 16 pixels of word k of the 4 rows of bits
 * (wpr words apart) to their levels at p, the words cleared, in SSE2:
 * rast__ss_word's popcount to 4-bit lanes on two rows a vector (a byte
 * holds an even pixel's row count in its low 4 bits, the odd one's in
 * its high 4), the two vectors added (at most 8 a lane), the lanes
 * split into bytes, the halves' rows added (c, 0 .. 16) and the even
 * and odd pixels' bytes interleaved, then rast__ss_level16. */
static inline void rast__ss_count4(uint64_t *bits, size_t wpr, int32_t k, unsigned char *p)
{
    const __m128i m1 = _mm_set1_epi8(0x55), m2 = _mm_set1_epi8(0x33), m4 = _mm_set1_epi8(0x0F);
    uint64_t *w = bits + k;
    __m128i a = _mm_unpacklo_epi64(_mm_loadl_epi64((const __m128i *)(const void *)w),
                                   _mm_loadl_epi64((const __m128i *)(const void *)(w + wpr))),
            b = _mm_unpacklo_epi64(_mm_loadl_epi64((const __m128i *)(const void *)(w + 2 * wpr)),
                                   _mm_loadl_epi64((const __m128i *)(const void *)(w + 3 * wpr))),
            lo, hi;
    w[0] = w[wpr] = w[2 * wpr] = w[3 * wpr] = 0;
    a = _mm_sub_epi8(a, _mm_and_si128(_mm_srli_epi16(a, 1), m1));
    b = _mm_sub_epi8(b, _mm_and_si128(_mm_srli_epi16(b, 1), m1));
    a = _mm_add_epi8(_mm_and_si128(a, m2), _mm_and_si128(_mm_srli_epi16(a, 2), m2));
    b = _mm_add_epi8(_mm_and_si128(b, m2), _mm_and_si128(_mm_srli_epi16(b, 2), m2));
    a = _mm_add_epi8(a, b);
    lo = _mm_and_si128(a, m4);
    hi = _mm_and_si128(_mm_srli_epi16(a, 4), m4);
    lo = _mm_add_epi8(lo, _mm_srli_si128(lo, 8));
    hi = _mm_add_epi8(hi, _mm_srli_si128(hi, 8));
    _mm_storeu_si128((__m128i *)(void *)p, rast__ss_level16(_mm_unpacklo_epi8(lo, hi)));
}
#else
/* The 8 bytes of x's low half (32 bits) spread to every other byte. */
static inline uint64_t rast__ss_spread(uint64_t x)
{
    x &= (uint64_t)0xFFFFFFFFu;
    x = (x | (x << 16)) & (uint64_t)0x0000FFFF0000FFFFu;
    return (x | (x << 8)) & (uint64_t)0x00FF00FF00FF00FFu;
}

/* x's bytes to p[0..7], the lowest first: one store where the compiler
 * says the byte order is little-endian, else a byte at a time. */
static inline void rast__ss_put8(unsigned char *p, uint64_t x)
{
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    memcpy(p, &x, 8);
#else
    p[0] = (unsigned char)x;
    p[1] = (unsigned char)(x >> 8);
    p[2] = (unsigned char)(x >> 16);
    p[3] = (unsigned char)(x >> 24);
    p[4] = (unsigned char)(x >> 32);
    p[5] = (unsigned char)(x >> 40);
    p[6] = (unsigned char)(x >> 48);
    p[7] = (unsigned char)(x >> 56);
#endif
}

/* 16 pixels of uint8_t levels at p, k = 4, their counts c (0 .. 16) in the
 * bytes of ev (the even pixels) and od (the odd ones): each level is
 * rast__cov_level's floor((255 c + 8) / 16) = 16 c - (c > 8), in every
 * byte at once as 16 (c - g) + 15 g, g = (c > 8) (c + 0x77 reaches bit 7
 * iff c > 8; c - g >= 0 and 16 (c - g) <= 240: no lane spills), then the
 * even and odd bytes interleaved and stored a byte at a time (compilers
 * join the stores where the byte order allows). */
static inline void rast__ss_u8x16(unsigned char *p, uint64_t ev, uint64_t od)
{
    const uint64_t ones = (uint64_t)0x0101010101010101u;
    const uint64_t ge = ((ev + 0x77 * ones) >> 7) & ones, go = ((od + 0x77 * ones) >> 7) & ones;
    const uint64_t le = ((ev - ge) << 4) | (ge * 15), lo = ((od - go) << 4) | (go * 15);
    const uint64_t a = rast__ss_spread(le) | (rast__ss_spread(lo) << 8);
    const uint64_t b = rast__ss_spread(le >> 32) | (rast__ss_spread(lo >> 32) << 8);
    rast__ss_put8(p, a);
    rast__ss_put8(p + 8, b);
}
#endif

/* Output row R (clip-relative) from the K = 2^kb fine rows of bits (wpr
 * words each; only words [k0, k1] may hold set bits): each pixel's value
 * the level of its count of samples set, the words read cleared, rows
 * R's predecessors not written yet zeroed, R handed on.  Words with no
 * bit set, or all, are constant runs, written as runs. */
RAST__HOT void rast__ss_bits_row_k(rast__ss *ss, int32_t kb, int32_t R, uint64_t *bits,
                                       size_t wpr, int32_t k0, int32_t k1)
{
    const rast__cov_out *o = ss->o;
    const rast_coverage_format f = o->format;
    const uint64_t *level = ss->level;
    const int32_t K = (int32_t)1 << kb, ppw = 64 >> kb, w = o->clip.x1 - o->clip.x0,
                  y = o->clip.y0 + R;
    const uint64_t lm = kb == 4 ? (uint64_t)0xFFFFFFFFu : ((uint64_t)1 << (2 * K)) - 1;
    unsigned char *row;
    uint64_t v = level[0];
    int32_t k, j, at = 0, end;
    rast__cov_zero_rows(o, o->clip.y0 + ss->next, y);
    ss->next = R + 1;
    row = rast__cov_row(o, y);
    for (k = k0; k <= k1; k++) {
        const int32_t base = k * ppw, n = w - base < ppw ? w - base : ppw;
        uint64_t ev, od, any = 0, all = ~(uint64_t)0;
#if RAST__SS_QUICK
        /* (a word with no bit set, or all, told before any counting: most
         * of a row of a pile) */
        for (j = 0; j < K; j++) {
            const uint64_t x = bits[(size_t)j * wpr + (size_t)k];
            any |= x;
            all &= x;
        }
#else
        rast__ss_word(bits, wpr, k, kb, &ev, &od, &any, &all);
#endif
        if (!any || !~all) { /* a constant run: joins the pending one, or starts */
            const uint64_t c = any ? level[K * K] : level[0];
            if (any)
                for (j = 0; j < K; j++) bits[(size_t)j * wpr + (size_t)k] = 0;
            if (c != v) {
                rast__cov_fill(f, row, at, base, v);
                at = base;
                v = c;
            }
            continue;
        }
        rast__cov_fill(f, row, at, base, v);
        if (kb == 2 && f == RAST_COVERAGE_U8 && n == ppw) {
#if RAST__SS_DELTA
            rast__ss_count4(bits, wpr, k, row + base);
#else
#if RAST__SS_QUICK
            rast__ss_word(bits, wpr, k, kb, &ev, &od, &any, &all);
#endif
            rast__ss_u8x16(row + base, ev, od);
#endif
        } else {
#if RAST__SS_QUICK
            rast__ss_word(bits, wpr, k, kb, &ev, &od, &any, &all);
#endif
            if (f == RAST_COVERAGE_U8 && n == ppw) { /* (no test a pixel) */
                unsigned char *p = row + base;
                for (j = 0; j < ppw; j += 2) {
                    p[j] = (unsigned char)level[(ev >> (j * K)) & lm];
                    p[j + 1] = (unsigned char)level[(od >> (j * K)) & lm];
                }
            } else {
                for (j = 0; j + 1 < n; j += 2) {
                    rast__cov_store(f, row, base + j, level[(ev >> (j * K)) & lm]);
                    rast__cov_store(f, row, base + j + 1, level[(od >> (j * K)) & lm]);
                }
                if (j < n) rast__cov_store(f, row, base + j, level[(ev >> (j * K)) & lm]);
            }
        }
        at = base + n;
        v = level[0];
    }
    end = (k1 + 1) * ppw < w ? (k1 + 1) * ppw : w;
    rast__cov_fill(f, row, at, end > at ? end : at, v);
    rast__cov_fill(f, row, end > at ? end : at, w, level[0]);
    rast__cov_row_done(o, y);
}

static void rast__ss_bits_row(rast__ss *ss, int32_t R, uint64_t *bits, size_t wpr, int32_t k0,
                              int32_t k1)
{
    switch (ss->kbits) {
    case 1: rast__ss_bits_row_k(ss, 1, R, bits, wpr, k0, k1); break;
    case 2: rast__ss_bits_row_k(ss, 2, R, bits, wpr, k0, k1); break;
    case 3: rast__ss_bits_row_k(ss, 3, R, bits, wpr, k0, k1); break;
    default: rast__ss_bits_row_k(ss, 4, R, bits, wpr, k0, k1); break;
    }
}

/* The left end of a triangle's run on its current row. */
static inline int32_t rast__ss_left(const rast__ss_tri *r)
{
    return r->x[0] < r->x[1] ? r->x[0] : r->x[1];
}

/* Triangle t joins the n active ones act[] where its run's left end
 * keeps them in order (they drift out of it as edges cross: the order
 * only lets neighbours' runs join before their bits are set, it changes
 * no value); returns n + 1. */
static int32_t rast__ss_insert(const rast__ss_tri *table, int32_t *act, int32_t n, int32_t t)
{
    int32_t lo = 0, hi = n, x = rast__ss_left(&table[t]);
    while (lo < hi) {
        int32_t mid = lo + (hi - lo) / 2;
        if (rast__ss_left(&table[act[mid]]) <= x)
            lo = mid + 1;
        else
            hi = mid;
    }
    memmove(act + lo + 1, act + lo, (size_t)(n - lo) * sizeof *act);
    act[lo] = t;
    return n + 1;
}

/* Many triangles active on an output row overlap, and most of their runs
 * lie inside others': F = [fa, fb) holds columns covered on all k fine
 * rows of the output row (set on each at its end).  A triangle whose
 * edges are straight across the k rows (no vertex between) has runs whose
 * ends move one way across them (a straight edge's column is a monotone
 * function of the row), so the first and the last row bound them all: it
 * covers on every row the columns between the inner bounds of its ends,
 * and when its runs on the first and last row lie in F so do all of them,
 * and it is skipped, its edges only stepped. */

/* The run of a triangle on a fine row, [*a, *b): between the columns of
 * its edges l and e, clipped to [fx0, fx1]. */
static inline void rast__ss_run_of(const rast__edge *l, const rast__edge *e, int32_t fx0,
                                   int32_t fx1, int32_t *a, int32_t *b)
{
    int32_t x0 = l->x < e->x ? l->x : e->x, x1 = l->x < e->x ? e->x : l->x;
    *a = x0 < fx0 ? fx0 : x0;
    *b = x1 > fx1 ? fx1 : x1;
}

/* Columns [a, b) (a < b) covered on all k fine rows into F: F grows when
 * they meet it, or they take its place when more (F's columns then go
 * into the k rows of bits, of wpr words each). */
static void rast__ss_grow(uint64_t *bits, size_t wpr, int32_t K, int32_t fx0, int32_t a,
                          int32_t b, int32_t *fa, int32_t *fb)
{
    int32_t t;
    if (*fa < *fb && a <= *fb && b >= *fa) {
        *fa = a < *fa ? a : *fa;
        *fb = b > *fb ? b : *fb;
    } else if (*fa >= *fb) {
        if (*fa < *fb)
            for (t = 0; t < K; t++) rast__ss_bits(bits + (size_t)t * wpr, *fa - fx0, *fb - fx0);
        *fa = a;
        *fb = b;
    }
}

#if RAST__SS_QUICK
/* In a pile (rast__cov_ss_tris: an output row at a time, F = [fa, fb)
 * the columns covered on all k rows so far), triangles act[i], act[i + 1],
 * ... skipped while they can be on what the test needs only: straight
 * across the K rows from `top` (r->lim), their edges' growth over K rows
 * known, and their runs on the first row and the row after the last (so
 * on all, the edges being straight) inside F; their edges moved K rows,
 * each kept at act[(*m)++] unless it ends there.  Returns the index of
 * the first that cannot be (n when none): its own loop, its numbers in
 * registers, as most triangles of a pile are skipped so. */
static int32_t rast__ss_skips(rast__ss_tri *table, const rast__edge *low, int32_t *act, int32_t i,
                              int32_t n, int32_t *m, int32_t top, int32_t K, int32_t fa,
                              int32_t fb, int32_t fx0, int32_t fx1)
{
    const int32_t y = top + K;
    int32_t k = *m;
    for (; i < n; i++) {
        rast__ss_tri *r = &table[act[i]];
        int64_t e0, e1;
        int32_t x0, x1, a, b;
        if (r->row != top || y > r->lim) break;
        e0 = r->e[0] - r->drk[0];
        e1 = r->e[1] - r->drk[1];
        x0 = r->x[0] + r->stepk[0] + (int32_t)(e0 < 0);
        x1 = r->x[1] + r->stepk[1] + (int32_t)(e1 < 0);
        a = x0 < x1 ? x0 : x1;
        b = x0 < x1 ? x1 : x0;
        a = a < r->x[0] ? a : r->x[0];
        a = a < r->x[1] ? a : r->x[1];
        b = b > r->x[0] ? b : r->x[0];
        b = b > r->x[1] ? b : r->x[1];
        a = a < fx0 ? fx0 : a;
        b = b > fx1 ? fx1 : b;
        if ((((int64_t)a - fa) | ((int64_t)fb - b)) < 0) break;
        if (y == r->end[0]) continue; /* done: dropped */
        r->row = y;
        r->e[0] = e0 + (r->q[0] & -(int64_t)(e0 < 0));
        r->x[0] = x0;
        if (r->next && y == r->end[1]) { /* the lower edge takes over */
            rast__ss_set(r, 1, &low[act[i]]);
            r->drk[1] = -1;
            r->lim = INT32_MIN;
            r->next = 0;
        } else {
            r->e[1] = e1 + (r->q[1] & -(int64_t)(e1 < 0));
            r->x[1] = x1;
        }
        act[k++] = act[i];
    }
    *m = k;
    return i;
}
#endif

rast_status rast__cov_ss_tris(const rast_point *tris, uint32_t ntris, int32_t s, int32_t kbits,
                              rast_sample sample, const rast__cov_out *o, rast__arena *arena)
{
    rast__ss ss;
    rast__grid g;
    rast_rect fine;
    rast__ss_tri *table;
    rast__edge *low;
    int32_t *bucket, *act;
    uint64_t *bits;
    uint32_t k;
    int32_t j, b0, n = 0, nact = 0, first = 0, rows, pa[16], pb[16], band, nb = 1;
    const int32_t K = (int32_t)1 << kbits;
    size_t wpr;
    rast_status st = rast__grid_init(&g, s, sample, RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT);
    if (st == RAST_OK) st = rast__ss_begin(&ss, kbits, o, arena, &fine);
    if (st != RAST_OK) return st;
    if (ntris <= (uint32_t)INT32_MAX / 6 &&
        rast__ss_cancel(&ss, tris, NULL, ntris * 3, &g, &fine, arena)) {
        rast__ss_finish(&ss);
        return RAST_OK;
    }
    rows = fine.y1 - fine.y0;
    wpr = rast__ss_bitwords(o->clip.x1 - o->clip.x0, kbits);
    /* within the room of the AET's tables (two edge records per vertex):
     * a record per triangle (three edges) and an index per triangle */
    table = (rast__ss_tri *)rast__take(arena, (size_t)ntris * sizeof(rast__ss_tri));
    low = (rast__edge *)rast__take(arena, (size_t)ntris * sizeof(rast__edge));
    act = (int32_t *)rast__take(arena, (size_t)ntris * sizeof(int32_t));
    bucket = (int32_t *)rast__take(arena, ((size_t)rows + 1) * sizeof(int32_t));
    /* rows of bits for a band of up to RAST__SS_BAND output rows, as many
     * as the room left holds (the scratch holds one; the records leave
     * more when there are many triangles) */
    band = (int32_t)(arena->left / (rast__align((size_t)K * wpr * 8) + RAST_SCRATCH_ALIGN));
    band = band < 1 ? 1 : band > RAST__SS_BAND ? RAST__SS_BAND : band;
#if RAST__SS_BAND > 8
    {
        const size_t most = RAST__SS_BAND_BYTES / ((size_t)K * wpr * 8);
        band = most >= (size_t)band || band <= 8 ? band : most < 8 ? 8 : (int32_t)most;
    }
#endif
    bits = (uint64_t *)rast__take(arena, (size_t)band * K * wpr * 8);
    if ((ntris && (!table || !low || !act)) || !bucket || !bits) return RAST_E_SCRATCH;
    memset(bucket, 0, ((size_t)rows + 1) * sizeof(int32_t));
    memset(bits, 0, (size_t)band * K * wpr * 8);
    /* the triangles grouped by first row (a counting sort: counted, then
     * set up where their row's run goes) */
    for (k = 0; k < ntris; k++) {
        int32_t row0;
#if RAST__SS_PREFETCH
        act[k] = -1; /* (each one's first row, relative to the clip's, kept
                        for the prefetch below; -1: it crosses no row) */
#endif
        if (rast__ss_tri_first(&tris[3 * k], &g, fine.y0, fine.y1, &row0)) {
            bucket[row0 - fine.y0 + 1]++;
#if RAST__SS_PREFETCH
            act[k] = row0 - fine.y0;
#endif
            n++;
        }
    }
    for (j = 0; j < rows; j++) bucket[j + 1] += bucket[j];
    for (k = 0; k < ntris; k++) {
        rast_point v[3];
        int32_t row[3];
#if RAST__SS_PREFETCH
        /* the records of the triangle RAST__SS_PREFETCH on, where its
         * row's run is now (the records go by first row, all over the
         * table: each write missed the caches, a quarter of the time of
         * tri10k) */
        if (k + RAST__SS_PREFETCH < ntris && act[k + RAST__SS_PREFETCH] >= 0) {
            const int32_t at = bucket[act[k + RAST__SS_PREFETCH]];
            __builtin_prefetch(&table[at], 1);
            __builtin_prefetch((const unsigned char *)&table[at] + 64, 1);
            __builtin_prefetch(&low[at], 1);
        }
#endif
        if (rast__ss_tri_rows(&tris[3 * k], &g, fine.y0, fine.y1, v, row)) {
            int32_t at = bucket[row[0] - fine.y0]++;
            rast__ss_tri_setup(&table[at], &low[at], v, row, &g, ss.fx0, ss.fx1);
        }
    }
    /* now bucket[j] is where row j's run ends.  A band of output rows
     * (K fine rows each) at a time: each active triangle's record is read
     * once, its rows walked with its edges in registers.  Its runs go
     * straight into the bits, or (many active, or no room for more than
     * one output row) each fine row keeps a pending run that the
     * triangles' runs meeting it join. */
    for (b0 = 0; b0 < rows && (nact || first < n); b0 += nb * K) {
        int32_t b1, top = fine.y0 + b0, fx0 = ss.fx0, fx1 = ss.fx1;
        int32_t i, m, t, lo = INT32_MAX, hi = INT32_MIN, fa, fb, overlap, direct, span;
        /* few active: a band of output rows at once (a triangle's record
         * read once for them all), each run straight into its row's bits;
         * many: an output row at a time (below) */
        nb = nact < 256 ? band : 1;
        nb = nb < (rows - b0) >> kbits ? nb : (rows - b0) >> kbits;
        span = nb * K;
        b1 = b0 + span;
        /* few active an output row at a time (no room for a band): in
         * order of their left ends, so that neighbours' runs join; else
         * (runs straight into the bits, or many that overlap anyway) in
         * table order, which walks the records in memory order */
        for (; first < bucket[b1 - 1]; first++)
            if (nact < 256 && band == 1)
                nact = rast__ss_insert(table, act, nact, first);
            else
                act[nact++] = first;
        if (!nact) continue;
        overlap = nb == 1 && nact >= 256;
        direct = RAST__SS_DIRECT && !overlap;
        for (t = 0; t < K; t++) pa[t] = pb[t] = 0;
        fa = fb = 0;
        for (i = 0, m = 0; i < nact; i++) {
            rast__ss_tri *r;
            rast__edge l, e;
            int32_t y, end, sw, low_in = 0;
#if RAST__SS_QUICK
            if (overlap) { /* those that can be skipped at once, first */
                i = rast__ss_skips(table, low, act, i, nact, &m, top, K, fa, fb, fx0, fx1);
                if (i == nact) break;
            }
#endif
            r = &table[act[i]];
            y = r->row;
            rast__ss_get(r, 0, &l);
            rast__ss_get(r, 1, &e);
            end = l.end < top + span ? l.end : top + span;
            sw = r->next ? e.end : INT32_MAX; /* where the edge below the middle takes over */
            if (overlap && y == top && end == top + K && sw >= top + K) {
                /* straight across the K rows: F (see above) */
                rast__edge l2 = l, e2 = e;
                if (rast__ss_jump(r, 0, &l2, K) && rast__ss_jump(r, 1, &e2, K)) {
                    int32_t u0, v0, u1, v1;
                    rast__ss_run_of(&l, &e, fx0, fx1, &u0, &v0);
                    rast__ss_run_of(&l2, &e2, fx0, fx1, &u1, &v1);
                    /* inside F: skipped (the four tests as one sign) */
                    if ((((int64_t)(u0 < u1 ? u0 : u1) - fa) |
                         ((int64_t)fb - (v0 > v1 ? v0 : v1))) >= 0) {
                        l = l2;
                        y = top + K;
                        if (y == sw) {
                            e = low[act[i]];
                            low_in = 1;
                        } else {
                            e = e2;
                        }
                        goto walked;
                    }
                    /* covered on every row: from the rightmost place of
                     * the left edge to the leftmost of the right one */
                    if (l.x < e.x) {
                        u0 = l.x > l2.x ? l.x : l2.x;
                        v0 = e.x < e2.x ? e.x : e2.x;
                    } else {
                        u0 = e.x > e2.x ? e.x : e2.x;
                        v0 = l.x < l2.x ? l.x : l2.x;
                    }
                    u0 = u0 < fx0 ? fx0 : u0;
                    v0 = v0 > fx1 ? fx1 : v0;
                    if (u0 < v0 && l.x != e.x) rast__ss_grow(bits, wpr, K, fx0, u0, v0, &fa, &fb);
                }
            }
            /* the rows to the end of the output row or of edge 0, the
             * lower edge taking over from edge 1 on its first row */
            if (direct) {
                lo = r->c0 < lo ? r->c0 : lo;
                hi = r->c1 > hi ? r->c1 : hi;
            }
            for (;;) {
                const int32_t stop = end < sw ? end : sw;
                if (direct) { /* each run straight into its row's bits */
                    uint64_t *row = bits + (size_t)(y - top) * wpr;
                    if (r->clamp)
                        rast__ss_walk(&l, &e, stop - y, row, wpr, fx0, fx1, 1, 0);
                    else if (r->c1 - r->c0 > 256) /* wide: runs mostly long */
                        if (r->flip)
                            rast__ss_walk(&e, &l, stop - y, row, wpr, fx0, fx1, 0, 0);
                        else
                            rast__ss_walk(&l, &e, stop - y, row, wpr, fx0, fx1, 0, 0);
                    /* runs within [c0, c1]: at most 57 columns, starting
                     * before the row's last 56 (tested once) */
                    else if (r->c1 - r->c0 <= 57 && r->c1 - fx0 < (int32_t)wpr * 64 - 56)
                        if (r->flip)
                            rast__ss_walk(&e, &l, stop - y, row, wpr, fx0, fx1, 0, 2);
                        else
                            rast__ss_walk(&l, &e, stop - y, row, wpr, fx0, fx1, 0, 2);
                    else if (r->flip)
                        rast__ss_walk(&e, &l, stop - y, row, wpr, fx0, fx1, 0, 1);
                    else
                        rast__ss_walk(&l, &e, stop - y, row, wpr, fx0, fx1, 0, 1);
                    y = stop > y ? stop : y;
                } else {
                    for (; y < stop; y++) {
                        int32_t a = l.x < e.x ? l.x : e.x, b = l.x < e.x ? e.x : l.x;
                        t = y - top;
                        a = a < fx0 ? fx0 : a;
                        b = b > fx1 ? fx1 : b;
                        if (a <= pb[t] && b >= pa[t]) {
                            pa[t] = a < pa[t] ? a : pa[t];
                            pb[t] = b > pb[t] ? b : pb[t];
                        } else if (a < b) {
                            if (pa[t] < pb[t]) { /* into the bits; lo, hi: the columns they reach */
                                rast__ss_bits(bits + (size_t)t * wpr, pa[t] - fx0, pb[t] - fx0);
                                lo = pa[t] < lo ? pa[t] : lo;
                                hi = pb[t] > hi ? pb[t] : hi;
                            }
                            pa[t] = a;
                            pb[t] = b;
                        }
                        rast__edge_step(&l);
                        rast__edge_step(&e);
                    }
                }
                if (y != sw) break;
                e = low[act[i]];
                sw = INT32_MAX;
                low_in = 1;
            }
        walked:
            if (y == l.end) continue; /* done: dropped */
            /* what changed: the edges' positions (all of edge 1 once the
             * lower edge took over) and the row */
            r->row = y;
            r->e[0] = l.e;
            r->x[0] = l.x;
            if (low_in) {
                rast__ss_set(r, 1, &e);
                r->drk[1] = -1;
                r->lim = INT32_MIN;
                r->next = 0;
            } else {
                r->e[1] = e.e;
                r->x[1] = e.x;
            }
            act[m++] = act[i];
        }
        nact = m;
        for (t = 0; t < K; t++) {
            if (pa[t] < pb[t]) {
                rast__ss_bits(bits + (size_t)t * wpr, pa[t] - fx0, pb[t] - fx0);
                lo = pa[t] < lo ? pa[t] : lo;
                hi = pb[t] > hi ? pb[t] : hi;
            }
            if (fa < fb) {
                rast__ss_bits(bits + (size_t)t * wpr, fa - fx0, fb - fx0);
                lo = fa < lo ? fa : lo;
                hi = fb > hi ? fb : hi;
            }
        }
        if (lo >= hi) continue; /* no run */
        for (t = 0; t < nb; t++)
            rast__ss_bits_row(&ss, (b0 >> kbits) + t, bits + (size_t)t * K * wpr, wpr, (lo - fx0) >> 6,
                              (hi - fx0 - 1) >> 6);
    }
    rast__cov_zero_rows(o, o->clip.y0 + ss.next, o->clip.y1);
    return RAST_OK;
}
