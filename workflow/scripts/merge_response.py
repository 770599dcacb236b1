"""Snakemake adapter: the legs' response files -> results/<route>/response.nc."""

from functools import reduce

from jls import registry
from jls.netcdf import read, write
from jls.provenance import workflow_step

sm = snakemake  # noqa: F821 - injected by Snakemake
with workflow_step(sm.log[0], "merge_response") as log:
    parts = [read(p) for p in sm.input]
    merged = reduce(lambda a, b: a.combine_first(b), parts)
    merged.attrs = {k: v for k, v in parts[0].attrs.items() if not k.startswith("input_sha256")}
    log.info("merged %d files: %d Tz values, headings %s", len(parts), merged.sizes["tz"],
             merged["heading"].values.tolist())
    write(merged, sm.output[0], config_sha256=registry.config_hash(sm.config, "response", sm.wildcards.route), created_by="rule merge_response")
