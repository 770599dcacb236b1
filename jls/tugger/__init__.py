"""Damping tuggers: a setting and its winch law (:mod:`~jls.tugger.setting`) and the
frequency-domain line loads it implies (:mod:`~jls.tugger.loads`).
"""
