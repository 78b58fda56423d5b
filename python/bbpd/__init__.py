"""BBPD Python tools.

Submodules (imported explicitly, so that ``bbpd.runner`` keeps working
without numpy/scipy):
    runner   run tools/lmp on an input script
    freund   analytic DSIF references (paper eqs. 41-43, mode-II step/ramp)
    metrics  peak and L2 relative errors (eqs. 44-45)
    dsif     displacement-extrapolation DSIFs (eqs. 39-40)
    plots    K(t) plots to PNG (matplotlib, Agg)
"""
