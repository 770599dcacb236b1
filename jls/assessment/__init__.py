"""From response statistics to verdicts: workability per cell, leg and route
(:mod:`~jls.assessment.workability`), winch limits and time-domain verdicts
(:mod:`~jls.assessment.winch_limits`), weather windows (:mod:`~jls.assessment.windows`),
uncertainty variants and bands (:mod:`~jls.assessment.uncertainty`,
:mod:`~jls.assessment.bands`), the criterion sweep (:mod:`~jls.assessment.criterion_sweep`)
and the recommendation's rules (:mod:`~jls.assessment.recommendation`).
"""
