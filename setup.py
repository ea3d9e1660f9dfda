"""Build the compiled deformation kernel; all other metadata lives in pyproject.toml.

``pip install -e .`` (``./bootstrap`` does it) compiles ``engine/_deform_kernel.c``
into the extension module ``engine._deform_kernel``. It needs a C compiler and
the Python headers (Debian: ``build-essential python3-dev``, in ``bootstrap``'s
package list). When compiling fails the install still succeeds
(``optional=True``) and ``engine.deform`` uses its numpy path; the test
``test_deform_kernel.py::test_kernel_is_built_and_current`` then reports it.
"""

import hashlib
from pathlib import Path

from setuptools import Extension, setup

SOURCE = "engine/_deform_kernel.c"
digest = hashlib.sha256((Path(__file__).parent / SOURCE).read_bytes()).hexdigest()

setup(
    ext_modules=[
        Extension(
            "engine._deform_kernel",
            sources=[SOURCE],
            # -O3 but no -march=native: the build runs on any CPU of its architecture.
            # -ffp-contract=off: no fused multiply-adds (the default on aarch64), so a vertex
            # gets the same bits in a vectorised loop body and in its scalar tail, which
            # invariant 2's bit-for-bit comparison relies on.
            extra_compile_args=["-O3", "-ffp-contract=off"],
            # lets the tests tell a stale build (C source edited, not re-installed) from a current one
            define_macros=[("SOURCE_SHA256", f'"{digest}"')],
            optional=True,
        )
    ],
)
