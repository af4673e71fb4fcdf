#!/usr/bin/env python3
"""make bench-gpu: every vista bench under one GL backend (EGL: the GPU's headless path) at one
frame size, in one run, writing one report: report.json (every bench's own JSON, its command,
exit code and seconds) and report.md (a headline per bench, then the commands).

On a GPU machine:   make bench-gpu            (1920x1080, --backend egl, out/bench-gpu/)
Small, on llvmpipe: tools/bench_gpu.py --quick --size 64x36 --out /tmp/bench-gpu
The full run is sized to take under 5 minutes on a GPU; --quick keeps every bench but shrinks
its sweeps so the test can run the same script on the CPU renderer."""

import argparse
import json
import os
import subprocess
import sys
import time


def benches(size, quick):
    """(name, arguments) for each bench; sizes where a frame size makes sense."""
    if quick:
        return [
            ("frame", ["frame", "--size", size, "--frames", "2", "--warmup", "1"]),
            ("terrain", ["terrain", "--size", "129", "--poses", "2", "--frame-size", size]),
            ("lights", ["lights", "--size", size, "--frames", "1", "--lights", "64", "--sweep", "counts,classes",
                        "--sweep-lights", "64", "--methods", "tiled,clustered,hashed"]),
            ("sky", ["sky", "--size", size, "--presets", "default", "--no-clouds", "--psnr-size", "16x9"]),
            ("shadows", ["shadows", "--size", size, "--no-reference"]),
            ("grass", ["grass", "--size", size, "--frames", "1", "--densities", "8"]),
        ]
    return [
        ("frame", ["frame", "--size", size, "--frames", "16", "--warmup", "4"]),
        ("terrain", ["terrain", "--frame-size", size]),
        ("lights", ["lights", "--size", size, "--sweep", "all", "--path-frames", "64",
                    "--resolutions", "320x180,640x360,1280x720,1920x1080,2560x1440"]),
        ("sky", ["sky", "--size", size]),
        ("shadows", ["shadows", "--size", size]),
        ("grass", ["grass", "--size", size]),
    ]


def headline(name, doc):
    """One line with the bench's key figures."""
    try:
        if name == "frame":
            copy = doc["reference_copy_ms"]
            gpu = doc["summary"]["gpu_ms_median"]
            return f"frame {gpu:.3f} ms GPU = {gpu / copy if copy else 0:.1f} copies (median of {len(doc['frames'])})"
        if name == "terrain":
            return (f"{doc['triangles_median']:.0f} triangles, {doc['terrain_gpu_ms_median']:.3f} ms = "
                    f"{doc['terrain_copies']:.1f} copies, max error {doc['max_error_px']:.3f} px "
                    f"(bound {doc['error_bound_px']})")
        if name == "lights":
            parts = []
            for r in doc.get("ratios", []):
                parts.append(f"{r['lights']} lights: tiled/clustered {r['tiled_over_clustered_evaluations']:.2f}, "
                             f"hashed/clustered {r['hashed_over_clustered_evaluations']:.2f} (evaluations)")
            return "; ".join(parts) or f"{len(doc['rows'])} rows"
        if name == "sky":
            return ", ".join(f"{p['name']} {p['psnr_db_min']:.1f} dB min, {p['sky_copies']:.1f} copies"
                             for p in doc["presets"])
        if name == "shadows":
            s = doc["shimmer_fraction"]
            return (f"shimmer stabilised {s['stabilised']:.5f} / unstabilised {s['unstabilised']:.5f}, "
                    f"acne max {doc['acne_fraction_max']:.5f}")
        if name == "grass":
            return ", ".join(f"density {r['density']:g}: {r['blades']:.0f} blades, {r['copies']:.1f} copies"
                             for r in doc["rows"])
    except (KeyError, TypeError, ZeroDivisionError) as e:
        return f"(no headline: missing {e})"
    return ""


def write_atomic(path, text):
    tmp = path + ".part"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vista", default="build/vista", help="the vista executable (default build/vista)")
    ap.add_argument("--size", default="1920x1080", help="frame size WxH (default 1920x1080)")
    ap.add_argument("--backend", default="egl", choices=["egl", "osmesa"], help="GL context (default egl)")
    ap.add_argument("--out", default="out/bench-gpu", help="report directory (default out/bench-gpu)")
    ap.add_argument("--quick", action="store_true", help="every bench, small sweeps (the test on llvmpipe)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds one bench may run (default 600)")
    a = ap.parse_args()
    if not os.access(a.vista, os.X_OK):
        print(f"bench_gpu.py: --vista {a.vista}: not an executable; build first (make build)", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    report = {"size": a.size, "backend": a.backend, "quick": a.quick, "benches": {}}
    start = time.monotonic()
    failed = []
    for name, args in benches(a.size, a.quick):
        out_json = os.path.join(a.out, f"{name}.json")
        cmd = [a.vista, "bench"] + args + ["--backend", a.backend, "--json", out_json]
        if name == "lights":
            cmd += ["--charts", a.out]
        t0 = time.monotonic()
        print(f"bench_gpu.py: {' '.join(cmd)}", flush=True)
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout)
            code, output = p.returncode, p.stdout + p.stderr
        except subprocess.TimeoutExpired as e:
            code, output = 124, f"timed out after {a.timeout} s\n{e.stdout or ''}"
        seconds = time.monotonic() - t0
        entry = {"command": cmd, "exit_code": code, "seconds": round(seconds, 2)}
        if code == 0 and os.path.exists(out_json):
            with open(out_json) as f:
                entry["result"] = json.load(f)
            entry["headline"] = headline(name, entry["result"])
        else:
            failed.append(name)
            entry["output_tail"] = output[-4000:]
        write_atomic(os.path.join(a.out, f"{name}.txt"), output)
        report["benches"][name] = entry
        print(f"bench_gpu.py: {name}: exit {code}, {seconds:.1f} s", flush=True)
    report["total_seconds"] = round(time.monotonic() - start, 2)
    renderer = next((b["result"].get("renderer", "") for b in report["benches"].values() if "result" in b), "")
    report["renderer"] = renderer

    md = [f"# vista bench-gpu report", "",
          f"{a.size}, backend {a.backend}, renderer {renderer or '?'}; {report['total_seconds']:.0f} s in all"
          + (" (quick sweeps)" if a.quick else ""), "",
          "| bench | exit | seconds | key figures |", "|---|---|---|---|"]
    for name, b in report["benches"].items():
        md.append(f"| {name} | {b['exit_code']} | {b['seconds']:.1f} | {b.get('headline', 'failed: see ' + name + '.txt')} |")
    md += ["", "Each bench's full output is NAME.txt and its JSON NAME.json beside this file; the lights charts "
           "are lights_*.png. Costs in copies are ratios to a full-screen RGBA16F copy measured in the same run.", "",
           "## Commands", ""]
    for name, b in report["benches"].items():
        md.append(f"- {name}: `{' '.join(b['command'])}`")
    write_atomic(os.path.join(a.out, "report.json"), json.dumps(report, indent=2) + "\n")
    write_atomic(os.path.join(a.out, "report.md"), "\n".join(md) + "\n")
    print(f"bench_gpu.py: wrote {a.out}/report.json and report.md ({report['total_seconds']:.0f} s)")
    if failed:
        print(f"bench_gpu.py: failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
