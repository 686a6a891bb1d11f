/*
 * bits.h - the lowest set bit of a 64-bit word, for the mask rows of the
 * fillers (fillers/poly.h) and the columns' bits of the coverage engines
 * (coverage/): in base/, so that neither includes the other's header.
 * Not installed.
 */
#ifndef RAST_BITS_H
#define RAST_BITS_H

#include <stdint.h>

/* Index of the lowest set bit of x != 0: the compiler's builtin, or (for
 * other compilers, or with -DRAST_NO_BUILTIN_CTZ to test it) a table. */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(RAST_NO_BUILTIN_CTZ)
#define rast__ctz64(x) __builtin_ctzll(x)
#else
static inline int rast__ctz64(uint64_t x)
{
    /* de Bruijn: the lowest bit times B has a distinct top 6 bits for each
     * position. */
    static const unsigned char pos[64] = {
        0,  1,  48, 2,  57, 49, 28, 3,  61, 58, 50, 42, 38, 29, 17, 4,
        62, 55, 59, 36, 53, 51, 43, 22, 45, 39, 33, 30, 24, 18, 12, 5,
        63, 47, 56, 27, 60, 41, 37, 16, 54, 35, 52, 21, 44, 32, 23, 11,
        46, 26, 40, 15, 34, 20, 31, 10, 25, 14, 19, 9,  13, 8,  7,  6};
    return pos[((x & (0 - x)) * (uint64_t)0x03f79d71b4cb0a89u) >> 58];
}
#endif

#endif /* RAST_BITS_H */
