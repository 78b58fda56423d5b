"""The opening lines every bbpd test input shares, written once.

peri_preamble() returns the text up to the body: the plugin, SI units, the dimension and
boundary, atom_style peri with the atom map the bbpd styles need, and optionally the processor
grid, the atoms of a data file and a lattice. Imported by name (pytest.ini puts tests/lammps on
the path): `from scenes import peri_preamble`.
"""


def peri_preamble(dim=2, boundary=None, lattice=None, data=None, plugin=True, clear=False,
                  processors=None, atom_modify=""):
    """Input lines in this order: [clear] [plugin load bbpdplugin.so] units si, dimension (not
    written for 3, LAMMPS's default), boundary (default 's s p' in 2D, 's s s' in 3D),
    atom_style peri, atom_modify map array[ atom_modify], [processors P], [read_data DATA],
    [lattice LATTICE], each ending in a newline.

    plugin=False where the plugin is loaded before (a script of several sections after
    'clear') or not at all (LAMMPS's own peri styles)."""
    boundary = boundary or ("s s p" if dim == 2 else "s s s")
    lines = ["clear"] if clear else []
    if plugin:
        lines.append("plugin load bbpdplugin.so")
    lines.append("units si")
    if dim != 3:
        lines.append(f"dimension {dim}")
    lines += [f"boundary {boundary}", "atom_style peri",
              f"atom_modify map array{' ' + atom_modify if atom_modify else ''}"]
    if processors:
        lines.append(f"processors {processors}")
    if data:
        lines.append(f"read_data {data}")
    if lattice:
        lines.append(f"lattice {lattice}")
    return "\n".join(lines) + "\n"
