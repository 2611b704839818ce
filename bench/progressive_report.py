"""bench/PROGRESSIVE.md from bench/progressive.jsonl (scripts/bench_progressive.sh)."""
import datetime
import json
import platform
import sys


def mib(b):
    return "%.2f MB" % (b / 1e6)


def main(src, dst):
    rows = [json.loads(line) for line in open(src) if line.strip()]
    rows.sort(key=lambda r: r["mesh"])
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo")
                if line.startswith("model name")), platform.machine())
    out = ["# A progressive mesh beside levels of detail and the full mesh alone", "",
           "`scripts/bench_progressive.sh`, %s, on %s. Each mesh's files written by one build "
           "in one run: `--progressive` (its default base, 0.3 %% of the faces), the full mesh alone "
           "(`--lods 1`), the levels-of-detail chain 100/50/10/1 %% (`--lods`), the last two "
           "also with EXT_meshopt_compression (`--compress`); gzip -9 of each as a server "
           "would send it compressed." % (datetime.date.today().isoformat(), cpu), "",
           "## Sizes", "",
           "| mesh | faces | full alone | progressive | ÷ full | LOD chain ÷ full | full meshopt | progressive ÷ full meshopt | gzip: progressive ÷ full | gzip: progressive ÷ full meshopt | progressive gzip ÷ full meshopt | base needs (of the file) |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        b, p = r["bytes"], r["progressive"]
        out.append("| %s | %s | %s | %s | **%.2f** | %.2f | %s | **%.2f** | %.2f | **%.2f** | %.2f | %s (%.2f %%) |" % (
            r["mesh"], format(p["input_faces"], ","), mib(b["full"]), mib(b["progressive"]),
            b["progressive"] / b["full"], b["chain"] / b["full"], mib(b["full_meshopt"]),
            b["progressive"] / b["full_meshopt"], b["progressive_gzip"] / b["full_gzip"],
            b["progressive_gzip"] / b["full_meshopt_gzip"], b["progressive_gzip"] / b["full_meshopt"],
            format(p["base_bytes"], ","), 100 * p["base_bytes"] / b["progressive"]))
    out += ["", "*Full meshopt*: the full mesh alone with EXT_meshopt_compression (meshoptimizer's "
            "lossless codec). *gzip*: both files gzip -9, as a server sends them compressed.", "",
            "The records' faces cost %s bytes a vertex; the rest of a record is its vertex, each "
            "value as its residual from the mean of its ring." % ", ".join(
                "%.1f (%s)" % (r["progressive"]["record_topology_bytes"] / r["progressive"]["insertions"],
                               r["mesh"]) for r in rows), "",
            "## What is drawn after 10 % of the file", "",
            "The records whole in the file's first 10 % of bytes, decoded by the reference "
            "decoder (`bench/progressive_prefix.py`), against a standalone run to the same face "
            "count; error against the input (`vrs_bench --compare`, in mesh units).", "",
            "| mesh | records applied | faces | mean error | standalone | ÷ | max error | standalone | ÷ |",
            "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        d = [float(x) for x in r["drawn"].split()]
        a = [float(x) for x in r["alone"].split()]
        x = r["prefix"]
        out.append("| %s | %s of %s | %s | %.3g | %.3g | **%.2f** | %.3g | %.3g | %.2f |" % (
            r["mesh"], format(x["records"], ","), format(x["insertions"], ","),
            format(x["faces"], ","), d[1], a[1], d[1] / a[1], d[0], a[0], d[0] / a[0]))
    out += ["", "## In the browser", "",
            "The viewer page in headless Chromium (SwiftShader), served by `vrsimplify serve` at "
            "20 MB/s (`tests/web/progressive_test.mjs --stream-only`): the base drawn after how "
            "many bytes (the page asks for the header and the base by range requests, then "
            "streams the records), the longest refining step (records applied within 8 ms a "
            "frame and handed to the GPU) and the longest frame (that and the drawing, which "
            "SwiftShader does on the CPU: seconds at a million faces), and the decoder alone in "
            "records a second (the whole file's records, best of three, no drawing): on a page "
            "of its own, as beside a GPU that draws without the CPU, and in the viewer's page, "
            "whose frames SwiftShader draws on the same two cores. The elephant: its base and "
            "the decoder only.", "",
            "| mesh | base drawn after | all applied at | longest refining step | longest frame | decoder, page of its own | decoder, viewer's page | checks | validator | time to write (s) |",
            "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        w = r["browser"]
        dash = lambda k, f: f % w[k] if k in w else "–"  # noqa: E731
        out.append("| %s | %s bytes (%.2f %%) | %s | %s | %s | %.2f M/s | %s | %s | %s | %.1f |" % (
            r["mesh"], format(w.get("baseBytes", 0), ","), 100 * w.get("baseBytes", 0) / w["bytes"],
            "%.1f s" % (w["doneMs"] / 1000) if "doneMs" in w else "–",
            dash("longestRefineMs", "%.0f ms"), dash("longestFrameMs", "%.0f ms"),
            w.get("recordsPerSecond", 0) / 1e6,
            "%.2f M/s" % (w["recordsPerSecondInViewer"] / 1e6) if "recordsPerSecondInViewer" in w else "–",
            r["browser_checks"], r["validator"], r["seconds"]))
    open(dst, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
