/*
 * glue.h - the binding's glue (the .c files of python/glue) compiled into a fuzz
 * target, as setup.py builds it into the extension: one translation unit,
 * the core linked as librastrum.a.  Include it instead of fuzz.h's core
 * headers alone (it defines RAST_STATIC_LINKING_ONLY for coco.c).
 */
#ifndef RAST_FUZZ_GLUE_H
#define RAST_FUZZ_GLUE_H
#define RAST_STATIC_LINKING_ONLY
/* fill.c's test hook calls into CPython; no interpreter here */
int PyGILState_Check(void);
int PyGILState_Check(void) { return 0; }
#include "../../python/glue/fill.c"
#include "../../python/glue/wide.c"
#include "../../python/glue/gdalline.c"
#include "../../python/glue/batch.c"
#include "../../python/glue/coco.c"
#include "../../python/glue/blend.c"
#include "../../python/glue/coverage.c"
#endif
