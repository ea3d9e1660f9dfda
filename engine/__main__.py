"""``python -m engine …`` runs the command line (``artificial-person``)."""

import sys

from engine.cli import main

sys.exit(main())
