"""The fracture examples' damage pictures (dump image, input variable images): each input draws
them on a small grid, a few over the run and one at its end, small PNGs with the plate's long
side LONG_SIDE pixels; -var images no draws none, and the pictures change no output of the run
(the benchmarks read the dumps, which are the same bits either way)."""
import struct
from pathlib import Path

import pytest

from bbpd import runner, snapshots

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
LONG_SIDE = 600            # pixels, the inputs' imgpx
MAX_BYTES = 100_000        # a picture small enough to commit
# (input, variables of a run of a few seconds at most)
CASES = {
    "kalthoff-winkler": ("in.kalthoff_winkler", {"dx": "4.0e-3"}),
    "mode1-propagation": ("in.mode1-propagation", {"dx": "0.1"}),
    "kink-mixed-mode": ("in.kink", {"ncross": "1", "nfast": "0.5"}),
    "crack-branching": ("in.crack_branching", {"dx": "1.0e-3", "tend": "10e-6"}),
    "strip-steady-crack": ("in.strip", {"dx": "5.0e-4", "H": "0.02", "L": "0.08",
                                        "tend": "5e-6"}),
}


def png_size(path):
    """(width, height) from a PNG's IHDR chunk"""
    head = Path(path).read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is no PNG"
    return struct.unpack(">II", head[16:24])


def pictures(folder, workdir, images, version=None):
    script, variables = CASES[folder]
    runner.run_lammps(str(EXAMPLES / folder / script), workdir, vars={**variables, "images": images},
               version=version)
    return snapshots.find(workdir)


@pytest.mark.parametrize("folder", sorted(CASES))
def test_example_draws_small_pictures_over_the_run(folder, tmp_path):
    found = pictures(folder, tmp_path, "yes")
    steps = [s for s, _ in found]
    # a picture every quarter (the kink test: eighth) of the longest run, and the end
    most = 9 if folder == "kink-mixed-mode" else 5
    assert 3 <= len(found) <= most and steps[0] == 0, steps
    for _, path in found:
        width, height = png_size(path)
        assert max(width, height) == LONG_SIDE, (path.name, width, height)
        assert path.stat().st_size < MAX_BYTES, path.name
    # the last picture is the end of the run: the crack has grown, so it differs from the first
    assert found[-1][1].read_bytes() != found[0][1].read_bytes()


def test_pictures_change_no_output_and_images_no_draws_none(tmp_path):
    """negative control and invariance: the same dumps bit for bit with and without pictures"""
    on, off = tmp_path / "on", tmp_path / "off"
    assert pictures("kalthoff-winkler", on, "yes")
    assert pictures("kalthoff-winkler", off, "no") == []
    for name in ("tips.dat", "damage.dump", "final.dump"):
        assert (on / name).read_bytes() == (off / name).read_bytes(), name


def test_scripted_runs_leave_the_pictures_off(tmp_path):
    """bbpd.runner passes images no unless told: the benchmarks and tests draw nothing"""
    script, variables = CASES["kalthoff-winkler"]
    runner.run_lammps(str(EXAMPLES / "kalthoff-winkler" / script), tmp_path, vars=variables)
    assert snapshots.find(tmp_path) == []
