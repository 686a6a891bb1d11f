/*
 * seq.c - the module rastrum._seq: COCO polygon lists read in one C pass.
 *
 * A COCO polygon segmentation is a list of parts, each a flat Python list
 * [x0, y0, x1, y1, ...] of floats (ints now and then).  numpy converts such
 * a list at about 10 ns a number plus a microsecond a call; a batch of 100
 * objects spends more time there than drawing.  This module reads the
 * numbers with the C API instead, into the packed form the batch fillers
 * take.  It is its own extension module (not part of the cffi one) because
 * it takes Python objects; it uses the limited API only.
 *
 * It accepts the common shape only -- lists of lists of exact floats and
 * ints -- and answers None for anything else, so that the Python code
 * that checks input and names what is wrong (coco.rings) stays the one
 * place where input is judged; for what it accepts, the numbers are those
 * numpy's float64 conversion gives (the nearest double).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <stdint.h>
#include <string.h>

/* The parts of one segmentation: a list of lists, or one flat list (its
 * first item a number), which is one part.  Sets *flat. */
static int seq_parts(PyObject *seg, int *flat)
{
    PyObject *first;
    if (!PyList_CheckExact(seg)) return 0;
    *flat = 0;
    if (PyList_Size(seg) == 0) return 1;
    first = PyList_GetItem(seg, 0);
    *flat = PyFloat_CheckExact(first) || PyLong_CheckExact(first);
    return 1;
}

static int seq_number(PyObject *v)
{
    return PyFloat_CheckExact(v) || PyLong_CheckExact(v);
}

/* Pass one over a part: 1 if every item is a float or an int (bool is
 * not: it is a subclass, not exactly int). */
static int seq_check(PyObject *part)
{
    Py_ssize_t i, n;
    if (!PyList_CheckExact(part)) return 0;
    n = PyList_Size(part);
    for (i = 0; i < n; i++)
        if (!seq_number(PyList_GetItem(part, i))) return 0;
    return 1;
}

/* Pass two: the part's 2 m numbers as doubles at out (the odd last one,
 * if any, dropped, as pycocotools drops it).  -1 with an exception set
 * when an int is too large for a double. */
static int seq_read(PyObject *part, double *out, Py_ssize_t m)
{
    Py_ssize_t i;
    for (i = 0; i < 2 * m; i++) {
        PyObject *v = PyList_GetItem(part, i);
        double d = PyFloat_CheckExact(v) ? PyFloat_AsDouble(v) : PyLong_AsDouble(v);
        if (d == -1.0 && PyErr_Occurred()) return -1;
        out[i] = d;
    }
    return 0;
}

/* flat(segmentations) -> (points, ring_sizes, rings_per_object) or None.
 * points: a bytearray of native float64 (x, y) pairs; ring_sizes: uint32
 * per ring (parts of fewer than 2 numbers have no point and are left
 * out); rings_per_object: uint32 per segmentation. */
static PyObject *seq_flat(PyObject *self, PyObject *segs)
{
    Py_ssize_t nobj, k, j, npts = 0, nrings = 0;
    PyObject *pts = NULL, *sizes = NULL, *counts = NULL, *res;
    double *p;
    uint32_t *sz, *ct;
    (void)self;
    if (!PyList_CheckExact(segs)) Py_RETURN_NONE;
    nobj = PyList_Size(segs);
    for (k = 0; k < nobj; k++) {
        PyObject *seg = PyList_GetItem(segs, k);
        int flat = 0;
        if (!seq_parts(seg, &flat)) Py_RETURN_NONE;
        if (flat) {
            if (!seq_check(seg)) Py_RETURN_NONE;
            if (PyList_Size(seg) >= 2) npts += PyList_Size(seg) / 2, nrings++;
            continue;
        }
        for (j = 0; j < PyList_Size(seg); j++) {
            PyObject *part = PyList_GetItem(seg, j);
            if (!seq_check(part)) Py_RETURN_NONE;
            if (PyList_Size(part) >= 2) npts += PyList_Size(part) / 2, nrings++;
        }
    }
    if (npts > (Py_ssize_t)UINT32_MAX || nobj > (Py_ssize_t)UINT32_MAX) Py_RETURN_NONE;
    pts = PyByteArray_FromStringAndSize(NULL, npts * 2 * (Py_ssize_t)sizeof(double));
    sizes = PyByteArray_FromStringAndSize(NULL, nrings * (Py_ssize_t)sizeof(uint32_t));
    counts = PyByteArray_FromStringAndSize(NULL, nobj * (Py_ssize_t)sizeof(uint32_t));
    if (!pts || !sizes || !counts) goto fail;
    p = (double *)(void *)PyByteArray_AsString(pts);
    sz = (uint32_t *)(void *)PyByteArray_AsString(sizes);
    ct = (uint32_t *)(void *)PyByteArray_AsString(counts);
    for (k = 0; k < nobj; k++) {
        PyObject *seg = PyList_GetItem(segs, k);
        Py_ssize_t nparts;
        int flat = 0;
        uint32_t r = 0;
        seq_parts(seg, &flat);
        nparts = flat ? 1 : PyList_Size(seg);
        for (j = 0; j < nparts; j++) {
            PyObject *part = flat ? seg : PyList_GetItem(seg, j);
            Py_ssize_t m = PyList_Size(part) / 2;
            if (m == 0) continue;
            if (seq_read(part, p, m) < 0) goto fail;
            p += 2 * m;
            *sz++ = (uint32_t)m;
            r++;
        }
        ct[k] = r;
    }
    res = PyTuple_New(3);
    if (!res) goto fail;
    PyTuple_SetItem(res, 0, pts);
    PyTuple_SetItem(res, 1, sizes);
    PyTuple_SetItem(res, 2, counts);
    return res;
fail:
    Py_XDECREF(pts);
    Py_XDECREF(sizes);
    Py_XDECREF(counts);
    if (PyErr_ExceptionMatches(PyExc_OverflowError)) {
        PyErr_Clear(); /* a huge int: the Python path names it */
        Py_RETURN_NONE;
    }
    return NULL;
}

static PyMethodDef seq_methods[] = {
    {"flat", seq_flat, METH_O,
     "flat(segmentations) -> (points, ring_sizes, rings_per_object) as bytearrays, or None"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef seq_module = {
    PyModuleDef_HEAD_INIT, "_seq", "COCO polygon lists read in one C pass.", -1, seq_methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__seq(void);
PyMODINIT_FUNC PyInit__seq(void)
{
    return PyModule_Create(&seq_module);
}
