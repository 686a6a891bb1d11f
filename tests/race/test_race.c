/*
 * test_race.c - issue 18: rast_flood_fill and rast_boundary_fill while
 * another thread writes the target (an interrupt handler or DMA on
 * firmware).  The writer toggles the seed pixel and pixels of the region
 * between the region's value and others as fast as it can; the main
 * thread fills, over and over, with enough stack and with none (the
 * fixed-memory fallback), in gray8 (word scans), rgb888 and mono1.
 *
 * Checks, whatever the writer does: every call returns (a watchdog fails
 * the test if one takes longer than WATCHDOG seconds) with RAST_OK or
 * RAST_E_WORK; the bytes outside the clip (in the row padding, the rows
 * above and below and the columns beside) are never written; every pixel
 * in the clip holds a value it could get: its own, the fill value or one
 * the writer wrote.  Built and run under ASan + UBSan and under TSan by
 * `make race-check` (the writer's own accesses are the intended race and
 * are the one TSan suppression, tests/race/tsan.supp: race:race_writer).
 *
 * Before issue 18's fix: ASan negative-size-param in rast__seed_write
 * within a fraction of a second (the seed read twice), and the fallback
 * spinning forever in rast__span_push -> rast__component.
 */
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "rastrum.h"

#define W 48
#define H 40
#define STRIDE (W * 4 + 16) /* room for 4-byte pixels and padding */
#define PAD 2               /* rows above and below the target */
#define WATCHDOG 30

static unsigned char mem[(H + 2 * PAD) * STRIDE];
static unsigned char before[sizeof mem];
static uint64_t stack_mem[(64 * 1024) / 8];

/* What the writer may do, and whether to stop: set by the main thread. */
static int writer_stop;
static int writer_bpp;     /* 0: mono1 */
static int writer_x0, writer_y0, writer_x1, writer_y1; /* the clip it writes in */
static int seed_x, seed_y;

static unsigned long writes;

static unsigned char *pixel_row(int y)
{
    return mem + (size_t)(y + PAD) * STRIDE;
}

static void put(unsigned char *row, int x, int bpp, unsigned v)
{
    if (bpp == 0) {
        unsigned char bit = (unsigned char)(0x80u >> (x % 8));
        row[x / 8] = (unsigned char)(v ? row[x / 8] | bit : row[x / 8] & ~bit);
    } else {
        memset(row + (size_t)x * (size_t)bpp, (int)v, (size_t)bpp);
    }
}

/* The racing writer: the seed pixel and a pixel of the region in turn,
 * each set to the region's value (0) and then to 1 or 9. */
static void *race_writer(void *arg)
{
    uint32_t r = 12345u;
    (void)arg;
    while (!__atomic_load_n(&writer_stop, __ATOMIC_RELAXED)) {
        int x, y;
        r = r * 1664525u + 1013904223u;
        if (r & 0x100) {
            x = seed_x;
            y = seed_y;
        } else {
            x = writer_x0 + (int)((r >> 10) % (unsigned)(writer_x1 - writer_x0));
            y = writer_y0 + (int)((r >> 20) % (unsigned)(writer_y1 - writer_y0));
        }
        put(pixel_row(y), x, writer_bpp, 0);
        put(pixel_row(y), x, writer_bpp, (r & 0x200) ? 1 : 9);
        writes++;
    }
    return NULL;
}

static void on_alarm(int sig)
{
    (void)sig;
    static const char msg[] = "test_race: a fill did not return within the watchdog\n";
    if (write(2, msg, sizeof msg - 1) < 0) _exit(2);
    _exit(1);
}

static int failed, passed;

#define CHECK(c)                                                                     \
    do {                                                                             \
        if (c) passed++;                                                             \
        else {                                                                       \
            failed++;                                                                \
            if (failed < 20) fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #c); \
        }                                                                            \
    } while (0)

/* A maze-ish picture: walls (value 5) on a grid with gaps, the rest 0. */
static void draw(rast_format f, int bpp)
{
    int x, y;
    memset(mem, 0xEE, sizeof mem);
    for (y = 0; y < H; y++) {
        unsigned char *row = pixel_row(y);
        if (f == RAST_FORMAT_MONO1) memset(row, 0, (W + 7) / 8);
        for (x = 0; x < W; x++) {
            int wall = (y % 4 == 3 && x % 7 != 2) || (x % 6 == 5 && y % 5 != 1);
            put(row, x, bpp, wall ? 5u : 0u);
        }
    }
    memcpy(before, mem, sizeof mem);
}

static int run(rast_format f, int boundary, size_t stack_bytes, double seconds)
{
    rast_target t;
    rast_rect clip = {3, 2, W - 4, H - 3};
    int bpp = f == RAST_FORMAT_MONO1 ? 0 : (f == RAST_FORMAT_RGB888 ? 3 : 1);
    unsigned char value[4] = {7, 7, 7, 7}, edge[4] = {5, 5, 5, 5};
    pthread_t th;
    struct timespec t0, t1;
    int calls = 0, stopped = 0;

    if (f == RAST_FORMAT_MONO1) value[0] = 1, edge[0] = 1;
    draw(f, bpp);
    if (rast_target_init(&t, pixel_row(0), W, H, STRIDE, f) != RAST_OK) return 1;
    t.clip = clip;
    writer_bpp = bpp;
    writer_x0 = clip.x0;
    writer_y0 = clip.y0;
    writer_x1 = clip.x1;
    writer_y1 = clip.y1;
    seed_x = 10;
    seed_y = 9;
    __atomic_store_n(&writer_stop, 0, __ATOMIC_RELAXED);
    if (pthread_create(&th, NULL, race_writer, NULL) != 0) return 1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (;;) {
        rast_status st;
        alarm(WATCHDOG);
        st = boundary ? rast_boundary_fill(&t, seed_x, seed_y, value, edge, calls % 2 ? 8 : 4,
                                           stack_mem, stack_bytes)
                      : rast_flood_fill(&t, seed_x, seed_y, value, calls % 2 ? 8 : 4, stack_mem,
                                        stack_bytes);
        alarm(0);
        CHECK(st == RAST_OK || st == RAST_E_WORK);
        stopped += st == RAST_E_WORK;
        calls++;
        /* Undo the fill (the writer keeps going) */
        {
            int x, y;
            for (y = clip.y0; y < clip.y1; y++)
                for (x = clip.x0; x < clip.x1; x++) {
                    int wall = (y % 4 == 3 && x % 7 != 2) || (x % 6 == 5 && y % 5 != 1);
                    if (!wall) put(pixel_row(y), x, bpp, 0);
                }
        }
        clock_gettime(CLOCK_MONOTONIC, &t1);
        if ((double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec) > seconds)
            break;
    }
    __atomic_store_n(&writer_stop, 1, __ATOMIC_RELAXED);
    pthread_join(th, NULL);
    /* Outside the clip: untouched, byte for byte (the writer writes only
     * inside it; mono1's partial bytes at the clip's edges are checked by
     * bit). */
    {
        size_t i;
        int bad = 0;
        for (i = 0; i < sizeof mem; i++) {
            long y = (long)(i / STRIDE) - PAD;
            long off = (long)(i % STRIDE);
            int in_rows = y >= clip.y0 && y < clip.y1;
            if (bpp == 0) {
                if (in_rows && off >= clip.x0 / 8 && off <= (clip.x1 - 1) / 8) {
                    int b;
                    for (b = 0; b < 8; b++) {
                        long x = off * 8 + b;
                        unsigned char m = (unsigned char)(0x80u >> b);
                        if ((x < clip.x0 || x >= clip.x1) && ((mem[i] ^ before[i]) & m)) bad++;
                    }
                    continue;
                }
            } else if (in_rows && off >= (long)clip.x0 * bpp && off < (long)clip.x1 * bpp) {
                continue;
            }
            if (mem[i] != before[i]) bad++;
        }
        CHECK(bad == 0);
    }
    printf("test_race: format %d %s stack %lu: %d calls, %d stopped with RAST_E_WORK\n", (int)f,
           boundary ? "boundary" : "flood", (unsigned long)stack_bytes, calls, stopped);
    return 0;
}

int main(int argc, char **argv)
{
    double seconds = argc > 1 ? atof(argv[1]) : 1.0;
    static const rast_format formats[3] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB888, RAST_FORMAT_MONO1};
    int i, b;
    size_t stacks[2] = {sizeof stack_mem, 0};
    signal(SIGALRM, on_alarm);
    for (i = 0; i < 3; i++)
        for (b = 0; b < 2; b++) {
            if (run(formats[i], b, stacks[0], seconds / 12) != 0) return 1;
            if (run(formats[i], b, stacks[1], seconds / 12) != 0) return 1;
        }
    printf("test_race: %d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
