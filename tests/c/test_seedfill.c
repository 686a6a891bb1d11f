/*
 * test_seedfill.c - rast_flood_fill and rast_boundary_fill against a
 * breadth-first reference, on noise, mazes (with and without loops) and
 * spirals, every format, both connectivities, stacks of 0 to 4 entries
 * (the fixed-memory fallback) and plenty, inside a clip, with guard bytes
 * around every target.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 2024u
#include "check.h"
#include "rastrum.h"

#define GUARD 0xA5
#define PAD 4
#define MAXW 96
#define MAXH 80

/* ---- scenes: labels 0..2 ------------------------------------------------------ */
static unsigned char lab[MAXH][MAXW];

static void scene_noise(int w, int h, int percent, int colors)
{
    int i, j;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++)
            lab[j][i] = (unsigned char)((int)(rng() % 100) < percent ? 1 + (int)(rng() % (unsigned)(colors - 1)) : 0);
}

/* Walls 1, corridors 0: depth-first carving on odd cells, then `loops`
 * percent of the inner walls knocked out. */
static void scene_maze(int w, int h, int loops)
{
    static int stack[MAXW * MAXH], seen[MAXH][MAXW];
    int cw = (w - 1) / 2, ch = (h - 1) / 2, n = 0, i, j;
    memset(lab, 1, sizeof lab);
    memset(seen, 0, sizeof seen);
    if (cw < 1 || ch < 1) return;
    stack[n++] = 0;
    seen[0][0] = 1;
    lab[1][1] = 0;
    while (n) {
        int c = stack[n - 1], cx = c % cw, cy = c / cw, opts[4], k = 0, d;
        static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
        for (d = 0; d < 4; d++) {
            int nx = cx + dx[d], ny = cy + dy[d];
            if (nx >= 0 && nx < cw && ny >= 0 && ny < ch && !seen[ny][nx]) opts[k++] = d;
        }
        if (!k) {
            n--;
            continue;
        }
        d = opts[rng() % (unsigned)k];
        seen[cy + dy[d]][cx + dx[d]] = 1;
        lab[2 * (cy + dy[d]) + 1][2 * (cx + dx[d]) + 1] = 0;
        lab[cy + (cy + dy[d]) + 1][cx + (cx + dx[d]) + 1] = 0;
        stack[n++] = (cy + dy[d]) * cw + cx + dx[d];
    }
    for (j = 1; j < h - 1; j++)
        for (i = 1; i < w - 1; i++)
            if (lab[j][i] == 1 && (int)(rng() % 100) < loops) lab[j][i] = 0;
}

/* A square spiral wall with a corridor `gap` wide from the border inwards. */
static void scene_spiral(int w, int h, int gap)
{
    int x0 = 0, y0 = 0, x1 = w - 1, y1 = h - 1, step = gap + 1, side = 0, i;
    memset(lab, 0, sizeof lab);
    while (x0 <= x1 && y0 <= y1) {
        if (side == 0) {
            for (i = x0; i <= x1; i++) lab[y0][i] = 1;
            y0 += step;
        } else if (side == 1) {
            for (i = y0 - step < 0 ? 0 : y0 - step; i <= y1; i++) lab[i][x1] = 1;
            x1 -= step;
        } else if (side == 2) {
            for (i = x0; i <= x1 + step && i < w; i++) lab[y1][i] = 1;
            y1 -= step;
        } else {
            for (i = y0; i <= y1 + step && i < h; i++) lab[i][x0] = 1;
            x0 += step;
        }
        side = (side + 1) & 3;
    }
}

/* ---- the reference: breadth-first search ------------------------------------ */
static unsigned char want[MAXH][MAXW];

/* want = lab after the fill of the clip [x0,x1) x [y0,y1) from (sx, sy). */
static void reference(int w, int h, const rast_rect *c, int sx, int sy, int value,
                      int boundary, int conn)
{
    static int queue[MAXW * MAXH];
    static unsigned char done[MAXH][MAXW];
    static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    int head = 0, tail = 0, old = lab[sy][sx];
#define IN(i, j) (boundary < 0 ? lab[j][i] == old : (lab[j][i] != boundary && lab[j][i] != value))
    memcpy(want, lab, sizeof want);
    memset(done, 0, sizeof done);
    (void)w;
    (void)h;
    if (sx < c->x0 || sx >= c->x1 || sy < c->y0 || sy >= c->y1 || !IN(sx, sy)) return;
    if (boundary < 0 && old == value) return;
    queue[tail++] = sy * MAXW + sx;
    done[sy][sx] = 1;
    while (head < tail) {
        int p = queue[head++], x = p % MAXW, y = p / MAXW, d;
        want[y][x] = (unsigned char)value;
        for (d = 0; d < conn; d++) {
            int a = x + dx[d], b = y + dy[d];
            if (a >= c->x0 && a < c->x1 && b >= c->y0 && b < c->y1 && !done[b][a] && IN(a, b)) {
                done[b][a] = 1;
                queue[tail++] = b * MAXW + a;
            }
        }
    }
#undef IN
}

/* ---- a guarded target of any format ------------------------------------------ */
static const rast_format formats[5] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB888,
                                       RAST_FORMAT_RGBA8888, RAST_FORMAT_COUNT16,
                                       RAST_FORMAT_RGB565};
static uint16_t bufmem[((MAXH + 2 * PAD) * ((MAXW + 2 * PAD) * 4 + 8)) / 2 + 8];
static unsigned char before[sizeof bufmem];

/* Label k as pixel bytes: equal but in the last byte (count16: a uint16). */
static void label_pixel(int bpp, int k, unsigned char *out)
{
    if (bpp == 2) {
        uint16_t v = (uint16_t)(0x1207 + 0x100 * k);
        memcpy(out, &v, 2);
        return;
    }
    memset(out, 7, (size_t)bpp);
    out[bpp - 1] = (unsigned char)(7 + k);
}

static int pixel_label(int bpp, const unsigned char *p)
{
    unsigned char q[4];
    int k;
    for (k = 0; k < 6; k++) {
        label_pixel(bpp, k, q);
        if (!memcmp(p, q, (size_t)bpp)) return k;
    }
    return -1;
}

static uint64_t stack_mem[1 << 14];

/* Fill a guarded target of format f from lab and compare with the
 * reference; 1 if equal and no guard byte changed. */
static int run(int f, int w, int h, const rast_rect *clip, int sx, int sy, int value,
               int boundary, int conn, size_t stack_bytes)
{
    unsigned char *buf = (unsigned char *)bufmem, px[4], bd[4];
    int32_t bpp;
    int stride, i, j, ok = 1;
    rast_target t;
    rast_rect c;
    rast_status st;
    rast_format_bytes(formats[f], &bpp);
    stride = (w + 2 * PAD) * bpp + 2;
    memset(bufmem, GUARD, sizeof bufmem);
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) label_pixel(bpp, lab[j][i], buf + (j + PAD) * stride + (i + PAD) * bpp);
    memcpy(before, bufmem, sizeof bufmem);
    if (rast_target_init(&t, buf + PAD * stride + PAD * bpp, w, h, stride, formats[f]) != RAST_OK) return 0;
    if (clip) t.clip = *clip;
    c = t.clip;
    if (c.x0 < 0) c.x0 = 0;
    if (c.y0 < 0) c.y0 = 0;
    if (c.x1 > w) c.x1 = w;
    if (c.y1 > h) c.y1 = h;
    label_pixel(bpp, value, px);
    label_pixel(bpp, boundary < 0 ? 0 : boundary, bd);
    st = boundary < 0 ? rast_flood_fill(&t, sx, sy, px, conn, stack_bytes ? stack_mem : NULL, stack_bytes)
                      : rast_boundary_fill(&t, sx, sy, px, bd, conn, stack_bytes ? stack_mem : NULL, stack_bytes);
    if (st != RAST_OK) return 0;
    reference(w, h, &c, sx, sy, value, boundary, conn);
    for (j = -PAD; j < h + PAD; j++)
        for (i = 0; i < stride; i++) {
            size_t k = (size_t)((j + PAD) * stride + i);
            int col = i / bpp - PAD;
            if (j >= 0 && j < h && col >= 0 && col < w && i >= PAD * bpp) {
                if (i % bpp == 0 && pixel_label(bpp, buf + k) != want[j][col]) ok = 0;
            } else if (buf[k] != before[k]) {
                ok = 0; /* a guard byte or stride padding changed */
            }
        }
    return ok;
}

static const size_t stacks[5] = {0, 16, 32, 64, sizeof stack_mem};

static void random_seed(int w, int h, int *sx, int *sy)
{
    int tries;
    for (tries = 0; tries < 50; tries++) {
        *sx = (int)(rng() % (unsigned)w);
        *sy = (int)(rng() % (unsigned)h);
        if (lab[*sy][*sx] == 0) return;
    }
}

static void scenes(void)
{
    int round, bad = 0, cases = 0;
    for (round = 0; round < 600; round++) {
        int kind = round % 5, w = 1 + (int)(rng() % 60), h = 1 + (int)(rng() % 50);
        int sx, sy, f = (int)(rng() % 5), conn = rng() & 1 ? 8 : 4, value = (int)(rng() % 4);
        int boundary = (int)(rng() % 5) - 1; /* -1: flood fill */
        size_t sb = stacks[rng() % 5];
        if (kind == 0) scene_noise(w, h, (int)(rng() % 100), 2);
        else if (kind == 1) scene_noise(w, h, (int)(rng() % 100), 3);
        else if (kind == 2) scene_maze(w, h, 0);
        else if (kind == 3) scene_maze(w, h, 10);
        else scene_spiral(w, h, 1 + (int)(rng() % 3));
        random_seed(w, h, &sx, &sy);
        cases++;
        if (!run(f, w, h, NULL, sx, sy, value, boundary, conn, sb)) {
            bad++;
            fprintf(stderr, "mismatch: kind %d %dx%d f %d seed %d,%d value %d boundary %d conn %d stack %u\n",
                    kind, w, h, f, sx, sy, value, boundary, conn, (unsigned)sb);
        }
    }
    CHECK(bad == 0);
    CHECK(cases == 600);
}

/* The largest scenes, each stack size, each format, both fills. */
static void big_scenes(void)
{
    int kind, s, f, conn;
    for (kind = 0; kind < 3; kind++)
        for (s = 0; s < 5; s++)
            for (f = 0; f < 5; f++)
                for (conn = 4; conn <= 8; conn += 4) {
                    int sx, sy;
                    /* the quick run (valgrind, qemu): one format in turn
                     * per scene and stack size */
                    if (check_count(5) < 5 && f != (kind + s) % 5) continue;
                    if (kind == 0) scene_maze(MAXW - 1, MAXH - 1, 0);
                    else if (kind == 1) scene_maze(MAXW - 1, MAXH - 1, 6);
                    else scene_spiral(MAXW, MAXH, 1);
                    random_seed(MAXW - 1, MAXH - 1, &sx, &sy);
                    CHECK(run(f, MAXW, MAXH, NULL, sx, sy, 2, -1, conn, stacks[s]));
                    CHECK(run(f, MAXW, MAXH, NULL, sx, sy, 2, 1, conn, stacks[s]));
                    CHECK(run(f, MAXW, MAXH, NULL, sx, sy, 1, 1, conn, stacks[s]));
                }
}

static void clipped(void)
{
    int round;
    for (round = 0; round < 200; round++) {
        int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 40), sx, sy;
        rast_rect c;
        c.x0 = (int32_t)(rng() % 50) - 5;
        c.y0 = (int32_t)(rng() % 50) - 5;
        c.x1 = c.x0 + (int32_t)(rng() % 50);
        c.y1 = c.y0 + (int32_t)(rng() % 50);
        if (round & 1) scene_maze(w, h, 5);
        else scene_noise(w, h, 40, 2);
        random_seed(w, h, &sx, &sy);
        CHECK(run((int)(rng() % 5), w, h, &c, sx, sy, 2, (round & 2) ? 1 : -1, (round & 4) ? 8 : 4,
                  stacks[rng() % 5]));
    }
}

static void errors(void)
{
    unsigned char img[4][5], px = 9, bd = 1;
    rast_target t;
    size_t n;
    memset(img, 0, sizeof img);
    CHECK(rast_target_init(&t, img, 5, 4, 5, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_flood_fill(&t, 5, 0, &px, 4, stack_mem, 64) == RAST_E_ARG);
    CHECK(rast_flood_fill(&t, 0, -1, &px, 4, stack_mem, 64) == RAST_E_ARG);
    CHECK(rast_flood_fill(&t, 0, 0, &px, 5, stack_mem, 64) == RAST_E_ARG);
    CHECK(rast_flood_fill(&t, 0, 0, NULL, 4, stack_mem, 64) == RAST_E_NULL);
    CHECK(rast_flood_fill(NULL, 0, 0, &px, 4, stack_mem, 64) == RAST_E_NULL);
    CHECK(rast_boundary_fill(&t, 0, 0, &px, NULL, 8, stack_mem, 64) == RAST_E_NULL);
    CHECK(rast_flood_fill(&t, 0, 0, &px, 4, NULL, 64) == RAST_E_NULL);
    CHECK(rast_flood_fill(&t, 0, 0, &px, 4, (unsigned char *)stack_mem + 4, 32) == RAST_E_ALIGN);
    t.format = (rast_format)99;
    CHECK(rast_flood_fill(&t, 0, 0, &px, 4, stack_mem, 64) == RAST_E_FORMAT);
    t.format = RAST_FORMAT_GRAY8;
    {
        static const unsigned char zero[sizeof img] = {0};
        CHECK(memcmp(img, zero, sizeof img) == 0);
    }
    /* no-ops: the same value; a seed on the boundary; a seed outside the clip */
    img[2][2] = 1;
    CHECK(rast_flood_fill(&t, 0, 0, &img[0][0], 4, NULL, 0) == RAST_OK);
    CHECK(rast_boundary_fill(&t, 2, 2, &px, &bd, 4, NULL, 0) == RAST_OK && img[2][2] == 1);
    t.clip.x0 = 3;
    CHECK(rast_flood_fill(&t, 0, 0, &px, 4, NULL, 0) == RAST_OK && img[0][0] == 0);
    /* the clip: only its part of the region */
    CHECK(rast_flood_fill(&t, 4, 0, &px, 8, NULL, 0) == RAST_OK);
    CHECK(img[0][2] == 0 && img[0][3] == 9 && img[3][4] == 9 && img[2][2] == 1);
    CHECK(rast_seed_stack_size(10, 3, &n) == RAST_OK && n == 16 * (2 * 3 * 5 + 2));
    CHECK(rast_seed_stack_size(-1, 3, &n) == RAST_E_SIZE);
    CHECK(rast_seed_stack_size(1, 1, NULL) == RAST_E_NULL);
}

/* MONO1: two values, eight pixels a byte, MSB first; the fallback must be
 * exact where a filled pixel and one that was on before look the same.
 * Guard bits: the row's bits past the target and the bytes around it. */
static void mono1(void)
{
    static unsigned char mbuf[(MAXH + 2 * PAD) * (MAXW / 8 + 2 * PAD)], mbefore[sizeof mbuf];
    int round, bad = 0;
    for (round = 0; round < 400; round++) {
        int w = 1 + (int)(rng() % (MAXW - 1)), h = 1 + (int)(rng() % (MAXH - 1)), kind = round % 4;
        int stride = (w + 7) / 8 + 2, sx, sy, i, j, ok = 1, conn = (round & 4) ? 8 : 4;
        int value = (int)(rng() & 1), boundary = (round & 8) ? (int)(rng() & 1) : -1;
        unsigned char px = (unsigned char)(value ? 0x80 : 0), bd = (unsigned char)(boundary > 0 ? 3 : 0);
        size_t sb = stacks[rng() % 5];
        rast_target t;
        rast_rect c;
        unsigned char *base = mbuf + PAD * stride + 1;
        if (kind == 0) scene_noise(w, h, (int)(rng() % 100), 2);
        else if (kind == 1) scene_maze(w, h, 0);
        else if (kind == 2) scene_maze(w, h, 8);
        else scene_spiral(w, h, 1 + (int)(rng() % 2));
        random_seed(w, h, &sx, &sy);
        memset(mbuf, GUARD, sizeof mbuf);
        for (j = 0; j < h; j++)
            for (i = 0; i < w; i++) {
                unsigned char *b = base + j * stride + i / 8, m = (unsigned char)(0x80 >> (i % 8));
                *b = (unsigned char)(lab[j][i] ? (*b | m) : (*b & ~m));
            }
        memcpy(mbefore, mbuf, sizeof mbuf);
        CHECK(rast_target_init(&t, base, w, h, stride, RAST_FORMAT_MONO1) == RAST_OK);
        c = t.clip;
        if (boundary < 0) CHECK(rast_flood_fill(&t, sx, sy, &px, conn, stack_mem, sb) == RAST_OK);
        else CHECK(rast_boundary_fill(&t, sx, sy, &px, &bd, conn, stack_mem, sb) == RAST_OK);
        reference(w, h, &c, sx, sy, value, boundary, conn);
        for (j = 0; j < (int)sizeof mbuf; j++) {
            int row = j / stride - PAD, col8 = j % stride - 1;
            if (row >= 0 && row < h && col8 >= 0 && col8 * 8 < w) {
                for (i = col8 * 8; i < col8 * 8 + 8; i++) {
                    int bit = (mbuf[j] >> (7 - i % 8)) & 1, was = (mbefore[j] >> (7 - i % 8)) & 1;
                    if (i < w ? bit != (want[row][i] != 0) : bit != was) ok = 0;
                }
            } else if (mbuf[j] != mbefore[j]) {
                ok = 0;
            }
        }
        if (!ok) {
            bad++;
            fprintf(stderr, "mono1 mismatch: kind %d %dx%d seed %d,%d value %d boundary %d conn %d stack %u\n",
                    kind, w, h, sx, sy, value, boundary, conn, (unsigned)sb);
        }
    }
    CHECK(bad == 0);
}

int main(void)
{
    mono1();
    scenes();
    big_scenes();
    clipped();
    errors();
    return check_report("test_seedfill");
}
