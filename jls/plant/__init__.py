"""The suspended jacket's plant: rigging geometry (:mod:`~jls.plant.rigging`), static
equilibrium (:mod:`~jls.plant.equilibrium`), the linearised matrices
(:mod:`~jls.plant.linearise`), the plant M, C, K, Kb and its modes
(:mod:`~jls.plant.model`, :mod:`~jls.plant.modes`), the safety constraints
(:mod:`~jls.plant.feasibility`), the rigging candidates with their dataset
(:mod:`~jls.plant.candidates`), the study's z-down frame and its conversion
(:mod:`~jls.plant.study_frame`) and the targets of the reconstructed baseline layout
(:mod:`~jls.plant.reconstruction`).
"""
