#!/usr/bin/env python3
"""sampler_study.py -- the sampler chosen by efficiency: independent
(hashed) numbers against Owen-scrambled Sobol points (--sampler), measured by
1 / (relMSE x seconds) at equal work on the Cornell box, its glass sphere,
Veach's MIS scene, MetalRoughSpheresNoTextures and ToyCar, as
roulette_study.py measures the roulette rules (its efficiency_table: one
reference a scene, interleaved rounds, medians). Prints a Markdown table.

Usage: python3 bench/sampler_study.py [--size N] [--spp N] [--ref-spp N] [--rounds N]
       (about 8 minutes on 2 cores at the defaults; run it on an idle machine)
"""

from roulette_study import efficiency_table, study_arguments
from throughput import REAL

SCENES = [  # name, path from the repository root
    ("Cornell box", "scenes/cornell-box.gltf"),
    ("Cornell box, glass sphere", "scenes/cornell-glass.gltf"),
    ("Veach MIS", "scenes/veach-mis.gltf"),
    ("MetalRoughSpheresNoTextures", REAL + "MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf"),
    ("ToyCar", REAL + "ToyCar/ToyCar.gltf"),
]
CONFIGS = [  # label, flags
    ("independent", ["--sampler", "independent"]),
    ("sobol", ["--sampler", "sobol"]),
]

if __name__ == "__main__":
    efficiency_table(SCENES, CONFIGS, study_arguments(__doc__), "sampler")
