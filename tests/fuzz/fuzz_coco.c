/*
 * fuzz_coco.c - the binding's COCO RLE glue (python/glue/coco.c): parsing
 * hostile counts strings, encode, decode, merge, area, toBbox and iou.
 * Oracle, written apart from coco.c: a string's counts by a reference
 * parser in 64-bit arithmetic with its validity rule (characters '0'..'o',
 * at most 7 groups a count, every count in 0..2^32 - 1, their sum at most
 * h * w); masks as bytes; merge and IoU from the runs as 64-bit intervals,
 * so that sizes past 2^31 pixels (h * w up to 2^32 - 1) are checked
 * without a mask.  The glue is compiled in (#include), as Python builds it.
 */
#include "glue.h"
#include "fuzz.h"

#include <stdlib.h>
#include <string.h>


#define CZ_MAXC 64 /* counts a string */

/* The reference parser: the counts of s[0..len), or -1 if invalid. */
static long ref_parse(const unsigned char *s, size_t len, uint64_t *out, size_t max)
{
    size_t p = 0, m = 0;
    while (p < len) {
        int64_t v = 0, scale = 1;
        int groups = 0, last = 0;
        for (;;) {
            int c;
            if (p == len || groups == 7) return -1;
            c = (int)s[p++] - '0';
            if (c < 0 || c > 63) return -1;
            v += (int64_t)(c & 31) * scale;
            scale *= 32;
            groups++;
            if (!(c & 32)) {
                last = c;
                break;
            }
        }
        if (last & 16) v -= scale; /* the top group's bit 4 is the sign */
        if (m > 2) v += (int64_t)out[m - 2];
        if (v < 0 || v > 4294967295LL || m == max) return -1;
        out[m++] = (uint64_t)v;
    }
    return (long)m;
}

/* The 1-runs of counts as [start, end) intervals. */
static size_t ones(const uint64_t *c, size_t m, uint64_t *iv)
{
    size_t j, n = 0;
    uint64_t at = 0;
    for (j = 0; j < m; j++) {
        if (j & 1 && c[j]) {
            iv[2 * n] = at;
            iv[2 * n + 1] = at + c[j];
            n++;
        }
        at += c[j];
    }
    return n;
}

/* Pixels in both (and) or either (or) of two interval lists. */
static uint64_t overlap(const uint64_t *a, size_t na, const uint64_t *b, size_t nb, int both)
{
    uint64_t total = 0, ia = 0;
    size_t i, j;
    for (i = 0; i < na; i++)
        for (j = 0; j < nb; j++) {
            uint64_t lo = a[2 * i] > b[2 * j] ? a[2 * i] : b[2 * j];
            uint64_t hi = a[2 * i + 1] < b[2 * j + 1] ? a[2 * i + 1] : b[2 * j + 1];
            if (hi > lo) ia += hi - lo;
        }
    if (both) return ia;
    for (i = 0; i < na; i++) total += a[2 * i + 1] - a[2 * i];
    for (j = 0; j < nb; j++) total += b[2 * j + 1] - b[2 * j];
    return total - ia;
}

/* Is position q inside the intervals? */
static int inside(const uint64_t *iv, size_t n, uint64_t q)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (q >= iv[2 * i] && q < iv[2 * i + 1]) return 1;
    return 0;
}

/* A string from the input: raw bytes now and then, else counts encoded
 * by the reference encoder (groups as pycocotools writes them) summing to
 * at most total (or, rarely, past it). */
static size_t make_string(fz_in *in, unsigned char *s, size_t cap, uint64_t total)
{
    size_t n = 0, k, m;
    uint64_t c[CZ_MAXC], left = total;
    if (fz_u8(in) < 48) {
        m = fz_below(in, 24);
        for (k = 0; k < m && n < cap; k++) {
            uint32_t b = fz_u8(in);
            s[n++] = (unsigned char)(b < 200 ? '0' + b % 64 : b);
        }
        return n;
    }
    m = fz_below(in, 12);
    for (k = 0; k < m; k++) {
        uint64_t v;
        uint32_t pick = fz_u8(in);
        if (pick < 16) v = left;
        else if (pick < 24) v = left + 1 + fz_u8(in); /* past h * w */
        else if (pick < 32) v = 0;
        else v = left ? ((uint64_t)fz_u32(in) * 4294967296u + fz_u32(in)) % (left + 1) : 0;
        if (pick >= 24 && pick < 32 && k == 0) v = 0;
        if (v > 0xFFFFFFFFu) v = 0xFFFFFFFFu;
        c[k] = v;
        left = v <= left ? left - v : 0;
    }
    for (k = 0; k < m; k++) {
        int64_t x = (int64_t)c[k] - (k > 2 ? (int64_t)c[k - 2] : 0);
        int more = 1;
        while (more && n < cap) {
            int64_t g = x & 31;
            x = (x - g) / 32;
            more = (g & 16) ? x != -1 : x != 0;
            s[n++] = (unsigned char)('0' + g + (more ? 32 : 0));
        }
    }
    return n;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    unsigned char s[2][256];
    size_t len[2], offs[3], k;
    uint64_t c[2][256], iv[2][512];
    long m[2];
    size_t niv[2] = {0, 0};
    uint32_t h, w, sizes[4], area[2];
    uint64_t total;
    int big = fz_u8(&in) < 96;
    char strs[512];
    /* small masks (checked pixel by pixel) or huge ones (past 2^31) */
    if (big) {
        static const uint32_t hs[] = {1, 2, 3, 65536, 46341, 1u << 31, 0xFFFFFFFFu};
        h = hs[fz_below(&in, 7)];
        w = (uint32_t)(0xFFFFFFFFu / (h ? h : 1));
        if (fz_u8(&in) < 128) w -= fz_below(&in, 3);
        if (h == 0xFFFFFFFFu) w = 1;
    } else {
        h = (uint32_t)fz_below(&in, 9);
        w = (uint32_t)fz_below(&in, 9);
    }
    total = (uint64_t)h * w;
    for (k = 0; k < 2; k++) {
        len[k] = make_string(&in, s[k], sizeof s[k], total);
        m[k] = ref_parse(s[k], len[k], c[k], 256);
        if (m[k] >= 0) {
            uint64_t sum = 0;
            long j;
            for (j = 0; j < m[k]; j++) sum += c[k][j];
            if (sum > total || sum > 0xFFFFFFFFu) m[k] = -1;
            else niv[k] = ones(c[k], (size_t)m[k], iv[k]);
        }
    }
    memcpy(strs, s[0], len[0]);
    memcpy(strs + len[0], s[1], len[1]);
    offs[0] = 0;
    offs[1] = len[0];
    offs[2] = len[0] + len[1];
    sizes[0] = sizes[2] = h;
    sizes[1] = sizes[3] = w;

    /* area: the glue's verdict is the reference's, and its sums */
    {
        long st = rastpy_coco_area(strs, offs, 2, sizes, area);
        int valid = m[0] >= 0 && m[1] >= 0;
        FZ_ASSERT(valid ? st == 0 : st == RASTPY_E_RLE);
        for (k = 0; valid && k < 2; k++)
            FZ_ASSERT(area[k] == overlap(iv[k], niv[k], NULL, 0, 0));
    }
    /* toBbox of each valid string: pycocotools' box, from the intervals */
    for (k = 0; k < 2; k++) {
        double bb[4], want[4] = {0, 0, 0, 0};
        size_t ok[2] = {0, len[k]};
        long st = rastpy_coco_bbox((const char *)s[k], ok, 1, sizes, bb);
        FZ_ASSERT(m[k] >= 0 ? st == 0 : st == RASTPY_E_RLE);
        if (st) continue;
        if (niv[k] && h) {
            uint64_t xs = w, ys = h, xe = 0, ye = 0;
            size_t i;
            for (i = 0; i < niv[k]; i++) {
                uint64_t a = iv[k][2 * i], b = iv[k][2 * i + 1] - 1;
                if (a / h < xs) xs = a / h;
                if (b / h > xe) xe = b / h;
                if (a / h < b / h) {
                    ys = 0;
                    ye = h - 1;
                } else {
                    if (a % h < ys) ys = a % h;
                    if (b % h > ye) ye = b % h;
                }
            }
            want[0] = (double)xs;
            want[1] = (double)ys;
            want[2] = (double)(xe - xs + 1);
            want[3] = (double)(ye - ys + 1);
        }
        FZ_ASSERT(bb[0] == want[0] && bb[1] == want[1] && bb[2] == want[2] && bb[3] == want[3]);
    }
    /* merge (union and intersection): the runs of the reference's */
    {
        int inter;
        for (inter = 0; inter < 2; inter++) {
            char *out = NULL;
            size_t oo[2];
            uint32_t osz[2];
            long st = rastpy_coco_merge(strs, offs, 2, sizes, inter, &out, oo, osz);
            if (m[0] < 0 || m[1] < 0) {
                FZ_ASSERT(st == RASTPY_E_RLE && out == NULL);
                continue;
            }
            if (st == RASTPY_E_RLE) { /* counts of different totals (pycocotools loops) */
                FZ_ASSERT(out == NULL);
                continue;
            }
            FZ_ASSERT(st == 0 && osz[0] == h && osz[1] == w);
            {
                uint64_t mc[512], miv[1024];
                long mm = ref_parse((const unsigned char *)out, oo[1], mc, 512);
                size_t nm, i;
                FZ_ASSERT(mm >= 0);
                nm = ones(mc, (size_t)mm, miv);
                /* the same set: equal sizes, and each side's ends agree */
                FZ_ASSERT(overlap(miv, nm, NULL, 0, 0) ==
                          overlap(iv[0], niv[0], iv[1], niv[1], inter));
                for (i = 0; i < nm; i++) {
                    uint64_t q = miv[2 * i], e = miv[2 * i + 1] - 1;
                    int a = inside(iv[0], niv[0], q), b = inside(iv[1], niv[1], q);
                    FZ_ASSERT(inter ? a && b : a || b);
                    a = inside(iv[0], niv[0], e);
                    b = inside(iv[1], niv[1], e);
                    FZ_ASSERT(inter ? a && b : a || b);
                }
            }
            rastpy_free(out);
        }
    }
    /* iou (plain and crowd) of string 0 against string 1 */
    if (m[0] >= 0 && m[1] >= 0) {
        uint8_t crowd = (uint8_t)fz_below(&in, 2);
        double o = -2;
        size_t o0[2] = {0, len[0]}, o1[2] = {0, len[1]};
        long st = rastpy_coco_iou((const char *)s[0], o0, sizes, 1, (const char *)s[1], o1, sizes, 1,
                                  &crowd, &o);
        uint64_t inter = overlap(iv[0], niv[0], iv[1], niv[1], 1);
        uint64_t uni = crowd ? overlap(iv[0], niv[0], NULL, 0, 0) : overlap(iv[0], niv[0], iv[1], niv[1], 0);
        uint64_t sum0 = 0, sum1 = 0;
        long j;
        for (j = 0; j < m[0]; j++) sum0 += c[0][j];
        for (j = 0; j < m[1]; j++) sum1 += c[1][j];
        if (st == RASTPY_E_RLE) FZ_ASSERT(sum0 != sum1); /* pycocotools loops */
        else FZ_ASSERT(st == 0 && o == (inter ? (double)inter / (double)uni : 0.0));
    }
    /* small sizes: decode, encode and the pixels */
    if (!big && total) {
        uint8_t mask[2 * 64 + 16], again[2 * 64 + 16];
        size_t px;
        long st;
        memset(mask, 0xEE, sizeof mask);
        st = rastpy_coco_decode(strs, offs, 2, h, w, mask, 1, (int64_t)h, (int64_t)total, 7);
        if (m[0] < 0 || m[1] < 0) {
            FZ_ASSERT(st == RASTPY_E_RLE);
            for (px = 0; px < sizeof mask; px++) FZ_ASSERT(mask[px] == 0xEE); /* untouched */
        } else {
            char *enc = NULL;
            size_t eo[3];
            FZ_ASSERT(st == 0);
            for (k = 0; k < 2; k++)
                for (px = 0; px < total; px++)
                    FZ_ASSERT(mask[k * total + px] == (inside(iv[k], niv[k], px) ? 7 : 0));
            for (px = 2 * total; px < sizeof mask; px++) FZ_ASSERT(mask[px] == 0xEE);
            /* row-major (a strided write) gives the same pixels */
            memset(again, 0xEE, sizeof again);
            st = rastpy_coco_decode(strs, offs, 2, h, w, again, (int64_t)w, 1, (int64_t)total, 7);
            FZ_ASSERT(st == 0);
            for (k = 0; k < 2; k++)
                for (px = 0; px < total; px++)
                    FZ_ASSERT(again[k * total + (px % h) * w + px / h] == mask[k * total + px]);
            /* encode: back to counts whose mask is the same */
            st = rastpy_coco_encode(mask, h, w, 2, 1, (int64_t)h, (int64_t)total, &enc, eo);
            FZ_ASSERT(st == 0);
            for (k = 0; k < 2; k++) {
                uint64_t ec[256], eiv[512];
                long em = ref_parse((const unsigned char *)enc + eo[k], eo[k + 1] - eo[k], ec, 256);
                size_t ne;
                FZ_ASSERT(em >= 0);
                ne = ones(ec, (size_t)em, eiv);
                for (px = 0; px < total; px++)
                    FZ_ASSERT(inside(eiv, ne, px) == inside(iv[k], niv[k], px));
            }
            rastpy_free(enc);
        }
    }
    return 0;
}
