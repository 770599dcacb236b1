"""The configuration: loading and validation against the schema
(:mod:`~jls.config.loader`), plausibility checks (:mod:`~jls.config.plausible`), relative
headings from courses (:mod:`~jls.config.headings`), the checks the workflow runs before
any job (:mod:`~jls.config.workflow_inputs`), the configuration parts each dataset depends
on (:mod:`~jls.config.dataset_hash`) and every settings object built from it
(:mod:`~jls.config.builders`). Only this package and :mod:`jls.stages` read the raw
configuration mapping.
"""
