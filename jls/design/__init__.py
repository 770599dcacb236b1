"""Rigging design: the screening scores (:mod:`~jls.design.scoring`), the constrained
refinement (:mod:`~jls.design.optimise`), the one-at-a-time sensitivity of the natural
periods (:mod:`~jls.design.sensitivity`), the screening of a design grid with its optimum
(:mod:`~jls.design.screening`) and the margin sweep (:mod:`~jls.design.margins`).
"""
