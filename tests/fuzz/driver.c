/*
 * driver.c - runs a fuzz target without libFuzzer: each argument is a file
 * or a directory of files (a corpus), each file one input to
 * LLVMFuzzerTestOneInput.  An oracle failure aborts; otherwise it prints
 * the count of inputs run (make fuzz-regress).  As lz4's
 * ossfuzz/standaloneengine.c.
 */
#define _POSIX_C_SOURCE 200809L /* opendir, readdir under -std=c99 */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static unsigned char buf[1 << 20];

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    size_t n;
    if (!f) return 0;
    n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    LLVMFuzzerTestOneInput(buf, n);
    return 1;
}

int main(int argc, char **argv)
{
    long runs = 0;
    int i;
    for (i = 1; i < argc; i++) {
        DIR *d = opendir(argv[i]);
        if (!d) {
            if (!run_file(argv[i])) {
                fprintf(stderr, "%s: cannot read\n", argv[i]);
                return 1;
            }
            runs++;
            continue;
        }
        for (;;) {
            struct dirent *e = readdir(d);
            char path[4096];
            if (!e) break;
            if (e->d_name[0] == '.') continue;
            snprintf(path, sizeof path, "%s/%s", argv[i], e->d_name);
            runs += run_file(path);
        }
        closedir(d);
    }
    printf("%s: %ld passed, 0 failed\n", argc > 0 ? argv[0] : "fuzz", runs);
    return 0;
}
