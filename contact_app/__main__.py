"""``python -m contact_app``: the command-line interface of :mod:`contact_app.cli`."""

import sys

from contact_app.cli import main

sys.exit(main())
