#!/usr/bin/env python3
"""tools/check_layers.py fails on a back edge: in a temporary copy of the sources, an #include
against the layering is planted (and, separately, a KNOWN edge removed); the script must fail
and name the file, line and layers, and pass on the untouched copy.

    python3 tests/layers/plant_back_edge.py ROOT
"""
import os
import shutil
import subprocess
import sys
import tempfile

FOLDERS = ["app", "config", "postfx", "renderer", "sky", "terrain", "tools"]
SOURCES = (".h", ".hpp", ".cpp", ".c", ".glsl", ".py")


def copy_sources(root, to):
    def ignore(directory, names):
        return [n for n in names if not os.path.isdir(os.path.join(directory, n)) and not n.endswith(SOURCES)]
    for folder in FOLDERS:
        shutil.copytree(os.path.join(root, folder), os.path.join(to, folder), ignore=ignore)


def check(root):
    run = subprocess.run([sys.executable, os.path.join(root, "tools", "check_layers.py"), root],
                         capture_output=True, text=True)
    return run.returncode, run.stdout + run.stderr


def plant(path, line):
    """Inserts line after the first #include of path; returns its line number."""
    with open(path, encoding="utf-8") as f:
        lines = f.readlines()
    at = next(i for i, l in enumerate(lines) if l.startswith("#include")) + 1
    lines.insert(at, line + "\n")
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(lines)
    return at + 1


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        copy_sources(root, tmp)
        rc, out = check(tmp)
        if rc != 0:
            failures.append(f"the untouched copy fails (rc {rc}):\n{out}")

        # Lower layers reaching up: the sky into the app, the renderer core into a feature, a
        # feature into the scene's aggregate, a feature into another it may not use.
        planted = [("sky/atmosphere.h", "app/frame.h", "sky"),
                   ("renderer/frame_graph.cpp", "sky/atmosphere.h", "renderer"),
                   ("postfx/bloom.h", "config/settings.h", "postfx"),
                   ("terrain/grass/grass.cpp", "terrain/water/water.h", "terrain/grass")]
        for path, include, layer in planted:
            number = plant(os.path.join(tmp, path), f'#include "{include}"')
            rc, out = check(tmp)
            expected = f"{path}:{number}: {layer} may not include {include}"
            if rc != 1 or expected not in out:
                failures.append(f"planting {include} in {path}: rc {rc}, expected a line with '{expected}':\n{out}")
            shutil.copy(os.path.join(root, path), os.path.join(tmp, path))

    with tempfile.TemporaryDirectory() as tmp:
        # A KNOWN edge that is gone must be deleted from the list (so the list only shrinks).
        copy_sources(root, tmp)
        sys.dont_write_bytecode = True  # no __pycache__ in the checkout
        sys.path.insert(0, os.path.join(root, "tools"))
        import check_layers
        if check_layers.KNOWN:
            path, include = sorted(check_layers.KNOWN)[0]
            full = os.path.join(tmp, path)
            with open(full, encoding="utf-8") as f:
                text = f.read()
            with open(full, "w", encoding="utf-8") as f:
                f.write(text.replace(f'#include "{include}"', f"// (removed) {include}"))
            rc, out = check(tmp)
            expected = f"KNOWN lists {path} -> {include}, which no longer exists"
            if rc != 1 or expected not in out:
                failures.append(f"removing the known edge {path} -> {include}: rc {rc}, expected '{expected}':\n{out}")

    for failure in failures:
        print(failure)
    print(f"plant_back_edge: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
