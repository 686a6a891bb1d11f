/*
 * wide.h - signed 128-bit products and their floor division by a 64-bit
 * divisor, in portable C99 (two 64-bit halves; no __int128, which neither
 * C99 nor a Cortex-M0 compiler has).  The shaded fills need them where a
 * plane equation's numerator outgrows int64_t: big triangles, slivers,
 * depths spanning the whole int32_t range.  The common small case never
 * comes here (shade.c checks the magnitudes per triangle).
 */
#ifndef RAST_WIDE_H
#define RAST_WIDE_H

#include "internal.h"

/* Two's complement: the value is hi * 2^64 + lo, hi read as signed. */
typedef struct rast__i128 {
    uint64_t hi, lo;
} rast__i128;

static inline rast__i128 rast__i128_from(int64_t v)
{
    rast__i128 r;
    r.lo = (uint64_t)v;
    r.hi = v < 0 ? ~(uint64_t)0 : 0;
    return r;
}

static inline rast__i128 rast__i128_neg(rast__i128 a)
{
    rast__i128 r;
    r.lo = ~a.lo + 1u;
    r.hi = ~a.hi + (r.lo == 0);
    return r;
}

static inline rast__i128 rast__i128_add(rast__i128 a, rast__i128 b)
{
    rast__i128 r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo);
    return r;
}

/* a * 2^n for 0 <= n < 64 (the caller keeps the result in range). */
static inline rast__i128 rast__i128_shl(rast__i128 a, int32_t n)
{
    rast__i128 r;
    if (n == 0) return a;
    r.hi = (a.hi << n) | (a.lo >> (64 - n));
    r.lo = a.lo << n;
    return r;
}

/* The exact product a * b. */
static inline rast__i128 rast__i128_mul(int64_t a, int64_t b)
{
#if defined(__SIZEOF_INT128__) && !defined(RAST_NO_INT128)
    __extension__ typedef __int128 rast__s128;
    __extension__ typedef unsigned __int128 rast__u128;
    rast__s128 p = (rast__s128)a * b;
    rast__i128 r;
    r.lo = (uint64_t)p;
    r.hi = (uint64_t)((rast__u128)p >> 64);
    return r;
#else
    const uint64_t m = 0xFFFFFFFFu;
    uint64_t ua = a < 0 ? 0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? 0 - (uint64_t)b : (uint64_t)b;
    uint64_t a0 = ua & m, a1 = ua >> 32, b0 = ub & m, b1 = ub >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & m) + (p10 & m);
    rast__i128 r;
    r.lo = (p00 & m) | (mid << 32);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return (a < 0) != (b < 0) ? rast__i128_neg(r) : r;
#endif
}

/* Is a (as a signed 128-bit value) inside int64_t? */
static inline int rast__i128_is64(rast__i128 a)
{
    return a.hi == (((a.lo >> 63) != 0) ? ~(uint64_t)0 : 0);
}

/* ceil(a / 2^n) for 0 < n < 64: the arithmetic shift of a + 2^n - 1
 * (two's complement, so the shift of the halves is the floor), which
 * stays in range for |a| < 2^126. */
static inline rast__i128 rast__i128_ceilshift(rast__i128 a, int32_t n)
{
    rast__i128 r;
    a = rast__i128_add(a, rast__i128_from(((int64_t)1 << n) - 1));
    r.lo = (a.lo >> n) | (a.hi << (64 - n));
    /* arithmetic shift of hi, without relying on >> of a negative */
    r.hi = (a.hi >> n) | ((a.hi >> 63) ? ~(~(uint64_t)0 >> n) : 0);
    return r;
}

/* Largest quotient magnitude rast__i128_floordiv hands back. */
#define RAST__WIDE_QMAX ((int64_t)1 << 62)

/* *q = floor(a / d), *r = a - *q * d in [0, d), for 0 < d < 2^62.
 * Returns 1; or, when |floor(a / d)| > 2^62, sets *q to +-2^62 (the sign
 * of a), *r to 0 and returns 0 (the caller clamps such values). */
static inline int rast__i128_floordiv(rast__i128 a, int64_t d, int64_t *q, int64_t *r)
{
    uint64_t hi, lo, qm = 0, ud = (uint64_t)d;
    int neg = (int)(a.hi >> 63), i;
    /* Fits int64_t: one native division. */
    if (a.hi == (((a.lo >> 63) != 0) ? ~(uint64_t)0 : 0)) {
        int64_t v = (int64_t)a.lo, qq = v / d, rr = v % d;
        if (rr < 0) {
            qq -= 1;
            rr += d;
        }
        if (qq > RAST__WIDE_QMAX || qq < -RAST__WIDE_QMAX) goto saturate;
        *q = qq;
        *r = rr;
        return 1;
    }
    if (neg) a = rast__i128_neg(a);
    hi = a.hi;
    lo = a.lo;
    if (hi >= ud) goto saturate; /* the quotient needs more than 64 bits */
    /* Restoring long division, one quotient bit a step; hi < d < 2^62 keeps
     * hi << 1 inside 64 bits. */
    for (i = 0; i < 64; i++) {
        hi = (hi << 1) | (lo >> 63);
        lo <<= 1;
        qm <<= 1;
        if (hi >= ud) {
            hi -= ud;
            qm |= 1u;
        }
    }
    if (qm > (uint64_t)RAST__WIDE_QMAX) goto saturate;
    if (!neg) {
        *q = (int64_t)qm;
        *r = (int64_t)hi;
    } else if (hi) {
        *q = -(int64_t)qm - 1;
        *r = d - (int64_t)hi;
    } else {
        *q = -(int64_t)qm;
        *r = 0;
    }
    return 1;
saturate:
    *q = neg ? -RAST__WIDE_QMAX : RAST__WIDE_QMAX;
    *r = 0;
    return 0;
}

/* *q = floor(a / d), *r = a - *q * d in [0, d), for 0 < d < 2^62 and a
 * quotient the caller knows to be within +-2^62 (the 64-bit polygon path:
 * a crossing's abscissa).  A native 128-bit division where the compiler
 * has one (GCC and clang on 64-bit targets), else the long division of
 * rast__i128_floordiv (the same results: tests build both,
 * -DRAST_NO_INT128). */
static inline void rast__wide_floordiv(rast__i128 a, int64_t d, int64_t *q, int64_t *r)
{
#if defined(__SIZEOF_INT128__) && !defined(RAST_NO_INT128)
    __extension__ typedef __int128 rast__s128;
    __extension__ typedef unsigned __int128 rast__u128;
    rast__s128 n = (rast__s128)(((rast__u128)a.hi << 64) | a.lo);
    rast__s128 qq = n / d, rr = n % d;
    if (rr < 0) {
        qq -= 1;
        rr += d;
    }
    *q = (int64_t)qq;
    *r = (int64_t)rr;
#else
    (void)rast__i128_floordiv(a, d, q, r);
#endif
}

#if !defined(__SIZEOF_INT128__) || defined(RAST_NO_INT128) /* (rast__shl_div_ceil's only, there) */
/* floor(r 2^n / d), its remainder into *rem, for 0 <= r < d <= 2^41 and
 * 0 <= n <= 62, in 64-bit divisions only: base-2^k long division, k bits
 * of the quotient a step, r 2^k < 2^64 (k = 64 - d's bit length, at
 * least 22, and r < d < 2^(64 - k); without the compiler's count of
 * leading zeros, 32 while d < 2^32, else 23), so at most three machine
 * divisions where n <= 60 instead of a 128-bit division's call (the
 * quotient is below 2^n). */
static inline uint64_t rast__shl_div64(uint64_t r, uint64_t d, int32_t n, uint64_t *rem)
{
#if (defined(__GNUC__) || defined(__clang__)) && !defined(RAST_NO_BUILTIN_CTZ)
    const int32_t k = __builtin_clzll(d);
#else
    const int32_t k = (d >> 32) ? 23 : 32;
#endif
    uint64_t q = 0;
    while (n > 0) {
        const int32_t s = n < k ? n : k;
        const uint64_t v = r << s;
        q = (q << s) | (v / d);
        r = v % d;
        n -= s;
    }
    *rem = r;
    return q;
}
#endif

/* ceil(n 2^h / d) for 0 < d <= 2^41, 0 <= h <= 60 and n < d 2^(64 - h)
 * (the quotient fits 64 bits): one division of the 128-bit n 2^h + d - 1
 * where the compiler has a 128-bit type (a single machine division of a
 * double word where the quotient fits one, as here), else n / d and
 * rast__shl_div64 of the remainder (up to four divisions: on "span", a
 * third of a crossing time's cycles were its divisions). */
static inline uint64_t rast__shl_div_ceil(uint64_t n, uint64_t d, int32_t h)
{
#if defined(__SIZEOF_INT128__) && !defined(RAST_NO_INT128)
    __extension__ typedef unsigned __int128 rast__u128;
    return (uint64_t)((((rast__u128)n << h) + (d - 1)) / d);
#else
    uint64_t rem, q = ((n / d) << h) + rast__shl_div64(n % d, d, h, &rem);
    return q + (rem > 0);
#endif
}

/* The high 64 bits of the 128-bit product a * b: one instruction where
 * the compiler has a 128-bit type (GCC and clang on 64-bit targets; the
 * __extension__ keeps -pedantic quiet), else four 32-bit products. */
static inline uint64_t rast__mulhi(uint64_t a, uint64_t b)
{
#if defined(__SIZEOF_INT128__) && !defined(RAST_NO_INT128)
    __extension__ typedef unsigned __int128 rast__u128;
    return (uint64_t)(((rast__u128)a * b) >> 64);
#else
    const uint64_t m = 0xFFFFFFFFu;
    uint64_t a0 = a & m, a1 = a >> 32, b0 = b & m, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & m) + (p10 & m);
    return p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
}

/* Division by an invariant divisor d (0 < d < 2^62) without a divide
 * instruction per quotient: m = floor((2^64 - 1) / d) once, then
 * q = floor(u m / 2^64) is floor(u / d) less 0, 1 or 2 (u < 2^64), which
 * at most two corrections fix.  Exact; a triangle's setup and each span
 * divide by the same d, and a 64-bit divide costs tens of cycles. */
typedef struct rast__recip {
    uint64_t d, m;
} rast__recip;

static inline void rast__recip_init(rast__recip *r, int64_t d)
{
    r->d = (uint64_t)d;
    r->m = ~(uint64_t)0 / (uint64_t)d;
}

/* floor(n / d) for any int64_t n, *rem = n - floor(n / d) d in [0, d). */
static inline int64_t rast__recip_floordiv(const rast__recip *rc, int64_t n, int64_t *rem)
{
    uint64_t u = n < 0 ? 0 - (uint64_t)n : (uint64_t)n;
    uint64_t q = rast__mulhi(u, rc->m), r = u - q * rc->d;
    while (r >= rc->d) {
        q++;
        r -= rc->d;
    }
    if (n >= 0) {
        *rem = (int64_t)r;
        return (int64_t)q;
    }
    if (r) {
        *rem = (int64_t)(rc->d - r);
        return -(int64_t)q - 1;
    }
    *rem = 0;
    return -(int64_t)q;
}

/* Signed 128-bit helpers shared by the coverage engines (coverage/rows.h,
 * coverage/coverage64.c). */

static inline rast__i128 rast__i128_sub(rast__i128 a, rast__i128 b)
{
    return rast__i128_add(a, rast__i128_neg(b));
}

/* -1, 0 or 1 as a < b, a == b, a > b (signed). */
static inline int rast__i128_cmp(rast__i128 a, rast__i128 b)
{
    if (a.hi != b.hi) return (int64_t)a.hi < (int64_t)b.hi ? -1 : 1;
    if (a.lo != b.lo) return a.lo < b.lo ? -1 : 1;
    return 0;
}

static inline int rast__i128_neg_p(rast__i128 a)
{
    return (int)(a.hi >> 63);
}

/* floor(a / 2^n), 0 < n < 64 (an arithmetic shift written without one:
 * C99 leaves >> of a negative value to the implementation). */
static inline rast__i128 rast__i128_sar(rast__i128 a, int32_t n)
{
    rast__i128 r;
    uint64_t fill = (a.hi >> 63) ? ~(~(uint64_t)0 >> n) : 0;
    r.lo = (a.lo >> n) | (a.hi << (64 - n));
    r.hi = (a.hi >> n) | fill;
    return r;
}

#endif /* RAST_WIDE_H */
