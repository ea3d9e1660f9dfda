"""``python -m engine …`` runs the command line (``artificial-person``)."""

import sys

from .cli import main

sys.exit(main())
