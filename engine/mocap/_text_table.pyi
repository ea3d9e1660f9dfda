"""Type stub of the compiled table reader ``engine.mocap._text_table`` (source: ``_text_table.c``)."""

import numpy as np

SOURCE_SHA256: str

def parse_table(text: bytes, out: np.ndarray, n_columns: int, delimiter: int, empty_is_missing: bool, /) -> int:
    """Parse ``text`` into the float64 rows of ``out``; the number of rows, or ``-1 - index`` of a bad row."""
