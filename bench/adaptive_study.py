#!/usr/bin/env python3
"""adaptive_study.py -- what adaptive sampling (--adaptive) buys at equal
time (issue 30, item 2): on each scene, the relMSE against a --ref-spp
reference of a uniform render followed round by round (error against time),
and of adaptive renders to three targets; each adaptive render's error is
set against the uniform render's at the same time, interpolated log-log
between its checkpoints. Times are the renders' own (from the first round,
no kernel build). relMSE is the renderer's (host/image/error_metrics.h).
Writes a Markdown table to stdout (or --out) and a log-log plot (--plot).

Usage: python3 bench/adaptive_study.py [--size N] [--ref-spp N] [--seed S]
                                       [--out adaptive.md] [--plot adaptive.png]
       (about 12 minutes on 2 cores at the defaults; python3-matplotlib for the plot)
"""

import math
import sys

from error_study import reference_image, study_arguments, wavefront
from throughput import REAL

SCENES = [  # name, path from the repository root, extra keywords
    ("Cornell box", "scenes/cornell-box.gltf", {}),
    ("Cornell box, small light", "scenes/cornell-box-small-light.gltf", {}),
    ("Cornell box, glass sphere", "scenes/cornell-glass.gltf", {}),
    ("MetalRoughSpheresNoTextures", REAL + "MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf", {}),
    ("ToyCar", REAL + "ToyCar/ToyCar.gltf", {}),
]
UNIFORM_SPP = 1024  # the uniform render's last round; the adaptive renders' cap
TARGET_SPPS = [64, 128, 256]  # the targets: the uniform render's estimated relMSE at these spp


def log_interpolate(points, t):
    """The error at time t on a curve of (seconds, relMSE), log-log; None outside it."""
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if t0 <= t <= t1:
            f = (math.log(t) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp(math.log(e0) + f * (math.log(e1) - math.log(e0)))
    return None


def main():
    args = study_arguments(__doc__, size=128)

    rows, curves, device = [], {}, ""
    for name, path, extra in SCENES:
        scene = wavefront.load_scene(path)
        common = dict(width=args.size, height=args.size, quiet=True, **extra)
        reference = reference_image(scene, args, **common)
        uniform = wavefront.render(scene, spp=UNIFORM_SPP, seed=args.seed, reference=reference, **common)
        device = uniform.device
        points = [(c.seconds, c.relmse) for c in uniform.checkpoints if c.spp >= 16]
        estimates = {c.spp: c.relmse_estimate for c in uniform.checkpoints}
        curves[name] = {"uniform": points, "adaptive": []}
        for spp in TARGET_SPPS:
            target = estimates[spp]
            r = wavefront.render(scene, spp=UNIFORM_SPP, seed=args.seed, reference=reference, adaptive=True,
                                 target_error=target, aov="samples", **common)
            last = r.checkpoints[-1]
            counts = r.aovs["samples"]
            at_equal_time = log_interpolate(points, last.seconds)
            curves[name]["adaptive"].append((last.seconds, last.relmse))
            rows.append((name, spp, target, last.seconds, last.relmse, float(counts.mean()), int(counts.min()),
                         int(counts.max()), at_equal_time))
            print(rows[-1], file=sys.stderr)

    lines = [f"Device: {device}. {args.size}x{args.size}; reference {args.ref_spp} spp (another seed); "
             f"uniform to {UNIFORM_SPP} spp, adaptive capped there. Target: the uniform render's estimated "
             "relMSE at the spp named. Gain: the uniform render's relMSE at the adaptive render's time "
             "(log-log between its checkpoints) over the adaptive render's.", "",
             "| scene | target (uniform's at) | adaptive s | adaptive relMSE | spp mean (min-max) | "
             "uniform relMSE then | gain |", "|---|--:|--:|--:|--:|--:|--:|"]
    for name, spp, target, seconds, err, mean, lo, hi, uniform_err in rows:
        gain = f"{uniform_err / err:.2f}x" if uniform_err else "(outside the uniform curve)"
        ue = f"{uniform_err:.3g}" if uniform_err else "-"
        lines.append(f"| {name} | {target:.3g} ({spp} spp) | {seconds:.2f} | {err:.3g} | {mean:.0f} ({lo}-{hi}) | "
                     f"{ue} | {gain} |")
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    print(text)

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, len(curves), figsize=(4 * len(curves), 3.6))
        for ax, (name, c) in zip(axes, curves.items()):
            t, e = zip(*c["uniform"])
            ax.loglog(t, e, "o-", label="uniform")
            t, e = zip(*c["adaptive"])
            ax.loglog(t, e, "s", label="adaptive")
            ax.set_title(name, fontsize=9)
            ax.set_xlabel("seconds")
            ax.grid(True, which="both", alpha=0.3)
        axes[0].set_ylabel("relMSE")
        axes[0].legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)


if __name__ == "__main__":
    main()
