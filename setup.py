"""Build the compiled kernels; all other metadata lives in pyproject.toml.

``pip install -e .`` (``./bootstrap`` does it) compiles ``engine/deform/_kernel.c``
into the extension module ``engine.deform._kernel`` (the deformation) and
``engine/mocap/_text_table.c`` into ``engine.mocap._text_table`` (reading large number
tables: motion-capture exports) and ``engine/mocap/_rigid_fit.c`` into
``engine.mocap._rigid_fit`` (Kabsch rotations of every frame: head-motion removal). They need a C compiler
and the Python headers (Debian: ``build-essential python3-dev``, in ``bootstrap``'s package list).
When compiling fails the install still succeeds (``optional=True``) and the
engine uses its numpy paths; ``test_deform_kernel.py::test_kernel_is_built_and_current``
and ``test_mocap_kernels.py::test_kernels_are_built_and_current`` then report it.
"""

import hashlib
from pathlib import Path

from setuptools import Extension, setup

SOURCE = "engine/deform/_kernel.c"
TABLE_SOURCE = "engine/mocap/_text_table.c"
RIGID_SOURCE = "engine/mocap/_rigid_fit.c"


def digest(source: str) -> str:
    return hashlib.sha256((Path(__file__).parent / source).read_bytes()).hexdigest()


setup(
    ext_modules=[
        Extension(
            "engine.deform._kernel",
            sources=[SOURCE],
            # -O3 but no -march=native: the build runs on any CPU of its architecture.
            # -ffp-contract=off: no fused multiply-adds (the default on aarch64), so a vertex
            # gets the same bits in a vectorised loop body and in its scalar tail, which
            # invariant 2's bit-for-bit comparison relies on.
            extra_compile_args=["-O3", "-ffp-contract=off"],
            # lets the tests tell a stale build (C source edited, not re-installed) from a current one
            define_macros=[("SOURCE_SHA256", f'"{digest(SOURCE)}"')],
            optional=True,
        ),
        Extension(
            "engine.mocap._text_table",
            sources=[TABLE_SOURCE],
            extra_compile_args=["-O3"],
            define_macros=[("SOURCE_SHA256", f'"{digest(TABLE_SOURCE)}"')],
            optional=True,
        ),
        Extension(
            "engine.mocap._rigid_fit",
            sources=[RIGID_SOURCE],
            extra_compile_args=["-O2"],
            define_macros=[("SOURCE_SHA256", f'"{digest(RIGID_SOURCE)}"')],
            optional=True,
        ),
    ],
)
