"""Input and output that knows nothing of physics: atomic writes (:mod:`~jls.io.atomic`),
NetCDF with provenance (:mod:`~jls.io.netcdf`), the dataset registry
(:mod:`~jls.io.registry`), a job's provenance and log (:mod:`~jls.io.provenance`), the
sea-state moment cache (:mod:`~jls.io.sea_state_cache`), file and mapping hashes
(:mod:`~jls.io.hashing`) and the one YAML reader (:mod:`~jls.io.yamlio`).
"""
