# jls: route-specific rigging assessment. Run: snakemake --cores 2
# Rules live in workflow/rules by stage; scripts in workflow/scripts are thin adapters
# around the jls library. The configuration is validated before anything runs.
from snakemake.utils import min_version

min_version("9.0")


configfile: "config/config.yaml"


include: "workflow/rules/common.smk"


rule all:
    input:
        expand("reports/{route}.pdf", route=ROUTES),
    default_target: True


include: "workflow/rules/sea.smk"
include: "workflow/rules/vessel.smk"
include: "workflow/rules/plant.smk"
include: "workflow/rules/response.smk"
include: "workflow/rules/assess.smk"
include: "workflow/rules/report.smk"
