"""Rigging design: the screening scores (:mod:`~jls.design.scoring`), the constrained
refinement (:mod:`~jls.design.optimise`) and the screening of a design grid with its
optimum (:mod:`~jls.design.screening`).
"""
