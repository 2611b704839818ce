#!/usr/bin/env python3
"""scripts/bench_lods.sh's results (JSON lines) -> bench/LODS.md.

    lods_report.py RESULTS.jsonl OUT.md
"""
import datetime
import json
import sys


def main():
    rows = [json.loads(l) for l in open(sys.argv[1])]
    chains = {r["mesh"]: r for r in rows if "chain" in r}
    browser = {r["mesh"]: r for r in rows if "browser" in r}
    levels = [r for r in rows if "nested" in r]
    packed = {r["mesh"]: r["compressed"] for r in rows if "compressed" in r}
    alone = {(r["mesh"], r["ratio"]): r for r in levels}
    names = {"bunny_loop2": "bunny00 Loop ×2 (positions)",
             "elephant_textured": "elephant Loop ×3, 7 UV charts (textured scan)"}
    out = ["# Levels of detail in one .glb", "",
           f"Measured {datetime.date.today()} on this machine by `scripts/bench_lods.sh`: one "
           "nested run (`vrsimplify IN OUT.glb --lods 1,0.5,0.1,0.01`), each level simplified "
           "from the finer one, written as one binary glTF: one vertex buffer shared by every "
           "level, coarsest level first, one index buffer per level, MSFT_lod on the finest "
           "level's node. Beside it, side by side in the same run: the full-resolution mesh "
           "written alone (`--ratio 1`), and the levels as separate runs make them (one .glb a "
           "level, its own vertices). Khronos' glTF-Validator on every file.", "",
           "## Size", "",
           "| mesh | input faces | chain .glb | full mesh alone | chain ÷ full | separate levels | separate ÷ full | glTF vertices | validator |",
           "|---|---|---|---|---|---|---|---|---|"]
    for m, c in chains.items():
        chain, full = c["chain"]["file_bytes"], c["full"]["file_bytes"]
        sep = full + sum(alone[(m, r)]["alone_bytes"] for r in (0.5, 0.1, 0.01))
        out.append(f"| {names.get(m, m)} | {c['chain']['input_faces']:,} | {chain:,} B | {full:,} B | "
                   f"**{chain / full:.2f}** | {sep:,} B | {sep / full:.2f} | "
                   f"{c['chain']['gltf_vertices']:,} | {c['validator']} |")
    out += ["", "Per level of the chain (finest first): faces, and the bytes a reader needs to draw "
            "it (header and JSON, its prefix of the vertices, its indices; the coarsest level's "
            "are one prefix of the file):", "",
            "| mesh | level | faces | vertices | bytes to draw | % of the file |", "|---|---|---|---|---|---|"]
    for m, c in chains.items():
        total = c["chain"]["file_bytes"]
        for k, lv in enumerate(c["chain"]["levels"]):
            out.append(f"| {names.get(m, m)} | {k} ({100 * lv['ratio']:g} %) | {lv['faces']:,} | "
                       f"{lv['vertices']:,} | {lv['bytes_to_draw']:,} | {100 * lv['bytes_to_draw'] / total:.2f} |")
    out += ["", "What the chain adds to the full mesh is the coarser levels' index buffers (the "
            "vertices are shared): 0.5 + 0.1 + 0.01 of the full mesh's indices, 32-bit wherever a "
            "level has 65 535 vertices or more. Indices are 12 bytes a face against about 6 for "
            "the positions alone (half a vertex a face) and 10 with texture coordinates, so "
            "uncompressed the chain is about 1.3-1.4x the mesh, not 1.15x; the separate levels "
            "cost 1.6x.", ""]
    if packed:
        out += ["## Compressed (EXT_meshopt_compression)", "",
                "`--compress`: meshoptimizer's own codec (built from Debian's pinned source), "
                "lossless (every decoded vertex record equals the uncompressed file's, "
                "`tests/web/glb_decoded.mjs`). Each level's triangles in the vertex cache's order "
                "and its new vertices in order of first use; each coarser level's vertices end on "
                "a block of the vertex codec (copies of its last vertex pad it), so the first "
                "bytes of the one vertex stream, with the stream's tail (in the JSON), decode that "
                "level alone: the file still streams coarsest first. Beside it, meshoptimizer's "
                "gltfpack (npm, pinned) compressing our full-resolution .glb, one file a level "
                "(`-cc -kv`: every vertex attribute kept, and `-si R` for the lower ones: its own simplifier), with its default "
                "quantization (positions rounded to 14 bits: not the input's coordinates) and "
                "without (`-noq`).", "",
                "| mesh | chain, compressed | full mesh alone, compressed | chain ÷ full | separate levels, compressed | separate ÷ full | gltfpack, 4 files | gltfpack -noq, 4 files | validator |",
                "|---|---|---|---|---|---|---|---|---|"]
        for m, p in packed.items():
            chain, full = p["chain"]["file_bytes"], p["full"]
            sep = full + sum(p["alone"].values())
            gp, gpq = sum(p["gltfpack"].values()), sum(p["gltfpack_noq"].values())
            out.append(f"| {names.get(m, m)} | {chain:,} B | {full:,} B | **{chain / full:.2f}** | "
                       f"{sep:,} B | {sep / full:.2f} | {gp:,} B ({gp / chain:.2f}x ours) | "
                       f"{gpq:,} B ({gpq / chain:.2f}x ours) | {p['validator']} |")
        out += ["", "gltfpack per level (bytes; 1 = the full mesh): " + "; ".join(
            f"{names.get(m, m)}: " + ", ".join(f"{r} → {p['gltfpack'][r]:,} / -noq {p['gltfpack_noq'][r]:,}"
                                                for r in p["gltfpack"]) for m, p in packed.items()) + ".", "",
                "| mesh | level | faces | bytes to draw | % of the file | drawn in the browser after (bytes, ms) |",
                "|---|---|---|---|---|---|"]
        for m, p in packed.items():
            total = p["chain"]["file_bytes"]
            seen = {lv["index"]: lv for lv in p["browser"]["levels"]}
            for k, lv in enumerate(p["chain"]["levels"]):
                b = seen.get(k)
                when = f"{b['bytes']:,} ({100 * b['bytes'] / p['browser']['total']:.2f} %), {b['ms']:.0f} ms" if b else "–"
                out.append(f"| {names.get(m, m)} | {k} ({100 * lv['ratio']:g} %) | {lv['faces']:,} | "
                           f"{lv['bytes_to_draw']:,} | {100 * lv['bytes_to_draw'] / total:.2f} | {when} |")
            out.append(f"| {names.get(m, m)} | browser checks | {p['browser_checks']} | | | |")
        out += ["", "Time and peak memory of the compressed chain's run: " + "; ".join(
            f"{names.get(m, m)} {p['seconds']} s, {p['peak_kb'] / 1024:.0f} MB" for m, p in packed.items()) + ".", ""]
    out += ["", "Time and peak memory of the chain's run (`/usr/bin/time`): " + "; ".join(
        f"{names.get(m, m)} {c['seconds']} s, {c['peak_kb'] / 1024:.0f} MB" for m, c in chains.items()) + ".",
        "", "## Nesting costs almost nothing", "",
        "Each nested level (read back from the chain's file) against a standalone run at the "
        "same ratio from the input, symmetric Hausdorff distance to the input (`vrs_bench "
        "--compare`, relative to the bounding-box diagonal):", "",
        "| mesh | ratio | nested mean / max | standalone mean / max | mean ratio | max ratio |",
        "|---|---|---|---|---|---|"]
    for r in levels:
        nmax, nmean = map(float, r["nested"].split()[:2])
        amax, amean = map(float, r["alone"].split()[:2])
        out.append(f"| {names.get(r['mesh'], r['mesh'])} | {100 * r['ratio']:g} % | {nmean:.3g} / {nmax:.3g} | "
                   f"{amean:.3g} / {amax:.3g} | {nmean / amean:.3f} | {nmax / amax:.3f} |")
    out += ["", "## In the browser", "",
            "The viewer page (`vrsimplify serve`, `web/`) in Debian's Chromium, headless, the "
            "server throttled to 20 MB/s: the level drawn, after how many bytes received, when.", "",
            "| mesh | level | faces | bytes received when drawn | % of the file | ms |", "|---|---|---|---|---|---|"]
    for m, b in browser.items():
        f = b["browser"]
        for lv in f["levels"]:
            out.append(f"| {names.get(m, m)} | {lv['index']} | {lv['faces']:,} | {lv['bytes']:,} | "
                       f"{100 * lv['bytes'] / f['total']:.2f} | {lv['ms']:.0f} |")
        out.append(f"| {names.get(m, m)} | checks | {b['browser_checks']} | | | |")
    out += ["", "## Targets (issue 32)", "", "| figure | measured | target | |", "|---|---|---|---|"]
    met = lambda ok: "met" if ok else "**missed**"
    for m, c in chains.items():
        r = c["chain"]["file_bytes"] / c["full"]["file_bytes"]
        out.append(f"| {names.get(m, m)}: chain ÷ full mesh alone | {r:.2f} | ≤ 1.15 | {met(r <= 1.15)} |")
        if m in packed:
            p = packed[m]
            r = p["chain"]["file_bytes"] / p["full"]
            out.append(f"| {names.get(m, m)}: compressed chain ÷ compressed full mesh alone | {r:.2f} | ≤ 1.15 | {met(r <= 1.15)} |")
            first = p["browser"]["levels"][0]
            share = first["bytes"] / p["browser"]["total"]
            out.append(f"| {names.get(m, m)}: compressed, coarsest level drawn after | {100 * share:.2f} % of the file | ≤ 2 % | {met(share <= 0.02)} |")
        ok = c["validator"].startswith("0 errors, 0 warnings")
        out.append(f"| {names.get(m, m)}: glTF-Validator | {c['validator']} | 0 errors, 0 warnings | {met(ok)} |")
    for m, b in browser.items():
        first = b["browser"]["levels"][0]
        share = first["bytes"] / b["browser"]["total"]
        out.append(f"| {names.get(m, m)}: coarsest level drawn after | {100 * share:.2f} % of the file | ≤ 2 % | {met(share <= 0.02)} |")
    for r in levels:
        nmax, nmean = map(float, r["nested"].split()[:2])
        amax, amean = map(float, r["alone"].split()[:2])
        worst = max(nmean / amean, nmax / amax)
        out.append(f"| {names.get(r['mesh'], r['mesh'])} at {100 * r['ratio']:g} %: nested ÷ standalone error (mean, max) | "
                   f"{nmean / amean:.3f}, {nmax / amax:.3f} | ≤ 1.05 | {met(worst <= 1.05)} |")
    open(sys.argv[2], "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
