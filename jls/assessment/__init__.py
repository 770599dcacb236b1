"""From response statistics to verdicts: workability per cell, leg and route
(:mod:`~jls.assessment.workability`), the tip clearance
(:mod:`~jls.assessment.tip_clearance`), winch limits and time-domain verdicts
(:mod:`~jls.assessment.winch_limits`), weather windows (:mod:`~jls.assessment.windows`)
on the hourly verdicts of a record (:mod:`~jls.assessment.hourly`; legs given by measured
spectra judged hour by hour in the workability, :mod:`~jls.assessment.measured_legs`),
the voyage extremes (:mod:`~jls.assessment.voyage`) with each criterion on its own level
(:mod:`~jls.assessment.criterion_levels`), the route simulation through hourly records
(:mod:`~jls.assessment.route_simulation`) and the route's hours
(:mod:`~jls.assessment.route_hours`), the operational basis
(:mod:`~jls.assessment.operation`), uncertainty variants and bands
(:mod:`~jls.assessment.uncertainty`, :mod:`~jls.assessment.bands`), the criterion sweep
(:mod:`~jls.assessment.criterion_sweep`) and the recommendation's rules
(:mod:`~jls.assessment.recommendation`).
"""
