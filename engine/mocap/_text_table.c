/*
 * Reading a large table of decimal numbers (motion-capture exports) in one pass.
 *
 * Built as the extension module ``engine.mocap._text_table`` by ``pip install -e .``
 * (setup.py); ``engine/mocap/text_tables.py`` uses it when it imports and falls
 * back to numpy's ``loadtxt`` otherwise. Only the Python C API and the buffer
 * protocol (no numpy headers); portable C, single thread, GIL released.
 *
 *     parse_table(text: bytes, out: writable float64 buffer, n_columns: int,
 *                 delimiter: int, empty_is_missing: bool) -> int
 *
 * ``text`` is the data part of the file, rows separated by "\n" (a "\r"
 * before it is ignored); blank rows (only spaces and tabs) are skipped. A
 * row holds exactly ``n_columns`` cells separated by the byte ``delimiter``
 * (a tab, a comma, …), or by runs of spaces and tabs when ``delimiter`` is
 * −1; spaces around a cell are allowed. With ``empty_is_missing`` an empty
 * cell is NaN, otherwise it is an irregularity. The numbers fill ``out``
 * row by row; the return value is the number of rows. Anything irregular (a
 * cell that is not a number, a row with another number of cells, more rows
 * than ``out`` holds) returns −1 − (the 0-based index of the offending
 * row), and the caller re-reads the text line by line to say what is wrong.
 *
 * Exactness. A cell is converted by the C library's ``strtod`` unless it is
 * a plain decimal ``[+-]digits[.digits]`` with at most 15 significant
 * digits (integer part and fraction together, leading zeros not counted)
 * — then its digits, read as an integer m < 2^53, and 10^k (k ≤ 15) are both
 * exact doubles and m / 10^k is one correctly rounded division: the same
 * double ``strtod`` (and Python's ``float``) gives. Everything else
 * (exponents, "nan", "inf", long mantissas) goes through ``strtod``.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifndef SOURCE_SHA256
#define SOURCE_SHA256 "unknown"
#endif

static const double POW10[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

static int is_blank(char c) { return c == ' ' || c == '\t'; }

/* Convert the cell [s, e) (no surrounding blanks, not empty). Returns 0 on success. */
static int convert(const char *s, const char *e, double *value) {
    const char *p = s;
    int negative = 0;
    if (*p == '+' || *p == '-') {
        negative = (*p == '-');
        p++;
    }
    uint64_t m = 0;
    int digits = 0, frac = 0, seen = 0, simple = 1;
    for (; p < e && *p >= '0' && *p <= '9'; p++) {
        seen = 1;
        if (m == 0 && *p == '0') continue;      /* leading zeros carry no digit */
        m = m * 10 + (uint64_t)(*p - '0');
        digits++;
    }
    if (p < e && *p == '.') {
        p++;
        for (; p < e && *p >= '0' && *p <= '9'; p++) {
            seen = 1;
            frac++;
            if (m == 0 && *p == '0') continue;
            m = m * 10 + (uint64_t)(*p - '0');
            digits++;
        }
    }
    if (p != e || !seen || digits > 15 || frac > 15) simple = 0;
    if (simple) {
        double v = (double)m;
        if (frac) v /= POW10[frac];
        *value = negative ? -v : v;
        return 0;
    }
    /* strtod needs a terminated string: copy the cell (numbers are short). */
    char buffer[128];
    size_t n = (size_t)(e - s);
    if (n >= sizeof buffer) return -1;
    memcpy(buffer, s, n);
    buffer[n] = '\0';
    char *end = NULL;
    double v = strtod(buffer, &end);
    if (end != buffer + n) return -1;
    *value = v;
    return 0;
}

/* Parse the whole text into out; see the comment at the top for the result. */
static Py_ssize_t parse(const char *text, Py_ssize_t length, double *out, Py_ssize_t capacity,
                        Py_ssize_t n_columns, int delimiter, int empty_is_missing) {
    const char *p = text, *end = text + length;
    Py_ssize_t rows = 0, row_index = 0;   /* rows written; index of the current row among all rows */
    while (p < end) {
        const char *line_end = memchr(p, '\n', (size_t)(end - p));
        if (line_end == NULL) line_end = end;
        const char *stop = line_end;
        if (stop > p && stop[-1] == '\r') stop--;
        const char *q = p;
        while (q < stop && is_blank(*q)) q++;
        if (q == stop) {                  /* blank row */
            p = line_end + 1;
            row_index++;
            continue;
        }
        if (rows >= capacity) return -1 - row_index;
        double *row = out + rows * n_columns;
        Py_ssize_t column = 0;
        const char *cell = p;
        for (;;) {
            const char *cell_end;
            if (delimiter < 0) {
                while (cell < stop && is_blank(*cell)) cell++;
                if (cell == stop) break;
                cell_end = cell;
                while (cell_end < stop && !is_blank(*cell_end)) cell_end++;
            } else {
                cell_end = memchr(cell, delimiter, (size_t)(stop - cell));
                if (cell_end == NULL) cell_end = stop;
            }
            if (column >= n_columns) return -1 - row_index;
            const char *a = cell, *b = cell_end;
            while (a < b && is_blank(*a)) a++;
            while (b > a && is_blank(b[-1])) b--;
            if (a == b) {
                if (!empty_is_missing) return -1 - row_index;
                row[column] = NAN;
            } else if (convert(a, b, &row[column]) != 0) {
                return -1 - row_index;
            }
            column++;
            if (delimiter < 0) {
                cell = cell_end;
            } else {
                if (cell_end == stop) break;
                cell = cell_end + 1;
            }
        }
        if (column != n_columns) return -1 - row_index;
        rows++;
        row_index++;
        p = line_end + 1;
    }
    return rows;
}

static PyObject *parse_table(PyObject *self, PyObject *args) {
    Py_buffer text, out;
    Py_ssize_t n_columns;
    int delimiter, empty_is_missing;
    (void)self;
    if (!PyArg_ParseTuple(args, "y*w*nip", &text, &out, &n_columns, &delimiter, &empty_is_missing))
        return NULL;
    Py_ssize_t result;
    if (n_columns <= 0 || out.len % (Py_ssize_t)(sizeof(double) * n_columns) != 0) {
        PyBuffer_Release(&text);
        PyBuffer_Release(&out);
        PyErr_SetString(PyExc_ValueError, "out must hold whole rows of n_columns float64 values");
        return NULL;
    }
    Py_ssize_t capacity = out.len / (Py_ssize_t)(sizeof(double) * n_columns);
    Py_BEGIN_ALLOW_THREADS
    result = parse((const char *)text.buf, text.len, (double *)out.buf, capacity, n_columns, delimiter,
                   empty_is_missing);
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&text);
    PyBuffer_Release(&out);
    return PyLong_FromSsize_t(result);
}

static PyMethodDef METHODS[] = {
    {"parse_table", parse_table, METH_VARARGS,
     "parse_table(text, out, n_columns, delimiter, empty_is_missing) -> rows, or -1 - bad row index"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef MODULE = {PyModuleDef_HEAD_INIT, "_text_table",
                                    "One-pass reader of decimal number tables (engine/mocap/_text_table.c).", -1,
                                    METHODS};

PyMODINIT_FUNC PyInit__text_table(void) {
    PyObject *module = PyModule_Create(&MODULE);
    if (module == NULL) return NULL;
    if (PyModule_AddStringConstant(module, "SOURCE_SHA256", SOURCE_SHA256) < 0) {
        Py_DECREF(module);
        return NULL;
    }
    return module;
}
