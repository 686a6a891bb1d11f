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

/* ---- rings(obj, ndarray, dtypes): a polygon's rings in one pass ----------
 *
 * polygon_mask, Canvas.fill_polygon and polygon_coverage take rings as a
 * list of (N, 2) numpy arrays or as Python lists of (x, y) pairs.  Checking
 * and measuring a list of 1,409 rings in Python cost about a millisecond;
 * here it is one C loop.  Only the common shapes are taken, and None
 * answers anything else (the Python path then checks and names what is
 * wrong):
 *   - a list of exactly ndarray objects, each with ndim 2 and its dtype
 *     one of `dtypes`, none empty: (None, sizes); the caller concatenates
 *     them (numpy: one pass over the points, which also requires every
 *     ring to have 2 columns);
 *   - one ring, a list of (x, y) pairs (tuples or lists of two exact
 *     floats or ints): (points, None);
 *   - a list of such rings, none empty: (points, sizes).
 * points: a bytearray of native float64 (x, y); sizes: uint32 per ring.
 * An int is taken only when |v| <= 2^53 (then it is a double exactly, as
 * numpy's conversion gives it); bool is not an int here. */

#define SEQ_EXACT_INT 9007199254740992LL /* 2^53 */

/* "ndim" and "dtype", interned once (PyInit__seq): a name made afresh for
 * every lookup misses the type's attribute cache, which made the loop over
 * 1,409 arrays cost a millisecond. */
static PyObject *seq_ndim_name, *seq_dtype_name;

/* One number as the double numpy would make of it; 0 if it is not an
 * exact float or a small exact int. */
static int seq_coord(PyObject *v, double *out)
{
    if (PyFloat_CheckExact(v)) {
        *out = PyFloat_AsDouble(v);
        return 1;
    }
    if (PyLong_CheckExact(v)) {
        int over = 0;
        long long i = PyLong_AsLongLongAndOverflow(v, &over);
        if (over || i > SEQ_EXACT_INT || i < -SEQ_EXACT_INT) {
            PyErr_Clear();
            return 0;
        }
        *out = (double)i;
        return 1;
    }
    return 0;
}

/* An exact tuple or list of two numbers, read to out[0], out[1]. */
static int seq_pair(PyObject *p, double *out)
{
    if (PyTuple_CheckExact(p)) {
        return PyTuple_Size(p) == 2 && seq_coord(PyTuple_GetItem(p, 0), out) &&
               seq_coord(PyTuple_GetItem(p, 1), out + 1);
    }
    if (PyList_CheckExact(p)) {
        return PyList_Size(p) == 2 && seq_coord(PyList_GetItem(p, 0), out) &&
               seq_coord(PyList_GetItem(p, 1), out + 1);
    }
    return 0;
}

/* Is p a pair (a tuple or list of two items that are not sequences)? */
static int seq_is_pair_like(PyObject *p)
{
    PyObject *first;
    if (PyTuple_CheckExact(p)) {
        if (PyTuple_Size(p) != 2) return 0;
        first = PyTuple_GetItem(p, 0);
    } else if (PyList_CheckExact(p)) {
        if (PyList_Size(p) != 2) return 0;
        first = PyList_GetItem(p, 0);
    } else {
        return 0;
    }
    return PyFloat_CheckExact(first) || PyLong_CheckExact(first);
}

/* The items of an exact list or tuple (borrowed). */
static PyObject *seq_item(PyObject *s, Py_ssize_t i)
{
    return PyList_CheckExact(s) ? PyList_GetItem(s, i) : PyTuple_GetItem(s, i);
}

static Py_ssize_t seq_len(PyObject *s)
{
    if (PyList_CheckExact(s)) return PyList_Size(s);
    if (PyTuple_CheckExact(s)) return PyTuple_Size(s);
    return -1;
}

/* The arrays' form: each item exactly of type `ndarray`, ndim 2, a dtype
 * in `dtypes` (by identity), at least one row.  Their lengths to a new
 * bytearray, or NULL (no exception) if one is not of that form. */
static PyObject *seq_array_sizes(PyObject *rings, Py_ssize_t n, PyObject *ndarray, PyObject *dtypes)
{
    PyObject *sizes;
    uint32_t *sz;
    Py_ssize_t k, j, ndt = PyTuple_Size(dtypes);
    if (ndt < 0) {
        PyErr_Clear();
        return NULL;
    }
    sizes = PyByteArray_FromStringAndSize(NULL, n * (Py_ssize_t)sizeof(uint32_t));
    if (!sizes) return NULL;
    sz = (uint32_t *)(void *)PyByteArray_AsString(sizes);
    for (k = 0; k < n; k++) {
        PyObject *a = PyList_GetItem(rings, k), *dt, *nd;
        long ndim;
        Py_ssize_t len;
        int ok = 0;
        if ((PyObject *)Py_TYPE(a) != ndarray) goto no;
        nd = PyObject_GetAttr(a, seq_ndim_name);
        if (!nd) goto no;
        ndim = PyLong_AsLong(nd);
        Py_DECREF(nd);
        if (ndim != 2) goto no;
        dt = PyObject_GetAttr(a, seq_dtype_name);
        if (!dt) goto no;
        for (j = 0; j < ndt; j++) ok |= dt == PyTuple_GetItem(dtypes, j);
        Py_DECREF(dt);
        if (!ok) goto no;
        len = PyObject_Size(a);
        if (len < 1 || len > (Py_ssize_t)UINT32_MAX) goto no;
        sz[k] = (uint32_t)len;
    }
    return sizes;
no:
    PyErr_Clear();
    Py_DECREF(sizes);
    return NULL;
}

static PyObject *seq_rings(PyObject *self, PyObject *args)
{
    PyObject *rings, *ndarray, *dtypes, *first, *pts = NULL, *sizes = NULL, *res;
    Py_ssize_t n, k, j, npts = 0;
    double *p;
    uint32_t *sz = NULL;
    int one;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOO", &rings, &ndarray, &dtypes)) return NULL;
    if (!PyList_CheckExact(rings) || (n = PyList_Size(rings)) == 0) Py_RETURN_NONE;
    first = PyList_GetItem(rings, 0);
    if ((PyObject *)Py_TYPE(first) == ndarray) {
        sizes = seq_array_sizes(rings, n, ndarray, dtypes);
        if (!sizes) {
            if (PyErr_Occurred()) return NULL;
            Py_RETURN_NONE;
        }
        res = PyTuple_New(2);
        if (!res) {
            Py_DECREF(sizes);
            return NULL;
        }
        Py_INCREF(Py_None);
        PyTuple_SetItem(res, 0, Py_None);
        PyTuple_SetItem(res, 1, sizes);
        return res;
    }
    /* One ring of pairs, or a list of rings of pairs: count, then read. */
    one = seq_is_pair_like(first);
    if (one) {
        npts = n;
    } else {
        for (k = 0; k < n; k++) {
            Py_ssize_t m = seq_len(PyList_GetItem(rings, k));
            if (m < 1 || m > (Py_ssize_t)UINT32_MAX) Py_RETURN_NONE;
            npts += m;
        }
    }
    if (npts > (Py_ssize_t)UINT32_MAX) Py_RETURN_NONE;
    pts = PyByteArray_FromStringAndSize(NULL, npts * 2 * (Py_ssize_t)sizeof(double));
    if (!pts) return NULL;
    p = (double *)(void *)PyByteArray_AsString(pts);
    if (one) {
        for (k = 0; k < n; k++, p += 2)
            if (!seq_pair(PyList_GetItem(rings, k), p)) goto none;
    } else {
        sizes = PyByteArray_FromStringAndSize(NULL, n * (Py_ssize_t)sizeof(uint32_t));
        if (!sizes) goto fail;
        sz = (uint32_t *)(void *)PyByteArray_AsString(sizes);
        for (k = 0; k < n; k++) {
            PyObject *ring = PyList_GetItem(rings, k);
            Py_ssize_t m = seq_len(ring);
            for (j = 0; j < m; j++, p += 2)
                if (!seq_pair(seq_item(ring, j), p)) goto none;
            sz[k] = (uint32_t)m;
        }
    }
    res = PyTuple_New(2);
    if (!res) goto fail;
    if (!sizes) {
        Py_INCREF(Py_None);
        sizes = Py_None;
    }
    PyTuple_SetItem(res, 0, pts);
    PyTuple_SetItem(res, 1, sizes);
    return res;
none:
    Py_XDECREF(pts);
    Py_XDECREF(sizes);
    if (PyErr_Occurred()) return NULL;
    Py_RETURN_NONE;
fail:
    Py_XDECREF(pts);
    Py_XDECREF(sizes);
    return NULL;
}

static PyMethodDef seq_methods[] = {
    {"flat", seq_flat, METH_O,
     "flat(segmentations) -> (points, ring_sizes, rings_per_object) as bytearrays, or None"},
    {"rings", seq_rings, METH_VARARGS,
     "rings(rings, ndarray, dtypes) -> (points or None, ring_sizes or None) as bytearrays, or None"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef seq_module = {
    PyModuleDef_HEAD_INIT, "_seq", "COCO polygon lists read in one C pass.", -1, seq_methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__seq(void);
PyMODINIT_FUNC PyInit__seq(void)
{
    if (!seq_ndim_name) seq_ndim_name = PyUnicode_InternFromString("ndim");
    if (!seq_dtype_name) seq_dtype_name = PyUnicode_InternFromString("dtype");
    if (!seq_ndim_name || !seq_dtype_name) return NULL;
    return PyModule_Create(&seq_module);
}
