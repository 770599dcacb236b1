"""The compiled solver kernels are what their generator writes: regenerating them from the
template in ``scripts/make_frequency_domain_kernels.py`` changes nothing."""

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GENERATOR = ROOT / "scripts" / "make_frequency_domain_kernels.py"


def _generator():
    spec = importlib.util.spec_from_file_location("make_frequency_domain_kernels", GENERATOR)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_kernels_equal_their_regeneration():
    gen = _generator()
    text = gen.MODULE.read_text()
    assert gen.BANNER in text, "the kernels module lacks the banner naming its generator"
    assert gen.generate(text) == text, ("jls/response/kernels.py differs from what "
                                        "scripts/make_frequency_domain_kernels.py writes; "
                                        "edit the template and rerun the script")


def test_a_hand_edit_of_a_kernel_is_found():
    gen = _generator()
    text = gen.MODULE.read_text()
    edited = text.replace("d0 = complex(a00.real * r, -a00.imag * r)", "d0 = complex(a00.real * r, a00.imag * r)", 1)
    assert edited != text
    assert gen.generate(edited) != edited
