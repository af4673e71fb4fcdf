#!/usr/bin/env python3
"""The layering of vista's folders, checked on every #include "..." of the sources.

Each folder is a layer that may include only the layers listed for it in ALLOWED (and itself).
config/ is split in two: its machinery (the visitor, file IO, input errors) sits at the bottom;
the scene (config/settings.h, ini, presets: the one Settings aggregate of every feature's
settings struct) sits just under app/, since it names every feature. The build mirrors the table
(CMakeLists.txt): one static library per layer, linked to the layers it may use, whose headers
reach the compiler only through build/layers/; tests/layers/plant_back_edge.py checks that this
script fails on a planted back edge.

An include against these rules is a back edge. The ones that exist today are listed in KNOWN,
each with what removes it (issue 26 #5); a new one fails, and so does a KNOWN entry that is
gone (delete its line, so the list only shrinks). Exit 0 clean, 1 with the edges named.

    python3 tools/check_layers.py [ROOT]
"""
import os
import re
import sys

# Most specific first: a file belongs to the first layer whose prefix it has.
LAYERS = [
    ("config/scene", ("config/settings.", "config/ini.", "config/presets.")),
    ("config", ("config/",)),
    ("renderer/lighting", ("renderer/lighting/",)),
    ("renderer/shadows", ("renderer/shadows/",)),
    ("renderer/meshes", ("renderer/meshes/",)),
    ("renderer", ("renderer/",)),
    ("terrain/grass", ("terrain/grass/",)),
    ("terrain/water", ("terrain/water/",)),
    ("terrain", ("terrain/",)),
    ("sky/clouds", ("sky/clouds/",)),
    ("sky/weather", ("sky/weather/",)),
    ("sky", ("sky/",)),
    ("postfx", ("postfx/",)),
    ("app", ("app/",)),
]

CORE = ["renderer", "config"]
ALLOWED = {
    "config": [],
    "renderer": ["config"],
    "renderer/shadows": CORE,
    "sky": CORE,
    "renderer/lighting": ["renderer/shadows", "sky"] + CORE,
    "terrain": ["renderer/shadows", "renderer/meshes"] + CORE,  # meshes: scatter places what Objects draws
    "terrain/grass": ["terrain", "renderer/shadows"] + CORE,
    "sky/clouds": ["sky"] + CORE,
    "sky/weather": ["sky/clouds", "sky", "terrain", "renderer/lighting"] + CORE,
    "terrain/water": ["sky/weather", "sky", "terrain", "renderer/lighting", "renderer/shadows"] + CORE,
    "postfx": CORE,
    "renderer/meshes": CORE,
    "app": [name for name, _ in LAYERS],
}
# The scene's Settings gathers every feature's settings struct (each beside its feature).
ALLOWED["config/scene"] = [name for name, _ in LAYERS if name not in ("config/scene", "app")]

# Back edges that exist today: (including file, included file) -> what removes it (issue 26 #5).
# The build links them too (CMakeLists.txt, "Back edge (KNOWN)").
KNOWN = {
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCE_ENDINGS = (".h", ".hpp", ".cpp", ".c", ".glsl")


def layer_of(path):
    for name, prefixes in LAYERS:
        if path.startswith(prefixes):
            return name
    return None


def back_edges(root):
    found = {}
    for folder in sorted({prefix.split("/")[0] for _, prefixes in LAYERS for prefix in prefixes}):
        for directory, _, files in os.walk(os.path.join(root, folder)):
            for name in sorted(files):
                if not name.endswith(SOURCE_ENDINGS):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root).replace(os.sep, "/")
                source = layer_of(path)
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = layer_of(m.group(1))
                        if target is None or target == source or target in ALLOWED[source]:
                            continue
                        found.setdefault((path, m.group(1)), f"{path}:{number}: {source} may not include {m.group(1)} ({target})")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    found = back_edges(root)
    new = [message for edge, message in sorted(found.items()) if edge not in KNOWN]
    gone = [edge for edge in sorted(KNOWN) if edge not in found]
    for message in new:
        print(f"{message}: a back edge against the layering (tools/check_layers.py ALLOWED)")
    for path, include in gone:
        print(f"tools/check_layers.py: KNOWN lists {path} -> {include}, which no longer exists: delete the line")
    known = len(found) - len(new)
    print(f"layers: {len(found)} back edge(s): {known} known (tools/check_layers.py KNOWN), {len(new)} new; {len(gone)} stale")
    return 1 if new or gone else 0


if __name__ == "__main__":
    sys.exit(main())
