"""Imported by every workflow script before numpy, xarray or jls's heavier modules: a job
is one short process whose modules and datasets live until it ends, so the cyclic garbage
collector runs seldom from its first import (:func:`jls.collector.collect_seldom`, which
imports only the standard library). :func:`jls.io.provenance.workflow_step` then freezes
what exists when the step starts.
"""

from _server import hand_over

hand_over()

from jls.collector import collect_seldom  # noqa: E402

collect_seldom()
