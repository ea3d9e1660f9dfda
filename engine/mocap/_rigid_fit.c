/*
 * Kabsch's optimal rotations for many frames at once (head-motion removal, §3.1.1).
 *
 * Built as the extension module ``engine.mocap._rigid_fit`` by ``pip install -e .``
 * (setup.py); ``engine/mocap/head_motion.py`` uses it when it imports and
 * falls back to numpy's batched SVD otherwise. Only the Python C API and the
 * buffer protocol (no numpy headers); portable C, single thread, GIL released.
 *
 *     rotations(H: float64 buffer F×3×3, R: writable F×3×3, S: writable F×3) -> None
 *     move(P: float64 buffer F×M×3, A: float64 buffer F×4×4, out: writable F×M×3) -> None
 *
 * For each frame's cross-covariance H (row convention: H = Σ_k p_kᵀ q_k of
 * the centred source and target points) it writes the rotation R (det +1)
 * that minimises Σ_k |p_k R − q_k|², i.e. R = U diag(1, 1, d) Vᵀ with
 * H = U Σ Vᵀ and d = sign det(U Vᵀ), and the singular values S in
 * descending order (the caller tells collinear points by S[1] ≪ S[0]).
 *
 * The SVD is one-sided Jacobi (Hestenes): plane rotations applied to the
 * columns of H·V until they are orthogonal to working precision; then
 * σ_i = |column i| (accurate even when tiny: collinear points give
 * σ_1 ≈ 1e-16 σ_0, not the 1e-8 σ_0 of an eigen-solve on HᵀH), u_i = column
 * i / σ_i. The third left vector is taken as u_0 × u_1 so that a rank-2 H
 * (three markers, or markers in one plane) still has a full, proper U; with
 * that choice R = [u_0, u_1, det(V)·(u_0 × u_1)] Vᵀ is the Kabsch rotation,
 * whatever the sign of det H (the reflection is excluded as in Kabsch 1976).
 *
 * ``move`` applies each frame's row-vector transform to that frame's points,
 * out = P·A[:3, :3] + A[3, :3], in one pass (NaN stays NaN); numpy would
 * make several passes over the whole recording.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <string.h>

#ifndef SOURCE_SHA256
#define SOURCE_SHA256 "unknown"
#endif

#define MAX_SWEEPS 40

/* a, v: 3×3 row-major; columns j of a and v are rotated together. */
static void rotate_columns(double a[9], double v[9], int i, int j, double c, double s) {
    for (int r = 0; r < 3; r++) {
        double ai = a[3 * r + i], aj = a[3 * r + j];
        a[3 * r + i] = c * ai - s * aj;
        a[3 * r + j] = s * ai + c * aj;
        double vi = v[3 * r + i], vj = v[3 * r + j];
        v[3 * r + i] = c * vi - s * vj;
        v[3 * r + j] = s * vi + c * vj;
    }
}

static void one_frame(const double h[9], double out_r[9], double out_s[3]) {
    double a[9], v[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    memcpy(a, h, sizeof a);
    for (int sweep = 0; sweep < MAX_SWEEPS; sweep++) {
        int rotated = 0;
        for (int i = 0; i < 2; i++) {
            for (int j = i + 1; j < 3; j++) {
                double alpha = 0, beta = 0, gamma = 0;
                for (int r = 0; r < 3; r++) {
                    alpha += a[3 * r + i] * a[3 * r + i];
                    beta += a[3 * r + j] * a[3 * r + j];
                    gamma += a[3 * r + i] * a[3 * r + j];
                }
                if (gamma == 0.0 || fabs(gamma) <= 1e-15 * sqrt(alpha * beta)) continue;
                double zeta = (beta - alpha) / (2.0 * gamma);
                double t = (zeta >= 0 ? 1.0 : -1.0) / (fabs(zeta) + sqrt(1.0 + zeta * zeta));
                double c = 1.0 / sqrt(1.0 + t * t);
                rotate_columns(a, v, i, j, c, c * t);
                rotated = 1;
            }
        }
        if (!rotated) break;
    }
    double sigma[3];
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        sigma[i] = sqrt(a[i] * a[i] + a[3 + i] * a[3 + i] + a[6 + i] * a[6 + i]);
    /* sort descending; each swap flips the sign of det(V) */
    double det_v = 1.0;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2 - i; j++)
            if (sigma[order[j]] < sigma[order[j + 1]]) {
                int k = order[j];
                order[j] = order[j + 1];
                order[j + 1] = k;
                det_v = -det_v;
            }
    for (int i = 0; i < 3; i++) out_s[i] = sigma[order[i]];
    if (!(sigma[order[1]] > 0.0)) {   /* rank ≤ 1: no rotation is determined; the caller rejects the frame */
        static const double eye[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        memcpy(out_r, eye, sizeof eye);
        return;
    }
    double u0[3], u1[3], u2[3], vt[9];
    int c0 = order[0], c1 = order[1], c2 = order[2];
    for (int r = 0; r < 3; r++) {
        u0[r] = a[3 * r + c0] / sigma[c0];
        u1[r] = a[3 * r + c1] / sigma[c1];
    }
    /* re-orthonormalise u1 against u0 (Jacobi leaves them orthogonal to ~1e-15) */
    double d01 = u0[0] * u1[0] + u0[1] * u1[1] + u0[2] * u1[2];
    for (int r = 0; r < 3; r++) u1[r] -= d01 * u0[r];
    double n1 = sqrt(u1[0] * u1[0] + u1[1] * u1[1] + u1[2] * u1[2]);
    for (int r = 0; r < 3; r++) u1[r] /= n1;
    u2[0] = det_v * (u0[1] * u1[2] - u0[2] * u1[1]);
    u2[1] = det_v * (u0[2] * u1[0] - u0[0] * u1[2]);
    u2[2] = det_v * (u0[0] * u1[1] - u0[1] * u1[0]);
    /* Vᵀ with its rows in sorted order: row i of Vᵀ is column order[i] of V */
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++) vt[3 * i + c] = v[3 * c + order[i]];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            out_r[3 * r + c] = u0[r] * vt[c] + u1[r] * vt[3 + c] + u2[r] * vt[6 + c];
}

static PyObject *rotations(PyObject *self, PyObject *args) {
    Py_buffer h, r, s;
    (void)self;
    if (!PyArg_ParseTuple(args, "y*w*w*", &h, &r, &s)) return NULL;
    Py_ssize_t frames = h.len / (Py_ssize_t)(9 * sizeof(double));
    if (h.len != frames * (Py_ssize_t)(9 * sizeof(double)) || r.len != h.len
        || s.len != frames * (Py_ssize_t)(3 * sizeof(double))) {
        PyBuffer_Release(&h);
        PyBuffer_Release(&r);
        PyBuffer_Release(&s);
        PyErr_SetString(PyExc_ValueError, "H and R must be F×3×3 and S F×3 float64 buffers");
        return NULL;
    }
    const double *hp = (const double *)h.buf;
    double *rp = (double *)r.buf, *sp = (double *)s.buf;
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t f = 0; f < frames; f++) one_frame(hp + 9 * f, rp + 9 * f, sp + 3 * f);
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&h);
    PyBuffer_Release(&r);
    PyBuffer_Release(&s);
    Py_RETURN_NONE;
}

static PyObject *move(PyObject *self, PyObject *args) {
    Py_buffer p, a, out;
    (void)self;
    if (!PyArg_ParseTuple(args, "y*y*w*", &p, &a, &out)) return NULL;
    Py_ssize_t frames = a.len / (Py_ssize_t)(16 * sizeof(double));
    Py_ssize_t per_frame = frames ? p.len / frames : 0;   /* bytes of one frame's points */
    if (a.len != frames * (Py_ssize_t)(16 * sizeof(double)) || out.len != p.len
        || (frames && (p.len % frames != 0 || per_frame % (Py_ssize_t)(3 * sizeof(double)) != 0))
        || (!frames && p.len != 0)) {
        PyBuffer_Release(&p);
        PyBuffer_Release(&a);
        PyBuffer_Release(&out);
        PyErr_SetString(PyExc_ValueError, "P and out must be F×M×3 and A F×4×4 float64 buffers");
        return NULL;
    }
    Py_ssize_t markers = frames ? per_frame / (Py_ssize_t)(3 * sizeof(double)) : 0;
    const double *pp = (const double *)p.buf, *ap = (const double *)a.buf;
    double *op = (double *)out.buf;
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t f = 0; f < frames; f++) {
        const double *m = ap + 16 * f;
        for (Py_ssize_t k = 0; k < markers; k++) {
            const double *x = pp + 3 * (f * markers + k);
            double *y = op + 3 * (f * markers + k);
            double x0 = x[0], x1 = x[1], x2 = x[2];
            for (int j = 0; j < 3; j++) y[j] = x0 * m[j] + x1 * m[4 + j] + x2 * m[8 + j] + m[12 + j];
        }
    }
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&p);
    PyBuffer_Release(&a);
    PyBuffer_Release(&out);
    Py_RETURN_NONE;
}

static PyMethodDef METHODS[] = {
    {"rotations", rotations, METH_VARARGS, "rotations(H, R, S): Kabsch rotations and singular values per frame"},
    {"move", move, METH_VARARGS, "move(P, A, out): out = P·A[:3, :3] + A[3, :3] per frame"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef MODULE = {PyModuleDef_HEAD_INIT, "_rigid_fit",
                                    "Batched Kabsch rotations by one-sided Jacobi SVD (engine/mocap/_rigid_fit.c).",
                                    -1, METHODS};

PyMODINIT_FUNC PyInit__rigid_fit(void) {
    PyObject *module = PyModule_Create(&MODULE);
    if (module == NULL) return NULL;
    if (PyModule_AddStringConstant(module, "SOURCE_SHA256", SOURCE_SHA256) < 0) {
        Py_DECREF(module);
        return NULL;
    }
    return module;
}
