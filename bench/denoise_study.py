#!/usr/bin/env python3
"""denoise_study.py -- how much nearer Open Image Denoise brings a render to
the converged image (issue 30, item 1): the relMSE against a --ref-spp
reference of the noisy and of the denoised image at 4, 16 and 64 spp, and the
denoiser's time, on the Cornell box, its glass-sphere variant and the
textured DamagedHelmet (under a uniform white sky). relMSE is the renderer's
own (host/image/error_metrics.h): the mean over pixels and channels of
(x - y)^2 / (y^2 + 0.01). Every image comes from `import wavefront`
(render(..., denoise=True) returns both); the noisy images are the
renderer's at the same seed, so the pair differs by the denoiser alone.
Writes a Markdown table to stdout (or --out) and a log-log plot (--plot).

Usage: python3 bench/denoise_study.py [--size N] [--ref-spp N] [--seed S]
                                      [--out denoise.md] [--plot denoise.png]
       (about 5 minutes on 2 cores at the defaults; needs scripts/setup.sh's
       build/oidn-venv, and python3-matplotlib for the plot)
"""

import sys

import numpy as np

from error_study import reference_image, study_arguments, wavefront
from throughput import REAL

SCENES = [  # name, path from the repository root, extra keywords
    ("Cornell box", "scenes/cornell-box.gltf", {}),
    ("Cornell box, glass sphere", "scenes/cornell-glass.gltf", {}),
    ("DamagedHelmet", REAL + "DamagedHelmet/DamagedHelmet.glb", {"env_uniform": 1.0}),
]
SPPS = [4, 16, 64]


def relmse(image, reference):
    return float(np.mean((image - reference) ** 2 / (reference ** 2 + 0.01)))


def main():
    args = study_arguments(__doc__, size=256)

    rows, curves, device = [], {}, ""
    for name, path, extra in SCENES:
        scene = wavefront.load_scene(path)
        common = dict(width=args.size, height=args.size, quiet=True, **extra)
        reference = reference_image(scene, args, **common)
        curves[name] = []
        for spp in SPPS:
            r = wavefront.render(scene, spp=spp, seed=args.seed, denoise=True, **common)
            noisy, denoised = relmse(r.noisy, reference), relmse(r.image, reference)
            curves[name].append((spp, noisy, denoised))
            device = r.device
            rows.append(f"| {name} | {spp} | {noisy:.3g} | {denoised:.3g} | {noisy / denoised:.1f}x | "
                        f"{r.stats.seconds:.2f} | {r.denoise_seconds:.2f} |")
            print(rows[-1], file=sys.stderr)

    lines = [f"`python3 bench/denoise_study.py --size {args.size} --ref-spp {args.ref_spp} --seed {args.seed}`: "
             f"{args.size}x{args.size}, references of {args.ref_spp} spp at another seed; Open Image Denoise "
             f"2.5.1's RT filter (pyoidn's CPU device), hdr, albedo and normal prefiltered; device {device}.",
             "",
             "| scene | spp | relMSE, noisy | relMSE, denoised | nearer by | render s | denoise s |",
             "|---|--:|--:|--:|--:|--:|--:|"] + rows
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    else:
        print(text)

    if args.plot:
        import matplotlib
        import matplotlib.ticker
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for (name, points), colour in zip(curves.items(), ["C0", "C1", "C2"]):
            spp = [p[0] for p in points]
            ax.loglog(spp, [p[1] for p in points], "o--", color=colour, label=f"{name}, noisy")
            ax.loglog(spp, [p[2] for p in points], "s-", color=colour, label=f"{name}, denoised")
        ax.set_xlabel("samples per pixel")
        ax.set_ylabel(f"relMSE against {args.ref_spp} spp")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xticks(SPPS, [str(s) for s in SPPS])
        ax.legend(fontsize=7, loc="lower left")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)


if __name__ == "__main__":
    main()
