/*
 * fuzz_seq.c - the list parser rastrum._seq (python/ext/seq.c) on Python
 * objects built from the fuzz bytes, in an embedded interpreter: lists
 * nested to any depth (one of them holding itself now and then), floats of
 * any bits (NaN, infinities), small and huge ints, bools, None, strings,
 * complex numbers, tuples.  Oracle: a pure-Python reference of what
 * seq.flat answers (the same packed bytes, or None for anything but lists
 * of lists of exact floats and ints, or an int too large for a double),
 * run on the same objects; flat must never raise.  Built with the
 * interpreter's headers and library (the Makefile's FUZZ_PY flags).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "../../python/ext/seq.c"

#include <stdio.h>
#include <stdlib.h>

/* The interpreter's own allocations live until exit. */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "detect_leaks=0"; }

#define CHECK(c)                                                               \
    do {                                                                       \
        if (!(c)) {                                                            \
            fprintf(stderr, "%s:%d: oracle failed: %s\n", __FILE__, __LINE__, #c); \
            if (PyErr_Occurred()) PyErr_Print();                               \
            abort();                                                           \
        }                                                                      \
    } while (0)

static const char ref_src[] =
    "from array import array\n"
    "def ref(segs):\n"
    "    if type(segs) is not list: return None\n"
    "    objs = []\n"
    "    for seg in segs:\n"
    "        if type(seg) is not list: return None\n"
    "        flat = len(seg) > 0 and type(seg[0]) in (float, int)\n"
    "        parts = [seg] if flat else list(seg)\n"
    "        for p in parts:\n"
    "            if type(p) is not list: return None\n"
    "            if any(type(v) not in (float, int) for v in p): return None\n"
    "        objs.append(parts)\n"
    "    pts, sizes, counts = array('d'), array('I'), array('I')\n"
    "    for parts in objs:\n"
    "        r = 0\n"
    "        for p in parts:\n"
    "            m = len(p) // 2\n"
    "            if m == 0: continue\n"
    "            try:\n"
    "                pts.extend(float(v) for v in p[:2 * m])\n"
    "            except OverflowError:\n"
    "                return None\n"
    "            sizes.append(m)\n"
    "            r += 1\n"
    "        counts.append(r)\n"
    "    return (pts.tobytes(), sizes.tobytes(), counts.tobytes())\n";

static PyObject *ref_fn, *flat_fn;
static unsigned long runs;

typedef struct {
    const uint8_t *d;
    size_t n, at;
} src;

static unsigned next(src *s) { return s->at < s->n ? s->d[s->at++] : 0; }

/* An object from the bytes; lists are mostly lists of numbers. */
static PyObject *build(src *s, int depth, PyObject *self)
{
    unsigned op = next(s);
    switch (op % 16) {
    case 0: case 1: case 2: case 3: { /* a float, any bits now and then */
        double v;
        if (op & 0x80) {
            uint64_t b = 0;
            int i;
            for (i = 0; i < 8; i++) b = b << 8 | next(s);
            memcpy(&v, &b, sizeof v);
        } else {
            v = (double)(int)(next(s) | next(s) << 8) / 4.0 - 1000.0;
        }
        return PyFloat_FromDouble(v);
    }
    case 4: case 5: case 6: /* a small int */
        return PyLong_FromLong((long)(signed char)next(s));
    case 7: { /* a huge int: +-2^k + j, k up to 1100 */
        PyObject *one = PyLong_FromLong(op & 0x40 ? -1 : 1), *sh = PyLong_FromLong((long)(next(s) * 4 + next(s) % 4));
        PyObject *v = one && sh ? PyNumber_Lshift(one, sh) : NULL;
        Py_XDECREF(one);
        Py_XDECREF(sh);
        return v;
    }
    case 8:
        return PyBool_FromLong(op & 0x20);
    case 9: {
        switch (next(s) % 5) {
        case 0: Py_RETURN_NONE;
        case 1: return PyUnicode_FromString("1.0");
        case 2: return PyComplex_FromDoubles(1.0, (double)next(s));
        case 3: return Py_BuildValue("(dd)", 1.0, 2.0);
        default:
            if (self) {
                Py_INCREF(self);
                return self; /* a list that holds itself */
            }
            Py_RETURN_NONE;
        }
    }
    default: { /* a list */
        Py_ssize_t n = (Py_ssize_t)(next(s) % 9), i;
        PyObject *l;
        if (depth > 4) return PyFloat_FromDouble(0.5);
        l = PyList_New(0);
        if (!l) return NULL;
        for (i = 0; i < n && s->at < s->n; i++) {
            PyObject *v = build(s, depth + 1, l);
            if (!v || PyList_Append(l, v) < 0) {
                Py_XDECREF(v);
                Py_DECREF(l);
                return NULL;
            }
            Py_DECREF(v);
        }
        return l;
    }
    }
}

static void init(void)
{
    PyObject *mod, *glb;
    PyPreConfig pre;
    /* every object from malloc, so that ASan sees each buffer's ends */
    PyPreConfig_InitPythonConfig(&pre);
    pre.allocator = PYMEM_ALLOCATOR_MALLOC;
    CHECK(!PyStatus_Exception(Py_PreInitialize(&pre)));
    Py_InitializeEx(0);
    glb = PyDict_New();
    CHECK(glb && PyDict_SetItemString(glb, "__builtins__", PyEval_GetBuiltins()) == 0);
    mod = PyRun_String(ref_src, Py_file_input, glb, glb);
    CHECK(mod);
    Py_DECREF(mod);
    ref_fn = PyDict_GetItemString(glb, "ref");
    CHECK(ref_fn);
    Py_INCREF(ref_fn);
    mod = PyInit__seq();
    CHECK(mod);
    flat_fn = PyObject_GetAttrString(mod, "flat");
    CHECK(flat_fn);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    src s = {data, size, 0};
    PyObject *segs, *got, *want;
    if (!flat_fn) init();
    segs = build(&s, 0, NULL);
    CHECK(segs);
    got = PyObject_CallFunctionObjArgs(flat_fn, segs, NULL);
    CHECK(got); /* never an exception */
    want = PyObject_CallFunctionObjArgs(ref_fn, segs, NULL);
    CHECK(want);
    if (want == Py_None) {
        CHECK(got == Py_None);
    } else {
        int eq;
        CHECK(got != Py_None && PyTuple_Check(got) && PyTuple_Size(got) == 3);
        eq = PyObject_RichCompareBool(got, want, Py_EQ); /* bytearray == bytes, item by item */
        CHECK(eq == 1);
    }
    Py_DECREF(got);
    Py_DECREF(want);
    /* break the self-references so that the lists are freed */
    if (PyList_Check(segs)) PyList_SetSlice(segs, 0, PyList_Size(segs), NULL);
    Py_DECREF(segs);
    if (++runs % 256 == 0) PyGC_Collect();
    return 0;
}
