/*
 * The deformation of §2.2 as one compiled pass over the vertices.
 *
 * Built as the extension module ``engine.deform._kernel`` by ``pip install -e .``
 * (setup.py); ``engine/deform/deformer.py`` uses it when it imports and falls back to
 * its numpy path otherwise. Only the Python C API and the buffer protocol are
 * used (no numpy headers); portable C, single thread.
 *
 * The formulation is the one of docs/deformation.md, section 3, in the row
 * convention p' = p·A + b (A the transposed linear part, b the translation):
 *
 *     q   = p + Σ_leaf w · (p·(T_k − I))             (field leaf k: + v_k · (w·D))
 *     out = q + Σ_group1 w̄ · (q·(T'_k − I))          (bound to one k: w̄ = 1)
 *
 * Layout. deform.py sorts the vertices by how they move (the Deformer's
 * internal order) and cuts that order into *segments*: runs of vertices with
 * the same group-1 class (bound to one parameter, free, or blended) and the
 * same set of leaves. Within a segment every vertex does the same arithmetic
 * with its own weights, so the loops run over vertices with fixed matrices
 * and the compiler vectorises them. A Plan holds:
 *
 *     kind, parent, topo   per parameter: 0 rotation, 1 translation, 2 field
 *                          translation; parent index (−1 at a root); an order
 *                          that puts parents before children
 *     axis, pivot, scale, direction
 *                          K × 3 (unit axis, mm), radians per unit, mm per unit
 *     rest                 3 × N: x, y, z rows in internal order
 *     order                internal vertex j is output row order[j]; empty when
 *                          the internal order is the model's own
 *     segments             S × 7: start, stop, carry, first band entry, band
 *                          entries, first leaf entry, leaf entries; carry is the
 *                          parameter a bound segment moves with, −1 free, −2 blended
 *     entries              E × 2: parameter, offset in data; the segment's
 *                          group-1 columns (blended only) and leaves, each in
 *                          parameter order
 *     data                 per entry and segment vertex: the normalised group-1
 *                          weight, the leaf weight, or for a field leaf three
 *                          rows w·D_x, w·D_y, w·D_z
 *
 * Plan.deform(values, out) builds every T_k and T'_k for the frame (Rodrigues
 * for rotations, T'_c = T_c · T'_parent down the tree), then runs the pass
 * with the GIL released. Exactness: a leaf at value 0 and a group-1 parameter
 * whose T' is exactly I are skipped, so all values 0 give the rest mesh bit for
 * bit, and a leaf at 0 changes no bit of any vertex (invariants 1 and 2 of
 * docs/deformation.md).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

/* Bumped whenever the Plan's arguments change; deform.py checks it. */
#define KERNEL_ABI 1

#ifndef SOURCE_SHA256
#define SOURCE_SHA256 "unknown"
#endif

#define CHUNK 128   /* vertices per inner loop: the scratch rows stay in L1 */

enum { ROTATION = 0, TRANSLATION = 1, FIELD = 2 };
enum { FREE = -1, BLENDED = -2 };
enum { SEG_START, SEG_STOP, SEG_CARRY, SEG_BAND_FIRST, SEG_BAND_COUNT, SEG_LEAF_FIRST, SEG_LEAF_COUNT, SEG_FIELDS };

/* Affine map in the row convention: p' = p·A + b, A row-major (a[3*i + j]). */
typedef struct {
    double a[9];
    double b[3];
} Affine;

typedef struct {
    PyObject_HEAD
    Py_ssize_t n_params, n_vertices, n_segments, n_entries, n_data;
    int64_t *kind, *parent, *topo;
    double *axis, *pivot, *scale, *direction;
    double *rest;
    int64_t *order;      /* NULL: output row j is internal vertex j */
    int64_t *segments, *entries;
    double *data;
} Plan;

/* ------------------------------------------------------------------------- */
/* Buffers                                                                    */

/* A C-contiguous buffer of float64 ('d') or int64 ('q'), copied to fresh memory. */
static int
copy_buffer(PyObject *obj, char code, const char *what, void **dest, Py_ssize_t *count)
{
    Py_buffer view;
    if (PyObject_GetBuffer(obj, &view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    const char *fmt = view.format ? view.format : "B";
    if (*fmt == '@' || *fmt == '=' || *fmt == '<')
        fmt++;
    int ok = view.itemsize == 8 && fmt[1] == '\0' &&
             (code == 'd' ? fmt[0] == 'd' : (fmt[0] == 'q' || fmt[0] == 'l'));
    if (!ok) {
        PyErr_Format(PyExc_TypeError, "%s: expected a contiguous array of %s, got format '%s'", what,
                     code == 'd' ? "float64" : "int64", view.format ? view.format : "B");
        PyBuffer_Release(&view);
        return -1;
    }
    *count = view.len / 8;
    *dest = PyMem_Malloc(view.len > 0 ? (size_t)view.len : 1);
    if (*dest == NULL) {
        PyBuffer_Release(&view);
        PyErr_NoMemory();
        return -1;
    }
    if (view.len > 0)
        memcpy(*dest, view.buf, (size_t)view.len);
    PyBuffer_Release(&view);
    return 0;
}

static int
fail(const char *message)
{
    PyErr_SetString(PyExc_ValueError, message);
    return -1;
}

/* Everything the pass indexes must be in range: a bad Plan raises instead of reading wild memory. */
static int
check_plan(Plan *self)
{
    const Py_ssize_t K = self->n_params, N = self->n_vertices, E = self->n_entries;
    for (Py_ssize_t j = 0; self->order && j < N; j++)
        if (self->order[j] < 0 || self->order[j] >= N)
            return fail("order: vertex index out of range");
    char *seen = PyMem_Calloc(K > 0 ? (size_t)K : 1, 1);
    if (seen == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    int bad = 0;
    for (Py_ssize_t t = 0; t < K && !bad; t++) {
        int64_t k = self->topo[t];
        bad = k < 0 || k >= K || seen[k] || self->kind[k] < ROTATION || self->kind[k] > FIELD;
        if (!bad) {
            int64_t p = self->parent[k];
            bad = p < -1 || p >= K || (p >= 0 && !seen[p]);
            seen[k] = 1;
        }
    }
    PyMem_Free(seen);
    if (bad)
        return fail("parameters: bad kind, parent or topological order");
    for (Py_ssize_t e = 0; e < E; e++)
        if (self->entries[2 * e] < 0 || self->entries[2 * e] >= K)
            return fail("entries: parameter index out of range");
    int64_t covered = 0;
    for (Py_ssize_t s = 0; s < self->n_segments; s++) {
        const int64_t *seg = self->segments + SEG_FIELDS * s;
        int64_t start = seg[SEG_START], stop = seg[SEG_STOP], len = stop - start, carry = seg[SEG_CARRY];
        if (start != covered || stop <= start || stop > N)
            return fail("segments: must cover the vertices in order");
        covered = stop;
        if (carry < BLENDED || carry >= K)
            return fail("segments: bad carry");
        int64_t ranges[2][2] = {{seg[SEG_BAND_FIRST], seg[SEG_BAND_COUNT]}, {seg[SEG_LEAF_FIRST], seg[SEG_LEAF_COUNT]}};
        for (int r = 0; r < 2; r++) {
            int64_t first = ranges[r][0], count = ranges[r][1];
            if (first < 0 || count < 0 || first + count > E || (r == 0 && carry != BLENDED && count != 0))
                return fail("segments: bad entry range");
            for (int64_t e = first; e < first + count; e++) {
                int64_t rows = (r == 1 && self->kind[self->entries[2 * e]] == FIELD) ? 3 : 1;
                int64_t offset = self->entries[2 * e + 1];
                if (offset < 0 || offset + rows * len > self->n_data)
                    return fail("entries: data offset out of range");
            }
        }
    }
    if (covered != N)
        return fail("segments: must cover the vertices in order");
    return 0;
}

/* ------------------------------------------------------------------------- */
/* Plan                                                                       */

static void
Plan_dealloc(Plan *self)
{
    void *arrays[] = {self->kind, self->parent, self->topo, self->axis, self->pivot, self->scale,
                      self->direction, self->rest, self->order, self->segments, self->entries, self->data};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
        PyMem_Free(arrays[i]);
    PyTypeObject *type = Py_TYPE(self);
    type->tp_free((PyObject *)self);
    Py_DECREF(type);
}

static int
Plan_init(Plan *self, PyObject *args, PyObject *kwds)
{
    enum { N_ARGS = 12 };
    static char *names[] = {"kind", "parent", "topo", "axis", "pivot", "scale", "direction",
                            "rest", "order", "segments", "entries", "data", NULL};
    PyObject *o[N_ARGS];
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "OOOOOOOOOOOO", names, &o[0], &o[1], &o[2], &o[3], &o[4],
                                     &o[5], &o[6], &o[7], &o[8], &o[9], &o[10], &o[11]))
        return -1;
    if (self->kind != NULL) {
        PyErr_SetString(PyExc_RuntimeError, "Plan is already initialised");
        return -1;
    }
    void **dest[N_ARGS] = {(void **)&self->kind, (void **)&self->parent, (void **)&self->topo,
                           (void **)&self->axis, (void **)&self->pivot, (void **)&self->scale,
                           (void **)&self->direction, (void **)&self->rest, (void **)&self->order,
                           (void **)&self->segments, (void **)&self->entries, (void **)&self->data};
    const char codes[N_ARGS + 1] = "qqqdddddqqqd";
    Py_ssize_t n[N_ARGS];
    for (int i = 0; i < N_ARGS; i++)
        if (copy_buffer(o[i], codes[i], names[i], dest[i], &n[i]) < 0)
            return -1;
    const Py_ssize_t K = n[0], N = n[7] / 3;
    self->n_params = K;
    self->n_vertices = N;
    self->n_segments = n[9] / SEG_FIELDS;
    self->n_entries = n[10] / 2;
    self->n_data = n[11];
    if (n[1] != K || n[2] != K || n[3] != 3 * K || n[4] != 3 * K || n[5] != K || n[6] != 3 * K)
        return fail("parameter arrays disagree on the number of parameters");
    if (n[7] != 3 * N || (n[8] != 0 && n[8] != N))
        return fail("rest must be 3 × N and order empty or N long");
    if (n[9] != SEG_FIELDS * self->n_segments || n[10] != 2 * self->n_entries)
        return fail("segments must be S × 7 and entries E × 2");
    if (n[8] == 0) {
        PyMem_Free(self->order);
        self->order = NULL;
    }
    return check_plan(self);
}

/* ------------------------------------------------------------------------- */
/* One frame: the matrices                                                    */

static void
identity(Affine *T)
{
    memset(T, 0, sizeof *T);
    T->a[0] = T->a[4] = T->a[8] = 1.0;
}

/* T_k(v): the arithmetic of Deformer.local_transforms (exactly I at angle 0). */
static void
local_transform(const Plan *P, int64_t k, double v, Affine *T)
{
    identity(T);
    if (P->kind[k] == ROTATION) {
        double theta = v * P->scale[k];
        if (theta == 0.0)
            return;
        double c = cos(theta), s = sin(theta), t = 1.0 - c;
        const double *u = P->axis + 3 * k, *piv = P->pivot + 3 * k;
        double R[9];   /* column convention, Rodrigues: R = cI + s[u]x + (1 − c)uuᵀ */
        R[0] = c + t * (u[0] * u[0]);
        R[1] = -s * u[2] + t * (u[0] * u[1]);
        R[2] = s * u[1] + t * (u[0] * u[2]);
        R[3] = s * u[2] + t * (u[1] * u[0]);
        R[4] = c + t * (u[1] * u[1]);
        R[5] = -s * u[0] + t * (u[1] * u[2]);
        R[6] = -s * u[1] + t * (u[2] * u[0]);
        R[7] = s * u[0] + t * (u[2] * u[1]);
        R[8] = c + t * (u[2] * u[2]);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                T->a[3 * i + j] = R[3 * j + i];
        for (int j = 0; j < 3; j++)      /* the pivot stays put: b = c − c·A */
            T->b[j] = piv[j] - (piv[0] * T->a[j] + piv[1] * T->a[3 + j] + piv[2] * T->a[6 + j]);
    } else if (P->kind[k] == TRANSLATION) {
        for (int j = 0; j < 3; j++)
            T->b[j] = v * P->direction[3 * k + j];
    }
}

/* out = c · p: apply c first, then p. */
static void
compose(const Affine *c, const Affine *p, Affine *out)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out->a[3 * i + j] = c->a[3 * i] * p->a[j] + c->a[3 * i + 1] * p->a[3 + j] + c->a[3 * i + 2] * p->a[6 + j];
    for (int j = 0; j < 3; j++)
        out->b[j] = c->b[0] * p->a[j] + c->b[1] * p->a[3 + j] + c->b[2] * p->a[6 + j] + p->b[j];
}

/* T − I in place; returns whether the result has a non-zero entry. */
static int
minus_identity(Affine *T)
{
    T->a[0] -= 1.0;
    T->a[4] -= 1.0;
    T->a[8] -= 1.0;
    for (int i = 0; i < 9; i++)
        if (T->a[i] != 0.0)
            return 1;
    return T->b[0] != 0.0 || T->b[1] != 0.0 || T->b[2] != 0.0;
}

/* ------------------------------------------------------------------------- */
/* One frame: the vertex pass                                                  */

typedef struct {
    const Plan *plan;
    const double *values;
    const Affine *leaf;              /* T_k − I */
    const Affine *carry;             /* T'_k − I */
    const unsigned char *active;     /* leaf k at a non-zero value */
    const unsigned char *moving;     /* T'_k − I has a non-zero entry */
    double *out;                     /* N × 3, model order */
} Frame;

/* Write rows (x, y, z) of n vertices starting at internal index c. */
static void
store(const Frame *F, Py_ssize_t c, Py_ssize_t n, const double *restrict x, const double *restrict y,
      const double *restrict z)
{
    const int64_t *order = F->plan->order;
    double *restrict out = F->out;
    if (order) {
        for (Py_ssize_t i = 0; i < n; i++) {
            double *o = out + 3 * order[c + i];
            o[0] = x[i];
            o[1] = y[i];
            o[2] = z[i];
        }
    } else {
        double *restrict o = out + 3 * c;
        for (Py_ssize_t i = 0; i < n; i++) {
            o[3 * i] = x[i];
            o[3 * i + 1] = y[i];
            o[3 * i + 2] = z[i];
        }
    }
}

/* out = q + q·D for n vertices (a bound segment). */
static void
carry_and_store(const Frame *F, Py_ssize_t c, Py_ssize_t n, const Affine *D, const double *restrict x,
                const double *restrict y, const double *restrict z)
{
    const double a0 = D->a[0], a1 = D->a[1], a2 = D->a[2], a3 = D->a[3], a4 = D->a[4], a5 = D->a[5];
    const double a6 = D->a[6], a7 = D->a[7], a8 = D->a[8], b0 = D->b[0], b1 = D->b[1], b2 = D->b[2];
    const int64_t *order = F->plan->order;
    double *restrict out = F->out;
    if (order) {
        for (Py_ssize_t i = 0; i < n; i++) {
            double *o = out + 3 * order[c + i];
            o[0] = x[i] + (x[i] * a0 + y[i] * a3 + z[i] * a6 + b0);
            o[1] = y[i] + (x[i] * a1 + y[i] * a4 + z[i] * a7 + b1);
            o[2] = z[i] + (x[i] * a2 + y[i] * a5 + z[i] * a8 + b2);
        }
    } else {
        double *restrict o = out + 3 * c;
        for (Py_ssize_t i = 0; i < n; i++) {
            o[3 * i] = x[i] + (x[i] * a0 + y[i] * a3 + z[i] * a6 + b0);
            o[3 * i + 1] = y[i] + (x[i] * a1 + y[i] * a4 + z[i] * a7 + b1);
            o[3 * i + 2] = z[i] + (x[i] * a2 + y[i] * a5 + z[i] * a8 + b2);
        }
    }
}

/* q = s + w · (p·D) for n vertices: a leaf rotation or translation on the rest points p, or
 * (with q in place of p) a group-1 column of the blended band. Writes to fresh rows, so that
 * every loop has distinct inputs and outputs and vectorises. */
static void
add_leaf(Py_ssize_t n, const Affine *D, const double *restrict w, const double *restrict x,
         const double *restrict y, const double *restrict z, const double *restrict sx,
         const double *restrict sy, const double *restrict sz, double *restrict qx, double *restrict qy,
         double *restrict qz)
{
    const double a0 = D->a[0], a1 = D->a[1], a2 = D->a[2], a3 = D->a[3], a4 = D->a[4], a5 = D->a[5];
    const double a6 = D->a[6], a7 = D->a[7], a8 = D->a[8], b0 = D->b[0], b1 = D->b[1], b2 = D->b[2];
    for (Py_ssize_t i = 0; i < n; i++) {
        qx[i] = sx[i] + w[i] * (x[i] * a0 + y[i] * a3 + z[i] * a6 + b0);
        qy[i] = sy[i] + w[i] * (x[i] * a1 + y[i] * a4 + z[i] * a7 + b1);
        qz[i] = sz[i] + w[i] * (x[i] * a2 + y[i] * a5 + z[i] * a8 + b2);
    }
}

/* q = s + v · (w·D) for n vertices (a field translation). */
static void
add_field(Py_ssize_t n, double v, const double *restrict dx, const double *restrict dy, const double *restrict dz,
          const double *restrict sx, const double *restrict sy, const double *restrict sz, double *restrict qx,
          double *restrict qy, double *restrict qz)
{
    for (Py_ssize_t i = 0; i < n; i++) {
        qx[i] = sx[i] + v * dx[i];
        qy[i] = sy[i] + v * dy[i];
        qz[i] = sz[i] + v * dz[i];
    }
}

static void
vertex_pass(const Frame *F)
{
    const Plan *P = F->plan;
    const Py_ssize_t N = P->n_vertices;
    const double *px = P->rest, *py = P->rest + N, *pz = P->rest + 2 * N;
    /* ping-pong rows: each update reads one set and writes the other (stage 1, then the band) */
    double scratch[2][3][CHUNK], blend[2][3][CHUNK];

    for (Py_ssize_t s = 0; s < P->n_segments; s++) {
        const int64_t *seg = P->segments + SEG_FIELDS * s;
        const Py_ssize_t start = seg[SEG_START], stop = seg[SEG_STOP], len = stop - start;
        const int64_t carry = seg[SEG_CARRY];
        const int64_t *band = P->entries + 2 * seg[SEG_BAND_FIRST];
        const int64_t *leaves = P->entries + 2 * seg[SEG_LEAF_FIRST];
        const int64_t n_band = seg[SEG_BAND_COUNT], n_leaves = seg[SEG_LEAF_COUNT];

        for (Py_ssize_t c = start; c < stop; c += CHUNK) {
            const Py_ssize_t n = stop - c < CHUNK ? stop - c : CHUNK, at = c - start;
            const double *x = px + c, *y = py + c, *z = pz + c;
            int next = 0;

            /* stage 1: leaves in the rest frame (Eq. 2); (sx, sy, sz) holds the result */
            const double *sx = x, *sy = y, *sz = z;
            for (int64_t e = 0; e < n_leaves; e++) {
                const int64_t k = leaves[2 * e];
                if (!F->active[k])
                    continue;
                double *qx = scratch[next][0], *qy = scratch[next][1], *qz = scratch[next][2];
                const double *d = P->data + leaves[2 * e + 1] + at;
                if (P->kind[k] == FIELD)
                    add_field(n, F->values[k], d, d + len, d + 2 * len, sx, sy, sz, qx, qy, qz);
                else
                    add_leaf(n, &F->leaf[k], d, x, y, z, sx, sy, sz, qx, qy, qz);
                sx = qx, sy = qy, sz = qz;
                next ^= 1;
            }

            /* stage 2: the rigid carry of group 1 */
            if (carry >= 0) {
                if (F->moving[carry])
                    carry_and_store(F, c, n, &F->carry[carry], sx, sy, sz);
                else
                    store(F, c, n, sx, sy, sz);
            } else if (carry == BLENDED) {
                /* o = q + Σ w̄ · (q·(T' − I)), column by column in parameter order */
                const double *ox = sx, *oy = sy, *oz = sz;
                int flip = 0;
                for (int64_t e = 0; e < n_band; e++) {
                    const int64_t k = band[2 * e];
                    if (!F->moving[k])
                        continue;
                    double *qx = blend[flip][0], *qy = blend[flip][1], *qz = blend[flip][2];
                    add_leaf(n, &F->carry[k], P->data + band[2 * e + 1] + at, sx, sy, sz, ox, oy, oz, qx, qy, qz);
                    ox = qx, oy = qy, oz = qz;
                    flip ^= 1;
                }
                store(F, c, n, ox, oy, oz);
            } else {
                store(F, c, n, sx, sy, sz);
            }
        }
    }
}

static PyObject *
Plan_deform(Plan *self, PyObject *args)
{
    PyObject *values_obj, *out_obj;
    if (!PyArg_ParseTuple(args, "OO:deform", &values_obj, &out_obj))
        return NULL;
    if (self->kind == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "Plan is not initialised");
        return NULL;
    }
    Py_buffer values, out;
    if (PyObject_GetBuffer(values_obj, &values, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return NULL;
    if (PyObject_GetBuffer(out_obj, &out, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_WRITABLE) < 0) {
        PyBuffer_Release(&values);
        return NULL;
    }
    const Py_ssize_t K = self->n_params, N = self->n_vertices;
    PyObject *result = NULL;
    Affine *local = NULL;
    unsigned char *flags = NULL;
    const char *vf = values.format ? values.format + (values.format[0] == '<' || values.format[0] == '=' ||
                                                      values.format[0] == '@') : "d";
    const char *of = out.format ? out.format + (out.format[0] == '<' || out.format[0] == '=' ||
                                                out.format[0] == '@') : "d";
    if (values.itemsize != 8 || strcmp(vf, "d") || values.len != K * 8) {
        PyErr_Format(PyExc_ValueError, "values: expected %zd float64 values", K);
        goto done;
    }
    if (out.itemsize != 8 || strcmp(of, "d") || out.len != 3 * N * 8) {
        /* the format string must be ASCII; a %s argument may be UTF-8 */
        PyErr_Format(PyExc_ValueError, "out: expected %zd %s 3 float64", N, "×");
        goto done;
    }
    /* T_k, T'_k, and their deltas from I: four matrices per parameter */
    local = PyMem_Malloc(4 * (size_t)(K > 0 ? K : 1) * sizeof(Affine));
    flags = PyMem_Malloc(2 * (size_t)(K > 0 ? K : 1));
    if (local == NULL || flags == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Affine *world = local + K, *leaf = local + 2 * K, *carry = local + 3 * K;
    unsigned char *active = flags, *moving = flags + K;
    const double *v = values.buf;
    for (Py_ssize_t t = 0; t < K; t++) {
        const int64_t k = self->topo[t], p = self->parent[k];
        local_transform(self, k, v[k], &local[k]);
        if (p < 0)
            world[k] = local[k];
        else
            compose(&local[k], &world[p], &world[k]);
    }
    for (Py_ssize_t k = 0; k < K; k++) {
        leaf[k] = local[k];
        minus_identity(&leaf[k]);
        active[k] = v[k] != 0.0;
        carry[k] = world[k];
        moving[k] = (unsigned char)minus_identity(&carry[k]);
    }
    Frame frame = {self, v, leaf, carry, active, moving, out.buf};
    Py_BEGIN_ALLOW_THREADS
    vertex_pass(&frame);
    Py_END_ALLOW_THREADS
    result = Py_NewRef(Py_None);
done:
    PyMem_Free(local);
    PyMem_Free(flags);
    PyBuffer_Release(&values);
    PyBuffer_Release(&out);
    return result;
}

static PyObject *
Plan_get_n_vertices(Plan *self, void *Py_UNUSED(closure))
{
    return PyLong_FromSsize_t(self->n_vertices);
}

static PyObject *
Plan_get_n_segments(Plan *self, void *Py_UNUSED(closure))
{
    return PyLong_FromSsize_t(self->n_segments);
}

static PyMethodDef Plan_methods[] = {
    {"deform", (PyCFunction)Plan_deform, METH_VARARGS,
     "deform(values, out): write the deformed vertices (N × 3 float64, model order) into out."},
    {NULL, NULL, 0, NULL},
};

static PyGetSetDef Plan_getset[] = {
    {"n_vertices", (getter)Plan_get_n_vertices, NULL, "number of vertices", NULL},
    {"n_segments", (getter)Plan_get_n_segments, NULL, "number of segments (runs of vertices moving alike)", NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

static PyType_Slot Plan_slots[] = {
    {Py_tp_doc, "Plan(kind, parent, topo, axis, pivot, scale, direction, rest, order, segments, entries, data): "
                "the static structure of one model's deformation (see engine/deform/_kernel.c)."},
    {Py_tp_new, PyType_GenericNew},
    {Py_tp_init, Plan_init},
    {Py_tp_dealloc, Plan_dealloc},
    {Py_tp_methods, Plan_methods},
    {Py_tp_getset, Plan_getset},
    {0, NULL},
};

static PyType_Spec Plan_spec = {
    .name = "engine.deform._kernel.Plan",
    .basicsize = sizeof(Plan),
    .flags = Py_TPFLAGS_DEFAULT,
    .slots = Plan_slots,
};

static int
module_exec(PyObject *module)
{
    PyObject *type = PyType_FromSpec(&Plan_spec);
    if (type == NULL)
        return -1;
    if (PyModule_AddObject(module, "Plan", type) < 0) {
        Py_DECREF(type);
        return -1;
    }
    if (PyModule_AddIntConstant(module, "ABI", KERNEL_ABI) < 0 ||
        PyModule_AddStringConstant(module, "SOURCE_SHA256", SOURCE_SHA256) < 0)
        return -1;
    return 0;
}

static PyModuleDef_Slot module_slots[] = {
    {Py_mod_exec, module_exec},
    {0, NULL},
};

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT,
    .m_name = "engine.deform._kernel",
    .m_doc = "Compiled vertex pass of the §2.2 deformation (see engine/deform/deformer.py).",
    .m_size = 0,
    .m_slots = module_slots,
};

PyMODINIT_FUNC
PyInit__kernel(void)
{
    return PyModuleDef_Init(&module_def);
}
