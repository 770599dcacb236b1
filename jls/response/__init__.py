"""Frequency-domain response of the plant to the hinge's motion: the solver and its
compiled kernels (:mod:`~jls.response.solver`, :mod:`~jls.response.kernels`), short-term
statistics (:mod:`~jls.response.statistics`), the RAO-range check
(:mod:`~jls.response.coverage`), wire tensions (:mod:`~jls.response.tension`,
:mod:`~jls.response.wire_loads`) and the unit-Hs moments and statistics of a set of
candidates (:mod:`~jls.response.moments`).
"""
