# SPDX-License-Identifier: GPL-2.0-or-later
"""The damage pictures the fracture examples draw with LAMMPS's dump image (damage.STEP.png,
input variable images), found in a run folder and set side by side in one figure: a crack
growing, as REPORT.md shows it."""
import re
from pathlib import Path

from bbpd import plots

PATTERN = re.compile(r"^damage\.(\d+)\.png$")
STRIP_DPI = 150
PANEL_WIDTH_IN = 1.6      # one snapshot's width in the strip, inches


def find(workdir):
    """[(step, path)] of the damage pictures in workdir, by step."""
    found = [(int(m[1]), p) for p in Path(workdir).glob("damage.*.png")
             if (m := PATTERN.match(p.name))]
    return sorted(found)


def draw_strip(frames, path, title):
    """One row of the pictures with their times: frames = [(label, png path)]."""
    if not frames:
        raise ValueError("no damage pictures to set in a row")
    images = [plots.plt.imread(str(p)) for _, p in frames]
    aspect = images[0].shape[0] / images[0].shape[1]    # height / width of one picture
    with plots.figure(path, 1, len(frames), squeeze=False, dpi=STRIP_DPI,
                      figsize=(PANEL_WIDTH_IN * len(frames), PANEL_WIDTH_IN * aspect + 0.7)) as (fig, axes):
        for ax, (label, _), image in zip(axes[0], frames, images):
            ax.imshow(image)
            ax.set_title(label, fontsize=8)
            ax.axis("off")
        fig.suptitle(title, fontsize=9)
    return path
