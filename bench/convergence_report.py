#!/usr/bin/env python3
"""convergence_report.py -- writes the markdown report of the equal-time study
that bench/convergence.sh runs: the machine and device, the commands, the
check of each scene's reference pair, and per scene a table of the techniques
sorted by relMSE at their final checkpoint, with their efficiency, and the plot.

It reads the CSVs of `wavefront render --report`, each with the render's
stdout next to it (same stem, .txt), named as convergence.sh names them:
study renders <scene>-<light>-<hemisphere>-<sampler>.csv, the second reference
rendered with --reference the first. convergence.sh is its only caller:

  convergence_report.py OUT.md --commands FILE --render-seconds S --size N
      --ref-seeds A B --seed N --load-at-start "L1 L5 L15"
      --scene NAME PLOT.png REF_A.csv REF_B.csv CSV ...   (once per scene)
"""

import argparse
import csv
import datetime
import os
import platform
import subprocess

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# relMSE(A, B) is about est(A) + est(B) when the two differ only by noise. The
# estimate (s²/n per pixel) overstates a Sobol render's error, which lowers the
# ratio; a ratio above this says the references disagree beyond their noise.
AGREEMENT_TOLERANCE = 1.5


def final_checkpoint(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: float(v) if v else None for k, v in rows[-1].items()}


def render_log_line(csv_path, key):
    """The line of the render's closing report that starts with `key`."""
    with open(os.path.splitext(csv_path)[0] + ".txt") as f:
        for line in f:
            if line.startswith(key + " "):
                return line[len(key):].strip()
    return "?"


def command_output(*args):
    try:
        return subprocess.run(args, cwd=REPO, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError) as e:
        return f"({' '.join(args)} failed: {e})"


def cpu_model():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return platform.processor() or "?"


def memory_gib():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) / 2**20
    return float("nan")


def code_block(text):
    return ["```", text, "```"]


def machine_section(args, device):
    return [
        "## Machine",
        "",
        f"- CPU: {cpu_model()}, {os.cpu_count()} logical CPUs, {memory_gib():.0f} GiB memory; "
        f"{platform.system()} {platform.release()} {platform.machine()}",
        f"- load average at the start (1, 5, 15 min): {args.load_at_start}",
        f"- device the renders used: {device}",
        "- OpenCL devices (`build/wavefront devices`):",
        "",
        *code_block(command_output("build/wavefront", "devices")),
        "",
    ]


def reference_section(scenes, ref_seeds):
    lines = [
        "## References",
        "",
        f"Two per scene, A (seed {ref_seeds[0]}) and B (seed {ref_seeds[1]}), rendered with mis, cosine, sobol. "
        "Each one's relMSE is estimated from its own per-pixel variance (s²/n); B is also measured against A. "
        "When the two differ only by their noise, relMSE(A, B) ≈ est(A) + est(B), i.e. about twice either; "
        f"the pair agrees if the ratio is at most {AGREEMENT_TOLERANCE} (below 1 is expected: "
        "s²/n overstates a Sobol render's error).",
        "",
        "| scene | spp | seconds A, B | est. relMSE A | est. relMSE B | relMSE(A, B) | ratio | agrees |",
        "|---|--:|--:|--:|--:|--:|--:|---|",
    ]
    for scene in scenes:
        a, b = final_checkpoint(scene["ref_a"]), final_checkpoint(scene["ref_b"])
        ratio = b["relmse"] / (a["relmse_estimate"] + b["relmse_estimate"])
        verdict = "yes" if ratio <= AGREEMENT_TOLERANCE else "**no**: bias or fireflies beyond the noise"
        lines.append(f"| {scene['name']} | {a['spp']:.0f} | {a['seconds']:.1f}, {b['seconds']:.1f} "
                     f"| {a['relmse_estimate']:.3e} | {b['relmse_estimate']:.3e} | {b['relmse']:.3e} "
                     f"| {ratio:.2f} | {verdict} |")
    lines.append("")
    return lines


def scene_section(scene, out_dir):
    # Half of relMSE(A, B) measures A's own error; the s²/n estimate overstates Sobol's.
    floor = final_checkpoint(scene["ref_b"])["relmse"] / 2
    rows = []
    for path in scene["csvs"]:
        technique = os.path.basename(path)[len(scene["name"]) + 1:-len(".csv")].split("-")
        final = final_checkpoint(path)
        rows.append((technique, final, 1.0 / (final["relmse"] * final["seconds"])))
    rows.sort(key=lambda row: row[1]["relmse"])
    best = max(efficiency for _, _, efficiency in rows)

    lines = [
        f"## {scene['name']}",
        "",
        "At the final checkpoint of each render, sorted by relMSE. Efficiency is 1/(relMSE · seconds), "
        "relative to the best. Reference A's own error is in every measurement (relMSE against A ≈ the "
        f"render's + A's); half of relMSE(A, B), {floor:.2e}, measures it, and is given as a share of each relMSE.",
        "",
        "| light sampling | hemisphere | sampler | spp | seconds | relMSE | MSE | efficiency | relative | A's share |",
        "|---|---|---|--:|--:|--:|--:|--:|--:|--:|",
    ]
    for (light, hemisphere, sampler), final, efficiency in rows:
        lines.append(f"| {light} | {hemisphere} | {sampler} | {final['spp']:.0f} | {final['seconds']:.2f} "
                     f"| {final['relmse']:.3e} | {final['mse']:.3e} | {efficiency:.3g} "
                     f"| {efficiency / best:.3f} | {floor / final['relmse']:.1%} |")
    plot = os.path.relpath(scene["plot"], out_dir)
    lines += ["", f"![{scene['name']}: relMSE against time, all 12 techniques]({plot})", ""]
    return lines


def main():
    parser = argparse.ArgumentParser(description="Write the markdown report of bench/convergence.sh.")
    parser.add_argument("output", metavar="OUT.md")
    parser.add_argument("--commands", required=True)
    parser.add_argument("--render-seconds", required=True)
    parser.add_argument("--size", required=True)
    parser.add_argument("--ref-seeds", nargs=2, required=True)
    parser.add_argument("--seed", required=True)
    parser.add_argument("--load-at-start", required=True)
    parser.add_argument("--scene", nargs="+", action="append", required=True,
                        metavar="NAME PLOT.png REF_A.csv REF_B.csv CSV")
    args = parser.parse_args()
    scenes = [{"name": s[0], "plot": s[1], "ref_a": s[2], "ref_b": s[3], "csvs": s[4:]} for s in args.scene]

    ref_spp = final_checkpoint(scenes[0]["ref_a"])["spp"]
    with open(args.commands) as f:
        commands = f.read().strip()
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# Equal-time convergence of the sampling techniques",
        "",
        f"Written by `bench/convergence.sh` on {now}, at commit "
        f"`{command_output('git', 'describe', '--always', '--dirty')}`. "
        f"Every image is {args.size}×{args.size}. Each of the 12 combinations of light sampling "
        "(bsdf, nee, mis), hemisphere sampling (uniform, cosine) and sampler (independent, sobol) "
        f"renders for {args.render_seconds} s with seed {args.seed}, against reference A of its scene, "
        f"which has {ref_spp:.0f} spp.",
        "",
        *machine_section(args, render_log_line(scenes[0]["csvs"][0], "device")),
        *reference_section(scenes, args.ref_seeds),
    ]
    out_dir = os.path.dirname(os.path.abspath(args.output))
    for scene in scenes:
        lines += scene_section(scene, out_dir)
    lines += ["## Commands", "", "From the repository root, in order:", "", *code_block(commands), ""]
    with open(args.output, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
