"""jls: route-specific rigging assessment for a suspended jacket in transit.

Units inside the library are t, kN, m, s, rad (1 kN = 1 t m/s^2).
"""

__version__ = "0.1.0"
