"""Make the in-repo package importable: /work/main/python on sys.path."""

import pathlib
import sys

PYTHON_DIR = pathlib.Path(__file__).resolve().parents[2] / "python"
if str(PYTHON_DIR) not in sys.path:
    sys.path.insert(0, str(PYTHON_DIR))
