"""error_study.py -- what the error studies against a converged image share
(denoise_study.py, adaptive_study.py): their flags and the reference, a
render of many samples with another seed, through `import wavefront`."""

import argparse
import os
import sys

from throughput import ROOT

sys.path.insert(0, os.path.join(ROOT, "build", "python"))
import wavefront  # noqa: E402  the module scripts/setup.sh builds


def study_arguments(doc, size):
    """--size, --ref-spp, --seed, --out and --plot; then works from the repository root."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=size)
    parser.add_argument("--ref-spp", type=int, default=4096)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--out")
    parser.add_argument("--plot")
    args = parser.parse_args()
    os.chdir(ROOT)
    return args


def reference_image(scene, args, **common):
    """The converged image the renders are measured against: --ref-spp samples of another seed."""
    return wavefront.render(scene, spp=args.ref_spp, seed=args.seed + 1000, **common).image
