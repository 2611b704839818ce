#!/usr/bin/env bash
# bench/results.csv -> bench/REPORT.md (tables) and bench/plots/*.png (gnuplot).
#   bench/make_report.sh CSV OUT_DIR
set -euo pipefail
csv=$1 out=$2
mkdir -p "$out/plots"
report=$out/REPORT.md
machine="$(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"

{
echo "# vrsimplify benchmark"
echo
echo "Measured $(date -u +%Y-%m-%d) on $machine by \`scripts/bench.sh\` (data: \`bench/results.csv\`)."
echo "Every run is a child process of \`build/bin/vrs_bench\`; time is the simplification call only;"
echo "memory is the process's resident high-water mark during that call (and the part above what it"
echo "held before it); error is the symmetric Hausdorff distance (vertices + 200 000 area-uniform"
echo "samples per side, exact closest points, vcglib as MeshLab's filter), relative to the input's"
echo "bounding-box diagonal, in %. QECD = MeshLab's Quadric Edge Collapse Decimation with its dialog"
echo "defaults (it simplifies boundaries; ours and vtkDecimatePro keep topology, ours keeps boundaries)."
echo
echo "## Headline"
echo
awk -F, 'NR > 1 && ($5 == "ours" || $5 == "qecd" || $5 == "meshopt" || $5 == "vtk") {
    k = $1 "," $3; f[k, $5] = $6; t[k, $5] = $8; mx[k, $5] = $11; mn[k, $5] = $12; mem[k, $5] = $9
    if (!(k in seen)) { seen[k] = 1; order[++n] = k } }
  function v(x, fmt) { return x > 0 ? sprintf(fmt, x) : "—" }
  END {
    print "| mesh | ratio | faces (ours/QECD/meshopt/vtk) | time s (ours/QECD/meshopt/vtk) | max err % (ours/QECD/meshopt/vtk) | mean err % (ours/QECD/meshopt/vtk) |"
    print "|---|---|---|---|---|---|"
    for (i = 1; i <= n; i++) { k = order[i]; split(k, p, ",")
      printf "| %s | %s | %s / %s / %s / %s | %s / %s / %s / %s | %s / %s / %s / %s | %s / %s / %s / %s |\n",
        p[1], p[2], v(f[k,"ours"], "%d"), v(f[k,"qecd"], "%d"), v(f[k,"meshopt"], "%d"), v(f[k,"vtk"], "%d"),
        v(t[k,"ours"], "%.3f"), v(t[k,"qecd"], "%.3f"), v(t[k,"meshopt"], "%.3f"), v(t[k,"vtk"], "%.3f"),
        v(100*mx[k,"ours"], "%.3f"), v(100*mx[k,"qecd"], "%.3f"), v(100*mx[k,"meshopt"], "%.3f"), v(100*mx[k,"vtk"], "%.3f"),
        v(100*mn[k,"ours"], "%.4f"), v(100*mn[k,"qecd"], "%.4f"), v(100*mn[k,"meshopt"], "%.4f"), v(100*mn[k,"vtk"], "%.4f") }
    # The error targets are over the real meshes at their three ratios (not the scaling inputs).
    lm = lx = lt = lq = lmem = 0; c = ct = cq = 0
    for (i = 1; i <= n; i++) { k = order[i]; split(k, p, ",")
      if (p[1] ~ /_loop|terrain/) continue
      if (mn[k,"qecd"] > 0 && mx[k,"qecd"] > 0 && mn[k,"ours"] > 0) {
        lm += log(mn[k,"ours"] / mn[k,"qecd"]); lx += log(mx[k,"ours"] / mx[k,"qecd"]); c++ }
      if (t[k,"ours"] > 0 && t[k,"meshopt"] > 0) {
        lt += log(t[k,"ours"] / t[k,"meshopt"]); lmem += log(mem[k,"ours"] / mem[k,"meshopt"]); ct++ }
      if (t[k,"ours"] > 0 && t[k,"qecd"] > 0) { lq += log(t[k,"qecd"] / t[k,"ours"]); cq++ } }
    print ""
    printf "Geometric means over the %d real-mesh cases: our mean error / QECD = **%.2f** (target <= 1.5), our max error / QECD = **%.2f** (target <= 1.0); our time / meshoptimizer = %.2f, QECD time / ours = %.2f; our peak memory / meshoptimizer = %.2f. Speed and memory targets: see Scaling.\n",
      c, exp(lm / c), exp(lx / c), exp(lt / ct), exp(lq / cq), exp(lmem / ct) }' "$csv"
echo
echo "## Priority: local error against the paper's factor"
echo
echo "\`ours\` sorts by the local error of the planned patch (the default); \`ours-factor\` by the"
echo "paper's evaluation factor. Geometric means over the real-mesh cases."
echo
echo "| priority | mean err / QECD | max err / QECD | time / meshoptimizer | time / QECD |"
echo "|---|---|---|---|---|"
awk -F, 'NR > 1 && $1 !~ /_loop|terrain/ { k = $1 "," $3; mn[k, $5] = $12; mx[k, $5] = $11; t[k, $5] = $8; keys[k] = 1 }
  END {
    split("ours ours-factor", ms, " ")
    for (i = 1; i <= 2; i++) { m = ms[i]; a = b = c = d = 0; n = 0
      for (k in keys) if (mn[k, m] > 0 && mn[k, "qecd"] > 0 && t[k, "meshopt"] > 0) {
        a += log(mn[k, m] / mn[k, "qecd"]); b += log(mx[k, m] / mx[k, "qecd"])
        c += log(t[k, m] / t[k, "meshopt"]); d += log(t[k, m] / t[k, "qecd"]); n++ }
      if (n) printf "| %s | %.3f | %.3f | %.2f | %.2f |\n", m, exp(a / n), exp(b / n), exp(c / n), exp(d / n) } }' "$csv"
echo
echo "## Hash table ablation"
echo
echo "Against the exact heap (\`ours-heap\`), same meshes and ratios: geometric mean of the mean and"
echo "max error ratios, and total simplification time. \`ours\` is the default (local-error priority,"
echo "linear mapping, 1000 intervals)."
echo
echo "| variant | mean err / heap | max err / heap | total time s |"
echo "|---|---|---|---|"
awk -F, 'NR > 1 && $5 ~ /^ours/ && $5 !~ /factor/ && $1 !~ /_loop|terrain/ { k = $1 "," $3; mn[k, $5] = $12; mx[k, $5] = $11; t[$5] += $8; v[$5] = 1; keys[k] = 1 }
  END {
    for (m in v) { a = b = 0; c = 0
      for (k in keys) if (mn[k, "ours-heap"] > 0 && mn[k, m] > 0) {
        a += log(mn[k, m] / mn[k, "ours-heap"]); b += log(mx[k, m] / mx[k, "ours-heap"]); c++ }
      printf "| %s | %.3f | %.3f | %.3f |\n", m, c ? exp(a / c) : 0, c ? exp(b / c) : 0, t[m] } }' "$csv" | sort -t'|' -k2,2
echo
echo "## Scaling (10 %)"
echo
echo "Time per input triangle and peak memory against input size, every mesh at 10 %."
echo
echo "| mesh | input faces | ours s | ours-factor s | meshopt s | QECD s | ours / meshopt | ours-factor / meshopt | QECD / ours | ours µs per input face | ours MB | meshopt MB | QECD MB |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
awk -F, 'NR > 1 && $3 == "0.1" { k = $1; f[k] = $2; t[k, $5] = $8; mem[k, $5] = $9; if (!(k in s)) { s[k] = 1; o[++n] = k } }
  function v(x, fmt) { return x > 0 ? sprintf(fmt, x) : "—" }
  END { for (i = 1; i <= n; i++) { k = o[i]; q = t[k,"qecd"] > 0 ? t[k,"qecd"] / t[k,"ours"] : 0
    r = t[k,"ours-factor"] > 0 && t[k,"meshopt"] > 0 ? t[k,"ours-factor"] / t[k,"meshopt"] : 0
    printf "| %s | %d | %s | %s | %s | %s | %.2f | %s | %s | %.2f | %.0f | %.0f | %s |\n", k, f[k], v(t[k,"ours"], "%.3f"), v(t[k,"ours-factor"], "%.3f"),
      v(t[k,"meshopt"], "%.3f"), v(t[k,"qecd"], "%.3f"), t[k,"ours"] / t[k,"meshopt"], v(r, "%.2f"), v(q, "%.2f"),
      1e6 * t[k,"ours"] / f[k], mem[k,"ours"], mem[k,"meshopt"], v(mem[k,"qecd"], "%.0f") } }' "$csv" |
  sort -t'|' -k3,3n
echo
echo "![time](plots/scaling_time.png) ![memory](plots/scaling_memory.png)"
echo
if [ -d "$out/renders" ]; then
  echo "## At 1 %: original, ours, QECD, meshoptimizer"
  echo
  echo "Flat shading with edges, rendered offscreen by VTK (\`build/bin/vrs_render\`)."
  echo
  echo "| original | vrsimplify | QECD | meshoptimizer |"
  echo "|---|---|---|---|"
  for m in fandisk bunny00; do
    [ -f "$out/renders/${m}_ours.png" ] || continue
    echo "| ![](renders/${m}_original.png) | ![](renders/${m}_ours.png) | ![](renders/${m}_qecd.png) | ![](renders/${m}_meshopt.png) |"
  done
  echo
fi
echo "## Error against face count"
echo
for m in $(awk -F, 'NR > 1 && !seen[$1 "," $3]++ { n[$1]++ } END { for (m in n) if (n[m] > 1) print m }' "$csv" | sort); do
  echo "![$m](plots/error_$m.png)"
done
# The speed runs (scripts/bench_speed.sh), measured apart: medians of alternated runs; and
# where their time goes (scripts/profile.sh); the Python peers and the numpy API
# (scripts/bench_python_peers.sh, scripts/bench_python_api.sh). Their headings one level down.
for part in SPEED PROFILE PYTHON_PEERS PYTHON_API; do
  if [ -f "$out/$part.md" ]; then
    echo
    sed 's/^#/##/' "$out/$part.md"
  fi
done
} >"$report"

# One plot per mesh run at several ratios: mean error against output faces, log-log.
for m in $(awk -F, 'NR > 1 && !seen[$1 "," $3]++ { n[$1]++ } END { for (m in n) if (n[m] > 1) print m }' "$csv" | sort); do
  for method in ours ours-factor qecd meshopt vtk; do
    awk -F, -v m="$m" -v me="$method" '$1 == m && $5 == me { print $6, 100 * $12, 100 * $11 }' "$csv" |
      sort -n >"$out/plots/.$m.$method.dat"
  done
  gnuplot <<GP
set terminal pngcairo size 720,480 font ",10"
set output "$out/plots/error_$m.png"
set title "$m: symmetric Hausdorff mean error (solid) and max (dashed)"
set logscale xy
set xlabel "output faces"
set ylabel "% of bounding-box diagonal"
set key left bottom
set grid
methods = "ours ours-factor qecd meshopt vtk"
file(i) = sprintf("$out/plots/.$m.%s.dat", word(methods, i))
plot for [i=1:5] file(i) using 1:2 with linespoints lc i lw 2 title word(methods, i), \
     for [i=1:5] file(i) using 1:3 with lines lc i dt 2 notitle
GP
  rm -f "$out/plots/.$m."*.dat
done

# Scaling: time per input face and peak memory against input faces, log-log, at 10 %.
for method in ours ours-factor qecd meshopt vtk; do
  awk -F, -v me="$method" '$3 == "0.1" && $5 == me && $8 > 0 { print $2, 1e6 * $8 / $2, $9 }' "$csv" | sort -n >"$out/plots/.scale.$method.dat"
done
gnuplot <<GP
set terminal pngcairo size 720,480 font ",10"
set logscale xy
set grid
set key left top
set xlabel "input faces"
methods = "ours ours-factor qecd meshopt vtk"
file(i) = sprintf("$out/plots/.scale.%s.dat", word(methods, i))
set output "$out/plots/scaling_time.png"
set title "simplification time per input face at 10 % (flat = linear)"
set ylabel "microseconds per input face"
plot for [i=1:5] file(i) using 1:2 with linespoints lc i lw 2 title word(methods, i)
set output "$out/plots/scaling_memory.png"
set title "peak resident memory during the call at 10 %"
set ylabel "MB"
plot for [i=1:5] file(i) using 1:3 with linespoints lc i lw 2 title word(methods, i)
GP
rm -f "$out/plots/.scale."*.dat
