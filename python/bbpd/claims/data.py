# SPDX-License-Identifier: GPL-2.0-or-later
"""The reference data the blocks are rendered from: the result CSVs of tools/reproduce,
committed under examples/<benchmark>/results/, and the quick start's step times."""
import shutil
from pathlib import Path

from bbpd.jobs import ROOT
from bbpd.csvfile import comment, read_csv

# benchmark (report/results/<benchmark>.csv) -> committed reference copy
REFERENCES = {
    "dispersion": ROOT / "examples" / "dispersion-1d" / "results" / "dispersion.csv",
    "mode1": ROOT / "examples" / "mode1-semi-infinite" / "results" / "mode1.csv",
    "mode2": ROOT / "examples" / "mode2-central-crack" / "results" / "mode2.csv",
    "kalthoff_winkler": ROOT / "examples" / "kalthoff-winkler" / "results" /
    "kalthoff_winkler.csv",
}
STEP_TIMES = ROOT / "doc" / "results" / "quickstart_times.csv"
# made by other commands, named in their first line
OTHERS = {"mode1_tips": ROOT / "examples" / "mode1-semi-infinite" / "results" / "tips.csv"}


class Data:
    """Rows of every reference file, read once: data.rows("mode2"), data.comments("mode2")."""

    def __init__(self, references=None, step_times=STEP_TIMES):
        self.paths = dict(REFERENCES if references is None else references)
        self.paths.update(OTHERS)
        self.paths["quickstart_times"] = Path(step_times)
        self._cache = {}

    def _read(self, name):
        if name not in self._cache:
            path = self.paths[name]
            if not path.is_file():
                raise FileNotFoundError(f"{path.relative_to(ROOT)} is missing: make it with "
                                        "tools/reproduce, then python -m bbpd.claims --from report")
            self._cache[name] = read_csv(path)
        return self._cache[name]

    def rows(self, name):
        return self._read(name)[1]

    def comments(self, name):
        return self._read(name)[0]

    def cpu(self, name):
        """The CPU model named in the file's 'machine:' line."""
        return (comment(self.comments(name), "machine") or "an unnamed CPU").split(",")[0]

    def source(self, name):
        """'examples/.../x.csv (made by: ...)' for the notes under a table."""
        made = next((c for c in self.comments(name) if c.startswith("made by:")), "")
        path = self.paths[name]
        path = path.relative_to(ROOT) if ROOT in path.parents else path
        return f"`{path}` ({made})" if made else f"`{path}`"


def import_report(report_dir):
    """Copy report_dir/results/<benchmark>.csv over the committed references; returns the
    paths written."""
    written = []
    for name, dest in REFERENCES.items():
        src = Path(report_dir) / "results" / f"{name}.csv"
        if src.is_file():
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, dest)
            written.append(dest)
    return written
