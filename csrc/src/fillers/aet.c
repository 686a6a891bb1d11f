/*
 * aet.c - the active edge table filler (seed 001, section 3.4); the walk
 * itself is in base/aet.h.
 *
 * (How the walk works, and how a row's new edges join the AET in
 * O(k log k + n): aet.h.)
 *
 * Scratch: the edge table and the AET (an edge record each) and one bucket
 * per visible row (where its run of the table ends).
 */
#include <string.h>

#include "../base/aet.h"
#include "../base/bits.h"
#include "../painters/paint.h"
#if !defined(__OPTIMIZE_SIZE__)
#include "small.h"
#endif
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__DELTA_SSE2 1
#endif

/* The edge record's size is part of the scratch contract in rastrum.h. */
typedef char rast__aet_edge_size_check[sizeof(rast__edge) == RAST_AET_EDGE_BYTES ? 1 : -1];

size_t rast__aet_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)width;
    return rast__size_add(
        rast__size_mul(2, rast__align(rast__size_mul(npoints, sizeof(rast__edge)))),
        rast__align(rast__size_mul((size_t)height + 1, sizeof(int32_t))));
}

static inline void rast__aet_span(void *user, int32_t row, const rast__edge *l, const rast__edge *r)
{
    rast__sink_span((rast__sink *)user, row, l->x, r->x);
}

#if !defined(__OPTIMIZE_SIZE__)
/* ---- many small rings: winding deltas, summed along each row ---------------
 * The AET pays per row and per active edge for keeping its table sorted
 * (joining, stepping through the table, re-sorting, compacting); a
 * paragraph of text, a mesh or a map has thousands of short edges and a
 * hundred or more active on a row, and that upkeep was most of the fill.
 * Here instead (the edge flag method's idea, section 3.3 of seed 001, as
 * edgeflag.c does it over a whole clip): every edge walks its rows with
 * the AET's own DDA (the same crossing columns, to the bit) and adds its
 * direction (1 under even-odd) to a byte counter at its crossing's column
 * in the row; then each row is swept left to right, its running sum giving
 * the winding number of each sample: sample i is inside iff the crossings
 * with column <= i make it so, exactly the AET's runs (aet.h).  No sorting.
 *
 * The counters and the running sum are kept modulo 2^8.  Even-odd needs
 * only the parity.  Non-zero is exact when no row has 512 crossings or
 * more: a row's crossings sum to 0 (closed rings), so a sample's winding
 * number, the sum of those that count for it, is minus the sum of those
 * that do not, and at most half the row's crossings in magnitude, below
 * 2^8, so it is 0 iff it is 0 modulo 2^8.
 *
 * Columns: the polygon's box (rast__box_of) cut to the clip, bits =
 * col1 - col0; a crossing left of it is counted at its first column, one
 * right of it at column `bits`, past every sample (the row's sum still
 * returns to 0 there).  A row takes stride = bits + 1 bytes rounded up to
 * whole 8-byte words, and the sweep tests a word at a time, so an empty
 * stretch costs a word test per 8 columns.  The rows go in bands in the
 * edge table's room (npoints edge records: rast__aet_scratch is unchanged);
 * each band walks every edge that reaches it, whose DDA is carried from
 * the band before.
 *
 * When (a rule on counts known before filling, never on a scene):
 *  - many edges for the rows: at least RAST__DELTA_EDGES edges a row on
 *    average (then edges join and leave the AET on most rows, and each
 *    time the AET merges or compacts its whole row: a mesh, a map, a
 *    paragraph); one big ring (a star, a circle, a glyph) keeps the AET,
 *    whose steady rows cost less than a sweep of the row's words;
 *  - the sweep's word tests and the bands' passes over the edges are at
 *    most RAST__DELTA_WORDS per crossing: rows x words + bands x edges
 *    <= RAST__DELTA_WORDS x crossings (a wide canvas with few crossings
 *    keeps the AET);
 *  - it can: a row of counters fits the room, and, non-zero, every row has
 *    at most 510 crossings (or there are at most 511 edges), as above. */
#ifndef RAST__DELTA_EDGES
#define RAST__DELTA_EDGES 8
#endif
#ifndef RAST__DELTA_WORDS
#define RAST__DELTA_WORDS 8
#endif

/* Is this build's byte order little-endian (a constant to the compiler)?
 * It maps a set bit of a loaded word back to its byte. */
static inline int rast__little_endian(void)
{
    const uint32_t one = 1;
    unsigned char c;
    memcpy(&c, &one, 1);
    return c;
}

/* `w`'s bytes in the other order: a big-endian load made little-endian,
 * so that the lowest set bit is the first column's byte either way. */
static inline uint64_t rast__swap64(uint64_t w)
{
    w = ((w & UINT64_C(0x00FF00FF00FF00FF)) << 8) | ((w >> 8) & UINT64_C(0x00FF00FF00FF00FF));
    w = ((w & UINT64_C(0x0000FFFF0000FFFF)) << 16) | ((w >> 16) & UINT64_C(0x0000FFFF0000FFFF));
    return (w << 32) | (w >> 32);
}

/* Sweep row `y`'s counters (stride bytes, the counters past `bits`
 * included) into its runs, left to right, clearing them as it goes. */
static void rast__delta_row(unsigned char *row, int32_t stride, uint32_t mask, int32_t col0,
                            int32_t y, rast__sink *sink)
{
    const int little = rast__little_endian();
    uint32_t sum = 0;
    int32_t k, start = 0, in = 0;
    for (k = 0; k < stride; k += 8) {
        uint64_t w;
        memcpy(&w, row + k, 8);
        if (!w) continue;
        memset(row + k, 0, 8);
        if (!little) w = rast__swap64(w);  /* the columns in order of the bits */
        do {
            const int bit = rast__ctz64(w) & ~7;
            int now;
            sum += (uint32_t)(w >> bit) & 0xFF;
            w &= ~((uint64_t)0xFF << bit);
            now = (sum & mask) != 0;
            if (now != in) {
                const int32_t c = k + (bit >> 3);
                if (now) start = c;
                else rast__sink_span(sink, y, col0 + start, col0 + c);
                in = now;
            }
        } while (w);
    }
}

/* ---- the rows written a word at a time -------------------------------------
 * When the sink's painter is rows of one-byte pixels (rast__sink_byte_rows,
 * painters/paint.c: a gray8 fill, or polygon_mask's opaque one), a row's
 * counters go straight to its pixels, eight columns a word, instead of
 * runs through the sink and the painter: a paragraph of text has ~150
 * runs a row, and forming them, gathering them and writing each was a
 * third of its fill.  The same samples: a column is inside iff the
 * running sum of the counters up to it, modulo 2^8, is (masked by the
 * rule) not 0, exactly the runs rast__delta_row forms.
 *
 * A word of eight counters is summed along its lanes at once
 * (rast__delta_lanes), lane i the column k + i on every byte order (a
 * big-endian load is swapped, as rast__delta_row does); a run of words
 * with no crossing is one memset (opaque, or inside). */
#define RAST__LANES_LO UINT64_C(0x0101010101010101)
#define RAST__HALVES_FF UINT64_C(0x00FF00FF00FF00FF)
#define RAST__HALVES_LO UINT64_C(0x0001000100010001)

/* Eight counters (a word, lane i the column k + i) into masks of their
 * lanes, 0xFF where the column is inside, 0 where not, given the running
 * sum (0..255) before them, *sum, which moves on past them.  The lanes'
 * running sums are formed in 16-bit halves, where no carry reaches the
 * next: even lanes e (lanes 0, 2, 4, 6) and odd ones o, each summed
 * along by one multiplication (A = e 0x0001000100010001: half f holds
 * c0 + c2 + .. + c2f; B the same of the odd lanes, c1 + .. + c2f+1, all
 * at most 4 x 255), and then column 2f's sum is A's half f plus B's half
 * f - 1, column 2f + 1's A's and B's halves f; modulo 2^8 the low byte
 * of each half. */
static inline uint64_t rast__delta_lanes(uint64_t w, uint32_t *sum, uint32_t mask)
{
    const uint64_t s = RAST__HALVES_LO * *sum;
    const uint64_t A = (w & RAST__HALVES_FF) * RAST__HALVES_LO;
    const uint64_t B = ((w >> 8) & RAST__HALVES_FF) * RAST__HALVES_LO;
    const uint64_t pe = (A + (B << 16) + s) & RAST__HALVES_FF; /* columns 0, 2, 4, 6 */
    const uint64_t po = (A + B + s) & RAST__HALVES_FF;         /* columns 1, 3, 5, 7 */
    uint64_t ie, io;
    *sum = (uint32_t)(po >> 48);
    if (mask == 1) { /* even-odd: odd sums */
        ie = pe & RAST__HALVES_LO;
        io = po & RAST__HALVES_LO;
    } else { /* non-zero: sums not 0 (a half plus 0xFF carries into bit 8) */
        ie = ((pe + RAST__HALVES_FF) >> 8) & RAST__HALVES_LO;
        io = ((po + RAST__HALVES_FF) >> 8) & RAST__HALVES_LO;
    }
    return (ie | (io << 8)) * 0xFF;
}

#if defined(RAST__DELTA_SSE2)
/* Sixteen counters at once (SSE2, docs/c.md): the columns k .. k + 15
 * (lane i, column k + i, from c) into their pixels o (the value where
 * inside, else the background, or, not opaque, the pixel as it was),
 * given the running sum before them, *sum, which moves on past them;
 * the last column's inside-ness is returned.  The lanes' running sums by
 * four shifted adds (modulo 2^8, as rast__delta_lanes), then the rule's
 * test of each, the same as the word's: even-odd odd, non-zero not 0.
 * A paragraph's rows have a crossing in most words, and the word's
 * multiplications and masks, eight columns a time, were a fifth of its
 * fill. */
static inline int rast__delta_lanes16(unsigned char *c, unsigned char *o, uint32_t *sum,
                                      uint32_t mask, __m128i vv, __m128i bv, int opaque)
{
    const __m128i zero = _mm_setzero_si128();
    __m128i v = _mm_add_epi8(rast__delta_take16(c), _mm_set1_epi8((char)*sum)), out;
    *sum = (uint32_t)_mm_extract_epi16(v, 7) >> 8;
    /* out: 0xFF where outside */
    out = mask == 1 ? _mm_cmpeq_epi8(_mm_and_si128(v, _mm_set1_epi8(1)), zero) : _mm_cmpeq_epi8(v, zero);
    if (!opaque) bv = _mm_loadu_si128((const __m128i *)(void *)o);
    _mm_storeu_si128((__m128i *)(void *)o, _mm_or_si128(_mm_and_si128(out, bv), _mm_andnot_si128(out, vv)));
    return !(_mm_movemask_epi8(out) & 0x8000);
}
#endif

/* Row y's counters (stride = 8 (bits / 8) + 8 bytes: the columns [0, bits)
 * are pixels col0 .., the last word's other lanes past the box) into its
 * pixels, clearing the counters; opaque: the whole clip row. */
static void rast__delta_bytes(unsigned char *row, int32_t stride, int32_t bits, uint32_t mask,
                              int32_t col0, int32_t y, const rast__byte_rows *b)
{
    const int little = rast__little_endian();
    unsigned char *px = b->base + (ptrdiff_t)y * b->stride;
    const uint64_t vw = RAST__LANES_LO * b->value, bw = RAST__LANES_LO * b->background;
    const int32_t last = stride - 8; /* the last word's first column */
    uint32_t sum = 0; /* the running sum, modulo 2^8 */
    uint64_t m, w, o;
    /* words of no crossing from column `from` on: all their columns as
     * the one before (inside: in), written as one run when they end */
    int32_t k, from = 0, i;
    int in = 0;
#if defined(RAST__DELTA_SSE2)
    const __m128i vv = _mm_set1_epi8((char)b->value), bv = _mm_set1_epi8((char)b->background);
#endif
    if (b->opaque) { /* (the row claimed: rast__aet_delta) */
        if (col0 > b->x0) memset(px + b->x0, b->background, (size_t)(col0 - b->x0));
        if (col0 + bits < b->x1)
            memset(px + col0 + bits, b->background, (size_t)(b->x1 - col0 - bits));
    }
    px += col0;
    for (k = 0;; k += 8) {
        /* (two words a test over a sparse row) */
        uint64_t w2;
        for (; k + 8 < last; k += 16) {
            memcpy(&w, row + k, 8);
            memcpy(&w2, row + k + 8, 8);
            if (w | w2) break;
        }
        memcpy(&w, row + k, 8);
        if (!w && k < last) continue;
        if (from < k && (in || b->opaque))
            memset(px + from, in ? b->value : b->background, (size_t)(k - from));
        if (k == last) break;
#if defined(RAST__DELTA_SSE2)
        if (k + 16 <= last) { /* (the last word's lanes past the box: below) */
            in = rast__delta_lanes16(row + k, px + k, &sum, mask, vv, bv, b->opaque);
            from = k + 16;
            k += 8;
            continue;
        }
#endif
        from = k + 8;
        memset(row + k, 0, 8);
        if (!little) w = rast__swap64(w);
        m = rast__delta_lanes(w, &sum, mask);
        in = (int)(m >> 63);
        if (b->opaque) {
            o = bw ^ ((bw ^ vw) & m);
        } else {
            if (!m) continue;
            memcpy(&o, px + k, 8);
            if (!little) o = rast__swap64(o);
            o ^= (o ^ vw) & m;
        }
        if (!little) o = rast__swap64(o);
        memcpy(px + k, &o, 8);
    }
    /* the last word: its columns below `bits`, lane by lane (the rest are
     * past the box: their counters cleared, no pixel touched) */
    memset(row + k, 0, 8);
    if (!little) w = rast__swap64(w);
    m = rast__delta_lanes(w, &sum, mask);
    for (i = 0; k + i < bits; i++) {
        if ((m >> (8 * i)) & 1) px[k + i] = b->value;
        else if (b->opaque) px[k + i] = b->background;
    }
}

/* The counters' columns: the polygon's box within the clip's (as
 * rast__box_of: the first columns counting the least and the greatest
 * abscissa bound every crossing's), col0 and bits = col1 - col0, a row's
 * stride (bits + 1 counters rounded up to whole words), the rule's mask,
 * and whether the clip leaves the box whole.  0 when no column is
 * visible (nothing inside). */
typedef struct rast__delta_cols {
    int32_t col0, bits, stride;
    uint32_t mask;
    int whole;
} rast__delta_cols;

static int rast__delta_box(const rast__grid *g, rast_fill_rule rule, const rast_rect *clip,
                           const rast__aet_tab *t, rast__delta_cols *d)
{
    int64_t r = rast__cross_col(2 * (int64_t)t->minx, 1, g);
    int32_t col1;
    d->col0 = r > clip->x0 ? (int32_t)r : clip->x0;
    d->whole = r >= clip->x0;
    r = rast__cross_col(2 * (int64_t)t->maxx, 1, g);
    col1 = r < clip->x1 ? (int32_t)r : clip->x1;
    d->whole = d->whole && r <= clip->x1;
    if (d->col0 >= col1) return 0;
    d->bits = col1 - d->col0;
    /* (a clip 2^31 - 8 columns wide or more: a stride no room holds, the
     * caller's sweep instead) */
    d->stride = d->bits < INT32_MAX - 8 ? (d->bits + 1 + 7) & ~7 : INT32_MAX & ~7;
    d->mask = rule == RAST_RULE_EVENODD ? 1 : 0xFF;
    return 1;
}

/* Whether the rows go straight to one-byte pixels (rast__delta_bytes, the
 * rows [row0, row1) claimed when the painter is opaque), into *out. */
static int rast__delta_direct(rast__sink *sink, const rast__delta_cols *d, int32_t row0,
                              int32_t row1, rast__byte_rows *out)
{
    const int direct = rast__sink_byte_rows(sink, out) && d->col0 >= out->x0 &&
                       d->col0 + d->bits <= out->x1;
    if (direct && out->opaque) rast__byte_rows_claim(out, row0, row1);
    return direct;
}

/* Rows [j0, j1) of counters (from buf) into their runs or pixels. */
static void rast__delta_out(unsigned char *buf, int32_t j0, int32_t j1, const rast__delta_cols *d,
                            int direct, const rast__byte_rows *out, rast__sink *sink)
{
    int32_t j;
    for (j = j0; j < j1; j++) {
        unsigned char *row = buf + (size_t)(j - j0) * (size_t)d->stride;
        if (direct) rast__delta_bytes(row, d->stride, d->bits, d->mask, d->col0, j, out);
        else rast__delta_row(row, d->stride, d->mask, d->col0, j, sink);
    }
}

/* ---- the counters in the mask itself ----------------------------------------
 * polygon_mask's opaque gray8 mask is rows of the clip's width laid end to
 * end (stride == width, the clip the whole row): its memory can hold the
 * counters, swept into pixels in place, instead of a separate buffer of
 * ~266 KB at 512 x 512 cleared, added into, read and cleared again while
 * the mask is written (the fill's working set halved; the counters'
 * stores were its largest cost on a map and a paragraph, issue 33).  A
 * row's crossings right of it (column `bits`) land on the next row's
 * first column; a row's counters sum to 0 modulo 2^8 under non-zero (its
 * parity even under even-odd), so the running sum carried on from the
 * row's end into the next row, S, is minus what spilled into it (in
 * parity, for even-odd): the sum over the rows end to end is each row's
 * own, exactly.  The last row would spill past the clip: its counters go
 * to a row of their own (rast__delta_bytes). */
static void rast__delta_inplace(unsigned char *p, size_t len, uint32_t mask, const rast__byte_rows *b)
{
    const int little = rast__little_endian();
    const uint64_t vw = RAST__LANES_LO * b->value, bw = RAST__LANES_LO * b->background;
    uint32_t sum = 0;
    size_t k = 0;
#if defined(RAST__DELTA_SSE2)
    /* The running sum kept in every lane of sv (the last lane broadcast:
     * three shuffles, not rast__delta_lanes16's trip through a general
     * register, on the path from one 16 columns to the next); 16 columns
     * of no crossing are all as the column before them (fill). */
    const __m128i vv = _mm_set1_epi8((char)b->value), bv = _mm_set1_epi8((char)b->background),
                  zero = _mm_setzero_si128(), lo = _mm_set1_epi8((char)mask);
    __m128i sv = zero, fill = bv;
    for (; k + 16 <= len; k += 16) {
        __m128i v = _mm_loadu_si128((const __m128i *)(void *)(p + k)), out;
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(v, zero)) != 0xFFFF) {
            v = _mm_add_epi8(rast__delta_sum16(v), sv);
            sv = _mm_unpackhi_epi8(v, v);
            sv = _mm_shufflehi_epi16(sv, 0xFF);
            sv = _mm_unpackhi_epi64(sv, sv);
            out = _mm_cmpeq_epi8(_mm_and_si128(v, lo), zero); /* 0xFF where outside */
            fill = _mm_cmpeq_epi8(_mm_and_si128(sv, lo), zero);
            fill = _mm_or_si128(_mm_and_si128(fill, bv), _mm_andnot_si128(fill, vv));
            _mm_storeu_si128((__m128i *)(void *)(p + k),
                             _mm_or_si128(_mm_and_si128(out, bv), _mm_andnot_si128(out, vv)));
        } else {
            _mm_storeu_si128((__m128i *)(void *)(p + k), fill);
        }
    }
    sum = (uint32_t)_mm_cvtsi128_si32(sv) & 0xFF;
#endif
    for (; k + 8 <= len; k += 8) {
        uint64_t w, o;
        memcpy(&w, p + k, 8);
        if (!little) w = rast__swap64(w);
        o = bw ^ ((bw ^ vw) & rast__delta_lanes(w, &sum, mask));
        if (!little) o = rast__swap64(o);
        memcpy(p + k, &o, 8);
    }
    for (; k < len; k++) {
        sum += p[k];
        p[k] = (sum & mask & 0xFF) ? b->value : b->background;
    }
}

/* The last row's crossing of an edge that reaches it, into its own row of
 * counters buf (the mask's rows take the others: rast__delta_inplace).
 * (Apart from rast__aet_delta_now: a second walk inlined there cost the
 * other one registers, on every edge.) */
RAST__APART void rast__delta_walk_last(rast__edge *ed, unsigned char *buf, const rast__delta_cols *d)
{
    rast__delta_walk(ed, buf, ed->end - 1, ed->end, d->stride, d->col0, d->bits,
                     (unsigned char)(d->mask == 1 ? 1 : ed->dir), 1, 1);
}

/* The fill by winding deltas, when the rule above takes it (or, `force`,
 * whenever it can), in the `room` bytes of the edge table t->edges:
 * returns 1, the runs handed to `sink`; 0, having done nothing, when not. */
static int rast__aet_delta(size_t room, const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, const rast__aet_tab *t, rast__sink *sink,
                           int force)
{
    const int32_t rows = t->row1 - t->row0;
    rast__edge *const ed = t->aet;
    rast__delta_cols d;
    int32_t hb, nb, e, j0;
    int64_t crossings = 0, cost;
    unsigned char *buf;
    rast__byte_rows out;
    int direct, whole;

    if (t->nedges == 0) return 1;
    if (!force && t->nedges < RAST__DELTA_EDGES * (int64_t)rows) return 0;
    if (!rast__delta_box(g, rule, clip, t, &d)) return 1; /* no visible column: nothing inside */
    if ((size_t)d.stride > room || d.bits >= INT32_MAX - 8) return 0;
    hb = (int32_t)(room / (size_t)d.stride < (size_t)rows ? room / (size_t)d.stride : (size_t)rows);
    nb = (rows + hb - 1) / hb;
    whole = d.whole && nb == 1; /* (the edges' rows are [row0, row1)'s: aet.h) */
    /* The crossings, and (non-zero, more than 511 edges) the most on a
     * row: the running count of edges started less edges ended, the
     * starts from the buckets (bucket[r - row0 + 1]: row r's), the ends
     * counted in the same pass over the edges, into the edge table's room
     * (free until the counters: rows + 1 counts fit it whenever the rule
     * can take the deltas, 8 edges a row; else the sweep fills). */
    if (d.mask != 1 && t->nedges > 511) {
        int32_t *b = t->bucket, *ends = (int32_t *)(void *)t->edges, run = 0, most = 0, y;
        if (((size_t)rows + 1) * sizeof(int32_t) > room) return 0;
        memset(ends, 0, ((size_t)rows + 1) * sizeof(int32_t));
        for (e = 0; e < t->nedges; e++) {
            crossings += ed[e].end - ed[e].row;
            ends[ed[e].end - t->row0]++; /* (an edge ending at row1: ends[rows]) */
        }
        for (y = 1; y <= rows; y++) {
            run += b[y] - ends[y - 1];
            if (run > most) most = run;
        }
        if (most > 510) return 0;
    } else {
        for (e = 0; e < t->nedges; e++) crossings += ed[e].end - ed[e].row;
    }
    cost = (int64_t)rows * (d.stride / 8) + (int64_t)nb * t->nedges;
    if (!force && cost > RAST__DELTA_WORDS * crossings) return 0;

    direct = rast__delta_direct(sink, &d, t->row0, t->row1, &out);
    buf = (unsigned char *)(void *)t->edges;
    memset(buf, 0, (size_t)hb * (size_t)d.stride);
    for (j0 = t->row0; j0 < t->row1; j0 += hb) {
        const int32_t j1 = t->row1 - j0 > hb ? j0 + hb : t->row1;
        /* Edge by edge: its direction at each of its crossings (in one
         * band of a box the clip does not cut, every edge's rows are the
         * band's and its crossings the box's: nothing to cut). */
        if (whole) {
            for (e = 0; e < t->nedges; e++)
                rast__delta_walk(&ed[e], buf, j0, j1, d.stride, d.col0, d.bits,
                                 (unsigned char)(d.mask == 1 ? 1 : ed[e].dir), 0, 0);
        } else {
            for (e = 0; e < t->nedges; e++)
                rast__delta_walk(&ed[e], buf, j0, j1, d.stride, d.col0, d.bits,
                                 (unsigned char)(d.mask == 1 ? 1 : ed[e].dir), 1, 1);
        }
        /* Row by row: the runs. */
        rast__delta_out(buf, j0, j1, &d, direct, &out, sink);
    }
    return 1;
}

/* A vertex's row (rast__row_at_or_after of its doubled y) and the column
 * that counts a crossing at its abscissa (rast__cross_col(2x, 1, g)),
 * each as one shift of a biased 32-bit value, both plus kb = 2^30 >>
 * shift (the bias's part, taken off only where a row or column is used:
 * the walk compares them as they are).  Exact: |2v| < 2^28 and the unit
 * at most 2^17 (S <= 16), so the biased value lies in (0, 2^31) and the
 * shift floors it; rows: ceil((2y - off) / unit); columns: the same
 * (exact rounding), or floor((2x - off + unit / 2) / unit) (textbook,
 * RAST_ROUND_TEXTBOOK). */
typedef struct rast__vshift {
    uint32_t ky, kx; /* 2^30 - off + unit - 1; kx: ky, or textbook 2^30 - off + unit / 2 */
    uint32_t shift;
    int32_t kb; /* 2^30 >> shift */
} rast__vshift;

static inline rast__vshift rast__vshift_of(const rast__grid *g)
{
    rast__vshift v;
    v.ky = ((uint32_t)1 << 30) - (uint32_t)g->off + (uint32_t)g->unit - 1;
    v.kx = g->textbook ? ((uint32_t)1 << 30) - (uint32_t)g->off + (uint32_t)g->unit / 2 : v.ky;
    v.shift = (uint32_t)g->shift;
    v.kb = (int32_t)(((uint32_t)1 << 30) >> v.shift);
    return v;
}

static inline int32_t rast__vshift_row(int32_t y, uint32_t ky, uint32_t shift)
{
    return (int32_t)(((uint32_t)y * 2u + ky) >> shift);
}

/* An edge's crossings of rows [a, b), all at counter column c (cut to
 * [0, bits]), added in: rows below mid in the mask (in, rows of bits),
 * the rest in buf (rows of stride from mid); `inplace` as
 * rast__delta_now_walk's. */
static inline void rast__delta_col(unsigned char *in, unsigned char *buf, int32_t row0, int32_t mid,
                                   int32_t a, int32_t b, int32_t bits, int32_t stride, int32_t c,
                                   unsigned char dir, const int inplace)
{
    unsigned char *p;
    c = c < 0 ? 0 : c;
    c = c > bits ? bits : c;
    if (inplace) {
        const int32_t m = b < mid ? b : mid;
        for (p = in + (ptrdiff_t)(a - row0) * bits + c; a < m; a++, p += bits) *p = (unsigned char)(*p + dir);
        if (a == b) return;
    }
    for (p = buf + (ptrdiff_t)(a - mid) * stride + c; a < b; a++, p += stride) *p = (unsigned char)(*p + dir);
}

/* rast__aet_delta_now's walk of every edge as it is set up, into the
 * counters: rows [row0, mid) in the mask itself (in, rows of d->bits),
 * [mid, row1) in buf (rows of d->stride); `inplace` a constant (0: in
 * NULL, mid = row0), so that each caller gets its own loop (one with both
 * cost the other ~8% more instructions on a paragraph of text).
 * An edge whose two ends count at one column crosses every row there
 * (the column is monotone in the abscissa, and every crossing lies
 * between the ends'): no DDA and no division (10,166 of a paragraph's
 * 18,060 edges that cross a row, 2,332 of a map's 8,343); one that
 * crosses a single row needs only its first column (one division, not
 * the DDA's two: 6,636 more of the paragraph's). */
RAST__HOT void rast__delta_now_walk(const rast_polygon *poly, const rast__grid *g, const rast__delta_cols *dc,
                                    int32_t row0, int32_t row1, int32_t mid, unsigned char *buf,
                                    unsigned char *in, int32_t *starts, const int inplace)
{
    const rast_point *pts = poly->points;
    const rast__grid gl = *g; /* (not reloaded every edge: aet.h) */
    const rast__delta_cols d = *dc;
    const rast__vshift v = rast__vshift_of(&gl);
    /* the clip's rows, biased as the vertices' rows are (rast__vshift) */
    const int32_t brow0 = row0 + v.kb, brow1 = row1 + v.kb;
    uint32_t k, base;
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        /* edge ib - 1 -> ib (as rast__aet_prepare_edges walks them; the
         * ring's last edge to its first vertex), each vertex's row found
         * once: the vertices of the row of the one before are passed by a
         * loop of their own (an edge between two vertices of one row
         * crosses none: most of a paragraph's) */
        const uint32_t stop = base + poly->ring_sizes[k];
        uint32_t ib;
        int32_t ra, rb = 0, r0;
        /* the rows of the crossing edges of one direction that follow each
         * other (from row cs, going down when cdown): each row between
         * their ends is crossed by one of them, exactly once, so the
         * crossings a row are counted a piece at a time, not an edge at a
         * time (starts: rast__aet_delta_now) */
        int32_t cs, cdown = -1;
        if (stop == base) continue;
        ra = r0 = cs = rast__vshift_row(pts[base].y, v.ky, v.shift);
        for (ib = base + 1;; ib++) {
            const rast_point *pa, *pb;
            int32_t first, end, c;
            unsigned char dir;
            while (ib < stop && (rb = rast__vshift_row(pts[ib].y, v.ky, v.shift)) == ra) ib++;
            if (ib == stop) {
                if (ra == r0) break;
                rb = r0;
                pb = &pts[base];
            } else {
                pb = &pts[ib];
            }
            pa = &pts[ib - 1];
            if (starts && (ra < rb) != cdown) {
                first = (cs < ra ? cs : ra);
                end = cs ^ ra ^ first;
                first = first < brow0 ? brow0 : first;
                end = end > brow1 ? brow1 : end;
                if (first < end) {
                    starts[first - brow0]++;
                    starts[end - brow0]--;
                }
                cs = ra;
                cdown = ra < rb;
            }
            first = ra < rb ? ra : rb;
            end = ra ^ rb ^ first;
            first = (first < brow0 ? brow0 : first) - v.kb;
            end = (end > brow1 ? brow1 : end) - v.kb;
            if (first < end) {
                dir = (unsigned char)(d.mask == 1 || ra < rb ? 1 : 0xFF);
                c = rast__vshift_row(pa->x, v.kx, v.shift);
                if (c != rast__vshift_row(pb->x, v.kx, v.shift)) {
                    /* (the ends ordered as rast__aet_edge_rows orders them) */
                    const ptrdiff_t swap = (pb - pa) & -(ptrdiff_t)(ra > rb);
                    const rast_point *top = pa + swap, *bottom = pb - swap;
                    if (end - first == 1) {
                        int64_t e;
                        c = rast__edge_first_col(*top, *bottom, first, &gl, &e) + v.kb;
                    } else {
                        rast__edge ed;
                        rast__edge_start_inline(&ed, *top, *bottom, ra < rb ? 1 : -1, first, end, &gl);
                        if (!inplace) {
                            rast__delta_walk(&ed, buf, row0, row1, d.stride, d.col0, d.bits, dir, 1, 1);
                        } else {
                            rast__delta_walk(&ed, in, row0, mid, d.bits, d.col0, d.bits, dir, 1, 1);
                            if (ed.end > mid) rast__delta_walk_last(&ed, buf, &d);
                        }
                        goto next;
                    }
                }
                rast__delta_col(in, buf, row0, mid, first, end, d.bits, d.stride, c - v.kb - d.col0, dir,
                                inplace);
            }
        next:
            if (ib == stop) break;
            ra = rb;
        }
        if (starts) { /* the ring's last piece, to its first vertex's row */
            int32_t first = cs < r0 ? cs : r0, end = cs ^ r0 ^ first;
            first = first < brow0 ? brow0 : first;
            end = end > brow1 ? brow1 : end;
            if (first < end) {
                starts[first - brow0]++;
                starts[end - brow0]--;
            }
        }
    }
}

/* ---- the vertices' rows and columns found first ----------------------------
 * rast__delta_now_walk finds a vertex's row (and, for an edge that crosses
 * one, both ends' columns) in its loop, and cuts each edge's rows and
 * column to the clip there: with the counters, the rings and the pieces,
 * more values than the registers hold, and the loop spilled and reloaded
 * them every edge (~145 instructions an edge that crosses a row on a
 * paragraph of text).  Here a pass of its own finds every vertex's row
 * and column (rast__vshift_row, the same values), relative to the clip's
 * first and cut to [0, rows] and [0, bits], as two 16-bit numbers; the
 * walk then reads them.  Cutting the vertices' rows and columns is
 * cutting the edges': min, max and the cut to an interval are monotone
 * and commute, so an edge's rows [min(ra, rb), max(ra, rb)) cut are the
 * cut ends' min and max, and its crossings' columns, which lie between
 * its ends' (rast__delta_now_walk), cut, lie between the cut ends': one
 * column when those are equal (an edge wholly left of the clip counts at
 * its first column on every row).  An edge of rows all outside the clip
 * has its two ends cut to the same row: no crossing, as before.  The
 * pieces' count (starts) is over the cut rows: a piece's cut rows are
 * monotone still, each crossed once.  When: rows and bits below 2^15
 * (the pair's halves), and room for 4 bytes a vertex and one more. */
#define RAST__RC_MAX 32767

/* rc[2 i], rc[2 i + 1]: vertex i's column and row, relative to col0 and
 * row0, cut to [0, bits] and [0, rows]; rc[2 n], rc[2 n + 1] set to 0 (the
 * walk's mark past the last ring). */
static void rast__delta_rc(const rast_point *pts, uint32_t n, const rast__vshift *v, int32_t col0,
                           int32_t row0, int32_t bits, int32_t rows, uint16_t *rc)
{
    const int32_t bc = v->kb + col0, br = v->kb + row0;
    uint32_t i = 0;
#if defined(RAST__DELTA_SSE2)
    {
        /* four vertices a step: doubled, biased, shifted (as
         * rast__vshift_row), the bias and the clip's first taken off, cut
         * to int16 (saturating) and then to [0, bits] x [0, rows] */
        const __m128i k = _mm_set_epi32((int)v->ky, (int)v->kx, (int)v->ky, (int)v->kx);
        const __m128i b = _mm_set_epi32(br, bc, br, bc);
        const __m128i hi = _mm_set_epi16((short)rows, (short)bits, (short)rows, (short)bits,
                                         (short)rows, (short)bits, (short)rows, (short)bits);
        const __m128i sh = _mm_cvtsi32_si128((int)v->shift), zero = _mm_setzero_si128();
        for (; i + 4 <= n; i += 4) {
            __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(pts + i));
            __m128i c = _mm_loadu_si128((const __m128i *)(const void *)(pts + i + 2));
            a = _mm_sub_epi32(_mm_srl_epi32(_mm_add_epi32(_mm_add_epi32(a, a), k), sh), b);
            c = _mm_sub_epi32(_mm_srl_epi32(_mm_add_epi32(_mm_add_epi32(c, c), k), sh), b);
            a = _mm_min_epi16(_mm_max_epi16(_mm_packs_epi32(a, c), zero), hi);
            _mm_storeu_si128((__m128i *)(void *)(rc + 2 * i), a);
        }
    }
#endif
    for (; i < n; i++) {
        int32_t c = rast__vshift_row(pts[i].x, v->kx, v->shift) - bc;
        int32_t r = rast__vshift_row(pts[i].y, v->ky, v->shift) - br;
        c = c < 0 ? 0 : c > bits ? bits : c;
        r = r < 0 ? 0 : r > rows ? rows : r;
        rc[2 * i] = (uint16_t)c;
        rc[2 * i + 1] = (uint16_t)r;
    }
    rc[2 * n] = rc[2 * n + 1] = 0;
}

/* The column of edge top -> bottom (top.y < bottom.y) at row `first`, as
 * rast__edge_first_col finds it, for an edge walked on that row alone:
 * base + ceil(n / q) (internal.h), by one 32-bit division with C's
 * truncation (the ceiling of n / q is the quotient, plus one when the
 * remainder is positive) when q and n fit 32 bits, and no remainder e for
 * a DDA.  (An edge of one row at S = 8: q < 2^20, |n| < 2^19 + 2^9 |dx|.)
 * Else rast__edge_first_col. */
static inline int32_t rast__one_row_col(rast_point top, rast_point bottom, int32_t first, const rast__grid *g)
{
    const rast__dpos xa = 2 * top.x, ya = 2 * top.y, dx = 2 * bottom.x - xa, dy = 2 * bottom.y - ya;
    const int32_t xo = xa - g->off;
    const int64_t q = (int64_t)dy * g->unit;
    int64_t n = (int64_t)(xo & (g->unit - 1)) * dy + ((int64_t)first * g->unit + g->off - ya) * dx, e;
    if (g->textbook) n += (int64_t)(g->unit / 2) * dy - q + 1;
    if (q <= INT32_MAX && (uint64_t)(n + INT32_MAX) <= (uint64_t)2 * INT32_MAX) {
        const int32_t t = (int32_t)n / (int32_t)q, r = (int32_t)n % (int32_t)q;
        return rast__floorshift32(xo, g->shift) + t + (r > 0);
    }
    return rast__edge_first_col(top, bottom, first, g, &e);
}

/* Whether the sample of column `col` on row `first` is not left of edge
 * top -> bottom's crossing there (top.y < bottom.y, exact rounding):
 * col unit + off >= the crossing's x, i.e. rast__one_row_col's ceiling is
 * col or less.  Both sides times dy > 0.  The products stay under 2^60:
 * |dx|, dy <= 2^29 (|x|, |y| <= 2^28 internal units; dy is that large
 * where the clip cut the edge's other rows); the sample tested lies
 * within a pixel of the ends' span (its column is one of the ends'
 * columns or the clip's side between them), so |col unit + off - xa| <=
 * |dx| + 2 unit; ys - ya is in [0, dy].  Where both ends' columns
 * (rast__delta_rc's) are col and col + 1, the crossing's column is one of
 * them (it moves monotonically along the edge, and the columns round it as
 * the ends' do): col when this holds, else col + 1. */
static inline int rast__one_row_side(rast_point top, rast_point bottom, int32_t first, int32_t col,
                                     const rast__grid *g)
{
    const int64_t xa = 2 * (int64_t)top.x, ya = 2 * (int64_t)top.y;
    const int64_t dx = 2 * (int64_t)bottom.x - xa, dy = 2 * (int64_t)bottom.y - ya;
    return ((int64_t)col * g->unit + g->off - xa) * dy >= ((int64_t)first * g->unit + g->off - ya) * dx;
}

/* An edge of rast__delta_rc_walk that crosses rows [first, end) (relative
 * to row0) with ends in different columns and more than one row: its DDA,
 * as rast__delta_now_walk walks it.  (Apart: it is rare, and inlined it
 * cost the walk's loop registers.) */
RAST__APART void rast__delta_rc_dda(rast_point top, rast_point bottom, int down, int32_t first,
                                    int32_t end, const rast__grid *g, const rast__delta_cols *d,
                                    int32_t row0, int32_t mid, unsigned char *buf, unsigned char *in,
                                    unsigned char dir, const int inplace)
{
    rast__edge ed;
    rast__edge_start_inline(&ed, top, bottom, down ? 1 : -1, first + row0, end + row0, g);
    if (!inplace) {
        rast__delta_walk(&ed, buf, row0, end + row0, d->stride, d->col0, d->bits, dir, 1, 1);
    } else {
        rast__delta_walk(&ed, in, row0, mid + row0, d->bits, d->col0, d->bits, dir, 1, 1);
        if (ed.end > mid + row0) rast__delta_walk_last(&ed, buf, d);
    }
}

/* How many columns more than two a row an edge of rast__delta_rc_walk
 * may cross and still be walked column by column (rast__rc_edge): each
 * column is an add and a test, where the DDA's set-up is two divisions
 * and ~130 instructions. */
#ifndef RAST__RC_COLS
#define RAST__RC_COLS 16
#endif

/* An edge of rast__delta_rc_walk that rast__rc_edge does not walk (a
 * column cut to the clip, or many columns a row): as before, one row by
 * rast__one_row_side or rast__one_row_col, more by the DDA
 * (rast__delta_rc_dda).  top -> bottom, rows [first, end) relative to
 * row0, ct and cb the ends' columns (rc's). */
RAST__APART void rast__delta_rc_other(rast_point top, rast_point bottom, int32_t ct, int32_t cb, int32_t first,
                                      int32_t end, const rast__grid *g, const rast__delta_cols *d,
                                      int32_t row0, int32_t mid, unsigned char *buf, unsigned char *in,
                                      unsigned char dir, const int inplace)
{
    int32_t c;
    if (end - first == 1) {
        const int32_t lo = ct < cb ? ct : cb;
        if ((ct ^ cb ^ lo) - lo == 1 && !g->textbook) {
            /* Two columns apart (rc's, cut to [0, bits]): the crossing's
             * is the first of them whose sample is not left of it
             * (rast__one_row_col's ceiling), or the second: one
             * comparison of products, no division (rast__one_row_side). */
            c = lo + !rast__one_row_side(top, bottom, first + row0, lo + d->col0, g);
        } else {
            c = rast__one_row_col(top, bottom, first + row0, g) - d->col0;
            c = c < 0 ? 0 : c;
            c = c > d->bits ? d->bits : c;
        }
        if (!inplace) buf[(ptrdiff_t)first * d->stride + c] = (unsigned char)(buf[(ptrdiff_t)first * d->stride + c] + dir);
        else if (first < mid) in[(ptrdiff_t)first * d->bits + c] = (unsigned char)(in[(ptrdiff_t)first * d->bits + c] + dir);
        else buf[c] = (unsigned char)(buf[c] + dir); /* (row mid, the last) */
    } else {
        /* (its down: the direction the last row's walk takes, rast__delta_walk_last) */
        rast__delta_rc_dda(top, bottom, dir == 1, first, end, g, d, row0, mid, buf, in, dir, inplace);
    }
}

/* What rast__delta_rc_walk's edges read, in locals (the counters are
 * bytes: through them the compiler would reload anything it reads
 * through a pointer after every add). */
typedef struct rast__rc_k {
    const rast_point *pts;
    const rast__grid *g;
    const rast__delta_cols *d;
    unsigned char *p0;   /* row 0's counters: the mask's (inplace) or buf's */
    unsigned char *buf;  /* the rows from mid (inplace: row mid alone) */
    unsigned char *in;
    int64_t cx0, ry0;    /* column 0's and row 0's sample, internal units */
    int64_t unit;
    int32_t pitch;       /* bits (inplace) or stride */
    int32_t mid, row0;
    int32_t bits;        /* bits, or 0 under textbook rounding (no edge walked) */
} rast__rc_k;

/* One edge of rast__delta_rc_walk, top -> bottom (it and ibm: their
 * indices), crossing rows [first, end) (relative to row0, first < end),
 * ct and cb the columns rc gives its ends: its direction dir added at its
 * crossing on each of those rows.  Ends in one column: every crossing is
 * there (rast__delta_now_walk).  Ends in different columns, neither cut to
 * the clip, exact rounding: the crossing's column on a row is the least c
 * whose sample is not left of the crossing, F(c) >= 0 with
 *     F(c) = (c unit + off - xa) dy - (y unit + off - ya) dx = c q - n
 * (q = dy unit, n as rast__edge_first_col's: F(x) = e, the DDA's
 * remainder, so F(c) >= 0 iff c >= n / q, and the least such c is the
 * DDA's x = ceil(n / q)).  F grows by q = U a column and falls by
 * dx unit = V a row, so the walk keeps F at its column and moves the
 * column while F says so: right (cb > ct, dx > 0) while F < 0, left while
 * F(c - 1) = F - U >= 0.  It starts from the top's column ct on row
 * first: the crossings' columns lie between the ends' (monotone along the
 * edge; the rows cut to the clip do not change that), so going right
 * F(ct - 1) < 0 there, going left F(ct) >= 0, and it never passes cb: no
 * test of the clip's columns (neither end is cut: 0 < the columns <
 * bits).  The same columns as the DDA's, with no division: two products
 * an edge and an add a column.  The rest (a cut column, textbook
 * rounding, or more than RAST__RC_COLS + 2 columns a row on average):
 * rast__delta_rc_other, as before.  `inplace` as rast__delta_rc_walk's
 * (the last row, mid, in buf). */
RAST__HOT void rast__rc_edge(const rast__rc_k *k, ptrdiff_t it, ptrdiff_t ibm, int32_t ct, int32_t cb,
                             int32_t first, int32_t end, unsigned char dir, const int inplace)
{
    unsigned char *p = k->p0 + (ptrdiff_t)first * k->pitch;
    const int32_t m = inplace && end > k->mid ? k->mid : end;
    int32_t c = ct;
    if (ct != cb) {
        const int32_t lo = ct < cb ? ct : cb, hi = ct ^ cb ^ lo;
        if (lo > 0 && hi < k->bits && hi - lo <= RAST__RC_COLS + 2 * (end - first)) {
            const rast_point a = k->pts[it], b = k->pts[ibm];
            const int64_t xa = 2 * (int64_t)a.x, ya = 2 * (int64_t)a.y;
            const int64_t dx = 2 * (int64_t)b.x - xa, dy = 2 * (int64_t)b.y - ya;
            const int64_t U = dy * k->unit, V = dx * k->unit;
            int64_t F = (ct * k->unit + k->cx0 - xa) * dy - (first * k->unit + k->ry0 - ya) * dx;
            if (cb > ct) {
                for (; first < m; first++, p += k->pitch, F -= V) {
                    while (F < 0) {
                        c++;
                        F += U;
                    }
                    p[c] = (unsigned char)(p[c] + dir);
                }
                if (inplace && end > m) { /* (row mid, the last) */
                    while (F < 0) {
                        c++;
                        F += U;
                    }
                    k->buf[c] = (unsigned char)(k->buf[c] + dir);
                }
            } else {
                for (; first < m; first++, p += k->pitch, F -= V) {
                    while (F >= U) {
                        c--;
                        F -= U;
                    }
                    p[c] = (unsigned char)(p[c] + dir);
                }
                if (inplace && end > m) {
                    while (F >= U) {
                        c--;
                        F -= U;
                    }
                    k->buf[c] = (unsigned char)(k->buf[c] + dir);
                }
            }
            return;
        }
        rast__delta_rc_other(k->pts[it], k->pts[ibm], ct, cb, first, end, k->g, k->d, k->row0, k->mid,
                             k->buf, k->in, dir, inplace);
        return;
    }
    for (p += c; first < m; first++, p += k->pitch) *p = (unsigned char)(*p + dir);
    if (inplace && end > m) k->buf[c] = (unsigned char)(k->buf[c] + dir); /* (row mid, the last) */
}

/* rast__delta_now_walk's work from rc (rast__delta_rc): rows relative to
 * the clip's first, [0, mid) in the mask itself (in, rows of bits), the
 * rest in buf (rows of stride from mid); `inplace` a constant (0: in
 * NULL, mid = 0).  The same edges, directions, columns and pieces.
 * A ring is walked a monotone chain at a time: a loop for the edges going
 * down and one for those going up, each with its direction and its ends'
 * order fixed, and the pieces' count (starts) paid once a chain, not once
 * an edge.  The vertices of one row are passed by a loop of their own
 * that stops at the next row's; past the ring's last vertex stands a row
 * that ends either chain's loop (0 going down: below every row an edge
 * going down reaches; 0xFFFF going up: above any row), set as each chain
 * starts, and the ring's last edge, to its first vertex, comes after. */
RAST__HOT void rast__delta_rc_walk(const rast_polygon *poly, uint16_t *rc, const rast__grid *g,
                                   const rast__delta_cols *d, int32_t row0, int32_t mid,
                                   unsigned char *buf, unsigned char *in, int32_t *starts,
                                   const int inplace)
{
    const unsigned char up = d->mask == 1 ? 1 : 0xFF;
    const uint32_t *const sizes = poly->ring_sizes;
    const uint32_t nrings = poly->nrings;
    rast__rc_k k;
    uint32_t r, base;
    k.pts = poly->points;
    k.g = g;
    k.d = d;
    k.p0 = inplace ? in : buf;
    k.buf = buf;
    k.in = in;
    k.unit = g->unit;
    k.cx0 = (int64_t)d->col0 * g->unit + g->off;
    k.ry0 = (int64_t)row0 * g->unit + g->off;
    k.pitch = inplace ? d->bits : d->stride;
    k.mid = mid;
    k.row0 = row0;
    k.bits = g->textbook ? 0 : d->bits;
    for (r = 0, base = 0; r < nrings; base += sizes[r], r++) {
        const uint32_t stop = base + sizes[r];
        uint16_t *const first = rc + 2 * base, *const mark = rc + 2 * stop;
        const uint16_t after = mark[1];
        const uint16_t *v = first; /* the vertex reached: column v[0], row v[1] */
        int32_t ra, rb, r0, cs;
        if (stop == base) continue;
        ra = r0 = cs = first[1];
        mark[1] = 0xFFFF;
        while ((rb = (v += 2)[1]) == ra) {}
        if (v == mark) goto close;
        if (rb < ra) goto up_chain;
    down_chain:
        mark[1] = 0;
        do {
            rast__rc_edge(&k, (ptrdiff_t)((size_t)(v - rc) >> 1) - 1, (ptrdiff_t)((size_t)(v - rc) >> 1), v[-2], v[0], ra, rb, 1, inplace);
            ra = rb;
            while ((rb = (v += 2)[1]) == ra) {}
        } while (rb > ra);
        if (starts) {
            starts[cs]++;
            starts[ra]--;
        }
        cs = ra;
        if (v == mark) goto close;
    up_chain:
        mark[1] = 0xFFFF;
        do {
            rast__rc_edge(&k, (ptrdiff_t)((size_t)(v - rc) >> 1), (ptrdiff_t)((size_t)(v - rc) >> 1) - 1, v[0], v[-2], rb, ra, up, inplace);
            ra = rb;
            while ((rb = (v += 2)[1]) == ra) {}
        } while (rb < ra);
        if (starts) {
            starts[ra]++;
            starts[cs]--;
        }
        cs = ra;
        if (v != mark) goto down_chain;
    close:
        mark[1] = after;
        if (ra != r0) { /* the ring's last edge, to its first vertex */
            const int down = ra < r0;
            const ptrdiff_t it = down ? (ptrdiff_t)stop - 1 : (ptrdiff_t)base;
            const ptrdiff_t ibm = down ? (ptrdiff_t)base : (ptrdiff_t)stop - 1;
            const int32_t top = down ? ra : r0, end = ra ^ r0 ^ top;
            rast__rc_edge(&k, it, ibm, rc[2 * it], rc[2 * ibm], top, end, down ? 1 : up, inplace);
            if (starts) {
                starts[top]++;
                starts[end]--;
            }
        }
    }
}

/* ---- the deltas added as the edges are set up ------------------------------
 * Finding each vertex's row in a pass of its own, setting every edge up
 * as a record of the edge table and walking the records afterwards was
 * half of a paragraph's fill (the rows stored and loaded again, stores
 * and loads of 48-byte records, the buckets, a pass to count the
 * crossings).  When the counters of all the clip's rows fit the AET's
 * room at once (one band), an edge can instead be walked into them as
 * soon as it is set up, ring by ring, each vertex's row found once, no
 * record kept: the same DDA, the same crossings, the same counters; their
 * columns are the clip's (a crossing left of it counted at its first
 * column, one right of it past every sample, as above), and every row of
 * the clip is swept.  When (counts known before any edge is set up: the
 * vertices and the clip's size): as the rule above with the vertices for
 * the edges and the clip for the polygon's box (at least
 * RAST__DELTA_EDGES vertices a row; the sweep's word tests at most
 * RAST__DELTA_WORDS a vertex) and one band.  Non-zero with more than 511
 * vertices needs at most 510 crossings on every row (above): the
 * crossings a row are counted as the edges go (a start and an end each,
 * summed along the rows once they are all walked), and past that the
 * counters, which may have wrapped, are left unread.  Returns 0 (the
 * rule does not take it, or it gave up: the arena as it was) or 1, the
 * runs handed to the sink. */
static int rast__aet_delta_now(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                               rast_fill_rule rule, const rast_rect *clip, rast__arena *arena,
                               rast__sink *sink)
{
    const rast__arena keep = *arena;
    const int32_t row0 = clip->y0, row1 = clip->y1, rows = row1 - row0;
    rast__delta_cols d;
    rast__byte_rows out;
    unsigned char *buf, *in = NULL;
    int32_t *starts = NULL;
    uint16_t *rc;
    int32_t mid = row0; /* rows [row0, mid) counted in the mask itself, [mid, row1) in buf */
    int direct;

    if (rows <= 0 || npoints < RAST__DELTA_EDGES * (uint64_t)rows) return 0;
    d.col0 = clip->x0;
    d.bits = clip->x1 - clip->x0;
    if (d.bits <= 0 || d.bits >= INT32_MAX - 8) return 0; /* (the stride below fits an int32) */
    d.stride = (d.bits + 1 + 7) & ~7;
    d.mask = rule == RAST_RULE_EVENODD ? 1 : 0xFF;
    d.whole = 0;
    if ((uint64_t)rows * (uint64_t)d.stride > (uint64_t)npoints * sizeof(rast__edge) ||
        (uint64_t)rows * (uint64_t)(d.stride / 8) > RAST__DELTA_WORDS * (uint64_t)npoints)
        return 0;
    if (rows >= 2 && rast__sink_byte_rows(sink, &out) && out.opaque && out.x0 == d.col0 &&
        out.x1 == d.col0 + d.bits && out.stride == d.bits) { /* (rast__delta_inplace) */
        mid = row1 - 1;
        in = out.base + (ptrdiff_t)row0 * out.stride + d.col0;
    }
    buf = (unsigned char *)rast__take(arena, (size_t)(row1 - mid) * (size_t)d.stride);
    if (buf && d.mask != 1 && npoints > 511) {
        /* starts[r - row0] less ends: row r's crossings, summed along */
        starts = (int32_t *)rast__take(arena, ((size_t)rows + 1) * sizeof(int32_t));
        if (starts) memset(starts, 0, ((size_t)rows + 1) * sizeof(int32_t));
        else buf = NULL;
    }
    if (!buf) {
        *arena = keep;
        return 0;
    }
    memset(buf, 0, (size_t)(row1 - mid) * (size_t)d.stride);
    if (in) memset(in, 0, (size_t)(mid - row0) * (size_t)d.bits);
    if (rows <= RAST__RC_MAX && d.bits <= RAST__RC_MAX &&
        (rc = (uint16_t *)rast__take(arena, ((size_t)npoints + 1) * 2 * sizeof(uint16_t))) != NULL) {
        const rast__vshift v = rast__vshift_of(g);
        rast__delta_rc(poly->points, npoints, &v, d.col0, row0, d.bits, rows, rc);
        if (in) rast__delta_rc_walk(poly, rc, g, &d, row0, mid - row0, buf, in, starts, 1);
        else rast__delta_rc_walk(poly, rc, g, &d, row0, 0, buf, NULL, starts, 0);
    } else if (in) {
        rast__delta_now_walk(poly, g, &d, row0, row1, mid, buf, in, starts, 1);
    } else {
        rast__delta_now_walk(poly, g, &d, row0, row1, row0, buf, NULL, starts, 0);
    }
    *arena = keep; /* (nothing taken is read after the fill) */
    if (starts) {
        int32_t y, run = 0;
        for (y = 0; y < rows; y++) {
            run += starts[y];
            if (run > 510) return 0;
        }
    }
    if (in) {
        rast__byte_rows_claim(&out, row0, row1);
        rast__delta_inplace(in, (size_t)(mid - row0) * (size_t)d.bits, d.mask, &out);
        direct = 1;
    } else {
        direct = rast__delta_direct(sink, &d, row0, row1, &out);
    }
    rast__delta_out(buf, mid, row1, &d, direct, &out, sink);
    return 1;
}
#endif

#if defined(__OPTIMIZE_SIZE__)
/* a build for size (firmware): the AET alone */
rast_status rast__aet_fill(const rast_polygon *poly, uint32_t npoints,
                           const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, rast__sink *sink,
                           rast__arena *arena)
{
    rast_status st = rast__aet_walk(poly, npoints, g, rule, clip, arena, rast__aet_span, NULL, sink, NULL);
    rast__sink_flush(sink);
    return st;
}

#else
/* ---- many small rings: shared edges cancel first ---------------------------
 * A mesh given as rings (its cells turned the same way) has each inner
 * edge twice, once each way: their parts of the winding number cancel at
 * every sample (rast__segs_cancel, aet.h), and walking them was nearly
 * all of the fill (a 40 x 40 grid of triangles: 9,600 edges of which the
 * 160 of its outline are left).  When (counts known before filling):
 * two rings or more of at most 8 vertices on average, and at most half
 * of the edges left (else the AET's own setup, the arena as it was).
 * What is left is set up as the walk's edge table, |n| copies of each
 * segment turned as n says: the same winding number at every sample,
 * so the same runs under either rule (even-odd: the parity). */
static int rast__aet_cancel(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                            rast_fill_rule rule, const rast_rect *clip, rast__arena *arena,
                            rast__aet_tab *t, size_t *room)
{
    const rast__arena keep = *arena;
    rast__seg *seg;
    uint32_t copies;
    int32_t m, i, miny, maxy, minx, maxx;
    int64_t r;
    m = rast__segs_cancel(poly->points, poly->ring_sizes, npoints, rule == RAST_RULE_EVENODD, arena, &seg,
                          &copies);
    if (m < 0) return 0;
    t->row0 = t->row1 = 0;
    if (m == 0) return 1;
    miny = seg[0].a.y;
    maxy = seg[0].b.y;
    minx = maxx = seg[0].a.x;
    for (i = 0; i < m; i++) {
        miny = seg[i].a.y < miny ? seg[i].a.y : miny;
        maxy = seg[i].b.y > maxy ? seg[i].b.y : maxy;
        minx = seg[i].a.x < minx ? seg[i].a.x : minx;
        minx = seg[i].b.x < minx ? seg[i].b.x : minx;
        maxx = seg[i].a.x > maxx ? seg[i].a.x : maxx;
        maxx = seg[i].b.x > maxx ? seg[i].b.x : maxx;
    }
    r = rast__row_at_or_after(2 * (int64_t)miny, g);
    t->row0 = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(2 * (int64_t)maxy, g);
    t->row1 = r < clip->y1 ? (int32_t)r : clip->y1;
    if (t->row0 >= t->row1) return 1;
    t->minx = minx;
    t->maxx = maxx;
    if (!rast__aet_tables(arena, copies, t->row0, t->row1, &t->edges, &t->aet, &t->bucket)) {
        *arena = keep;
        return 0;
    }
    t->nedges = rast__segs_edges(seg, m, g, t->row0, t->row1, t->aet, t->bucket);
    *room = (size_t)copies * sizeof(rast__edge);
    return 1;
}

/* ---- one outline's rows straight to one-byte pixels ------------------------
 * When the sink's painter is rows of one-byte pixels (rast__sink_byte_rows,
 * painters/paint.c: a gray8 fill, or polygon_mask's opaque one) and the
 * sweep fills (a circle, a glyph, a star: few edges for the rows), the
 * sweep's row hook (rast__aet_order_fn with no span function, aet.h)
 * writes each row itself: the runs of the row's crossings, exactly the
 * sweep's (aet.h), cut to the clip's columns, each pixel once (opaque: the
 * background between the runs, not the whole row first and the runs over
 * it), with no runs gathered in the sink and handed to the painter
 * through its entry.  Rows [row0, row1) are claimed whole (opaque); the
 * rows of no crossing among them (between two glyphs) are written as the
 * next row with some, or at the end. */
typedef struct rast__aet_bytes {
    rast__byte_rows out;
    rast_fill_rule rule;
    int32_t next; /* opaque: the first claimed row not yet written */
} rast__aet_bytes;

/* Opaque: the claimed rows [a->next, to) that had no crossing. */
static void rast__aet_bytes_blank(rast__aet_bytes *a, int32_t to)
{
    const rast__byte_rows *b = &a->out;
    for (; a->next < to; a->next++)
        memset(b->base + (ptrdiff_t)a->next * b->stride + b->x0, b->background, (size_t)(b->x1 - b->x0));
}

/* Bytes p[0 .. len) set to w's byte (w: it in all eight), by whole
 * 16-byte stores from p: up to 16 bytes past the run may be written too,
 * which the row's later runs write again.  A star's rows are ~70 runs of
 * 3 to 8 columns, a glyph's a few of 30 to 200, and the exact writes
 * (rast__run8: tests of the length, memset for a long run) were a sixth
 * of the star's fill's time. */
static inline void rast__aet_bytes_over(unsigned char *p, size_t len, uint64_t w)
{
    unsigned char *const end = p + len;
#if defined(RAST__DELTA_SSE2)
    const __m128i v = _mm_set1_epi64x((long long)w);
    if (len <= 8) {
        memcpy(p, &w, 8);
        return;
    }
    /* (the first 16 bytes as they fall, then whole aligned 16 bytes: a
     * long run's stores split across cache lines one in four times
     * otherwise, which made a circle's 512 x 512 mask ~2 us slower) */
    _mm_storeu_si128((__m128i *)(void *)p, v);
    p += 16 - ((uintptr_t)p & 15);
    for (; p < end; p += 16) _mm_store_si128((__m128i *)(void *)p, v);
#else
    do {
        memcpy(p, &w, 8);
        memcpy(p + 8, &w, 8);
        p += 16;
    } while (p < end);
#endif
}

/* Run [l, r) of a row (px its first byte, opaque: the background from
 * *pos up to it), cut to the columns [x0, x1); *pos moves past it.  Opaque
 * and 16 columns or more before x1, the two by rast__aet_bytes_over (the
 * bytes it writes past r lie in [r, x1), which the row's later runs and
 * its last background, exact, write again). */
static inline void rast__aet_bytes_run(const rast__byte_rows *b, unsigned char *px, int32_t *pos,
                                       int32_t l, int32_t r, uint64_t vw, uint64_t bw)
{
    if (l < b->x0) l = b->x0;
    if (r > b->x1) r = b->x1;
    if (l >= r) return;
    if (b->opaque && r <= b->x1 - 16) {
        rast__aet_bytes_over(px + *pos, (size_t)(l - *pos), bw);
        rast__aet_bytes_over(px + l, (size_t)(r - l), vw);
    } else {
        if (b->opaque) rast__run8(px + *pos, (size_t)(l - *pos), b->background, bw);
        rast__run8(px + l, (size_t)(r - l), b->value, vw);
    }
    *pos = r;
}

/* The hook: row `row`'s runs into its pixels (opaque: the whole row), the
 * n active edges stepped to the next row and sorted again, as the sweep's
 * own pass does them (aet.h); each crossing read before its edge steps.
 * Whether two stepped crossings came out of order is noted as they step:
 * the insertion sort's pass over the records to find out (a star's ~70
 * edges a row, none crossing) was a sixth of the fill's time. */
RAST__HOT void rast__aet_bytes_row(void *user, int32_t row, rast__edge *aet, int32_t n)
{
    rast__aet_bytes *a = (rast__aet_bytes *)user;
    const rast__byte_rows *b = &a->out;
    unsigned char *px = b->base + (ptrdiff_t)row * b->stride;
    const uint64_t vw = RAST__LANES_LO * b->value, bw = RAST__LANES_LO * b->background;
    int32_t k, pos = b->x0, prev = INT32_MIN;
    int unsorted = 0;
    if (b->opaque) {
        if (a->next < row) rast__aet_bytes_blank(a, row);
        a->next = row + 1;
    }
    if (a->rule == RAST_RULE_EVENODD) {
        /* crossings 2k and 2k + 1 */
        for (k = 0; k + 1 < n; k += 2) {
            const int32_t l = aet[k].x, r = aet[k + 1].x;
            rast__edge_step(&aet[k]);
            rast__edge_step(&aet[k + 1]);
            unsorted |= (prev > aet[k].x) | (aet[k].x > aet[k + 1].x);
            prev = aet[k + 1].x;
            rast__aet_bytes_run(b, px, &pos, l, r, vw, bw);
        }
        if (k < n) {
            rast__edge_step(&aet[k]);
            unsorted |= prev > aet[k].x;
        }
    } else {
        /* where the winding number leaves 0 and where it comes back */
        int32_t w = 0, l = 0;
        for (k = 0; k < n; k++) {
            const int32_t x = aet[k].x;
            if (w == 0) l = x;
            w += aet[k].dir;
            rast__edge_step(&aet[k]);
            unsorted |= prev > aet[k].x;
            prev = aet[k].x;
            if (w == 0) rast__aet_bytes_run(b, px, &pos, l, x, vw, bw);
        }
    }
    if (b->opaque) rast__run8(px + pos, (size_t)(b->x1 - pos), b->background, bw);
    if (unsorted) rast__aet_sort(aet, n);
}

/* The sweep of table t through the hook above, when the sink's painter
 * is rows of one-byte pixels: 1; else 0, nothing done.  (Apart from
 * rast__aet_fill_by: inlined there, it cost the winding deltas' setup
 * loop a register, an instruction a vertex.) */
RAST__APART int rast__aet_sweep_bytes(rast__aet_tab *t, rast_fill_rule rule, rast__sink *sink)
{
    rast__aet_bytes a;
    if (!rast__sink_byte_rows(sink, &a.out)) return 0;
    a.rule = rule;
    a.next = t->row0;
    if (a.out.opaque) rast__byte_rows_claim(&a.out, t->row0, t->row1);
    rast__aet_sweep(t->edges, t->aet, t->bucket, t->nedges, t->row0, t->row1, rule, NULL,
                    rast__aet_bytes_row, &a);
    if (a.out.opaque) rast__aet_bytes_blank(&a, t->row1);
    return 1;
}

/* ---- a few vertices: edge by edge ------------------------------------------
 * A polygon of a handful of vertices (a loop over small shapes, one call
 * each: 4 to 8 vertices over a few rows) spent most of its fill on the
 * AET's upkeep, not its pixels: grouping the table by row, joining,
 * compacting, the sweep's set-up (~2,900 instructions a polygon of the
 * "loop" family, bench/families.py).  The batch's small filler (small.h)
 * walks each edge down its rows into per-row slots instead and forms the
 * same runs (the AET's crossings to the bit, maximal runs in order); they
 * go to the sink, or, when its painter has the fast kind (a gray8 fill,
 * nothing but the run written), straight into the row.  When: at most
 * RAST__AET_FEW vertices (a count known before filling; a bigger outline
 * keeps the AET, whose steady rows cost less than a row's slots). */
#ifndef RAST__AET_FEW
#define RAST__AET_FEW 16
#endif

/* The walk's runs: [x0, x1) non-empty and within the clip's columns
 * already (the walk clamps its crossings to them), so the fast kind
 * writes it as it is. */
static inline void rast__aet_few_span(void *user, uint32_t index, int32_t y, int32_t x0, int32_t x1)
{
    rast__sink *s = (rast__sink *)user;
    (void)index;
    if (s->direct)
        rast__run8(s->direct + (ptrdiff_t)y * s->stride + x0, (size_t)(x1 - x0), (unsigned char)s->value,
                   RAST__LANES_LO * (unsigned char)s->value);
    else
        rast__sink_span(s, y, x0, x1);
}

/* ---- one ring that every row crosses twice: its two sides ------------------
 * A ring whose vertices' rows (rast__row_at_or_after of their y), taken
 * round it, go down once and up once (plateaus aside: a y-monotone ring,
 * every convex one among them) has two sides from its top row to its
 * bottom one, each crossing every row between them exactly once (an
 * edge crosses the rows [its upper end's, its lower end's), so the edges
 * of a side, one after the other, cross each row once, and an edge
 * between two vertices of one row none).  Each row then has those two
 * crossings and no other: the AET's runs (aet.h) are the columns from the
 * lesser to the greater (empty when equal), under either rule.  So the
 * walk needs no table, no slots and no sort: the two sides' edges are
 * set up in turn as the rows reach them (the same DDA, from the same
 * first row, as the AET's: the same columns), stepped a row at a time,
 * and each row's run written; the "loop" family's small rings
 * (bench/families.py, one call each) spent three quarters of their fill
 * on the slots' upkeep.  When: one ring of at most RAST__AET_FEW
 * vertices whose rows change direction exactly twice round it (counted
 * before anything is written).  Returns 1 when it filled, 0 when the ring
 * is not such a ring (nothing done). */
typedef struct rast__side {
    rast__edge ed; /* the current edge: its column ed.x, its rows up to ed.end */
    uint32_t at;   /* its upper vertex */
} rast__side;

/* Side s (vertices in the order at, at + step, ... modulo n) at row j, a
 * row it crosses: its edge there set up from row j (only its column when
 * that is its last row). */
RAST__HOT void rast__side_at(rast__side *s, const rast_point *pts, const int32_t *vrow, uint32_t n,
                                 uint32_t step, int32_t j, const rast__grid *g)
{
    uint32_t a = s->at, b = a + step >= n ? a + step - n : a + step;
    while (vrow[b] <= j) {
        a = b;
        b = a + step >= n ? a + step - n : a + step;
    }
    s->at = a;
    if (vrow[b] - j == 1) {
        int64_t e;
        s->ed.x = rast__edge_first_col(pts[a], pts[b], j, g, &e);
        s->ed.end = j + 1;
    } else {
        rast__edge_start_inline(&s->ed, pts[a], pts[b], 1, j, vrow[b], g);
    }
}

RAST__APART int rast__aet_sides(const rast_point *pts, uint32_t n, const rast__grid *g, const rast_rect *clip,
                                rast__sink *sink)
{
    const rast__vshift v = rast__vshift_of(g);
    const int32_t c0 = clip->x0, c1 = clip->x1;
    /* the sink's fast kind in locals (the pixels' stores may alias the
     * sink, which made every row reload it: rast__rows_of) */
    unsigned char *const direct = sink->direct;
    const ptrdiff_t stride = sink->stride;
    const int value = sink->value;
    int32_t vrow[RAST__AET_FEW], j, j1, rp;
    uint32_t i, top = 0, bottom = 0, turns = 0, at = 0;
    /* the direction (1 down) of the last edge that crosses a row so far,
     * and of the first one (edge at - 1 -> at), -1 before there is one */
    int last = -1, first = -1;
    rast__side l, r;
    if (n < 3 || n > RAST__AET_FEW) return 0;
    /* each vertex's row; the turns at edge i - 1 -> i (the last edge,
     * n - 1 -> 0, first), its upper or lower end a top or a bottom */
    rp = rast__vshift_row(pts[n - 1].y, v.ky, v.shift) - v.kb;
    for (i = 0; i < n; i++) {
        const int32_t row = rast__vshift_row(pts[i].y, v.ky, v.shift) - v.kb;
        vrow[i] = row;
        if (row != rp) {
            const int down = row > rp;
            if (last < 0) {
                first = down;
                at = i;
            } else if (down != last) {
                turns++;
                if (down) top = i ? i - 1 : n - 1;
                else bottom = i ? i - 1 : n - 1;
            }
            last = down;
        }
        rp = row;
    }
    if (first < 0) return 1; /* (every vertex on one row: no row crossed) */
    if (first != last) { /* the turn at the first crossing edge */
        turns++;
        if (first) top = at ? at - 1 : n - 1;
        else bottom = at ? at - 1 : n - 1;
    }
    if (turns != 2) return 0;
    j = vrow[top] > clip->y0 ? vrow[top] : clip->y0;
    j1 = vrow[bottom] < clip->y1 ? vrow[bottom] : clip->y1;
    if (j >= j1) return 1;
    l.at = r.at = top;
    /* (a side's edge of one row is its column alone, never stepped:
     * the rest set for the compiler, which cannot tell) */
    l.ed.e = l.ed.dr = l.ed.q = r.ed.e = r.ed.dr = r.ed.q = 0;
    l.ed.step = r.ed.step = 0;
    rast__side_at(&l, pts, vrow, n, 1, j, g);
    rast__side_at(&r, pts, vrow, n, n - 1, j, g);
    for (;;) {
        int32_t x0, x1;
        x0 = l.ed.x < r.ed.x ? l.ed.x : r.ed.x;
        x1 = l.ed.x ^ r.ed.x ^ x0;
        x0 = x0 < c0 ? c0 : x0;
        x1 = x1 > c1 ? c1 : x1;
        if (x0 < x1) {
            if (direct)
                rast__run8(direct + (ptrdiff_t)j * stride + x0, (size_t)(x1 - x0), (unsigned char)value,
                           RAST__LANES_LO * (unsigned char)value);
            else
                rast__sink_span(sink, j, x0, x1);
        }
        if (++j == j1) break;
        if (j == l.ed.end) rast__side_at(&l, pts, vrow, n, 1, j, g);
        else rast__edge_step(&l.ed);
        if (j == r.ed.end) rast__side_at(&r, pts, vrow, n, n - 1, j, g);
        else rast__edge_step(&r.ed);
    }
    rast__sink_flush(sink);
    return 1;
}

/* The walk's runs to the sink: 1, or 0 (nothing done) when the scratch
 * is too small for it.  (Apart from rast__aet_fill_by: inlined there, it
 * cost the winding deltas' setup loop a register, ~24,000 instructions of
 * a paragraph of text's fill.) */
RAST__APART int rast__aet_few(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                              rast_fill_rule rule, const rast_rect *clip, rast__sink *sink,
                              rast__arena *arena)
{
    if (!rast__small_walk(poly, npoints, g, rule, clip, rast__aet_few_span, sink, 0, arena->p, arena->left))
        return 0;
    rast__sink_flush(sink);
    return 1;
}

rast_status rast__aet_fill_by(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                              rast_fill_rule rule, const rast_rect *clip, rast__sink *sink,
                              rast__arena *arena, int how)
{
    rast__aet_tab t;
    rast_status st = RAST_OK;
    size_t room = (size_t)npoints * sizeof(rast__edge);
    if (how == RAST__AET_BY_RULE && npoints <= RAST__AET_FEW && clip->x1 - clip->x0 <= RAST_MAX_DIM &&
        ((poly->nrings == 1 && rast__aet_sides(poly->points, npoints, g, clip, sink)) ||
         rast__aet_few(poly, npoints, g, rule, clip, sink, arena)))
        return RAST_OK;
    if (!(how == RAST__AET_BY_RULE && poly->nrings >= 2 &&
          npoints <= 8 * (uint64_t)poly->nrings &&
          rast__aet_cancel(poly, npoints, g, rule, clip, arena, &t, &room))) {
        if (how == RAST__AET_BY_RULE && rast__aet_delta_now(poly, npoints, g, rule, clip, arena, sink)) {
            rast__sink_flush(sink);
            return RAST_OK;
        }
        st = rast__aet_prepare(poly, npoints, g, clip, arena, NULL, &t);
    }
    if (st == RAST_OK && t.row0 < t.row1 &&
        (how == RAST__AET_BY_SWEEP ||
         !rast__aet_delta(room, g, rule, clip, &t, sink, how == RAST__AET_BY_DELTA)) &&
        /* (RAST__AET_BY_SWEEP: the sweep's runs through the sink, the
         * reference the tests hold the others to) */
        (how == RAST__AET_BY_SWEEP || !rast__aet_sweep_bytes(&t, rule, sink)))
        rast__aet_sweep(t.edges, t.aet, t.bucket, t.nedges, t.row0, t.row1, rule, rast__aet_span,
                        NULL, sink);
    rast__sink_flush(sink);
    return st;
}

rast_status rast__aet_fill(const rast_polygon *poly, uint32_t npoints,
                           const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, rast__sink *sink,
                           rast__arena *arena)
{
    return rast__aet_fill_by(poly, npoints, g, rule, clip, sink, arena, RAST__AET_BY_RULE);
}
#endif
