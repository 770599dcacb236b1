"""Which configuration a dataset was made from: the parts of the validated configuration
each dataset depends on (the ``config`` list of its layout in the registry,
``jls/schemas/datasets.yaml``) and their SHA-256, written into the dataset
(``config_sha256``) so that a report can tell a dataset made from another configuration."""

from __future__ import annotations

import hashlib
import json

import numpy as np

from jls.io import registry


def config_subset(cfg: dict, name: str, route: str | None = None) -> dict:
    """The parts of a validated configuration that dataset ``name`` depends on."""
    out = {}
    for part in registry.layout(name)["config"]:
        if part == "headings":
            legs = cfg["routes"][route]["legs"]
            out["headings"] = sorted({float(h) for leg in legs for h in leg["headings_deg"]})
            continue
        node, ok = cfg, True
        for key in part.replace("{route}", str(route)).split("."):
            if not isinstance(node, dict) or key not in node:
                ok = False
                break
            node = node[key]
        out[part.replace("{route}", "route")] = node if ok else None
    return out


def config_hash(cfg: dict, name: str, route: str | None = None) -> str:
    """SHA-256 of the configuration parts dataset ``name`` depends on."""
    text = json.dumps(config_subset(cfg, name, route), sort_keys=True,
                      default=lambda o: np.asarray(o).tolist())
    return hashlib.sha256(text.encode()).hexdigest()


