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
#include <stdlib.h>
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

/* ---- rings(obj, ndarray): a polygon's rings in one pass ------------------
 *
 * polygon_mask, Canvas.fill_polygon and polygon_coverage take rings as a
 * list of (N, 2) numpy arrays or as Python lists of (x, y) pairs.  Checking
 * and measuring a list of 1,409 rings in Python cost about a millisecond,
 * and numpy's concatenation of the arrays 3.2 M instructions (2,300 an
 * array); here it is one C loop.  Only the common shapes are taken, and
 * None answers anything else (the Python path then checks and names what
 * is wrong):
 *   - a list of exactly ndarray objects, each of shape (N >= 1, 2) and of
 *     numpy's float64 or int32 dtype (`dtypes`, seq_dtype_is; any strides):
 *     (points, sizes);
 *   - one ring, a list of (x, y) pairs (tuples or lists of two exact
 *     floats or ints): (points, None);
 *   - a list of such rings, none empty: (points, sizes).
 * points: a bytearray of native float64 (x, y); sizes: uint32 per ring.
 * An int is taken only when |v| <= 2^53 (then it is a double exactly, as
 * numpy's conversion gives it); bool is not an int here.
 *
 * The limited API of Python 3.9 (this module is abi3) has no buffer
 * protocol; an array's memory is read through numpy's array interface
 * instead, the capsule `__array_struct__` holding a PyArrayInterface
 * (numpy's documentation, "The array interface protocol"): its kind,
 * item size, byte order, shape, strides and data pointer in one C struct,
 * at a third of numpy.concatenate's cost per array (most of it numpy's
 * malloc and free of that struct).  Quicker still, the array object's own
 * head, the fields numpy's C API reads inline (PyArray_DATA, PyArray_NDIM,
 * PyArray_DIMS, PyArray_STRIDES, PyArray_DESCR, PyArray_FLAGS: a layout
 * numpy keeps for the extensions built against any of its versions): a
 * few loads an array.  That layout is trusted only once it has been seen
 * to agree, field by field, with what __array_struct__ says of an array
 * in this process (seq_head_ok); else every array takes the capsule. */

#define SEQ_EXACT_INT 9007199254740992LL /* 2^53 */

/* numpy's PyArrayInterface (numpy/ndarraytypes.h), the capsule's pointer,
 * and its flags this module reads (fixed by the protocol, version 3). */
typedef struct {
    int two; /* 2: the struct's version */
    int nd;
    char typekind;
    int itemsize;
    int flags;
    Py_intptr_t *shape;
    Py_intptr_t *strides;
    void *data;
    PyObject *descr;
} seq_array_interface;
#define SEQ_ARRAY_ALIGNED 0x100
#define SEQ_ARRAY_NOTSWAPPED 0x200

/* The head of numpy's array object (PyArrayObject_fields in
 * numpy/ndarraytypes.h, numpy 1.x and 2.x alike). */
typedef struct {
    PyObject ob_base;
    char *data;
    int nd;
    Py_intptr_t *dimensions;
    Py_intptr_t *strides;
    PyObject *base;
    PyObject *descr;
    int flags;
} seq_array_head;

/* Whether seq_array_head is numpy's layout in this process: -1 not yet
 * known, 1 seen to agree with __array_struct__, 0 not (or turned off by
 * _seq.use_head(False), which the tests use to run the capsule path). */
static int seq_head_ok = -1;

/* "__array_struct__", interned once (PyInit__seq): a name made afresh for
 * every lookup misses the type's attribute cache. */
static PyObject *seq_struct_name, *seq_dtype_name;

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

/* m rows of (x, y) from `row` (row stride s0, column stride s1), float64
 * (f64 != 0) or int32, to out[0 .. 2 m) as float64. */
static void seq_copy(const char *row, Py_intptr_t s0, Py_intptr_t s1, int f64, Py_ssize_t m, double *out)
{
    Py_ssize_t i;
    if (f64 && s0 == 16 && s1 == 8) {
        memcpy(out, row, (size_t)m * 2 * sizeof(double));
    } else if (f64) {
        for (i = 0; i < m; i++, row += s0, out += 2) {
            out[0] = *(const double *)(const void *)row;
            out[1] = *(const double *)(const void *)(row + s1);
        }
    } else {
        for (i = 0; i < m; i++, row += s0, out += 2) {
            out[0] = (double)*(const int32_t *)(const void *)row;
            out[1] = (double)*(const int32_t *)(const void *)(row + s1);
        }
    }
}

/* One array's points through __array_struct__: m rows of an (m, 2) array
 * of native float64 or int32 to out; 0 if `a` is not of that form (no
 * exception set). */
static int seq_array_read(PyObject *a, Py_ssize_t m, double *out)
{
    PyObject *cap = PyObject_GetAttr(a, seq_struct_name);
    const seq_array_interface *ai;
    int ok = 0;
    if (!cap) {
        PyErr_Clear();
        return 0;
    }
    ai = (const seq_array_interface *)PyCapsule_GetPointer(cap, NULL);
    if (!ai) {
        PyErr_Clear();
    } else if (ai->two == 2 && ai->nd == 2 && ai->shape[0] == m && ai->shape[1] == 2 &&
               (ai->flags & SEQ_ARRAY_NOTSWAPPED) && (ai->flags & SEQ_ARRAY_ALIGNED)) {
        if (ai->typekind == 'f' && ai->itemsize == 8) ok = 1;
        if (ai->typekind == 'i' && ai->itemsize == 4) ok = 2;
        if (ok) seq_copy((const char *)ai->data, ai->strides[0], ai->strides[1], ok == 1, m, out);
    }
    Py_DECREF(cap);
    return ok != 0;
}

/* Is an array's dtype `descr` the dtype `want` (numpy's native float64
 * or int32)?  By identity first (the usual case: one pointer compare);
 * else by numpy's own equality, which an equal dtype made apart passes:
 * an array unpickled carries a dtype object of its own (equal to
 * numpy.dtype(numpy.float64), not it), which the identity alone sent
 * polygon_mask's rings the slow way. */
static int seq_dtype_is(PyObject *descr, PyObject *want)
{
    int eq;
    if (descr == want) return 1;
    eq = PyObject_RichCompareBool(descr, want, Py_EQ);
    if (eq < 0) {
        PyErr_Clear();
        return 0;
    }
    return eq;
}

/* Does seq_array_head read `a` as __array_struct__ and .dtype describe
 * it?  The pointers are compared first (data, dtype), the dimensions
 * read only once they agree. */
static int seq_head_check(PyObject *a)
{
    const seq_array_head *h = (const seq_array_head *)(const void *)a;
    PyObject *cap = PyObject_GetAttr(a, seq_struct_name), *dt = PyObject_GetAttr(a, seq_dtype_name);
    const seq_array_interface *ai = cap ? (const seq_array_interface *)PyCapsule_GetPointer(cap, NULL) : NULL;
    int ok = 0, j;
    if (ai && dt && ai->two == 2 && (void *)h->data == ai->data && h->descr == dt && h->nd == ai->nd &&
        ((h->flags & SEQ_ARRAY_ALIGNED) == (ai->flags & SEQ_ARRAY_ALIGNED))) {
        ok = 1;
        for (j = 0; j < ai->nd; j++)
            ok &= h->dimensions[j] == ai->shape[j] && h->strides[j] == ai->strides[j];
    }
    PyErr_Clear();
    Py_XDECREF(cap);
    Py_XDECREF(dt);
    return ok;
}

/* One array's points through its head: as seq_array_read, the dtype one
 * of `dtypes` by identity (numpy's float64 and int32: native order). */
static int seq_head_read(PyObject *a, Py_ssize_t m, PyObject *f64, PyObject *i32, double *out)
{
    const seq_array_head *h = (const seq_array_head *)(const void *)a;
    int f;
    if (h->nd != 2 || h->dimensions[0] != m || h->dimensions[1] != 2 || !(h->flags & SEQ_ARRAY_ALIGNED))
        return 0;
    f = h->descr == f64;
    if (!f && h->descr != i32) { /* (the identities first: the usual case) */
        f = seq_dtype_is(h->descr, f64);
        if (!f && !seq_dtype_is(h->descr, i32)) return 0;
    }
    seq_copy(h->data, h->strides[0], h->strides[1], f, m, out);
    return 1;
}

/* A new buffer of n bytes for seq_rings' results and its memory: a
 * bytearray, or (as_bytes) a bytes object, which a cffi call takes as a
 * char * with no ffi.from_buffer made of it (polygon_mask's rings: the
 * two were ~0.8 us of a glyph's 16 us call).  Written only before it is
 * handed out. */
static PyObject *seq_buf_new(Py_ssize_t n, int as_bytes)
{
    return as_bytes ? PyBytes_FromStringAndSize(NULL, n) : PyByteArray_FromStringAndSize(NULL, n);
}

static char *seq_buf(PyObject *b, int as_bytes)
{
    return as_bytes ? PyBytes_AsString(b) : PyByteArray_AsString(b);
}

/* The arrays' form: each item exactly of type `ndarray`, of shape (m >= 1,
 * 2), native float64 or int32 (`dtypes`: numpy's (float64, int32)):
 * (points, sizes) as new bytearrays (as_bytes: bytes) in *pts, *sizes, 1;
 * or 0 (nothing made, no exception) if one is not of that form; -1 with
 * an exception (no memory). */
static int seq_arrays(PyObject *rings, Py_ssize_t n, PyObject *ndarray, PyObject *dtypes, PyObject **pts,
                      PyObject **sizes, int as_bytes)
{
    PyObject *f64, *i32;
    Py_ssize_t k, m, npts = 0;
    uint32_t *sz;
    double *p;
    *pts = *sizes = NULL;
    if (PyTuple_Size(dtypes) != 2) {
        PyErr_Clear();
        return 0;
    }
    f64 = PyTuple_GetItem(dtypes, 0);
    i32 = PyTuple_GetItem(dtypes, 1);
    if (seq_head_ok < 0) seq_head_ok = seq_head_check(PyList_GetItem(rings, 0));
    *sizes = seq_buf_new(n * (Py_ssize_t)sizeof(uint32_t), as_bytes);
    if (!*sizes) return -1;
    sz = (uint32_t *)(void *)seq_buf(*sizes, as_bytes);
    for (k = 0; k < n; k++) { /* the lengths (len(): no attribute lookup) */
        PyObject *a = PyList_GetItem(rings, k);
        if ((PyObject *)Py_TYPE(a) != ndarray) goto no;
        m = PyObject_Size(a); /* a 0-d array raises: not a ring */
        if (m < 1 || m > (Py_ssize_t)UINT32_MAX) goto no;
        sz[k] = (uint32_t)m;
        npts += m;
        if (npts > (Py_ssize_t)UINT32_MAX) goto no;
    }
    *pts = seq_buf_new(npts * 2 * (Py_ssize_t)sizeof(double), as_bytes);
    if (!*pts) {
        Py_CLEAR(*sizes);
        return -1;
    }
    p = (double *)(void *)seq_buf(*pts, as_bytes);
    for (k = 0; k < n; k++) {
        m = (Py_ssize_t)sz[k];
        PyObject *a = PyList_GetItem(rings, k);
        if (!(seq_head_ok > 0 ? seq_head_read(a, m, f64, i32, p) : seq_array_read(a, m, p))) goto no;
        p += 2 * m;
    }
    return 1;
no:
    PyErr_Clear();
    Py_CLEAR(*pts);
    Py_CLEAR(*sizes);
    return 0;
}

static PyObject *seq_rings(PyObject *self, PyObject *args)
{
    PyObject *rings, *ndarray, *dtypes, *first, *pts = NULL, *sizes = NULL, *res;
    Py_ssize_t n, k, j, npts = 0;
    double *p;
    uint32_t *sz = NULL;
    int one, as_bytes = 0;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOO|i", &rings, &ndarray, &dtypes, &as_bytes)) return NULL;
    if (!PyList_CheckExact(rings) || (n = PyList_Size(rings)) == 0) Py_RETURN_NONE;
    first = PyList_GetItem(rings, 0);
    if ((PyObject *)Py_TYPE(first) == ndarray) {
        int got = seq_arrays(rings, n, ndarray, dtypes, &pts, &sizes, as_bytes);
        if (got < 0) return NULL;
        if (!got) Py_RETURN_NONE;
        goto done;
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
    pts = seq_buf_new(npts * 2 * (Py_ssize_t)sizeof(double), as_bytes);
    if (!pts) return NULL;
    p = (double *)(void *)seq_buf(pts, as_bytes);
    if (one) {
        for (k = 0; k < n; k++, p += 2)
            if (!seq_pair(PyList_GetItem(rings, k), p)) goto none;
    } else {
        sizes = seq_buf_new(n * (Py_ssize_t)sizeof(uint32_t), as_bytes);
        if (!sizes) goto fail;
        sz = (uint32_t *)(void *)seq_buf(sizes, as_bytes);
        for (k = 0; k < n; k++) {
            PyObject *ring = PyList_GetItem(rings, k);
            Py_ssize_t m = seq_len(ring);
            for (j = 0; j < m; j++, p += 2)
                if (!seq_pair(seq_item(ring, j), p)) goto none;
            sz[k] = (uint32_t)m;
        }
    }
done:
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

/* ring_ptrs(rings, ndarray, float64): polygon_mask's list of rings as
 * their own memory, for the glue to snap each ring straight from it
 * (rastpy_mask_rings) instead of copying every point into one buffer
 * first (a paragraph of text: 541 KB written and read again, ~8% of its
 * call, issue 33).  Each item exactly of type `ndarray`, C-contiguous
 * (m >= 1, 2) native float64 (`float64`, seq_dtype_is), aligned, read
 * through its head (seq_head_ok; else None, and the caller packs):
 * (addresses, sizes, points, rings as a tuple) -- the rings' data
 * addresses and their sizes as bytes objects (a cffi call takes each as
 * a char *), the total of the sizes, and a tuple holding every array
 * for as long as the caller holds it (so that no array is freed while
 * the call, which runs without the GIL, reads it); None otherwise. */
static PyObject *seq_ring_ptrs(PyObject *self, PyObject *args)
{
    PyObject *rings, *ndarray, *f64, *ptrs = NULL, *sizes = NULL, *keep = NULL;
    Py_ssize_t n, k, npts = 0;
    const char **pp;
    uint32_t *sz;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOO", &rings, &ndarray, &f64)) return NULL;
    if (!PyList_CheckExact(rings) || (n = PyList_Size(rings)) == 0 ||
        (PyObject *)Py_TYPE(PyList_GetItem(rings, 0)) != ndarray)
        Py_RETURN_NONE;
    if (seq_head_ok < 0) seq_head_ok = seq_head_check(PyList_GetItem(rings, 0));
    if (seq_head_ok <= 0) Py_RETURN_NONE;
    keep = PyList_AsTuple(rings); /* (the arrays, as this call sees them) */
    ptrs = PyBytes_FromStringAndSize(NULL, n * (Py_ssize_t)sizeof(char *));
    sizes = PyBytes_FromStringAndSize(NULL, n * (Py_ssize_t)sizeof(uint32_t));
    if (!keep || !ptrs || !sizes) goto fail;
    pp = (const char **)(void *)PyBytes_AsString(ptrs);
    sz = (uint32_t *)(void *)PyBytes_AsString(sizes);
    for (k = 0; k < n; k++) {
        PyObject *a = PyTuple_GetItem(keep, k);
        const seq_array_head *h = (const seq_array_head *)(const void *)a;
        if ((PyObject *)Py_TYPE(a) != ndarray || h->nd != 2 || h->dimensions[1] != 2 ||
            h->dimensions[0] < 1 || h->dimensions[0] > (Py_ssize_t)UINT32_MAX || h->strides[0] != 16 ||
            h->strides[1] != 8 || !(h->flags & SEQ_ARRAY_ALIGNED) || !seq_dtype_is(h->descr, f64))
            goto none;
        pp[k] = h->data;
        sz[k] = (uint32_t)h->dimensions[0];
        npts += h->dimensions[0];
        if (npts > (Py_ssize_t)UINT32_MAX) goto none;
    }
    return Py_BuildValue("(NNnN)", ptrs, sizes, npts, keep);
none:
    Py_DECREF(keep);
    Py_DECREF(ptrs);
    Py_DECREF(sizes);
    Py_RETURN_NONE;
fail:
    Py_XDECREF(keep);
    Py_XDECREF(ptrs);
    Py_XDECREF(sizes);
    return NULL;
}

/* The calls of every small fill (fill, coverage) take their arguments as
 * a C array (METH_FASTCALL) where the running Python's stable ABI has it:
 * no tuple made, filled, unpacked and freed (~240 instructions of a
 * six-argument call, a third of what the call cost besides the fill).
 * The flag (0x0080) and the function's form are the stable ABI's from
 * Python 3.10; this module names 3.9 (setup.py), whose headers do not
 * define it, so PyInit__seq turns it on only when the running Python is
 * 3.10 or later, and 3.9 keeps the tuple form (seq_unpack's).  Both
 * forms run the same code and say the same things. */
#define SEQ_METH_FASTCALL 0x0080
typedef PyObject *(*seq_fast_fn)(PyObject *self, PyObject *const *args, Py_ssize_t nargs);

/* 1 when a call of `name` may take nargs arguments, else 0 with
 * PyArg_UnpackTuple's TypeError. */
static int seq_nargs(const char *name, Py_ssize_t lo, Py_ssize_t hi, Py_ssize_t nargs)
{
    if (nargs >= lo && nargs <= hi) return 1;
    if (lo == hi)
        PyErr_Format(PyExc_TypeError, "%s expected %s%zd argument%s, got %zd", name, "", lo, lo == 1 ? "" : "s",
                     nargs);
    else
        PyErr_Format(PyExc_TypeError, "%s expected %s%zd argument%s, got %zd", name,
                     nargs < lo ? "at least " : "at most ", nargs < lo ? lo : hi,
                     (nargs < lo ? lo : hi) == 1 ? "" : "s", nargs);
    return 0;
}

/* The tuple form: args's items to a[] (borrowed), their number checked. */
static int seq_unpack(const char *name, Py_ssize_t lo, Py_ssize_t hi, PyObject *args, PyObject **a)
{
    Py_ssize_t n = PyTuple_Size(args), k;
    if (!seq_nargs(name, lo, hi, n)) return 0;
    for (k = 0; k < n; k++) a[k] = PyTuple_GetItem(args, k);
    return 1;
}

/* Is the running Python 3.10 or later (Py_GetVersion: "3.11.7 (main, ...")? */
static int seq_runtime_fastcall(void)
{
    const char *v = Py_GetVersion();
    char *end;
    long major = strtol(v, &end, 10), minor = *end == '.' ? strtol(end + 1, NULL, 10) : 0;
    return major > 3 || (major == 3 && minor >= 10);
}

/* Canvas.fill_polygon's common call, whole in C (docs/api.md): one ring
 * of 3 points or more -- an exact ndarray, C-contiguous aligned native
 * float64 (n, 2), read through its head; or an exact list of (x, y)
 * pairs -- filled through the cffi module's rastpy_fill_ring (binary) or
 * rastpy_fill_polygon_aa (aa=...), whose addresses fill_setup gives (a
 * module of its own: this one takes Python objects, that one does not). */
typedef long (*seq_fill_fn)(const void *target, const double *xy, uint32_t n, const void *opts,
                            const void *pixel);
/* rastpy_scratch (python/glue/coverage.h): scratch lent to the aa call. */
typedef struct {
    void *buf;
    size_t size;
    size_t want;
} seq_scratch;
typedef long (*seq_fill_aa_fn)(const void *target, const double *xy, uint32_t n, const uint32_t *ring_sizes,
                               uint32_t nrings, const void *opts, const void *pixel, seq_scratch *sc);
static seq_fill_fn seq_fill;
static seq_fill_aa_fn seq_fill_aa;
static const void *seq_fill_opts;
static PyObject *seq_ndarray, *seq_f64;
/* {rule: {aa: options address}} for keyword calls (fill_setup), and the
 * keyword names, interned. */
static PyObject *seq_kw_table, *seq_rule_name, *seq_aa_name, *seq_evenodd;
/* The aa call's scratch, kept between calls as _coverage._lent keeps its
 * own (a block taken and freed on every call can go back to the system
 * and fault in again), up to SEQ_SCRATCH_KEEP bytes.  The GIL is held
 * through the call: one block serves every thread. */
static seq_scratch seq_sc;
#define SEQ_SCRATCH_KEEP ((size_t)32 << 20)
#define SEQ_ARRAY_WRITEABLE 0x400
#define SEQ_STACK_POINTS 64

/* The last rule and aa objects seq_table_opts found, held, and what it
 * found for them: a loop of calls passes the very same objects each time
 * (its code's constants), and the table's two lookups cost more than the
 * rest of the call's checks (~350 instructions of a call: a method name
 * the table holds as another str object of the same value is compared by
 * value).  Held, a cached object cannot be freed and another one made at
 * its address; str is immutable: the same objects, the same options.
 * fill_setup (a new table) forgets it. */
static PyObject *seq_last_rule, *seq_last_method;
static const void *seq_last_opts;
static int seq_last_aa;

/* After a call that lent seq_sc: keep a block as large as it wanted
 * (within SEQ_SCRATCH_KEEP) for the next. */
static void seq_keep_scratch(void)
{
    if (seq_sc.size < seq_sc.want && seq_sc.want <= SEQ_SCRATCH_KEEP) {
        void *grown = malloc(seq_sc.want); /* 16-byte aligned, as the glue wants */
        if (grown) {
            free(seq_sc.buf);
            seq_sc.buf = grown;
            seq_sc.size = seq_sc.want;
        }
    }
}

static void seq_forget_last(void)
{
    Py_CLEAR(seq_last_rule);
    Py_CLEAR(seq_last_method);
    seq_last_opts = NULL;
}

static void *seq_address(PyObject *v)
{
    void *a = PyLong_AsVoidPtr(v);
    if (!a && !PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "fill_setup: a NULL address");
    return a;
}

/* fill_setup(rastpy_fill_ring address, default rast_fill_opts address,
 * numpy.ndarray, numpy's float64 dtype[, rastpy_fill_polygon_aa address,
 * {rule: {aa: options address}}]) -> None.  The table's addresses are of
 * a rast_fill_opts (aa None) or a rast_coverage_opts, the options of a
 * call whose keywords are only rule and aa, and must outlive the module's
 * use (the caller keeps them). */
static PyObject *seq_fill_setup(PyObject *self, PyObject *args)
{
    PyObject *fn, *opts, *nd, *f64, *fn_aa = NULL, *table = NULL;
    void *f, *fa = NULL;
    (void)self;
    if (!PyArg_UnpackTuple(args, "fill_setup", 4, 6, &fn, &opts, &nd, &f64, &fn_aa, &table)) return NULL;
    f = seq_address(fn);
    if (!f) return NULL;
    seq_fill_opts = seq_address(opts);
    if (!seq_fill_opts) return NULL;
    if (fn_aa && !(fa = seq_address(fn_aa))) return NULL;
    if (table && !PyDict_CheckExact(table)) {
        PyErr_SetString(PyExc_TypeError, "fill_setup: the table is a dict");
        return NULL;
    }
    memcpy(&seq_fill, &f, sizeof f); /* an object pointer to a function pointer (POSIX) */
    memcpy(&seq_fill_aa, &fa, sizeof fa);
    Py_XINCREF(nd);
    Py_XINCREF(f64);
    Py_XINCREF(table);
    Py_XDECREF(seq_ndarray);
    Py_XDECREF(seq_f64);
    Py_XDECREF(seq_kw_table);
    seq_forget_last();
    seq_ndarray = nd;
    seq_f64 = f64;
    seq_kw_table = table;
    Py_RETURN_NONE;
}

static int seq_is(PyObject *key, PyObject *name)
{
    return key == name || (PyUnicode_CheckExact(key) && PyUnicode_Compare(key, name) == 0);
}

/* The options of rule (an exact str) and aa (None or an exact str) found
 * in the table: the address, *aa set when it is a coverage method; NULL
 * (no exception) for anything else. */
static const void *seq_table_opts(PyObject *rule, PyObject *method, int *aa)
{
    PyObject *row, *addr;
    const void *a;
    if (rule == seq_last_rule && method == seq_last_method && seq_last_opts) {
        *aa = seq_last_aa;
        return seq_last_opts;
    }
    if (!PyUnicode_CheckExact(rule) || (method != Py_None && !PyUnicode_CheckExact(method)) || !seq_kw_table ||
        !(row = PyDict_GetItem(seq_kw_table, rule)) || !PyDict_CheckExact(row) ||
        !(addr = PyDict_GetItem(row, method)))
        return NULL;
    a = PyLong_AsVoidPtr(addr);
    if (!a) {
        PyErr_Clear();
        return NULL;
    }
    *aa = method != Py_None;
    Py_INCREF(rule);
    Py_INCREF(method);
    seq_forget_last();
    seq_last_rule = rule;
    seq_last_method = method;
    seq_last_opts = a;
    seq_last_aa = *aa;
    return a;
}

/* The options of a keyword dict kw of only rule= and aa= (seq_table_opts). */
static const void *seq_kw_opts(PyObject *kw, int *aa)
{
    PyObject *key, *value, *rule = seq_evenodd, *method = Py_None;
    Py_ssize_t pos = 0;
    while (PyDict_Next(kw, &pos, &key, &value)) {
        if (seq_is(key, seq_rule_name))
            rule = value;
        else if (seq_is(key, seq_aa_name))
            method = value;
        else
            return NULL;
    }
    return seq_table_opts(rule, method, aa);
}

/* fill(q, target, rings, color[, opts]) -> bool: True when the ring was
 * filled.  q is the canvas's remembered call, (target, color, their
 * addresses -- a bytes of two uintptr_t, the target's and the pixel's:
 * two copies out of one object, where two ints' PyLong_AsVoidPtr and
 * their lookups were ~110 instructions of a call (issue 33) --, None,
 * array, pixel, aa allowed): it holds only for
 * the very target and colour objects given, and the canvas's array still
 * writable.  opts: None or an empty dict (the default options), the
 * address of a rast_fill_opts, or the call's keyword dict (seq_kw_opts);
 * or, as fill(q, target, rings, color, rule, aa), the call's rule= and
 * aa= themselves (seq_table_opts: no dict made for them).
 * False (nothing written, no exception) for anything else or an error
 * status: the caller's general path then checks and says what is wrong. */
static PyObject *seq_fill_do(PyObject *const *a, Py_ssize_t nargs)
{
    PyObject *q = a[0], *target = a[1], *rings = a[2], *color = a[3], *opt = nargs > 4 ? a[4] : NULL,
             *method = nargs > 5 ? a[5] : NULL, *arr, *addr;
    const seq_array_head *h;
    uintptr_t ptr[2];
    double stack[2 * SEQ_STACK_POINTS], *xy = NULL, *heap = NULL;
    const void *t, *pix, *opts = seq_fill_opts;
    Py_ssize_t n = 0, k;
    long st;
    int aa = 0;
    if (!seq_fill || !PyTuple_CheckExact(q) || PyTuple_Size(q) != 7 || target == Py_None ||
        PyTuple_GetItem(q, 0) != target || PyTuple_GetItem(q, 1) != color)
        Py_RETURN_FALSE;
    arr = PyTuple_GetItem(q, 4);
    if ((PyObject *)Py_TYPE(arr) != seq_ndarray) Py_RETURN_FALSE;
    if (seq_head_ok < 0) seq_head_ok = seq_head_check(arr);
    if (seq_head_ok <= 0 ||
        !(((const seq_array_head *)(const void *)arr)->flags & SEQ_ARRAY_WRITEABLE))
        Py_RETURN_FALSE;
    if (method == Py_None && opt == seq_evenodd) {
        /* rule= and aa= at their defaults (the interned "evenodd"): the
         * default options, without the table's two lookups */
    } else if (method || (opt && PyDict_CheckExact(opt) && PyDict_Size(opt) != 0)) {
        opts = method ? seq_table_opts(opt, method, &aa) : seq_kw_opts(opt, &aa);
        if (!opts || (aa && (!seq_fill_aa || PyTuple_GetItem(q, 6) != Py_True))) Py_RETURN_FALSE;
    } else if (opt && opt != Py_None && !PyDict_CheckExact(opt)) {
        opts = PyLong_AsVoidPtr(opt);
        if (!opts) {
            PyErr_Clear();
            Py_RETURN_FALSE;
        }
    }
    if ((PyObject *)Py_TYPE(rings) == seq_ndarray) {
        h = (const seq_array_head *)(const void *)rings;
        if (!seq_dtype_is(h->descr, seq_f64) || h->nd != 2 || h->dimensions[1] != 2 || h->strides[0] != 16 ||
            h->strides[1] != 8 || !(h->flags & SEQ_ARRAY_ALIGNED))
            Py_RETURN_FALSE;
        n = h->dimensions[0];
        xy = (double *)(void *)h->data;
    } else if (PyList_CheckExact(rings)) {
        n = PyList_Size(rings);
        if (n >= 3 && n <= (Py_ssize_t)UINT32_MAX) {
            xy = stack;
            if (n > SEQ_STACK_POINTS) {
                heap = (double *)PyMem_Malloc((size_t)n * 2 * sizeof(double));
                if (!heap) return PyErr_NoMemory();
                xy = heap;
            }
            for (k = 0; k < n; k++) {
                if (!seq_pair(PyList_GetItem(rings, k), xy + 2 * k)) {
                    PyMem_Free(heap);
                    if (PyErr_Occurred()) return NULL;
                    Py_RETURN_FALSE;
                }
            }
        }
    }
    if (!xy || n < 3 || n > (Py_ssize_t)UINT32_MAX) {
        PyMem_Free(heap);
        Py_RETURN_FALSE;
    }
    addr = PyTuple_GetItem(q, 2);
    if (!PyBytes_CheckExact(addr) || PyBytes_Size(addr) != (Py_ssize_t)sizeof ptr) {
        PyMem_Free(heap);
        Py_RETURN_FALSE;
    }
    memcpy(ptr, PyBytes_AsString(addr), sizeof ptr);
    t = (const void *)ptr[0];
    pix = (const void *)ptr[1];
    if (!t || !pix) {
        PyMem_Free(heap);
        Py_RETURN_FALSE;
    }
    if (aa) {
        st = seq_fill_aa(t, xy, (uint32_t)n, NULL, 1, opts, pix, &seq_sc);
        seq_keep_scratch();
    } else {
        st = seq_fill(t, xy, (uint32_t)n, opts, pix);
    }
    PyMem_Free(heap);
    return PyBool_FromLong(st == 0);
}

static PyObject *seq_fill_fast(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    (void)self;
    return seq_nargs("fill", 4, 6, nargs) ? seq_fill_do(args, nargs) : NULL;
}

static PyObject *seq_fill_call(PyObject *self, PyObject *args)
{
    PyObject *a[6];
    return seq_unpack("fill", 4, 6, args, a) ? seq_fill_fast(self, a, PyTuple_Size(args)) : NULL;
}

/* Canvas.fill_polygon itself, called from Python (issue 33): the common
 * call -- rings and a colour by position, no keyword but rule= and aa= --
 * goes from the interpreter straight to seq_fill_do, with no Python frame
 * in between.  That frame (its keyword matching, its **kw dict, its
 * attribute loads and its call of fill) was ~930 of the ~6,800
 * instructions of a tiny polygon's binary call.  Anything else, and
 * anything seq_fill_do declines, goes to the full method with the same
 * arguments: the function that _canvas's global `_fill_polygon` names at
 * the time of the call (looked up then, so that a test can stand in for
 * it).
 *
 * fill_method(cls, globals, name, doc) makes the class attribute: a method
 * descriptor of cls (PyDescr_NewMethod, as a builtin type's methods are
 * made), which the interpreter calls with the canvas and the arguments as
 * they are (no bound method made, no tuple or dict on 3.10+); doc is its
 * text signature and docstring, what help() and inspect read.  The call
 * reads one attribute, _fpq, the canvas's remembered call, whose target
 * is the canvas's (Canvas._set forgets _fpq when it sets another). */
static PyObject *seq_fp_globals, *seq_fp_name, *seq_fp_doc, *seq_fpq_name;
static PyMethodDef seq_fp_def = {"fill_polygon", NULL, 0, NULL};

/* The full method's call: func(self, *args, **kw) (kw NULL: none). */
static PyObject *seq_fp_full(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *f = seq_fp_globals ? PyDict_GetItem(seq_fp_globals, seq_fp_name) : NULL, *t, *r = NULL;
    Py_ssize_t n = PyTuple_Size(args), k;
    if (!f) {
        PyErr_SetString(PyExc_RuntimeError, "fill_method: the full method is gone");
        return NULL;
    }
    Py_INCREF(f);
    t = PyTuple_New(n + 1);
    if (t) {
        Py_INCREF(self);
        PyTuple_SetItem(t, 0, self);
        for (k = 0; k < n; k++) {
            PyObject *v = PyTuple_GetItem(args, k);
            Py_INCREF(v);
            PyTuple_SetItem(t, k + 1, v);
        }
        r = PyObject_Call(f, t, kw);
        Py_DECREF(t);
    }
    Py_DECREF(f);
    return r;
}

/* The common call by seq_fill_do (rule and aa NULL: their defaults):
 * None when it drew, NULL with no exception when it declined, NULL with
 * one when a number could not be read. */
static PyObject *seq_fp_quick(PyObject *self, PyObject *const *args, Py_ssize_t nargs, PyObject *rule,
                              PyObject *aa)
{
    PyObject *a[6], *r;
    if (nargs < 1 || nargs > 2) return NULL;
    if (!(a[0] = PyObject_GetAttr(self, seq_fpq_name))) {
        PyErr_Clear();
        return NULL;
    }
    if (!PyTuple_CheckExact(a[0]) || PyTuple_Size(a[0]) != 7) {
        Py_DECREF(a[0]);
        return NULL;
    }
    a[1] = PyTuple_GetItem(a[0], 0); /* (the canvas's target: see above) */
    a[2] = args[0];
    a[3] = nargs > 1 ? args[1] : Py_None;
    a[4] = rule ? rule : seq_evenodd;
    a[5] = aa ? aa : Py_None;
    r = seq_fill_do(a, 6);
    Py_DECREF(a[0]);
    if (r == Py_True) {
        Py_DECREF(r);
        Py_RETURN_NONE;
    }
    Py_XDECREF(r);
    return NULL;
}

/* rule= or aa= given as the keyword `key` with `value` to *rule or *aa;
 * 0 for any other keyword.  (The names are compared as objects first: a
 * call's keywords are its code's interned constants.) */
static int seq_fp_keyword(PyObject *key, PyObject *value, PyObject **rule, PyObject **aa)
{
    if (key == seq_rule_name || (key != seq_aa_name && seq_is(key, seq_rule_name)))
        *rule = value;
    else if (key == seq_aa_name || seq_is(key, seq_aa_name))
        *aa = value;
    else
        return 0;
    return 1;
}

/* The forms of the call (METH_FASTCALL | METH_KEYWORDS where
 * seq_runtime_fastcall, else METH_VARARGS | METH_KEYWORDS). */
static PyObject *seq_fp_fast(PyObject *self, PyObject *const *args, Py_ssize_t nargs, PyObject *kwnames)
{
    PyObject *rule = NULL, *aa = NULL, *r, *t, *kw = NULL;
    Py_ssize_t nk = kwnames ? PyTuple_Size(kwnames) : 0, k;
    int plain = 1;
    for (k = 0; k < nk && plain; k++)
        plain = seq_fp_keyword(PyTuple_GetItem(kwnames, k), args[nargs + k], &rule, &aa);
    if (plain && ((r = seq_fp_quick(self, args, nargs, rule, aa)) || PyErr_Occurred())) return r;
    /* the full method, with the same arguments */
    if (!(t = PyTuple_New(nargs))) return NULL;
    for (k = 0; k < nargs; k++) {
        Py_INCREF(args[k]);
        PyTuple_SetItem(t, k, args[k]);
    }
    if (nk && !(kw = PyDict_New())) {
        Py_DECREF(t);
        return NULL;
    }
    for (k = 0; k < nk; k++) {
        if (PyDict_SetItem(kw, PyTuple_GetItem(kwnames, k), args[nargs + k]) < 0) {
            Py_DECREF(t);
            Py_DECREF(kw);
            return NULL;
        }
    }
    r = seq_fp_full(self, t, kw);
    Py_DECREF(t);
    Py_XDECREF(kw);
    return r;
}

static PyObject *seq_fp_call(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *rule = NULL, *aa = NULL, *key, *value, *a[2], *r;
    Py_ssize_t pos = 0, n = PyTuple_Size(args), k;
    int plain = 1;
    while (plain && kw && PyDict_Next(kw, &pos, &key, &value)) plain = seq_fp_keyword(key, value, &rule, &aa);
    for (k = 0; k < n && k < 2; k++) a[k] = PyTuple_GetItem(args, k);
    if (plain && ((r = seq_fp_quick(self, a, n, rule, aa)) || PyErr_Occurred())) return r;
    return seq_fp_full(self, args, kw);
}

/* fill_method(cls, globals, name, doc) -> the method descriptor (see
 * above).  Once: the descriptor keeps the one method definition. */
static PyObject *seq_fill_method(PyObject *self, PyObject *args)
{
    PyObject *cls, *globals, *name, *doc;
    (void)self;
    if (!PyArg_UnpackTuple(args, "fill_method", 4, 4, &cls, &globals, &name, &doc)) return NULL;
    if (!PyType_Check(cls) || !PyDict_CheckExact(globals) || !PyUnicode_CheckExact(name) ||
        !PyUnicode_CheckExact(doc)) {
        PyErr_SetString(PyExc_TypeError, "fill_method(type, dict, str, str)");
        return NULL;
    }
    if (seq_fp_def.ml_meth) {
        PyErr_SetString(PyExc_RuntimeError, "fill_method: made once");
        return NULL;
    }
    if (!(seq_fpq_name = PyUnicode_InternFromString("_fpq"))) return NULL;
    if (!(seq_fp_doc = PyUnicode_AsUTF8String(doc))) return NULL;
    Py_INCREF(globals);
    Py_INCREF(name);
    seq_fp_globals = globals;
    seq_fp_name = name;
    seq_fp_def.ml_doc = PyBytes_AsString(seq_fp_doc);
    if (seq_runtime_fastcall()) {
        seq_fp_def.ml_meth = (PyCFunction)(void (*)(void))seq_fp_fast;
        seq_fp_def.ml_flags = SEQ_METH_FASTCALL | METH_KEYWORDS;
    } else {
        seq_fp_def.ml_meth = (PyCFunction)(void (*)(void))seq_fp_call;
        seq_fp_def.ml_flags = METH_VARARGS | METH_KEYWORDS;
    }
    return PyDescr_NewMethod((PyTypeObject *)cls, &seq_fp_def);
}

/* rastrum.polygon_coverage's common call, whole in C (issue 33: its
 * Python and cffi cost more than the C of a small polygon's coverage):
 * one ring -- an exact ndarray, C-contiguous aligned native float64
 * (n, 2) with 3 <= n <= SEQ_COV_POINTS, alone or the one item of an exact
 * list -- into a (h, w) of two exact ints, at most SEQ_COV_PIXELS, with
 * (method, rule, subpixel_bits, sample_offset, dtype) a key the general
 * path has checked and remembered in the table coverage_setup gives:
 * {key: (rast_coverage_opts address, uint8 or uint16 format, numpy
 * dtype, the options kept alive)}.  The array is made by numpy.empty and
 * written whole by rastpy_polygon_coverage with the GIL held (small calls
 * only: a large one, and everything else, is the general path's, which
 * lets other threads run), lent this thread's scratch as _coverage._lent
 * lends it (the threading.local's `at`, its address; _coverage._keep
 * called after when the call wanted more); None (no exception, nothing kept) for
 * anything else or an error status: the general path then checks and
 * says what is wrong. */
typedef long (*seq_cov_fn)(void *out, int32_t height, int32_t width, int format, const double *xy,
                           uint32_t npoints, const uint32_t *ring_sizes, uint32_t nrings, const void *opts,
                           seq_scratch *sc);
static seq_cov_fn seq_cov;
static PyObject *seq_cov_table, *seq_empty, *seq_cov_tls, *seq_cov_keep, *seq_at_name;
#define SEQ_COV_POINTS 256
#define SEQ_COV_PIXELS ((long)1 << 18)

/* coverage_setup(table, numpy.empty, rastpy_polygon_coverage address,
 * the scratch's threading.local, _coverage._keep) -> None */
static PyObject *seq_coverage_setup(PyObject *self, PyObject *args)
{
    PyObject *table, *empty, *fn, *tls, *keep;
    void *f;
    (void)self;
    if (!PyArg_UnpackTuple(args, "coverage_setup", 5, 5, &table, &empty, &fn, &tls, &keep)) return NULL;
    if (!PyDict_CheckExact(table)) {
        PyErr_SetString(PyExc_TypeError, "coverage_setup: the table is a dict");
        return NULL;
    }
    if (!(f = seq_address(fn))) return NULL;
    memcpy(&seq_cov, &f, sizeof f); /* an object pointer to a function pointer (POSIX) */
    if (!seq_at_name && !(seq_at_name = PyUnicode_InternFromString("at"))) return NULL;
    Py_INCREF(table);
    Py_INCREF(empty);
    Py_INCREF(tls);
    Py_INCREF(keep);
    Py_XDECREF(seq_cov_table);
    Py_XDECREF(seq_empty);
    Py_XDECREF(seq_cov_tls);
    Py_XDECREF(seq_cov_keep);
    seq_cov_table = table;
    seq_empty = empty;
    seq_cov_tls = tls;
    seq_cov_keep = keep;
    Py_RETURN_NONE;
}

/* The one ring of `rings` as seq_coverage_call takes it (its points at
 * *xy, their number returned), else 0. */
static Py_ssize_t seq_cov_ring(PyObject *rings, const double **xy)
{
    const seq_array_head *h;
    if (PyList_CheckExact(rings) && PyList_Size(rings) == 1) rings = PyList_GetItem(rings, 0);
    if ((PyObject *)Py_TYPE(rings) != seq_ndarray) return 0;
    if (seq_head_ok < 0) seq_head_ok = seq_head_check(rings);
    if (seq_head_ok <= 0) return 0;
    h = (const seq_array_head *)(const void *)rings;
    if (!seq_dtype_is(h->descr, seq_f64) || h->nd != 2 || h->dimensions[1] != 2 || h->strides[0] != 16 ||
        h->strides[1] != 8 || !(h->flags & SEQ_ARRAY_ALIGNED) || h->dimensions[0] < 3 ||
        h->dimensions[0] > SEQ_COV_POINTS)
        return 0;
    *xy = (const double *)(const void *)h->data;
    return h->dimensions[0];
}

/* coverage(rings, shape, method, rule, subpixel_bits, sample_offset,
 * dtype) -> array or None */
static PyObject *seq_coverage_fast(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    PyObject *rings, *shape, *method, *rule, *s, *offset, *dtype, *key, *got, *arr, *at;
    const double *xy = NULL;
    const void *opts;
    seq_scratch *sc;
    Py_ssize_t n;
    long h, w, fmt, st;
    (void)self;
    if (!seq_nargs("coverage", 7, 7, nargs)) return NULL;
    rings = args[0];
    shape = args[1];
    method = args[2];
    rule = args[3];
    s = args[4];
    offset = args[5];
    dtype = args[6];
    if (!seq_cov || !seq_cov_table || !PyUnicode_CheckExact(method) || !PyUnicode_CheckExact(rule) ||
        !PyLong_CheckExact(s) || !PyFloat_CheckExact(offset) || !PyTuple_CheckExact(shape) ||
        PyTuple_Size(shape) != 2 || !PyLong_CheckExact(PyTuple_GetItem(shape, 0)) ||
        !PyLong_CheckExact(PyTuple_GetItem(shape, 1)))
        Py_RETURN_NONE;
    if (!(n = seq_cov_ring(rings, &xy))) Py_RETURN_NONE;
    h = PyLong_AsLong(PyTuple_GetItem(shape, 0));
    w = PyLong_AsLong(PyTuple_GetItem(shape, 1));
    if (PyErr_Occurred()) {
        PyErr_Clear();
        Py_RETURN_NONE;
    }
    if (h <= 0 || w <= 0 || h > SEQ_COV_PIXELS / w) /* (so both below RAST_MAX_DIM, 2^30 - 1) */
        Py_RETURN_NONE;
    key = PyTuple_Pack(5, method, rule, s, offset, dtype);
    if (!key) return NULL;
    got = PyDict_GetItem(seq_cov_table, key); /* (an unhashable dtype: NULL, no exception) */
    Py_DECREF(key);
    if (!got || !PyTuple_CheckExact(got) || PyTuple_Size(got) != 4) Py_RETURN_NONE;
    opts = PyLong_AsVoidPtr(PyTuple_GetItem(got, 0));
    fmt = PyLong_AsLong(PyTuple_GetItem(got, 1));
    if (!opts || PyErr_Occurred()) {
        PyErr_Clear();
        Py_RETURN_NONE;
    }
    at = PyObject_GetAttr(seq_cov_tls, seq_at_name); /* (none yet: _lent makes it) */
    sc = at ? (seq_scratch *)PyLong_AsVoidPtr(at) : NULL;
    Py_XDECREF(at);
    if (!sc) {
        PyErr_Clear();
        Py_RETURN_NONE;
    }
    arr = PyObject_CallFunctionObjArgs(seq_empty, shape, PyTuple_GetItem(got, 2), NULL);
    if (!arr) return NULL;
    if ((PyObject *)Py_TYPE(arr) != seq_ndarray) {
        Py_DECREF(arr);
        Py_RETURN_NONE;
    }
    st = seq_cov(((const seq_array_head *)(const void *)arr)->data, (int32_t)h, (int32_t)w, (int)fmt, xy,
                 (uint32_t)n, NULL, 1, opts, sc);
    if (st) {
        Py_DECREF(arr);
        Py_RETURN_NONE;
    }
    if (sc->size < sc->want) { /* (the cap is _keep's) */
        PyObject *r = PyObject_CallObject(seq_cov_keep, NULL);
        if (!r) {
            Py_DECREF(arr);
            return NULL;
        }
        Py_DECREF(r);
    }
    return arr;
}

static PyObject *seq_coverage_call(PyObject *self, PyObject *args)
{
    PyObject *a[7];
    return seq_unpack("coverage", 7, 7, args, a) ? seq_coverage_fast(self, a, PyTuple_Size(args)) : NULL;
}

/* use_head(flag): read arrays through their head (when it checks out:
 * the default) or always through __array_struct__; the previous setting. */
static PyObject *seq_use_head(PyObject *self, PyObject *flag)
{
    int prev = seq_head_ok != 0, on = PyObject_IsTrue(flag);
    (void)self;
    if (on < 0) return NULL;
    seq_head_ok = on ? -1 : 0;
    return PyBool_FromLong(prev);
}

static PyMethodDef seq_methods[] = {
    {"flat", seq_flat, METH_O,
     "flat(segmentations) -> (points, ring_sizes, rings_per_object) as bytearrays, or None"},
    {"rings", seq_rings, METH_VARARGS,
     "rings(rings, ndarray, (float64, int32)[, as_bytes]) -> (points, ring_sizes or None) as bytearrays "
     "(as_bytes: bytes), or None"},
    {"ring_ptrs", seq_ring_ptrs, METH_VARARGS,
     "ring_ptrs(rings, ndarray, float64) -> (addresses, ring_sizes as bytes, points, tuple of the rings), or None"},
    {"use_head", seq_use_head, METH_O,
     "use_head(flag) -> bool: whether arrays are read through their head (once checked) or __array_struct__"},
    {"fill_setup", seq_fill_setup, METH_VARARGS,
     "fill_setup(fill_ring address, default opts address, ndarray, float64[, fill_polygon_aa address, "
     "{rule: {aa: opts address}}]) -> None"},
    {"fill", seq_fill_call, METH_VARARGS,
     "fill(q, target, rings, color[, opts address or keyword dict | rule, aa]) -> bool: Canvas.fill_polygon's common call, "
     "done"},
    {"fill_method", seq_fill_method, METH_VARARGS,
     "fill_method(Canvas, the _canvas module's globals, the full method's name there, doc) -> "
     "Canvas.fill_polygon's method descriptor"},
    {"coverage_setup", seq_coverage_setup, METH_VARARGS,
     "coverage_setup({key: (opts address, format, dtype, opts)}, numpy.empty, polygon_coverage address) -> None"},
    {"coverage", seq_coverage_call, METH_VARARGS,
     "coverage(rings, shape, method, rule, subpixel_bits, sample_offset, dtype) -> array or None: "
     "polygon_coverage's common call, done"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef seq_module = {
    PyModuleDef_HEAD_INIT, "_seq", "COCO polygon lists read in one C pass.", -1, seq_methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__seq(void);
PyMODINIT_FUNC PyInit__seq(void)
{
    if (!seq_struct_name) seq_struct_name = PyUnicode_InternFromString("__array_struct__");
    if (!seq_dtype_name) seq_dtype_name = PyUnicode_InternFromString("dtype");
    if (!seq_rule_name) seq_rule_name = PyUnicode_InternFromString("rule");
    if (!seq_aa_name) seq_aa_name = PyUnicode_InternFromString("aa");
    if (!seq_evenodd) seq_evenodd = PyUnicode_InternFromString("evenodd");
    if (!seq_struct_name || !seq_dtype_name || !seq_rule_name || !seq_aa_name || !seq_evenodd) return NULL;
    if (seq_runtime_fastcall()) {
        PyMethodDef *m;
        for (m = seq_methods; m->ml_name; m++) {
            seq_fast_fn f = !strcmp(m->ml_name, "fill") ? seq_fill_fast
                            : !strcmp(m->ml_name, "coverage") ? seq_coverage_fast : NULL;
            if (!f) continue;
            /* (a function pointer cast as CPython's own tables cast them) */
            m->ml_meth = (PyCFunction)(void (*)(void))f;
            m->ml_flags = SEQ_METH_FASTCALL;
        }
    }
    return PyModule_Create(&seq_module);
}
