"""python -m stickslip.schema --write  (from the repository root): regenerate the config's JSON schema."""

import sys

from . import SCHEMA_PATH, schema_text

if sys.argv[1:] == ["--write"]:
    SCHEMA_PATH.write_text(schema_text())
else:
    sys.stdout.write(schema_text())
