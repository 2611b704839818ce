# MeshLab 2020.09 filter-script (.mlx) snippets, for `source`. MeshLab aborts (exit 134) when a
# declared parameter is missing, so every filter is written with all of its parameters; pass
# NAME=VALUE words to override the defaults (which are the dialog's).

mlx_begin() { printf '<!DOCTYPE FilterScript>\n<FilterScript>\n'; }
mlx_end() { printf '</FilterScript>\n'; }

# _mlx_filter NAME "TYPE NAME DEFAULT"... -- OVERRIDES...
# An enum declares its labels after the default: "RichEnum NAME DEFAULT LABEL0|LABEL1|...".
_mlx_filter() {
  local filter=$1; shift
  local -a decl=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do decl+=("$1"); shift; done
  [ "${1:-}" = -- ] && shift
  printf ' <filter name="%s">\n' "$filter"
  local d type name value labels kv i
  local -a label
  for d in "${decl[@]}"; do
    read -r type name value <<<"$d" # value: the rest of the line (strings hold spaces)
    labels=
    if [ "$type" = RichEnum ]; then labels=${value#* } value=${value%% *}; fi
    for kv in "$@"; do [ "${kv%%=*}" = "$name" ] && value=${kv#*=}; done
    # XML escapes (the \& keeps bash 5.2 from reading & as "the match")
    value=${value//&/\&amp;} value=${value//</\&lt;} value=${value//>/\&gt;} value=${value//\"/\&quot;}
    case $type in
    RichEnum)
      IFS='|' read -r -a label <<<"$labels"
      printf '  <Param type="RichEnum" name="%s" value="%s" enum_cardinality="%d"' "$name" "$value" "${#label[@]}"
      for i in "${!label[@]}"; do printf ' enum_val%d="%s"' "$i" "${label[$i]}"; done
      printf '/>\n' ;;
    RichAbsPerc) printf '  <Param type="RichAbsPerc" name="%s" value="%s" min="0" max="%s"/>\n' "$name" "$value" "$value" ;;
    *) printf '  <Param type="%s" name="%s" value="%s"/>\n' "$type" "$name" "$value" ;;
    esac
  done
  printf ' </filter>\n'
}

# Ours. Defaults as the dialog, except TargetFaceNum, which the dialog sets to half the faces.
mlx_vertex_removal() {
  _mlx_filter "Simplification: Vertex Removal Decimation" \
    "RichInt TargetFaceNum 0" "RichFloat TargetPerc 0" "RichInt TargetVertNum 0" \
    "RichFloat MaxFactor 0" "RichBool AutoStop false" \
    "RichEnum Mode 0 3D surface (average plane)|2.5D terrain (XY plane)|2D planar mesh" \
    "RichEnum Priority 0 Local error of the new patch|Evaluation factor (paper)" "RichInt Intervals 1000" \
    "RichBool PreserveBoundary true" "RichBool Selected false" "RichBool AutoClean true" \
    "RichInt LODLevels 1" -- "$@"
}

# MeshLab's Quadric Edge Collapse Decimation with its dialog defaults.
mlx_qecd() {
  _mlx_filter "Simplification: Quadric Edge Collapse Decimation" \
    "RichInt TargetFaceNum 0" "RichFloat TargetPerc 0" "RichFloat QualityThr 0.3" \
    "RichBool PreserveBoundary false" "RichFloat BoundaryWeight 0.5" \
    "RichBool PreserveNormal false" "RichBool PreserveTopology false" \
    "RichBool OptimalPlacement true" "RichBool PlanarQuadric false" \
    "RichFloat PlanarWeight 0.001" "RichBool QualityWeight false" "RichBool AutoClean true" \
    "RichBool Selected false" -- "$@"
}

# MeshLab's Hausdorff Distance from layer SampledMesh to layer TargetMesh.
mlx_hausdorff() {
  _mlx_filter "Hausdorff Distance" \
    "RichMesh SampledMesh 1" "RichMesh TargetMesh 0" "RichBool SaveSample false" \
    "RichBool SampleVert true" "RichBool SampleEdge true" "RichBool SampleFauxEdge false" \
    "RichBool SampleFace true" "RichInt SampleNum 100000" "RichAbsPerc MaxDist 1000000" -- "$@"
}

mlx_select_layer() { _mlx_filter "Change the current layer" "RichMesh layer $1"; }

# Selects the faces for which the muparser condition holds (x0, y0, z0: first vertex).
mlx_select_faces_where() {
  _mlx_filter "Conditional Face Selection" "RichString condSelect $1"
}
